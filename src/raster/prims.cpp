// Lines, points and unfilled polygons assembled in Mesa's draw module's order (its clip, cull,
// twoside, offset, flatshade, unfilled, stipple and smooth-line/point stages), each line or
// point ending as pieces for the triangle rasterizer (prim_setup.cpp decides their pixels).
#include "raster/prims.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace shadelab::detail {

namespace {

// Mesa's limits: GL_LINE_WIDTH_RANGE and GL_POINT_SIZE_RANGE are [1, 255].
constexpr float kMaxWidth = 255.0f;

float clamp_size(float v) { return std::clamp(std::isnan(v) ? 1.0f : v, 1.0f, kMaxWidth); }

// A vertex a fraction t along a-b in window space: every value interpolated linearly, as
// Mesa's line stipple splits a line.
PrimVertex screen_lerp(const PrimVertex& a, const PrimVertex& b, float t) {
  PrimVertex v;
  v.clip = a.clip;
  v.win = {a.win.x + t * (b.win.x - a.win.x), a.win.y + t * (b.win.y - a.win.y)};
  v.z = a.z + t * (b.z - a.z);
  v.inv_w = a.inv_w + t * (b.inv_w - a.inv_w);
  for (int i = 0; i < kAttrCount; ++i) v.attr[i] = a.attr[i] + t * (b.attr[i] - a.attr[i]);
  v.edge = true;
  v.point_size = a.point_size;
  return v;
}

// The corner of a line's quadrilateral at parameter t: depth and 1/w linear along the line,
// the other attributes perspective-correct (a/w and 1/w linear, then divided), as llvmpipe
// sets up a line's planes. Only the attribute slots in `slots`.
void line_corner(PieceCorner& c, const PrimVertex& a, const PrimVertex& b, float t, std::uint64_t slots) {
  c.z = a.z + t * (b.z - a.z);
  c.inv_w = a.inv_w + t * (b.inv_w - a.inv_w);
  auto corner = [&](int i) {
    const float pa = a.attr[i] * a.inv_w, pb = b.attr[i] * b.inv_w;
    c.attr[i] = (pa + t * (pb - pa)) / c.inv_w;
  };
  if (slots == PrimAssembler::kEverySlot) {
    for (int i = 0; i < kAttrCount; ++i) corner(i);
  } else {
    for (; slots; slots &= slots - 1) corner(std::countr_zero(slots));
  }
}

void copy_vertex(PieceCorner& c, const PrimVertex& v, double x, double y) {
  c.x = x;
  c.y = y;
  c.z = v.z;
  c.inv_w = v.inv_w;
  c.attr = v.attr;
}

// The affine function of GL window position through values f0, f1, f2 at corners p0, p1, p2.
void affine(const PieceCorner& p0, const PieceCorner& p1, const PieceCorner& p2, float f0, float f1, float f2,
            float& c0, float& cx, float& cy) {
  const double ex = p1.x - p0.x, ey = p1.y - p0.y, fx = p2.x - p0.x, fy = p2.y - p0.y;
  const double det = ex * fy - ey * fx;
  if (det == 0.0) {
    c0 = f0, cx = cy = 0.0f;
    return;
  }
  const double gx = ((f1 - f0) * fy - (f2 - f0) * ey) / det, gy = ((f2 - f0) * ex - (f1 - f0) * fx) / det;
  cx = float(gx), cy = float(gy);
  c0 = float(f0 - gx * p0.x - gy * p0.y);
}

double gl_y(float down, int fb_height) { return double(fb_height) - double(down); }

// A line's or point's piece before its corners: two triangles fanned from corner 0 (0 1 2,
// 0 2 3), not a polygon's (no offset, no stipple), no coverage yet.
void start_piece(Piece& p, bool front, std::uint32_t provoking) {
  p.tri[0][0] = 0, p.tri[0][1] = 1, p.tri[0][2] = 2;
  p.tri[1][0] = 0, p.tri[1][1] = 2, p.tri[1][2] = 3;
  p.triangles = 2;
  p.front = front;
  p.offset = false;
  p.polygon = false;
  p.parallelogram = false;
  p.provoking = provoking;
  p.coverage = Coverage{};
}

// Mesa's SATURATE: NaN passes through.
float saturate(float v) { return v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v); }

