// One binned triangle made ready for rasterizing a tile: its vertices in the reference
// rasterizer's counter-clockwise order, exact integer edge functions and fill-rule thresholds,
// its pixel box; and the per-fragment reference path (stencil, capture, textures, other
// lighting) that fragments take when a draw needs it. No SIMD here.
#pragma once

#include <cstdint>

#include "fast/draw_job.hpp"

namespace shadelab::fast {

struct TriSetup {
  const RasterVertex* v[3];  ///< counter-clockwise (the reference's order after its swap)
  const float* var[3];       ///< their varyings
  const float* flat;         ///< provoking vertex's varyings when flat shading, else null
  bool front;
  std::int64_t area;         ///< twice the snapped area, > 0
  double inv_area;           ///< 1 / area (the reference's barycentric scale)
  bool affine;               ///< equal 1/w at the three vertices: no perspective division
  std::int64_t dx[3], dy[3];  ///< edge e runs from v[e+1] to v[e+2] (mod 3)
  std::int64_t ox[3], oy[3];  ///< edge e's start, v[e+1]'s snapped position
  double threshold[3];        ///< coverage: edge value >= threshold (0 owned, 1 not)
  detail::DepthPlane depth;   ///< window depth from the screen-space weights (the reference's)
  float offset;               ///< polygon offset added to depth
  const detail::Coverage* coverage;  ///< a smooth line's or point's, else null
  bool polygon;  ///< a polygon's (the polygon stipple applies), not a line's or a point's
  /// An aliased line's parallelogram (ClippedTriangle::parallelogram): v are corners 0, 1, 2
  /// and the planes theirs. Edge 1 (the diagonal) bounds nothing (its threshold below every
  /// value); the opposite sides bound edges 0 and 2 from above: a pixel is covered where
  /// also edge e's value <= upper[e] (e = 0, 2).
  bool parallelogram;
  double upper[3];
  int x0, x1, y0, y1;         ///< pixel box within the framebuffer and the tile
  /// A point's box (PointBox): its pixels are the box's, its three vertices the point itself
  /// (zero edges, all covering, and zero slopes: each fragment takes the point's values).
  bool box;
  RasterVertex box_at;  ///< a box's depth and 1/w, where its v[k] point
  std::uint32_t provoking_index;  ///< main-vertex index of the provoking vertex
};

/// The pixels of the triangle's box in the tile.
inline int box_pixels(const TriSetup& t) { return (t.x1 - t.x0 + 1) * (t.y1 - t.y0 + 1); }

/// Prepares bin entry `entry` of setup chunk `chunk` for the tile with pixel origin (tx, ty):
/// a triangle, or a point's box (kBinBox). Returns false when it has no pixels in the tile
/// (or zero snapped area).
bool setup_triangle(const DrawJob& job, int chunk, std::uint32_t entry, int tx, int ty,
                    TriSetup& t);

/// Asks the cache for what setup_triangle will read of bin entry `entry`, without waiting:
/// its ClippedTriangle or Triangle (`vertices` false), or its three vertices and their
/// varyings (`vertices` true; the entry's ClippedTriangle or Triangle is read, so it should
/// have been asked for a few entries earlier). A tile's entries are spread over the chunk's
/// arrays (a tile's points and line pieces were made anywhere in the draw), and their misses
/// otherwise take most of a small primitive's time.
void prefetch_setup(const DrawJob& job, int chunk, std::uint32_t entry, bool vertices);

/// Edge e's value at the centre of pixel (x, y): exact, as the reference's edge_function.
inline std::int64_t edge_at(const TriSetup& t, int e, int x, int y) {
  std::int64_t cx = std::int64_t(x) * detail::kSubpixelOne + detail::kSubpixelOne / 2;
  std::int64_t cy = std::int64_t(y) * detail::kSubpixelOne + detail::kSubpixelOne / 2;
  return t.dx[e] * (cy - t.oy[e]) - t.dy[e] * (cx - t.ox[e]);
}

/// Loads the triangle's three full reference attribute sets into ws.attribs (flat shading's
/// provoking colours substituted), for scalar_fragment.
void expand_triangle(const DrawJob& job, const TriSetup& t, WorkerScratch& ws);

/// The reference's per-fragment work for the covered pixel (x, y) with edge values w0, w1
/// and window depth z (offset and clamped): depth/stencil test, shading with shade_fragment,
/// capture or blending and colour write. Needs expand_triangle first.
void scalar_fragment(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, int x, int y,
                     double w0, double w1, float z);

}  // namespace shadelab::fast
