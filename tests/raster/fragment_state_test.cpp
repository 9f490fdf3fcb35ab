// GL's per-fragment state with values computed by hand, on the reference pipeline and on the
// fast one: fog factors at a known eye distance (GL 1.1 section 3.9), a polygon stipple bit
// (3.5.2), the scissor box (4.1.2), the alpha test in 8 bits with its depth writes (4.1.3),
// logic ops under the colour mask (4.1.7), and draw_fragments' rectangles (3.6.4, 3.7).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/fragment_ops.hpp"
#include "shadelab/pipeline.hpp"

namespace shadelab {
namespace {

constexpr int kW = 70, kH = 40;

// Draws one unlit rectangle over the whole buffer at eye-space depth `eye_z` (orthographic,
// so every fragment has fog coordinate |eye_z|), through the reference (null) or the fast
// pipeline.
struct Canvas {
  Framebuffer fb;
  FragmentState frag;
  ShadeState shade;
  std::unique_ptr<PipelineContext> fast;

  explicit Canvas(bool use_fast) {
    if (use_fast) fast = std::make_unique<PipelineContext>(2);
    fb.resize(kW, kH);
    fb.clear_color(glm::vec4(0, 0, 0, 1));
    fb.clear_depth(1.0f);
    frag.depth_test = false;
    shade.lighting = false;
  }
  void rect(glm::vec4 color, float eye_z = -2.0f, float x0 = -1, float y0 = -1, float x1 = 1, float y1 = 1) {
    const std::vector<glm::vec4> pos = {{x0, y0, eye_z, 1}, {x1, y0, eye_z, 1}, {x1, y1, eye_z, 1}, {x0, y1, eye_z, 1}};
    const std::vector<Triangle> tris = {{0, 1, 2}, {0, 2, 3}};
    VertexInput in;
    in.positions = pos;
    in.constant_color = color;
    in.triangles = tris;
    const glm::mat4 ortho = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.0f, 10.0f);
    draw_triangles(fb, ortho, Viewport{0, 0, kW, kH}, frag, shade, in, nullptr, fast.get());
    if (fast) fast->finish_draws();
  }
  glm::ivec4 at(int x, int y) const {
    const std::uint8_t* p = &fb.color[(std::size_t(y) * kW + x) * 4];
    return {p[0], p[1], p[2], p[3]};
  }
  int drawn(glm::ivec4 color) const {
    int n = 0;
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) n += at(x, y) == color;
    }
    return n;
  }
};

class FragmentStateTest : public ::testing::TestWithParam<bool> {};

TEST(FogFactor, HandComputedValues) {
  FogState fog;
  fog.enabled = true;
  fog.mode = FogMode::kLinear;
  fog.start = 1.0f, fog.end = 5.0f;
  EXPECT_FLOAT_EQ(detail::fog_factor(detail::fog_params(fog), 2.0f), 0.75f);  // (5 - 2) / (5 - 1)
  EXPECT_EQ(detail::fog_factor(detail::fog_params(fog), 7.0f), 0.0f);         // clamped
  EXPECT_EQ(detail::fog_factor(detail::fog_params(fog), 0.0f), 1.0f);
  fog.mode = FogMode::kExp;
  fog.density = 0.5f;
  EXPECT_NEAR(detail::fog_factor(detail::fog_params(fog), 2.0f), std::exp(-1.0f), 1e-6f);  // e^-(0.5 * 2)
  fog.mode = FogMode::kExp2;
  fog.density = 0.25f;
  EXPECT_NEAR(detail::fog_factor(detail::fog_params(fog), 2.0f), std::exp(-0.25f), 1e-6f);  // e^-((0.25 * 2)^2)
  fog.mode = FogMode::kLinear;  // start == end: Mesa's scale of 1, f = c - end
  fog.start = fog.end = 3.0f;
  EXPECT_EQ(detail::fog_factor(detail::fog_params(fog), 2.0f), 0.0f);
  EXPECT_FLOAT_EQ(detail::fog_factor(detail::fog_params(fog), 3.5f), 0.5f);
}

TEST_P(FragmentStateTest, FogAtAKnownDepth) {
  Canvas c(GetParam());
  c.shade.fog = {true, FogMode::kLinear, glm::vec3(0, 0, 1), 1.0f, 5.0f, 1.0f};
  c.rect({1, 0, 0, 0.5f}, -2.0f);  // f = 0.75: red 0.75 -> 191, blue 0.25 -> 64, alpha kept
  EXPECT_EQ(c.at(10, 10), glm::ivec4(191, 0, 64, 128));
  c.shade.fog = {true, FogMode::kExp2, glm::vec3(0, 0, 1), 0.0f, 1.0f, 0.25f};
  c.rect({1, 0, 0, 1}, -2.0f);  // f = e^-0.25 = 0.7788: red 198.6 -> 199, blue 56.4 -> 56
  EXPECT_EQ(c.at(30, 20), glm::ivec4(199, 0, 56, 255));
  c.shade.fog = {true, FogMode::kExp, glm::vec3(0, 1, 0), 0.0f, 1.0f, 0.5f};
  c.rect({1, 0, 0, 1}, -2.0f);  // f = e^-1 = 0.3679: red 93.8 -> 94, green 161.2 -> 161
  EXPECT_EQ(c.at(69, 39), glm::ivec4(94, 161, 0, 255));
}

