// Scene files: JSON (docs/scene-format.md) into a validated Scene. All problems are collected
// with their locations; meshes are built only after their size has been checked.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/reader.hpp"
#include "shadelab/image.hpp"
#include "shadelab/materials.hpp"
#include "shadelab/scene_io.hpp"
#include "shadelab/shapes.hpp"

namespace shadelab {

using detail::JsonValue;
using detail::join_path;
using detail::index_path;
using Type = JsonValue::Type;

namespace {

const std::vector<std::string> kShapes = {"teapot", "sphere", "cylinder", "cone", "torus", "cube",
                                          "tetrahedron", "wall", "plane", "disk", "mesh"};

class SceneReader {
 public:
  SceneReader(Diagnostics& d, std::string base_dir, const LoadOptions& o)
      : r_(d), diags_(d), base_dir_(std::move(base_dir)), options_(o) {}

  void read(const JsonValue& root, Scene& s) {
    if (!r_.object(root, "", {"caption", "image", "camera", "light_model", "lights", "materials", "objects", "shadows", "transparency"})) return;
    if (int t = r_.choice(root, "transparency", "", {"sorted", "exact"}); t >= 0) {
      s.transparency = Scene::Transparency(t);
    }
    if (const JsonValue* c = root.find("caption"); c && r_.is_type(*c, Type::kString, "caption")) s.caption = c->text;
    if (const JsonValue* v = root.find("image")) image(*v, s);
    if (const JsonValue* v = root.find("camera")) camera(*v, s.camera);
    if (const JsonValue* v = root.find("light_model")) light_model(*v, s.light_model);
    if (const JsonValue* v = root.find("lights")) lights(*v, s);
    if (const JsonValue* v = root.find("materials")) materials(*v);
    if (const JsonValue* v = root.find("objects")) objects(*v, s);
    if (const JsonValue* v = root.find("shadows")) shadows(*v, s);
  }

 private:
  detail::Reader r_;
  Diagnostics& diags_;
  std::string base_dir_;
  const LoadOptions& options_;
  std::map<std::string, Material> materials_;
  std::map<std::string, std::shared_ptr<const Mesh>> meshes_;
  std::map<std::string, std::shared_ptr<const Texture>> textures_;
  long long triangles_ = 0;

  void image(const JsonValue& v, Scene& s) {
    if (!r_.object(v, "image", {"width", "height", "background", "samples"})) return;
    r_.integer(v, "width", "image", s.width, 1, 16384);
    r_.integer(v, "height", "image", s.height, 1, 16384);
    r_.color(v, "background", "image", s.background, 0, 1);
    if (const JsonValue* n = v.find("samples")) {
      int samples = 1;
      r_.integer(v, "samples", "image", samples, 1, 64);
      int root = int(std::lround(std::sqrt(double(samples))));
      if (root * root != samples) {
        r_.error(*n, "image.samples", "expected a square number (1, 4, 9, 16, 25, 36, 49, 64), got " +
                                          detail::format_number(n->number));
      } else {
        s.samples = samples;
      }
    }
    long long grid = std::lround(std::sqrt(double(s.samples)));
    if ((long long)s.width * s.height * grid * grid > options_.max_pixels) {
      r_.error(v, "image", "the image has " + std::to_string((long long)s.width * s.height * grid * grid) +
                               " samples, more than the limit of " + std::to_string(options_.max_pixels));
    }
  }

  void camera(const JsonValue& v, Camera& c) {
    if (!r_.object(v, "camera", {"eye", "target", "up", "projection", "fovy", "ortho_height", "near", "far"})) return;
    r_.vec3(v, "eye", "camera", c.eye);
    r_.vec3(v, "target", "camera", c.target);
    r_.vec3(v, "up", "camera", c.up);
    int p = r_.choice(v, "projection", "camera", {"perspective", "orthographic"});
    if (p >= 0) c.projection = p == 0 ? Camera::Projection::kPerspective : Camera::Projection::kOrthographic;
    r_.number(v, "fovy", "camera", c.fovy_degrees, 0.01, 179.0, "(0.01..179)");
    r_.positive(v, "ortho_height", "camera", c.ortho_height);
    r_.positive(v, "near", "camera", c.near_plane);
    r_.positive(v, "far", "camera", c.far_plane);
    if (const JsonValue* f = v.find("far"); f && c.far_plane <= c.near_plane) {
      r_.error(*f, "camera.far", "must be greater than near (" + detail::format_number(c.near_plane) + ")");
    }
    glm::vec3 dir = c.target - c.eye;
    if (glm::length(dir) == 0.0f || glm::length(glm::cross(dir, c.up)) < 1e-6f * glm::length(dir) * glm::length(c.up)) {
      r_.error(v, "camera", "eye, target and up must give a view direction not parallel to up");
    }
  }

