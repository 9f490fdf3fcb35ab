// The machine's physical limits, measured: peak single-precision FLOP/s (independent fused
// multiply-add chains in the widest SIMD the CPU has, chosen at run time by Highway) and
// memory bandwidth (a STREAM-like read and triad over arrays far larger than the caches), on 1
// thread and on every core. From them and each stage's operation counts (below), the bound
// for each stage of the fast pipeline, for docs/performance.md to set beside the measured
// rates of shadelab_micro_bench.
//
//   build/bench/micro/shadelab_machine_bench [--threads N] [--mib M]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "machine_bench.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace shadelab_machine {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// 16 independent chains of a = a * m + c: enough in flight to cover the FMA latency on every
// pipe. Returns a value that depends on every chain, so nothing is optimised away.
float FmaChains(std::size_t iterations) {
  const hn::ScalableTag<float> d;
  const auto m = hn::Set(d, 0.9999999f), c = hn::Set(d, 1e-7f);
  auto a0 = hn::Set(d, 1.00f), a1 = hn::Set(d, 1.01f), a2 = hn::Set(d, 1.02f), a3 = hn::Set(d, 1.03f);
  auto a4 = hn::Set(d, 1.04f), a5 = hn::Set(d, 1.05f), a6 = hn::Set(d, 1.06f), a7 = hn::Set(d, 1.07f);
  auto a8 = hn::Set(d, 1.08f), a9 = hn::Set(d, 1.09f), a10 = hn::Set(d, 1.10f), a11 = hn::Set(d, 1.11f);
  auto a12 = hn::Set(d, 1.12f), a13 = hn::Set(d, 1.13f), a14 = hn::Set(d, 1.14f), a15 = hn::Set(d, 1.15f);
  for (std::size_t i = 0; i < iterations; ++i) {
    a0 = hn::MulAdd(a0, m, c), a1 = hn::MulAdd(a1, m, c), a2 = hn::MulAdd(a2, m, c), a3 = hn::MulAdd(a3, m, c);
    a4 = hn::MulAdd(a4, m, c), a5 = hn::MulAdd(a5, m, c), a6 = hn::MulAdd(a6, m, c), a7 = hn::MulAdd(a7, m, c);
    a8 = hn::MulAdd(a8, m, c), a9 = hn::MulAdd(a9, m, c), a10 = hn::MulAdd(a10, m, c), a11 = hn::MulAdd(a11, m, c);
    a12 = hn::MulAdd(a12, m, c), a13 = hn::MulAdd(a13, m, c), a14 = hn::MulAdd(a14, m, c), a15 = hn::MulAdd(a15, m, c);
  }
  auto s = hn::Add(hn::Add(hn::Add(hn::Add(a0, a1), hn::Add(a2, a3)), hn::Add(hn::Add(a4, a5), hn::Add(a6, a7))),
                   hn::Add(hn::Add(hn::Add(a8, a9), hn::Add(a10, a11)), hn::Add(hn::Add(a12, a13), hn::Add(a14, a15))));
  return hn::GetLane(hn::SumOfLanes(d, s));
}

std::size_t FloatLanes() { return hn::Lanes(hn::ScalableTag<float>()); }
const char* TargetName() { return hwy::TargetName(HWY_TARGET); }

// Sums `count` floats (read bandwidth).
float ReadSum(const float* HWY_RESTRICT a, std::size_t count) {
  const hn::ScalableTag<float> d;
  const std::size_t n = hn::Lanes(d);
  auto s0 = hn::Zero(d), s1 = hn::Zero(d), s2 = hn::Zero(d), s3 = hn::Zero(d);
  std::size_t i = 0;
  for (; i + 4 * n <= count; i += 4 * n) {
    s0 = hn::Add(s0, hn::LoadU(d, a + i));
    s1 = hn::Add(s1, hn::LoadU(d, a + i + n));
    s2 = hn::Add(s2, hn::LoadU(d, a + i + 2 * n));
    s3 = hn::Add(s3, hn::LoadU(d, a + i + 3 * n));
  }
  float rest = 0.0f;
  for (; i < count; ++i) rest += a[i];
  return hn::GetLane(hn::SumOfLanes(d, hn::Add(hn::Add(s0, s1), hn::Add(s2, s3)))) + rest;
}

