// Materials (named, inline or presets), objects (shape, material, shading, culling, blending)
// and their transforms, composed in OpenGL's call order.
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/scene_reader.hpp"
#include "shadelab/materials.hpp"

namespace shadelab::detail {

using Type = JsonValue::Type;

void SceneReader::materials(const JsonValue& v) {
  if (!r_.is_type(v, Type::kObject, "materials")) return;
  for (const JsonMember& m : v.members) {
    materials_[m.key] = material_object(m.value, join_path("materials", m.key));
  }
}

Material SceneReader::material_object(const JsonValue& v, const std::string& path) {
  Material m;  // OpenGL's default material (SPEC section 3)
  if (!r_.object(v, path, {"ambient", "diffuse", "specular", "emission", "shininess",
                           "specular_model", "diffuse_model", "roughness"})) {
    return m;
  }
  r_.color(v, "ambient", path, m.ambient, closed(0, 1));
  r_.color(v, "diffuse", path, m.diffuse, closed(0, 1));
  r_.color(v, "specular", path, m.specular, closed(0, 1));
  r_.color(v, "emission", path, m.emission, closed(0, 1));
  r_.number(v, "shininess", path, m.shininess, closed(0, 128));
  if (int s = r_.choice(v, "specular_model", path, {"blinn", "phong"}); s >= 0) {
    m.specular_model = SpecularModel(s);
  }
  if (int d = r_.choice(v, "diffuse_model", path, {"lambert", "oren-nayar"}); d >= 0) {
    m.diffuse_model = DiffuseModel(d);
  }
  r_.number(v, "roughness", path, m.roughness, closed(0, 1.5707964));
  return m;
}

// A material by name (the scene's own first, then the presets) or inline.
Material SceneReader::material(const JsonValue& v, const std::string& path) {
  if (v.type == Type::kObject) return material_object(v, path);
  if (v.type != Type::kString) {
    r_.error(v, path, "expected a material name or a material object, got " + v.type_name());
    return {};
  }
  if (auto it = materials_.find(v.text); it != materials_.end()) return it->second;
  if (auto preset = find_material_preset(v.text)) return *preset;
  std::vector<std::string> names = material_preset_names();
  for (const auto& [name, m] : materials_) names.push_back(name);
  r_.error(v, path, "unknown material \"" + v.text + "\"" + suggestion(v.text, names));
  return {};
}

void SceneReader::objects(const JsonValue& v, Scene& s) {
  if (!r_.is_type(v, Type::kArray, "objects")) return;
  for (std::size_t i = 0; i < v.items.size(); ++i) object(v.items[i], index_path("objects", i), s);
}

void SceneReader::object(const JsonValue& v, const std::string& path, Scene& s) {
  if (!r_.object(v, path, {"name", "shape", "transform", "material", "back_material", "shading",
                           "cull", "blend", "lighting", "color", "texture"})) {
    return;
  }
  SceneObject o;
  o.name = path;
  r_.string(v, "name", path, o.name);
  appearance(v, path, o);
  if (const JsonValue* t = v.find("transform")) o.model = transform(*t, join_path(path, "transform"));
  if (const JsonValue* t = v.find("texture")) texture(*t, join_path(path, "texture"), o);
  const JsonValue* shape_value = v.find("shape");
  if (!shape_value) {
    r_.error(v, path, "missing required key \"shape\"");
    return;
  }
  o.mesh = shape(*shape_value, join_path(path, "shape"));
  if (o.mesh) s.objects.push_back(std::move(o));
}

// Materials, shading, culling, lighting and blending.
void SceneReader::appearance(const JsonValue& v, const std::string& path, SceneObject& o) {
  if (const JsonValue* m = v.find("material")) o.front = material(*m, join_path(path, "material"));
  if (const JsonValue* m = v.find("back_material")) {
    o.back = material(*m, join_path(path, "back_material"));
  }
  if (int sh = r_.choice(v, "shading", path, {"flat", "gouraud", "phong"}); sh >= 0) {
    o.shading = ShadingMode(sh);
  }
  if (int c = r_.choice(v, "cull", path, {"none", "back", "front"}); c >= 0) o.cull = CullMode(c);
  r_.boolean(v, "lighting", path, o.lighting);
  r_.color(v, "color", path, o.color, closed(0, 1));
  int blend = r_.choice(v, "blend", path, {"auto", "none", "alpha", "additive"});
  // auto: alpha blending when the lit colour's alpha (the front diffuse alpha), or the unlit
  // colour's alpha, is below 1 (SPEC section 5).
  bool translucent = o.lighting ? o.front.diffuse.a < 1.0f : o.color.a < 1.0f;
  if (blend == 2 || (blend <= 0 && translucent)) {
    o.blend = {true, BlendFactor::kSrcAlpha, BlendFactor::kOneMinusSrcAlpha};
  } else if (blend == 3) {
    o.blend = {true, BlendFactor::kOne, BlendFactor::kOne};
  }
}

// model = matrix * translate * rotate[0] * rotate[1] * ... * scale: the order of the
// glMultMatrixf, glTranslatef, glRotatef and glScalef calls that would build it.
glm::mat4 SceneReader::transform(const JsonValue& v, const std::string& path) {
  glm::mat4 m(1.0f);
  if (!r_.object(v, path, {"translate", "rotate", "scale", "matrix"})) return m;
  std::vector<double> n;
  if (const JsonValue* mat = v.find("matrix"); mat && r_.numbers(*mat, join_path(path, "matrix"), n, 16)) {
    float f[16];
    for (int i = 0; i < 16; ++i) f[i] = float(n[i]);
    m = glm::make_mat4(f);  // column-major, as glMultMatrixf
  }
  glm::vec3 t(0.0f);
  r_.vec3(v, "translate", path, t);
  m = glm::translate(m, t);
  if (const JsonValue* rot = v.find("rotate")) m *= rotations(*rot, join_path(path, "rotate"));
  if (const JsonValue* sc = v.find("scale")) m *= scaling(*sc, join_path(path, "scale"));
  return m;
}

// [angle_degrees, ax, ay, az] or a list of those, applied in order (glRotatef calls).
glm::mat4 SceneReader::rotations(const JsonValue& v, const std::string& path) {
  bool list = v.type == Type::kArray && !v.items.empty() && v.items[0].type == Type::kArray;
  std::vector<const JsonValue*> each;
  if (list) {
    for (const JsonValue& x : v.items) each.push_back(&x);
  } else {
    each.push_back(&v);
  }
  glm::mat4 m(1.0f);
  for (std::size_t i = 0; i < each.size(); ++i) {
    std::string p = list ? index_path(path, i) : path;
    std::vector<double> n;
    if (!r_.numbers(*each[i], p, n, 4)) continue;
    glm::vec3 axis{float(n[1]), float(n[2]), float(n[3])};
    if (glm::length(axis) == 0.0f) {
      r_.error(*each[i], p, "the rotation axis must not be the zero vector");
      continue;
    }
    m = glm::rotate(m, glm::radians(float(n[0])), axis);
  }
  return m;
}

// A number (uniform) or [sx, sy, sz]; no factor may be 0 (the normals would be lost).
glm::mat4 SceneReader::scaling(const JsonValue& v, const std::string& path) {
  glm::vec3 s(1.0f);
  std::vector<double> n;
  double k = 1.0;
  if (v.type == Type::kNumber) {
    if (!r_.number_value(v, path, k, {})) return glm::mat4(1.0f);
    s = glm::vec3(float(k));
  } else if (v.type != Type::kArray) {
    r_.error(v, path, "expected a number or an array of 3 numbers, got " + v.type_name());
    return glm::mat4(1.0f);
  } else if (r_.numbers(v, path, n, 3)) {
    s = glm::vec3(float(n[0]), float(n[1]), float(n[2]));
  } else {
    return glm::mat4(1.0f);
  }
  if (s.x == 0.0f || s.y == 0.0f || s.z == 0.0f) {
    r_.error(v, path, "scale factors must not be 0");
    return glm::mat4(1.0f);
  }
  return glm::scale(glm::mat4(1.0f), s);
}

}  // namespace shadelab::detail
