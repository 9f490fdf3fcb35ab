// Writing a captured frame (capture_frame.hpp): each object's triangles as an OBJ file (its
// vertex colours on the `v` lines when unlit) and the scene file that names them, with the
// camera at the GL eye, the lights in eye space and a caption of what the scene leaves out.
#include <algorithm>
#include <cerrno>  // program_invocation_short_name
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "gl/src/capture_frame.hpp"
#include "shadelab/image.hpp"

namespace shadelab::gl {

namespace {

// The shortest text that reads back as the same float (0.1f as 0.1).
std::string num(float x) {
  if (!std::isfinite(x)) x = 0.0f;
  char b[32];
  for (int digits = 6; digits <= 9; ++digits) {
    std::snprintf(b, sizeof b, "%.*g", digits, double(x));
    if (std::strtof(b, nullptr) == x) break;
  }
  return b;
}

// `x` to 6 significant digits (a camera's near and far worked out from its matrix).
float round6(float x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", double(x));
  return std::strtof(b, nullptr);
}

std::string color(glm::vec4 v, std::size_t& clamped, bool clamp01 = true) {
  if (clamp01) {
    glm::vec4 k = glm::clamp(v, 0.0f, 1.0f);
    if (k != v) ++clamped;
    v = k;
  }
  return "[" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ", " + num(v.w) + "]";
}

std::string vec(const glm::vec3& v) { return "[" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + "]"; }

std::string material_json(const Material& m, std::size_t& clamped) {
  return "{\"ambient\": " + color(m.ambient, clamped) + ", \"diffuse\": " + color(m.diffuse, clamped) +
         ", \"specular\": " + color(m.specular, clamped) + ", \"emission\": " + color(m.emission, clamped) +
         ", \"shininess\": " + num(std::clamp(m.shininess, 0.0f, 128.0f)) + "}";
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') out += '\\', out += ch;
    else if (static_cast<unsigned char>(ch) < 0x20) out += ' ';
    else out += ch;
  }
  return out + "\"";
}

// The projection as camera keys: fovy or ortho_height with near and far when the matrix is
// a symmetric glFrustum / gluPerspective or glOrtho whose aspect is the viewport's (and the
// scene's parameters give it back), else the matrix itself.
std::string camera_json(const FrameCapture& f, float depth) {
  const glm::mat4& p = f.projection;
  const float aspect = float(f.viewport.width) / float(std::max(f.viewport.height, 1));
  Camera cam;
  cam.eye = glm::vec3(0.0f);
  cam.target = glm::vec3(0.0f, 0.0f, -depth);
  bool fits = false;
  const bool symmetric = p[1][0] == 0 && p[0][1] == 0 && p[2][0] == 0 && p[2][1] == 0 && p[3][0] == 0 &&
                         p[3][1] == 0 && p[0][2] == 0 && p[1][2] == 0 && p[0][3] == 0 && p[1][3] == 0 &&
                         p[0][0] != 0 && p[1][1] != 0;
  if (symmetric && p[2][3] == -1.0f && p[3][3] == 0.0f) {
    cam.projection = Camera::Projection::kPerspective;
    cam.fovy_degrees = float(2.0 * std::atan(1.0 / p[1][1]) * 180.0 / std::numbers::pi);
    cam.near_plane = p[3][2] / (p[2][2] - 1.0f);
    cam.far_plane = p[3][2] / (p[2][2] + 1.0f);
    fits = true;
  } else if (symmetric && p[2][3] == 0.0f && p[3][3] == 1.0f && p[2][2] != 0) {
    cam.projection = Camera::Projection::kOrthographic;
    cam.ortho_height = 2.0f / p[1][1];
    cam.near_plane = (p[3][2] + 1.0f) / p[2][2];
    cam.far_plane = (p[3][2] - 1.0f) / p[2][2];
    fits = true;
  }
  fits = fits && cam.near_plane > 0 && cam.far_plane > cam.near_plane && cam.fovy_degrees > 0 &&
         cam.fovy_degrees < 180 && cam.ortho_height > 0 && std::isfinite(cam.far_plane);
  // The parameters must give the program's matrix back: rounded to 6 digits (gluPerspective's
  // 40 and 30, not 39.9999981 and 29.9999828) when that still does, else as worked out.
  auto gives_back = [&](const Camera& k) {
    const glm::mat4 q = k.projection_matrix(aspect);
    for (int i = 0; i < 16; ++i) {
      const float a = p[i / 4][i % 4], b = q[i / 4][i % 4];
      if (!(std::fabs(a - b) <= 1e-5f * std::max(1.0f, std::fabs(a)))) return false;
    }
    return true;
  };
  if (fits) {
    Camera rounded = cam;
    rounded.fovy_degrees = round6(cam.fovy_degrees);
    rounded.ortho_height = round6(cam.ortho_height);
    rounded.near_plane = round6(cam.near_plane);
    rounded.far_plane = round6(cam.far_plane);
    if (gives_back(rounded)) cam = rounded;
    else fits = gives_back(cam);
  }
  std::string s = "{\"eye\": [0, 0, 0], \"target\": [0, 0, " + num(-depth) + "], \"up\": [0, 1, 0]";
  if (fits) {
    if (cam.projection == Camera::Projection::kPerspective) s += ", \"projection\": \"perspective\", \"fovy\": " + num(cam.fovy_degrees);
    else s += ", \"projection\": \"orthographic\", \"ortho_height\": " + num(cam.ortho_height);
    s += ", \"near\": " + num(cam.near_plane) + ", \"far\": " + num(cam.far_plane) + "}";
    return s;
  }
  s += ", \"projection_matrix\": [";
  for (int i = 0; i < 16; ++i) s += (i ? ", " : "") + num(p[i / 4][i % 4]);
  return s + "]}";
}

std::string light_json(const Light& l, std::size_t& clamped) {
  std::string s = "{\"enabled\": " + std::string(l.enabled ? "true" : "false") + ", \"space\": \"eye\"";
  s += ", \"position\": [" + num(l.position.x) + ", " + num(l.position.y) + ", " + num(l.position.z) + ", " +
       num(l.position.w) + "]";
  s += ", \"ambient\": " + color(l.ambient, clamped, false) + ", \"diffuse\": " + color(l.diffuse, clamped, false) +
       ", \"specular\": " + color(l.specular, clamped, false);
  const bool attenuated = l.constant_attenuation != 1 || l.linear_attenuation != 0 || l.quadratic_attenuation != 0;
  const bool some = l.constant_attenuation > 0 || l.linear_attenuation > 0 || l.quadratic_attenuation > 0;
  if (attenuated && some) {
    s += ", \"attenuation\": {\"constant\": " + num(l.constant_attenuation) + ", \"linear\": " +
         num(l.linear_attenuation) + ", \"quadratic\": " + num(l.quadratic_attenuation) + "}";
  }
  if (l.spot_cutoff != 180.0f && glm::length(l.spot_direction) > 0.0f) {
    s += ", \"spot\": {\"direction\": " + vec(l.spot_direction) + ", \"cutoff\": " + num(l.spot_cutoff) +
         ", \"exponent\": " + num(l.spot_exponent) + "}";
  }
  return s + "}";
}

std::string plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// What the scene leaves out or changes, for its caption.
std::string omissions(const FrameCapture& f, std::size_t clamped) {
  const Omitted& o = f.omitted;
  std::vector<std::string> parts;
  auto add = [&](std::size_t n, const std::string& text) {
    if (n) parts.push_back(text);
  };
  add(o.lines, plural(o.lines, "line segment", "line segments"));
  add(o.points, plural(o.points, "point", "points"));
  add(o.unfilled, plural(o.unfilled, "triangle drawn as lines or points", "triangles drawn as lines or points"));
  add(o.pixels, plural(o.pixels, "pixel rectangle (glDrawPixels, glBitmap)", "pixel rectangles (glDrawPixels, glBitmap)"));
  add(o.behind_eye, plural(o.behind_eye, "triangle reaching behind the eye", "triangles reaching behind the eye"));
  add(o.over_limit, plural(o.over_limit, "triangle over the limit", "triangles over the limit"));
  std::string s = parts.empty() ? "" : " Not in the scene: ";
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? ", " : "") + parts[i];
  if (!parts.empty()) s += ".";
  parts.clear();
  add(o.textured, plural(o.textured, "draw with a 1D, 3D, cube-map, depth or incomplete texture is",
                         "draws with a 1D, 3D, cube-map, depth or incomplete texture are") + " drawn without it");
  add(o.more_units, plural(o.more_units, "multitextured draw keeps", "multitextured draws keep") + " its first unit's texture only");
  add(o.texture_settings, plural(o.texture_settings, "textured object's wrap, filter or environment is",
                                 "textured objects' wraps, filters or environments are") + " the nearest the scene has");
  add(o.fogged, plural(o.fogged, "fogged draw is", "fogged draws are") + " drawn without fog");
  add(o.no_depth_test, plural(o.no_depth_test, "draw without depth test is", "draws without depth test are") + " depth tested");
  add(o.blend_other, plural(o.blend_other, "draw's blend function is", "draws' blend functions are") + " taken as alpha blending");
  add(o.mixed, plural(o.mixed, "triangle whose vertices had different materials takes", "triangles whose vertices had different materials take") + " its last vertex's");
  add(o.merged, plural(o.merged, "triangle takes", "triangles take") + " the nearest of the first 512 materials");
  add(o.lights_differ, "the lights changed between draws (" + plural(o.lights_differ, "draw", "draws") + "): these are the first lit draw's");
  add(o.views_differ, "the projection or viewport changed between draws (" + plural(o.views_differ, "draw", "draws") + "): these are the first draw's");
  add(clamped, plural(clamped, "material colour outside 0..1 is", "material colours outside 0..1 are") + " clamped");
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? "; " : " Approximated: ") + parts[i];
  if (!parts.empty()) s += ".";
  return s;
}

