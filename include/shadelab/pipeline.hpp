// The drawing pipeline shared by both front ends (scene files and the GL library):
// eye-space vertices in, pixels in a framebuffer out. Vertex lighting, clipping, triangle
// setup, rasterization, per-pixel shading and blending happen here. It keeps no state
// between calls besides the framebuffer it is given.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shadelab/image.hpp"
#include "shadelab/light.hpp"
#include "shadelab/material.hpp"
#include "shadelab/mesh.hpp"
#include "shadelab/scene.hpp"
#include "shadelab/texture.hpp"

namespace shadelab {

class PipelineContext;

/// A framebuffer's RGBA8 bytes: its own storage, or memory its owner lends it (attach), as
/// an OSMesa caller's buffer of the same layout is the GL library's colour buffer itself.
/// Copies always own their bytes.
class ColorBuffer {
 public:
  ColorBuffer() = default;
  ColorBuffer(const ColorBuffer& other) : owned_(other.begin(), other.end()) { point_at_owned(); }
  ColorBuffer& operator=(const ColorBuffer& other) {
    if (this != &other) {
      owned_.assign(other.begin(), other.end());
      point_at_owned();
    }
    return *this;
  }
  ColorBuffer(ColorBuffer&& other) noexcept { take(other); }
  ColorBuffer& operator=(ColorBuffer&& other) noexcept {
    if (this != &other) take(other);
    return *this;
  }

  std::uint8_t* data() { return data_; }
  const std::uint8_t* data() const { return data_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::uint8_t& operator[](std::size_t i) { return data_[i]; }
  const std::uint8_t& operator[](std::size_t i) const { return data_[i]; }
  std::uint8_t* begin() { return data_; }
  std::uint8_t* end() { return data_ + size_; }
  const std::uint8_t* begin() const { return data_; }
  const std::uint8_t* end() const { return data_ + size_; }
  friend bool operator==(const ColorBuffer& a, const ColorBuffer& b) {
    return a.size_ == b.size_ && (a.size_ == 0 || std::equal(a.begin(), a.end(), b.begin()));
  }

  /// Own storage of n bytes, all `value` (lent memory is let go, untouched).
  void assign(std::size_t n, std::uint8_t value) {
    owned_.assign(n, value);
    point_at_owned();
  }
  /// Uses the n bytes at `bytes` from now on, as they are, until assign, detach or the next
  /// attach; they must outlive that use. Nothing is copied.
  void attach(std::uint8_t* bytes, std::size_t n) {
    owned_ = {};
    data_ = bytes;
    size_ = n;
    lent_ = true;
  }
  /// Copies lent memory into own storage and lets it go.
  void detach() {
    if (!lent_) return;
    std::vector<std::uint8_t> copy(begin(), end());
    owned_.swap(copy);
    point_at_owned();
  }
  bool attached() const { return lent_; }

 private:
  void take(ColorBuffer& other) {
    owned_ = std::move(other.owned_);
    data_ = other.lent_ ? other.data_ : owned_.data();
    size_ = other.size_;
    lent_ = other.lent_;
    other.owned_ = {};
    other.point_at_owned();
  }
  void point_at_owned() {
    data_ = owned_.data();
    size_ = owned_.size();
    lent_ = false;
  }
  std::vector<std::uint8_t> owned_;
  std::uint8_t* data_ = nullptr;
  std::size_t size_ = 0;
  bool lent_ = false;
};

/// Colour, depth and stencil in OpenGL window space: row 0 is the BOTTOM row.
struct Framebuffer {
  int width = 0;
  int height = 0;
  ColorBuffer color;  ///< RGBA8, width * height * 4
  std::vector<float> depth;         ///< window-space depth in [0, 1]
  std::vector<std::uint8_t> stencil;

