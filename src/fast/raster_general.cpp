// The fast rasterizer's general SIMD path: simd_block for every block of a triangle, with any
// fragment state the SIMD path supports (raster-inl.h).
// Compiled once per SIMD target (Highway); raster-inl.h says why it is a unit of its own.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fast/raster_general.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "fast/raster-inl.h"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {

void raster_general(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, bool interior) {
  if (interior) raster_path<Path::kInterior>(job, t, ws, true);
  else raster_path<Path::kEdge>(job, t, ws, false);
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();