  void light_model(const JsonValue& v, LightModel& m) {
    if (!r_.object(v, "light_model", {"ambient", "local_viewer", "two_side", "separate_specular"})) return;
    r_.color(v, "ambient", "light_model", m.ambient, -1e6, 1e6);
    r_.boolean(v, "local_viewer", "light_model", m.local_viewer);
    r_.boolean(v, "two_side", "light_model", m.two_side);
    r_.boolean(v, "separate_specular", "light_model", m.separate_specular);
  }

  void lights(const JsonValue& v, Scene& s) {
    if (!r_.is_type(v, Type::kArray, "lights")) return;
    if (int(v.items.size()) > options_.max_lights) {
      r_.error(v, "lights", std::to_string(v.items.size()) + " lights, more than the limit of " +
                                std::to_string(options_.max_lights));
      return;
    }
    for (std::size_t i = 0; i < v.items.size(); ++i) s.lights.push_back(light(v.items[i], index_path("lights", i), int(i)));
  }

  SceneLight light(const JsonValue& v, const std::string& path, int index) {
    SceneLight sl;
    sl.light = default_light(index);
    Light& l = sl.light;
    if (!r_.object(v, path, {"position", "ambient", "diffuse", "specular", "attenuation", "spot", "enabled", "space",
                             "shadow", "shadow_bias", "shadow_map_size", "shadow_pcf"})) return sl;
    r_.boolean(v, "shadow", path, sl.shadow);
    r_.number(v, "shadow_bias", path, sl.shadow_bias, 0, 1, "(0..1, in window depth units)");
    r_.integer(v, "shadow_map_size", path, sl.shadow_map_size, 16, 8192);
    r_.integer(v, "shadow_pcf", path, sl.shadow_pcf, 0, 4);
    r_.vec4(v, "position", path, l.position);
    r_.color(v, "ambient", path, l.ambient, -1e6, 1e6);
    r_.color(v, "diffuse", path, l.diffuse, -1e6, 1e6);
    r_.color(v, "specular", path, l.specular, -1e6, 1e6);
    r_.boolean(v, "enabled", path, l.enabled);
    int space = r_.choice(v, "space", path, {"world", "eye"});
    sl.eye_space = space == 1;
    if (const JsonValue* a = v.find("attenuation")) {
      std::string p = join_path(path, "attenuation");
      if (r_.object(*a, p, {"constant", "linear", "quadratic"})) {
        r_.number(*a, "constant", p, l.constant_attenuation, 0, 1e30, "(0 or more)");
        r_.number(*a, "linear", p, l.linear_attenuation, 0, 1e30, "(0 or more)");
        r_.number(*a, "quadratic", p, l.quadratic_attenuation, 0, 1e30, "(0 or more)");
        if (l.constant_attenuation == 0 && l.linear_attenuation == 0 && l.quadratic_attenuation == 0) {
          r_.error(*a, p, "constant, linear and quadratic are all 0: the light would be infinitely bright");
        }
      }
    }
    if (const JsonValue* sp = v.find("spot")) {
      std::string p = join_path(path, "spot");
      if (r_.object(*sp, p, {"direction", "cutoff", "exponent"})) {
        r_.vec3(*sp, "direction", p, l.spot_direction);
        if (const JsonValue* d = sp->find("direction"); d && glm::length(l.spot_direction) == 0.0f) {
          r_.error(*d, join_path(p, "direction"), "must not be the zero vector");
        }
        r_.number(*sp, "cutoff", p, l.spot_cutoff, 0, 90, "(0..90, or 180)", 180.0);
        r_.number(*sp, "exponent", p, l.spot_exponent, 0, 128, "(0..128)");
      }
    }
    return sl;
  }

