// Listing and forcing Highway's runtime-dispatch targets; the current one is asked of the
// dispatcher itself, so it reports what the pipeline really runs.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fast/simd_targets.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "fast/simd_targets.hpp"
#include "hwy/highway.h"
#include "hwy/targets.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {

const char* DispatchedTarget() { return hwy::TargetName(HWY_TARGET); }

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace shadelab::fast {

HWY_EXPORT(DispatchedTarget);

std::vector<std::string> available_simd_targets() {
  std::vector<std::string> names;
  for (std::int64_t t : hwy::SupportedAndGeneratedTargets()) names.push_back(hwy::TargetName(t));
  return names;
}

std::string current_simd_target() { return HWY_DYNAMIC_DISPATCH(DispatchedTarget)(); }

bool force_simd_target(const std::string& name) {
  hwy::SetSupportedTargetsForTest(0);
  if (name.empty()) return true;
  for (std::int64_t t : hwy::SupportedAndGeneratedTargets()) {
    if (name == hwy::TargetName(t)) {
      hwy::SetSupportedTargetsForTest(t);
      return true;
    }
  }
  return false;
}

}  // namespace shadelab::fast
#endif
