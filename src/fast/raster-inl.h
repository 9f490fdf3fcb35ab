// The fast rasterizer's per-target building blocks (Highway: included once per SIMD target by
// each unit that draws triangles): a block of two rows of as many pixels as the target has
// double lanes, its coverage from exact integer edge functions held in doubles (below 2^53),
// so coverage is the reference's; its depth, the reference's float plane (reference_raster.inl's
// plane_depth); its fragments through simd_block, a kernel or the reference per fragment; and
// raster_path, which walks a triangle's blocks. It must not choose a path (raster.cpp does) nor
// know about tiles beyond the job's pixel target.
//
// raster_path's instantiations are the rasterizer's largest functions, so they are compiled in
// units of their own, in parallel: raster.cpp (the kernels of the usual fragment state and the
// tile loop), raster_general.cpp (simd_block inside and at the framebuffer's edge),
// raster_coverage.cpp (smooth lines and points), raster_scalar.cpp (the reference path).
#if defined(SHADELAB_FAST_RASTER_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SHADELAB_FAST_RASTER_INL_H_
#undef SHADELAB_FAST_RASTER_INL_H_
#else
#define SHADELAB_FAST_RASTER_INL_H_
#endif

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "fast/block_color-inl.h"
#include "fast/fragment-inl.h"
#include "fast/triangle.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

/// A triangle drawn by simd_block in every block: `interior`, wholly inside the framebuffer;
/// otherwise touching its right or bottom edge (raster_general.cpp).
void raster_general(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, bool interior);
/// A smooth line's or point's triangle on the SIMD path, its coverage applied to alpha
/// (raster_coverage.cpp).
void raster_coverage(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, bool interior);
/// A triangle whose fragments take the reference per-fragment path (raster_scalar.cpp).
void raster_scalar(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, bool interior);

namespace {

constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);

// A block's depth and colour rows: in the framebuffer or, where a row leaves it (past its
// right or bottom edge), a local copy of the part inside.
struct BlockPixels {
  float* depth[kRows];
  std::uint32_t* color[kRows];
  std::uint8_t* stencil[kRows];
  alignas(64) float depth_copy[kRows][kMaxLanes];
  alignas(64) std::uint32_t color_copy[kRows][kMaxLanes];
  alignas(64) std::uint8_t stencil_copy[kRows][kMaxLanes];
  std::size_t index[kRows];  // framebuffer index of each row's first pixel
  int copied[kRows];         // pixels of the row inside the framebuffer, when copied; else 0
};

HWY_INLINE void open_block(const DrawJob& job, const PixelTarget& target, int x, int y, bool interior,
                           BlockPixels& g) {
  const bool stencil = job.frag->stencil.enabled;
  if (interior) {  // every row inside the framebuffer
    const std::size_t first = std::size_t(y - target.y0) * target.stride + std::size_t(x - target.x0);
    #pragma GCC unroll 4
    for (int r = 0; r < kRows; ++r) {
      const std::size_t index = first + std::size_t(r) * target.stride;
      g.depth[r] = job.frag->depth_test ? target.depth + index : nullptr;
      g.color[r] = job.plan.writes_color ? target.color + index : nullptr;
      g.stencil[r] = stencil ? target.stencil + std::size_t(y + r) * target.stencil_stride + std::size_t(x) : nullptr;
      g.copied[r] = 0;
    }
    return;
  }
  Framebuffer& fb = *job.fb;
  const std::size_t width = std::size_t(fb.width);
  const std::size_t first = std::size_t(y) * width + std::size_t(x);
  const int lanes = int(hn::Lanes(DD()));
  const int valid = std::min(fb.width - x, lanes);
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) {
    const bool inside = y + r < fb.height;
    g.index[r] = inside ? first + std::size_t(r) * width : 0;
    g.depth[r] = job.frag->depth_test ? &fb.depth[g.index[r]] : nullptr;
    g.color[r] = job.plan.writes_color ? reinterpret_cast<std::uint32_t*>(&fb.color[g.index[r] * 4]) : nullptr;
    g.stencil[r] = stencil ? &fb.stencil[g.index[r]] : nullptr;
    g.copied[r] = 0;
    if (inside && valid == lanes) continue;
    // A partial row: its lanes outside the framebuffer are never covered, but are loaded.
    const int n = inside ? valid : 0;
    g.copied[r] = n;
    std::fill_n(g.depth_copy[r], lanes, 0.0f);
    std::fill_n(g.color_copy[r], lanes, 0u);
    std::fill_n(g.stencil_copy[r], lanes, std::uint8_t(0));
    if (g.depth[r]) g.depth[r] = static_cast<float*>(std::memcpy(g.depth_copy[r], g.depth[r], std::size_t(n) * 4));
    if (g.color[r]) g.color[r] = static_cast<std::uint32_t*>(std::memcpy(g.color_copy[r], g.color[r], std::size_t(n) * 4));
    if (g.stencil[r]) g.stencil[r] = static_cast<std::uint8_t*>(std::memcpy(g.stencil_copy[r], g.stencil[r], std::size_t(n)));
  }
}

inline void close_block(const DrawJob& job, const BlockPixels& g) {
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) {
    const std::size_t n = std::size_t(g.copied[r]);
    if (!n) continue;
    if (g.depth[r]) std::memcpy(&job.fb->depth[g.index[r]], g.depth[r], n * sizeof(float));
    if (g.color[r]) std::memcpy(&job.fb->color[g.index[r] * 4], g.color[r], n * 4);
    if (g.stencil[r]) std::memcpy(&job.fb->stencil[g.index[r]], g.stencil[r], n);
  }
}

