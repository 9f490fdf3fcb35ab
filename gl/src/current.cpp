// The current vertex attributes (GL 1.1 section 2.7): glColor*, glNormal3*, glTexCoord*,
// glIndex* and glEdgeFlag* in every type and size (glMultiTexCoord*: multitexture.cpp), GL 1.4's glSecondaryColor3* and glFogCoord*. Each
// converts its arguments (table 2.6 for colours and normals) and records them in
// GlContext::current; nothing is drawn here (a vertex takes them in draw.cpp's emit_vertex).
#include <type_traits>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"
#include "gl/src/convert.hpp"

namespace shadelab::gl {
namespace {

// The current colour; with GL_COLOR_MATERIAL the material follows it (section 2.13.3).
void color(GlContext& c, float r, float g, float b, float a) {
  c.current.color = glm::vec4(r, g, b, a);
  apply_color_material(c);
}

template <class T>
void color3(GlContext& c, T r, T g, T b) {
  color(c, color_component(r), color_component(g), color_component(b), 1.0f);
}

template <class T>
void color4(GlContext& c, T r, T g, T b, T a) {
  color(c, color_component(r), color_component(g), color_component(b), color_component(a));
}

// The vector forms: a null pointer is an error rather than a crash (Mesa would read it).
template <class T>
void color_v(GlContext& c, const T* v, int n) {
  if (!v) return c.set_error(GL_INVALID_VALUE);
  if (n == 3) return color3(c, v[0], v[1], v[2]);
  color4(c, v[0], v[1], v[2], v[3]);
}

// Normals convert as colours do (table 2.6); they are not normalized here (section 2.10.3).
template <class T>
void normal(GlContext& c, T x, T y, T z) {
  c.current.normal = glm::vec3(color_component(x), color_component(y), color_component(z));
}

template <class T>
void normal_v(GlContext& c, const T* v) {
  if (!v) return c.set_error(GL_INVALID_VALUE);
  normal(c, v[0], v[1], v[2]);
}

// Texture coordinates convert directly; missing ones are t = 0, r = 0, q = 1 (section 2.7).
void texcoord(GlContext& c, double s, double t, double r, double q) {
  c.current.texcoords[0] = glm::vec4(float(s), float(t), float(r), float(q));  // GL 1.3: unit 0's
}

template <class T>
void texcoord_v(GlContext& c, const T* v, int n) {
  if (!v) return c.set_error(GL_INVALID_VALUE);
  texcoord(c, double(v[0]), n > 1 ? double(v[1]) : 0.0, n > 2 ? double(v[2]) : 0.0, n > 3 ? double(v[3]) : 1.0);
}

// The current secondary colour (GL 1.4 section 2.7): red, green and blue converted as
// glColor's (table 2.6); alpha is kept at 1, as Mesa keeps it.
template <class T>
void secondary3(GlContext& c, T r, T g, T b) {
  c.current.secondary = glm::vec4(color_component(r), color_component(g), color_component(b), 1.0f);
}

template <class T>
void secondary_v(GlContext& c, const T* v) {
  if (!v) return c.set_error(GL_INVALID_VALUE);
  secondary3(c, v[0], v[1], v[2]);
}

// The current fog coordinate (GL 1.4 section 2.7), as given.
void fog_coord(GlContext& c, double f) { c.current.fog_coord = float(f); }

template <class T>
void fog_coord_v(GlContext& c, const T* v) {
  if (!v) return c.set_error(GL_INVALID_VALUE);
  fog_coord(c, double(v[0]));
}

// The colour index: stored and reported in an RGBA context, where it colours nothing
// (section 2.7; Mesa keeps it the same way).
template <class T>
void index(GlContext& c, T i) {
  c.current.index = float(i);
}

template <class T>
void index_v(GlContext& c, const T* v) {
  if (!v) return c.set_error(GL_INVALID_VALUE);
  index(c, v[0]);
}

}  // namespace

void exec::Color3b(GlContext& c, GLbyte r, GLbyte g, GLbyte b) { color3(c, r, g, b); }
void exec::Color3s(GlContext& c, GLshort r, GLshort g, GLshort b) { color3(c, r, g, b); }
void exec::Color3i(GlContext& c, GLint r, GLint g, GLint b) { color3(c, r, g, b); }
void exec::Color3f(GlContext& c, GLfloat r, GLfloat g, GLfloat b) { color3(c, r, g, b); }
void exec::Color3d(GlContext& c, GLdouble r, GLdouble g, GLdouble b) { color3(c, r, g, b); }
void exec::Color3ub(GlContext& c, GLubyte r, GLubyte g, GLubyte b) { color3(c, r, g, b); }
void exec::Color3us(GlContext& c, GLushort r, GLushort g, GLushort b) { color3(c, r, g, b); }
void exec::Color3ui(GlContext& c, GLuint r, GLuint g, GLuint b) { color3(c, r, g, b); }
void exec::Color4b(GlContext& c, GLbyte r, GLbyte g, GLbyte b, GLbyte a) { color4(c, r, g, b, a); }
void exec::Color4s(GlContext& c, GLshort r, GLshort g, GLshort b, GLshort a) { color4(c, r, g, b, a); }
void exec::Color4i(GlContext& c, GLint r, GLint g, GLint b, GLint a) { color4(c, r, g, b, a); }
void exec::Color4f(GlContext& c, GLfloat r, GLfloat g, GLfloat b, GLfloat a) { color4(c, r, g, b, a); }
void exec::Color4d(GlContext& c, GLdouble r, GLdouble g, GLdouble b, GLdouble a) { color4(c, r, g, b, a); }
void exec::Color4ub(GlContext& c, GLubyte r, GLubyte g, GLubyte b, GLubyte a) { color4(c, r, g, b, a); }
void exec::Color4us(GlContext& c, GLushort r, GLushort g, GLushort b, GLushort a) { color4(c, r, g, b, a); }
void exec::Color4ui(GlContext& c, GLuint r, GLuint g, GLuint b, GLuint a) { color4(c, r, g, b, a); }
void exec::Color3bv(GlContext& c, const GLbyte* v) { color_v(c, v, 3); }
void exec::Color3sv(GlContext& c, const GLshort* v) { color_v(c, v, 3); }
void exec::Color3iv(GlContext& c, const GLint* v) { color_v(c, v, 3); }
void exec::Color3fv(GlContext& c, const GLfloat* v) { color_v(c, v, 3); }
void exec::Color3dv(GlContext& c, const GLdouble* v) { color_v(c, v, 3); }
void exec::Color3ubv(GlContext& c, const GLubyte* v) { color_v(c, v, 3); }
void exec::Color3usv(GlContext& c, const GLushort* v) { color_v(c, v, 3); }
void exec::Color3uiv(GlContext& c, const GLuint* v) { color_v(c, v, 3); }
void exec::Color4bv(GlContext& c, const GLbyte* v) { color_v(c, v, 4); }
void exec::Color4sv(GlContext& c, const GLshort* v) { color_v(c, v, 4); }
void exec::Color4iv(GlContext& c, const GLint* v) { color_v(c, v, 4); }
void exec::Color4fv(GlContext& c, const GLfloat* v) { color_v(c, v, 4); }
void exec::Color4dv(GlContext& c, const GLdouble* v) { color_v(c, v, 4); }
void exec::Color4ubv(GlContext& c, const GLubyte* v) { color_v(c, v, 4); }
void exec::Color4usv(GlContext& c, const GLushort* v) { color_v(c, v, 4); }
void exec::Color4uiv(GlContext& c, const GLuint* v) { color_v(c, v, 4); }

void exec::Normal3b(GlContext& c, GLbyte x, GLbyte y, GLbyte z) { normal(c, x, y, z); }
void exec::Normal3s(GlContext& c, GLshort x, GLshort y, GLshort z) { normal(c, x, y, z); }
void exec::Normal3i(GlContext& c, GLint x, GLint y, GLint z) { normal(c, x, y, z); }
void exec::Normal3f(GlContext& c, GLfloat x, GLfloat y, GLfloat z) { normal(c, x, y, z); }
void exec::Normal3d(GlContext& c, GLdouble x, GLdouble y, GLdouble z) { normal(c, x, y, z); }
void exec::Normal3bv(GlContext& c, const GLbyte* v) { normal_v(c, v); }
void exec::Normal3sv(GlContext& c, const GLshort* v) { normal_v(c, v); }
void exec::Normal3iv(GlContext& c, const GLint* v) { normal_v(c, v); }
void exec::Normal3fv(GlContext& c, const GLfloat* v) { normal_v(c, v); }
void exec::Normal3dv(GlContext& c, const GLdouble* v) { normal_v(c, v); }

void exec::TexCoord1s(GlContext& c, GLshort s) { texcoord(c, s, 0, 0, 1); }
void exec::TexCoord1i(GlContext& c, GLint s) { texcoord(c, s, 0, 0, 1); }
void exec::TexCoord1f(GlContext& c, GLfloat s) { texcoord(c, s, 0, 0, 1); }
void exec::TexCoord1d(GlContext& c, GLdouble s) { texcoord(c, s, 0, 0, 1); }
void exec::TexCoord2s(GlContext& c, GLshort s, GLshort t) { texcoord(c, s, t, 0, 1); }
void exec::TexCoord2i(GlContext& c, GLint s, GLint t) { texcoord(c, s, t, 0, 1); }
void exec::TexCoord2f(GlContext& c, GLfloat s, GLfloat t) { texcoord(c, s, t, 0, 1); }
void exec::TexCoord2d(GlContext& c, GLdouble s, GLdouble t) { texcoord(c, s, t, 0, 1); }
void exec::TexCoord3s(GlContext& c, GLshort s, GLshort t, GLshort r) { texcoord(c, s, t, r, 1); }
void exec::TexCoord3i(GlContext& c, GLint s, GLint t, GLint r) { texcoord(c, s, t, r, 1); }
void exec::TexCoord3f(GlContext& c, GLfloat s, GLfloat t, GLfloat r) { texcoord(c, s, t, r, 1); }
void exec::TexCoord3d(GlContext& c, GLdouble s, GLdouble t, GLdouble r) { texcoord(c, s, t, r, 1); }
void exec::TexCoord4s(GlContext& c, GLshort s, GLshort t, GLshort r, GLshort q) { texcoord(c, s, t, r, q); }
void exec::TexCoord4i(GlContext& c, GLint s, GLint t, GLint r, GLint q) { texcoord(c, s, t, r, q); }
void exec::TexCoord4f(GlContext& c, GLfloat s, GLfloat t, GLfloat r, GLfloat q) { texcoord(c, s, t, r, q); }
void exec::TexCoord4d(GlContext& c, GLdouble s, GLdouble t, GLdouble r, GLdouble q) { texcoord(c, s, t, r, q); }
void exec::TexCoord1sv(GlContext& c, const GLshort* v) { texcoord_v(c, v, 1); }
void exec::TexCoord1iv(GlContext& c, const GLint* v) { texcoord_v(c, v, 1); }
void exec::TexCoord1fv(GlContext& c, const GLfloat* v) { texcoord_v(c, v, 1); }
void exec::TexCoord1dv(GlContext& c, const GLdouble* v) { texcoord_v(c, v, 1); }
void exec::TexCoord2sv(GlContext& c, const GLshort* v) { texcoord_v(c, v, 2); }
void exec::TexCoord2iv(GlContext& c, const GLint* v) { texcoord_v(c, v, 2); }
void exec::TexCoord2fv(GlContext& c, const GLfloat* v) { texcoord_v(c, v, 2); }
void exec::TexCoord2dv(GlContext& c, const GLdouble* v) { texcoord_v(c, v, 2); }
void exec::TexCoord3sv(GlContext& c, const GLshort* v) { texcoord_v(c, v, 3); }
void exec::TexCoord3iv(GlContext& c, const GLint* v) { texcoord_v(c, v, 3); }
void exec::TexCoord3fv(GlContext& c, const GLfloat* v) { texcoord_v(c, v, 3); }
void exec::TexCoord3dv(GlContext& c, const GLdouble* v) { texcoord_v(c, v, 3); }
void exec::TexCoord4sv(GlContext& c, const GLshort* v) { texcoord_v(c, v, 4); }
void exec::TexCoord4iv(GlContext& c, const GLint* v) { texcoord_v(c, v, 4); }
void exec::TexCoord4fv(GlContext& c, const GLfloat* v) { texcoord_v(c, v, 4); }
void exec::TexCoord4dv(GlContext& c, const GLdouble* v) { texcoord_v(c, v, 4); }

void exec::Indexs(GlContext& c, GLshort i) { index(c, i); }
void exec::Indexi(GlContext& c, GLint i) { index(c, i); }
void exec::Indexf(GlContext& c, GLfloat i) { index(c, i); }
void exec::Indexd(GlContext& c, GLdouble i) { index(c, i); }
void exec::Indexub(GlContext& c, GLubyte i) { index(c, i); }
void exec::Indexsv(GlContext& c, const GLshort* v) { index_v(c, v); }
void exec::Indexiv(GlContext& c, const GLint* v) { index_v(c, v); }
void exec::Indexfv(GlContext& c, const GLfloat* v) { index_v(c, v); }
void exec::Indexdv(GlContext& c, const GLdouble* v) { index_v(c, v); }
void exec::Indexubv(GlContext& c, const GLubyte* v) { index_v(c, v); }

void exec::SecondaryColor3b(GlContext& c, GLbyte r, GLbyte g, GLbyte b) { secondary3(c, r, g, b); }
void exec::SecondaryColor3s(GlContext& c, GLshort r, GLshort g, GLshort b) { secondary3(c, r, g, b); }
void exec::SecondaryColor3i(GlContext& c, GLint r, GLint g, GLint b) { secondary3(c, r, g, b); }
void exec::SecondaryColor3f(GlContext& c, GLfloat r, GLfloat g, GLfloat b) { secondary3(c, r, g, b); }
void exec::SecondaryColor3d(GlContext& c, GLdouble r, GLdouble g, GLdouble b) { secondary3(c, r, g, b); }
void exec::SecondaryColor3ub(GlContext& c, GLubyte r, GLubyte g, GLubyte b) { secondary3(c, r, g, b); }
void exec::SecondaryColor3us(GlContext& c, GLushort r, GLushort g, GLushort b) { secondary3(c, r, g, b); }
void exec::SecondaryColor3ui(GlContext& c, GLuint r, GLuint g, GLuint b) { secondary3(c, r, g, b); }
void exec::SecondaryColor3bv(GlContext& c, const GLbyte* v) { secondary_v(c, v); }
void exec::SecondaryColor3sv(GlContext& c, const GLshort* v) { secondary_v(c, v); }
void exec::SecondaryColor3iv(GlContext& c, const GLint* v) { secondary_v(c, v); }
void exec::SecondaryColor3fv(GlContext& c, const GLfloat* v) { secondary_v(c, v); }
void exec::SecondaryColor3dv(GlContext& c, const GLdouble* v) { secondary_v(c, v); }
void exec::SecondaryColor3ubv(GlContext& c, const GLubyte* v) { secondary_v(c, v); }
void exec::SecondaryColor3usv(GlContext& c, const GLushort* v) { secondary_v(c, v); }
void exec::SecondaryColor3uiv(GlContext& c, const GLuint* v) { secondary_v(c, v); }

void exec::FogCoordf(GlContext& c, GLfloat f) { fog_coord(c, f); }
void exec::FogCoordd(GlContext& c, GLdouble f) { fog_coord(c, f); }
void exec::FogCoordfv(GlContext& c, const GLfloat* v) { fog_coord_v(c, v); }
void exec::FogCoorddv(GlContext& c, const GLdouble* v) { fog_coord_v(c, v); }

// The edge flag (section 2.6.2) is kept as the number given, as Mesa keeps it: GL_EDGE_FLAG
// reads GL_TRUE only for exactly 1 (glEdgeFlag(2) reads back GL_FALSE there too).
void exec::EdgeFlag(GlContext& c, GLboolean flag) { c.current.edge_flag = float(flag); }
void exec::EdgeFlagv(GlContext& c, const GLboolean* flag) {
  if (!flag) return c.set_error(GL_INVALID_VALUE);
  c.current.edge_flag = float(flag[0]);
}

}  // namespace shadelab::gl
