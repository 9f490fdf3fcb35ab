// glLight*, glLightModel*, glMaterial*, glColorMaterial, glShadeModel and their queries
// (GL 1.1 section 2.13, 6.1.3). Validates and stores parameters: light positions and spot
// directions go to eye space here. The lighting equation itself is the core's light_point.
#include <array>

#include <glm/mat3x3.hpp>

#include "gl/generated/exec.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/context.hpp"
#include "gl/src/convert.hpp"

namespace shadelab::gl {
namespace {

bool is_color_param(GLenum pname) {
  return pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR ||
         pname == GL_EMISSION || pname == GL_AMBIENT_AND_DIFFUSE;
}

int light_param_count(GLenum pname) {
  switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_POSITION: return 4;
    case GL_SPOT_DIRECTION: return 3;
    case GL_SPOT_EXPONENT: case GL_SPOT_CUTOFF: case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION: case GL_QUADRATIC_ATTENUATION: return 1;
    default: return 0;
  }
}

// Range checks of GL 1.1 section 2.13.2 (written so that NaN fails them).
bool light_value_ok(GLenum pname, float v) {
  switch (pname) {
    case GL_SPOT_EXPONENT: return v >= 0.0f && v <= 128.0f;
    case GL_SPOT_CUTOFF: return (v >= 0.0f && v <= 90.0f) || v == 180.0f;
    case GL_CONSTANT_ATTENUATION: case GL_LINEAR_ATTENUATION: case GL_QUADRATIC_ATTENUATION:
      return v >= 0.0f;
    default: return true;
  }
}

// glLight: `p` holds light_param_count(pname) values already converted to float.
void set_light(GlContext& c, Light& l, GLenum pname, const float* p) {
  glm::vec4 v4(p[0], 0.0f, 0.0f, 0.0f);
  if (light_param_count(pname) >= 3) v4 = glm::vec4(p[0], p[1], p[2], pname == GL_SPOT_DIRECTION ? 0.0f : p[3]);
  const glm::mat4& mv = c.modelview.top();
  switch (pname) {
    case GL_AMBIENT: l.ambient = v4; break;
    case GL_DIFFUSE: l.diffuse = v4; break;
    case GL_SPECULAR: l.specular = v4; break;
    // Positions and spot directions are transformed by the modelview in force now and kept
    // in eye space (GL 1.1 section 2.13.2): directions by its upper-left 3x3.
    case GL_POSITION: l.position = mv * v4; break;
    case GL_SPOT_DIRECTION: l.spot_direction = glm::mat3(mv) * glm::vec3(v4); break;
    case GL_SPOT_EXPONENT: l.spot_exponent = p[0]; break;
    case GL_SPOT_CUTOFF: l.spot_cutoff = p[0]; break;
    case GL_CONSTANT_ATTENUATION: l.constant_attenuation = p[0]; break;
    case GL_LINEAR_ATTENUATION: l.linear_attenuation = p[0]; break;
    case GL_QUADRATIC_ATTENUATION: l.quadratic_attenuation = p[0]; break;
    default: break;
  }
}

// The scalar forms (glLightf, glLightModeli, glMaterialf, ...) as Mesa runs them: the vector
// form with (param, 0, 0, 0), so a vector parameter is set rather than refused (GL 1.1 makes
// it GL_INVALID_ENUM; Mesa's errors are the bar: docs/gl.md).
template <class T>
std::array<T, 4> padded(T param) {
  return {param, T(0), T(0), T(0)};
}

// Shared by the four glLight variants. Integer colours map to [-1, 1]; other integers convert
// directly.
template <class T>
void light_call(GlContext& c, GLenum light, GLenum pname, const T* params, bool scalar) {
  if (scalar) return light_call(c, light, pname, padded(*params).data(), false);
  int n = light_param_count(pname);
  if (light < GL_LIGHT0 || light >= GL_LIGHT0 + kMaxLights || n == 0 || (scalar && n != 1)) {
    return c.set_error(GL_INVALID_ENUM);
  }
  if (!params) return c.set_error(GL_INVALID_VALUE);
  float v[4] = {0, 0, 0, 0};
  for (int i = 0; i < n; ++i) {
    if constexpr (std::is_integral_v<T>) {
      v[i] = is_color_param(pname) ? int_to_color(params[i]) : float(params[i]);
    } else {
      v[i] = float(params[i]);
    }
  }
  if (!light_value_ok(pname, v[0])) return c.set_error(GL_INVALID_VALUE);
  set_light(c, c.lighting.lights[light - GL_LIGHT0], pname, v);
}

template <class T>
void light_model_call(GlContext& c, GLenum pname, const T* params, bool scalar) {
  if (scalar) return light_model_call(c, pname, padded(*params).data(), false);
  LightModel& m = c.lighting.model;
  bool known = pname == GL_LIGHT_MODEL_AMBIENT || pname == GL_LIGHT_MODEL_LOCAL_VIEWER ||
               pname == GL_LIGHT_MODEL_TWO_SIDE || pname == GL_LIGHT_MODEL_COLOR_CONTROL;
  if (!known || (scalar && pname == GL_LIGHT_MODEL_AMBIENT)) return c.set_error(GL_INVALID_ENUM);
  if (!params) return c.set_error(GL_INVALID_VALUE);
  if (pname == GL_LIGHT_MODEL_AMBIENT) {
    for (int i = 0; i < 4; ++i) {
      if constexpr (std::is_integral_v<T>) {
        m.ambient[i] = int_to_color(params[i]);
      } else {
        m.ambient[i] = float(params[i]);
      }
    }
  } else if (pname == GL_LIGHT_MODEL_COLOR_CONTROL) {
    double v = double(params[0]);
    if (v != GL_SINGLE_COLOR && v != GL_SEPARATE_SPECULAR_COLOR) return c.set_error(GL_INVALID_ENUM);
    m.separate_specular = v == GL_SEPARATE_SPECULAR_COLOR;
  } else {
    (pname == GL_LIGHT_MODEL_LOCAL_VIEWER ? m.local_viewer : m.two_side) = params[0] != T(0);
  }
}

int material_param_count(GLenum pname) {
  if (is_color_param(pname)) return 4;
  if (pname == GL_SHININESS) return 1;
  if (pname == GL_COLOR_INDEXES) return 3;
  return 0;
}

// Is `pname` of `face` currently replaced by the colour (GL_COLOR_MATERIAL)? Then glMaterial
// leaves it alone, as Mesa does: the parameter tracks the current colour.
bool tracked(const LightingState& l, bool front, GLenum pname) {
  if (!l.color_material) return false;
  if (l.color_material_face != GL_FRONT_AND_BACK && l.color_material_face != (front ? GL_FRONT : GL_BACK)) return false;
  GLenum m = l.color_material_mode;
  return m == pname || (m == GL_AMBIENT_AND_DIFFUSE && (pname == GL_AMBIENT || pname == GL_DIFFUSE));
}

void set_material(const LightingState& l, Material& m, bool front, GLenum pname, const float* v) {
  glm::vec4 c(v[0], v[1], v[2], v[3]);
  auto set = [&](GLenum which, glm::vec4& dst) {
    if (!tracked(l, front, which)) dst = c;
  };
  switch (pname) {
    case GL_AMBIENT: set(GL_AMBIENT, m.ambient); break;
    case GL_DIFFUSE: set(GL_DIFFUSE, m.diffuse); break;
    case GL_SPECULAR: set(GL_SPECULAR, m.specular); break;
    case GL_EMISSION: set(GL_EMISSION, m.emission); break;
    case GL_AMBIENT_AND_DIFFUSE: set(GL_AMBIENT, m.ambient); set(GL_DIFFUSE, m.diffuse); break;
    case GL_SHININESS: m.shininess = v[0]; break;
    default: break;  // GL_COLOR_INDEXES: colour-index mode only
  }
}

template <class T>
void material_call(GlContext& c, GLenum face, GLenum pname, const T* params, bool scalar) {
  if (scalar) return material_call(c, face, pname, padded(*params).data(), false);
  int n = material_param_count(pname);
  bool face_ok = face == GL_FRONT || face == GL_BACK || face == GL_FRONT_AND_BACK;
  if (!face_ok || n == 0 || (scalar && pname != GL_SHININESS)) return c.set_error(GL_INVALID_ENUM);
  if (!params) return c.set_error(GL_INVALID_VALUE);
  float v[4] = {0, 0, 0, 0};
  for (int i = 0; i < n; ++i) {
    if constexpr (std::is_integral_v<T>) {
      v[i] = is_color_param(pname) ? int_to_color(params[i]) : float(params[i]);
    } else {
      v[i] = float(params[i]);
    }
  }
  if (pname == GL_SHININESS && !(v[0] >= 0.0f && v[0] <= 128.0f)) return c.set_error(GL_INVALID_VALUE);
  LightingState& l = c.lighting;
  if (c.prim.active) settle_lighting(c);  // earlier vertices keep the material they had
  if (face != GL_BACK) set_material(l, l.front, true, pname, v);
  if (face != GL_FRONT) set_material(l, l.back, false, pname, v);
}

// Values of glGetLight; returns the count (0: unknown pname). `color` tells glGetLightiv to
// map them as colours.
int get_light(const Light& l, GLenum pname, float* out, bool& color) {
  auto put4 = [&](const glm::vec4& v) {
    for (int i = 0; i < 4; ++i) out[i] = v[i];
    return 4;
  };
  color = pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR;
  switch (pname) {
    case GL_AMBIENT: return put4(l.ambient);
    case GL_DIFFUSE: return put4(l.diffuse);
    case GL_SPECULAR: return put4(l.specular);
    case GL_POSITION: return put4(l.position);
    case GL_SPOT_DIRECTION: put4(glm::vec4(l.spot_direction, 0.0f)); return 3;
    case GL_SPOT_EXPONENT: out[0] = l.spot_exponent; return 1;
    case GL_SPOT_CUTOFF: out[0] = l.spot_cutoff; return 1;
    case GL_CONSTANT_ATTENUATION: out[0] = l.constant_attenuation; return 1;
    case GL_LINEAR_ATTENUATION: out[0] = l.linear_attenuation; return 1;
    case GL_QUADRATIC_ATTENUATION: out[0] = l.quadratic_attenuation; return 1;
    default: return 0;
  }
}

int get_material(const Material& m, GLenum pname, float* out, bool& color) {
  auto put4 = [&](const glm::vec4& v) {
    for (int i = 0; i < 4; ++i) out[i] = v[i];
    return 4;
  };
  color = pname != GL_SHININESS && pname != GL_COLOR_INDEXES;
  switch (pname) {
    case GL_AMBIENT: return put4(m.ambient);
    case GL_DIFFUSE: return put4(m.diffuse);
    case GL_SPECULAR: return put4(m.specular);
    case GL_EMISSION: return put4(m.emission);
    case GL_SHININESS: out[0] = m.shininess; return 1;
    case GL_COLOR_INDEXES: out[0] = 0; out[1] = out[2] = 1; return 3;  // Mesa's defaults
    default: return 0;
  }
}

template <class T>
void get_light_call(GlContext& c, GLenum light, GLenum pname, T* params) {
  if (light < GL_LIGHT0 || light >= GL_LIGHT0 + kMaxLights) return c.set_error(GL_INVALID_ENUM);
  float v[4];
  bool color = false;
  int n = get_light(c.lighting.lights[light - GL_LIGHT0], pname, v, color);
  if (n == 0) return c.set_error(GL_INVALID_ENUM);
  if (!params) return c.set_error(GL_INVALID_VALUE);
  write_gl_values(v, n, color, params);
}

template <class T>
void get_material_call(GlContext& c, GLenum face, GLenum pname, T* params) {
  if (face != GL_FRONT && face != GL_BACK) return c.set_error(GL_INVALID_ENUM);
  float v[4];
  bool color = false;
  int n = get_material(face == GL_FRONT ? c.lighting.front : c.lighting.back, pname, v, color);
  if (n == 0) return c.set_error(GL_INVALID_ENUM);
  if (!params) return c.set_error(GL_INVALID_VALUE);
  write_gl_values(v, n, color, params);
}

}  // namespace