  void materials(const JsonValue& v) {
    if (!r_.is_type(v, Type::kObject, "materials")) return;
    for (const auto& [name, m] : v.members) materials_[name] = material_object(m, join_path("materials", name));
  }

  Material material_object(const JsonValue& v, const std::string& path) {
    Material m;
    if (!r_.object(v, path, {"ambient", "diffuse", "specular", "emission", "shininess", "specular_model",
                             "diffuse_model", "roughness"})) return m;
    r_.color(v, "ambient", path, m.ambient, 0, 1);
    r_.color(v, "diffuse", path, m.diffuse, 0, 1);
    r_.color(v, "specular", path, m.specular, 0, 1);
    r_.color(v, "emission", path, m.emission, 0, 1);
    r_.number(v, "shininess", path, m.shininess, 0, 128, "(0..128)");
    if (int s = r_.choice(v, "specular_model", path, {"blinn", "phong"}); s >= 0) {
      m.specular_model = s == 0 ? SpecularModel::kBlinn : SpecularModel::kPhong;
    }
    if (int d = r_.choice(v, "diffuse_model", path, {"lambert", "oren-nayar"}); d >= 0) {
      m.diffuse_model = d == 0 ? DiffuseModel::kLambert : DiffuseModel::kOrenNayar;
    }
    r_.number(v, "roughness", path, m.roughness, 0, 1.5707964, "(0..1.5707964 radians)");
    return m;
  }

  // A material by name (the scene's own first, then the presets) or inline.
  Material material(const JsonValue& v, const std::string& path) {
    if (v.type == Type::kObject) return material_object(v, path);
    if (!r_.is_type(v, Type::kString, path)) return {};
    if (auto it = materials_.find(v.text); it != materials_.end()) return it->second;
    if (auto preset = find_material_preset(v.text)) return *preset;
    std::vector<std::string> names = material_preset_names();
    for (const auto& [n, m] : materials_) names.push_back(n);
    std::string near = nearest_match(v.text, names);
    r_.error(v, path, "unknown material \"" + v.text + "\"" + (near.empty() ? "" : " (did you mean \"" + near + "\"?)"));
    return {};
  }

  void objects(const JsonValue& v, Scene& s) {
    if (!r_.is_type(v, Type::kArray, "objects")) return;
    for (std::size_t i = 0; i < v.items.size(); ++i) object(v.items[i], index_path("objects", i), s);
  }

  void object(const JsonValue& v, const std::string& path, Scene& s) {
    if (!r_.object(v, path, {"name", "shape", "transform", "material", "back_material", "shading", "cull",
                             "blend", "lighting", "color", "texture"})) return;
    SceneObject o;
    o.name = path;
    if (const JsonValue* n = v.find("name"); n && r_.is_type(*n, Type::kString, join_path(path, "name"))) o.name = n->text;
    if (const JsonValue* m = v.find("material")) o.front = material(*m, join_path(path, "material"));
    if (const JsonValue* m = v.find("back_material")) o.back = material(*m, join_path(path, "back_material"));
    if (int sh = r_.choice(v, "shading", path, {"flat", "gouraud", "phong"}); sh >= 0) o.shading = ShadingMode(sh);
    if (int c = r_.choice(v, "cull", path, {"none", "back", "front"}); c >= 0) o.cull = CullMode(c);
    int blend = r_.choice(v, "blend", path, {"auto", "none", "alpha", "additive"});
    r_.boolean(v, "lighting", path, o.lighting);
    r_.color(v, "color", path, o.color, 0, 1);
    if (const JsonValue* t = v.find("transform")) o.model = transform(*t, join_path(path, "transform"));
    if (const JsonValue* t = v.find("texture")) texture(*t, join_path(path, "texture"), o);
    bool translucent = o.lighting ? o.front.diffuse.a < 1.0f : o.color.a < 1.0f;
    if (blend == 2 || ((blend <= 0) && translucent)) o.blend = {true, BlendFactor::kSrcAlpha, BlendFactor::kOneMinusSrcAlpha};
    if (blend == 3) o.blend = {true, BlendFactor::kOne, BlendFactor::kOne};
    const JsonValue* shape = v.find("shape");
    if (!shape) {
      r_.error(v, path, "missing required key \"shape\"");
      return;
    }
    o.mesh = mesh(*shape, join_path(path, "shape"));
    if (o.mesh) s.objects.push_back(std::move(o));
  }