TEST_P(FragmentStateTest, StippleBitSelectsPixels) {
  Canvas c(GetParam());
  c.frag.stipple.enabled = true;
  c.frag.stipple.rows[5] = 1u << 3;  // only pixels x % 32 == 3 on rows y % 32 == 5
  c.rect({1, 1, 1, 1});
  EXPECT_EQ(c.drawn({255, 255, 255, 255}), 6);  // x = 3, 35, 67 on rows 5 and 37
  EXPECT_EQ(c.at(35, 5), glm::ivec4(255, 255, 255, 255));
  EXPECT_EQ(c.at(35, 37), glm::ivec4(255, 255, 255, 255)) << "row 37 = 5 + 32";
}

TEST_P(FragmentStateTest, ScissorBoxKeepsItsPixels) {
  Canvas c(GetParam());
  c.frag.scissor = {true, 5, 7, 20, 11};
  c.rect({0, 1, 0, 1});
  EXPECT_EQ(c.drawn({0, 255, 0, 255}), 20 * 11);
  EXPECT_EQ(c.at(5, 7), glm::ivec4(0, 255, 0, 255));
  EXPECT_EQ(c.at(24, 17), glm::ivec4(0, 255, 0, 255));
  EXPECT_EQ(c.at(25, 17), glm::ivec4(0, 0, 0, 255));
  EXPECT_EQ(c.at(24, 18), glm::ivec4(0, 0, 0, 255));
  c.frag.scissor = {true, -10, -10, 5, 100};  // wholly left of the buffer
  c.rect({1, 1, 1, 1});
  EXPECT_EQ(c.drawn({255, 255, 255, 255}), 0);
}

TEST_P(FragmentStateTest, AlphaTestInEightBitsWritesDepthOnlyWhereItPasses) {
  Canvas c(GetParam());
  c.frag.depth_test = true;
  c.frag.depth_func = CompareFunc::kAlways;
  c.frag.alpha_test = {true, CompareFunc::kLess, 0.5f};  // ref byte 128
  c.rect({1, 0, 0, 0.5f}, -2.0f);                        // alpha byte 128: not less
  EXPECT_EQ(c.drawn({255, 0, 0, 128}), 0);
  EXPECT_EQ(c.fb.depth[0], 1.0f) << "no depth written by rejected fragments";
  c.frag.alpha_test.func = CompareFunc::kEqual;
  c.rect({1, 0, 0, 0.5009f}, -2.0f);  // 127.73 rounds to 128: equal in 8 bits, not in floats
  EXPECT_EQ(c.drawn({255, 0, 0, 128}), kW * kH);
  EXPECT_NEAR(c.fb.depth[0], 0.2f, 1e-6f);
  c.frag.alpha_test.func = CompareFunc::kLess;
  c.rect({0, 1, 0, 0.499f}, -6.0f);  // byte 127 < 128
  EXPECT_EQ(c.drawn({0, 255, 0, 127}), kW * kH);
  EXPECT_NEAR(c.fb.depth[0], 0.6f, 1e-6f);
}

TEST_P(FragmentStateTest, LogicOpsOnBytesUnderTheColourMask) {
  Canvas c(GetParam());
  c.fb.clear_color(glm::vec4(0x0f, 0xf0, 0x55, 0xff) / 255.0f);
  c.frag.logic_op = {true, LogicOp::kXor};
  c.frag.blend = {true, BlendFactor::kOne, BlendFactor::kOne};  // not done: logic op instead
  c.rect(glm::vec4(0xff, 0xff, 0x0f, 0x00) / 255.0f);
  EXPECT_EQ(c.at(1, 1), glm::ivec4(0xf0, 0x0f, 0x5a, 0xff));
  c.frag.logic_op.op = LogicOp::kAndReverse;  // s & ~d
  c.frag.color_mask[1] = false;
  c.rect(glm::vec4(0xff, 0x00, 0xff, 0xff) / 255.0f);
  EXPECT_EQ(c.at(1, 1), glm::ivec4(0x0f, 0x0f, 0xa5, 0x00));
  EXPECT_EQ(detail::logic_op(LogicOp::kEquiv, 0x12345678u, 0x0f0f0f0fu), ~(0x12345678u ^ 0x0f0f0f0fu));
  EXPECT_EQ(detail::logic_op(LogicOp::kOrInverted, 0u, 0u), ~0u);
  EXPECT_EQ(detail::logic_op(LogicOp::kNoop, 1u, 2u), 2u);
}

