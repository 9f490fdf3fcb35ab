// The matrix stacks and the viewport (GL 1.1 sections 2.10.1-2.10.2): glMatrixMode,
// glLoad/MultMatrix, glLoad/MultTransposeMatrix (GL 1.3), glPush/PopMatrix, glTranslate/Rotate/Scale, glFrustum, glOrtho,
// glViewport, glDepthRange. Matrices only; vertices are transformed in draw.cpp.
#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {
namespace {

void multiply(GlContext& c, const glm::mat4& m) { c.current_stack().top() *= m; }

template <class T>
glm::mat4 from_column_major(const T* m) {
  glm::mat4 r;
  for (int i = 0; i < 16; ++i) r[i / 4][i % 4] = float(m[i]);
  return r;
}

// GL 1.3 section 2.10.2: glLoadTransposeMatrix and glMultTransposeMatrix take the matrix
// row by row.
template <class T>
glm::mat4 from_row_major(const T* m) {
  return glm::transpose(from_column_major(m));
}

template <class T>
void load_matrix(GlContext& c, const T* m) {
  if (!m) return c.set_error(GL_INVALID_VALUE);
  c.current_stack().top() = from_column_major(m);
}

template <class T>
void mult_matrix(GlContext& c, const T* m) {
  if (!m) return c.set_error(GL_INVALID_VALUE);
  c.current_stack().top() *= from_column_major(m);
}

// glRotate's matrix (GL 1.1 section 2.10.2); angle in degrees. A zero axis leaves the matrix
// unchanged, as Mesa does.
void rotate(GlContext& c, double angle, double x, double y, double z) {
  double len = std::sqrt(x * x + y * y + z * z);
  if (!(len > 1e-30) || !std::isfinite(len)) return;
  x /= len, y /= len, z /= len;
  double a = angle * (3.14159265358979323846 / 180.0);
  double s = std::sin(a), co = std::cos(a), t = 1.0 - co;
  glm::dmat4 r(1.0);
  r[0] = {x * x * t + co, y * x * t + z * s, x * z * t - y * s, 0.0};
  r[1] = {x * y * t - z * s, y * y * t + co, y * z * t + x * s, 0.0};
  r[2] = {x * z * t + y * s, y * z * t - x * s, z * z * t + co, 0.0};
  c.current_stack().top() *= glm::mat4(r);
}

void translate(GlContext& c, double x, double y, double z) {
  glm::mat4 m(1.0f);
  m[3] = glm::vec4(float(x), float(y), float(z), 1.0f);
  multiply(c, m);
}

void scale(GlContext& c, double x, double y, double z) {
  multiply(c, glm::mat4(glm::vec4(float(x), 0, 0, 0), glm::vec4(0, float(y), 0, 0),
                        glm::vec4(0, 0, float(z), 0), glm::vec4(0, 0, 0, 1)));
}

}  // namespace

void exec::MatrixMode(GlContext& c, GLenum mode) {
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) {
    return c.set_error(GL_INVALID_ENUM);
  }
  c.matrix_mode = mode;
}

void exec::LoadIdentity(GlContext& c) { c.current_stack().top() = glm::mat4(1.0f); }

void exec::LoadMatrixf(GlContext& c, const GLfloat* m) { load_matrix(c, m); }
void exec::LoadMatrixd(GlContext& c, const GLdouble* m) { load_matrix(c, m); }
void exec::MultMatrixf(GlContext& c, const GLfloat* m) { mult_matrix(c, m); }
void exec::MultMatrixd(GlContext& c, const GLdouble* m) { mult_matrix(c, m); }

// A null matrix is ignored, as Mesa ignores it.
void exec::LoadTransposeMatrixf(GlContext& c, const GLfloat* m) {
  if (!m) return;
  c.current_stack().top() = from_row_major(m);
}
void exec::LoadTransposeMatrixd(GlContext& c, const GLdouble* m) {
  if (!m) return;
  c.current_stack().top() = from_row_major(m);
}
void exec::MultTransposeMatrixf(GlContext& c, const GLfloat* m) {
  if (!m) return;
  c.current_stack().top() *= from_row_major(m);
}
void exec::MultTransposeMatrixd(GlContext& c, const GLdouble* m) {
  if (!m) return;
  c.current_stack().top() *= from_row_major(m);
}

