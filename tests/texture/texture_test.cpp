// Texture sampling on tiny synthetic textures: nearest and bilinear values worked out by hand,
// wrap modes (mirrored repeat, clamp to border) and the border colour, 1D textures,
// completeness with base and maximum levels, mipmap generation, llvmpipe's level of detail
// (rho^2, its level choice, the bias and the LOD clamps), environment modes.
#include <gtest/gtest.h>

#include "shadelab/texture.hpp"

namespace shadelab {
namespace {

// 2x2 texture: texels (0,0)=0, (1,0)=100, (0,1)=200, (1,1)=255 in red; alpha 255.
Texture two_by_two(TextureFilter filter, TextureWrap wrap) {
  Texture t;
  TextureLevel l{2, 2, {0, 0, 0, 255, 100, 0, 0, 255, 200, 0, 0, 255, 255, 0, 0, 255}};
  t.levels.push_back(l);
  t.min_filter = t.mag_filter = filter;
  t.wrap_s = t.wrap_t = wrap;
  return t;
}

// rho2: the squared scale factor (0.25: magnified twice).
float red_at(const Texture& t, float s, float tt, float rho2 = 0.25f) {
  return sample_texture(t, {s, tt, 0.0f}, rho2).r * 255.0f;
}

TEST(Texture, NearestPicksTheTexelContainingThePoint) {
  Texture t = two_by_two(TextureFilter::kNearest, TextureWrap::kRepeat);
  EXPECT_NEAR(red_at(t, 0.25f, 0.25f), 0.0f, 1e-3);
  EXPECT_NEAR(red_at(t, 0.75f, 0.25f), 100.0f, 1e-3);
  EXPECT_NEAR(red_at(t, 0.25f, 0.75f), 200.0f, 1e-3);
  EXPECT_NEAR(red_at(t, 1.25f, 0.75f), 200.0f, 1e-3);  // repeat
}

TEST(Texture, BilinearBlendsTheFourNearestTexels) {
  Texture t = two_by_two(TextureFilter::kLinear, TextureWrap::kClampToEdge);
  // Centre (0.5, 0.5): u = v = 1, equal weights (128 / 256) in llvmpipe's 8-bit filter, each
  // lerp rounded to a byte: rows 50 and 228, then 139 (the mean of the four is 138.75).
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f), 139.0f, 1e-3);
  // (0.5, 0.25): vv = 0 -> row 0 only, halfway: (0 + 100) / 2.
  EXPECT_NEAR(red_at(t, 0.5f, 0.25f), 50.0f, 1e-3);
  // (0.375, 0.25): u = 0.75, uu = 0.25 -> 0.75 * 0 + 0.25 * 100.
  EXPECT_NEAR(red_at(t, 0.375f, 0.25f), 25.0f, 1e-3);
}

