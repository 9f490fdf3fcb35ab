// The fast rasterizer: one tile at a time, every binned triangle in submission order, each
// by the path its draw's fragment state calls for: one of the kernels of the usual state
// (here), the general SIMD path, the smooth primitives' coverage path or the reference's
// per-fragment path (raster-inl.h and the units it names); large triangles hidden behind the
// tile's depth are skipped.
// Compiled once per SIMD target (Highway), chosen at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fast/raster.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include <limits>

#include "fast/raster-inl.h"
#include "fast/raster.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

namespace {

// Triangles whose box covers at least three quarters of a tile are checked against its
// largest depth (computing it again takes about as long as drawing 16 blocks; the teapot's
// triangles of 32 x 32 pixels and more paid for it in 1% of its time and were never hidden).
constexpr int kBoundedArea = kTileSize * kTileSize * 3 / 4;

// The largest depth in the tile buffer.
float tile_max_depth(const PixelTarget& target) {
  const hn::ScalableTag<float> df;
  const std::size_t n = hn::Lanes(df);
  auto m = hn::LoadU(df, target.depth);
  for (std::size_t i = n; i < std::size_t(kTileSize) * kTileSize; i += n) m = hn::Max(m, hn::LoadU(df, target.depth + i));
  return hn::GetLane(hn::MaxOfLanes(df, m));
}

// Whether the tile's largest depth shows that no fragment of this large triangle passes the
// depth test GL_LESS (or with `lequal` GL_LEQUAL), so that it need not be rasterized in this
// tile (a draw whose fragments are counted is always rasterized). Only for draws without the
// stencil test, whose operations would count the fragments that fail.
bool behind_tile(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, bool lequal) {
  TileDepthBound& b = ws.bound;
  if (!b.on || job.counted || box_pixels(t) < kBoundedArea) return false;
  if (!b.known) {
    b.known = true;
    b.max = tile_max_depth(ws.target);
  }
  const float z = nearest_depth(t);
  return lequal ? z > b.max : z >= b.max;
}

// After a triangle is drawn: the tile's largest depth is no longer known where it wrote
// depth, and the blocks' bounds no longer hold where its test let a write raise a depth.
void depth_written(const DrawJob& job, WorkerScratch& ws) {
  const FragmentState& f = *job.frag;
  if (!f.depth_test || !f.depth_write) return;
  TileDepthBound& b = ws.bound;
  b.known = false;
  const CompareFunc func = f.depth_func;
  if (func != CompareFunc::kLess && func != CompareFunc::kLequal && func != CompareFunc::kEqual &&
      func != CompareFunc::kNever) {
    b.blocks_ready = false;
    b.initial = std::numeric_limits<float>::infinity();
  }
}

// A triangle drawn by a kernel, unless its tile's depth bound hides it.
template <BlockKernel kKernel>
void raster_kernel(const DrawJob& job, const TriSetup& t, WorkerScratch& ws) {
  if constexpr (!kernel_tests_depth(kKernel)) {
    return raster_path<Path::kInterior, kKernel>(job, t, ws, true);
  } else {
    if (behind_tile(job, t, ws, kKernel == BlockKernel::kOpaqueLequal || kKernel == BlockKernel::kBlendLequal)) return;
    raster_path<Path::kInterior, kKernel>(job, t, ws, true);
    depth_written(job, ws);
  }
}

// A triangle drawn by a textured kernel: hidden behind its tile's depth bound (alpha-tested
// layers drawn front to back), or drawn.
template <BlockKernel kKernel>
void raster_textured(const DrawJob& job, const TriSetup& t, WorkerScratch& ws) {
  const FragmentState& f = *job.frag;
  const bool less = f.depth_func == CompareFunc::kLess, lequal = f.depth_func == CompareFunc::kLequal;
  if (f.depth_test && (less || lequal) && behind_tile(job, t, ws, lequal)) return;
  raster_path<Path::kInterior, kKernel>(job, t, ws, true);
  depth_written(job, ws);
}

void raster_triangle(const DrawJob& job, const TriSetup& t, WorkerScratch& ws) {
  const int lanes = int(hn::Lanes(DD()));
  const bool interior = (t.x1 & ~(lanes - 1)) + lanes <= job.fb->width &&
                        (t.y1 & ~(kRows - 1)) + kRows <= job.fb->height;
  if (job.plan.scalar_fragments) {
    raster_scalar(job, t, ws, interior);  // its tile keeps no depth bounds (draw_tile)
  } else if (interior) {
    switch (job.plan.kernel) {
      case BlockKernel::kOpaqueLess: return raster_kernel<BlockKernel::kOpaqueLess>(job, t, ws);
      case BlockKernel::kOpaqueLequal: return raster_kernel<BlockKernel::kOpaqueLequal>(job, t, ws);
      case BlockKernel::kBlendLess: return raster_kernel<BlockKernel::kBlendLess>(job, t, ws);
      case BlockKernel::kBlendLequal: return raster_kernel<BlockKernel::kBlendLequal>(job, t, ws);
      case BlockKernel::kOpaque: return raster_kernel<BlockKernel::kOpaque>(job, t, ws);
      case BlockKernel::kBlend: return raster_kernel<BlockKernel::kBlend>(job, t, ws);
      case BlockKernel::kTextured: return raster_textured<BlockKernel::kTextured>(job, t, ws);
      case BlockKernel::kTextured2D: return raster_textured<BlockKernel::kTextured2D>(job, t, ws);
      case BlockKernel::kStencil:
        raster_path<Path::kInterior, BlockKernel::kStencil>(job, t, ws, true);
        return depth_written(job, ws);
      case BlockKernel::kGeneral: break;
    }
    raster_general(job, t, ws, true);
    depth_written(job, ws);
  } else {  // in a tile drawn in place, whose blocks' bounds follow its depth all the same
    raster_general(job, t, ws, false);
    depth_written(job, ws);
  }
}

// Before entry i of a tile's bin is set up: the triangle records of the entry 8 ahead and the
// vertices of the entry 4 ahead are asked for (prefetch_setup), so that their loads overlap
// the rasterizing of the entries before them.
HWY_INLINE void prefetch_ahead(const DrawJob& job, int c, const std::vector<std::uint32_t>& bin, std::size_t i) {
  constexpr std::size_t kRecords = 8, kVertices = 4;
  if (i + kRecords < bin.size()) prefetch_setup(job, c, bin[i + kRecords], false);
  if (i + kVertices < bin.size()) prefetch_setup(job, c, bin[i + kVertices], true);
  if (i == 0) {  // the first entries had no one to ask for them
    for (std::size_t k = 1; k < std::min(kRecords, bin.size()); ++k) prefetch_setup(job, c, bin[k], false);
  }
}

// A tile of a draw with smooth lines or points: their triangles take the coverage path, the
// others raster_triangle. Out of line, so that RasterTile's own loop (the triangles' hot
// path, raster_triangle inlined) is compiled as it is without it.
[[gnu::noinline]] void raster_tile_coverage(const DrawJob& job, int tile, WorkerScratch& ws) {
  const int tx = (tile % job.tiles_x) * kTileSize, ty = (tile / job.tiles_x) * kTileSize;
  const int lanes = int(hn::Lanes(DD()));
  TriSetup t;
  for (int c = 0; c < job.chunk_count; ++c) {
    const std::vector<std::uint32_t>& bin = job.chunks[std::size_t(c)].bins[std::size_t(tile)];
    for (std::size_t i = 0; i < bin.size(); ++i) {
      prefetch_ahead(job, c, bin, i);
      const std::uint32_t entry = bin[i];
      if (!setup_triangle(job, c, entry, tx, ty, t)) continue;
      if (!t.coverage || job.plan.scalar_fragments) {
        raster_triangle(job, t, ws);
        continue;
      }
      const bool interior = (t.x1 & ~(lanes - 1)) + lanes <= job.fb->width &&
                            (t.y1 & ~(kRows - 1)) + kRows <= job.fb->height;
      raster_coverage(job, t, ws, interior);
      depth_written(job, ws);
    }
  }
}

}  // namespace

void RasterTile(const DrawJob& job, int tile, WorkerScratch& ws) {
  if (job.plan.coverage) return raster_tile_coverage(job, tile, ws);
  const int tx = (tile % job.tiles_x) * kTileSize, ty = (tile / job.tiles_x) * kTileSize;
  TriSetup t;
  for (int c = 0; c < job.chunk_count; ++c) {
    const std::vector<std::uint32_t>& bin = job.chunks[std::size_t(c)].bins[std::size_t(tile)];
    for (std::size_t i = 0; i < bin.size(); ++i) {
      prefetch_ahead(job, c, bin, i);
      if (setup_triangle(job, c, bin[i], tx, ty, t)) raster_triangle(job, t, ws);
    }
  }
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace shadelab::fast {

HWY_EXPORT(RasterTile);

void raster_tile(const DrawJob& job, int tile, WorkerScratch& ws) {
  HWY_DYNAMIC_DISPATCH(RasterTile)(job, tile, ws);
}

}  // namespace shadelab::fast
#endif