// a = b + s * c (STREAM's triad: two streams read, one written).
void Triad(float* HWY_RESTRICT a, const float* HWY_RESTRICT b, const float* HWY_RESTRICT c, float s,
           std::size_t count) {
  const hn::ScalableTag<float> d;
  const std::size_t n = hn::Lanes(d);
  const auto vs = hn::Set(d, s);
  std::size_t i = 0;
  for (; i + n <= count; i += n) hn::StoreU(hn::MulAdd(vs, hn::LoadU(d, c + i), hn::LoadU(d, b + i)), d, a + i);
  for (; i < count; ++i) a[i] = b[i] + s * c[i];
}

}  // namespace HWY_NAMESPACE
}  // namespace shadelab_machine
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace shadelab_machine {

HWY_EXPORT(FmaChains);
HWY_EXPORT(FloatLanes);
HWY_EXPORT(TargetName);
HWY_EXPORT(ReadSum);
HWY_EXPORT(Triad);

using Clock = std::chrono::steady_clock;

// Runs fn(thread) on `threads` threads at once, `reps` times; the median wall time in seconds.
template <typename Fn>
double median_seconds(int threads, int reps, Fn fn) {
  std::vector<double> times;
  for (int r = 0; r < reps; ++r) {
    auto t0 = Clock::now();
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(fn, t);
    fn(0);
    for (std::thread& t : pool) t.join();
    times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

volatile float sink;

double peak_flops(int threads) {
  const std::size_t iterations = 50'000'000;
  const double flops = 2.0 * 16 * double(HWY_DYNAMIC_DISPATCH(FloatLanes)()) * double(iterations) * threads;
  HWY_DYNAMIC_DISPATCH(FmaChains)(iterations / 10);  // clocks up
  double s = median_seconds(threads, 5, [&](int) { sink = HWY_DYNAMIC_DISPATCH(FmaChains)(iterations); });
  return flops / s;
}

struct Bandwidth {
  double read, triad;  // bytes per second
};

Bandwidth bandwidth(int threads, std::size_t mib) {
  const std::size_t count = (mib << 20) / sizeof(float);
  std::vector<float> a(count, 1.0f), b(count, 2.0f), c(count, 3.0f);  // touched: no page faults timed
  const std::size_t part = count / std::size_t(threads);
  auto slice = [&](int t) { return std::make_pair(part * std::size_t(t), t + 1 == threads ? count : part * std::size_t(t + 1)); };
  Bandwidth out{};
  double s = median_seconds(threads, 7, [&](int t) {
    auto [lo, hi] = slice(t);
    sink = HWY_DYNAMIC_DISPATCH(ReadSum)(b.data() + lo, hi - lo);
  });
  out.read = double(count * sizeof(float)) / s;
  s = median_seconds(threads, 7, [&](int t) {
    auto [lo, hi] = slice(t);
    HWY_DYNAMIC_DISPATCH(Triad)(a.data() + lo, b.data() + lo, c.data() + lo, 0.5f, hi - lo);
  });
  // Three streams: two read, one written (counted once, as STREAM does).
  out.triad = 3.0 * double(count * sizeof(float)) / s;
  return out;
}

// Operations per item of each stage, counted from the code of src/fast/ and src/lighting/
// (docs/performance.md explains each count). A FLOP is one float add, multiply or compare; an
// FMA counts two; a square root, reciprocal or division counts 4; pow (log2 + exp2) counts 20.
struct Stage {
  const char* name;
  const char* unit;
  double flops;  // per item
  double bytes;  // to or from memory per item, when the working set is larger than the caches
};

const Stage kStages[] = {
    // modelview (12 FMA) + projection (16 FMA) + normal matrix (9 FMA) + normalise (5 + 4)
    // + per light 76 (VP 3, |VP| 5 + 4, normalise 3, attenuation 4 + 4, N.L 5, H 3 + normalise
    // 5 + 4 + 3, N.H 5, pow 20, ambient/diffuse/specular sums 3 x 3 FMA = 18 minus shared)
    // x 8 + clamp 6; reads 24 bytes (position, normal), writes 32 (window xyz w, colour).
    {"vertices lit, 8 positional lights", "M vertices/s", 69 + 8 * 76 + 6, 56},
    // edge setup (3 edges x 5), area and its reciprocal (3 + 4), bounding box (8 compares), depth
    // and 1/w planes (2 x 8), colour gradients (4 x 8), fill-rule biases and binning (~12).
    {"triangle setup and binning", "M triangles/s", 15 + 7 + 8 + 16 + 32 + 12, 48},
    // edge functions (3 adds), depth interpolation (1 FMA) and test (1), colour (4 FMA) and
    // packing (4 mul + 4 convert); depth read and written, colour written: 12 bytes.
    {"Gouraud depth-tested fill", "G pixels/s", 3 + 2 + 1 + 8 + 8, 12},
    // the same plus per pixel normal and position interpolation (6 FMA), normalisation (5 + 4),
    // 8 lights as above without the transforms (76 each), clamp and pack.
    {"Phong fill, 8 lights", "M pixels/s", 22 + 12 + 9 + 8 * 76, 12},
};

}  // namespace shadelab_machine

int main(int argc, char** argv) {
  using namespace shadelab_machine;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  std::size_t mib = 256;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--threads" && i + 1 < argc) threads = std::max(1, std::atoi(argv[++i]));
    else if (a == "--mib" && i + 1 < argc) mib = std::size_t(std::max(16, std::atoi(argv[++i])));
    else {
      std::fprintf(stderr, "usage: shadelab_machine_bench [--threads N] [--mib M]\n");
      return 2;
    }
  }
  std::printf("SIMD: %s, %zu float lanes\n", HWY_DYNAMIC_DISPATCH(TargetName)(),
              HWY_DYNAMIC_DISPATCH(FloatLanes)());
  double f1 = peak_flops(1), fn = peak_flops(threads);
  std::printf("peak FLOP/s (FMA, single precision)  1 thread %7.1f G   %d threads %7.1f G\n", f1 / 1e9,
              threads, fn / 1e9);
  Bandwidth b1 = bandwidth(1, mib), bn = bandwidth(threads, mib);
  std::printf("memory read  (%zu MiB)               1 thread %7.1f GB/s %d threads %7.1f GB/s\n", mib,
              b1.read / 1e9, threads, bn.read / 1e9);
  std::printf("memory triad (3 x %zu MiB)           1 thread %7.1f GB/s %d threads %7.1f GB/s\n", mib,
              b1.triad / 1e9, threads, bn.triad / 1e9);
  std::printf("\nbounds per stage on %d threads: min(peak FLOP/s / FLOPs per item, triad bandwidth / bytes per item)\n",
              threads);
  std::printf("%-36s %10s %10s %12s %12s %14s\n", "stage", "FLOP/item", "B/item", "FLOP bound", "memory bound",
              "bound");
  for (const Stage& s : kStages) {
    double scale = std::strncmp(s.unit, "G", 1) == 0 ? 1e9 : 1e6;
    double by_flops = fn / s.flops / scale, by_bytes = bn.triad / s.bytes / scale;
    std::printf("%-36s %10.0f %10.0f %12.1f %12.1f %8.1f %s\n", s.name, s.flops, s.bytes, by_flops, by_bytes,
                std::min(by_flops, by_bytes), s.unit);
  }
  return 0;
}
#endif  // HWY_ONCE