// llvmpipe's 8-bit filter (GL_REPEAT and GL_CLAMP_TO_EDGE): positions in 256ths of a texel,
// every lerp rounded to a byte, halves up; the other wrap modes filter in float.
TEST(Texture, EightBitFilteringForRepeatAndClampToEdge) {
  // 2x1: red 10 and 11. Half-way (s = 0.5) is 10.5: 11 in 8 bits, 10.5 in float (GL_CLAMP).
  Texture t;
  t.levels.push_back({2, 1, {10, 0, 0, 255, 11, 0, 0, 255}});
  t.min_filter = t.mag_filter = TextureFilter::kLinear;
  t.wrap_s = t.wrap_t = TextureWrap::kClampToEdge;
  EXPECT_TRUE(eight_bit_filtering(t));
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f), 11.0f, 1e-3);
  t.wrap_s = TextureWrap::kClamp;
  EXPECT_FALSE(eight_bit_filtering(t));
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f), 10.5f, 1e-3);
  t.wrap_s = TextureWrap::kRepeat;
  t.wrap_t = TextureWrap::kMirroredRepeat;
  EXPECT_FALSE(eight_bit_filtering(t));
  t.depth = true;
  t.wrap_t = TextureWrap::kRepeat;
  EXPECT_FALSE(eight_bit_filtering(t));  // depth textures: compared in float
  t.depth = false;
  t.wide = true;
  EXPECT_FALSE(eight_bit_filtering(t));  // 16-bit components: llvmpipe filters them in float

  // 3x1 (not a power of two), red 0, 90, 180, repeated: the position's fraction of the row
  // (lp_build_coord_repeat_npot_linear_int). s = 0.05: 0.15 texels, less half a texel is
  // -0.35, so texel 2 (180) and texel 0 (0), weight round(0.65 * 256) = 166: 180 + round(166
  // (0 - 180) / 256) = 180 - 117 = 63.
  Texture n;
  n.levels.push_back({3, 1, {0, 0, 0, 255, 90, 0, 0, 255, 180, 0, 0, 255}});
  n.min_filter = n.mag_filter = TextureFilter::kLinear;
  EXPECT_NEAR(red_at(n, 0.05f, 0.5f), 63.0f, 1e-3);
  EXPECT_NEAR(red_at(n, 1.05f, 0.5f), 63.0f, 1e-3);
  // s = 0.5: texel 1 exactly (weight 0 to texel 2).
  EXPECT_NEAR(red_at(n, 0.5f, 0.5f), 90.0f, 1e-3);
}

TEST(Texture, RepeatWrapsAcrossTheEdgeWhenFiltering) {
  Texture t = two_by_two(TextureFilter::kLinear, TextureWrap::kRepeat);
  // s = 0 on row 0: uu = -0.5 -> texels i = -1 (wraps to 1: 100) and 0 (0), half each.
  EXPECT_NEAR(red_at(t, 0.0f, 0.25f), 50.0f, 1e-3);
}

TEST(Texture, ClampBlendsWithTheBorderColour) {
  Texture t = two_by_two(TextureFilter::kLinear, TextureWrap::kClamp);
  // s = 0: half the border (by default (0, 0, 0, 0)) and half texel 0 -> alpha 0.5.
  EXPECT_NEAR(sample_texture(t, {0.0f, 0.25f, 0.0f}, 0.25f).a, 0.5f, 1e-6);
  t.border_color = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
  // Red: half of 255 (border) and half of 0 (texel 0).
  EXPECT_NEAR(red_at(t, 0.0f, 0.25f), 127.5f, 1e-3);
  Texture e = two_by_two(TextureFilter::kLinear, TextureWrap::kClampToEdge);
  EXPECT_NEAR(sample_texture(e, {0.0f, 0.25f, 0.0f}, 0.25f).a, 1.0f, 1e-6);
}

TEST(Texture, OneDimensionalTexturesIgnoreT) {
  Texture t;
  t.dimensions = 1;
  t.levels.push_back({2, 1, {0, 0, 0, 255, 200, 0, 0, 255}});
  t.min_filter = t.mag_filter = TextureFilter::kLinear;
  t.wrap_s = TextureWrap::kClampToEdge;
  t.wrap_t = TextureWrap::kClamp;  // would blend in the border for a 2D texture of one row
  t.border_color = glm::vec4(1.0f);
  EXPECT_NEAR(red_at(t, 0.5f, 0.0f), 100.0f, 1e-3);
  EXPECT_NEAR(red_at(t, 0.5f, 7.3f), 100.0f, 1e-3);
  EXPECT_NEAR(red_at(t, 0.375f, -2.0f), 50.0f, 1e-3);
  // rho^2 from s alone: 2 texels per pixel across.
  EXPECT_FLOAT_EQ(texture_rho2(t, {0.5f, 3.0f, 0.25f, 9.0f}), 1.0f);
}

