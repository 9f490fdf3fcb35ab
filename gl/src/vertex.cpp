// Immediate mode (GL 1.1 sections 2.6-2.7): glBegin/glEnd, glVertex*, and the current
// attributes glNormal*, glColor*, glTexCoord*; glRect* (section 2.9). Records attributes and
// passes vertices to draw.cpp; transformation and lighting happen there.
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

void normal(GlContext& c, double x, double y, double z) {
  c.current.normal = glm::vec3(float(x), float(y), float(z));
}

template <class T>
void normal_v(GlContext& c, const T* v) {
  if (!v) return c.set_error(GL_INVALID_VALUE);
  normal(c, v[0], v[1], v[2]);
}

// The current colour; with GL_COLOR_MATERIAL the material follows it (section 2.13.3).
void color(GlContext& c, float r, float g, float b, float a) {
  c.current.color = glm::vec4(r, g, b, a);
  apply_color_material(c);
}

template <class T>
void color_v(GlContext& c, const T* v, int n) {
  if (!v) return c.set_error(GL_INVALID_VALUE);
  if constexpr (std::is_same_v<T, GLubyte>) {
    color(c, ubyte_to_float(v[0]), ubyte_to_float(v[1]), ubyte_to_float(v[2]),
          n > 3 ? ubyte_to_float(v[3]) : 1.0f);
  } else {
    color(c, float(v[0]), float(v[1]), float(v[2]), n > 3 ? float(v[3]) : 1.0f);
  }
}

void texcoord(GlContext& c, double s, double t) {
  c.current.texcoord = glm::vec4(float(s), float(t), 0.0f, 1.0f);
}

template <class T>
void texcoord_v(GlContext& c, const T* v) {
  if (!v) return c.set_error(GL_INVALID_VALUE);
  texcoord(c, v[0], v[1]);
}