  void resize(int w, int h);
  /// Clears are split over `threads`' threads when given (a full-HD frame is 16 MB of colour
  /// and depth).
  void clear_color(glm::vec4 rgba, PipelineContext* threads = nullptr);
  /// The RGBA8 bytes clear_color writes for `rgba`.
  static std::array<std::uint8_t, 4> color_bytes(glm::vec4 rgba);
  void clear_depth(float d, PipelineContext* threads = nullptr);
  void clear_stencil(std::uint8_t s);
  /// The colour buffer as an image, top row first.
  Image to_image() const;
};

/// glViewport / glDepthRange.
struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;
  float near_depth = 0.0f, far_depth = 1.0f;
};

enum class CompareFunc { kNever, kLess, kEqual, kLequal, kGreater, kNotequal, kGequal, kAlways };
enum class StencilOp { kKeep, kZero, kReplace, kIncr, kDecr, kInvert };

/// glStencilFunc / glStencilOp / glStencilMask.
struct StencilState {
  bool enabled = false;
  CompareFunc func = CompareFunc::kAlways;
  std::uint8_t ref = 0, value_mask = 0xff, write_mask = 0xff;
  StencilOp fail = StencilOp::kKeep, depth_fail = StencilOp::kKeep, pass = StencilOp::kKeep;
};

/// Order-independent transparency: instead of blending, fragments that pass the depth test are
/// kept per pixel and composited later in true depth order (resolve_fragments).
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
  glm::vec4 texcoord;  ///< (s, t, r, q), not divided by q
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

/// Sorts every pixel's captured fragments far to near and blends them over the framebuffer with
/// each fragment's own blend state, then empties the capture.
void resolve_fragments(Framebuffer& fb, FragmentCapture& capture);

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
};

/// How points are drawn (GL 1.1 section 3.3).
struct PointState {
  float size = 1.0f;    ///< glPointSize, pixels; aliased points round it (at least 1)
  bool smooth = false;  ///< GL_POINT_SMOOTH: coverage multiplies the fragment's alpha
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

/// A depth map seen from one light (shadow mapping): one face for directional and spot lights,
/// six (a cube) for point lights. Built by render_scene; looked up during lighting.
struct ShadowMap {
  struct Face {
    glm::mat4 eye_to_clip{1.0f};  ///< camera eye space -> the light's clip space
    std::vector<float> depth;     ///< size x size window depths, row 0 at the bottom
  };
  int size = 0;                    ///< 0: this light casts no shadow
  std::vector<Face> faces;
  bool perspective = false;
  glm::vec3 light_eye{0.0f};       ///< light position in eye space (perspective maps)
  float texel_at_unit = 0.0f;      ///< world size of a texel at distance 1 (or everywhere, ortho)
  float bias = -1.0f;              ///< depth bias; < 0: automatic (normal offset, slope-scaled)
  int pcf = 1;                     ///< filter radius: (2 pcf + 1)^2 depth comparisons

