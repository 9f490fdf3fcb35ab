// A frame kept as a scene file (capture.hpp): the variables read, the chosen frame's draws
// recorded, its triangles grouped into objects by what lit them (a new material, shading,
// culling or blending starts another), and the frame's end counted (capture_scene.cpp writes
// it).
#include "gl/src/capture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>

#include <glm/common.hpp>

#include "gl/src/capture_frame.hpp"
#include "shadelab/pipeline.hpp"

namespace shadelab::gl {

namespace {

// Beyond this many triangles in a frame the rest are counted, not kept (the scene reader's
// own limit is 20,000,000).
constexpr std::size_t kMaxTriangles = 5'000'000;
// Beyond this many distinct materials (colour material with a colour per vertex), triangles
// join the object whose material is nearest.
constexpr std::size_t kMaxObjects = 512;

}  // namespace

void FrameCaptureDeleter::operator()(FrameCapture* f) const { delete f; }

namespace {

bool recording(const GlContext& c) {
  const FrameCapture* f = c.capture.get();
  return f && !f->written && f->ended + 1 == f->frame;
}

bool same_lights(const std::array<Light, kMaxLights>& a, const std::array<Light, kMaxLights>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Light& x = a[i];
    const Light& y = b[i];
    if (x.enabled != y.enabled) return false;
    if (!x.enabled) continue;
    if (x.ambient != y.ambient || x.diffuse != y.diffuse || x.specular != y.specular || x.position != y.position ||
        x.spot_direction != y.spot_direction || x.spot_exponent != y.spot_exponent || x.spot_cutoff != y.spot_cutoff ||
        x.constant_attenuation != y.constant_attenuation || x.linear_attenuation != y.linear_attenuation ||
        x.quadratic_attenuation != y.quadratic_attenuation)
      return false;
  }
  return true;
}

float material_distance(const Material& a, const Material& b) {
  glm::vec4 d = glm::abs(a.ambient - b.ambient) + glm::abs(a.diffuse - b.diffuse) + glm::abs(a.specular - b.specular) +
                glm::abs(a.emission - b.emission);
  return d.x + d.y + d.z + d.w + std::fabs(a.shininess - b.shininess) / 128.0f;
}

// The object triangles of `key` go into: the same key's, a new one, or past kMaxObjects the
// nearest material's.
Object& object_for(FrameCapture& f, const ObjectKey& key) {
  for (Object& o : f.objects) {
    if (o.key == key) return o;
  }
  if (f.objects.size() >= kMaxObjects) {
    Object* best = nullptr;
    float best_d = 0.0f;
    for (Object& o : f.objects) {
      if (o.key.lit != key.lit || o.key.flat != key.flat || o.key.cull != key.cull || o.key.blend != key.blend) continue;
      const float d = material_distance(o.key.front, key.front) + material_distance(o.key.back, key.back);
      if (!best || d < best_d) best = &o, best_d = d;
    }
    if (best) {
      ++f.omitted.merged;
      return *best;
    }
  }
  Object& o = f.objects.emplace_back();
  o.key = key;
  o.first_draw = f.draws;
  return o;
}

Blend blend_of(const GlContext& c, Omitted& omitted) {
  const RasterState& r = c.raster;
  if (!r.blend) return Blend::kNone;
  const bool rgb_add = r.blend_equation == GL_FUNC_ADD;
  if (rgb_add && r.blend_src == GL_SRC_ALPHA && r.blend_dst == GL_ONE_MINUS_SRC_ALPHA) return Blend::kAlpha;
  if (rgb_add && r.blend_src == GL_ONE && r.blend_dst == GL_ONE) return Blend::kAdditive;
  ++omitted.blend_other;
  return Blend::kAlpha;
}

// Texture unit 0's texture as the scene can hold it (a complete 2D colour texture), copied the
// first time a draw of the frame reads it; -1 when there is none. Draws textured by other units
// count as approximated.
int captured_texture(FrameCapture& f, const ShadeState& shade) {
  for (std::size_t u = 1; u < shade.textures.size(); ++u) {
    if (shade.textures[u].texture) {
      ++f.omitted.more_units;
      break;
    }
  }
  const Texture* t = shade.textures[0].texture;
  if (!t) return -1;
  const std::size_t base = std::size_t(std::max(t->base_level, 0));
  if (t->dimensions != 2 || t->cube_map || t->depth || base >= t->levels.size() || !t->complete()) {
    ++f.omitted.textured;
    return -1;
  }
  for (std::size_t i = 0; i < f.textures.size(); ++i) {
    if (f.textures[i].source == t) return int(i);
  }
  const TextureLevel& level = t->levels[base];
  CapturedTexture& k = f.textures.emplace_back();
  k.source = t;
  k.width = level.width, k.height = level.height;
  k.rgba = level.rgba;
  k.wrap_s = t->wrap_s, k.wrap_t = t->wrap_t;
  k.min_filter = t->min_filter, k.mag_filter = t->mag_filter;
  k.border = t->border_color;
  return int(f.textures.size() - 1);
}

CullMode cull_of(const GlContext& c) {
  if (!c.raster.cull) return CullMode::kNone;
  return c.raster.cull_mode == GL_FRONT ? CullMode::kFront : CullMode::kBack;
}

}  // namespace