// What a PrimitiveObserver is told of a vertex: GL window coordinates (y up, in float as
// Mesa's feedback stage computes height - y), the clip w back from 1/w, and the colour of the
// face shown.
ObservedVertex observed(const PrimVertex& v, bool front, int fb_height) {
  ObservedVertex o;
  o.window = {v.win.x, float(fb_height) - v.win.y, v.z, 1.0f / v.inv_w};
  const int color = front ? kFrontColor : kBackColor;
  o.color = {v.attr[color], v.attr[color + 1], v.attr[color + 2], v.attr[color + 3]};
  o.texcoord = {v.attr[kTexCoord], v.attr[kTexCoord + 1], v.attr[kTexCoord + 2], v.attr[kTexCoord + 3]};
  return o;
}

}  // namespace

float coverage_at(const Coverage& c, double x, double y) {
  const float u = float(c.u0 + c.ux * x + c.uy * y), v = float(c.v0 + c.vx * x + c.vy * y);
  if (c.kind == Coverage::Kind::kLine) {
    auto sat = [](float s) { return std::clamp(s, 0.0f, 1.0f); };
    return sat(c.a - std::fabs(u)) * sat(c.b - std::fabs(v));
  }
  if (c.kind == Coverage::Kind::kPoint) {
    const float d = u * u + v * v;
    if (1.0f < d) return -1.0f;
    return c.a >= d ? (1.0f / (1.0f - c.a)) * (1.0f - d) : 1.0f;
  }
  return 1.0f;
}

PrimAssembler::PrimAssembler(const FragmentState& fragment, const Viewport& viewport, const glm::mat4& projection,
                             int fb_height, bool flat, std::uint32_t stipple_counter)
    : frag_(fragment), viewport_(viewport), window_(viewport, fb_height), fb_height_(fb_height), flat_(flat),
      planes_(fragment.clip, projection), stipple_counter_(stipple_counter) {}

float derived_point_size(const PointState& p, float eye_z) {
  const float d = std::fabs(eye_z);
  const float f = d * (d * p.attenuation.z + p.attenuation.y) + p.attenuation.x;
  const float size = (1.0f / std::sqrt(f)) * p.size;
  return std::fmin(std::fmax(size, p.min_size), p.max_size);
}

PrimVertex PrimAssembler::make_vertex(const glm::vec4& clip, float eye_z) const {
  PrimVertex v;
  v.clip = clip;
  v.edge = true;
  v.point_size = frag_.point.attenuated() ? derived_point_size(frag_.point, eye_z) : frag_.point.size;
  const DownVertex d = to_down_window(clip, window_);
  v.win = d.win;
  v.z = d.z;
  v.inv_w = d.inv_w;
  return v;
}

void PrimAssembler::flat_colors(Piece& p) const {
  if (!flat_) return;
  for (PieceCorner& c : p.corner) {
    std::copy(flat_attr_.begin() + kFrontColor, flat_attr_.begin() + kEyePosition, c.attr.begin() + kFrontColor);
  }
}

void PrimAssembler::line(PrimVertex a, PrimVertex b, std::uint32_t flags, std::uint32_t provoking,
                         PieceSink& sink) {
  if (flat_) flat_attr_ = b.attr;
  const std::uint32_t oa = outcode(a), ob = outcode(b);
  if ((oa | ob) && !clip_segment(planes_, oa, ob, a, b, viewport_, fb_height_)) return;
  // The stipple restarts with the segment (Mesa: in its stipple stage, after clipping).
  if (flags & LineSegment::kRestartStipple) stipple_counter_ = 0;
  segment(a, b, true, provoking, sink);
}