  /// Fraction of the light reaching eye-space point `p` with unit normal `n` (0 in shadow).
  float visibility(const glm::vec3& p, const glm::vec3& n) const;
};

enum class FogMode { kLinear, kExp, kExp2 };

/// Fog (GL 1.1 section 3.9), as Mesa's fixed-function programs compute it: every vertex has
/// a fog coordinate (VertexInput::fog_coords, or by default the distance |z| of its eye-space
/// position from the eye plane, Mesa's GL_EYE_PLANE_ABSOLUTE_NV), interpolated per fragment
/// like any other attribute; each fragment computes its factor f from it (GL_LINEAR:
/// (end - c) / (end - start); GL_EXP: e^(-density c); GL_EXP2: e^(-(density c)^2)), clamps
/// it to [0, 1] and takes f C + (1 - f) C_fog as its red, green and blue; alpha is kept.
struct FogState {
  bool enabled = false;
  FogMode mode = FogMode::kExp;
  glm::vec3 color{0.0f};  ///< in [0, 1]
  float start = 0.0f, end = 1.0f, density = 1.0f;
};

/// How colours are made. With `lighting` the pipeline lights vertices or pixels (by `shading`)
/// with the one lighting function; without it, vertex colours are used as given.
struct ShadeState {
  bool lighting = true;
  ShadingMode shading = ShadingMode::kGouraud;
  LightModel model;
  std::span<const Light> lights;  ///< eye space
  Material front;
  Material back;  ///< used for back faces when model.two_side
  /// Texturing: when set (and complete), fragments are textured with `texture_env`, before the
  /// secondary colour is added. Needs texcoords in the vertex input.
  const Texture* texture = nullptr;
  TextureEnvMode texture_env = TextureEnvMode::kModulate;
  glm::vec4 texture_env_color{0.0f};  ///< GL_TEXTURE_ENV_COLOR, for kBlend, in [0, 1]
  /// The caller keeps `*texture` alive and unchanged until the context's finish_draws (the GL
  /// library finishes the waiting draws before it changes a texture and keeps the textures of
  /// waiting draws alive): a textured draw may then wait (PipelineContext::set_deferred).
  bool texture_kept = false;
  /// Shadow maps by light index (empty, or as long as `lights`; size 0 = unshadowed light).
  std::span<const ShadowMap> shadow_maps;
  /// Fog, applied after texturing and the colour sum.
  FogState fog;
};

/// One line segment of a draw: its two vertices; the second provokes (flat shading takes its
/// colour, GL 1.1 section 2.13.7). With kRestartStipple, the line stipple pattern starts
/// again at this segment (each segment of GL_LINES, the first of a strip or loop).
struct LineSegment {
  static constexpr std::uint32_t kRestartStipple = 1;
  std::uint32_t v[2];
  std::uint32_t flags = kRestartStipple;
};

/// Per-triangle flags for polygons drawn in GL_LINE / GL_POINT mode (VertexInput::
/// triangle_flags): which of its edges are edges of the polygon it comes from, with the edge
/// flag of their first vertex set (GL 1.1 section 2.6.2), and whether the line stipple
/// pattern starts again with it.
enum TriangleFlag : std::uint8_t {
  kTriangleEdge01 = 1,  ///< the edge from vertex 0 to vertex 1 (in point mode: vertex 0)
  kTriangleEdge12 = 2,  ///< ... from vertex 1 to vertex 2 (vertex 1)
  kTriangleEdge20 = 4,  ///< ... from vertex 2 to vertex 0 (vertex 2)
  kTriangleEdges = 7,
  kTriangleRestartStipple = 8,
};

/// Vertices in eye space and the triangles over them.
/// - `normals` (unit, eye space) are needed when lighting.
/// - `colors`: per-vertex colours used when lighting is off (empty: `constant_color`).
/// - `back_colors` / `secondary_colors`: optional pre-lit colours for back faces and the
///   separate specular colour, for front ends that light vertices themselves (the GL library).
struct VertexInput {
  std::span<const glm::vec4> positions;
  std::span<const glm::vec3> normals;
  std::span<const glm::vec4> colors;
  std::span<const glm::vec4> back_colors;
  std::span<const glm::vec3> secondary_colors;
  std::span<const glm::vec3> back_secondary_colors;
  /// (s, t, r, q) per vertex, for texturing: s / q and t / q index the texture, divided per
  /// fragment (GL 1.1 section 3.8), so that projected texture coordinates interpolate as GL
  /// says.
  std::span<const glm::vec4> texcoords;
  /// Fog coordinate per vertex (eye-space distance); empty: |z| of `positions`.
  std::span<const float> fog_coords;
  glm::vec4 constant_color{1.0f};
  std::span<const Triangle> triangles;  ///< last index of each is the provoking vertex
  /// Per triangle, TriangleFlag bits for the polygon modes (empty: every edge drawn, the stipple
  /// restarting at each triangle).
  std::span<const std::uint8_t> triangle_flags;
  std::span<const LineSegment> lines;  ///< drawn after the triangles (a draw has one kind)
  std::span<const std::uint32_t> points;
  /// Line stipple across draws: in, the pattern position for a first segment that does not
  /// restart it; out, the position after the last segment (a long GL_LINE_STRIP drawn in
  /// parts). Null: 0 in, nothing out.
  std::uint32_t* stipple_counter = nullptr;
};

/// Counters and timings for `shadelab render --stats`.
struct RenderStats {
  std::uint64_t triangles_in = 0;       ///< triangles submitted
  std::uint64_t triangles_culled = 0;   ///< back-face culled or degenerate
  std::uint64_t triangles_clipped = 0;  ///< crossing a clip plane (then split)
  std::uint64_t triangles_rasterized = 0;
  std::uint64_t vertices_lit = 0;
  std::uint64_t fragments = 0;        ///< covered samples that passed stipple and scissor
  /// Of `fragments`, those the fast pipeline handed one at a time to the reference's
  /// per-fragment operations (stencil, capture, shadow maps) instead of its SIMD blocks.
  std::uint64_t fragments_reference = 0;
  std::uint64_t pixels_shaded = 0;    ///< fragments that passed every test and were written
  std::uint64_t draws = 0;            ///< draw_triangles calls (PipelineContext::take_counts)
  std::uint64_t draws_deferred = 0;   ///< of them, those that waited for finish_draws
  double ms_vertex = 0, ms_raster = 0, ms_resolve = 0, ms_total = 0;
  bool interrupted = false;  ///< render_scene stopped at RenderOptions::deadline
  /// Exact transparency: fragments not blended because RenderOptions::max_fragment_memory was
  /// spent.
  std::uint64_t fragments_dropped = 0;
};

/// The fast pipeline's worker threads and reusable buffers (src/fast/, docs/performance.md).
/// Keep one alive across draws and frames: steady-state drawing then allocates nothing. Not
/// thread-safe: one draw at a time per context.
class PipelineContext {
 public:
  /// `threads` workers including the caller; 0: $SHADELAB_THREADS if set, else all cores.
  explicit PipelineContext(int threads = 0);
  ~PipelineContext();
  PipelineContext(const PipelineContext&) = delete;
  PipelineContext& operator=(const PipelineContext&) = delete;
  int threads() const;
  /// The SIMD instruction set the fast pipeline dispatches to on this CPU ("AVX3", "AVX2",
  /// "SSE4", "SSSE3" or the portable "EMU128"): the best one compiled that the CPU runs, or
  /// the one $SHADELAB_SIMD names ("avx512", "avx2", "sse4", "ssse3", "scalar"; read when the
  /// first context is made, ignored when that target is not available).
  static std::string simd_target();
  /// The framebuffer's tiles: squares of kTileSize pixels, numbered row by row from pixel
  /// (0, 0), (width + kTileSize - 1) / kTileSize to a row.
  static constexpr int kTileSize = 64;
  /// The tiles the last draw_triangles through this context may have written to (those its
  /// triangles reached, in increasing order), or will write to when it is deferred; no pixel
  /// outside them changed.
  std::span<const int> last_draw_tiles() const;
  /// Deferred drawing, llvmpipe's way (off by default; the GL library turns it on). While on,
  /// draw_triangles through this context transforms, lights, sets up and bins a draw's
  /// triangles when called and leaves rasterizing them to finish_draws, which draws every
  /// waiting draw tile by tile: in each tile, every draw's triangles in submission order,
  /// while the tile is in the cache. A frame's draws then pass over the framebuffer once
  /// rather than once each; the pixels are the same. A draw waits only when nothing it reads
  /// stays the caller's after the call (no shadow maps, fragment capture or texture but a
  /// kept one, ShadeState::texture_kept), no
  /// counts are asked of it (stats null), and it and the queue are small (a long draw pays for
  /// its own pass); any other draw first finishes the waiting ones. Call finish_draws (or
  /// apply_pending_clears, which calls it) before anything else reads or writes the
  /// framebuffer, and before it is resized or destroyed. Turning it off finishes the waiting
  /// draws.
  void set_deferred(bool on);
  /// Rasterizes every waiting draw (set_deferred), applying the pending clears of the tiles
  /// they reach.
  void finish_draws();
  /// How many draws wait for finish_draws.
  std::size_t deferred_draws() const;
  /// Counting (off by default): every draw through the context adds its triangle, fragment
  /// and draw counts (RenderStats; fragments by path, draws deferred or not) to totals that
  /// take_counts returns and resets. Deferred draws count when finish_draws draws them.
  void set_counting(bool on);
  RenderStats take_counts();
  /// Clears left to the draws, as llvmpipe does (the GL library's glClear): a tile flagged in
  /// `tiles` is cleared (colour to `color` with kColor, depth to `depth` with kDepth) by the
  /// next draw_triangles through this context that draws into it, just before its first
  /// triangle, while the tile is in the cache; its flag is then reset. Whoever flags tiles
  /// sizes `tiles` to the framebuffer's and calls apply_pending_clears before anything else
  /// reads or writes the framebuffer; tiles are flagged only while no draw waits (call
  /// finish_draws first: waiting draws come before the clear). Empty: nothing pending.
  struct PendingClears {
    static constexpr std::uint8_t kColor = 1, kDepth = 2;
    std::vector<std::uint8_t> tiles;
    std::uint32_t color = 0;  ///< the pixel's RGBA8 bytes
    float depth = 1.0f;
  };
  PendingClears& pending_clears();
  /// Leaves a clear of `fb`'s colour (PendingClears::kColor, to `color`) and / or depth
  /// (kDepth, to `depth`) pending on every tile: each tile is cleared by the next draw into
  /// it, while it is in the cache, and apply_pending_clears clears the others (call it before
  /// reading `fb`). Waiting draws are finished first.
  void clear_later(Framebuffer& fb, std::uint8_t what, glm::vec4 color, float depth);
  /// Finishes the waiting draws, then applies the pending clears of the buffers in `what`
  /// (PendingClears::kColor, kDepth: both by default) to `fb` now, on the context's threads;
  /// the others stay pending. Colour is written with streaming stores where it can be (it
  /// is not read first).
  void apply_pending_clears(Framebuffer& fb, std::uint8_t what = PendingClears::kColor | PendingClears::kDepth);
  /// Starts applying the pending clears of the buffers in `what` to the listed tiles of `fb`
  /// on one of the context's worker threads, and returns while it runs: memory-bound writes
  /// that then overlap the caller's own work (the GL library's glClear, for the tiles no draw
  /// reached since the clear before: the tiles it expects to stay as cleared). Every other
  /// call through the context waits for it to end first; until then `fb` must not be read,
  /// written, resized or destroyed. With one thread it does nothing (the clears stay
  /// pending). A listed tile that a draw reaches after all is cleared twice, which costs
  /// time, not correctness; tiles listed twice or not in `fb` are ignored.
  void clear_ahead(Framebuffer& fb, std::uint8_t what, std::span<const int> tiles);
  /// Runs fn(begin, end) over [0, count) in chunks of about `grain` items on the context's
  /// threads (the caller joins in); returns when every chunk is done. For front ends that
  /// prepare vertices before a draw. fn must be safe to run concurrently on disjoint ranges.
  /// fn is called through a reference (nothing is copied or allocated).
  template <class Fn>
  void parallel_for(std::size_t count, std::size_t grain, Fn&& fn) {
    using F = std::remove_reference_t<Fn>;
    parallel_for_ref(count, grain, [](void* f, std::size_t b, std::size_t e) { (*static_cast<F*>(f))(b, e); },
                     const_cast<void*>(static_cast<const void*>(&fn)));
  }
  struct Impl;
  Impl& impl() { return *impl_; }

