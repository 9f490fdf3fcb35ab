// Texture coordinate generation (GL 1.1 section 2.10.4; GL 1.3's modes of section 2.10.4):
// glTexGen{i,f,d}[v], glGetTexGen{i,f,d}v, and the generated coordinates of a vertex (object
// linear, eye linear with the eye plane taken through the inverse modelview of the call, sphere
// map, GL 1.3's normal map and reflection map for cube maps), which
// draw.cpp and array_mesh.cpp compute per vertex before the texture matrix. Errors are Mesa's
// (texgen.c).
#include "gl/src/texgen.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "gl/generated/exec.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/convert.hpp"

namespace shadelab::gl {
namespace {

int coord_index(GLenum coord) {
  switch (coord) {
    case GL_S: return 0;
    case GL_T: return 1;
    case GL_R: return 2;
    case GL_Q: return 3;
    default: return -1;
  }
}

// glTexGen with its values as floats (4 for a plane; the scalar forms give (v, 0, 0, 0), as
// Mesa's). The mode is truncated to an integer.
void tex_gen(GlContext& c, GLenum coord, GLenum pname, const float* v) {
  const int i = coord_index(coord);
  if (i < 0) return c.set_error(GL_INVALID_ENUM);
  if (!v) return c.set_error(GL_INVALID_VALUE);
  TexGenCoord& g = c.textures.unit().gen[std::size_t(i)];
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: {
      const GLint mode = std::isfinite(v[0]) && std::fabs(v[0]) < 2e9f ? GLint(v[0]) : 0;
      const bool sphere_ok = i < 2;  // GL_SPHERE_MAP generates s and t only
      const bool cube_ok = i < 3;    // GL 1.3: GL_NORMAL_MAP and GL_REFLECTION_MAP s, t and r
      if (mode != GL_OBJECT_LINEAR && mode != GL_EYE_LINEAR && !(mode == GL_SPHERE_MAP && sphere_ok) &&
          !((mode == GL_NORMAL_MAP || mode == GL_REFLECTION_MAP) && cube_ok)) {
        return c.set_error(GL_INVALID_ENUM);
      }
      g.mode = GLenum(mode);
      return;
    }
    case GL_OBJECT_PLANE: g.object_plane = glm::vec4(v[0], v[1], v[2], v[3]); return;
    case GL_EYE_PLANE:  // p' = p M^-1 (a row vector times the inverse modelview)
      g.eye_plane = glm::vec4(v[0], v[1], v[2], v[3]) * glm::inverse(c.modelview.top());
      return;
    default: return c.set_error(GL_INVALID_ENUM);
  }
}

template <class T>
void tex_gen_v(GlContext& c, GLenum coord, GLenum pname, const T* params) {
  float v[4] = {0, 0, 0, 0};
  const int n = pname == GL_OBJECT_PLANE || pname == GL_EYE_PLANE ? 4 : 1;
  for (int k = 0; params && k < n; ++k) v[k] = float(params[k]);
  tex_gen(c, coord, pname, params ? v : nullptr);
}

template <class T>
void tex_gen_1(GlContext& c, GLenum coord, GLenum pname, T param) {
  const float v[4] = {float(param), 0, 0, 0};
  tex_gen(c, coord, pname, v);
}

// glGetTexGen: planes and the mode, integers truncated (Mesa's).
template <class T>
void get_tex_gen(GlContext& c, GLenum coord, GLenum pname, T* params) {
  const int i = coord_index(coord);
  if (i < 0) return c.set_error(GL_INVALID_ENUM);
  const TexGenCoord& g = c.textures.unit().gen[std::size_t(i)];
  glm::vec4 v(0.0f);
  int n = 4;
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: v[0] = float(g.mode), n = 1; break;
    case GL_OBJECT_PLANE: v = g.object_plane; break;
    case GL_EYE_PLANE: v = g.eye_plane; break;
    default: return c.set_error(GL_INVALID_ENUM);
  }
  if (!params) return c.set_error(GL_INVALID_VALUE);
  for (int k = 0; k < n; ++k) {
    if constexpr (std::is_integral_v<T>) {
      params[k] = std::isfinite(v[k]) && std::fabs(v[k]) < 2e9f ? T(v[k]) : 0;
    } else {
      params[k] = T(v[k]);
    }
  }
}

