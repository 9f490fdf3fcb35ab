// Per-fragment state of one draw (part of pipeline.hpp): culling, facing, polygon modes,
// lines, points and user clip planes, then GL's per-fragment operations (scissor, alpha,
// stencil and depth tests, blending or logic op, colour mask), and what may take a draw's
// output instead of the framebuffer (fragment capture, GL's feedback and selection). Plain
// data: the pipeline (src/pipeline, src/fast) applies it; nothing here draws.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shadelab/scene.hpp"

namespace shadelab {

enum class CompareFunc { kNever, kLess, kEqual, kLequal, kGreater, kNotequal, kGequal, kAlways };
/// glStencilOp's operations: GL 1.1's (kIncr and kDecr clamp to [0, 255]), then GL 1.4's
/// kIncrWrap and kDecrWrap, which wrap around modulo 256.
enum class StencilOp { kKeep, kZero, kReplace, kIncr, kDecr, kInvert, kIncrWrap, kDecrWrap };

/// glStencilFunc / glStencilOp / glStencilMask.
struct StencilState {
  bool enabled = false;
  CompareFunc func = CompareFunc::kAlways;
  std::uint8_t ref = 0, value_mask = 0xff, write_mask = 0xff;
  StencilOp fail = StencilOp::kKeep, depth_fail = StencilOp::kKeep, pass = StencilOp::kKeep;
};

/// Order-independent transparency: instead of blending, fragments that pass the depth test are
/// kept per pixel and composited later in true depth order (resolve_fragments, pipeline.hpp).
struct FragmentCapture {
  struct Entry {
    float depth;
    glm::vec4 color;  ///< unclamped shaded colour with alpha
    BlendState blend;
  };
  std::vector<std::vector<Entry>> pixels;  ///< one list per pixel, sized by the caller
  std::size_t count = 0;
  std::size_t limit = 64u << 20;  ///< entries kept at most (memory bound)
  std::size_t dropped = 0;        ///< entries arriving once `limit` were kept (not kept)
};

/// A vertex of a primitive that a draw hands to a PrimitiveObserver instead of rasterizing it.
struct ObservedVertex {
  glm::vec4 window;    ///< GL window x, y (y up), depth z in [0, 1], and the clip-space w
  glm::vec4 color;     ///< its colour, of the face the primitive shows (two-sided lighting)
  glm::vec4 texcoord;  ///< texture unit 0's (s, t, r, q), not divided by q (GL 1.3 section 5.3)
};

/// GL's feedback and selection modes (GL 1.1 sections 5.2, 5.3): what a draw would rasterize,
/// handed over primitive by primitive, in the order and form Mesa's draw module gives its last
/// stage: after clipping (a clipped polygon as a fan of triangles), culling, the polygon modes
/// and edge flags, before any rasterization rule (wide and stippled lines, large points and flat
/// shading change nothing here). Set FragmentState::observer and nothing is drawn.
class PrimitiveObserver {
 public:
  virtual void point(const ObservedVertex& v) = 0;
  virtual void line(const ObservedVertex& a, const ObservedVertex& b) = 0;
  virtual void triangle(const ObservedVertex& a, const ObservedVertex& b, const ObservedVertex& c) = 0;
  /// Where a triangle of a polygon drawn as lines starts the line stipple again (its
  /// TriangleFlag kTriangleRestartStipple): GL's feedback marks the next line it reports
  /// (GL_LINE_RESET_TOKEN). Lines of line primitives never call it, as in Mesa.
  virtual void restart_stipple() = 0;