// A bound below every fragment's depth (block(): clamp_unit(plane + offset)). A plane with
// no slope gives each fragment base + 0 + 0 exactly: that depth itself. Otherwise the
// vertices' nearest, less far more than the few float roundings of the plane and the offset.
inline float nearest_depth(const TriSetup& t) {
  const float base = t.depth.base, d0 = t.depth.d0, d1 = t.depth.d1;
  auto unit = [](float v) { return v > 0.0f ? std::min(v, 1.0f) : 0.0f; };
  if (d0 == 0.0f && d1 == 0.0f) return unit(base + t.offset);
  const float margin = 0x1p-20f * (std::fabs(base) + std::fabs(d0) + std::fabs(d1) + std::fabs(t.offset));
  return unit(std::min({base, base + d0, base + d1}) + t.offset - margin);
}

// The depth bounds of the tile's blocks (TileDepthBound::blocks, filled at their first use)
// for a triangle drawn with the depth test GL_LESS or GL_LEQUAL, or null where they do not
// serve (a tile some draw of which takes the reference's path; a draw whose fragments are
// counted, always rasterized). A block whose bound is at most `reject` (the triangle's
// nearest depth, or for GL_LEQUAL the float below it) holds no depth any fragment of the
// triangle passes.
HWY_INLINE float* block_bounds(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, float& reject) {
  const FragmentState& f = *job.frag;
  TileDepthBound& b = ws.bound;
  const bool less = f.depth_func == CompareFunc::kLess, lequal = f.depth_func == CompareFunc::kLequal;
  if (!b.blocks_on || job.counted || !f.depth_test || !(less || lequal)) return nullptr;
  if (!b.blocks_ready) {
    const std::size_t n = std::size_t(kTileSize / kRows) * (kTileSize / hn::Lanes(DD()));
    std::fill_n(b.blocks.begin(), n, b.initial);
    b.blocks_ready = true;
  }
  const float z = nearest_depth(t);
  reject = less ? z : std::nextafter(z, -1.0f);
  return b.blocks.data();
}

// A triangle's fragment counts, kept in registers while it is drawn (RenderStats at the end).
struct GroupCounts {
  std::uint64_t fragments = 0, shaded = 0;
};

// How a triangle's blocks are drawn: on the SIMD path, wholly inside the framebuffer (no
// copies: the hot loop calls nothing, so its vectors stay in registers) or touching its right
// or bottom edge; or fragment by fragment on the reference path.
enum class Path { kInterior, kEdge, kScalar };

/// apply_stencil_op on stencil values held in 32-bit lanes.
HWY_INLINE hn::Vec<DUB> stencil_op(StencilOp op, hn::Vec<DUB> v, hn::Vec<DUB> ref) {
  const DUB du;
  const auto one = hn::Set(du, 1u);
  switch (op) {
    case StencilOp::kKeep: return v;
    case StencilOp::kZero: return hn::Zero(du);
    case StencilOp::kReplace: return ref;
    case StencilOp::kIncr: return hn::Min(hn::Add(v, one), hn::Set(du, 0xffu));  // clamped (GL 1.1)
    case StencilOp::kDecr: return hn::Sub(hn::Max(v, one), one);
    case StencilOp::kInvert: return hn::Xor(v, hn::Set(du, 0xffu));
    case StencilOp::kIncrWrap: return hn::And(hn::Add(v, one), hn::Set(du, 0xffu));  // modulo 256 (GL 1.4)
    case StencilOp::kDecrWrap: return hn::And(hn::Sub(v, one), hn::Set(du, 0xffu));
  }
  return v;
}

/// depth_compare's for stencil values (0 to 255) in 32-bit lanes: `ref` func `value`.
HWY_INLINE hn::Mask<DIB> stencil_compare(CompareFunc func, hn::Vec<DIB> ref, hn::Vec<DIB> value) {
  const DIB di;
  switch (func) {
    case CompareFunc::kNever: return hn::FirstN(di, 0);
    case CompareFunc::kLess: return hn::Lt(ref, value);
    case CompareFunc::kEqual: return hn::Eq(ref, value);
    case CompareFunc::kLequal: return hn::Not(hn::Gt(ref, value));  // (integer Le is newer than Highway 1.0)
    case CompareFunc::kGreater: return hn::Gt(ref, value);
    case CompareFunc::kNotequal: return hn::Not(hn::Eq(ref, value));
    case CompareFunc::kGequal: return hn::Not(hn::Lt(ref, value));
    case CompareFunc::kAlways: break;
  }
  return hn::FirstN(di, hn::Lanes(di));
}

/// Whether a draw's stencil operations can change a stencil value.
inline bool writes_stencil(const StencilState& s) {
  return s.write_mask != 0 && (s.fail != StencilOp::kKeep || s.depth_fail != StencilOp::kKeep || s.pass != StencilOp::kKeep);
}

