// Immediate mode (GL 1.1 sections 2.6-2.7): glBegin/glEnd, glVertex*, and the current
// attributes glNormal*, glColor*, glTexCoord*; glRect* (section 2.9). Records attributes and
// passes vertices to draw.cpp; transformation and lighting happen there.
#include "gl/src/convert.hpp"
#include "gl/src/draw.hpp"

namespace shadelab::gl {
namespace {

// glVertex outside glBegin/glEnd does nothing (GL 1.1 section 2.6.3 leaves it undefined).
void vertex(double x, double y, double z, double w) {
  with_context([&](GlContext& c) {
    if (!c.prim.active) return;
    emit_vertex(c, glm::vec4(float(x), float(y), float(z), float(w)));
  });
}

template <class T>
void vertex_v(const T* v, int n) {
  if (!v) return with_context([](GlContext& c) { c.set_error(GL_INVALID_VALUE); });
  vertex(double(v[0]), double(v[1]), n > 2 ? double(v[2]) : 0.0, n > 3 ? double(v[3]) : 1.0);
}

void normal(double x, double y, double z) {
  with_context([&](GlContext& c) { c.current.normal = glm::vec3(float(x), float(y), float(z)); });
}

// The current colour; with GL_COLOR_MATERIAL the material follows it (section 2.13.3).
void color(float r, float g, float b, float a) {
  with_context([&](GlContext& c) {
    c.current.color = glm::vec4(r, g, b, a);
    apply_color_material(c);
  });
}

template <class T>
void color_v(const T* v, int n) {
  if (!v) return with_context([](GlContext& c) { c.set_error(GL_INVALID_VALUE); });
  if constexpr (std::is_same_v<T, GLubyte>) {
    color(ubyte_to_float(v[0]), ubyte_to_float(v[1]), ubyte_to_float(v[2]),
          n > 3 ? ubyte_to_float(v[3]) : 1.0f);
  } else {
    color(float(v[0]), float(v[1]), float(v[2]), n > 3 ? float(v[3]) : 1.0f);
  }
}

void texcoord(double s, double t) {
  with_context([&](GlContext& c) { c.current.texcoord = glm::vec4(float(s), float(t), 0.0f, 1.0f); });
}

// glRect: a GL_POLYGON (x1, y1), (x2, y1), (x2, y2), (x1, y2) in z = 0 (section 2.9).
void rect(double x1, double y1, double x2, double y2) {
  outside_begin_end([&](GlContext& c) {
    begin_primitive(c, GL_POLYGON);
    emit_vertex(c, glm::vec4(float(x1), float(y1), 0.0f, 1.0f));
    emit_vertex(c, glm::vec4(float(x2), float(y1), 0.0f, 1.0f));
    emit_vertex(c, glm::vec4(float(x2), float(y2), 0.0f, 1.0f));
    emit_vertex(c, glm::vec4(float(x1), float(y2), 0.0f, 1.0f));
    end_primitive(c);
  });
}

}  // namespace
}  // namespace shadelab::gl

using namespace shadelab::gl;

extern "C" {

// GL_POINTS and the line modes are valid and accepted, but shadelab draws only polygons.
void GLAPIENTRY glBegin(GLenum mode) {
  outside_begin_end([&](GlContext& c) {
    if (mode > GL_POLYGON) return c.set_error(GL_INVALID_ENUM);
    begin_primitive(c, mode);
  });
}

void GLAPIENTRY glEnd(void) {
  with_context([](GlContext& c) {
    if (!c.prim.active) return c.set_error(GL_INVALID_OPERATION);
    end_primitive(c);
  });
}

void GLAPIENTRY glVertex2d(GLdouble x, GLdouble y) { vertex(x, y, 0, 1); }
void GLAPIENTRY glVertex2f(GLfloat x, GLfloat y) { vertex(x, y, 0, 1); }
void GLAPIENTRY glVertex2i(GLint x, GLint y) { vertex(x, y, 0, 1); }
void GLAPIENTRY glVertex3d(GLdouble x, GLdouble y, GLdouble z) { vertex(x, y, z, 1); }
void GLAPIENTRY glVertex3f(GLfloat x, GLfloat y, GLfloat z) { vertex(x, y, z, 1); }
void GLAPIENTRY glVertex3i(GLint x, GLint y, GLint z) { vertex(x, y, z, 1); }
void GLAPIENTRY glVertex4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) { vertex(x, y, z, w); }
void GLAPIENTRY glVertex4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { vertex(x, y, z, w); }
void GLAPIENTRY glVertex4i(GLint x, GLint y, GLint z, GLint w) { vertex(x, y, z, w); }
void GLAPIENTRY glVertex2dv(const GLdouble* v) { vertex_v(v, 2); }
void GLAPIENTRY glVertex2fv(const GLfloat* v) { vertex_v(v, 2); }
void GLAPIENTRY glVertex2iv(const GLint* v) { vertex_v(v, 2); }
void GLAPIENTRY glVertex3dv(const GLdouble* v) { vertex_v(v, 3); }
void GLAPIENTRY glVertex3fv(const GLfloat* v) { vertex_v(v, 3); }
void GLAPIENTRY glVertex3iv(const GLint* v) { vertex_v(v, 3); }
void GLAPIENTRY glVertex4dv(const GLdouble* v) { vertex_v(v, 4); }
void GLAPIENTRY glVertex4fv(const GLfloat* v) { vertex_v(v, 4); }
void GLAPIENTRY glVertex4iv(const GLint* v) { vertex_v(v, 4); }