  glm::mat4 transform(const JsonValue& v, const std::string& path) {
    glm::mat4 m(1.0f);
    if (!r_.object(v, path, {"translate", "rotate", "scale", "matrix"})) return m;
    if (const JsonValue* mat = v.find("matrix")) {
      std::vector<double> n;
      if (r_.numbers(*mat, join_path(path, "matrix"), n, 16)) {
        float f[16];
        for (int i = 0; i < 16; ++i) f[i] = float(n[i]);
        m = glm::make_mat4(f);  // column-major, as glMultMatrixf
      }
    }
    glm::vec3 t(0.0f);
    r_.vec3(v, "translate", path, t);
    m = m * glm::translate(glm::mat4(1.0f), t);
    if (const JsonValue* rot = v.find("rotate")) {
      std::string p = join_path(path, "rotate");
      bool list = rot->type == Type::kArray && !rot->items.empty() && rot->items[0].type == Type::kArray;
      std::vector<const JsonValue*> rs;
      if (list) for (const JsonValue& x : rot->items) rs.push_back(&x);
      else rs.push_back(rot);
      for (std::size_t i = 0; i < rs.size(); ++i) {
        std::vector<double> n;
        std::string pi = list ? index_path(p, i) : p;
        if (!r_.numbers(*rs[i], pi, n, 4)) continue;
        glm::vec3 axis{float(n[1]), float(n[2]), float(n[3])};
        if (glm::length(axis) == 0.0f) {
          r_.error(*rs[i], pi, "the rotation axis must not be the zero vector");
          continue;
        }
        m = glm::rotate(m, glm::radians(float(n[0])), axis);
      }
    }
    if (const JsonValue* sc = v.find("scale")) {
      std::string p = join_path(path, "scale");
      glm::vec3 s(1.0f);
      std::vector<double> n;
      if (sc->type == Type::kNumber) s = glm::vec3(float(sc->number));
      else if (r_.numbers(*sc, p, n, 3)) s = glm::vec3(float(n[0]), float(n[1]), float(n[2]));
      if (s.x == 0.0f || s.y == 0.0f || s.z == 0.0f) r_.error(*sc, p, "scale factors must not be 0");
      else m = glm::scale(m, s);
    }
    return m;
  }