// A text file written whole or not at all (the core's write_file_atomically).
bool write_text(const std::string& path, const std::string& text) {
  std::string error;
  return write_file_atomically(std::vector<std::uint8_t>(text.begin(), text.end()), path, &error);
}

std::string obj_text(const Object& o) {
  std::string s;
  s.reserve(o.positions.size() * 80 + o.triangles.size() * 40);
  s += "# shadelab: a captured frame's triangles, in the program's eye space\n";
  for (std::size_t i = 0; i < o.positions.size(); ++i) {
    const glm::vec3& p = o.positions[i];
    s += "v " + num(p.x) + " " + num(p.y) + " " + num(p.z);
    if (!o.key.lit) {
      const glm::vec4 k = glm::clamp(o.colors[i], 0.0f, 1.0f);
      s += " " + num(k.r) + " " + num(k.g) + " " + num(k.b);
    }
    s += "\n";
  }
  for (const glm::vec3& n : o.normals) {
    const float len = glm::length(n);
    const glm::vec3 u = len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0, 0, 1);
    s += "vn " + num(u.x) + " " + num(u.y) + " " + num(u.z) + "\n";
  }
  for (const glm::vec2& t : o.texcoords) s += "vt " + num(t.x) + " " + num(t.y) + "\n";
  const bool textured = !o.texcoords.empty();
  for (const Triangle& t : o.triangles) {
    s += "f";
    for (std::uint32_t v : t) {
      const std::string i = std::to_string(v + 1);
      s += " " + i + (textured ? "/" + i : o.key.lit ? "/" : "") + (o.key.lit ? "/" + i : "");
    }
    s += "\n";
  }
  return s;
}

