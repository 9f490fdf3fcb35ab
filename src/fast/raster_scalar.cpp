// The fast rasterizer's path for draws whose fragments need the reference's per-fragment
// operations (triangle.cpp's scalar_fragment): SIMD coverage and depth, then fragment by
// fragment (raster-inl.h, scalar_row).
// Compiled once per SIMD target (Highway); raster-inl.h says why it is a unit of its own.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fast/raster_scalar.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "fast/raster-inl.h"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {

void raster_scalar(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, bool interior) {
  expand_triangle(job, t, ws);
  raster_path<Path::kScalar>(job, t, ws, interior);
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();