void PrimAssembler::point(const PrimVertex& p, std::uint32_t provoking, PieceSink& sink) {
  if (outcode(p) != 0) return;  // a point outside the view volume or a clip plane is gone
  if (flat_) flat_attr_ = p.attr;
  point_piece(p, true, provoking, sink);
}

bool PrimAssembler::plain_points() const {
  const PointState& ps = frag_.point;
  return !frag_.observer && !ps.sprite && !ps.smooth && !ps.multisample;
}

bool PrimAssembler::point_pixels(const glm::vec4& clip, float eye_z, PointPixels& out) {
  if (planes_.outcode(clip) != 0) return false;  // as point()
  if (frag_.line.stipple) stipple_counter_ = 0;   // as point_piece
  const DownVertex d = to_down_window(clip, window_);
  const PointState& ps = frag_.point;
  RasterQuad q;
  if (!point_quad(d.win, clamp_size(ps.attenuated() ? derived_point_size(ps, eye_z) : ps.size), fb_height_, q)) {
    return false;
  }
  // The square's sides lie on pixel boundaries: the pixels from its left and bottom sides up
  // to those before its right and top ones.
  out.box = {int(q.corner[0].x / kSubpixelOne), int(q.corner[0].y / kSubpixelOne),
             int(q.corner[2].x / kSubpixelOne) - 1, int(q.corner[2].y / kSubpixelOne) - 1};
  out.z = d.z;
  out.inv_w = d.inv_w;
  return true;
}

void PrimAssembler::segment(const PrimVertex& a, const PrimVertex& b, bool front, std::uint32_t provoking,
                            PieceSink& sink) {
  if (PrimitiveObserver* o = frag_.observer) return o->line(observed(a, front, fb_height_), observed(b, front, fb_height_));
  if (frag_.line.stipple) return stippled(a, b, front, provoking, sink);
  if (frag_.line.multisample) return multisample_line(a, b, front, provoking, sink);
  if (frag_.line.smooth) return smooth_line(a, b, front, provoking, sink);
  aliased_line(a, b, front, provoking, sink);
}

// GL 1.1 section 3.4.2: pixel i along the line is drawn when bit (counter / factor) mod 16 of
// the pattern is set; Mesa cuts the line into its drawn runs (of the major axis' length, or
// the Euclidean one for smooth lines), each drawn as a line of its own.
void PrimAssembler::stippled(const PrimVertex& a, const PrimVertex& b, bool front, std::uint32_t provoking,
                             PieceSink& sink) {
  const float dx = b.win.x - a.win.x, dy = b.win.y - a.win.y;
  const float length = frag_.line.smooth || frag_.line.multisample ? std::sqrt(dx * dx + dy * dy)
                                                                   : std::max(std::fabs(dx), std::fabs(dy));
  const int pixels = std::isfinite(length) ? int(std::ceil(length)) : 0;
  const unsigned factor = std::max<unsigned>(1u, frag_.line.factor);
  auto on = [&](int i) { return (frag_.line.pattern >> (((stipple_counter_ + unsigned(i)) / factor) & 15u)) & 1u; };
  auto run = [&](float t0, float t1) {
    const PrimVertex v0 = t0 > 0.0f ? screen_lerp(a, b, t0) : a, v1 = t1 < 1.0f ? screen_lerp(a, b, t1) : b;
    if (frag_.line.multisample) multisample_line(v0, v1, front, provoking, sink);
    else if (frag_.line.smooth) smooth_line(v0, v1, front, provoking, sink);
    else aliased_line(v0, v1, front, provoking, sink);
  };
  bool state = false;
  float start = 0.0f;
  for (int i = 0; i < pixels; ++i) {
    const bool drawn = on(i) != 0;
    if (drawn == state) continue;
    if (state) run(start / length, float(i) / length);
    else start = float(i);
    state = drawn;
  }
  if (state && start < length) run(start / length, 1.0f);
  stipple_counter_ += unsigned(pixels);
}

