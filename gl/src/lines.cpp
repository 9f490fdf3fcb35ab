// Points, lines, polygon modes and user clip planes (GL 1.1 sections 2.11, 3.3-3.5):
// glPointSize, GL 1.4's glPointParameter, glLineWidth, glLineStipple, glPolygonMode, glClipPlane and glGetClipPlane.
// State and validation only, with Mesa's errors; draw_state.cpp hands the state to the pipeline
// (the edge flags are in current.cpp and arrays.cpp).
#include <algorithm>
#include <glm/matrix.hpp>

#include "gl/generated/exec.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {

// GL 1.1 section 3.3: a size must be positive (Mesa rejects `size <= 0` only: NaN is kept).
void exec::PointSize(GlContext& c, GLfloat size) {
  if (size <= 0.0f) return c.set_error(GL_INVALID_VALUE);
  c.prims.point_size = size;
}

// GL 1.4 section 3.3 with Mesa's rules: a negative size or threshold is GL_INVALID_VALUE; the
// scalar forms of GL_POINT_DISTANCE_ATTENUATION set (param, 0, 0). `p` holds three values.
namespace {
void point_parameter(GlContext& c, GLenum pname, const GLfloat* p) {
  PrimState& s = c.prims;
  switch (pname) {
    case GL_POINT_DISTANCE_ATTENUATION: s.point_attenuation = glm::vec3(p[0], p[1], p[2]); return;
    case GL_POINT_SIZE_MIN:
    case GL_POINT_SIZE_MAX:
    case GL_POINT_FADE_THRESHOLD_SIZE:
      if (p[0] < 0.0f) return c.set_error(GL_INVALID_VALUE);
      (pname == GL_POINT_SIZE_MIN ? s.point_min : pname == GL_POINT_SIZE_MAX ? s.point_max : s.point_fade) = p[0];
      return;
    default: c.set_error(GL_INVALID_ENUM);
  }
}
}  // namespace

// How many values glPointParameterfv / iv read (display lists copy them).
std::size_t save_count::PointParameterfv(GLenum pname) { return pname == GL_POINT_DISTANCE_ATTENUATION ? 3 : 1; }
std::size_t save_count::PointParameteriv(GLenum pname) { return pname == GL_POINT_DISTANCE_ATTENUATION ? 3 : 1; }

void exec::PointParameterf(GlContext& c, GLenum pname, GLfloat param) {
  const GLfloat p[3] = {param, 0.0f, 0.0f};
  point_parameter(c, pname, p);
}
void exec::PointParameteri(GlContext& c, GLenum pname, GLint param) {
  const GLfloat p[3] = {GLfloat(param), 0.0f, 0.0f};
  point_parameter(c, pname, p);
}
void exec::PointParameterfv(GlContext& c, GLenum pname, const GLfloat* params) {
  if (!params) return;  // nothing to read (Mesa would fault)
  GLfloat p[3] = {params[0], 0.0f, 0.0f};
  if (pname == GL_POINT_DISTANCE_ATTENUATION) p[1] = params[1], p[2] = params[2];
  point_parameter(c, pname, p);
}
void exec::PointParameteriv(GlContext& c, GLenum pname, const GLint* params) {
  if (!params) return;
  GLfloat p[3] = {GLfloat(params[0]), 0.0f, 0.0f};
  if (pname == GL_POINT_DISTANCE_ATTENUATION) p[1] = GLfloat(params[1]), p[2] = GLfloat(params[2]);
  point_parameter(c, pname, p);
}

// Section 3.4: likewise for the line width.
void exec::LineWidth(GlContext& c, GLfloat width) {
  if (width <= 0.0f) return c.set_error(GL_INVALID_VALUE);
  c.prims.line_width = width;
}

// Section 3.4.2: the repeat factor is clamped to [1, 256]; no error.
void exec::LineStipple(GlContext& c, GLint factor, GLushort pattern) {
  c.prims.stipple_repeat = std::clamp(factor, 1, 256);
  c.prims.stipple_pattern = pattern;
}

// Section 3.5.4. Mesa checks the mode first, then the face.
void exec::PolygonMode(GlContext& c, GLenum face, GLenum mode) {
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) return c.set_error(GL_INVALID_ENUM);
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK)
    return c.set_error(GL_INVALID_ENUM);
  if (face != GL_BACK) c.prims.front_mode = mode;
  if (face != GL_FRONT) c.prims.back_mode = mode;
}

// Section 2.11: the plane is transformed to eye space by the inverse of the modelview matrix
// current at the call (a row vector times M^-1), and kept there. Mesa rounds the plane to
// float first.
void exec::ClipPlane(GlContext& c, GLenum plane, const GLdouble* equation) {
  const GLint i = GLint(plane) - GLint(GL_CLIP_PLANE0);
  if (i < 0 || i >= kMaxClipPlanes) return c.set_error(GL_INVALID_ENUM);
  if (!equation) return c.set_error(GL_INVALID_VALUE);
  const glm::vec4 given{float(equation[0]), float(equation[1]), float(equation[2]),
                        float(equation[3])};
  const glm::dvec4 rounded{given};
  const glm::dvec4 eye = rounded * glm::inverse(glm::dmat4(c.modelview.top()));
  c.prims.clip_planes[std::size_t(i)] = glm::vec4(eye);
}

void exec::GetClipPlane(GlContext& c, GLenum plane, GLdouble* equation) {
  const GLint i = GLint(plane) - GLint(GL_CLIP_PLANE0);
  if (i < 0 || i >= kMaxClipPlanes) return c.set_error(GL_INVALID_ENUM);
  if (!equation) return c.set_error(GL_INVALID_VALUE);
  const glm::vec4& p = c.prims.clip_planes[std::size_t(i)];
  for (int k = 0; k < 4; ++k) equation[k] = double(p[k]);
}

}  // namespace shadelab::gl