void GLAPIENTRY glNormal3d(GLdouble x, GLdouble y, GLdouble z) { normal(x, y, z); }
void GLAPIENTRY glNormal3f(GLfloat x, GLfloat y, GLfloat z) { normal(x, y, z); }
void GLAPIENTRY glNormal3dv(const GLdouble* v) {
  if (!v) return with_context([](GlContext& c) { c.set_error(GL_INVALID_VALUE); });
  normal(v[0], v[1], v[2]);
}
void GLAPIENTRY glNormal3fv(const GLfloat* v) {
  if (!v) return with_context([](GlContext& c) { c.set_error(GL_INVALID_VALUE); });
  normal(v[0], v[1], v[2]);
}

void GLAPIENTRY glColor3d(GLdouble r, GLdouble g, GLdouble b) { color(float(r), float(g), float(b), 1.0f); }
void GLAPIENTRY glColor3f(GLfloat r, GLfloat g, GLfloat b) { color(r, g, b, 1.0f); }
void GLAPIENTRY glColor3ub(GLubyte r, GLubyte g, GLubyte b) {
  color(ubyte_to_float(r), ubyte_to_float(g), ubyte_to_float(b), 1.0f);
}
void GLAPIENTRY glColor4d(GLdouble r, GLdouble g, GLdouble b, GLdouble a) {
  color(float(r), float(g), float(b), float(a));
}
void GLAPIENTRY glColor4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a) { color(r, g, b, a); }
void GLAPIENTRY glColor4ub(GLubyte r, GLubyte g, GLubyte b, GLubyte a) {
  color(ubyte_to_float(r), ubyte_to_float(g), ubyte_to_float(b), ubyte_to_float(a));
}
void GLAPIENTRY glColor3dv(const GLdouble* v) { color_v(v, 3); }
void GLAPIENTRY glColor3fv(const GLfloat* v) { color_v(v, 3); }
void GLAPIENTRY glColor3ubv(const GLubyte* v) { color_v(v, 3); }
void GLAPIENTRY glColor4dv(const GLdouble* v) { color_v(v, 4); }
void GLAPIENTRY glColor4fv(const GLfloat* v) { color_v(v, 4); }
void GLAPIENTRY glColor4ubv(const GLubyte* v) { color_v(v, 4); }

void GLAPIENTRY glTexCoord2d(GLdouble s, GLdouble t) { texcoord(s, t); }
void GLAPIENTRY glTexCoord2f(GLfloat s, GLfloat t) { texcoord(s, t); }
void GLAPIENTRY glTexCoord2dv(const GLdouble* v) {
  if (!v) return with_context([](GlContext& c) { c.set_error(GL_INVALID_VALUE); });
  texcoord(v[0], v[1]);
}
void GLAPIENTRY glTexCoord2fv(const GLfloat* v) {
  if (!v) return with_context([](GlContext& c) { c.set_error(GL_INVALID_VALUE); });
  texcoord(v[0], v[1]);
}

void GLAPIENTRY glRectf(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2) { rect(x1, y1, x2, y2); }
void GLAPIENTRY glRectd(GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2) { rect(x1, y1, x2, y2); }
void GLAPIENTRY glRecti(GLint x1, GLint y1, GLint x2, GLint y2) { rect(x1, y1, x2, y2); }

}  // extern "C"
