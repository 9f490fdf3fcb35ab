// Which SIMD instruction sets the fast pipeline was built for and this CPU runs, and a switch
// to force one (for tests and benchmarks comparing targets). Dispatch is otherwise automatic:
// the best target the CPU supports is used.
#pragma once

#include <string>
#include <vector>

namespace shadelab::fast {

/// Names of the compiled targets this CPU can run, best first (e.g. "AVX3", "AVX2", "SSE4").
std::vector<std::string> available_simd_targets();

/// The target the fast pipeline uses now.
std::string current_simd_target();

/// Restricts dispatch to the named target (one of available_simd_targets(), in any case, or
/// "avx512" for AVX3 and "scalar" for the portable fallback, SCALAR or EMU128); "" restores
/// the automatic choice. Returns false
/// for a name not compiled or not supported by this CPU (dispatch is then automatic). Not
/// thread-safe: call between draws.
bool force_simd_target(const std::string& name);

}  // namespace shadelab::fast