  // "texture": "file.png" or {"file", "wrap", "filter", "env"}: glTexImage2D + glTexParameter
  // + glTexEnv. Mipmaps are built for the mipmapped filters (the default is trilinear).
  void texture(const JsonValue& v, const std::string& path, SceneObject& o) {
    JsonValue named;
    const JsonValue* t = &v;
    if (v.type == Type::kString) {
      named.type = Type::kObject;
      named.location = v.location;
      named.members.emplace_back("file", v);
      named.key_locations.push_back(v.location);
      t = &named;
    }
    if (!r_.object(*t, path, {"file", "wrap", "filter", "env", "repeat"})) return;
    if (const JsonValue* rep = t->find("repeat")) {
      std::vector<double> n;
      if (r_.numbers(*rep, join_path(path, "repeat"), n, 2, -1, -1e6, 1e6)) o.texture_repeat = {float(n[0]), float(n[1])};
    }
    const JsonValue* f = t->find("file");
    if (!f) {
      r_.error(*t, path, "missing required key \"file\"");
      return;
    }
    std::string fpath = v.type == Type::kString ? path : join_path(path, "file");
    if (!r_.is_type(*f, Type::kString, fpath)) return;
    auto tex = std::make_shared<Texture>();
    int wrap = r_.choice(*t, "wrap", path, {"repeat", "clamp", "clamp_to_edge"});
    if (wrap >= 0) tex->wrap_s = tex->wrap_t = TextureWrap(wrap);
    int filter = r_.choice(*t, "filter", path, {"nearest", "linear", "bilinear_mipmap", "trilinear"});
    const TextureFilter filters[] = {TextureFilter::kNearest, TextureFilter::kLinear,
                                     TextureFilter::kLinearMipmapNearest, TextureFilter::kLinearMipmapLinear};
    tex->min_filter = filter >= 0 ? filters[filter] : TextureFilter::kLinearMipmapLinear;
    tex->mag_filter = filter == 0 ? TextureFilter::kNearest : TextureFilter::kLinear;
    int env = r_.choice(*t, "env", path, {"modulate", "replace", "decal", "blend"});
    if (env >= 0) o.texture_env = TextureEnvMode(env);
    std::string full = (std::filesystem::path(base_dir_) / f->text).string();
    std::string key = full + "|" + std::to_string(wrap) + "|" + std::to_string(filter);
    if (auto it = textures_.find(key); it != textures_.end()) {
      o.texture = it->second;
      return;
    }
    Image img;
    std::string error;
    if (!read_image(full, img, &error)) {
      r_.error(*f, fpath, error);
      return;
    }
    if (img.width > 8192 || img.height > 8192) {
      r_.error(*f, fpath, "texture is " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                              ", more than the limit of 8192x8192");
      return;
    }
    // Image rows run top down; texture row 0 is t = 0, the bottom of the picture.
    TextureLevel level{img.width, img.height, {}};
    for (int y = img.height - 1; y >= 0; --y) {
      level.rgba.insert(level.rgba.end(), img.pixel(0, y), img.pixel(0, y) + std::size_t(img.width) * 4);
    }
    tex->levels.push_back(std::move(level));
    generate_mipmaps(*tex);
    o.texture = textures_[key] = std::move(tex);
  }

  void shadows(const JsonValue& v, Scene& s) {
    if (!r_.is_type(v, Type::kArray, "shadows")) return;
    std::vector<std::string> names;
    for (const SceneObject& o : s.objects) names.push_back(o.name);
    for (std::size_t i = 0; i < v.items.size() && i < 255; ++i) {
      const JsonValue& e = v.items[i];
      std::string path = index_path("shadows", i);
      if (!r_.object(e, path, {"plane", "light", "color", "receiver"})) continue;
      PlanarShadow sh;
      r_.vec4(e, "plane", path, sh.plane);
      if (const JsonValue* p = e.find("plane"); p && glm::length(glm::vec3(sh.plane)) == 0.0f) {
        r_.error(*p, join_path(path, "plane"), "(a, b, c) must not be the zero vector");
      }
      r_.integer(e, "light", path, sh.light, 0, std::max(0, int(s.lights.size()) - 1));
      if (s.lights.empty()) r_.error(e, path, "a shadow needs a light, and the scene has none");
      r_.color(e, "color", path, sh.color, 0, 1);
      const JsonValue* rec = e.find("receiver");
      if (!rec) {
        r_.error(e, path, "missing required key \"receiver\"");
      } else if (r_.is_type(*rec, Type::kString, join_path(path, "receiver"))) {
        sh.receiver = rec->text;
        if (std::find(names.begin(), names.end(), rec->text) == names.end()) {
          std::string near = nearest_match(rec->text, names);
          r_.error(*rec, join_path(path, "receiver"), "no object named \"" + rec->text + "\"" +
                                                          (near.empty() ? "" : " (did you mean \"" + near + "\"?)"));
        }
      }
      s.shadows.push_back(sh);
    }
    if (v.items.size() > 255) r_.error(v, "shadows", "at most 255 shadows");
  }

  bool count(const JsonValue& at, const std::string& path, long long triangles) {
    triangles_ += triangles;
    if (triangles_ > options_.max_triangles) {
      r_.error(at, path, "the scene would have " + std::to_string(triangles_) +
                             " triangles, more than the limit of " + std::to_string(options_.max_triangles));
      return false;
    }
    return true;
  }

