// The fragment path's 8-bit conversions against the reference's: trunc(v * 255 +
// kJustBelowHalf) is lround(v * 255) for every float in [0, 255], and the fused-multiply-add
// quotient x / 255 of a channel read back is the division's for every byte.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>

#include "fast/draw_job.hpp"

namespace shadelab {
namespace {

TEST(Unorm8, TruncatedSumIsRoundHalfAwayForEveryFloatUpTo255) {
  EXPECT_EQ(fast::kJustBelowHalf, std::nextafter(0.5f, 0.0f));
  // lround(s) for s in [0, 255] is trunc(double(s) + 1/2): the double sum is exact where s >=
  // 2^-29, and below that it is under 1 either way. (A loop the compiler can vectorize: the
  // 1.1 billion floats take a second, not four.)
  const std::uint32_t last = std::bit_cast<std::uint32_t>(255.0f);
  std::uint32_t mismatches = 0;
  for (std::uint32_t u = 0; u <= last; ++u) {  // every non-negative float up to 255, in order
    const float s = std::bit_cast<float>(u);
    const int fast_path = static_cast<int>(s + fast::kJustBelowHalf);
    const int reference = static_cast<int>(static_cast<double>(s) + 0.5);
    mismatches += fast_path != reference;
  }
  EXPECT_EQ(mismatches, 0u);
  for (float s : {0.0f, 1e-30f, 0.5f, 1.5f, 2.5f, 127.49998f, 127.5f, 254.5f, 255.0f}) {
    EXPECT_EQ(static_cast<int>(s + fast::kJustBelowHalf), std::lround(s)) << s;
  }
}

TEST(Unorm8, TiesRoundAwayFromZero) {
  for (int k = 0; k < 255; ++k) {
    EXPECT_EQ(static_cast<int>((float(k) + 0.5f) + fast::kJustBelowHalf), k + 1) << k;
    EXPECT_EQ(static_cast<int>(std::nextafter(float(k) + 0.5f, 0.0f) + fast::kJustBelowHalf), k) << k;
  }
}

TEST(Unorm8, ByteToUnitWithFusedResidualIsTheDivision) {
  for (int x = 0; x < 256; ++x) {
    const float xf = float(x);
    const float q = xf * fast::kInv255;
    const float quotient = std::fma(std::fma(-q, 255.0f, xf), fast::kInv255, q);
    EXPECT_EQ(quotient, xf / 255.0f) << x;
  }
  int plain_product_differs = 0;  // the product alone is not enough, which is why the residual
  for (int x = 0; x < 256; ++x) plain_product_differs += float(x) * fast::kInv255 != float(x) / 255.0f;
  EXPECT_GT(plain_product_differs, 0);
}

}  // namespace
}  // namespace shadelab