// draw_fragments: a rectangle of given colours (glDrawPixels' fragments) through the same
// operations: ownership at the framebuffer's edge, a mask (glBitmap), the depth test with its
// writes, the alpha test, fog at the raster position's coordinate, the scissor box.
TEST_P(FragmentStateTest, DrawFragmentsRunsTheFragmentOperations) {
  Canvas c(GetParam());
  std::vector<glm::vec4> colors;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i) colors.emplace_back(float(i) / 3.0f, float(j) / 2.0f, 1.0f, 1.0f);
  }
  FragmentRect r;
  r.x = kW - 2, r.y = 5, r.width = 4, r.height = 3;  // two columns past the right edge
  r.colors = colors;
  r.depth = 0.5f;
  c.frag.depth_test = true;
  draw_fragments(c.fb, c.frag, c.shade, r, nullptr, c.fast.get());
  EXPECT_EQ(c.at(kW - 2, 5), glm::ivec4(0, 0, 255, 255));
  EXPECT_EQ(c.at(kW - 1, 7), glm::ivec4(85, 255, 255, 255));  // 1/3 -> 85, 2/2 -> 255
  EXPECT_EQ(c.fb.depth[std::size_t(6) * kW + kW - 1], 0.5f);
  // Behind what is there: nothing changes.
  const std::vector<glm::vec4> red = {{1, 0, 0, 1}};
  r.colors = red;
  r.depth = 0.7f;
  draw_fragments(c.fb, c.frag, c.shade, r, nullptr, c.fast.get());
  EXPECT_EQ(c.at(kW - 2, 5), glm::ivec4(0, 0, 255, 255));
  // A bitmap's mask, one colour, fogged at the raster position's distance, in a scissor box.
  const std::vector<std::uint8_t> mask = {1, 0, 0, 1, 0, 1, 1, 0, 1, 1, 1, 1};
  r = FragmentRect{};
  r.x = 10, r.y = 10, r.width = 4, r.height = 3;
  r.colors = red;
  r.mask = mask;
  r.depth = 0.25f;
  r.fog_coord = 2.0f;
  c.shade.fog = {true, FogMode::kLinear, glm::vec3(0, 0, 1), 1.0f, 5.0f, 1.0f};  // f = 0.75
  c.frag.scissor = {true, 0, 0, 13, 100};                                        // column 13 out
  RenderStats stats;
  draw_fragments(c.fb, c.frag, c.shade, r, &stats, c.fast.get());
  EXPECT_EQ(stats.fragments, 6u);
  EXPECT_EQ(stats.pixels_shaded, 6u);
  EXPECT_EQ(c.drawn({191, 0, 64, 255}), 6);
  EXPECT_EQ(c.at(10, 10), glm::ivec4(191, 0, 64, 255));
  EXPECT_EQ(c.at(11, 10), glm::ivec4(0, 0, 0, 255));
  // The alpha test rejects them all; the depth buffer keeps its values.
  c.frag.alpha_test = {true, CompareFunc::kLess, 0.5f};
  c.shade.fog.enabled = false;
  r.mask = {};
  r.depth = 0.0f;
  draw_fragments(c.fb, c.frag, c.shade, r, nullptr, c.fast.get());
  EXPECT_EQ(c.at(11, 10), glm::ivec4(0, 0, 0, 255));
  EXPECT_EQ(c.fb.depth[std::size_t(10) * kW + 10], 0.25f);
}

// Large rectangles are split over the context's threads by rows: the same pixels as one loop.
TEST(DrawFragments, RowsOnThreadsAreOneLoop) {
  Canvas ref(false), fast(true);
  std::vector<glm::vec4> colors;
  std::vector<float> depths;
  for (int i = 0; i < 90 * 60; ++i) {
    colors.emplace_back(float(i % 7) / 6.0f, float(i % 11) / 10.0f, float(i % 13) / 12.0f, float(i % 5) / 4.0f);
    depths.push_back(float(i % 17) / 16.0f);
  }
  FragmentRect r;
  r.x = -10, r.y = -12, r.width = 90, r.height = 60;
  r.colors = colors;
  r.depths = depths;
  for (Canvas* c : {&ref, &fast}) {
    c->frag.depth_test = true;
    c->frag.blend = {true, BlendFactor::kSrcAlpha, BlendFactor::kOneMinusSrcAlpha};
    c->frag.alpha_test = {true, CompareFunc::kGreater, 0.2f};
    draw_fragments(c->fb, c->frag, c->shade, r, nullptr, c->fast.get());
  }
  EXPECT_EQ(fast.fb.color, ref.fb.color);
  EXPECT_EQ(fast.fb.depth, ref.fb.depth);
  EXPECT_NE(ref.fb.color, Canvas(false).fb.color);
}

INSTANTIATE_TEST_SUITE_P(Pipelines, FragmentStateTest, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "fast" : "reference"; });

}  // namespace
}  // namespace shadelab