void PrimAssembler::aliased_line(const PrimVertex& a, const PrimVertex& b, bool front, std::uint32_t provoking,
                                 PieceSink& sink) {
  RasterQuad q;
  if (!line_quad(a.win, b.win, clamp_size(frag_.line.width), fb_height_, q)) return;
  Piece& p = piece_;
  start_piece(p, front, provoking);
  for (int k = 0; k < 4; ++k) {
    PieceCorner& c = p.corner[k];
    c.x = double(q.corner[k].x) / double(kSubpixelOne);
    c.y = double(q.corner[k].y) / double(kSubpixelOne);
    // The corners across the line from each other lie at the same t: interpolated once.
    const int same = k > 0 && q.t[k] == q.t[k - 1] ? k - 1 : k == 3 && q.t[3] == q.t[0] ? 0 : -1;
    if (same < 0) {
      line_corner(c, a, b, q.t[k], slots_);
    } else {
      c.z = p.corner[same].z, c.inv_w = p.corner[same].inv_w, c.attr = p.corner[same].attr;
    }
  }
  p.parallelogram = true;
  flat_colors(p);
  sink.piece(p);
}

// The piece of a line drawn as a rectangle: corners 0 and 1 at a, 2 and 3 at b, each moved by
// (ox, oy) in window coordinates (y down), two triangles, no coverage yet.
void PrimAssembler::line_rectangle(const PrimVertex& a, const PrimVertex& b, const float (&ox)[4],
                                   const float (&oy)[4], bool front, std::uint32_t provoking) {
  Piece& p = piece_;
  for (int k = 0; k < 4; ++k) {
    const PrimVertex& v = k < 2 ? a : b;
    copy_vertex(p.corner[k], v, double(v.win.x + ox[k]), gl_y(v.win.y + oy[k], fb_height_));
  }
  start_piece(p, front, provoking);
  p.tri[0][0] = 2, p.tri[0][1] = 1, p.tri[0][2] = 0;
  p.tri[1][0] = 3, p.tri[1][1] = 1, p.tri[1][2] = 2;
}

// GL 1.5 section 3.4.4's multisampled line: the rectangle of the line's width centred on the
// segment, from endpoint to endpoint, filled as two triangles (no coverage: it covers the
// pixel centres, each a sample of the pass, inside it).
void PrimAssembler::multisample_line(const PrimVertex& a, const PrimVertex& b, bool front, std::uint32_t provoking,
                                     PieceSink& sink) {
  const float dx = b.win.x - a.win.x, dy = b.win.y - a.win.y;
  const float length = std::sqrt(dx * dx + dy * dy);
  if (!(length > 0.0f) || !std::isfinite(length)) return;  // no area
  const float half_width = 0.5f * clamp_size(frag_.line.width);
  const float nx = -dy / length * half_width, ny = dx / length * half_width;
  const float ox[4] = {nx, -nx, nx, -nx}, oy[4] = {ny, -ny, ny, -ny};
  line_rectangle(a, b, ox, oy, front, provoking);
  flat_colors(piece_);
  sink.piece(piece_);
}

// Mesa's smooth line: a rectangle half a pixel longer than the line at each end and wider
// than it (half width 1 up to width 1, else width / 2 + 1/2), its coverage from the distance
// to the line across and along (window coordinates y down, as Mesa computes them).
void PrimAssembler::smooth_line(const PrimVertex& a, const PrimVertex& b, bool front, std::uint32_t provoking,
                                PieceSink& sink) {
  const float width = clamp_size(frag_.line.width);
  const float half_width = width <= 1.0f ? 1.0f : 0.5f * width + 0.5f;
  const float dx = b.win.x - a.win.x, dy = b.win.y - a.win.y;
  const float angle = std::atan2(dy, dx), c = std::cos(angle), s = std::sin(angle);
  float half_length = 0.5f * std::sqrt(dx * dx + dy * dy);
  half_length = half_length < 0.5f ? 2.0f * half_length : half_length + 0.5f;
  const float tl = 0.5f, tw = half_width;
  const float ox[4] = {-tl * c - tw * s, -tl * c - -tw * s, tl * c - tw * s, tl * c - -tw * s};
  const float oy[4] = {-tl * s + tw * c, -tl * s + -tw * c, tl * s + tw * c, tl * s + -tw * c};
  line_rectangle(a, b, ox, oy, front, provoking);
  Piece& p = piece_;
  Coverage& cov = p.coverage;
  cov.kind = Coverage::Kind::kLine;
  cov.a = half_width;
  cov.b = half_length;
  affine(p.corner[0], p.corner[1], p.corner[2], -half_width, half_width, -half_width, cov.u0, cov.ux, cov.uy);
  affine(p.corner[0], p.corner[1], p.corner[2], -half_length, -half_length, half_length, cov.v0, cov.vx, cov.vy);
  flat_colors(p);
  sink.piece(p);
}