void exec::PushMatrix(GlContext& c) {
  MatrixStack& s = c.current_stack();
  if (s.entries.size() >= s.max_depth) return c.set_error(GL_STACK_OVERFLOW);
  s.entries.push_back(s.top());
}

void exec::PopMatrix(GlContext& c) {
  MatrixStack& s = c.current_stack();
  if (s.entries.size() <= 1) return c.set_error(GL_STACK_UNDERFLOW);
  s.entries.pop_back();
}

void exec::Rotatef(GlContext& c, GLfloat angle, GLfloat x, GLfloat y, GLfloat z) { rotate(c, angle, x, y, z); }
void exec::Rotated(GlContext& c, GLdouble angle, GLdouble x, GLdouble y, GLdouble z) { rotate(c, angle, x, y, z); }
void exec::Translatef(GlContext& c, GLfloat x, GLfloat y, GLfloat z) { translate(c, x, y, z); }
void exec::Translated(GlContext& c, GLdouble x, GLdouble y, GLdouble z) { translate(c, x, y, z); }
void exec::Scalef(GlContext& c, GLfloat x, GLfloat y, GLfloat z) { scale(c, x, y, z); }
void exec::Scaled(GlContext& c, GLdouble x, GLdouble y, GLdouble z) { scale(c, x, y, z); }

// GL 1.1 section 2.10.1, equation for Frustum: near and far positive, no empty extent.
void exec::Frustum(GlContext& c, GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  if (!(n > 0.0) || !(f > 0.0) || l == r || b == t || n == f) return c.set_error(GL_INVALID_VALUE);
  glm::dmat4 m(0.0);
  m[0][0] = 2.0 * n / (r - l);
  m[1][1] = 2.0 * n / (t - b);
  m[2][0] = (r + l) / (r - l);
  m[2][1] = (t + b) / (t - b);
  m[2][2] = -(f + n) / (f - n);
  m[2][3] = -1.0;
  m[3][2] = -2.0 * f * n / (f - n);
  c.current_stack().top() *= glm::mat4(m);
}

void exec::Ortho(GlContext& c, GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  if (l == r || b == t || n == f) return c.set_error(GL_INVALID_VALUE);
  glm::dmat4 m(1.0);
  m[0][0] = 2.0 / (r - l);
  m[1][1] = 2.0 / (t - b);
  m[2][2] = -2.0 / (f - n);
  m[3][0] = -(r + l) / (r - l);
  m[3][1] = -(t + b) / (t - b);
  m[3][2] = -(f + n) / (f - n);
  c.current_stack().top() *= glm::mat4(m);
}

// Negative sizes are errors; sizes are clamped to GL_MAX_VIEWPORT_DIMS and the origin to
// Mesa's bounds (GL 1.1 section 2.10.1).
void exec::Viewport(GlContext& c, GLint x, GLint y, GLsizei width, GLsizei height) {
  if (width < 0 || height < 0) return c.set_error(GL_INVALID_VALUE);
  shadelab::Viewport& v = c.raster.viewport;
  v.x = std::clamp(x, -2 * kMaxViewportDim, 2 * kMaxViewportDim - 1);
  v.y = std::clamp(y, -2 * kMaxViewportDim, 2 * kMaxViewportDim - 1);
  v.width = std::min(width, kMaxViewportDim);
  v.height = std::min(height, kMaxViewportDim);
  if (c.surface) c.surface->viewport_set(c);
}

void exec::DepthRange(GlContext& c, GLdouble near_val, GLdouble far_val) {
  auto clamp01 = [](double d) { return d == d ? std::clamp(d, 0.0, 1.0) : 0.0; };
  c.raster.viewport.near_depth = float(clamp01(near_val));
  c.raster.viewport.far_depth = float(clamp01(far_val));
}

}  // namespace shadelab::gl
