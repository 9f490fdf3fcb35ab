// The fast rasterizer's path for a smooth line's or point's triangle: simd_block with the
// primitive's coverage at each pixel centre multiplying alpha (raster-inl.h, block_coverage).
// Compiled once per SIMD target (Highway); raster-inl.h says why it is a unit of its own.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fast/raster_coverage.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "fast/raster-inl.h"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {

void raster_coverage(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, bool interior) {
  if (interior) raster_path<Path::kInterior, BlockKernel::kGeneral, true>(job, t, ws, true);
  else raster_path<Path::kEdge, BlockKernel::kGeneral, true>(job, t, ws, false);
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();
