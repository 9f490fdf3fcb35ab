// The data the fast pipeline's stages hand to each other for one draw: transformed vertices,
// the varying layout, per-tile bins of triangles in submission order, and per-thread scratch.
// Plain data and small helpers only; the stages themselves live in vertex_stage.cpp,
// setup.cpp and raster.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>

#include "fast/lighting_setup.hpp"
#include "pipeline/fragment_ops.hpp"
#include "pipeline/stages.hpp"
#include "raster/prims.hpp"
#include "shadelab/detail/default_init.hpp"
#include "shadelab/pipeline.hpp"

namespace shadelab::fast {

inline constexpr int kTileShift = 6;  ///< 64 x 64 pixel tiles
inline constexpr int kTileSize = 1 << kTileShift;
static_assert(kTileSize == PipelineContext::kTileSize, "the tiles last_draw_tiles names");
inline constexpr float kMinClipW = 1e-6f;  ///< clip.cpp's w >= epsilon plane

/// The float just below 1/2 (1/2 - 2^-25). For every float s in [0, 255], trunc(s +
/// kJustBelowHalf) is lround(s), half away from zero: where the sum is inexact, s is too far
/// from any k + 1/2 for its rounding to cross an integer. The fragment path's 8-bit conversion
/// (three operations instead of a rounding and a tie correction); tests/fast/unorm8_test.cpp
/// checks every float in the range.
inline constexpr float kJustBelowHalf = 0x1.fffffep-2f;

/// 1/255 rounded to float: the fragment path's reciprocal for 8-bit channels read back.
inline constexpr float kInv255 = 1.0f / 255.0f;

/// The first and last pixel whose centre (x + 1/2) lies in [lo, hi], snapped coordinates: no
/// pixel outside can be covered. The reference rasterizer scans a box one pixel wider on
/// every side; its edge tests leave those pixels uncovered, so coverage is the same.
inline int first_centre(std::int64_t lo) {
  return int((lo - detail::kSubpixelOne / 2 + detail::kSubpixelOne - 1) >> detail::kSubpixelBits);
}
inline int last_centre(std::int64_t hi) { return int((hi - detail::kSubpixelOne / 2) >> detail::kSubpixelBits); }

/// Edge e of a counter-clockwise triangle runs from vertex kEdgeFrom[e] to kEdgeTo[e]
/// (v[e + 1] to v[e + 2], mod 3), as the reference's edge functions w0, w1, w2.
inline constexpr int kEdgeFrom[3] = {1, 2, 0}, kEdgeTo[3] = {2, 0, 1};

/// A vertex after the viewport transform, as setup and the rasterizer read it. Values are
/// the reference's to_window results bit for bit; sx, sy are snap()'s.
struct RasterVertex {
  double x, y;        ///< window coordinates
  std::int32_t sx, sy;  ///< snapped to 1/256 pixel
  float z;            ///< window depth
  float inv_w;        ///< 1 / w_clip
};

/// Where each reference attribute slot (stages.hpp Attr) lives among a vertex's varyings;
/// -1: not carried (zero). Back slots may alias the front ones.
struct VaryingLayout {
  int front_color = -1, back_color = -1;          // 4 floats
  int front_secondary = -1, back_secondary = -1;  // 3 floats
  int eye_position = -1, eye_normal = -1;         // 3 floats
  int texcoord[kMaxTextureUnits] = {-1, -1, -1, -1};  // per texture unit, 4 floats: s, t, r, q
  int fog = -1;                                   // 1 float: the fog coordinate
  int count = 0;                                  // floats per vertex
};

/// The SIMD block loop a draw's triangles wholly inside the framebuffer take (raster-inl.h):
/// the general one, which reads the fragment state at every block, or one compiled for the
/// usual state, with nothing left to decide per block but fog (no scissor, stipple, alpha
/// test or logic op): the depth test kLess or kLequal writing depth (kOpaqueLess...), or no
/// depth test (kOpaque, kBlend: 2D drawing), every colour channel written, flat or Gouraud
/// colours, and the colour either replacing what is there (kOpaque...) or blended over it by
/// its alpha (kBlend...: glBlendFunc GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA for every channel
/// with GL_FUNC_ADD, BlendState::source_over). kTextured: one texture unit
/// (DrawPlan::texture_unit), any filter and environment but GL_COMBINE, any depth test, alpha
/// test, fog and blend, without stencil, logic op, per-pixel lighting or masks; these it reads
/// per block. kTextured2D: kTextured's draws whose texture is a 2D colour texture (not 1D, 3D,
/// a cube map or a depth texture), with a sampler compiled for that shape alone. kStencil:
/// the stencil test with any function and operations, any depth test, flat or Gouraud colours
/// opaque or blended as kBlend, every colour channel written or none, fogged or not, without
/// texture, alpha test, logic op, per-pixel lighting or masks.
enum class BlockKernel : std::uint8_t { kGeneral, kOpaqueLess, kOpaqueLequal, kBlendLess, kBlendLequal, kOpaque, kBlend,
                                        kTextured, kTextured2D, kStencil };

/// Whether a kernel is one of the textured ones (kTextured, kTextured2D).
constexpr bool kernel_textured(BlockKernel k) { return k == BlockKernel::kTextured || k == BlockKernel::kTextured2D; }

/// Whether a kernel is one of the untextured ones that test depth (GL_LESS or GL_LEQUAL,
/// writing it); kOpaque and kBlend draw without the depth test.
constexpr bool kernel_tests_depth(BlockKernel k) {
  return k == BlockKernel::kOpaqueLess || k == BlockKernel::kOpaqueLequal || k == BlockKernel::kBlendLess ||
         k == BlockKernel::kBlendLequal;
}
/// Whether a kernel blends (source alpha over the framebuffer) rather than writing its colours.
constexpr bool kernel_blends(BlockKernel k) {
  return k == BlockKernel::kBlendLess || k == BlockKernel::kBlendLequal || k == BlockKernel::kBlend;
}
/// Whether a kernel writes its colours opaque from the byte planes (TrianglePlanes::bytes).
constexpr bool kernel_opaque(BlockKernel k) {
  return k == BlockKernel::kOpaqueLess || k == BlockKernel::kOpaqueLequal || k == BlockKernel::kOpaque;
}

/// How a texture unit of a draw samples, decided once per draw (plan.cpp) for the SIMD
/// samplers (texture-inl.h): the texture's levels and parameters as sample_texture reads them.
struct TexturePlan {
  const Texture* texture = nullptr;  ///< complete; null: the unit is off
  bool one_d = false;
  bool three_d = false;  ///< r sampled too (texcoord planes project it)
  bool cube = false;     ///< a cube map: (s, t, r) picks a face (cube_face), r projected too
  bool depth_texture = false;  ///< a depth texture (Texture::depth): r projected too, the value compared
  bool compare = false;  ///< Texture::compare, with compare_func
  TextureCompare compare_func = TextureCompare::kLequal;
  float border_depth = 0.0f;  ///< the border colour's red, a depth texture's border texel
  /// A level of detail per quad is needed: mipmaps, or minification and magnification
  /// filtering differently. Otherwise level 0 with the one filter.
  bool lod = false;
  bool mipmaps = false;
  bool linear_mip = false;  ///< *_MIPMAP_LINEAR: two levels blended
  bool mag_linear = false;  ///< GL_LINEAR magnification
  bool min_linear = false;  ///< linear within a level when minified (GL_LINEAR, GL_LINEAR_MIPMAP_*)
  TextureWrap wrap_s = TextureWrap::kRepeat, wrap_t = TextureWrap::kRepeat, wrap_r = TextureWrap::kRepeat;
  float width = 0.0f, height = 0.0f, depth = 0.0f;  ///< the base level's
  int base_level = 0;                 ///< Texture::base_level
  int last_level = 0;                 ///< Texture::last_level
  TextureLod adjust;                  ///< texture_lod: bias and clamps
  float border[4] = {};               ///< the border colour in byte units
  TextureEnvMode env = TextureEnvMode::kModulate;
  TextureFormat format = TextureFormat::kRgba;
  /// eight_bit_filtering: linear filtering in llvmpipe's 8-bit arithmetic, on RGBA8 words.
  bool eight_bit = false;
  /// The base level's sides are powers of two (repeat masks the 8-bit filter's indices).
  bool pot_s = false, pot_t = false, pot_r = false;
  float env_color[4] = {};
  TextureCombine combine;  ///< env kCombine's
};

/// What a draw needs from each stage, decided once per draw (plan.cpp).
struct DrawPlan {
  VaryingLayout layout;
  bool vertex_lighting = false;  ///< flat/Gouraud: light_point at vertices
  bool simd_vertex_lighting = false;
  bool phong = false;            ///< lit per pixel
  bool flat = false;             ///< colours from the provoking vertex
  bool two_side = false;         ///< back-facing triangles use back colours / material
  bool scalar_fragments = false; ///< per-fragment reference operations (capture, shadow
                                 ///< maps, Phong the SIMD kernel does not cover)
  TexturePlan texture[kMaxTextureUnits];  ///< texturing on the SIMD path, per texture unit
  bool textured = false;         ///< some unit has a texture
  bool combine = false;          ///< some unit's environment is GL_COMBINE
  bool writes_color = true;      ///< some colour channel is written (or captured)
  bool fog = false;              ///< fogged colours (ShadeState::fog)
  detail::FogParams fog_params;
  bool alpha_test = false;       ///< colour before depth: the alpha test decides first
  /// Interpolated colours computed as the reference does (raster-inl.h's block_color): the
  /// alpha test's alpha, or every channel for the logic op.
  bool exact_colors = false;
  float alpha_ref = 0.0f;        ///< the reference as an 8-bit value (detail::alpha_test)
  float blend_constant[4] = {};  ///< glBlendColor's, in 8 bits (detail::blend_constant)
  /// Lanes of each block masked by the scissor box and the polygon stipple (raster-inl.h, kept_lanes).
  bool lane_masks = false;
  /// The pixels a draw may write: the framebuffer, cut by the scissor box (inclusive bounds;
  /// empty when x1 < x0). Setup bins no tile outside it.
  int box_x0 = 0, box_y0 = 0, box_x1 = -1, box_y1 = -1;
  bool prims = false;            ///< lines, points or unfilled polygons (fast/prims.cpp)
  /// The enabled user clip planes in clip space (clip.cpp's clip_space_planes).
  std::array<glm::vec4, ClipPlanes::kCount> user_planes;
  int user_plane_count = 0;
  bool coverage = false;         ///< smooth lines or points: alpha times their coverage
  BlockKernel kernel = BlockKernel::kGeneral;
  int texture_unit = 0;  ///< the textured kernels' unit
  /// A textured kernel writes its unit's filtered bytes as the colour (and alpha-tests their
  /// alpha byte): GL_REPLACE of an RGBA texture filtered by the 8-bit sampler, without
  /// blending or fog (byte b is b / 255 in the float chain, which packs it back to b).
  bool texel_bytes = false;
  LightingSetup lighting;
};

/// One fan triangle of a clipped polygon, or a triangle of a line, a point or an unfilled
/// polygon's piece (raster/prims.hpp); indices into its setup chunk's clip vertices.
struct ClippedTriangle {
  static constexpr std::uint32_t kNoCoverage = ~0u;
  std::uint32_t v[3];
  std::uint32_t provoking;  ///< the original triangle's last vertex (a main vertex index)
  std::uint32_t coverage = kNoCoverage;  ///< a smooth line's or point's, in the chunk's list
  bool offset = true;  ///< takes glPolygonOffset's fill offset (lines and points have theirs)
  bool polygon = true;  ///< a polygon's: the polygon stipple applies (not a line's or a point's)
  /// An aliased line's parallelogram (Piece::parallelogram): v are its corners 0, 1, 2
  /// (counter-clockwise), the fourth v[0] + v[2] - v[1]; one plane, triangle v's.
  bool parallelogram = false;
};

/// A point drawn as the box of pixels it covers (PrimAssembler::point_pixels): no edges, one
/// bin entry, and its fragments' values the vertex's own (`vertex`, a main vertex index; its
/// varyings copied into SetupChunk::box_varyings): window depth `z`, `inv_w`. `box` is cut to
/// the draw's pixel box. Two to a cache line, none across two.
struct alignas(32) PointBox {
  detail::PixelBox box;
  float z, inv_w;
  std::uint32_t vertex;
};

/// Bin entries: a triangle index with these flags.
inline constexpr std::uint32_t kBinClipped = 1u << 31;  ///< index into ClippedTriangle list
inline constexpr std::uint32_t kBinFront = 1u << 30;
inline constexpr std::uint32_t kBinBox = 1u << 29;  ///< index into PointBox list
inline constexpr std::uint32_t kBinIndexMask = kBinBox - 1;

/// One contiguous range of triangles set up together: its bins keep submission order.
struct SetupChunk {
  std::vector<std::vector<std::uint32_t>> bins;  ///< per tile
  std::vector<RasterVertex> clip_vertices;
  std::vector<float> clip_varyings;
  std::vector<ClippedTriangle> clipped;
  std::vector<detail::Coverage> coverage;
  std::vector<PointBox> boxes;
  std::vector<float> box_varyings;  ///< box i's at i times the layout's count
  std::vector<detail::ClipVertex> poly, scratch;
  RenderStats stats;
};

/// Where the SIMD path reads and writes the pixels of blocks wholly inside the framebuffer:
/// pixel (x, y) at index (y - y0) * stride + (x - x0) of `depth` and `color` (RGBA8 as one
/// word). The framebuffer itself, or a worker's tile buffer (draw_fast.cpp: a cleared tile is
/// drawn in the cache and written out once). Blocks touching the framebuffer's edge and the
/// per-fragment reference path always use the framebuffer.
struct PixelTarget {
  float* depth = nullptr;
  std::uint32_t* color = nullptr;
  std::size_t stride = 0;
  int x0 = 0, y0 = 0;
  /// The framebuffer's stencil values, always in place: pixel (x, y) at y * stencil_stride + x.
  std::uint8_t* stencil = nullptr;
  std::size_t stencil_stride = 0;
};

/// One tile's colour and depth, rows of kTileSize pixels.
struct alignas(64) TileBuffer {
  std::uint32_t color[kTileSize * kTileSize];
  float depth[kTileSize * kTileSize];
};

/// The largest depth value of the tile a worker draws in its tile buffer (raster.cpp's
/// behind_tile): a large triangle every fragment of which would fail GL_LESS or GL_LEQUAL
/// against it is not rasterized there at all. And, in the tile buffer or in place, a bound
/// above the depth of each of the tile's blocks (raster-inl.h's block_bounds), by which the
/// depth-testing and textured kernels skip a block hidden there before its coverage and depth
/// are computed.
struct TileDepthBound {
  bool on = false;     ///< drawing a tile in the tile buffer
  bool known = false;  ///< `max` is the largest depth in the tile (else computed when needed)
  float max = 1.0f;
  /// Whether the blocks' bounds serve the tile drawn: only the SIMD paths draw in it, and
  /// each leaves every bound above its block's depth (raster.cpp's depth_written).
  bool blocks_on = false;
  /// `blocks` holds a bound for each block of the tile, row of blocks after row; else every
  /// block's bound is `initial` (the cleared depth, or infinity when unknown) and `blocks` is
  /// filled at its first use. Depth tests GL_LESS, GL_LEQUAL, GL_EQUAL and GL_NEVER only ever
  /// lower a stored depth, so a bound stays above it through their writes.
  bool blocks_ready = false;
  float initial = 1.0f;
  int x0 = 0, y0 = 0;  ///< the tile's first pixel
  /// Room for a tile's blocks of one pixel (the scalar target's); no allocation while drawing.
  std::array<float, kTileSize * kTileSize> blocks;