void PrimAssembler::point_piece(const PrimVertex& v, bool front, std::uint32_t provoking, PieceSink& sink) {
  if (PrimitiveObserver* o = frag_.observer) return o->point(observed(v, front, fb_height_));
  if (frag_.line.stipple) stipple_counter_ = 0;  // Mesa's stipple stage restarts at a point
  const PointState& ps = frag_.point;
  float size = clamp_size(v.point_size);  // glPointSize's, or the derived size
  float fade = 1.0f;
  if (ps.multisample) {  // unrounded, below 1 too; faded below the threshold
    size = std::isnan(v.point_size) ? 1.0f : std::min(v.point_size, kMaxWidth);
    if (size < ps.fade_threshold) {
      const float q = std::max(size, 0.0f) / ps.fade_threshold;
      fade = q * q;
      size = ps.fade_threshold;
    }
    if (!(size > 0.0f)) return;
  }
  Piece& p = piece_;
  start_piece(p, front, provoking);
  if (ps.sprite || ps.smooth || ps.multisample) {
    // A square around the point: a sprite's side is its size; Mesa's smooth point has radius 1
    // up to size 2, else size / 2, and discards the fragments beyond the radius; a
    // multisampled point is the disc of radius size / 2, whole.
    const bool sprite = ps.sprite;
    const float r = sprite || ps.multisample || size > 2.0f ? 0.5f * size : 1.0f;
    const float sx[4] = {-r, r, r, -r}, sy[4] = {-r, -r, r, r};
    for (int k = 0; k < 4; ++k) {
      copy_vertex(p.corner[k], v, double(v.win.x + sx[k]), gl_y(v.win.y + sy[k], fb_height_));
      // The sprite's replaced texture coordinates (window y grows downward here: t is 0 at the top).
      for (std::size_t u = 0; sprite && u < kMaxTextureUnits; ++u) {
        if (!(frag_.point.coord_replace >> u & 1u)) continue;
        float* tc = &p.corner[k].attr[std::size_t(kTexCoord) + 4 * u];
        tc[0] = sx[k] < 0.0f ? 0.0f : 1.0f, tc[1] = sy[k] < 0.0f ? 0.0f : 1.0f, tc[2] = 0.0f, tc[3] = 1.0f;
      }
    }
    if (!sprite) {
      float k = 1.0f / r;
      k = 1.0f - 2.0f * k + k * k;
      p.coverage.kind = Coverage::Kind::kPoint;
      p.coverage.a = ps.multisample ? -1.0f : k;  // -1: no rim, the disc is whole
      affine(p.corner[0], p.corner[1], p.corner[2], -1.0f, 1.0f, 1.0f, p.coverage.u0, p.coverage.ux, p.coverage.uy);
      affine(p.corner[0], p.corner[1], p.corner[2], -1.0f, -1.0f, 1.0f, p.coverage.v0, p.coverage.vx, p.coverage.vy);
    }
  } else {
    RasterQuad q;
    if (!point_quad(v.win, size, fb_height_, q)) return;
    for (int k = 0; k < 4; ++k) {
      copy_vertex(p.corner[k], v, double(q.corner[k].x) / double(kSubpixelOne),
                  double(q.corner[k].y) / double(kSubpixelOne));
    }
    if (q.corner[1].x - q.corner[0].x == kSubpixelOne) {
      // A one-pixel square (the usual point): one triangle, its legs 1.5 pixels along the
      // square's bottom and left edges, holds the pixel's centre (0.5 from both legs and the
      // hypotenuse) and no other pixel's: half the set-up and binning of two triangles.
      p.corner[1].x = p.corner[0].x + 1.5;
      p.corner[2].x = p.corner[0].x, p.corner[2].y = p.corner[0].y + 1.5;
      p.triangles = 1;
    }
  }
  flat_colors(p);
  for (int k = 0; fade < 1.0f && k < 4; ++k) {  // the faded point's alpha
    p.corner[k].attr[std::size_t(kFrontColor) + 3] *= fade;
    p.corner[k].attr[std::size_t(kBackColor) + 3] *= fade;
  }
  sink.piece(p);
}

