// Multitexture (GL 1.3 section 2.7, ARB_multitexture): glActiveTexture, which selects the
// texture unit that glBindTexture, glTexEnv, glTexGen, glEnable of a texture target, the
// texture matrix and the texture queries address; glClientActiveTexture, which selects the unit
// whose texture-coordinate array glTexCoordPointer and GL_TEXTURE_COORD_ARRAY address; and
// glMultiTexCoord*, a unit's current texture coordinates. State only: draws read every unit
// (draw.cpp, array_mesh.cpp, texture.cpp's texture_draw_state).
#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {
namespace {

// The unit GL_TEXTUREi names, or -1 (GL_INVALID_ENUM) past the last.
int unit_of(GLenum texture) {
  const GLenum i = texture - GL_TEXTURE0;  // (wraps below GL_TEXTURE0)
  return i < GLenum(kMaxTextureUnits) ? int(i) : -1;
}

// Texture coordinates convert directly; missing ones are t = 0, r = 0, q = 1 (section 2.7).
void multi_texcoord(GlContext& c, GLenum target, double s, double t, double r, double q) {
  const int u = unit_of(target);
  if (u < 0) return c.set_error(GL_INVALID_ENUM);
  c.current.texcoords[std::size_t(u)] = glm::vec4(float(s), float(t), float(r), float(q));
}

template <class T>
void multi_texcoord_v(GlContext& c, GLenum target, const T* v, int n) {
  if (unit_of(target) < 0) return c.set_error(GL_INVALID_ENUM);
  if (!v) return c.set_error(GL_INVALID_VALUE);
  multi_texcoord(c, target, double(v[0]), n > 1 ? double(v[1]) : 0.0, n > 2 ? double(v[2]) : 0.0,
                 n > 3 ? double(v[3]) : 1.0);
}

}  // namespace

void exec::ActiveTexture(GlContext& c, GLenum texture) {
  const int u = unit_of(texture);
  if (u < 0) return c.set_error(GL_INVALID_ENUM);
  c.textures.active = std::size_t(u);
}

void exec::ClientActiveTexture(GlContext& c, GLenum texture) {
  const int u = unit_of(texture);
  if (u < 0) return c.set_error(GL_INVALID_ENUM);
  c.arrays.client_active = std::size_t(u);
}

void exec::MultiTexCoord1s(GlContext& c, GLenum target, GLshort s) {
  multi_texcoord(c, target, s, 0, 0, 1);
}
void exec::MultiTexCoord1i(GlContext& c, GLenum target, GLint s) {
  multi_texcoord(c, target, s, 0, 0, 1);
}
void exec::MultiTexCoord1f(GlContext& c, GLenum target, GLfloat s) {
  multi_texcoord(c, target, s, 0, 0, 1);
}
void exec::MultiTexCoord1d(GlContext& c, GLenum target, GLdouble s) {
  multi_texcoord(c, target, s, 0, 0, 1);
}
void exec::MultiTexCoord2s(GlContext& c, GLenum target, GLshort s, GLshort t) {
  multi_texcoord(c, target, s, t, 0, 1);
}
void exec::MultiTexCoord2i(GlContext& c, GLenum target, GLint s, GLint t) {
  multi_texcoord(c, target, s, t, 0, 1);
}
void exec::MultiTexCoord2f(GlContext& c, GLenum target, GLfloat s, GLfloat t) {
  multi_texcoord(c, target, s, t, 0, 1);
}
void exec::MultiTexCoord2d(GlContext& c, GLenum target, GLdouble s, GLdouble t) {
  multi_texcoord(c, target, s, t, 0, 1);
}
void exec::MultiTexCoord3s(GlContext& c, GLenum target, GLshort s, GLshort t, GLshort r) {
  multi_texcoord(c, target, s, t, r, 1);
}
void exec::MultiTexCoord3i(GlContext& c, GLenum target, GLint s, GLint t, GLint r) {
  multi_texcoord(c, target, s, t, r, 1);
}
void exec::MultiTexCoord3f(GlContext& c, GLenum target, GLfloat s, GLfloat t, GLfloat r) {
  multi_texcoord(c, target, s, t, r, 1);
}
void exec::MultiTexCoord3d(GlContext& c, GLenum target, GLdouble s, GLdouble t, GLdouble r) {
  multi_texcoord(c, target, s, t, r, 1);
}
void exec::MultiTexCoord4s(GlContext& c, GLenum target, GLshort s, GLshort t, GLshort r,
                           GLshort q) {
  multi_texcoord(c, target, s, t, r, q);
}
void exec::MultiTexCoord4i(GlContext& c, GLenum target, GLint s, GLint t, GLint r, GLint q) {
  multi_texcoord(c, target, s, t, r, q);
}
void exec::MultiTexCoord4f(GlContext& c, GLenum target, GLfloat s, GLfloat t, GLfloat r,
                           GLfloat q) {
  multi_texcoord(c, target, s, t, r, q);
}
void exec::MultiTexCoord4d(GlContext& c, GLenum target, GLdouble s, GLdouble t, GLdouble r,
                           GLdouble q) {
  multi_texcoord(c, target, s, t, r, q);
}
void exec::MultiTexCoord1sv(GlContext& c, GLenum target, const GLshort* v) {
  multi_texcoord_v(c, target, v, 1);
}
void exec::MultiTexCoord1iv(GlContext& c, GLenum target, const GLint* v) {
  multi_texcoord_v(c, target, v, 1);
}
void exec::MultiTexCoord1fv(GlContext& c, GLenum target, const GLfloat* v) {
  multi_texcoord_v(c, target, v, 1);
}
void exec::MultiTexCoord1dv(GlContext& c, GLenum target, const GLdouble* v) {
  multi_texcoord_v(c, target, v, 1);
}
void exec::MultiTexCoord2sv(GlContext& c, GLenum target, const GLshort* v) {
  multi_texcoord_v(c, target, v, 2);
}
void exec::MultiTexCoord2iv(GlContext& c, GLenum target, const GLint* v) {
  multi_texcoord_v(c, target, v, 2);
}
void exec::MultiTexCoord2fv(GlContext& c, GLenum target, const GLfloat* v) {
  multi_texcoord_v(c, target, v, 2);
}
void exec::MultiTexCoord2dv(GlContext& c, GLenum target, const GLdouble* v) {
  multi_texcoord_v(c, target, v, 2);
}
void exec::MultiTexCoord3sv(GlContext& c, GLenum target, const GLshort* v) {
  multi_texcoord_v(c, target, v, 3);
}
void exec::MultiTexCoord3iv(GlContext& c, GLenum target, const GLint* v) {
  multi_texcoord_v(c, target, v, 3);
}
void exec::MultiTexCoord3fv(GlContext& c, GLenum target, const GLfloat* v) {
  multi_texcoord_v(c, target, v, 3);
}
void exec::MultiTexCoord3dv(GlContext& c, GLenum target, const GLdouble* v) {
  multi_texcoord_v(c, target, v, 3);
}
void exec::MultiTexCoord4sv(GlContext& c, GLenum target, const GLshort* v) {
  multi_texcoord_v(c, target, v, 4);
}
void exec::MultiTexCoord4iv(GlContext& c, GLenum target, const GLint* v) {
  multi_texcoord_v(c, target, v, 4);
}
void exec::MultiTexCoord4fv(GlContext& c, GLenum target, const GLfloat* v) {
  multi_texcoord_v(c, target, v, 4);
}
void exec::MultiTexCoord4dv(GlContext& c, GLenum target, const GLdouble* v) {
  multi_texcoord_v(c, target, v, 4);
}

}  // namespace shadelab::gl