/// fragment_ops.cpp's depth_stencil_test for the lanes `bits` of a block whose rows are
/// `depth` and `stencil`: the stencil test, then the depth test for the lanes it passes, each
/// lane's stencil value updated by the operation of its outcome (through the write mask) and
/// its depth written where both pass. Returns the lanes that pass both.
HWY_INLINE unsigned stencil_and_depth(const FragmentState& fs, VB z, unsigned bits, float* const depth[kRows],
                                      std::uint8_t* const stencil[kRows]) {
  const DF df;
  const DB db;
  const DIB di;
  const hn::Rebind<std::uint8_t, DU> d8;
  const hn::RebindToSigned<DU> dis;
  const StencilState& s = fs.stencil;
  const hn::Vec<DIB> stored = join_rows(dis, hn::PromoteTo(dis, hn::LoadU(d8, stencil[0])),
                                        hn::PromoteTo(dis, hn::LoadU(d8, stencil[kRows - 1])));
  const auto value_mask = hn::Set(di, s.value_mask);
  const MB live = block_mask(bits);
  const MB stencil_pass =
      hn::And(live, hn::RebindMask(db, stencil_compare(s.func, hn::Set(di, s.ref & s.value_mask), hn::And(stored, value_mask))));
  MB depth_pass = stencil_pass;
  if (fs.depth_test && !hn::AllFalse(db, stencil_pass)) {
    depth_pass = hn::And(stencil_pass, depth_compare(fs.depth_func, z, load_rows(df, depth)));
    if (fs.depth_write) {
      const unsigned written = block_bits(depth_pass);
      if (written) store_rows(df, z, written, depth);
    }
  }
  if (writes_stencil(s)) {
    const DUB du;
    const auto old = hn::BitCast(du, stored), ref = hn::Set(du, s.ref);
    const auto fail = hn::RebindMask(du, hn::AndNot(stencil_pass, live));
    const auto depth_fail = hn::RebindMask(du, hn::AndNot(depth_pass, stencil_pass));
    const auto pass = hn::RebindMask(du, depth_pass);
    auto next = hn::IfThenElse(fail, stencil_op(s.fail, old, ref), old);
    next = hn::IfThenElse(depth_fail, stencil_op(s.depth_fail, old, ref), next);
    next = hn::IfThenElse(pass, stencil_op(s.pass, old, ref), next);
    const auto write_mask = hn::Set(du, s.write_mask);
    next = hn::Or(hn::AndNot(write_mask, old), hn::And(next, write_mask));
    #pragma GCC unroll 4
    for (int r = 0; r < kRows; ++r) hn::StoreU(hn::DemoteTo(d8, hn::BitCast(dis, row_of(DU(), next, r))), d8, stencil[r]);
  }
  return block_bits(depth_pass);
}

// The SIMD fragment path for the covered lanes `bits` of a block: depth test, then colour;
// with the alpha test, the colour first, and depth only for the lanes it keeps (GL 1.1
// section 4.1.3: the alpha test comes before the stencil and depth tests). A smooth line's or
// point's `coverage` multiplies the colour's alpha before the alpha test sees it.
template <Path kPath>
HWY_INLINE void simd_block(const DrawJob& job, const TriSetup& t, const PixelTarget& target, TrianglePlanes& planes,
                           GroupCounts& counts, int x, int y, unsigned bits, const VD e[kRows][3], const VD b0[kRows],
                           const VD b1[kRows], VB f0, VB f1, VB z, const VB* coverage) {
  const DF df;
  const FragmentState& fs = *job.frag;
  BlockPixels g;
  open_block(job, target, x, y, kPath == Path::kInterior, g);
  unsigned passed = bits;
  Rgba color;
  if (job.plan.alpha_test && !fs.stencil.enabled && fs.depth_test) {
    // Nothing but the depth write depends on the order of the two tests here: the depth test
    // first, then the colours of the lanes it passes only, alpha-tested, and their depth
    // written (llvmpipe's early test and late write). The colours of hidden fragments of
    // alpha-tested layers drawn front to back are not computed.
    passed = block_bits(hn::And(block_mask(bits), depth_compare(fs.depth_func, z, load_rows(df, g.depth))));
    if (passed) {
      color = block_color(job, t, planes, b0, b1, f0, f1, coverage, BlockPlace{x, y, e, passed});
      passed &= alpha_bits(fs.alpha_test, job.plan.alpha_ref, color.c[3]);
      if (fs.depth_write && passed) store_rows(df, z, passed, g.depth);
    }
    counts.fragments += unsigned(std::popcount(bits));
    counts.shaded += unsigned(std::popcount(passed));
    if (passed && job.plan.writes_color) write_colors(job, color, passed, g.color);
    if constexpr (kPath == Path::kEdge) close_block(job, g);
    return;
  }
  if (job.plan.alpha_test) {  // the alpha test first (GL 1.1 section 4.1.3): it comes before the stencil test
    color = block_color(job, t, planes, b0, b1, f0, f1, coverage, BlockPlace{x, y, e, bits});
    passed &= alpha_bits(fs.alpha_test, job.plan.alpha_ref, color.c[3]);
  }
  if (fs.stencil.enabled) {
    if (passed) passed = stencil_and_depth(fs, z, passed, g.depth, g.stencil);
  } else if (fs.depth_test && passed) {
    MB live = hn::And(block_mask(passed), depth_compare(fs.depth_func, z, load_rows(df, g.depth)));
    passed = block_bits(live);
    if (fs.depth_write && passed) store_rows(df, z, passed, g.depth);
  }
  counts.fragments += unsigned(std::popcount(bits));
  counts.shaded += unsigned(std::popcount(passed));
  if (passed && job.plan.writes_color) {
    if (!job.plan.alpha_test) color = block_color(job, t, planes, b0, b1, f0, f1, coverage, BlockPlace{x, y, e, passed});
    write_colors(job, color, passed, g.color);
  }
  if constexpr (kPath == Path::kEdge) close_block(job, g);
}