// GL 1.1 section 3.5.4 in Mesa's order: the triangle clipped (its edge flags following the
// edges, edges along a user clip plane drawn), each triangle of the clipped polygon's fan then
// facing, culled, coloured by its facing, offset, and drawn in its face's mode.
void PrimAssembler::triangle(const PrimVertex (&v)[3], std::uint8_t flags, std::uint32_t provoking,
                             PieceSink& sink) {
  if (flat_) flat_attr_ = v[2].attr;
  const std::uint32_t o0 = outcode(v[0]), o1 = outcode(v[1]), o2 = outcode(v[2]);
  if (!(o0 | o1 | o2)) {
    const PrimVertex* tri[3] = {&v[0], &v[1], &v[2]};
    return fan_triangle(tri, flags, provoking, sink);
  }
  if (o0 & o1 & o2) return;  // wholly outside one plane
  poly_.assign({v[0], v[1], v[2]});
  poly_[0].edge = flags & kTriangleEdge01;
  poly_[1].edge = flags & kTriangleEdge12;
  poly_[2].edge = flags & kTriangleEdge20;
  clip_edged_polygon(planes_, o0 | o1 | o2, poly_, scratch_, viewport_, fb_height_);
  polygon(poly_, provoking, sink);
}

// The clipped polygon's fan (p[i - 1], p[i], p[0]), its outer edges flagged, the stipple
// restarting with its first triangle (Mesa's clipper emits it so).
void PrimAssembler::polygon(std::vector<PrimVertex>& p, std::uint32_t provoking, PieceSink& sink) {
  const std::size_t n = p.size();
  for (std::size_t i = 2; i < n; ++i) {
    std::uint8_t f = p[i - 1].edge ? kTriangleEdge01 : 0;
    if (i == 2) f |= kTriangleRestartStipple | (p[0].edge ? kTriangleEdge20 : 0);
    if (i == n - 1 && p[n - 1].edge) f |= kTriangleEdge12;
    const PrimVertex* tri[3] = {&p[i - 1], &p[i], &p[0]};
    fan_triangle(tri, f, provoking, sink);
  }
}

// glPolygonOffset for a polygon drawn as lines or points, as Mesa's draw module computes it
// per triangle in float: the depth slopes from the window coordinates (dz/dx and dz/dy of the
// plane, through 1/det: infinite or NaN for a zero-area triangle), the units in steps of two
// 24-bit depth resolutions.
float PrimAssembler::unfilled_offset(const PrimVertex (&w)[3], float det) const {
  const float inv_det = 1.0f / det;
  const float ex = w[0].win.x - w[2].win.x, ey = w[0].win.y - w[2].win.y, ez = w[0].z - w[2].z;
  const float fx = w[1].win.x - w[2].win.x, fy = w[1].win.y - w[2].win.y, fz = w[1].z - w[2].z;
  const float a = ey * fz - ez * fy, b = ez * fx - ex * fz;
  const float dzdx = std::fabs(a * inv_det), dzdy = std::fabs(b * inv_det);
  const float slope = dzdx > dzdy ? dzdx : dzdy;
  const float units = float(double(frag_.offset_units) * (1.0 / double((1 << 24) - 1)) * 2.0);
  return units + slope * frag_.offset_factor;
}

