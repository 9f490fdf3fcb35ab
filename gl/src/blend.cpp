// Blending (GL 1.4 section 4.1.7, the imaging subset's blending made core): glBlendFunc,
// glBlendFuncSeparate, glBlendEquation, glBlendColor, and EXT_blend_equation_separate's
// glBlendEquationSeparateEXT. Stores state; the core pipeline blends
// (BlendState, draw_state.cpp translates).
#include <algorithm>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {
namespace {

// GL 1.4's factors, each accepted as a source and as a destination factor, as Mesa accepts
// them (GL 1.4 allows the source colour as a source factor and the destination colour as a
// destination factor; Mesa also takes GL_SRC_ALPHA_SATURATE as a destination factor).
bool is_blend_factor(GLenum f) {
  return f == GL_ZERO || f == GL_ONE || (f >= GL_SRC_COLOR && f <= GL_SRC_ALPHA_SATURATE) ||
         (f >= GL_CONSTANT_COLOR && f <= GL_ONE_MINUS_CONSTANT_ALPHA);
}

bool is_blend_equation(GLenum mode) {
  return mode == GL_FUNC_ADD || mode == GL_FUNC_SUBTRACT || mode == GL_FUNC_REVERSE_SUBTRACT || mode == GL_MIN ||
         mode == GL_MAX;
}

// Section 4.1.7: the constant colour is clamped to [0, 1] when given (NaN to 0).
float clamp01(float v) { return v == v ? std::clamp(v, 0.0f, 1.0f) : 0.0f; }

}  // namespace

// The same factors for the colour and for alpha.
void exec::BlendFunc(GlContext& c, GLenum sfactor, GLenum dfactor) {
  exec::BlendFuncSeparate(c, sfactor, dfactor, sfactor, dfactor);
}

void exec::BlendFuncSeparate(GlContext& c, GLenum sfactor_rgb, GLenum dfactor_rgb, GLenum sfactor_alpha,
                             GLenum dfactor_alpha) {
  if (!is_blend_factor(sfactor_rgb) || !is_blend_factor(dfactor_rgb) || !is_blend_factor(sfactor_alpha) ||
      !is_blend_factor(dfactor_alpha)) {
    return c.set_error(GL_INVALID_ENUM);
  }
  RasterState& r = c.raster;
  r.blend_src = sfactor_rgb, r.blend_dst = dfactor_rgb;
  r.blend_src_alpha = sfactor_alpha, r.blend_dst_alpha = dfactor_alpha;
}

// The same equation for the colour and for alpha.
void exec::BlendEquation(GlContext& c, GLenum mode) { exec::BlendEquationSeparateEXT(c, mode, mode); }

// EXT_blend_equation_separate: either equation unknown is GL_INVALID_ENUM, and nothing is set.
void exec::BlendEquationSeparateEXT(GlContext& c, GLenum mode_rgb, GLenum mode_alpha) {
  if (!is_blend_equation(mode_rgb) || !is_blend_equation(mode_alpha)) return c.set_error(GL_INVALID_ENUM);
  c.raster.blend_equation = mode_rgb;
  c.raster.blend_equation_alpha = mode_alpha;
}

void exec::BlendColor(GlContext& c, GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha) {
  c.raster.blend_color = glm::vec4(clamp01(red), clamp01(green), clamp01(blue), clamp01(alpha));
}

}  // namespace shadelab::gl