// The lanes of the block at (x, y) that the scissor box and the polygon stipple (of polygons
// only) keep (fragment_ops.hpp's pixel_kept). Blocks start at multiples of their width, which divides
// 32: a row's lanes are consecutive bits of one stipple row.
HWY_INLINE unsigned kept_lanes(const DrawJob& job, const TriSetup& t, int x, int y, int lanes) {
  const DrawPlan& p = job.plan;
  const unsigned all = (1u << lanes) - 1u;
  unsigned columns = all;
  if (x < p.box_x0) columns &= ~((1u << std::min(p.box_x0 - x, lanes)) - 1u);
  if (x + lanes - 1 > p.box_x1) columns &= (1u << std::clamp(p.box_x1 - x + 1, 0, lanes)) - 1u;
  const PolygonStipple& stipple = job.frag->stipple;
  unsigned kept = 0;
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) {
    const int row = y + r;
    unsigned m = row < p.box_y0 || row > p.box_y1 ? 0u : columns;
    if (stipple.enabled && t.polygon) m &= (stipple.rows[std::size_t(row & 31)] >> (x & 31)) & all;
    kept |= m << (r * lanes);
  }
  return kept;
}

// The lanes of the block at (x, y) inside a point's box (TriSetup::box): [t.x0, t.x1] by
// [t.y0, t.y1].
HWY_INLINE unsigned box_lanes(const TriSetup& t, int x, int y, int lanes) {
  const unsigned all = (1u << lanes) - 1u;
  unsigned columns = all;
  if (x < t.x0) columns &= ~((1u << std::min(t.x0 - x, lanes)) - 1u);
  if (x + lanes - 1 > t.x1) columns &= (1u << std::clamp(t.x1 - x + 1, 0, lanes)) - 1u;
  unsigned kept = 0;
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) {
    if (y + r >= t.y0 && y + r <= t.y1) kept |= columns << (r * lanes);
  }
  return kept;
}

// The kernels' colours for the lanes `passed` of a block whose colour rows are `color`: the
// triangle's one packed colour, the byte planes' (kBlend false: opaque) or source alpha over
// the framebuffer's (kBlend true); fogged, block_color's and write_colors' in float.
template <bool kBlend>
HWY_INLINE void kernel_colors(const DrawJob& job, const TriSetup& t, TrianglePlanes& planes, unsigned passed,
                              const VD b0[kRows], const VD b1[kRows], VB f0, VB f1, std::uint32_t* const color[kRows]) {
  if (!planes.ready) set_up_planes(job, t, planes);
  if constexpr (!kBlend) {  // one colour over the triangle: no weights, no planes (never fogged)
    if (planes.uniform) return store_rows(DU(), hn::Set(DUB(), planes.uniform_bytes), passed, color);
  }
  const Weights w = perspective_weights(t, b0, b1, f0, f1);
  if (job.plan.fog) {
    Rgba c = vertex_color(t, planes, w);
    apply_fog(job.plan.fog_params, t, planes, w, c);
    return write_colors(job, c, passed, color);
  }
  if (planes.exact || planes.has_secondary) return write_colors(job, vertex_color(t, planes, w), passed, color);
  if constexpr (kBlend) {
    const Rgba src = clamped(vertex_color(t, planes, w));
    store_rows(DU(), pack_unorm8(blend_src_alpha(src, unit_colors(load_rows(DU(), color)))), passed, color);
  } else {
    store_rows(DU(), byte_plane_colors(planes, w), passed, color);
  }
}

// A block of a triangle wholly inside the framebuffer, by one of the kernels compiled for
// the usual fragment state (BlockKernel, draw_job.hpp): the same operations as simd_block's
// for that state, without reading it per block; the opaque kernels' colours from the byte
// planes. `bound`, when not null, is the block's depth bound (block_bounds): set to the
// largest depth the block holds after its depth test.
template <BlockKernel kKernel>
HWY_INLINE void kernel_block(const DrawJob& job, const TriSetup& t, const PixelTarget& target, TrianglePlanes& planes,
                             GroupCounts& counts, int x, int y, unsigned bits, const VD b0[kRows],
                             const VD b1[kRows], VB f0, VB f1, VB z, float* bound) {
  constexpr bool kLequal = kKernel == BlockKernel::kOpaqueLequal || kKernel == BlockKernel::kBlendLequal;
  constexpr bool kBlend = kernel_blends(kKernel);
  const DF df;
  const std::size_t first = std::size_t(y - target.y0) * target.stride + std::size_t(x - target.x0);
  std::uint32_t* color[kRows];
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) color[r] = target.color + first + std::size_t(r) * target.stride;
  unsigned passed = bits;
  if constexpr (kernel_tests_depth(kKernel)) {
    float* depth[kRows];
    #pragma GCC unroll 4
    for (int r = 0; r < kRows; ++r) depth[r] = target.depth + first + std::size_t(r) * target.stride;
    const VB stored = load_rows(df, depth);
    passed = block_bits(hn::And(block_mask(bits), kLequal ? hn::Le(z, stored) : hn::Lt(z, stored)));
    counts.fragments += unsigned(std::popcount(bits));
    counts.shaded += unsigned(std::popcount(passed));
    if (!passed) {
      if (bound) *bound = hn::GetLane(hn::MaxOfLanes(DB(), stored));
      return;
    }
    store_rows(df, z, passed, depth);
    if (bound) *bound = hn::GetLane(hn::MaxOfLanes(DB(), hn::IfThenElse(block_mask(passed), z, stored)));
  } else {
    (void)z, (void)bound;
    counts.fragments += unsigned(std::popcount(bits));
    counts.shaded += unsigned(std::popcount(bits));
  }
  kernel_colors<kBlend>(job, t, planes, passed, b0, b1, f0, f1, color);
}