void PrimAssembler::fan_triangle(const PrimVertex* v[3], std::uint8_t flags, std::uint32_t provoking,
                                 PieceSink& sink) {
  // Mesa's determinant, in window coordinates with y down: negative is counter-clockwise on
  // the screen. A zero-area triangle is back facing for culling, takes its mode by the
  // clockwise rule and keeps its front colours.
  const float ex = v[0]->win.x - v[2]->win.x, ey = v[0]->win.y - v[2]->win.y;
  const float fx = v[1]->win.x - v[2]->win.x, fy = v[1]->win.y - v[2]->win.y;
  const float det = ex * fy - ey * fx;
  const bool ccw = det < 0.0f, front_ccw = frag_.front_ccw;
  const bool front_face = det != 0.0f && ccw == front_ccw;
  if ((frag_.cull == CullMode::kBack && !front_face) || (frag_.cull == CullMode::kFront && front_face)) return;
  const bool front_colors = !(det * (front_ccw ? -1.0f : 1.0f) < 0.0f);
  const bool cw = det >= 0.0f;
  const PolygonMode mode = cw == front_ccw ? frag_.back_mode : frag_.front_mode;
  const bool offset = mode == PolygonMode::kFill ? frag_.polygon_offset
                      : mode == PolygonMode::kLine ? frag_.offset_line : frag_.offset_point;
  PrimVertex w[3] = {*v[0], *v[1], *v[2]};
  if (offset && mode != PolygonMode::kFill) {
    // A zero-area triangle's offset is NaN, and so its depth: fragments take depth 0 (the
    // fragment path clamps NaN to 0, as llvmpipe does).
    const float dz = unfilled_offset(w, det);
    for (PrimVertex& u : w) u.z = saturate(u.z + dz);
  }
  if (mode == PolygonMode::kFill && frag_.observer) {
    return frag_.observer->triangle(observed(w[0], front_colors, fb_height_), observed(w[1], front_colors, fb_height_),
                                    observed(w[2], front_colors, fb_height_));
  }
  if (mode == PolygonMode::kFill) {
    if (frag_.line.stipple) stipple_counter_ = 0;  // Mesa's stipple stage restarts at a triangle
    Piece& p = piece_;
    for (int k = 0; k < 3; ++k) copy_vertex(p.corner[k], w[k], w[k].win.x, gl_y(w[k].win.y, fb_height_));
    p.tri[0][0] = 0, p.tri[0][1] = 1, p.tri[0][2] = 2;
    p.triangles = 1;
    p.front = front_colors;
    p.offset = frag_.polygon_offset;
    p.polygon = true;
    p.parallelogram = false;
    p.provoking = provoking;
    p.coverage = Coverage{};
    flat_colors(p);
    return sink.piece(p);
  }
  if (mode == PolygonMode::kLine) {
    if (flags & kTriangleRestartStipple) {
      stipple_counter_ = 0;
      if (frag_.observer) frag_.observer->restart_stipple();
    }
    if (flags & kTriangleEdge20) segment(w[2], w[0], front_colors, provoking, sink);
    if (flags & kTriangleEdge01) segment(w[0], w[1], front_colors, provoking, sink);
    if (flags & kTriangleEdge12) segment(w[1], w[2], front_colors, provoking, sink);
    return;
  }
  if (flags & kTriangleEdge01) point_piece(w[0], front_colors, provoking, sink);
  if (flags & kTriangleEdge12) point_piece(w[1], front_colors, provoking, sink);
  if (flags & kTriangleEdge20) point_piece(w[2], front_colors, provoking, sink);
}

}  // namespace shadelab::detail