TEST(Texture, RhoIsTheLargerSquaredFootprintInTexels) {
  Texture t = two_by_two(TextureFilter::kLinear, TextureWrap::kRepeat);
  // x: (0.5 * 2, 0.25 * 2) -> 1 + 0.25; y: (0, 1.5 * 2) -> 9.
  EXPECT_FLOAT_EQ(texture_rho2(t, {0.5f, 0.25f, 0.0f, 1.5f}), 9.0f);
}

TEST(Texture, CompletenessNeedsEveryMipLevel) {
  Texture t = two_by_two(TextureFilter::kLinear, TextureWrap::kRepeat);
  EXPECT_TRUE(t.complete());
  t.min_filter = TextureFilter::kLinearMipmapLinear;
  EXPECT_FALSE(t.complete());
  generate_mipmaps(t);
  ASSERT_EQ(t.levels.size(), 2u);
  EXPECT_TRUE(t.complete());
  // The 1x1 level is the rounded mean: (0 + 100 + 200 + 255 + 2) / 4 = 139.
  EXPECT_EQ(t.levels[1].rgba[0], 139);
}

TEST(Texture, MipmapLevelChoiceIsLlvmpipes) {
  // 4x4 level 0 all red 40, 2x2 level 1 all 120, 1x1 level 2 all 240: the level is visible.
  Texture t;
  t.levels = {{4, 4, std::vector<std::uint8_t>(64, 40)}, {2, 2, std::vector<std::uint8_t>(16, 120)},
              {1, 1, std::vector<std::uint8_t>(4, 240)}};
  t.min_filter = TextureFilter::kNearestMipmapNearest;
  t.mag_filter = TextureFilter::kNearest;
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 0.25f), 40, 1e-3);    // magnified: level 0
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1.9f), 40, 1e-3);     // lambda 0.46 rounds to level 0
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 2.0f), 120, 1e-3);    // lambda 0.5 rounds up: level 1
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 7.9f), 120, 1e-3);    // lambda 1.49: level 1
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 8.0f), 240, 1e-3);    // lambda 1.5: level 2
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1e9f), 240, 1e-3);    // clamped to the last level
  // Trilinear: lambda = 0.5 fast_log2(rho2), linear between powers of two: rho2 = 6 gives
  // 0.5 (2 - 1 + 1.5) = 1.25, levels 1 and 2 weighed 0.75 and 0.25.
  t.min_filter = TextureFilter::kNearestMipmapLinear;
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 6.0f), 0.75f * 120 + 0.25f * 240, 1e-3);
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 8.0f), 0.5f * 120 + 0.5f * 240, 1e-3);
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1.5f), 0.75f * 40 + 0.25f * 120, 1e-3);  // lambda 0.25
}

TEST(Texture, MinificationStartsAtRhoOneForEveryFilterPair) {
  // GL 1.1 puts the switch at lambda 0.5 for a linear mag filter with a *_MIPMAP_NEAREST min
  // filter; llvmpipe (and GL 3.1 onwards) at 0: a nearest min filter already at rho2 = 1.2.
  Texture t = two_by_two(TextureFilter::kLinear, TextureWrap::kRepeat);
  t.min_filter = TextureFilter::kNearestMipmapNearest;
  generate_mipmaps(t);
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1.0f), 139.0f, 1e-3);  // magnified: bilinear, level 0
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1.2f), 255.0f, 1e-3);   // nearest, level 0: texel (1, 1)
}

// 4x1 texture, red 0, 80, 160, 240: mirrored repeat runs 0..3 then 3..0.
Texture four_wide(TextureFilter filter, TextureWrap wrap) {
  Texture t;
  t.levels.push_back({4, 1, {0, 0, 0, 255, 80, 0, 0, 255, 160, 0, 0, 255, 240, 0, 0, 255}});
  t.min_filter = t.mag_filter = filter;
  t.wrap_s = wrap;
  t.wrap_t = TextureWrap::kRepeat;
  return t;
}

