// Primitive assembly for lines, points and polygons drawn in line or point mode, shared by the
// reference and the fast pipeline: clipping, facing, culling, the polygon modes and edge flags,
// polygon offset, line stipple, then each line or point turned into pieces for the triangle
// rasterizer (a quadrilateral, or the triangles of a smooth line or point) with their
// corners' attributes. The order of these stages is Mesa's draw module's (clip, cull,
// two-sided colours, offset, flat shading, unfilled, stipple). Draws no pixels: a sink takes
// the pieces, or, in a draw with FragmentState::observer (GL's selection and feedback), the
// observer takes the points, lines and triangles themselves where they would become pieces
// (the filled triangles of such a draw come here too).
#pragma once

#include <cstdint>
#include <vector>

#include "raster/prim_clip.hpp"

namespace shadelab::detail {

/// Coverage of a smooth line or point (GL 1.1 sections 3.3.2, 3.4.2) as Mesa's draw module
/// computes it, from two functions affine in window position (GL coordinates: u = u0 + ux x
/// + uy y at the pixel centre (x, y)). Lines: alpha times sat(a - |u|) sat(b - |v|). Points:
/// d = u^2 + v^2; fragments with d > 1 are discarded; alpha times (1 - d) / (1 - a) where
/// d <= a (Mesa 22's lowering; see docs/rasterization.md), else alpha unchanged (a < 0: a
/// multisampled point's whole disc).
struct Coverage {
  enum class Kind : std::uint8_t { kNone, kLine, kPoint };
  Kind kind = Kind::kNone;
  float u0 = 0, ux = 0, uy = 0, v0 = 0, vx = 0, vy = 0;
  float a = 0, b = 0;
};

/// An attenuated point's derived size at eye-space z (GL 1.4 section 3.3) as Mesa's
/// fixed-function vertex program computes it: d = |z|, a + d (b + d c), its reciprocal square
/// root times the size, then at least min_size (a NaN becomes min_size) and at most max_size.
float derived_point_size(const PointState& p, float eye_z);

/// The alpha factor at GL window position (x, y) (a pixel centre); negative: discarded.
float coverage_at(const Coverage& c, double x, double y);

/// Pixels x0..x1 by y0..y1 (inclusive).
struct PixelBox {
  int x0, y0, x1, y1;
};

/// An aliased point's pixels (GL window coordinates, y up; not cut to the framebuffer), and
/// the window depth and 1/w every fragment of it takes.
struct PointPixels {
  PixelBox box;
  float z, inv_w;
};

/// A corner of a piece: GL window position (y up), depth, 1/w and attributes.
struct PieceCorner {
  double x, y;
  float z, inv_w;
  Attribs attr;
};

/// What the rasterizer draws: one or two triangles over `corner` (tri[k] holds corner
/// indices; their winding does not matter), facing `front` (two-sided colours), from the
/// draw's main vertex `provoking` (flat shading's colours). `offset`: a filled polygon, which
/// takes glPolygonOffset's fill offset; lines and points have their offset in their depth.
/// `polygon`: a filled polygon's triangle (polygon stipple applies to it alone).
struct Piece {
  PieceCorner corner[4];
  std::uint8_t tri[2][3];
  int triangles = 0;
  bool front = true;
  bool offset = false;
  bool polygon = false;  ///< a filled polygon's triangle: the polygon stipple applies
  /// An aliased line's quadrilateral: corners 0..3 a parallelogram (corner 3 - corner 2 =
  /// corner 0 - corner 1) drawn with one plane, triangle (0, 1, 2)'s, over the pixels of both
  /// triangles (rasterize_parallelogram).
  bool parallelogram = false;
  std::uint32_t provoking = 0;
  Coverage coverage;
};

class PieceSink {
 public:
  virtual void piece(const Piece& p) = 0;

 protected:
  ~PieceSink() = default;
};

/// Assembles one draw's lines, points and unfilled polygons. Vertices come in as clip
/// coordinates with their attributes (make_vertex); attributes are the reference's slots.
class PrimAssembler {
 public:
  PrimAssembler(const FragmentState& fragment, const Viewport& viewport, const glm::mat4& projection,
                int fb_height, bool flat, std::uint32_t stipple_counter);