  /// At the start of the tile at (x, y): drawn in the tile buffer or in place (`buffered`),
  /// by the SIMD paths only (`simd`), its depth cleared to `depth` or (`cleared` false)
  /// unknown.
  void start(int x, int y, bool buffered, bool simd, bool cleared, float depth) {
    on = buffered;
    known = cleared;
    max = depth;
    blocks_on = simd;
    blocks_ready = false;
    initial = cleared ? depth : std::numeric_limits<float>::infinity();
    x0 = x;
    y0 = y;
  }
};

/// Per-worker scratch (vertex stage and rasterizer).
struct WorkerScratch {
  detail::Attribs attribs[3];     ///< full reference attributes (scalar fragments)
  std::vector<float> visibility;  ///< shadow-map visibility per light (scalar lighting)
  PixelTarget target;             ///< set before each raster_tile
  std::unique_ptr<TileBuffer> tile;  ///< made at its first use
  TileDepthBound bound;              ///< of the tile drawn in `tile`
  RenderStats stats;
};

/// Everything one draw's stages read. Filled by draw_fast.cpp. A deferred draw (rasterized
/// later, PipelineContext::set_deferred) owns everything its rasterization reads: its state,
/// lights and triangles are copied here; `in` is read only while the draw is made.
struct DrawJob {
  Framebuffer* fb = nullptr;
  int fb_width = 0, fb_height = 0;      ///< fb's size when the draw was made
  const FragmentState* frag = nullptr;  ///< the caller's, or frag_copy when deferred
  const ShadeState* shade = nullptr;  ///< shade_copy: an incomplete texture already dropped
  const VertexInput* in = nullptr;    ///< null once the draw is set up
  std::span<const Triangle> triangles;  ///< in->triangles, or triangle_copy when deferred
  FragmentState frag_copy;
  ShadeState shade_copy;
  std::vector<Light> light_copy;  ///< shade_copy.lights when deferred
  detail::ScratchVector<Triangle> triangle_copy;
  std::vector<int> tiles;  ///< the tiles this draw's triangles reach (deferred draws)
  bool counted = false;    ///< its fragments are counted (RenderStats asked for)
  glm::mat4 projection{1.0f};
  Viewport viewport;
  DrawPlan plan;
  // Vertex stage output, one entry per input vertex.
  // Written in full for every vertex by the vertex stage: resizing zeroes nothing.
  detail::ScratchVector<RasterVertex> vertices;
  detail::ScratchVector<float> varyings;       ///< layout.count floats per vertex
  detail::ScratchVector<std::uint8_t> outcodes;  ///< bit k: outside clip plane k (clip.cpp's order)
  /// With user clip planes: bit k, outside user plane k (clip_outcode's bit 7 + k).
  detail::ScratchVector<std::uint8_t> user_outcodes;
  // Setup output.
  std::vector<SetupChunk> chunks;
  int chunk_count = 0;
  int tiles_x = 0, tiles_y = 0;
};

/// Expands a vertex's varyings into the reference's attribute slots (absent slots zero).
void expand_varyings(const VaryingLayout& layout, const float* varyings, detail::Attribs& out);

/// Packs reference attribute slots back into varyings.
void compact_varyings(const VaryingLayout& layout, const detail::Attribs& attr, float* out);
/// The reference's attribute slots (bit i: slot i of detail::Attribs) that `layout` carries:
/// those expand_varyings fills and compact_varyings reads.
std::uint64_t attribute_slots(const VaryingLayout& layout);

}  // namespace shadelab::fast
