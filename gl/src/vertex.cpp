// Immediate mode (GL 1.1 sections 2.6-2.7): glBegin/glEnd and glVertex* in every type and
// size; glRect* (section 2.9). Passes vertices to draw.cpp, where they are transformed and
// lit; the current attributes they take are set in current.cpp.
#include "gl/generated/exec.hpp"
#include "gl/src/convert.hpp"
#include "gl/src/draw.hpp"

namespace shadelab::gl {
namespace {

// glVertex outside glBegin/glEnd does nothing (GL 1.1 section 2.6.3 leaves it undefined).
void vertex(GlContext& c, double x, double y, double z, double w) {
  if (!c.prim.active) return;
  emit_vertex(c, glm::vec4(float(x), float(y), float(z), float(w)));
}

template <class T>
void vertex_v(GlContext& c, const T* v, int n) {
  if (!v) return c.set_error(GL_INVALID_VALUE);
  vertex(c, double(v[0]), double(v[1]), n > 2 ? double(v[2]) : 0.0, n > 3 ? double(v[3]) : 1.0);
}

// glRect: the polygon (x1, y1), (x2, y1), (x2, y2), (x1, y2) in z = 0 (section 2.9), drawn
// as Mesa draws it, as GL_QUADS: the two differ only where the implementation may choose
// (the order its edges are drawn in GL_LINE mode, which the line stipple shows).
void rect(GlContext& c, double x1, double y1, double x2, double y2) {
  begin_primitive(c, GL_QUADS);
  emit_vertex(c, glm::vec4(float(x1), float(y1), 0.0f, 1.0f));
  emit_vertex(c, glm::vec4(float(x2), float(y1), 0.0f, 1.0f));
  emit_vertex(c, glm::vec4(float(x2), float(y2), 0.0f, 1.0f));
  emit_vertex(c, glm::vec4(float(x1), float(y2), 0.0f, 1.0f));
  end_primitive(c);
}

// glRect*v: the corners (v1[0], v1[1]) and (v2[0], v2[1]).
template <class T>
void rect_v(GlContext& c, const T* v1, const T* v2) {
  if (!v1 || !v2) return c.set_error(GL_INVALID_VALUE);
  rect(c, double(v1[0]), double(v1[1]), double(v2[0]), double(v2[1]));
}

}  // namespace

// GL_POINTS and the line modes are valid and accepted, but shadelab draws only polygons.
void exec::Begin(GlContext& c, GLenum mode) {
  if (mode > GL_POLYGON) return c.set_error(GL_INVALID_ENUM);
  begin_primitive(c, mode);
}

void exec::End(GlContext& c) {
  if (!c.prim.active) return c.set_error(GL_INVALID_OPERATION);
  end_primitive(c);
}

void exec::Vertex2s(GlContext& c, GLshort x, GLshort y) { vertex(c, x, y, 0, 1); }
void exec::Vertex2i(GlContext& c, GLint x, GLint y) { vertex(c, x, y, 0, 1); }
void exec::Vertex2f(GlContext& c, GLfloat x, GLfloat y) { vertex(c, x, y, 0, 1); }
void exec::Vertex2d(GlContext& c, GLdouble x, GLdouble y) { vertex(c, x, y, 0, 1); }
void exec::Vertex3s(GlContext& c, GLshort x, GLshort y, GLshort z) { vertex(c, x, y, z, 1); }
void exec::Vertex3i(GlContext& c, GLint x, GLint y, GLint z) { vertex(c, x, y, z, 1); }
void exec::Vertex3f(GlContext& c, GLfloat x, GLfloat y, GLfloat z) { vertex(c, x, y, z, 1); }
void exec::Vertex3d(GlContext& c, GLdouble x, GLdouble y, GLdouble z) { vertex(c, x, y, z, 1); }
void exec::Vertex4s(GlContext& c, GLshort x, GLshort y, GLshort z, GLshort w) { vertex(c, x, y, z, w); }
void exec::Vertex4i(GlContext& c, GLint x, GLint y, GLint z, GLint w) { vertex(c, x, y, z, w); }
void exec::Vertex4f(GlContext& c, GLfloat x, GLfloat y, GLfloat z, GLfloat w) { vertex(c, x, y, z, w); }
void exec::Vertex4d(GlContext& c, GLdouble x, GLdouble y, GLdouble z, GLdouble w) { vertex(c, x, y, z, w); }
void exec::Vertex2sv(GlContext& c, const GLshort* v) { vertex_v(c, v, 2); }
void exec::Vertex2iv(GlContext& c, const GLint* v) { vertex_v(c, v, 2); }
void exec::Vertex2fv(GlContext& c, const GLfloat* v) { vertex_v(c, v, 2); }
void exec::Vertex2dv(GlContext& c, const GLdouble* v) { vertex_v(c, v, 2); }
void exec::Vertex3sv(GlContext& c, const GLshort* v) { vertex_v(c, v, 3); }
void exec::Vertex3iv(GlContext& c, const GLint* v) { vertex_v(c, v, 3); }
void exec::Vertex3fv(GlContext& c, const GLfloat* v) { vertex_v(c, v, 3); }
void exec::Vertex3dv(GlContext& c, const GLdouble* v) { vertex_v(c, v, 3); }
void exec::Vertex4sv(GlContext& c, const GLshort* v) { vertex_v(c, v, 4); }
void exec::Vertex4iv(GlContext& c, const GLint* v) { vertex_v(c, v, 4); }
void exec::Vertex4fv(GlContext& c, const GLfloat* v) { vertex_v(c, v, 4); }
void exec::Vertex4dv(GlContext& c, const GLdouble* v) { vertex_v(c, v, 4); }

void exec::Rects(GlContext& c, GLshort x1, GLshort y1, GLshort x2, GLshort y2) { rect(c, x1, y1, x2, y2); }
void exec::Recti(GlContext& c, GLint x1, GLint y1, GLint x2, GLint y2) { rect(c, x1, y1, x2, y2); }
void exec::Rectf(GlContext& c, GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2) { rect(c, x1, y1, x2, y2); }
void exec::Rectd(GlContext& c, GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2) { rect(c, x1, y1, x2, y2); }
void exec::Rectsv(GlContext& c, const GLshort* v1, const GLshort* v2) { rect_v(c, v1, v2); }
void exec::Rectiv(GlContext& c, const GLint* v1, const GLint* v2) { rect_v(c, v1, v2); }
void exec::Rectfv(GlContext& c, const GLfloat* v1, const GLfloat* v2) { rect_v(c, v1, v2); }
void exec::Rectdv(GlContext& c, const GLdouble* v1, const GLdouble* v2) { rect_v(c, v1, v2); }

}  // namespace shadelab::gl