void exec::Lightf(GlContext& c, GLenum light, GLenum pname, GLfloat param) { light_call(c, light, pname, &param, true); }
void exec::Lighti(GlContext& c, GLenum light, GLenum pname, GLint param) { light_call(c, light, pname, &param, true); }
void exec::Lightfv(GlContext& c, GLenum light, GLenum pname, const GLfloat* params) { light_call(c, light, pname, params, false); }
void exec::Lightiv(GlContext& c, GLenum light, GLenum pname, const GLint* params) { light_call(c, light, pname, params, false); }

void exec::LightModelf(GlContext& c, GLenum pname, GLfloat param) { light_model_call(c, pname, &param, true); }
void exec::LightModeli(GlContext& c, GLenum pname, GLint param) { light_model_call(c, pname, &param, true); }
void exec::LightModelfv(GlContext& c, GLenum pname, const GLfloat* params) { light_model_call(c, pname, params, false); }
void exec::LightModeliv(GlContext& c, GLenum pname, const GLint* params) { light_model_call(c, pname, params, false); }

// glMaterial is legal between glBegin and glEnd: it changes the material of the vertices
// that follow (GL 1.1 section 2.6.3).
void exec::Materialf(GlContext& c, GLenum face, GLenum pname, GLfloat param) { material_call(c, face, pname, &param, true); }
void exec::Materiali(GlContext& c, GLenum face, GLenum pname, GLint param) { material_call(c, face, pname, &param, true); }
void exec::Materialfv(GlContext& c, GLenum face, GLenum pname, const GLfloat* params) { material_call(c, face, pname, params, false); }
void exec::Materialiv(GlContext& c, GLenum face, GLenum pname, const GLint* params) { material_call(c, face, pname, params, false); }