 private:
  void parallel_for_ref(std::size_t count, std::size_t grain, void (*call)(void*, std::size_t, std::size_t),
                        void* fn);
  std::unique_ptr<Impl> impl_;
};

/// Draws the triangles, lines and points of `vertices` into `fb`: vertex lighting
/// (flat/Gouraud), projection, homogeneous clipping against the view volume and the user clip
/// planes, viewport mapping, facing, culling and the polygon modes, rasterization (triangles
/// with the top-left fill rule at pixel centres; lines and points by llvmpipe's rules,
/// docs/rasterization.md), depth/stencil tests, per-pixel lighting (Phong), blending.
/// `projection` maps eye space to clip space. With `fast`, the tiled, multithreaded SIMD
/// pipeline draws instead of the reference path: the same coverage and depth, colours within
/// 1/255.
void draw_triangles(Framebuffer& fb, const glm::mat4& projection, const Viewport& viewport,
                    const FragmentState& fragment, const ShadeState& shade,
                    const VertexInput& vertices, RenderStats* stats = nullptr,
                    PipelineContext* fast = nullptr);

/// A rectangle of window-space fragments that no primitive made: what glDrawPixels,
/// glCopyPixels and glBitmap produce (GL 1.1 sections 3.6.4, 3.6.5, 3.7). Fragment (i, j) of
/// the rectangle is at window pixel (x + i, y + j); arrays are indexed by j * width + i
/// (row 0 the bottom row).
struct FragmentRect {
  int x = 0, y = 0;
  int width = 0, height = 0;  ///< >= 0
  /// The fragments' colours, unclamped: width * height of them, or one for every fragment
  /// (glBitmap's raster colour).
  std::span<const glm::vec4> colors;
  float depth = 0.0f;                ///< window depth of every fragment (the raster position's)
  std::span<const float> depths;     ///< or one per fragment (glDrawPixels of depth values)
  std::span<const std::uint8_t> mask;  ///< empty, or width * height: 0 makes no fragment (glBitmap)
  /// (s, t, r, q) of every fragment (the raster position's), for texturing (s / q, t / q).
  glm::vec4 texcoord{0.0f, 0.0f, 0.0f, 1.0f};
  float fog_coord = 0.0f;    ///< the raster position's fog coordinate
};

/// Runs GL's per-fragment operations on the fragments of `rect`, as on a primitive's: their
/// colours textured with `shade`'s texture at `texcoord` (its magnification filter: the
/// coordinates do not change across the rectangle) and fogged with `shade.fog` at `fog_coord`
/// (lighting and shading are not used), then `fragment`'s scissor, alpha test, stencil and
/// depth tests, blending or logic op and colour mask. Fragments outside the framebuffer are
/// dropped (pixel ownership); polygon stipple, culling and polygon offset do not apply.
/// With `fast`, its waiting draws and pending clears are applied first and the fragments are
/// written at once, rows split over its threads (a simple loop over the reference's
/// operations: not a hot path); the caller marks what it knows of the rectangle's tiles.
void draw_fragments(Framebuffer& fb, const FragmentState& fragment, const ShadeState& shade,
                    const FragmentRect& rect, RenderStats* stats = nullptr,
                    PipelineContext* fast = nullptr);

}  // namespace shadelab
