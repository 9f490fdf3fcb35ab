// Per-fragment operations (GL 1.1 sections 3.5.2, 3.9 and chapter 4.1): polygon stipple,
// fog, scissor, alpha test, stencil test, depth test, blending or logic op and the colour
// mask, on one framebuffer pixel. The reference's arithmetic, which the fast pipeline's SIMD
// path repeats lane by lane. Private to the pipeline.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shadelab/pipeline.hpp"

namespace shadelab::detail {

/// Fog's per-draw constants, as Mesa's state tracker derives them (prog_statevars.c's
/// STATE_FOG_PARAMS_OPTIMIZED): linear fog is c * scale + bias; GL_EXP is 2^-(c k) and GL_EXP2
/// 2^-((c k)^2), with k = density / ln 2 and density / sqrt(ln 2), computed in double and
/// rounded to float. start == end gives scale 1, as in Mesa.
struct FogParams {
  FogMode mode = FogMode::kExp;
  float scale = 0.0f, bias = 0.0f;  ///< linear
  float k = 0.0f;                   ///< exp, exp2
  glm::vec3 color{0.0f};
};
FogParams fog_params(const FogState& fog);

/// The fog factor at fog coordinate c, clamped to [0, 1] (NaN to 0).
float fog_factor(const FogParams& p, float c);

/// Fog blended into `color` (red, green, blue: f (C - C_fog) + C_fog; alpha kept).
glm::vec4 apply_fog(const FogParams& p, float c, glm::vec4 color);

/// Whether window pixel (x, y) passes the scissor test and, for polygons, the polygon stipple.
inline bool pixel_kept(const FragmentState& f, int x, int y, bool polygon) {
  const ScissorState& s = f.scissor;
  if (s.enabled && (x < s.x || y < s.y || x - s.x >= s.width || y - s.y >= s.height)) return false;
  return !(polygon && f.stipple.enabled) || ((f.stipple.rows[std::size_t(y & 31)] >> (x & 31)) & 1u);
}

/// A colour channel as the 8-bit colour buffer stores it: clamped to [0, 1] (NaN to 0),
/// times 255, rounded half away from zero.
std::uint8_t unorm8(float c);

/// The alpha test on a fragment's alpha, in 8 bits (AlphaTestState). True: kept.
bool alpha_test(const AlphaTestState& a, float alpha);

/// glLogicOp's operation on 32-bit words of four 8-bit channels.
std::uint32_t logic_op(LogicOp op, std::uint32_t s, std::uint32_t d);

bool compare(CompareFunc func, float incoming, float stored);
bool compare_stencil(CompareFunc func, unsigned ref, unsigned stored);

/// Runs the stencil and depth tests for the fragment at pixel index `i` with depth `z`,
/// updating stencil and depth as GL specifies. Returns true if the fragment survives.
bool depth_stencil_test(Framebuffer& fb, std::size_t i, float z, const FragmentState& state);

/// glBlendColor's constant as the colour buffer holds it: each channel rounded to 8 bits (as
/// llvmpipe stores it for an 8-bit buffer), back in [0, 1].
glm::vec4 blend_constant(const BlendState& b);

/// The blended colour (GL 1.4 section 4.1.7) of source `src` (clamped to [0, 1]) over
/// destination `dst` (the pixel's, in [0, 1]), with `constant` from blend_constant: unclamped
/// (a subtraction may go below 0). Each product and the sum or difference rounded in float.
glm::vec4 blend(const BlendState& b, const glm::vec4& constant, const glm::vec4& src, const glm::vec4& dst);

/// Blends `src` (unclamped colour, alpha) into pixel `i`, or combines it by the logic op
/// when that is enabled, and writes it through the colour mask.
void write_color(Framebuffer& fb, std::size_t i, glm::vec4 src, const FragmentState& state);

}  // namespace shadelab::detail