  std::shared_ptr<const Mesh> mesh(const JsonValue& v, const std::string& path) {
    JsonValue typed;
    const JsonValue* params = &v;
    std::string type;
    if (v.type == Type::kString) {
      type = v.text;
    } else if (v.type == Type::kObject) {
      const JsonValue* t = v.find("type");
      if (!t) {
        r_.error(v, path, "missing required key \"type\"");
        return nullptr;
      }
      if (!r_.is_type(*t, Type::kString, join_path(path, "type"))) return nullptr;
      type = t->text;
    } else {
      r_.error(v, path, "expected a shape name or an object with \"type\", got " + v.type_name());
      return nullptr;
    }
    const JsonValue& at = v.type == Type::kString ? v : *v.find("type");
    if (std::find(kShapes.begin(), kShapes.end(), type) == kShapes.end()) {
      std::string near = nearest_match(type, kShapes);
      r_.error(at, v.type == Type::kString ? path : join_path(path, "type"),
               "unknown shape \"" + type + "\"" + (near.empty() ? "" : " (did you mean \"" + near + "\"?)"));
      return nullptr;
    }
    if (v.type == Type::kString) {
      typed.type = Type::kObject;
      typed.location = v.location;
      params = &typed;
    }
    return build_shape(type, *params, path);
  }

