// Per-vertex operations the two vertex paths share (draw.cpp's glBegin/glEnd and
// array_mesh.cpp's vertex arrays): NaN made 0 in colours, the modelview transform in glm's
// order of operations, the eye-space normal GL lights with, texture coordinates (glTexGen,
// the texture matrix), whether clip coordinates are finite, and a flat triangle's rotation.
// Inline, as they run once per vertex; they change no state, light nothing and draw nothing.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/src/context.hpp"
#include "gl/src/convert.hpp"
#include "gl/src/texgen.hpp"

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace shadelab::gl {

// NaN components made 0 (finite_or_zero).
inline glm::vec4 sanitize(glm::vec4 v) {
  for (int i = 0; i < 4; ++i) v[i] = finite_or_zero(v[i]);
  return v;
}
inline glm::vec3 sanitize(glm::vec3 v) {
  for (int i = 0; i < 3; ++i) v[i] = finite_or_zero(v[i]);
  return v;
}

// m * v with glm's operations in glm's order, (m0 x + m1 y) + (m2 z + m3 w), so the same
// floats; in one SSE register where the target has one. glm's operator*, called from the
// per-vertex loops, was not inlined: its result went through memory in two halves and was
// read back whole, a store-forwarding stall per vertex (most of draw_array_mesh's time on
// the 1M-triangle sphere).
[[gnu::always_inline]] inline glm::vec4 transform(const glm::mat4& m, const glm::vec4& v) {
#if defined(__SSE2__)
  const __m128 x = _mm_set1_ps(v.x), y = _mm_set1_ps(v.y), z = _mm_set1_ps(v.z), w = _mm_set1_ps(v.w);
  const __m128 a = _mm_add_ps(_mm_mul_ps(_mm_loadu_ps(&m[0][0]), x), _mm_mul_ps(_mm_loadu_ps(&m[1][0]), y));
  const __m128 b = _mm_add_ps(_mm_mul_ps(_mm_loadu_ps(&m[2][0]), z), _mm_mul_ps(_mm_loadu_ps(&m[3][0]), w));
  alignas(16) float out[4];
  _mm_store_ps(out, _mm_add_ps(a, b));
  return glm::vec4(out[0], out[1], out[2], out[3]);
#else
  return m * v;
#endif
}

// The eye-space normal GL lights with: inverse transpose of the modelview, then rescaled
// (GL 1.2 equation 2.1) or normalized when enabled; otherwise left as it is.
[[gnu::always_inline]] inline glm::vec3 eye_normal(const GlContext& c, const glm::vec3& normal) {
  const Primitive& p = c.prim;
  glm::vec3 n = p.normal_matrix * normal;
  if (c.lighting.normalize) {
    float len = glm::length(n);
    return len > 0.0f ? n / len : n;
  }
  return c.lighting.rescale_normal ? n * p.rescale : n;
}

// (s, t, r, q) after texture unit `unit`'s texture matrix; the pipeline divides by q per
// fragment.
inline glm::vec4 texcoord(const GlContext& c, std::size_t unit, glm::vec4 tc) {
  if (!c.prim.identity_texture_matrix[unit]) tc = c.prim.texture_matrix[unit] * tc;
  return tc;
}

// A vertex's texture coordinates for texture unit `unit` before its texture matrix: `given`,
// or generated where the unit's glTexGen is enabled (GL 1.1 section 2.10.4) from its object and eye positions and its
// object-space `normal` (transformed here when a sphere map reads it).
inline glm::vec4 source_texcoord(const GlContext& c, std::size_t unit, const glm::vec4& given, const glm::vec4& object,
                                 const glm::vec4& eye, const glm::vec3& normal) {
  const TextureUnitState& t = c.textures.units[unit];
  if (!t.any_texgen()) return given;
  const glm::vec3 n = texgen_needs_normal(t) ? eye_normal(c, normal) : glm::vec3(0.0f);
  return generate_texcoords(t, given, object, eye, n);
}

// Whether every entry is finite and at most 1e18 in magnitude: products of two such numbers,
// and sums of four products, stay below 4e36, finite.
inline bool bounded(const float* v, int n) {
  bool ok = true;
  for (int i = 0; i < n; ++i) ok &= std::fabs(v[i]) <= 1e18f;  // false for NaN
  return ok;
}

// Whether projection * eye is finite; `small_projection`: bounded(projection), checked once.
[[gnu::always_inline]] inline bool finite_clip(const glm::mat4& projection, bool small_projection,
                                               const glm::vec4& eye) {
#if defined(__SSE2__)  // bounded(&eye[0], 4) in one comparison of the four (false for NaN)
  const __m128 magnitude = _mm_andnot_ps(_mm_set1_ps(-0.0f), _mm_loadu_ps(&eye[0]));
  const bool small_eye = _mm_movemask_ps(_mm_cmple_ps(magnitude, _mm_set1_ps(1e18f))) == 0xf;
#else
  const bool small_eye = bounded(&eye[0], 4);
#endif
  if (small_projection && small_eye) return true;  // no overflow possible
  glm::vec4 clip = transform(projection, eye);
  return std::isfinite(clip.x) && std::isfinite(clip.y) && std::isfinite(clip.z) &&
         std::isfinite(clip.w);
}

// Rotates a triangle so that its provoking vertex comes last (the core's flat convention);
// false when the provoking vertex is not one of its three.
inline bool provoking_last(const PrimitiveTriangle& t, Triangle& out) {
  const std::uint32_t* v = t.v;
  if (v[0] == t.provoking) out = {v[1], v[2], v[0]};
  else if (v[1] == t.provoking) out = {v[2], v[0], v[1]};
  else if (v[2] == t.provoking) out = {v[0], v[1], v[2]};
  else return false;
  return true;
}

}  // namespace shadelab::gl
