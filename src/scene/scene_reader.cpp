// The scene reader's top level: which keys a scene has, the image, the camera, the light
// model and the lights (OpenGL's defaults per light index, SPEC section 3).
#include "scene/scene_reader.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace shadelab::detail {

using Type = JsonValue::Type;

namespace {

// Light colours are intensities: any finite value (GL allows negative "dark" lights).
const Range kIntensity = closed(-1e6, 1e6);

// The member `key` of `obj` if present (and `path` extended to it), else `obj` itself.
const JsonValue& member_or_self(const JsonValue& obj, std::string_view key, std::string& path) {
  const JsonValue* m = obj.find(key);
  if (!m) return obj;
  path = join_path(path, key);
  return *m;
}

}  // namespace

void SceneReader::read(const JsonValue& root, Scene& s) {
  if (!r_.object(root, "", {"caption", "image", "camera", "light_model", "lights", "materials",
                            "objects", "shadows", "transparency"})) {
    return;
  }
  r_.string(root, "caption", "", s.caption);
  if (int t = r_.choice(root, "transparency", "", {"sorted", "exact"}); t >= 0) {
    s.transparency = Scene::Transparency(t);
  }
  if (const JsonValue* v = root.find("image")) image(*v, s);
  if (const JsonValue* v = root.find("camera")) camera(*v, s.camera);
  if (const JsonValue* v = root.find("light_model")) light_model(*v, s.light_model);
  if (const JsonValue* v = root.find("lights")) lights(*v, s);
  if (const JsonValue* v = root.find("materials")) materials(*v);  // before the objects use them
  if (const JsonValue* v = root.find("objects")) objects(*v, s);
  if (const JsonValue* v = root.find("shadows")) shadows(*v, s);  // after the objects it names
}

void SceneReader::image(const JsonValue& v, Scene& s) {
  if (!r_.object(v, "image", {"width", "height", "background", "samples"})) return;
  r_.integer(v, "width", "image", s.width, 1, 16384);
  r_.integer(v, "height", "image", s.height, 1, 16384);
  r_.color(v, "background", "image", s.background, closed(0, 1));
  samples(v, s);
  long long total = (long long)s.width * s.height * s.samples;
  if (total > options_.max_pixels) {
    std::string size = std::to_string(s.width) + " x " + std::to_string(s.height);
    r_.error(v, "image", (s.samples == 1 ? size + " = " + std::to_string(total) + " pixels"
                                         : size + " pixels x " + std::to_string(s.samples) +
                                               " samples = " + std::to_string(total)) +
                             ", more than the limit of " + std::to_string(options_.max_pixels));
  }
}

// Supersampling takes n x n samples per pixel: the count must be a square.
void SceneReader::samples(const JsonValue& v, Scene& s) {
  int samples = 1;
  if (!r_.integer(v, "samples", "image", samples, 1, 64)) return;
  int root = int(std::lround(std::sqrt(double(samples))));
  if (root * root != samples) {
    r_.error(*v.find("samples"), "image.samples",
             "expected a square number (1, 4, 9, 16, 25, 36, 49, 64), got " + std::to_string(samples));
    return;
  }
  s.samples = samples;
}

void SceneReader::camera(const JsonValue& v, Camera& c) {
  if (!r_.object(v, "camera", {"eye", "target", "up", "projection", "fovy", "ortho_height", "near",
                               "far", "projection_matrix"})) {
    return;
  }
  r_.vec3(v, "eye", "camera", c.eye);
  r_.vec3(v, "target", "camera", c.target);
  r_.vec3(v, "up", "camera", c.up);
  if (int p = r_.choice(v, "projection", "camera", {"perspective", "orthographic"}); p >= 0) {
    c.projection = Camera::Projection(p);
  }
  r_.number(v, "fovy", "camera", c.fovy_degrees, exclusive(0, 180));
  r_.number(v, "ortho_height", "camera", c.ortho_height, above(0));
  r_.number(v, "near", "camera", c.near_plane, above(0));
  r_.number(v, "far", "camera", c.far_plane, above(0));
  if (c.far_plane <= c.near_plane) {
    std::string path = "camera";
    const JsonValue& at = member_or_self(v, v.find("far") ? "far" : "near", path);
    r_.error(at, path, "far (" + format_number(c.far_plane) + ") must be greater than near (" +
                           format_number(c.near_plane) + ")");
  }
  check_view(v, c);
  projection_matrix(v, c);
}

// A column-major 4 x 4 matrix, as glLoadMatrixf takes it; it must be invertible.
void SceneReader::projection_matrix(const JsonValue& v, Camera& c) {
  const JsonValue* m = v.find("projection_matrix");
  if (!m) return;
  std::vector<double> values;
  const std::string path = "camera.projection_matrix";
  if (!r_.numbers(*m, path, values, 16, -1, closed(-kHuge, kHuge))) return;
  glm::mat4 p;
  for (int i = 0; i < 16; ++i) p[i / 4][i % 4] = float(values[std::size_t(i)]);
  const float det = glm::determinant(p);
  if (!(std::isfinite(det) && det != 0.0f)) {
    r_.error(*m, path, "the matrix is not invertible (it maps the view volume onto a plane)");
    return;
  }
  c.matrix = p;
}

