// Which pixels a line or a point covers, by the rules Mesa's llvmpipe follows (its line and
// point setup): a line becomes a parallelogram, a point a square, whose corners are snapped to
// 1/256 pixel; the pixels are then those whose centres the quadrilateral covers by the
// triangle fill rule (docs/rasterization.md). Pure geometry in window space: no clipping, no
// attributes beyond the parameter that places each corner along the line, no drawing.
#pragma once

#include "pipeline/stages.hpp"

namespace shadelab::detail {

/// A window position as llvmpipe computes it: pixels from the framebuffer's top-left corner,
/// y pointing down (gallium's window space for a window-system buffer), pixel centres at
/// + 0.5, in float.
struct DownPoint {
  float x, y;
};

/// The area a primitive covers: the convex quadrilateral corner[0..3] (shadelab's snapped
/// window coordinates, GL y up), rasterized as the triangles (0, 1, 2) and (0, 2, 3) with the
/// fill rule: the diagonal's pixels go to exactly one of them, so the pair covers what the
/// quadrilateral's four edges cover. For lines, t[k] places corner k along the line: an
/// attribute there (depth, colours, a/w and 1/w for perspective) is a0 + t (a1 - a0), as
/// llvmpipe interpolates along the major axis only (a wide line's pixels across it share
/// their values).
struct RasterQuad {
  FixedPoint corner[4];
  float t[4];
};

/// An aliased line from `a` to `b` of `width` pixels (rounded to an integer, at least 1),
/// GL 1.1 section 3.4 as llvmpipe implements it: x-major or y-major, the diamond-exit rule
/// deciding the end pixels, the width across the minor axis. `fb_height` maps y back to GL
/// window space. False when nothing is drawn (zero length, or not finite).
bool line_quad(DownPoint a, DownPoint b, float width, int fb_height, RasterQuad& out);

/// An aliased point of `size` pixels (rounded to an integer, at least 1), GL 1.1 section 3.3:
/// the size x size square of pixels around the point's position (for an odd size, centred on
/// its pixel; for an even size, on the pixel corner nearest to it). t is 0 at every corner.
bool point_quad(DownPoint p, float size, int fb_height, RasterQuad& out);

}  // namespace shadelab::detail