// The scene's texture keys for a captured texture and environment; counts what they change.
std::string texture_json(const CapturedTexture& t, TextureEnvMode env, const std::string& file, std::size_t& changed) {
  auto wrap = [](TextureWrap w) {
    return w == TextureWrap::kClamp || w == TextureWrap::kClampToBorder ? "clamp"
           : w == TextureWrap::kClampToEdge                            ? "clamp_to_edge"
                                                                        : "repeat";
  };
  const char* filter = t.min_filter == TextureFilter::kNearest                  ? "nearest"
                       : t.min_filter == TextureFilter::kLinear                 ? "linear"
                       : t.min_filter == TextureFilter::kNearestMipmapNearest ||
                               t.min_filter == TextureFilter::kLinearMipmapNearest ? "bilinear_mipmap"
                                                                                  : "trilinear";
  const char* mode = env == TextureEnvMode::kReplace ? "replace"
                     : env == TextureEnvMode::kDecal ? "decal"
                     : env == TextureEnvMode::kBlend ? "blend"
                                                     : "modulate";
  const bool nearest_mag = t.mag_filter == TextureFilter::kNearest;
  const bool exact = t.wrap_s == t.wrap_t && t.wrap_s != TextureWrap::kMirroredRepeat &&
                     t.wrap_s != TextureWrap::kClampToBorder && (t.wrap_s != TextureWrap::kClamp || t.border == glm::vec4(0.0f)) &&
                     nearest_mag == (t.min_filter == TextureFilter::kNearest) &&
                     (env == TextureEnvMode::kModulate || std::string(mode) != "modulate");
  if (!exact) ++changed;
  return "{\"file\": " + json_string(file) + ", \"wrap\": \"" + wrap(t.wrap_s) + "\", \"filter\": \"" + filter +
         "\", \"env\": \"" + mode + "\"}";
}

// Texture i as a PNG beside the scene (its first row the texture's top, t = 1).
bool write_texture_png(const CapturedTexture& t, const std::string& path) {
  Image image;
  image.width = t.width, image.height = t.height;
  image.rgba.resize(t.rgba.size());
  const std::size_t row = std::size_t(t.width) * 4;
  for (int y = 0; y < t.height; ++y) {
    std::copy_n(t.rgba.begin() + std::ptrdiff_t(std::size_t(y) * row), row,
                image.rgba.begin() + std::ptrdiff_t(std::size_t(t.height - 1 - y) * row));
  }
  std::string error;
  return write_png(image, path, &error);
}

