// The reference rasterizer: simple and exact, kept as the oracle for faster paths.
// Window coordinates are snapped to 1/256 pixel; coverage uses 64-bit edge functions at pixel
// centres (x + 0.5, y + 0.5) with llvmpipe's fill rule (see docs/rasterization.md).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "raster/texcoord.hpp"

namespace shadelab::detail {

inline constexpr int kSubpixelBits = 8;
inline constexpr std::int64_t kSubpixelOne = 1 << kSubpixelBits;

struct FixedPoint {
  std::int64_t x, y;
};

inline FixedPoint snap(double x, double y) {
  return {std::llround(x * kSubpixelOne), std::llround(y * kSubpixelOne)};
}

/// Twice the signed area of (a, b, p): positive when p is left of a->b (counter-clockwise
/// with y up, GL window space).
inline std::int64_t edge_function(FixedPoint a, FixedPoint b, FixedPoint p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

/// Fill rule for a counter-clockwise triangle in y-up window space: a pixel centre exactly on
/// an edge belongs to the triangle if the edge is a left edge (going down) or a bottom edge
/// (horizontal, going right, the interior above it). This is the top-left rule of a y-down
/// raster whose first row is GL's bottom row (OSMesa's buffer order), and what Mesa's llvmpipe
/// does; each edge shared by two triangles gives its pixels to exactly one of them.
inline bool owns_edge(FixedPoint a, FixedPoint b) {
  std::int64_t dx = b.x - a.x, dy = b.y - a.y;
  return dy < 0 || (dy == 0 && dx > 0);
}

/// The float weights of the oriented triangle `v` at a point with edge functions w0, w1
/// (texcoord.hpp).
inline FloatWeights texcoord_weights(const WindowVertex* const v[3], double w0, double w1, double inv_area,
                                     bool affine) {
  const float inv_w[3] = {v[0]->inv_w, v[1]->inv_w, v[2]->inv_w};
  return float_weights(w0 * inv_area, w1 * inv_area, inv_w, affine);
}

/// Texture coordinate slot `slot` (kTexCoord + 4 unit + 0..3) at weights `w` (texcoord.hpp).
inline float texcoord_at(const WindowVertex* const v[3], int slot, FloatWeights w) {
  return texcoord_plane((*v[0]->attr)[slot], (*v[1]->attr)[slot], (*v[2]->attr)[slot], w);
}

/// The four texture coordinates of a fragment from slot `first`, in the fast pipeline's float
/// arithmetic.
inline void fragment_texcoords(const WindowVertex* const v[3], FloatWeights w, int first, Fragment& frag) {
  for (int i = 0; i < 4; ++i) frag.attr[std::size_t(first + i)] = texcoord_at(v, first + i, w);
}

/// llvmpipe computes the level of detail once per 2x2 pixel quad of its own rows, which run
/// from the top of the window down (GL's row height - 1 is its row 0): from the quad's
/// top-left pixel to the pixel on its right and to the one below (lp_bld_sample.c's rho).
/// Every pixel of the quad gets those differences, covered or not. The projected
/// coordinates at those pixels are the fragments' own (texcoord.hpp), wherever they lie.
inline TextureDerivatives texture_derivatives(const WindowVertex* const v[3], const FixedPoint p[3], int x,
                                             int y, int height, int first) {
  const double inv_area = 1.0 / double(edge_function(p[0], p[1], p[2]));
  const bool affine = v[0]->inv_w == v[1]->inv_w && v[1]->inv_w == v[2]->inv_w;
  return quad_derivatives(x, y, height, [&](int px, int py) {
    const FixedPoint c{std::int64_t(px) * kSubpixelOne + kSubpixelOne / 2,
                       std::int64_t(py) * kSubpixelOne + kSubpixelOne / 2};
    const FloatWeights w = texcoord_weights(v, double(edge_function(p[1], p[2], c)),
                                            double(edge_function(p[2], p[0], c)), inv_area, affine);
    return project_texcoord(texcoord_at(v, first, w), texcoord_at(v, first + 1, w),
                            texcoord_at(v, first + 2, w), texcoord_at(v, first + 3, w));
  });
}

/// Window depth over a triangle: z2 + b0 (z0 - z2) + b1 (z1 - z2) in float arithmetic, in
/// this order and without fused operations, from the screen-space weights b0, b1 rounded to
/// float. The fast pipeline computes the same operations a block of pixels at a time (16 lanes
/// of floats with AVX-512, where doubles would take two vectors and three times the
/// operations), so depth is identical in both. Its error is a few float roundings of
/// |z0 - z2| and |z1 - z2|, of the order of the float depth buffer's own resolution.
struct DepthPlane {
  float base, d0, d1;
};

inline DepthPlane depth_plane(float z0, float z1, float z2) { return {z2, z0 - z2, z1 - z2}; }

inline float plane_depth(float b0, float b1, const DepthPlane& p) {
  const float t0 = b0 * p.d0, t1 = b1 * p.d1;
  return (p.base + t0) + t1;
}

/// A triangle made ready for its fragments: counter-clockwise vertices, snapped positions,
/// 1 / (twice its area), whether its vertices share 1/w, its depth plane.
struct OrientedTriangle {
  const WindowVertex* v[3];
  FixedPoint p[3];
  std::int64_t area;
  double inv_area;
  bool affine;
  DepthPlane dz;
};

/// False for a triangle of zero snapped area.
inline bool orient_triangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                            OrientedTriangle& t) {
  t.v[0] = &a, t.v[1] = &b, t.v[2] = &c;
  t.p[0] = snap(a.x, a.y), t.p[1] = snap(b.x, b.y), t.p[2] = snap(c.x, c.y);
  t.area = edge_function(t.p[0], t.p[1], t.p[2]);
  if (t.area == 0) return false;
  if (t.area < 0) {  // make it counter-clockwise; the weights follow the vertices
    std::swap(t.v[1], t.v[2]);
    std::swap(t.p[1], t.p[2]);
    t.area = -t.area;
  }
  t.inv_area = 1.0 / double(t.area);
  // Equal 1/w at the three vertices (an orthographic view, or a face-on triangle): the
  // perspective weights are the screen-space ones, taken as they are.
  t.affine = t.v[0]->inv_w == t.v[1]->inv_w && t.v[1]->inv_w == t.v[2]->inv_w;
  t.dz = depth_plane(t.v[0]->z, t.v[1]->z, t.v[2]->z);
  return true;
}

/// The fragment at pixel (x, y), whose edge functions of the triangle's edges v1->v2 and
/// v2->v0 are w0 and w1: depth and attributes from the triangle's planes.
inline void plane_fragment(const OrientedTriangle& t, int x, int y, std::int64_t w0, std::int64_t w1, int height,
                           unsigned texture_units, Fragment& frag) {
  const WindowVertex* const* v = t.v;
  // Screen-space barycentrics: depth is linear in window space (GL 1.5 section 3.5.1).
  double b0 = double(w0) * t.inv_area, b1 = double(w1) * t.inv_area;
  double b2 = 1.0 - b0 - b1;
  frag.x = x;
  frag.y = y;
  frag.z = plane_depth(float(b0), float(b1), t.dz);
  // Perspective-correct attributes: interpolate a/w and 1/w, then divide.
  double q0 = b0, q1 = b1, q2 = b2;
  if (!t.affine) {
    q0 = b0 * v[0]->inv_w, q1 = b1 * v[1]->inv_w, q2 = b2 * v[2]->inv_w;
    double inv = 1.0 / (q0 + q1 + q2);
    q0 *= inv;
    q1 *= inv;
    q2 *= inv;
  }
  for (int i = 0; i < kAttrCount; ++i) {
    frag.attr[i] = static_cast<float>(q0 * (*v[0]->attr)[i] + q1 * (*v[1]->attr)[i] + q2 * (*v[2]->attr)[i]);
  }
  if (texture_units) {
    const FloatWeights tw = texcoord_weights(v, double(w0), double(w1), t.inv_area, t.affine);
    for (int u = 0; u < kMaxTextureUnits; ++u) {
      if (!(texture_units >> u & 1u)) continue;
      fragment_texcoords(v, tw, kTexCoord + 4 * u, frag);
      frag.texture_derivatives[std::size_t(u)] = texture_derivatives(v, t.p, x, y, height, kTexCoord + 4 * u);
    }
  }
}

/// The pixels whose centres lie in the box of snapped points p[0..n-1], one pixel wider on
/// each side, within the framebuffer.
struct PixelRange {
  int x0, x1, y0, y1;
};

inline PixelRange pixel_range(const FixedPoint* p, int n, int width, int height) {
  std::int64_t min_x = p[0].x, max_x = p[0].x, min_y = p[0].y, max_y = p[0].y;
  for (int k = 1; k < n; ++k) {
    min_x = std::min(min_x, p[k].x), max_x = std::max(max_x, p[k].x);
    min_y = std::min(min_y, p[k].y), max_y = std::max(max_y, p[k].y);
  }
  return {static_cast<int>(std::max<std::int64_t>(0, (min_x >> kSubpixelBits) - 1)),
          static_cast<int>(std::min<std::int64_t>(width - 1, (max_x >> kSubpixelBits) + 1)),
          static_cast<int>(std::max<std::int64_t>(0, (min_y >> kSubpixelBits) - 1)),
          static_cast<int>(std::min<std::int64_t>(height - 1, (max_y >> kSubpixelBits) + 1))};
}

inline FixedPoint pixel_centre(int x, int y) {
  return {std::int64_t(x) * kSubpixelOne + kSubpixelOne / 2, std::int64_t(y) * kSubpixelOne + kSubpixelOne / 2};
}

template <class Emit>
std::uint64_t rasterize_triangle(const WindowVertex& a, const WindowVertex& b,
                                 const WindowVertex& c, int width, int height, unsigned texture_units,
                                 Emit&& emit) {
  OrientedTriangle t;
  if (!orient_triangle(a, b, c, t)) return 0;
  const FixedPoint* p = t.p;
  // Bias of -1 on edges the triangle does not own turns "> 0 or (== 0 and owned)" into ">= 0".
  std::int64_t bias[3] = {owns_edge(p[1], p[2]) ? 0 : -1, owns_edge(p[2], p[0]) ? 0 : -1,
                          owns_edge(p[0], p[1]) ? 0 : -1};
  const PixelRange r = pixel_range(p, 3, width, height);
  std::uint64_t covered = 0;
  Fragment frag;
  for (int y = r.y0; y <= r.y1; ++y) {
    for (int x = r.x0; x <= r.x1; ++x) {
      const FixedPoint centre = pixel_centre(x, y);
      std::int64_t w0 = edge_function(p[1], p[2], centre);
      std::int64_t w1 = edge_function(p[2], p[0], centre);
      std::int64_t w2 = edge_function(p[0], p[1], centre);
      if (w0 + bias[0] < 0 || w1 + bias[1] < 0 || w2 + bias[2] < 0) continue;
      plane_fragment(t, x, y, w0, w1, height, texture_units, frag);
      ++covered;
      emit(frag);
    }
  }
  return covered;
}

/// The counter-clockwise parallelogram a, b, c, d (d - c = a - b, as an aliased line's
/// quadrilateral) with one plane: it covers the pixels its four edges cover (what its
/// triangles (a, b, c) and (a, c, d) cover together, by the fill rule), and every fragment
/// takes triangle (a, b, c)'s depth and attributes, extended past its diagonal, as llvmpipe
/// gives a line one set of interpolation coefficients. Turned clockwise (inside out), its
/// edges' inner sides exclude each other: it covers nothing.
template <class Emit>
std::uint64_t rasterize_parallelogram(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                                      const WindowVertex& d, int width, int height, unsigned texture_units,
                                      Emit&& emit) {
  OrientedTriangle t;
  if (!orient_triangle(a, b, c, t) || t.v[1] != &b) return 0;
  const FixedPoint q[4] = {t.p[0], t.p[1], t.p[2], snap(d.x, d.y)};
  std::int64_t bias[4];
  for (int k = 0; k < 4; ++k) bias[k] = owns_edge(q[k], q[(k + 1) % 4]) ? 0 : -1;
  const PixelRange r = pixel_range(q, 4, width, height);
  std::uint64_t covered = 0;
  Fragment frag;
  for (int y = r.y0; y <= r.y1; ++y) {
    for (int x = r.x0; x <= r.x1; ++x) {
      const FixedPoint centre = pixel_centre(x, y);
      bool inside = true;
      for (int k = 0; k < 4; ++k) inside = inside && edge_function(q[k], q[(k + 1) % 4], centre) + bias[k] >= 0;
      if (!inside) continue;
      plane_fragment(t, x, y, edge_function(t.p[1], t.p[2], centre), edge_function(t.p[2], t.p[0], centre), height,
                     texture_units, frag);
      ++covered;
      emit(frag);
    }
  }
  return covered;
}

}  // namespace shadelab::detail