// The eye-space reflection of the direction from the eye through the vertex, r = u - 2 n (n . u)
// (GL 1.3 section 2.10.4: GL_REFLECTION_MAP's (s, t, r), and what GL_SPHERE_MAP maps).
glm::vec3 reflection(const glm::vec4& eye, const glm::vec3& normal) {
  glm::vec3 u(eye);
  const float len = glm::length(u);
  if (len > 0.0f) u /= len;
  return u - 2.0f * normal * glm::dot(normal, u);
}

// GL 1.1 section 2.10.4's sphere map: the reflection mapped onto the unit disc centred at
// (0.5, 0.5).
glm::vec2 sphere_map(const glm::vec3& r) {
  const float m = 2.0f * std::sqrt(r.x * r.x + r.y * r.y + (r.z + 1.0f) * (r.z + 1.0f));
  if (!(m > 0.0f)) return glm::vec2(0.5f);
  return glm::vec2(r.x / m + 0.5f, r.y / m + 0.5f);
}

}  // namespace

bool texgen_needs_normal(const TextureUnitState& t) {
  for (const TexGenCoord& g : t.gen) {
    if (g.enabled && (g.mode == GL_SPHERE_MAP || g.mode == GL_NORMAL_MAP || g.mode == GL_REFLECTION_MAP)) return true;
  }
  return false;
}

glm::vec4 generate_texcoords(const TextureUnitState& t, glm::vec4 current, const glm::vec4& object, const glm::vec4& eye,
                             const glm::vec3& eye_normal) {
  glm::vec3 r(0.0f);
  glm::vec2 sphere(0.0f);
  if (texgen_needs_normal(t)) r = reflection(eye, eye_normal), sphere = sphere_map(r);
  for (int i = 0; i < 4; ++i) {
    const TexGenCoord& g = t.gen[std::size_t(i)];
    if (!g.enabled) continue;
    switch (g.mode) {
      case GL_OBJECT_LINEAR: current[i] = glm::dot(g.object_plane, object); break;
      case GL_EYE_LINEAR: current[i] = glm::dot(g.eye_plane, eye); break;
      case GL_NORMAL_MAP: current[i] = eye_normal[i]; break;   // s, t, r only
      case GL_REFLECTION_MAP: current[i] = r[i]; break;        // s, t, r only
      default: current[i] = sphere[i]; break;  // GL_SPHERE_MAP, s and t only
    }
  }
  return current;
}

// How many values the vector forms read, for their display-list savers.
std::size_t save_count::TexGeniv(GLenum pname) { return pname == GL_OBJECT_PLANE || pname == GL_EYE_PLANE ? 4 : 1; }
std::size_t save_count::TexGenfv(GLenum pname) { return pname == GL_OBJECT_PLANE || pname == GL_EYE_PLANE ? 4 : 1; }
std::size_t save_count::TexGendv(GLenum pname) { return pname == GL_OBJECT_PLANE || pname == GL_EYE_PLANE ? 4 : 1; }

void exec::TexGeni(GlContext& c, GLenum coord, GLenum pname, GLint param) { tex_gen_1(c, coord, pname, param); }
void exec::TexGenf(GlContext& c, GLenum coord, GLenum pname, GLfloat param) { tex_gen_1(c, coord, pname, param); }
void exec::TexGend(GlContext& c, GLenum coord, GLenum pname, GLdouble param) { tex_gen_1(c, coord, pname, param); }
void exec::TexGeniv(GlContext& c, GLenum coord, GLenum pname, const GLint* params) { tex_gen_v(c, coord, pname, params); }
void exec::TexGenfv(GlContext& c, GLenum coord, GLenum pname, const GLfloat* params) { tex_gen_v(c, coord, pname, params); }
void exec::TexGendv(GlContext& c, GLenum coord, GLenum pname, const GLdouble* params) { tex_gen_v(c, coord, pname, params); }
void exec::GetTexGeniv(GlContext& c, GLenum coord, GLenum pname, GLint* params) { get_tex_gen(c, coord, pname, params); }
void exec::GetTexGenfv(GlContext& c, GLenum coord, GLenum pname, GLfloat* params) { get_tex_gen(c, coord, pname, params); }
void exec::GetTexGendv(GlContext& c, GLenum coord, GLenum pname, GLdouble* params) { get_tex_gen(c, coord, pname, params); }

}  // namespace shadelab::gl
