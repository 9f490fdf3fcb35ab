// Texture sampling on tiny synthetic textures: nearest and bilinear values worked out by hand,
// wrap modes, completeness, mipmap generation and level choice, environment modes.
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

float red_at(const Texture& t, float s, float tt, float lambda = -1.0f) {
  return sample_texture(t, {s, tt}, lambda).r * 255.0f;
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

TEST(Texture, ClampBlendsWithTheBlackBorder) {
  Texture t = two_by_two(TextureFilter::kLinear, TextureWrap::kClamp);
  // s = 0: half the border (0, alpha 0) and half texel 0 -> alpha 0.5.
  EXPECT_NEAR(sample_texture(t, {0.0f, 0.25f}, -1.0f).a, 0.5f, 1e-6);
  Texture e = two_by_two(TextureFilter::kLinear, TextureWrap::kClampToEdge);
  EXPECT_NEAR(sample_texture(e, {0.0f, 0.25f}, -1.0f).a, 1.0f, 1e-6);
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

TEST(Texture, MipmapLevelChoiceFollowsLambda) {
  // 4x4 level 0 all red 40, 2x2 level 1 all 120, 1x1 level 2 all 240: the level is visible.
  Texture t;
  t.levels = {{4, 4, std::vector<std::uint8_t>(64, 40)}, {2, 2, std::vector<std::uint8_t>(16, 120)},
              {1, 1, std::vector<std::uint8_t>(4, 240)}};
  t.min_filter = TextureFilter::kNearestMipmapNearest;
  t.mag_filter = TextureFilter::kNearest;
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, -2.0f), 40, 1e-3);   // magnified: level 0
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 0.4f), 40, 1e-3);    // lambda <= 0.5: level 0
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1.2f), 120, 1e-3);   // ceil(1.7) - 1 = 1
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1.6f), 240, 1e-3);   // ceil(2.1) - 1 = 2
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 9.0f), 240, 1e-3);   // clamped to the last level
  t.min_filter = TextureFilter::kNearestMipmapLinear;
  EXPECT_NEAR(red_at(t, 0.5f, 0.5f, 1.25f), 0.75f * 120 + 0.25f * 240, 1e-3);  // trilinear
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