std::string program_name() {
  const char* name = program_invocation_short_name;  // glibc: argv[0] without its folder
  return name && *name ? name : "the program";
}

}  // namespace

void write_scene(FrameCapture& f, bool ended) {
  f.written = true;
  namespace fs = std::filesystem;
  const fs::path scene_path(f.path);
  const std::string stem = scene_path.stem().string();
  std::size_t clamped = 0;
  std::string objects;
  glm::vec3 sum(0.0f);
  std::size_t count = 0;
  for (std::size_t i = 0; i < f.objects.size(); ++i) {
    const Object& o = f.objects[i];
    const std::string file = stem + "-" + std::to_string(i + 1) + ".obj";
    if (!write_text((scene_path.parent_path() / file).string(), obj_text(o))) return;
    for (const glm::vec3& p : o.positions) sum += p, ++count;
    const char* cull = o.key.cull == CullMode::kBack ? "back" : o.key.cull == CullMode::kFront ? "front" : "none";
    const char* blend = o.key.blend == Blend::kAlpha ? "alpha" : o.key.blend == Blend::kAdditive ? "additive" : "none";
    objects += std::string(i ? ",\n" : "") + "    {\"name\": " + json_string("draw " + std::to_string(o.first_draw)) +
               ", \"shape\": {\"type\": \"mesh\", \"file\": " + json_string(file) + "}";
    if (o.key.lit) {
      objects += ",\n     \"material\": " + material_json(o.key.front, clamped);
      if (f.model.two_side) objects += ",\n     \"back_material\": " + material_json(o.key.back, clamped);
    } else {
      objects += ", \"lighting\": false";
    }
    if (o.key.texture >= 0) {
      const std::string png = stem + "-texture-" + std::to_string(o.key.texture + 1) + ".png";
      objects += ",\n     \"texture\": " +
                 texture_json(f.textures[std::size_t(o.key.texture)], o.key.env, png, f.omitted.texture_settings);
    }
    objects += ",\n     \"shading\": \"" + std::string(o.key.flat ? "flat" : "gouraud") + "\", \"cull\": \"" + cull +
               "\", \"blend\": \"" + blend + "\"}";
  }
  for (std::size_t i = 0; i < f.textures.size(); ++i) {
    const std::string png = stem + "-texture-" + std::to_string(i + 1) + ".png";
    if (!write_texture_png(f.textures[i], (scene_path.parent_path() / png).string())) return;
  }
  // The camera looks at the middle of what was drawn (where the lab's orbit turns).
  float depth = count ? -sum.z / float(count) : 1.0f;
  if (!(depth > 1e-3f) || !std::isfinite(depth)) depth = 1.0f;
  int last_light = -1;
  for (int i = 0; i < kMaxLights; ++i) {
    if (f.lights[std::size_t(i)].enabled) last_light = i;
  }
  std::string lights;
  for (int i = 0; i <= last_light && f.have_lights; ++i) {
    lights += std::string(i ? ",\n    " : "    ") + light_json(f.lights[std::size_t(i)], clamped);
  }
  const std::string body_end = omissions(f, clamped);
  std::string caption = "Frame " + std::to_string(f.frame) + " of " + program_name() + ", captured by shadelab: " +
                        plural(f.triangles, "triangle", "triangles") + " in " + plural(f.objects.size(), "object", "objects") +
                        " (one per material), in the program's eye space." +
                        (ended ? "" : " The frame did not end: this is what it had drawn when the program stopped.") + body_end;
  const Viewport& vp = f.viewport;
  std::string s = "{\n  \"caption\": " + json_string(caption) + ",\n";
  s += "  \"image\": {\"width\": " + std::to_string(std::clamp(vp.width, 1, 16384)) + ", \"height\": " +
       std::to_string(std::clamp(vp.height, 1, 16384)) + ", \"background\": " + color(f.background, clamped) + "},\n";
  s += "  \"camera\": " + camera_json(f, depth) + ",\n";
  s += "  \"light_model\": {\"ambient\": " + color(f.model.ambient, clamped, false) + ", \"local_viewer\": " +
       (f.model.local_viewer ? "true" : "false") + ", \"two_side\": " + (f.model.two_side ? "true" : "false") +
       ", \"separate_specular\": " + (f.model.separate_specular ? "true" : "false") + "},\n";
  s += "  \"lights\": [\n" + lights + "\n  ],\n";
  s += "  \"objects\": [\n" + objects + "\n  ]\n}\n";
  write_text(f.path, s);
}

}  // namespace shadelab::gl