// A block of a stencil-tested triangle wholly inside the framebuffer, by the kStencil kernel:
// simd_block's operations for its state (the stencil and depth tests, whatever their
// functions and operations; then the colours of the lanes both pass, opaque or blended by
// source alpha, unless every channel is masked), with the stencil values in 32-bit integers.
HWY_INLINE void stencil_block(const DrawJob& job, const TriSetup& t, const PixelTarget& target, TrianglePlanes& planes,
                              GroupCounts& counts, int x, int y, unsigned bits, const VD b0[kRows],
                              const VD b1[kRows], VB f0, VB f1, VB z) {
  const FragmentState& fs = *job.frag;
  const std::size_t first = std::size_t(y - target.y0) * target.stride + std::size_t(x - target.x0);
  float* depth[kRows];
  std::uint8_t* stencil[kRows];
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) {
    depth[r] = fs.depth_test ? target.depth + first + std::size_t(r) * target.stride : nullptr;
    stencil[r] = target.stencil + std::size_t(y + r) * target.stencil_stride + std::size_t(x);
  }
  const unsigned passed = stencil_and_depth(fs, z, bits, depth, stencil);
  counts.fragments += unsigned(std::popcount(bits));
  counts.shaded += unsigned(std::popcount(passed));
  if (!passed || !job.plan.writes_color) return;
  std::uint32_t* color[kRows];
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) color[r] = target.color + first + std::size_t(r) * target.stride;
  if (fs.blend.enabled) return kernel_colors<true>(job, t, planes, passed, b0, b1, f0, f1, color);
  kernel_colors<false>(job, t, planes, passed, b0, b1, f0, f1, color);
}

// The kTextured kernel's depth for the lanes `passed` of a block whose depths were `stored`:
// written where the draw writes depth, and the block's bound kept.
HWY_INLINE void textured_depth(const FragmentState& fs, VB z, VB stored, unsigned passed, float* const depth[kRows],
                               float* bound) {
  if (fs.depth_test && fs.depth_write) {
    store_rows(DF(), z, passed, depth);
    stored = hn::IfThenElse(block_mask(passed), z, stored);
  }
  if (bound) *bound = hn::GetLane(hn::MaxOfLanes(DB(), stored));
}

// A block of a triangle wholly inside the framebuffer by a textured kernel (k2D: kTextured2D,
// its sampler compiled for 2D colour textures alone): simd_block's operations for its state
// (the depth test first, the colours of the lanes it passes, the alpha test, then depth and
// colour written), block_color's for one unit. `bound`, when not null, is the block's depth
// bound (block_bounds): set to the largest depth the block holds after it is drawn.
template <bool k2D>
HWY_INLINE void textured_block(const DrawJob& job, const TriSetup& t, const PixelTarget& target, TrianglePlanes& planes,
                               GroupCounts& counts, int x, int y, unsigned bits, const VD e[kRows][3],
                               const VD b0[kRows], const VD b1[kRows], VB f0, VB f1, VB z, float* bound) {
  const DF df;
  const FragmentState& fs = *job.frag;
  const std::size_t first = std::size_t(y - target.y0) * target.stride + std::size_t(x - target.x0);
  float* depth[kRows];
  std::uint32_t* color[kRows];
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) {
    depth[r] = fs.depth_test ? target.depth + first + std::size_t(r) * target.stride : nullptr;
    color[r] = target.color + first + std::size_t(r) * target.stride;
  }
  counts.fragments += unsigned(std::popcount(bits));
  unsigned passed = bits;
  VB stored = z;
  if (fs.depth_test) {
    stored = load_rows(df, depth);
    passed = block_bits(hn::And(block_mask(bits), depth_compare(fs.depth_func, z, stored)));
  }
  if (!passed) {
    if (bound) *bound = hn::GetLane(hn::MaxOfLanes(DB(), stored));
    return;
  }
  if (!planes.ready) set_up_planes(job, t, planes);
  const Weights w = perspective_weights(t, b0, b1, f0, f1);
  const int unit = job.plan.texture_unit;
  const TexturePlan& tp = job.plan.texture[unit];
  if (job.plan.texel_bytes && !planes.has_secondary) {  // the filtered bytes are the colours
    const hn::Vec<DUB> words = sample_block_words<k2D>(job, unit, t, planes.texcoord[unit], w, x, y, e, block_mask(passed));
    if (job.plan.alpha_test) {
      const VB alpha = hn::ConvertTo(DB(), hn::BitCast(DIB(), hn::ShiftRight<24>(words)));
      passed &= alpha_byte_bits(fs.alpha_test, job.plan.alpha_ref, alpha);
    }
    counts.shaded += unsigned(std::popcount(passed));
    if (!passed) {
      if (bound) *bound = hn::GetLane(hn::MaxOfLanes(DB(), stored));
      return;
    }
    textured_depth(fs, z, stored, passed, depth, bound);
    return store_rows(DU(), words, passed, color);
  }
  // textured_color's for one unit (no GL_COMBINE, logic op or per-pixel lighting).
  const bool alpha_replaced =
      tp.env == TextureEnvMode::kReplace && tp.format != TextureFormat::kLuminance && tp.format != TextureFormat::kRgb;
  const bool exact = job.plan.exact_colors && !planes.exact && !planes.uniform && !alpha_replaced;
  Rgba c = vertex_color(t, planes, w, false);
  if (exact && !t.flat) exact_color(t, planes, w, 3, c, false);
  VB texel[4];
  sample_block<k2D>(job, unit, t, planes.texcoord[unit], w, x, y, e, block_mask(passed), texel);
  texture_env(tp, c.c, texel);
  c.clamped = false;
  if (planes.has_secondary) {
    #pragma GCC unroll 3
    for (int k = 0; k < 3; ++k) c.c[k] = hn::Add(c.c[k], varying(t, planes, w, planes.secondary[k]));
  }
  if (job.plan.fog) apply_fog(job.plan.fog_params, t, planes, w, c);
  if (job.plan.alpha_test) passed &= alpha_bits(fs.alpha_test, job.plan.alpha_ref, c.c[3]);
  counts.shaded += unsigned(std::popcount(passed));
  if (!passed) {
    if (bound) *bound = hn::GetLane(hn::MaxOfLanes(DB(), stored));
    return;
  }
  textured_depth(fs, z, stored, passed, depth, bound);
  write_colors(job, c, passed, color);
}