  std::shared_ptr<const Mesh> build_shape(const std::string& type, const JsonValue& p, const std::string& path);
};

std::shared_ptr<const Mesh> SceneReader::build_shape(const std::string& type, const JsonValue& p,
                                                     const std::string& path) {
  auto keys = [&](std::vector<std::string> k) {
    k.push_back("type");
    return r_.object(p, path, k);
  };
  std::size_t errors = diags_.size();
  auto done = [&](Mesh m) -> std::shared_ptr<const Mesh> {
    return std::make_shared<const Mesh>(std::move(m));
  };
  if (type == "teapot") {
    TeapotParams t;
    if (!keys({"size", "tessellation"})) return nullptr;
    r_.positive(p, "size", path, t.size);
    r_.integer(p, "tessellation", path, t.tessellation, 1, 64);
    if (diags_.size() != errors || !count(p, path, 32LL * 2 * t.tessellation * t.tessellation)) return nullptr;
    return done(make_teapot(t));
  }
  if (type == "sphere") {
    SphereParams s;
    if (!keys({"radius", "slices", "stacks"})) return nullptr;
    r_.positive(p, "radius", path, s.radius);
    r_.integer(p, "slices", path, s.slices, 3, 4096);
    r_.integer(p, "stacks", path, s.stacks, 2, 4096);
    if (diags_.size() != errors || !count(p, path, 2LL * s.slices * s.stacks)) return nullptr;
    return done(make_sphere(s));
  }
  if (type == "cylinder") {
    CylinderParams c;
    if (!keys({"radius", "height", "slices", "stacks", "caps", "angle_colors"})) return nullptr;
    r_.positive(p, "radius", path, c.radius);
    r_.positive(p, "height", path, c.height);
    r_.integer(p, "slices", path, c.slices, 3, 4096);
    r_.integer(p, "stacks", path, c.stacks, 1, 4096);
    r_.boolean(p, "caps", path, c.caps);
    r_.boolean(p, "angle_colors", path, c.angle_colors);
    if (diags_.size() != errors || !count(p, path, 2LL * c.slices * (c.stacks + 2))) return nullptr;
    return done(make_cylinder(c));
  }
  if (type == "cone") {
    ConeParams c;
    if (!keys({"radius", "height", "slices", "stacks", "cap"})) return nullptr;
    r_.positive(p, "radius", path, c.radius);
    r_.positive(p, "height", path, c.height);
    r_.integer(p, "slices", path, c.slices, 3, 4096);
    r_.integer(p, "stacks", path, c.stacks, 1, 4096);
    r_.boolean(p, "cap", path, c.cap);
    if (diags_.size() != errors || !count(p, path, 2LL * c.slices * (c.stacks + 1))) return nullptr;
    return done(make_cone(c));
  }
  if (type == "torus") {
    TorusParams t;
    if (!keys({"major_radius", "minor_radius", "sides", "rings"})) return nullptr;
    r_.positive(p, "major_radius", path, t.major_radius);
    r_.positive(p, "minor_radius", path, t.minor_radius);
    r_.integer(p, "sides", path, t.sides, 3, 4096);
    r_.integer(p, "rings", path, t.rings, 3, 4096);
    if (diags_.size() != errors || !count(p, path, 2LL * t.sides * t.rings)) return nullptr;
    return done(make_torus(t));
  }
  if (type == "cube" || type == "tetrahedron") {
    float size = 1.0f;
    if (!keys(type == "cube" ? std::vector<std::string>{"size"} : std::vector<std::string>{})) return nullptr;
    r_.positive(p, "size", path, size);
    if (diags_.size() != errors || !count(p, path, 12)) return nullptr;
    return done(type == "cube" ? make_cube(size) : make_tetrahedron());
  }
  if (type == "wall") {
    WallParams w;
    if (!keys({"width", "height", "nx", "ny"})) return nullptr;
    r_.positive(p, "width", path, w.width);
    r_.positive(p, "height", path, w.height);
    r_.integer(p, "nx", path, w.nx, 1, 4096);
    r_.integer(p, "ny", path, w.ny, 1, 4096);
    if (diags_.size() != errors || !count(p, path, 2LL * w.nx * w.ny)) return nullptr;
    return done(make_wall(w));
  }
  if (type == "plane") {
    float size = 10.0f;
    int n = 1;
    if (!keys({"size", "n"})) return nullptr;
    r_.positive(p, "size", path, size);
    r_.integer(p, "n", path, n, 1, 4096);
    if (diags_.size() != errors || !count(p, path, 2LL * n * n)) return nullptr;
    return done(make_plane(size, n));
  }
  if (type == "disk") {
    DiskParams d;
    if (!keys({"inner_radius", "outer_radius", "slices", "loops"})) return nullptr;
    r_.number(p, "inner_radius", path, d.inner_radius, 0, 1e9, "(0 or more)");
    r_.positive(p, "outer_radius", path, d.outer_radius, d.inner_radius);
    r_.integer(p, "slices", path, d.slices, 3, 4096);
    r_.integer(p, "loops", path, d.loops, 1, 4096);
    if (diags_.size() != errors || !count(p, path, 2LL * d.slices * d.loops)) return nullptr;
    return done(make_disk(d));
  }
  // mesh
  if (!keys({"file"})) return nullptr;
  const JsonValue* f = p.find("file");
  if (!f) {
    r_.error(p, path, "missing required key \"file\"");
    return nullptr;
  }
  if (!r_.is_type(*f, Type::kString, join_path(path, "file"))) return nullptr;
  std::string full = (std::filesystem::path(base_dir_) / f->text).string();
  if (auto it = meshes_.find(full); it != meshes_.end()) return it->second;
  Mesh m;
  Diagnostics mesh_diags;
  if (!load_obj(full, m, mesh_diags)) {
    for (const Diagnostic& d : mesh_diags.items()) r_.error(*f, join_path(path, "file"), d.location.file + ": " + d.message);
    return nullptr;
  }
  if (!count(*f, join_path(path, "file"), (long long)m.triangles.size())) return nullptr;
  return meshes_[full] = done(std::move(m));
}

}  // namespace

LoadResult parse_scene(std::string_view text, const std::string& filename, const std::string& base_dir,
                       const LoadOptions& options) {
  LoadResult result;
  detail::JsonValue root;
  if (!detail::parse_json(text, filename, root, result.diagnostics)) return result;
  for (const std::string& o : options.overrides) detail::apply_override(root, o, result.diagnostics);
  if (!result.diagnostics.empty()) return result;
  Scene scene;
  SceneReader reader(result.diagnostics, base_dir, options);
  reader.read(root, scene);
  if (result.diagnostics.empty()) result.scene = std::move(scene);
  return result;
}

LoadResult load_scene_file(const std::string& path, const LoadOptions& options) {
  std::ifstream f(path, std::ios::binary);
  if (!f || std::filesystem::is_directory(path)) {
    LoadResult r;
    r.diagnostics.error({path, 0, 0}, "", std::string("cannot open scene file: ") +
                                              (f ? "Is a directory" : std::strerror(errno)));
    return r;
  }
  std::stringstream s;
  s << f.rdbuf();
  std::string base = std::filesystem::path(path).parent_path().string();
  return parse_scene(s.str(), path, base.empty() ? "." : base, options);
}

}  // namespace shadelab