TEST(Texture, MirroredRepeatReflectsEveryOtherRepeat) {
  Texture t = four_wide(TextureFilter::kNearest, TextureWrap::kMirroredRepeat);
  EXPECT_NEAR(red_at(t, 0.1f, 0.5f), 0.0f, 1e-3);
  EXPECT_NEAR(red_at(t, 1.1f, 0.5f), 240.0f, 1e-3);   // mirrored: 0.9 -> texel 3
  EXPECT_NEAR(red_at(t, 1.4f, 0.5f), 160.0f, 1e-3);   // 0.6 -> texel 2
  EXPECT_NEAR(red_at(t, 2.1f, 0.5f), 0.0f, 1e-3);     // repeated again
  EXPECT_NEAR(red_at(t, -0.1f, 0.5f), 0.0f, 1e-3);    // |-0.1| -> texel 0
  EXPECT_NEAR(red_at(t, -0.9f, 0.5f), 240.0f, 1e-3);  // 0.9 -> texel 3
  EXPECT_NEAR(red_at(t, 1.0f, 0.5f), 240.0f, 1e-3);   // the edge: the last texel
  // Linear across the mirror at s = 1: texel 3 on both sides, whatever the weight.
  Texture l = four_wide(TextureFilter::kLinear, TextureWrap::kMirroredRepeat);
  EXPECT_NEAR(red_at(l, 1.0f, 0.5f), 240.0f, 1e-3);
  EXPECT_NEAR(red_at(l, 1.05f, 0.5f), 240.0f, 1e-3);  // 0.95: u = 3.8 - 0.5, texels 3 and 3
  // 1.25 -> 0.75: u = 3, uu = 2.5: texels 2 and 3 half and half.
  EXPECT_NEAR(red_at(l, 1.25f, 0.5f), 200.0f, 1e-3);
  // Near 0 the first texel is taken twice, as with clamp to edge.
  EXPECT_NEAR(red_at(l, 0.05f, 0.5f), 0.0f, 1e-3);
}

TEST(Texture, ClampToBorderTakesTheBorderColourOutside) {
  Texture t = four_wide(TextureFilter::kNearest, TextureWrap::kClampToBorder);
  t.border_color = glm::vec4(1.0f, 0.0f, 0.0f, 0.5f);
  EXPECT_NEAR(red_at(t, 0.9f, 0.5f), 240.0f, 1e-3);
  EXPECT_NEAR(red_at(t, 1.01f, 0.5f), 255.0f, 1e-3);  // nearest reads the border, unlike GL_CLAMP
  EXPECT_NEAR(red_at(t, -0.01f, 0.5f), 255.0f, 1e-3);
  EXPECT_NEAR(red_at(t, 1e6f, 0.5f), 255.0f, 1e-3);
  EXPECT_NEAR(sample_texture(t, {-3.0f, 0.5f, 0.0f}, 0.25f).a, 0.5f, 1e-6);
  // Linear: at s = 1 half the last texel and half the border; inside the texels alone.
  Texture l = four_wide(TextureFilter::kLinear, TextureWrap::kClampToBorder);
  l.border_color = glm::vec4(1.0f);
  EXPECT_NEAR(red_at(l, 1.0f, 0.5f), 0.5f * 240.0f + 0.5f * 255.0f, 1e-3);
  EXPECT_NEAR(red_at(l, 0.5f, 0.5f), 120.0f, 1e-3);
  EXPECT_NEAR(red_at(l, 1.125f, 0.5f), 255.0f, 1e-3);  // u = 4.5, uu = 4: border only
  // GL_CLAMP at the same s = 1.125 is clamped to 1 first: half border, half texel.
  Texture c = four_wide(TextureFilter::kLinear, TextureWrap::kClamp);
  c.border_color = glm::vec4(1.0f);
  EXPECT_NEAR(red_at(c, 1.125f, 0.5f), 0.5f * 240.0f + 0.5f * 255.0f, 1e-3);
}