// glRect: a GL_POLYGON (x1, y1), (x2, y1), (x2, y2), (x1, y2) in z = 0 (section 2.9).
void rect(GlContext& c, double x1, double y1, double x2, double y2) {
  begin_primitive(c, GL_POLYGON);
  emit_vertex(c, glm::vec4(float(x1), float(y1), 0.0f, 1.0f));
  emit_vertex(c, glm::vec4(float(x2), float(y1), 0.0f, 1.0f));
  emit_vertex(c, glm::vec4(float(x2), float(y2), 0.0f, 1.0f));
  emit_vertex(c, glm::vec4(float(x1), float(y2), 0.0f, 1.0f));
  end_primitive(c);
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

void exec::Vertex2d(GlContext& c, GLdouble x, GLdouble y) { vertex(c, x, y, 0, 1); }
void exec::Vertex2f(GlContext& c, GLfloat x, GLfloat y) { vertex(c, x, y, 0, 1); }
void exec::Vertex2i(GlContext& c, GLint x, GLint y) { vertex(c, x, y, 0, 1); }
void exec::Vertex3d(GlContext& c, GLdouble x, GLdouble y, GLdouble z) { vertex(c, x, y, z, 1); }
void exec::Vertex3f(GlContext& c, GLfloat x, GLfloat y, GLfloat z) { vertex(c, x, y, z, 1); }
void exec::Vertex3i(GlContext& c, GLint x, GLint y, GLint z) { vertex(c, x, y, z, 1); }
void exec::Vertex4d(GlContext& c, GLdouble x, GLdouble y, GLdouble z, GLdouble w) { vertex(c, x, y, z, w); }
void exec::Vertex4f(GlContext& c, GLfloat x, GLfloat y, GLfloat z, GLfloat w) { vertex(c, x, y, z, w); }
void exec::Vertex4i(GlContext& c, GLint x, GLint y, GLint z, GLint w) { vertex(c, x, y, z, w); }
void exec::Vertex2dv(GlContext& c, const GLdouble* v) { vertex_v(c, v, 2); }
void exec::Vertex2fv(GlContext& c, const GLfloat* v) { vertex_v(c, v, 2); }
void exec::Vertex2iv(GlContext& c, const GLint* v) { vertex_v(c, v, 2); }
void exec::Vertex3dv(GlContext& c, const GLdouble* v) { vertex_v(c, v, 3); }
void exec::Vertex3fv(GlContext& c, const GLfloat* v) { vertex_v(c, v, 3); }
void exec::Vertex3iv(GlContext& c, const GLint* v) { vertex_v(c, v, 3); }
void exec::Vertex4dv(GlContext& c, const GLdouble* v) { vertex_v(c, v, 4); }
void exec::Vertex4fv(GlContext& c, const GLfloat* v) { vertex_v(c, v, 4); }
void exec::Vertex4iv(GlContext& c, const GLint* v) { vertex_v(c, v, 4); }

void exec::Normal3d(GlContext& c, GLdouble x, GLdouble y, GLdouble z) { normal(c, x, y, z); }
void exec::Normal3f(GlContext& c, GLfloat x, GLfloat y, GLfloat z) { normal(c, x, y, z); }
void exec::Normal3dv(GlContext& c, const GLdouble* v) { normal_v(c, v); }
void exec::Normal3fv(GlContext& c, const GLfloat* v) { normal_v(c, v); }

void exec::Color3d(GlContext& c, GLdouble r, GLdouble g, GLdouble b) {
  color(c, float(r), float(g), float(b), 1.0f);
}
void exec::Color3f(GlContext& c, GLfloat r, GLfloat g, GLfloat b) { color(c, r, g, b, 1.0f); }
void exec::Color3ub(GlContext& c, GLubyte r, GLubyte g, GLubyte b) {
  color(c, ubyte_to_float(r), ubyte_to_float(g), ubyte_to_float(b), 1.0f);
}
void exec::Color4d(GlContext& c, GLdouble r, GLdouble g, GLdouble b, GLdouble a) {
  color(c, float(r), float(g), float(b), float(a));
}
void exec::Color4f(GlContext& c, GLfloat r, GLfloat g, GLfloat b, GLfloat a) { color(c, r, g, b, a); }
void exec::Color4ub(GlContext& c, GLubyte r, GLubyte g, GLubyte b, GLubyte a) {
  color(c, ubyte_to_float(r), ubyte_to_float(g), ubyte_to_float(b), ubyte_to_float(a));
}
void exec::Color3dv(GlContext& c, const GLdouble* v) { color_v(c, v, 3); }
void exec::Color3fv(GlContext& c, const GLfloat* v) { color_v(c, v, 3); }
void exec::Color3ubv(GlContext& c, const GLubyte* v) { color_v(c, v, 3); }
void exec::Color4dv(GlContext& c, const GLdouble* v) { color_v(c, v, 4); }
void exec::Color4fv(GlContext& c, const GLfloat* v) { color_v(c, v, 4); }
void exec::Color4ubv(GlContext& c, const GLubyte* v) { color_v(c, v, 4); }

void exec::TexCoord2d(GlContext& c, GLdouble s, GLdouble t) { texcoord(c, s, t); }
void exec::TexCoord2f(GlContext& c, GLfloat s, GLfloat t) { texcoord(c, s, t); }
void exec::TexCoord2dv(GlContext& c, const GLdouble* v) { texcoord_v(c, v); }
void exec::TexCoord2fv(GlContext& c, const GLfloat* v) { texcoord_v(c, v); }

void exec::Rectf(GlContext& c, GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2) { rect(c, x1, y1, x2, y2); }
void exec::Rectd(GlContext& c, GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2) { rect(c, x1, y1, x2, y2); }
void exec::Recti(GlContext& c, GLint x1, GLint y1, GLint x2, GLint y2) { rect(c, x1, y1, x2, y2); }

}  // namespace shadelab::gl