  /// A vertex at `clip` whose eye-space z is `eye_z`: window position and, for attenuated
  /// points, the derived size computed; attributes left to the caller.
  PrimVertex make_vertex(const glm::vec4& clip, float eye_z) const;
  std::uint32_t outcode(const PrimVertex& v) const { return planes_.outcode(v.clip); }

  /// A segment of GL_LINES or a strip (LineSegment flags); `provoking` is the draw's index of
  /// b, whose colours are the flat ones.
  void line(PrimVertex a, PrimVertex b, std::uint32_t flags, std::uint32_t provoking, PieceSink& sink);
  void point(const PrimVertex& p, std::uint32_t provoking, PieceSink& sink);
  /// Whether this draw's points are aliased squares whose fragments all take the point's own
  /// values (no sprite, smoothing or multisampling, no observer): point_pixels can say which
  /// pixels each covers.
  bool plain_points() const;
  /// The point at `clip` (eye-space z `eye_z`) of a draw with plain_points(), as point()
  /// would draw make_vertex's vertex there, without its attributes: false when it is clipped
  /// away or covers nothing, else the pixels of its square. Its fragments take the vertex's
  /// depth and attributes (flat shading's too: the point is its own provoking vertex): the
  /// values point()'s piece gives every pixel centre it covers.
  bool point_pixels(const glm::vec4& clip, float eye_z, PointPixels& out);
  /// A triangle of a draw with some face in GL_LINE or GL_POINT mode (every triangle of such a
  /// draw comes here, filled ones too): `flags` are its TriangleFlag bits.
  void triangle(const PrimVertex (&v)[3], std::uint8_t flags, std::uint32_t provoking, PieceSink& sink);

  /// Whether a draw with this state sends its triangles to triangle().
  static bool unfilled(const FragmentState& f) {
    return f.front_mode != PolygonMode::kFill || f.back_mode != PolygonMode::kFill;
  }
  std::uint32_t stipple_counter() const { return stipple_counter_; }

  /// Every attribute slot (bit i: slot i of Attribs).
  static constexpr std::uint64_t kEverySlot = (std::uint64_t(1) << kAttrCount) - 1;
  /// Interpolates only the slots set in `slots` at the corners of aliased lines; the others
  /// are left as they were (for a caller that reads no other slot of a piece). kEverySlot by
  /// default.
  void interpolate_only(std::uint64_t slots) { slots_ = slots; }

 private:
  void polygon(std::vector<PrimVertex>& poly, std::uint32_t provoking, PieceSink& sink);
  void fan_triangle(const PrimVertex* v[3], std::uint8_t flags, std::uint32_t provoking, PieceSink& sink);
  void segment(const PrimVertex& a, const PrimVertex& b, bool front, std::uint32_t provoking, PieceSink& sink);
  void stippled(const PrimVertex& a, const PrimVertex& b, bool front, std::uint32_t provoking, PieceSink& sink);
  void aliased_line(const PrimVertex& a, const PrimVertex& b, bool front, std::uint32_t provoking, PieceSink& sink);
  void smooth_line(const PrimVertex& a, const PrimVertex& b, bool front, std::uint32_t provoking, PieceSink& sink);
  void multisample_line(const PrimVertex& a, const PrimVertex& b, bool front, std::uint32_t provoking, PieceSink& sink);
  void line_rectangle(const PrimVertex& a, const PrimVertex& b, const float (&ox)[4], const float (&oy)[4], bool front,
                      std::uint32_t provoking);
  void point_piece(const PrimVertex& p, bool front, std::uint32_t provoking, PieceSink& sink);
  void flat_colors(Piece& p) const;
  float unfilled_offset(const PrimVertex (&w)[3], float det) const;

  const FragmentState& frag_;
  Viewport viewport_;
  DownTransform window_;  // viewport_'s, for fb_height_
  int fb_height_;
  bool flat_;
  ClipSpace planes_;
  std::uint32_t stipple_counter_;
  std::uint64_t slots_ = kEverySlot;
  Attribs flat_attr_{};  // flat shading: the current primitive's provoking colours
  Piece piece_;
  std::vector<PrimVertex> poly_, scratch_;
};

}  // namespace shadelab::detail