// A 4x4 chain whose levels are flat reds 40, 120, 240 (level 0 to 2).
Texture flat_chain(TextureFilter min) {
  Texture t;
  t.levels = {{4, 4, std::vector<std::uint8_t>(64, 40)}, {2, 2, std::vector<std::uint8_t>(16, 120)},
              {1, 1, std::vector<std::uint8_t>(4, 240)}};
  t.min_filter = min;
  t.mag_filter = TextureFilter::kNearest;
  return t;
}

TEST(Texture, BaseAndMaxLevelLimitTheLevelsSampled) {
  Texture t = flat_chain(TextureFilter::kNearestMipmapNearest);
  t.base_level = 1;
  EXPECT_TRUE(t.complete());
  EXPECT_EQ(t.last_level(), 2);
  // Magnified: the base level. rho2 is measured in the base level's texels.
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 0.25f), 120, 1e-3);
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 4.0f), 240, 1e-3);  // lambda 1: base + 1
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1e9f), 240, 1e-3);
  t.max_level = 1;
  EXPECT_EQ(t.last_level(), 1);
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1e9f), 120, 1e-3);
  // A base level of 1x1: one level is a whole chain; levels below the base need not exist.
  Texture one = flat_chain(TextureFilter::kLinearMipmapLinear);
  one.levels[0] = {};
  one.levels[1] = {};
  one.base_level = 2;
  EXPECT_TRUE(one.complete());
  EXPECT_NEAR(red_at(one, 0.3f, 0.8f, 50.0f), 240, 1e-3);
  // Max level below the base: incomplete with a mipmap filter, complete without one.
  t.base_level = 2;
  t.max_level = 1;
  EXPECT_FALSE(t.complete());
  t.min_filter = TextureFilter::kLinear;
  EXPECT_TRUE(t.complete());
  // A missing level between base and max makes the chain incomplete; max_level can end it
  // before the gap.
  Texture gap = flat_chain(TextureFilter::kNearestMipmapLinear);
  gap.levels.pop_back();
  EXPECT_FALSE(gap.complete());
  gap.max_level = 1;
  EXPECT_TRUE(gap.complete());
  EXPECT_FALSE(Texture{}.complete());
}

TEST(Texture, LodBiasAndClampsMoveTheLevel) {
  Texture t = flat_chain(TextureFilter::kNearestMipmapNearest);
  // No adjustment: llvmpipe's rho^2 path, lambda 0.5 at rho2 = 2 already level 1.
  EXPECT_FALSE(texture_lod(t, 0.0f).adjusted);
  // A bias of +1 at rho2 = 1 (lambda 0): lambda 1, level 1; the bias turns magnification
  // into minification (nearest within the level, the min filter's).
  t.lod_bias = 1.0f;
  EXPECT_TRUE(texture_lod(t, 0.0f).adjusted);
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1.0f), 120, 1e-3);
  // The unit's bias adds to it: 1 + 1 = 2.
  EXPECT_NEAR(sample_texture(t, {0.5f, 0.5f, 0.0f}, 1.0f, 1.0f).r * 255.0f, 240, 1e-3);
  // -1 + 1: back to lambda 0, magnified.
  EXPECT_NEAR(sample_texture(t, {0.5f, 0.5f, 0.0f}, 1.0f, -1.0f).r * 255.0f, 40, 1e-3);
  // Adjusted lambdas round half to even: lambda 0.5 (rho2 = 1, bias 0.5) stays at level 0.
  t.lod_bias = 0.5f;
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1.0f), 40, 1e-3);
  t.lod_bias = 1.5f;  // 1.5 rounds to 2
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1.0f), 240, 1e-3);
  // The sum is clamped to GL_MAX_TEXTURE_LOD_BIAS; each part quantized to 1/256.
  t.lod_bias = 100.0f;
  EXPECT_EQ(texture_lod(t, 100.0f).bias, kMaxTextureLodBias);
  t.lod_bias = 0.3f;
  EXPECT_EQ(texture_lod(t, 0.0f).bias, 77.0f / 256.0f);
  t.lod_bias = 0.0f;
  // MIN_LOD 1: never the base level, even magnified (lambda clamped to 1 > 0: minified).
  t.min_lod = 1.0f;
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 0.01f), 120, 1e-3);
  // MAX_LOD 1: never past level 1.
  t.min_lod = -1000.0f;
  t.max_lod = 1.0f;
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1e9f), 120, 1e-3);
  // MAX_LOD 0: magnified everywhere, the mag filter on the base level.
  t.max_lod = 0.0f;
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1e9f), 40, 1e-3);
  // Trilinear with a clamp: lambda = min(0.5 fast_log2(64), 1.25) = 1.25 -> levels 1 and 2.
  Texture l = flat_chain(TextureFilter::kNearestMipmapLinear);
  l.max_lod = 1.25f;
  EXPECT_NEAR(red_at(l, 0.5f, 0.5f, 64.0f), 0.75f * 120 + 0.25f * 240, 1e-3);
  EXPECT_FLOAT_EQ(adjusted_lod(64.0f, texture_lod(l, 0.0f)), 1.25f);
  EXPECT_FLOAT_EQ(adjusted_lod(6.0f, texture_lod(l, 0.5f)), 1.25f);  // 1.25 + 0.5, clamped to 1.25
}

