// Line and point coverage by llvmpipe's rules (GL 1.1 sections 3.3 and 3.4, as Mesa 22's
// llvmpipe rasterizes them; read from its setup code and checked pixel by pixel against it).
// Every operation is a float operation in llvmpipe's order: the end-pixel decisions compare
// coordinates with pixel centres, and one rounding can move a line's last pixel.
//
// A line is x-major when |dx| >= |dy|. Its quadrilateral spans the major axis from one end to
// the other and `width` pixels across the minor axis. The GL specification's diamond-exit
// rule decides whether each end's pixel is drawn: the first pixel when the line leaves its
// diamond (|x - xc| + |y - yc| < 1/2), the last pixel when the line entered it and does not
// end inside it. Where the plain quadrilateral would decide otherwise, its end is moved along
// the line to the pixel's boundary, half a pixel from the centre.
#include "raster/prim_setup.hpp"

#include <cmath>
#include <utility>

namespace shadelab::detail {

namespace {

constexpr int kOne = int(kSubpixelOne);
constexpr int kHalfPixel = kOne / 2;

// Mesa 22's util_iround on x86-64: adds one half in float, then truncates (so ties round away
// from zero, and a value just below one half can round up).
int round_float(float v) { return v >= 0.0f ? int(v + 0.5f) : int(v - 0.5f); }

// llvmpipe's snapping to 1/256 pixel.
int snap(float v) { return round_float(float(kSubpixelOne) * v); }

bool non_negative(float v) { return v >= 0.0f; }

float fraction(float v) { return v - std::floor(v); }

// Offset from the centre of the pixel holding v, in [-1/2, 1/2).
float from_centre(float v) { return v - std::floor(v) - 0.5f; }

// The quadrilateral in llvmpipe's fixed point (pixel centres at multiples of 256, y down).
struct DownQuad {
  int x[4], y[4];
};

// Where each end of the line moves along it (in pixels), and the quadrilateral's corners.
struct Ends {
  DownPoint first, last;  // after the swap that orders the ends (see below)
  float first_dx = 0, first_dy = 0, last_dx = 0, last_dy = 0;
};

// Whether the first pixel of an x-major line is drawn (diamond exit).
bool x_major_draws_start(DownPoint v, float xd, float yd, float dx, float dy, float slope) {
  if (std::fabs(xd) + std::fabs(yd) < 0.5f) return true;
  if (non_negative(xd) == non_negative(-dx)) return false;
  if (non_negative(-yd) != non_negative(dy)) return true;
  const float cross = fraction(v.y) + xd * slope;
  return cross < 1.0f && cross > 0.0f;
}

bool x_major_draws_end(DownPoint v, float xd, float yd, float dx, float dy, float slope) {
  if (std::fabs(xd) + std::fabs(yd) < 0.5f) return false;
  if (non_negative(xd) != non_negative(-dx)) return false;
  if (non_negative(-yd) == non_negative(dy)) return true;
  const float cross = fraction(v.y) + xd * slope;
  return cross < 1.0f && cross > 0.0f;
}

bool y_major_draws_start(DownPoint v, float xd, float yd, float dx, float dy, float slope) {
  if (std::fabs(xd) + std::fabs(yd) < 0.5f) return true;
  if (non_negative(-yd) == non_negative(dy)) return false;
  if (non_negative(xd) != non_negative(-dx)) return true;
  const float cross = fraction(v.x) + yd * slope;
  return cross < 1.0f && cross > 0.0f;
}

bool y_major_draws_end(DownPoint v, float xd, float yd, float dx, float dy, float slope) {
  if (std::fabs(xd) + std::fabs(yd) < 0.5f) return false;
  if (non_negative(-yd) != non_negative(dy)) return false;
  if (non_negative(xd) == non_negative(-dx)) return true;
  const float cross = fraction(v.x) + yd * slope;
  return cross < 1.0f && cross >= 0.0f;
}

// An x-major line's ends: ordered right to left, each moved to its pixel's boundary when the
// plain quadrilateral would draw its pixel against the diamond-exit rule (the left edge
// includes pixel centres on it, the right edge does not).
Ends x_major_ends(DownPoint v1, DownPoint v2) {
  const float dx = v1.x - v2.x, dy = v1.y - v2.y, slope = dy / dx;
  const float x1d = from_centre(v1.x), y1d = from_centre(v1.y), x2d = from_centre(v2.x);
  float y2d = from_centre(v2.y);
  if (y2d == -0.5f && dy < 0.0f) y2d = 0.5f;
  const bool start = x_major_draws_start(v1, x1d, y1d, dx, dy, slope);
  const bool end = x_major_draws_end(v2, x2d, y2d, dx, dy, slope);
  // Whether the plain quadrilateral already draws each end's pixel.
  const bool draws_start = non_negative(-x1d) != non_negative(dx);
  const bool draws_end = non_negative(x2d) == non_negative(-dx) || x2d == 0.0f;
  Ends e;
  if (dx < 0.0f) {  // v1 on the left: the right end is v2
    e.first = v2, e.last = v1;
    if (draws_start != start) e.last_dx = -x1d - 0.5f, e.last_dy = e.last_dx * slope;
    if (draws_end != end) e.first_dx = -x2d - 0.5f, e.first_dy = e.first_dx * slope;
  } else {
    e.first = v1, e.last = v2;
    if (draws_start != start) e.first_dx = -x1d + 0.5f, e.first_dy = e.first_dx * slope;
    if (draws_end != end) e.last_dx = -x2d + 0.5f, e.last_dy = e.last_dx * slope;
  }
  return e;
}

// A y-major line's ends, ordered top to bottom; the bottom edge includes pixel centres on it
// (the fill rule of a window-system buffer, whose y points down), the top edge does not.
Ends y_major_ends(DownPoint v1, DownPoint v2) {
  const float dx = v1.x - v2.x, dy = v1.y - v2.y, slope = dx / dy;
  const float x1d = from_centre(v1.x), y1d = from_centre(v1.y), y2d = from_centre(v2.y);
  float x2d = from_centre(v2.x);
  if (x2d == -0.5f && dx < 0.0f) x2d = 0.5f;
  const bool start = y_major_draws_start(v1, x1d, y1d, dx, dy, slope);
  const bool end = y_major_draws_end(v2, x2d, y2d, dx, dy, slope);
  const bool draws_start = non_negative(y1d) == non_negative(dy);
  const bool draws_end = non_negative(-y2d) == non_negative(dy) || y2d == 0.0f;
  Ends e;
  if (dy > 0.0f) {  // v1 below v2: the top end is v2
    e.first = v2, e.last = v1;
    if (draws_start != start) e.last_dy = -y1d + 0.5f, e.last_dx = e.last_dy * slope;
    if (draws_end != end) e.first_dy = -y2d + 0.5f, e.first_dx = e.first_dy * slope;
  } else {
    e.first = v1, e.last = v2;
    if (draws_start != start) e.first_dy = -y1d - 0.5f, e.first_dx = e.first_dy * slope;
    if (draws_end != end) e.last_dy = -y2d - 0.5f, e.last_dx = e.last_dy * slope;
  }
  return e;
}

// The ends' snapped positions, relative to pixel centres.
int snap_centre(float v, float shift) { return snap(v + shift - 0.5f); }

DownQuad x_major_quad(const Ends& e, int half_width) {
  const int x_first = snap_centre(e.first.x, e.first_dx), x_last = snap_centre(e.last.x, e.last_dx);
  const int y_first = snap_centre(e.first.y, e.first_dy), y_last = snap_centre(e.last.y, e.last_dy);
  return {{x_first, x_last, x_last, x_first},
          {y_first - half_width, y_last - half_width, y_last + half_width, y_first + half_width}};
}

DownQuad y_major_quad(const Ends& e, int half_width) {
  const int x_first = snap_centre(e.first.x, e.first_dx), x_last = snap_centre(e.last.x, e.last_dx);
  const int y_first = snap_centre(e.first.y, e.first_dy), y_last = snap_centre(e.last.y, e.last_dy);
  return {{x_first - half_width, x_last - half_width, x_last + half_width, x_first + half_width},
          {y_first, y_last, y_last, y_first}};
}

// Fixed point relative to pixel centres, y down -> shadelab's snapped GL window coordinates.
FixedPoint to_gl(int x, int y, int fb_height) {
  return {std::int64_t(x) + kHalfPixel, std::int64_t(fb_height) * kSubpixelOne - kHalfPixel - y};
}

// Twice the signed area in GL coordinates (positive: counter-clockwise).
std::int64_t quad_area(const FixedPoint (&c)[4]) {
  std::int64_t a = 0;
  for (int i = 0; i < 4; ++i) {
    const FixedPoint &p = c[i], &q = c[(i + 1) % 4];
    a += p.x * q.y - q.x * p.y;
  }
  return a;
}

}  // namespace

bool line_quad(DownPoint a, DownPoint b, float width, int fb_height, RasterQuad& out) {
  const float dx = a.x - b.x, dy = a.y - b.y;
  const float length2 = dx * dx + dy * dy;
  if (!(length2 > 0.0f) || !std::isfinite(length2)) return false;
  const int half_width = round_float(std::fmax(1.0f, width)) * kOne / 2;
  const bool x_major = std::fabs(dx) >= std::fabs(dy);
  const DownQuad q = x_major ? x_major_quad(x_major_ends(a, b), half_width)
                             : y_major_quad(y_major_ends(a, b), half_width);
  // Attributes vary along the major axis only: t at the corner's major coordinate, which
  // corners 0 and 3 share, and 1 and 2.
  const double from = x_major ? a.x : a.y, to = x_major ? b.x : b.y;
  for (int k = 0; k < 2; ++k) {
    const double along = double(x_major ? q.x[k] : q.y[k]) / kSubpixelOne + 0.5;
    out.t[k] = out.t[3 - k] = float((along - from) / (to - from));
  }
  for (int k = 0; k < 4; ++k) out.corner[k] = to_gl(q.x[k], q.y[k], fb_height);
  // A quadrilateral turned inside out (ends moved past each other) covers nothing: llvmpipe
  // tests its four edges, whose inside sides then exclude each other.
  return quad_area(out.corner) > 0;
}

bool point_quad(DownPoint p, float size, int fb_height, RasterQuad& out) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  // GL 1.1 section 3.3: the size rounded to an integer (llvmpipe rounds 1/256 steps up from
  // just below one half) and at least 1.
  const int fixed_size = (snap(size) + kHalfPixel - 1) & ~(kOne - 1);
  const int n = std::max(kOne, fixed_size) / kOne;
  // llvmpipe's bottom-edge rule: a y exactly on a pixel boundary belongs to the pixel above.
  const int x = snap(p.x), y = snap(p.y) - 1;
  int x0, y0;
  if (n % 2 == 1) {
    x0 = (x >> kSubpixelBits) - (n - 1) / 2;
    y0 = (y >> kSubpixelBits) - (n - 1) / 2;
  } else {
    x0 = ((x + kHalfPixel) >> kSubpixelBits) - n / 2;
    y0 = ((y + kHalfPixel) >> kSubpixelBits) - n / 2;
  }
  // Pixels x0 .. x0 + n - 1 and rows y0 .. y0 + n - 1 (down): the square's edges lie on pixel
  // boundaries, away from every centre.
  const std::int64_t left = std::int64_t(x0) * kSubpixelOne, right = left + std::int64_t(n) * kSubpixelOne;
  const std::int64_t top = (std::int64_t(fb_height) - y0) * kSubpixelOne, bottom = top - std::int64_t(n) * kSubpixelOne;
  out.corner[0] = {left, bottom};
  out.corner[1] = {right, bottom};
  out.corner[2] = {right, top};
  out.corner[3] = {left, top};
  for (float& t : out.t) t = 0.0f;
  return true;
}

}  // namespace shadelab::detail
