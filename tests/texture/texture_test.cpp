// Texture sampling on tiny synthetic textures: nearest and bilinear values worked out by hand,
// wrap modes and the border colour, 1D textures, completeness, mipmap generation, llvmpipe's
// level of detail (rho^2, its level choice), environment modes.
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
  return sample_texture(t, {s, tt}, rho2).r * 255.0f;
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
  // Centre (0.5, 0.5): u = v = 1, uu = vv = 0.5 -> equal weights: (0+100+200+255)/4.
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f), 138.75f, 1e-3);
  // (0.5, 0.25): vv = 0 -> row 0 only, halfway: (0 + 100) / 2.
  EXPECT_NEAR(red_at(t, 0.5f, 0.25f), 50.0f, 1e-3);
  // (0.375, 0.25): u = 0.75, uu = 0.25 -> 0.75 * 0 + 0.25 * 100.
  EXPECT_NEAR(red_at(t, 0.375f, 0.25f), 25.0f, 1e-3);
}

TEST(Texture, RepeatWrapsAcrossTheEdgeWhenFiltering) {
  Texture t = two_by_two(TextureFilter::kLinear, TextureWrap::kRepeat);
  // s = 0 on row 0: uu = -0.5 -> texels i = -1 (wraps to 1: 100) and 0 (0), half each.
  EXPECT_NEAR(red_at(t, 0.0f, 0.25f), 50.0f, 1e-3);
}

TEST(Texture, ClampBlendsWithTheBorderColour) {
  Texture t = two_by_two(TextureFilter::kLinear, TextureWrap::kClamp);
  // s = 0: half the border (by default (0, 0, 0, 0)) and half texel 0 -> alpha 0.5.
  EXPECT_NEAR(sample_texture(t, {0.0f, 0.25f}, 0.25f).a, 0.5f, 1e-6);
  t.border_color = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
  // Red: half of 255 (border) and half of 0 (texel 0).
  EXPECT_NEAR(red_at(t, 0.0f, 0.25f), 127.5f, 1e-3);
  Texture e = two_by_two(TextureFilter::kLinear, TextureWrap::kClampToEdge);
  EXPECT_NEAR(sample_texture(e, {0.0f, 0.25f}, 0.25f).a, 1.0f, 1e-6);
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
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1.0f), 138.75f, 1e-3);  // magnified: bilinear, level 0
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1.2f), 255.0f, 1e-3);   // nearest, level 0: texel (1, 1)
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
}

}  // namespace
}  // namespace shadelab
