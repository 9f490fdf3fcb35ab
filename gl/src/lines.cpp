// Points, lines, polygon modes and user clip planes (GL 1.1 sections 2.11, 3.3-3.5):
// glPointSize, glLineWidth, glLineStipple, glPolygonMode, glClipPlane and glGetClipPlane.
// State and validation only, with Mesa's errors; draw_state.cpp hands the state to the pipeline
// (the edge flags are in current.cpp and arrays.cpp).
#include <algorithm>
#include <glm/matrix.hpp>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {

// GL 1.1 section 3.3: a size must be positive (Mesa rejects `size <= 0` only: NaN is kept).
void exec::PointSize(GlContext& c, GLfloat size) {
  if (size <= 0.0f) return c.set_error(GL_INVALID_VALUE);
  c.prims.point_size = size;
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