TEST(Texture, ThreeDimensionalTexturesFilterTrilinearly) {
  // 2x2x2: image 0 red 0 everywhere, image 1 red 200; (1, 1, 1) red 100 instead.
  Texture t;
  t.dimensions = 3;
  TextureLevel l{2, 2, std::vector<std::uint8_t>(32, 0), 2};
  for (int i = 4; i < 8; ++i) l.rgba[std::size_t(i) * 4] = 200;
  l.rgba[7 * 4] = 100;
  t.levels.push_back(l);
  t.min_filter = t.mag_filter = TextureFilter::kLinear;
  t.wrap_s = t.wrap_t = t.wrap_r = TextureWrap::kClampToEdge;
  EXPECT_TRUE(t.complete());
  auto red = [&](float s, float tt, float r) { return sample_texture(t, {s, tt, r}, 0.25f).r * 255.0f; };
  EXPECT_NEAR(red(0.25f, 0.25f, 0.25f), 0.0f, 1e-3);
  EXPECT_NEAR(red(0.25f, 0.25f, 0.75f), 200.0f, 1e-3);
  EXPECT_NEAR(red(0.75f, 0.75f, 0.75f), 100.0f, 1e-3);
  EXPECT_NEAR(red(0.25f, 0.25f, 0.5f), 100.0f, 1e-3);  // halfway between the images
  // Centre: image 1's bilinear mean (200 * 3 + 100) / 4 = 175, then half of it, 87.5, which
  // the 8-bit filter rounds up.
  EXPECT_NEAR(red(0.5f, 0.5f, 0.5f), 88.0f, 1e-3);
  t.min_filter = t.mag_filter = TextureFilter::kNearest;
  EXPECT_NEAR(red(0.9f, 0.9f, 0.6f), 100.0f, 1e-3);
  t.wrap_r = TextureWrap::kClampToBorder;
  t.border_color = glm::vec4(1.0f);
  EXPECT_NEAR(red(0.9f, 0.9f, 1.2f), 255.0f, 1e-3);
  // rho^2 adds the r difference in the depth's texels last: (1 + 0) + (0.5 * 2)^2 = 2.
  EXPECT_FLOAT_EQ(texture_rho2(t, {0.5f, 0.0f, 0.0f, 0.0f, 0.5f, 0.0f}), 2.0f);
  // A mipmap chain halves the depth too: 2x2x2 then 1x1x1.
  t.min_filter = TextureFilter::kLinearMipmapLinear;
  EXPECT_FALSE(t.complete());
  t.levels.push_back({1, 1, std::vector<std::uint8_t>(4, 9), 2});
  EXPECT_FALSE(t.complete());
  t.levels[1].depth = 1;
  EXPECT_TRUE(t.complete());
}