 protected:
  ~PrimitiveObserver() = default;
};

/// glScissor (GL 1.1 section 4.1.2): with `enabled`, fragments outside the window-space box
/// [x, x + width) x [y, y + height) are discarded, and draw_triangles visits no tile outside it.
struct ScissorState {
  bool enabled = false;
  int x = 0, y = 0;
  int width = 0, height = 0;  ///< >= 0
};

/// glAlphaFunc (GL 1.1 section 4.1.3): with `enabled`, a fragment is kept when
/// `func(alpha, ref)` holds. Both are compared in the colour buffer's precision, as llvmpipe
/// does: clamped to [0, 1] and rounded to 8 bits first.
struct AlphaTestState {
  bool enabled = false;
  CompareFunc func = CompareFunc::kAlways;
  float ref = 0.0f;  ///< clamped to [0, 1]
  /// When at least 0, the alpha must also exceed it (compared the same way): a multisample
  /// pass's GL_SAMPLE_ALPHA_TO_COVERAGE, whose sample is covered above that alpha.
  float floor = -1.0f;
};

/// glLogicOp's sixteen operations (GL 1.1 section 4.1.7, table 4.2), in the order of their GL
/// enums (GL_CLEAR = 0x1500 ... GL_SET = 0x150F): s is the fragment's colour, d the pixel's,
/// both as 8-bit values.
enum class LogicOp : std::uint8_t {
  kClear, kAnd, kAndReverse, kCopy, kAndInverted, kNoop, kXor, kOr,
  kNor, kEquiv, kInvert, kOrReverse, kCopyInverted, kOrInverted, kNand, kSet,
};

/// GL_COLOR_LOGIC_OP: with `enabled`, the colour written is `op(s, d)` bit by bit on the 8-bit
/// values instead of the blended colour (blending is not done), then the colour mask applies.
struct LogicOpState {
  bool enabled = false;
  LogicOp op = LogicOp::kCopy;
};

/// glPolygonStipple (GL 1.1 section 3.5.2): with `enabled`, a triangle's fragment at window
/// pixel (x, y) is produced only when bit (x mod 32) of rows[y mod 32] is set (bit 0 is the
/// leftmost pixel of the 32; row 0 the bottom row). Applies to polygons only.
struct PolygonStipple {
  bool enabled = false;
  std::array<std::uint32_t, 32> rows{};
};

/// glPolygonMode for one face (GL 1.1 section 3.5.4): filled, or its edges drawn as lines,
/// or its vertices as points.
enum class PolygonMode : std::uint8_t { kFill, kLine, kPoint };

/// How lines are drawn (GL 1.1 section 3.4).
struct LineState {
  float width = 1.0f;  ///< glLineWidth, pixels; aliased lines round it (at least 1)
  bool smooth = false;   ///< GL_LINE_SMOOTH: coverage multiplies the fragment's alpha
  bool stipple = false;  ///< GL_LINE_STIPPLE
  std::uint16_t pattern = 0xffff;  ///< glLineStipple: bit i draws pixel i of 16
  std::uint16_t factor = 1;        ///< glLineStipple's repeat, 1 to 256
  /// Multisample rasterization (GL 1.5 section 3.4.4): the line is the rectangle of its width
  /// (at least 1) centred on the segment, ending at its endpoints, and covers the pixels whose
  /// centre it holds (smooth ignored). The GL library sets it for a multisample buffer's
  /// passes, each of which puts a sample on the pixel centres.
  bool multisample = false;
};

/// How points are drawn (GL 1.1 section 3.3; GL 1.4's point parameters).
struct PointState {
  float size = 1.0f;    ///< glPointSize, pixels; aliased points round it (at least 1)
  bool smooth = false;  ///< GL_POINT_SMOOTH: coverage multiplies the fragment's alpha
  /// GL_POINT_DISTANCE_ATTENUATION (a, b, c): unless (1, 0, 0), each point's size is derived
  /// from its eye-space distance d = |z_eye| (not divided by w): size / sqrt(a + b d + c d^2),
  /// clamped to [min_size, max_size] (GL 1.4 section 3.3, in Mesa's order of operations).
  glm::vec3 attenuation{1.0f, 0.0f, 0.0f};
  float min_size = 0.0f, max_size = 255.0f;  ///< pixels
  /// GL_POINT_SPRITE_ARB (ARB_point_sprite, core in GL 2.0): each point is a square of side
  /// `size` (not rounded, never smooth) rasterized as two triangles, and the texture units whose
  /// bit is set in `coord_replace` (GL_COORD_REPLACE_ARB) take (s, t, 0, 1) across it instead of
  /// the vertex's coordinates: s from 0 at its left edge to 1 at its right, t from 0 at its top
  /// to 1 at its bottom (the upper-left origin).
  bool sprite = false;
  std::uint8_t coord_replace = 0;
  /// Multisample rasterization (GL 1.5 section 3.3.3): the point is the disc of diameter its
  /// size (a square of side its size with `sprite`), unrounded, covering the pixels whose
  /// centre it holds (smooth ignored); a size below `fade_threshold` (GL_POINT_FADE_THRESHOLD_SIZE)
  /// draws the point at the threshold's size with its alpha times (size / threshold)^2.
  bool multisample = false;
  float fade_threshold = 1.0f;
  bool attenuated() const { return attenuation != glm::vec3(1.0f, 0.0f, 0.0f); }
};

/// User clip planes (GL 1.1 section 2.11) in EYE space: a point p is inside plane i when
/// dot(plane[i], p) >= 0. Planes whose bit is not set in `enabled` are ignored.
struct ClipPlanes {
  static constexpr int kCount = 8;
  std::array<glm::vec4, kCount> eye{};
  std::uint8_t enabled = 0;
};

/// Per-fragment state for one draw, and the rasterization rules before it: culling, facing,
/// polygon modes, line and point state, user clip planes. The operations run in GL's order
/// (GL 1.1 chapter 4): pixel ownership (the framebuffer), polygon stipple (rasterization, of
/// polygons only), scissor, alpha test, stencil test, depth test, blending or logic op, colour
/// mask. Dithering is never done (as llvmpipe's). Fog belongs to the colour (ShadeState::fog)
/// and comes before all of them.
struct FragmentState {
  CullMode cull = CullMode::kNone;
  bool front_ccw = true;  ///< glFrontFace(GL_CCW): counter-clockwise in window space is front
  bool depth_test = true;
  CompareFunc depth_func = CompareFunc::kLess;
  bool depth_write = true;
  BlendState blend;
  bool color_mask[4] = {true, true, true, true};
  StencilState stencil;
  bool polygon_offset = false;  ///< glPolygonOffset for filled polygons
  bool offset_line = false;     ///< ... for polygons drawn as lines (GL_POLYGON_OFFSET_LINE)
  bool offset_point = false;    ///< ... for polygons drawn as points (GL_POLYGON_OFFSET_POINT)
  float offset_factor = 0.0f, offset_units = 0.0f;
  ScissorState scissor;
  AlphaTestState alpha_test;
  /// GL_SAMPLE_ALPHA_TO_ONE (GL 1.5 section 4.1.3): the alpha of a fragment that passed the
  /// alpha test is 1 from there on (blending, the logic op and the colour written).
  bool alpha_one = false;
  LogicOpState logic_op;
  PolygonStipple stipple;
  PolygonMode front_mode = PolygonMode::kFill, back_mode = PolygonMode::kFill;
  LineState line;
  PointState point;
  ClipPlanes clip;
  /// When set, fragments passing the depth test are captured (with `blend`) instead of being
  /// written; depth is not written. For exact transparency.
  FragmentCapture* capture = nullptr;
  /// When set, the draw's primitives go to it instead of being rasterized (the reference
  /// path, even when a fast context is given): nothing is written.
  PrimitiveObserver* observer = nullptr;
};

}  // namespace shadelab