// gluLookAt needs a view direction, and an up vector not along it.
void SceneReader::check_view(const JsonValue& v, const Camera& c) {
  glm::vec3 dir = c.target - c.eye;
  std::string path = "camera";
  if (glm::length(dir) == 0.0f) {
    const JsonValue& at = member_or_self(v, v.find("target") ? "target" : "eye", path);
    r_.error(at, path, "eye and target are the same point: there is no view direction");
    return;
  }
  float up = glm::length(c.up);
  if (up == 0.0f || !(glm::length(glm::cross(glm::normalize(dir), c.up)) > 1e-4f * up)) {
    r_.error(member_or_self(v, "up", path), path,
             "up is parallel to the view direction (from eye to target)");
  }
}

void SceneReader::light_model(const JsonValue& v, LightModel& m) {
  if (!r_.object(v, "light_model", {"ambient", "local_viewer", "two_side", "separate_specular"})) return;
  r_.color(v, "ambient", "light_model", m.ambient, kIntensity);
  r_.boolean(v, "local_viewer", "light_model", m.local_viewer);
  r_.boolean(v, "two_side", "light_model", m.two_side);
  r_.boolean(v, "separate_specular", "light_model", m.separate_specular);
}

void SceneReader::lights(const JsonValue& v, Scene& s) {
  if (!r_.is_type(v, Type::kArray, "lights")) return;
  if (v.items.size() > std::size_t(std::max(options_.max_lights, 0))) {
    r_.error(v, "lights", std::to_string(v.items.size()) + " lights, more than the limit of " +
                              std::to_string(options_.max_lights));
    return;
  }
  for (std::size_t i = 0; i < v.items.size(); ++i) {
    s.lights.push_back(light(v.items[i], index_path("lights", i), int(i)));
  }
}

SceneLight SceneReader::light(const JsonValue& v, const std::string& path, int index) {
  SceneLight sl;
  sl.light = default_light(index);  // GL_LIGHT0 is white, the others black
  Light& l = sl.light;
  if (!r_.object(v, path, {"position", "ambient", "diffuse", "specular", "attenuation", "spot",
                           "enabled", "space", "shadow", "shadow_bias", "shadow_map_size",
                           "shadow_pcf"})) {
    return sl;
  }
  if (r_.vec4(v, "position", path, l.position) && l.position.w == 0.0f &&
      glm::length(glm::vec3(l.position)) == 0.0f) {
    r_.error(*v.find("position"), join_path(path, "position"),
             "a directional light (w = 0) needs a direction: x, y, z must not all be 0");
  }
  r_.color(v, "ambient", path, l.ambient, kIntensity);
  r_.color(v, "diffuse", path, l.diffuse, kIntensity);
  r_.color(v, "specular", path, l.specular, kIntensity);
  r_.boolean(v, "enabled", path, l.enabled);
  sl.eye_space = r_.choice(v, "space", path, {"world", "eye"}) == 1;
  if (const JsonValue* a = v.find("attenuation")) attenuation(*a, join_path(path, "attenuation"), l);
  if (const JsonValue* sp = v.find("spot")) spot(*sp, join_path(path, "spot"), l);
  light_shadow(v, path, sl);
  return sl;
}

void SceneReader::attenuation(const JsonValue& v, const std::string& path, Light& l) {
  if (!r_.object(v, path, {"constant", "linear", "quadratic"})) return;
  r_.number(v, "constant", path, l.constant_attenuation, at_least(0));
  r_.number(v, "linear", path, l.linear_attenuation, at_least(0));
  r_.number(v, "quadratic", path, l.quadratic_attenuation, at_least(0));
  if (l.constant_attenuation == 0 && l.linear_attenuation == 0 && l.quadratic_attenuation == 0) {
    r_.error(v, path, "constant, linear and quadratic are all 0: the light would be infinitely bright");
  }
}

void SceneReader::spot(const JsonValue& v, const std::string& path, Light& l) {
  if (!r_.object(v, path, {"direction", "cutoff", "exponent"})) return;
  if (r_.vec3(v, "direction", path, l.spot_direction) && glm::length(l.spot_direction) == 0.0f) {
    r_.error(*v.find("direction"), join_path(path, "direction"), "must not be the zero vector");
  }
  Range cutoff = closed(0, 90);
  cutoff.also = 180.0;  // GL_SPOT_CUTOFF: 0..90, or exactly 180 (no spot)
  r_.number(v, "cutoff", path, l.spot_cutoff, cutoff);
  r_.number(v, "exponent", path, l.spot_exponent, closed(0, 128));
}

void SceneReader::light_shadow(const JsonValue& v, const std::string& path, SceneLight& l) {
  r_.boolean(v, "shadow", path, l.shadow);
  r_.number(v, "shadow_bias", path, l.shadow_bias, closed(0, 1));
  r_.integer(v, "shadow_map_size", path, l.shadow_map_size, 16, 8192);
  r_.integer(v, "shadow_pcf", path, l.shadow_pcf, 0, 4);
}

}  // namespace shadelab::detail