void capture_init(GlContext& c) {
  const char* path = std::getenv(kCaptureSceneVariable);
  if (!path || !*path) return;
  auto f = std::unique_ptr<FrameCapture, FrameCaptureDeleter>(new FrameCapture);
  f->path = path;
  if (const char* n = std::getenv(kCaptureFrameVariable)) {
    char* end = nullptr;
    const long v = std::strtol(n, &end, 10);
    if (end != n && *end == '\0' && v >= 1 && v <= (1L << 30)) f->frame = int(v);
  }
  c.capture = std::move(f);
}

bool capture_recording(const GlContext& c) { return recording(c); }

void capture_draw(GlContext& c, const ShadeState& shade, const VertexInput& in, bool lit,
                  std::span<const VertexMaterials> vertex_materials) {
  if (!recording(c)) return;
  FrameCapture& f = *c.capture;
  Omitted& om = f.omitted;
  ++f.draws;
  om.lines += in.lines.size();
  om.points += in.points.size();
  if (!in.triangle_flags.empty()) {  // polygons drawn as lines or points
    om.unfilled += in.triangles.size();
    return;
  }
  if (in.triangles.empty()) return;
  if (shade.fog.enabled) ++om.fogged;
  if (!c.raster.depth_test) ++om.no_depth_test;
  if (!f.have_view) {
    f.have_view = true;
    f.projection = c.projection.top();
    f.viewport = c.raster.viewport;
  } else if (f.projection != c.projection.top() || f.viewport.width != c.raster.viewport.width ||
             f.viewport.height != c.raster.viewport.height) {
    ++om.views_differ;
  }
  if (lit) {
    if (!f.have_lights) {
      f.have_lights = true;
      f.lights = c.lighting.lights;
      f.model = c.lighting.model;
    } else if (!same_lights(f.lights, c.lighting.lights)) {
      ++om.lights_differ;
    }
  }
  ObjectKey key;
  key.lit = lit;
  key.flat = shade.shading == ShadingMode::kFlat;
  key.cull = cull_of(c);
  key.blend = blend_of(c, om);
  if (lit && vertex_materials.empty()) key.front = shade.front, key.back = shade.back;
  key.texture = captured_texture(f, shade);
  key.env = shade.textures[0].env;
  const std::span<const glm::vec4> texcoords = in.texcoords[0];
  const bool clockwise = c.raster.front_face == GL_CW;  // scene triangles face front counter-clockwise
  const std::size_t n = in.positions.size();
  Object* current = nullptr;
  for (const Triangle& t : in.triangles) {
    if (f.triangles >= kMaxTriangles) {
      ++om.over_limit;
      continue;
    }
    bool behind = false;
    for (std::uint32_t v : t) behind = behind || !(in.positions[v].w > 0.0f);
    if (behind) {  // clipped by GL; a scene vertex is a point (x, y, z)
      ++om.behind_eye;
      continue;
    }
    if (lit && !vertex_materials.empty()) {
      const VertexMaterials& m = vertex_materials[t[2]];  // the provoking vertex's
      key.front = m.front;
      key.back = m.back;
      for (int k = 0; k < 2; ++k) {
        const VertexMaterials& other = vertex_materials[t[std::size_t(k)]];
        if (!ObjectKey::same(other.front, m.front) || !ObjectKey::same(other.back, m.back)) {
          ++om.mixed;
          break;
        }
      }
    }
    if (!current || !(current->key == key)) current = &object_for(f, key);
    Object& o = *current;
    if (o.remap_draw != f.draws) o.remap.assign(n, UINT32_MAX), o.remap_draw = f.draws;
    Triangle out;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = t[std::size_t(k)];
      if (o.remap[v] == UINT32_MAX) {
        o.remap[v] = std::uint32_t(o.positions.size());
        const glm::vec4& p = in.positions[v];
        o.positions.push_back(glm::vec3(p) / p.w);
        if (lit) o.normals.push_back(in.normals.empty() ? glm::vec3(0, 0, 1) : in.normals[v]);
        else o.colors.push_back(in.colors.empty() ? in.constant_color : in.colors[v]);
        if (key.texture >= 0) {
          const glm::vec4 tc = texcoords.empty() ? glm::vec4(0, 0, 0, 1) : texcoords[v];
          o.texcoords.push_back(tc.w != 0.0f ? glm::vec2(tc) / tc.w : glm::vec2(tc));
        }
      }
      out[std::size_t(k)] = o.remap[v];
    }
    if (clockwise) std::swap(out[0], out[1]);  // the last vertex still provokes
    o.triangles.push_back(out);
    ++f.triangles;
  }
}

void capture_pixels(GlContext& c) {
  if (recording(c)) ++c.capture->omitted.pixels;
}

void capture_clear(GlContext& c, GLbitfield mask, bool scissored) {
  if (!recording(c) || !(mask & GL_COLOR_BUFFER_BIT) || scissored) return;
  c.capture->restart();
  c.capture->background = glm::clamp(c.raster.clear_color, 0.0f, 1.0f);
}

void capture_frame_end(GlContext& c) {
  FrameCapture* f = c.capture.get();
  if (!f || f->written) return;
  if (recording(c) && f->draws > 0) write_scene(*f, true);
  ++f->ended;
  f->restart();
}

void capture_context_end(GlContext& c) {
  FrameCapture* f = c.capture.get();
  if (f && recording(c) && f->draws > 0) write_scene(*f, false);
}

}  // namespace shadelab::gl