// Reference per-fragment operations for the covered lanes of one row (stencil, capture,
// textures...).
inline void scalar_row(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, int x, int y,
                unsigned bits, VD e0, VD e1, VF z) {
  alignas(64) double w0[kMaxLanes], w1[kMaxLanes];
  alignas(64) float zs[kMaxLanes];
  hn::Store(e0, DD(), w0);
  hn::Store(e1, DD(), w1);
  hn::StoreU(z, DF(), zs);
  for (; bits; bits &= bits - 1) {
    int lane = std::countr_zero(bits);
    scalar_fragment(job, t, ws, x + lane, y, w0[lane], w1[lane], zs[lane]);
  }
}

// Coverage, then depth (reference_raster.inl: b = w * (1 / area), z = plane_depth(b0, b1)),
// for the block whose top-left pixel is (x, y); e[r] are row r's edge values; `box`: t is a
// point's box (TriSetup::box), whose lanes box_lanes keeps; `quad`: t is a parallelogram
// (TriSetup::parallelogram), whose edges 0 and 2 are also bounded by upper[0] and upper[1];
// `bound` the block's depth bound for the depth-testing and textured kernels to keep
// (block_bounds), or null.
template <Path kPath, BlockKernel kKernel, bool kCoverage>
HWY_INLINE void block(const DrawJob& job, const TriSetup& t, TrianglePlanes& planes, WorkerScratch& ws,
                      GroupCounts& counts, int x, int y, bool interior, bool box, bool quad,
                      const VD e[kRows][3], const VD thr[3], const VD upper[2], [[maybe_unused]] float* bound) {
  const DD dd;
  const DF df;
  const int lanes = int(hn::Lanes(dd));
  unsigned bits = 0;
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) {
    auto cov = hn::And(hn::And(hn::Ge(e[r][0], thr[0]), hn::Ge(e[r][1], thr[1])), hn::Ge(e[r][2], thr[2]));
    if (quad) cov = hn::And(cov, hn::And(hn::Le(e[r][0], upper[0]), hn::Le(e[r][2], upper[1])));
    bits |= bits_of_mask(dd, cov) << (r * lanes);
  }
  if (box) bits &= box_lanes(t, x, y, lanes);  // a point's box (t.box), whose edges cover every lane
  if (!bits) return;
  if constexpr (kKernel == BlockKernel::kGeneral) {  // the kernels never mask lanes
    if (job.plan.lane_masks) {
      bits &= kept_lanes(job, t, x, y, lanes);
      if (!bits) return;
    }
  }
  // Lanes outside the framebuffer (the tile's pixels end there) are not drawn.
  if (kPath == Path::kEdge || (kPath == Path::kScalar && !interior)) {
    const int valid = job.fb->width - x;
    if (valid < lanes) {
      unsigned row = (1u << valid) - 1u;
      bits &= row | row << lanes;
    }
    for (int r = 1; r < kRows; ++r) {
      if (y + r >= job.fb->height) bits &= (1u << (r * lanes)) - 1u;
    }
    if (!bits) return;
  }
  VB coverage;
  if constexpr (kCoverage) {  // smooth lines and points (the scalar path applies it per fragment)
    coverage = block_coverage(*t.coverage, x, y, bits);
    if (!bits) return;
  }
  const VD inv_area = hn::Set(dd, t.inv_area);
  VD b0[kRows], b1[kRows];
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) b0[r] = hn::Mul(e[r][0], inv_area), b1[r] = hn::Mul(e[r][1], inv_area);
  // The weights in floats, and depth from them as reference_raster.inl's plane_depth.
  const DB db;
  const VB f0 = join_rows(df, hn::DemoteTo(df, b0[0]), hn::DemoteTo(df, b0[kRows - 1]));
  const VB f1 = join_rows(df, hn::DemoteTo(df, b1[0]), hn::DemoteTo(df, b1[kRows - 1]));
  const VB plane = hn::Add(hn::Add(hn::Set(db, t.depth.base), hn::Mul(f0, hn::Set(db, t.depth.d0))),
                           hn::Mul(f1, hn::Set(db, t.depth.d1)));
  VB z = clamp_unit(hn::Add(plane, hn::Set(db, t.offset)));  // draw.cpp's emit
  if constexpr (kPath == Path::kScalar) {
    #pragma GCC unroll 4
    for (int r = 0; r < kRows; ++r) {
      if (unsigned rb = row_bits(bits, r)) scalar_row(job, t, ws, x, y + r, rb, e[r][0], e[r][1], row_of(df, z, r));
    }
  } else if constexpr (kPath == Path::kInterior && kernel_textured(kKernel)) {
    constexpr bool k2D = kKernel == BlockKernel::kTextured2D;
    textured_block<k2D>(job, t, ws.target, planes, counts, x, y, bits, e, b0, b1, f0, f1, z, bound);
  } else if constexpr (kPath == Path::kInterior && kKernel == BlockKernel::kStencil) {
    stencil_block(job, t, ws.target, planes, counts, x, y, bits, b0, b1, f0, f1, z);
  } else if constexpr (kPath == Path::kInterior && kKernel != BlockKernel::kGeneral) {
    kernel_block<kKernel>(job, t, ws.target, planes, counts, x, y, bits, b0, b1, f0, f1, z, bound);
  } else {
    simd_block<kPath>(job, t, ws.target, planes, counts, x, y, bits, e, b0, b1, f0, f1, z,
                      kCoverage ? &coverage : nullptr);
  }
}