void exec::GetLightfv(GlContext& c, GLenum light, GLenum pname, GLfloat* params) { get_light_call(c, light, pname, params); }
void exec::GetLightiv(GlContext& c, GLenum light, GLenum pname, GLint* params) { get_light_call(c, light, pname, params); }
void exec::GetMaterialfv(GlContext& c, GLenum face, GLenum pname, GLfloat* params) { get_material_call(c, face, pname, params); }
void exec::GetMaterialiv(GlContext& c, GLenum face, GLenum pname, GLint* params) { get_material_call(c, face, pname, params); }

// How many values the vector forms read, for their display-list savers (0 for a pname they
// reject: they read nothing then).
std::size_t save_count::Lightfv(GLenum pname) { return std::size_t(light_param_count(pname)); }
std::size_t save_count::Lightiv(GLenum pname) { return std::size_t(light_param_count(pname)); }
std::size_t save_count::LightModelfv(GLenum pname) { return pname == GL_LIGHT_MODEL_AMBIENT ? 4 : 1; }
std::size_t save_count::LightModeliv(GLenum pname) { return pname == GL_LIGHT_MODEL_AMBIENT ? 4 : 1; }
std::size_t save_count::Materialfv(GLenum pname) { return std::size_t(material_param_count(pname)); }
std::size_t save_count::Materialiv(GLenum pname) { return std::size_t(material_param_count(pname)); }

void exec::ColorMaterial(GlContext& c, GLenum face, GLenum mode) {
  bool face_ok = face == GL_FRONT || face == GL_BACK || face == GL_FRONT_AND_BACK;
  bool mode_ok = mode == GL_EMISSION || mode == GL_AMBIENT || mode == GL_DIFFUSE ||
                 mode == GL_SPECULAR || mode == GL_AMBIENT_AND_DIFFUSE;
  if (!face_ok || !mode_ok) return c.set_error(GL_INVALID_ENUM);
  c.lighting.color_material_face = face;
  c.lighting.color_material_mode = mode;
  apply_color_material(c);
}

void exec::ShadeModel(GlContext& c, GLenum mode) {
  if (mode != GL_FLAT && mode != GL_SMOOTH) return c.set_error(GL_INVALID_ENUM);
  c.lighting.shade_model = mode;
}

}  // namespace shadelab::gl
