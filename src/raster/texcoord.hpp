// Texture coordinates per fragment as both pipelines compute them, in float: the screen-space
// weights rounded to float, the perspective division in float (the fast pipeline's varyings,
// fragment-inl.h's perspective_weights), and each coordinate's plane a2 + p0 (a0 - a2) +
// p1 (a1 - a2) without fused operations. The reference and every SIMD target then sample the
// same texel at the same place: a coordinate one float rounding apart picks another texel
// where it falls on a texel's edge, a whole texel's difference, not a rounding's. llvmpipe
// interpolates its coordinates in float too. Not for other varyings (colours are the
// reference's doubles).
#pragma once

#include <cstdint>

#include "shadelab/texture.hpp"

namespace shadelab::detail {

/// The perspective-correct weights of vertices 0 and 1 in float, from the screen-space
/// weights b0, b1 (edge function times 1 / area, in double). `inv_w` are the vertices' 1/w;
/// `affine` when the three are equal (the screen-space weights themselves).
struct FloatWeights {
  float p0, p1;
};

inline FloatWeights float_weights(double b0, double b1, const float inv_w[3], bool affine) {
  const float f0 = float(b0), f1 = float(b1);
  if (affine) return {f0, f1};
  const float f2 = (1.0f - f0) - f1;
  const float q0 = f0 * inv_w[0], q1 = f1 * inv_w[1], q2 = f2 * inv_w[2];
  const float inv = 1.0f / ((q0 + q1) + q2);
  return {q0 * inv, q1 * inv};
}

/// One coordinate over the triangle, from its values at the three vertices.
inline float texcoord_plane(float a0, float a1, float a2, FloatWeights w) {
  const float t0 = w.p0 * (a0 - a2), t1 = w.p1 * (a1 - a2);
  return (a2 + t0) + t1;
}

/// (s / q, t / q, r / q) from interpolated (s, t, r, q), made finite for the samplers
/// (finite_texcoord); r matters to 3D textures only.
struct ProjectedTexcoord {
  float s, t, r;
};

inline ProjectedTexcoord project_texcoord(float s, float t, float r, float q) {
  return {finite_texcoord(s / q), finite_texcoord(t / q), finite_texcoord(r / q)};
}

/// llvmpipe's level-of-detail differences for the 2x2 quad of GL rows (top, top - 1) and
/// columns (left, left + 1): from the top-left pixel to the one on its right and to the one
/// below it. `at(x, y)` gives the projected coordinates at a pixel's centre, inside the
/// triangle or not. llvmpipe's quads run from the top of the window down: top is
/// height - 1 - 2k.
template <class At>
TextureDerivatives quad_derivatives(int x, int y, int height, At&& at) {
  const int left = x & ~1, top = height - 1 - ((height - 1 - y) & ~1);
  const ProjectedTexcoord c = at(left, top), right = at(left + 1, top), b = at(left, top - 1);
  return {right.s - c.s, right.t - c.t, b.s - c.s, b.t - c.t, right.r - c.r, b.r - c.r, c.s, c.t, c.r};
}

}  // namespace shadelab::detail