// The blocks of one row of blocks that a triangle's edges can cover, [first, last], counted
// in blocks from the triangle's first block column; empty when first > last. From the exact
// edge values at that column in the block row's top and bottom pixel rows and each edge's
// step a pixel right: an edge is linear, so over a block its values lie between those at its
// corners. The quotients are floating point, each widened by more than its rounding error:
// a block kept that no edge covers is tested and draws nothing, so the pixels drawn are the
// edges' (the blocks outside a sliver's or a line's box need no test).
struct RowSpan {
  int first, last;
};

// Per bound of a triangle (its three edges; a parallelogram's also edges 0 and 2 negated,
// their upper bounds as lower ones): its step a pixel right, 1 / (that step times the block
// width), and the coverage threshold.
constexpr int kMaxBounds = 5;
struct SpanEdges {
  int count;
  std::int64_t step[kMaxBounds];
  double inv_block_step[kMaxBounds];
  std::int64_t threshold[kMaxBounds];
};

HWY_INLINE RowSpan row_span(const SpanEdges& s, const std::int64_t top[kMaxBounds],
                            const std::int64_t bottom[kMaxBounds], int lanes, int blocks) {
  constexpr double kSlack = 0x1p-46;  // above a product's relative rounding error
  double first = 0.0, last = double(blocks - 1);
  #pragma GCC unroll 5
  for (int k = 0; k < kMaxBounds; ++k) {
    if (k >= s.count) break;
    const std::int64_t hi = std::max(top[k], bottom[k]), a = s.step[k], thr = s.threshold[k];
    if (a == 0) {  // the same value along the row
      if (hi < thr) return {0, -1};
      continue;
    }
    // Block i holds a pixel inside the edge where hi + a * (i * lanes + j) >= thr for a lane j.
    if (a > 0) {
      const double q = double(thr - hi - a * (lanes - 1)) * s.inv_block_step[k];
      first = std::max(first, std::ceil(q - std::fabs(q) * kSlack - kSlack));
    } else {
      const double q = double(thr - hi) * s.inv_block_step[k];
      last = std::min(last, std::floor(q + std::fabs(q) * kSlack + kSlack));
    }
  }
  if (first > last) return {0, -1};
  return {int(first), int(last)};
}

// Triangles whose box in the tile holds fewer pixels neither read nor keep the blocks' depth
// bounds: a bound left as it was stays above its block's depths (the kernels' tests only lower
// them), and keeping it costs a horizontal maximum per block, which small triangles, sharing
// their blocks with their neighbours, pay for far more often than they are hidden.
constexpr int kBoundedBlocksArea = 256;

// Triangles this many blocks wide and more find their rows' spans (row_span); narrower ones
// test every block of their box (the span costs about what testing 2 to 4 blocks does).
constexpr int kSpanBlocks = HWY_TARGET <= HWY_AVX3 ? 8 : 4;