TEST(Texture, EnvironmentModes) {
  glm::vec4 frag(0.5f, 0.5f, 1.0f, 0.8f), tex(0.2f, 0.4f, 0.6f, 0.5f), env(1, 0, 0, 1);
  glm::vec4 m = apply_texture_env(TextureEnvMode::kModulate, TextureFormat::kRgba, frag, tex, env);
  EXPECT_NEAR(m.r, 0.1f, 1e-6);
  EXPECT_NEAR(m.a, 0.4f, 1e-6);
  glm::vec4 r = apply_texture_env(TextureEnvMode::kReplace, TextureFormat::kRgb, frag, tex, env);
  EXPECT_NEAR(r.g, 0.4f, 1e-6);
  EXPECT_NEAR(r.a, 0.8f, 1e-6);  // an RGB texture keeps the fragment's alpha
  glm::vec4 d = apply_texture_env(TextureEnvMode::kDecal, TextureFormat::kRgba, frag, tex, env);
  EXPECT_NEAR(d.r, 0.5f * 0.5f + 0.2f * 0.5f, 1e-6);
  EXPECT_NEAR(d.a, 0.8f, 1e-6);
  glm::vec4 b = apply_texture_env(TextureEnvMode::kBlend, TextureFormat::kRgba, frag, tex, env);
  EXPECT_NEAR(b.r, 0.5f * 0.8f + 1.0f * 0.2f, 1e-6);
  EXPECT_NEAR(b.g, 0.5f * 0.6f, 1e-6);
  // GL_ADD: colours summed and saturated; an RGBA texture's alpha modulates.
  glm::vec4 a = apply_texture_env(TextureEnvMode::kAdd, TextureFormat::kRgba, frag, tex, env);
  EXPECT_NEAR(a.r, 0.7f, 1e-6);
  EXPECT_EQ(a.b, 1.0f);
  EXPECT_NEAR(a.a, 0.4f, 1e-6);
}

// GL 1.3's GL_COMBINE: the functions of table 3.24 over their sources and operands, the
// scales and clamps, the dot products and the crossbar's other units.
TEST(Texture, CombineEnvironment) {
  const glm::vec4 texels[kMaxTextureUnits] = {{0.2f, 0.4f, 0.6f, 0.5f}, {0.9f, 0.1f, 0.5f, 0.25f}, {}, {}};
  const CombineInputs in{texels, 0, {1.0f, 0.5f, 0.0f, 0.75f}, {0.3f, 0.3f, 0.3f, 1.0f}, {0.5f, 0.6f, 0.7f, 0.8f}};
  TextureCombine c;  // the defaults: texture times previous, colour and alpha
  glm::vec4 v = apply_texture_combine(c, in);
  EXPECT_NEAR(v.r, 0.1f, 1e-6);
  EXPECT_NEAR(v.a, 0.4f, 1e-6);
  c.rgb = CombineFunction::kAddSigned;  // 0.2 + 0.5 - 0.5, times 4
  c.rgb_scale = 4.0f;
  v = apply_texture_combine(c, in);
  EXPECT_NEAR(v.r, 0.8f, 1e-6);
  EXPECT_EQ(v.g, 1.0f);  // (0.4 + 0.6 - 0.5) * 4 clamped
  c = TextureCombine{};
  c.rgb = CombineFunction::kInterpolate;  // texture * constant.a + previous * (1 - constant.a)
  c.rgb_operand[2] = CombineOperand::kSrcAlpha;
  v = apply_texture_combine(c, in);
  EXPECT_NEAR(v.b, 0.6f * 0.75f + 0.7f * 0.25f, 1e-6);
  c = TextureCombine{};
  c.rgb = CombineFunction::kSubtract;  // primary - texture 1 (the crossbar), clamped at 0
  c.rgb_source[0] = CombineSource::kPrimaryColor;
  c.rgb_source[1] = CombineSource::kTexture1;
  c.alpha = CombineFunction::kReplace;
  c.alpha_operand[0] = CombineOperand::kOneMinusSrcAlpha;
  v = apply_texture_combine(c, in);
  EXPECT_EQ(v.r, 0.0f);
  EXPECT_NEAR(v.g, 0.2f, 1e-6);
  EXPECT_NEAR(v.a, 0.5f, 1e-6);
  c = TextureCombine{};
  c.rgb = CombineFunction::kDot3Rgba;  // (2 t0 - 1) . (2 t1 - 1) in every component
  c.rgb_source[1] = CombineSource::kTexture1;
  v = apply_texture_combine(c, in);
  const float dot = (0.4f - 1.0f) * (1.8f - 1.0f) + (0.8f - 1.0f) * (0.2f - 1.0f) + (1.2f - 1.0f) * (1.0f - 1.0f);
  EXPECT_NEAR(v.r, dot > 0.0f ? dot : 0.0f, 1e-6);
  EXPECT_EQ(v.a, v.r);
}

}  // namespace
}  // namespace shadelab

