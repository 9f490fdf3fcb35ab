// Listing and forcing Highway's runtime-dispatch targets; the current one is asked of the
// dispatcher itself, so it reports what the pipeline really runs.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fast/simd_targets.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "fast/simd_targets.hpp"

#include <cctype>
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

namespace {

// Whether `name` names target `t`: Highway's own name in any case ("avx2", "SSE4"), "avx512"
// for AVX3, and "scalar" or "emu128" for the portable fallback, whichever of SCALAR and EMU128
// this Highway compiled.
bool names_target(const std::string& name, std::int64_t t) {
  std::string upper;
  for (char ch : name) upper += char(std::toupper(static_cast<unsigned char>(ch)));
  const std::string target = hwy::TargetName(t);
  if (upper == target) return true;
  if (upper == "AVX512") return target == "AVX3";
  if (upper == "SCALAR" || upper == "EMU128") return target == "SCALAR" || target == "EMU128";
  return false;
}

}  // namespace

bool force_simd_target(const std::string& name) {
  hwy::SetSupportedTargetsForTest(0);
  if (name.empty()) return true;
  for (std::int64_t t : hwy::SupportedAndGeneratedTargets()) {
    if (names_target(name, t)) {
      hwy::SetSupportedTargetsForTest(t);
      return true;
    }
  }
  return false;
}

}  // namespace shadelab::fast
#endif