// kCoverage: a smooth line's or point's triangle on the SIMD path (draws with them take the
// general path, never a kernel).
template <Path kPath, BlockKernel kKernel = BlockKernel::kGeneral, bool kCoverage = false>
void raster_path(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, bool interior) {
  const DD dd;
  constexpr int lanes = int(hn::MaxLanes(DD()));  // Lanes (no x86 target's vectors are scalable), a constant
  VD lane_step[3], thr[3];
  SpanEdges span;
  #pragma GCC unroll 4
  for (int e = 0; e < 3; ++e) {
    span.step[e] = -t.dy[e] * detail::kSubpixelOne;  // edge change one pixel right
    span.threshold[e] = std::int64_t(t.threshold[e]);
    lane_step[e] = hn::Mul(hn::Iota(dd, 0.0), hn::Set(dd, double(span.step[e])));
    thr[e] = hn::Set(dd, t.threshold[e]);
  }
  const bool quad = t.parallelogram;  // read once, as box
  VD upper[2] = {hn::Zero(dd), hn::Zero(dd)};
  span.count = 3;
  if (quad) {  // edges 0 and 2 bounded above: -e >= -upper
    upper[0] = hn::Set(dd, t.upper[0]), upper[1] = hn::Set(dd, t.upper[2]);
    span.count = kMaxBounds;
    span.step[3] = -span.step[0], span.threshold[3] = -std::int64_t(t.upper[0]);
    span.step[4] = -span.step[2], span.threshold[4] = -std::int64_t(t.upper[2]);
  } else {
    span.step[3] = span.step[4] = span.threshold[3] = span.threshold[4] = 0;
  }
  // Blocks start on even rows (tiles do): a row above the triangle's box or below it inside
  // the tile has no covered pixel, and rows past the framebuffer's bottom are masked.
  const int gx0 = t.x0 & ~(lanes - 1);
  const int gy0 = t.y0 & ~(kRows - 1);
  const int blocks = (t.x1 - gx0) / lanes + 1;
  TrianglePlanes planes;
  GroupCounts counts;
  // The depth-testing and textured kernels skip the blocks their bounds show hidden
  // (block_bounds), for triangles of kBoundedBlocksArea pixels and more.
  float reject = 0.0f;
  const bool bounded = kernel_textured(kKernel) || kernel_tests_depth(kKernel);
  float* const bounds =
      bounded && box_pixels(t) >= kBoundedBlocksArea ? block_bounds(job, t, ws, reject) : nullptr;
  const int blocks_per_row = kTileSize / lanes;
  const bool box = t.box;  // read once: the blocks' stores may alias t for the compiler
  std::int64_t row_start[3], row_step[3];  // exact edge values at (gx0, y); one row down
  VD group_step[3];
  #pragma GCC unroll 4
  for (int k = 0; k < 3; ++k) {
    row_start[k] = edge_at(t, k, gx0, gy0);
    row_step[k] = t.dx[k] * detail::kSubpixelOne;
    group_step[k] = hn::Set(dd, double(span.step[k] * lanes));
  }
  // Each row of blocks' span (row_span), when the triangle is wide enough for them to pay.
  const bool spans = blocks >= kSpanBlocks;
  RowSpan row_spans[kTileSize / kRows];
  if (spans) {
    for (int k = 0; k < span.count; ++k) {
      span.inv_block_step[k] = span.step[k] ? 1.0 / double(span.step[k] * lanes) : 0.0;
    }
    std::int64_t top[kMaxBounds] = {row_start[0], row_start[1], row_start[2]}, bottom[kMaxBounds];
    for (int j = 0, y = gy0; y <= t.y1; y += kRows, ++j) {
      #pragma GCC unroll 4
      for (int k = 0; k < 3; ++k) bottom[k] = top[k] + row_step[k] * (kRows - 1);
      top[3] = -top[0], top[4] = -top[2], bottom[3] = -bottom[0], bottom[4] = -bottom[2];
      row_spans[j] = row_span(span, top, bottom, lanes, blocks);
      #pragma GCC unroll 4
      for (int k = 0; k < 3; ++k) top[k] += row_step[k] * kRows;
    }
  }
  for (int j = 0, y = gy0; y <= t.y1; y += kRows, ++j) {
    const RowSpan row = spans ? row_spans[j] : RowSpan{0, blocks - 1};
    // The top row's edge values carried from block to block, the others' made from them
    // (exact integers in doubles): fewer vectors live across the loop, which AVX2's sixteen
    // registers otherwise spill.
    VD top[3];
    #pragma GCC unroll 4
    for (int k = 0; k < 3; ++k) {
      const std::int64_t at_first = row_start[k] + span.step[k] * (row.first * lanes);
      top[k] = hn::Add(hn::Set(dd, double(at_first)), lane_step[k]);
      row_start[k] += row_step[k] * kRows;
    }
    float* const row_bounds = bounds ? bounds + ((y - ws.bound.y0) / kRows) * blocks_per_row : nullptr;
    for (int i = row.first; i <= row.last; ++i) {
      const int x = gx0 + i * lanes;
      float* const bound = row_bounds ? row_bounds + (x - ws.bound.x0) / lanes : nullptr;
      // Not `*bound > reject`: a bound or a depth that is not a number hides nothing.
      if (!bound || !(*bound <= reject)) {
        VD e[kRows][3];
        #pragma GCC unroll 4
        for (int k = 0; k < 3; ++k) {
          e[0][k] = top[k];
          #pragma GCC unroll 4
          for (int r = 1; r < kRows; ++r) e[r][k] = hn::Add(top[k], hn::Set(dd, double(row_step[k] * r)));
        }
        block<kPath, kKernel, kCoverage>(job, t, planes, ws, counts, x, y, interior, box, quad, e, thr, upper, bound);
      }
      #pragma GCC unroll 4
      for (int k = 0; k < 3; ++k) top[k] = hn::Add(top[k], group_step[k]);
    }
  }
  ws.stats.fragments += counts.fragments;
  ws.stats.pixels_shaded += counts.shaded;
}

}  // namespace
}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // per-target include guard