namespace shadelab {
namespace {

// GL 1.3 table 3.19 as llvmpipe resolves ties (z over y over x): the face and (s', t') =
// (sc / |ma| + 1) / 2, computed by hand.
TEST(CubeMap, FaceAndCoordinatesFromTheMajorAxis) {
  CubeCoord c = cube_face({1.0f, 0.5f, -0.25f});  // +X: sc = -r, tc = -t
  EXPECT_EQ(c.face, 0);
  EXPECT_FLOAT_EQ(c.s, 0.625f);
  EXPECT_FLOAT_EQ(c.t, 0.25f);
  c = cube_face({-0.2f, -0.9f, 0.3f});  // -Y: sc = s, tc = -r
  EXPECT_EQ(c.face, 3);
  EXPECT_NEAR(c.s, 0.5f - 0.2f / 1.8f, 1e-6f);
  EXPECT_NEAR(c.t, 0.5f - 0.3f / 1.8f, 1e-6f);
  c = cube_face({1.0f, 1.0f, 1.0f});  // a tie goes to z: +Z, sc = s, tc = -t
  EXPECT_EQ(c.face, 4);
  EXPECT_FLOAT_EQ(c.s, 1.0f);
  EXPECT_FLOAT_EQ(c.t, 0.0f);
  c = cube_face({1.0f, -1.0f, 0.0f});  // |s| = |t|: y, negative
  EXPECT_EQ(c.face, 3);
  EXPECT_EQ(cube_face({0.0f, 0.0f, -2.0f}).face, 5);
  EXPECT_EQ(cube_face({-3.0f, 0.0f, 1.0f}).face, 1);
}

// A face of 8 texels seen straight on at (0, 0, 1): ds/dx of 0.1 is d(s') = 0.05, 0.4 texels.
TEST(CubeMap, ScaleFactorOfTheFaceCoordinates) {
  Texture t;
  t.cube_map = true;
  TextureLevel l;
  l.width = l.height = 8, l.depth = 6;
  l.rgba.assign(8 * 8 * 6 * 4, 0);
  t.levels.push_back(l);
  TextureDerivatives d;
  d.ds_dx = 0.1f, d.r = 1.0f;
  EXPECT_FLOAT_EQ(texture_rho2(t, d), 0.16f);
  d.dr_dx = 0.5f, d.s = 0.5f;  // the major axis changes too: (0.1 - 0.5 * 0.5) / 2 = -0.075
  EXPECT_NEAR(texture_rho2(t, d), 0.6f * 0.6f, 1e-6f);
}

}  // namespace
}  // namespace shadelab
