// GL 1.4's blending and stencil operations with values computed by hand, on the reference
// pipeline and on the fast one: the blend equations (GL 1.4 section 4.1.7; kMin and kMax
// ignore the factors), separate alpha factors, the constant colour in the colour buffer's 8
// bits, and GL_INCR_WRAP / GL_DECR_WRAP (section 4.1.5) wrapping through the write mask.
#include <gtest/gtest.h>

#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/fragment_ops.hpp"
#include "shadelab/pipeline.hpp"

namespace shadelab {
namespace {

constexpr int kW = 48, kH = 20;

// One unlit rectangle over the whole buffer, through the reference (null) or the fast pipeline.
struct Canvas {
  Framebuffer fb;
  FragmentState frag;
  ShadeState shade;
  std::unique_ptr<PipelineContext> fast;
  RenderStats stats;

  explicit Canvas(bool use_fast) {
    if (use_fast) fast = std::make_unique<PipelineContext>(2);
    fb.resize(kW, kH);
    fb.clear_depth(1.0f);
    frag.depth_test = false;
    shade.lighting = false;
  }
  void rect(glm::vec4 color) {
    const std::vector<glm::vec4> pos = {{-1, -1, -2, 1}, {1, -1, -2, 1}, {1, 1, -2, 1}, {-1, 1, -2, 1}};
    const std::vector<Triangle> tris = {{0, 1, 2}, {0, 2, 3}};
    VertexInput in;
    in.positions = pos;
    in.constant_color = color;
    in.triangles = tris;
    const glm::mat4 ortho = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.0f, 10.0f);
    draw_triangles(fb, ortho, Viewport{0, 0, kW, kH}, frag, shade, in, &stats, fast.get());
  }
  // Every pixel's colour when they are all the same; (-1, ...) otherwise.
  glm::ivec4 color() const {
    const glm::ivec4 first(fb.color[0], fb.color[1], fb.color[2], fb.color[3]);
    for (std::size_t i = 0; i < fb.color.size(); i += 4) {
      if (glm::ivec4(fb.color[i], fb.color[i + 1], fb.color[i + 2], fb.color[i + 3]) != first) return glm::ivec4(-1);
    }
    return first;
  }
};

// 8-bit values as the buffer stores them, back in [0, 1].
glm::vec4 bytes(int r, int g, int b, int a) { return glm::vec4(r, g, b, a) / 255.0f; }

class BlendStateTest : public ::testing::TestWithParam<bool> {};

TEST(BlendConstant, RoundedToTheBuffersEightBits) {
  BlendState b;
  b.color = {0.3f, 0.5f, 0.0f, 1.0f};  // 76.5 and 127.5 steps (a little above: 0.3f > 0.3)
  const glm::vec4 k = detail::blend_constant(b);
  EXPECT_EQ(k, bytes(77, 128, 0, 255));
}

TEST_P(BlendStateTest, ConstantColourFactorsUseItsEightBits) {
  Canvas c(GetParam());
  c.fb.clear_color(bytes(10, 20, 30, 40));
  c.frag.blend = {true, BlendFactor::kConstantColor, BlendFactor::kOneMinusConstantAlpha};
  c.frag.blend.color = {0.3f, 0.2f, 1.0f, 0.6f};  // 77, 51, 255, 153
  c.rect(glm::vec4(1.0f));
  // src k + dst (1 - 153/255): 77 + 10 * 0.4 = 81, 51 + 8 = 59, 255 + 12 (clamped), 153 + 16.
  EXPECT_EQ(c.color(), glm::ivec4(81, 59, 255, 169));
}

TEST_P(BlendStateTest, SubtractionsClampAtZero) {
  Canvas c(GetParam());
  c.fb.clear_color(bytes(200, 40, 100, 255));
  c.frag.blend = {true, BlendFactor::kOne, BlendFactor::kOne};
  c.frag.blend.equation = BlendEquation::kSubtract;  // src - dst
  c.rect(bytes(100, 100, 100, 100));
  EXPECT_EQ(c.color(), glm::ivec4(0, 60, 0, 0));
  c.fb.clear_color(bytes(200, 40, 100, 255));
  c.frag.blend.equation = BlendEquation::kReverseSubtract;  // dst - src
  c.rect(bytes(100, 100, 100, 100));
  EXPECT_EQ(c.color(), glm::ivec4(100, 0, 0, 155));
}

TEST_P(BlendStateTest, MinAndMaxIgnoreTheFactors) {
  Canvas c(GetParam());
  c.fb.clear_color(bytes(200, 40, 100, 255));
  c.frag.blend = {true, BlendFactor::kZero, BlendFactor::kZero};
  c.frag.blend.equation = BlendEquation::kMin;
  c.rect(bytes(100, 100, 100, 100));
  EXPECT_EQ(c.color(), glm::ivec4(100, 40, 100, 100));
  c.fb.clear_color(bytes(200, 40, 100, 255));
  c.frag.blend.equation = BlendEquation::kMax;
  c.rect(bytes(100, 100, 100, 100));
  EXPECT_EQ(c.color(), glm::ivec4(200, 100, 100, 255));
}

TEST_P(BlendStateTest, AlphaTakesItsOwnEquationWhenSeparate) {
  Canvas c(GetParam());
  c.fb.clear_color(bytes(200, 40, 100, 60));
  c.frag.blend = {true, BlendFactor::kOne, BlendFactor::kOne};
  c.frag.blend.equation = BlendEquation::kReverseSubtract;  // dst - src for the colour
  c.frag.blend.separate_equations = true;
  c.frag.blend.equation_alpha = BlendEquation::kMax;  // max(src, dst) for alpha
  c.rect(bytes(100, 100, 100, 100));
  EXPECT_EQ(c.color(), glm::ivec4(100, 0, 0, 100));
  c.fb.clear_color(bytes(200, 40, 100, 60));
  c.frag.blend.separate_equations = false;  // the colour's equation for alpha again
  c.rect(bytes(100, 100, 100, 100));
  EXPECT_EQ(c.color(), glm::ivec4(100, 0, 0, 0));
}

TEST_P(BlendStateTest, AlphaTakesItsOwnFactors) {
  Canvas c(GetParam());
  c.fb.clear_color(bytes(200, 40, 100, 60));
  // glBlendFuncSeparate(GL_ONE, GL_ZERO, GL_ZERO, GL_ONE): the source's colour, the
  // destination's alpha; then (GL_DST_COLOR, GL_ZERO, GL_ONE, GL_ONE): colours multiplied,
  // alphas added.
  c.frag.blend = {true, BlendFactor::kOne, BlendFactor::kZero};
  c.frag.blend.src_alpha = BlendFactor::kZero;
  c.frag.blend.dst_alpha = BlendFactor::kOne;
  c.rect(bytes(0, 255, 51, 170));
  EXPECT_EQ(c.color(), glm::ivec4(0, 255, 51, 60));
  c.frag.blend = {true, BlendFactor::kDstColor, BlendFactor::kZero};
  c.frag.blend.src_alpha = c.frag.blend.dst_alpha = BlendFactor::kOne;
  c.rect(bytes(255, 255, 255, 100));
  EXPECT_EQ(c.color(), glm::ivec4(0, 255, 51, 160));
}

TEST_P(BlendStateTest, StencilWrapsBothWaysThroughTheWriteMask) {
  Canvas c(GetParam());
  c.frag.stencil.enabled = true;
  c.frag.stencil.func = CompareFunc::kAlways;
  const std::uint8_t start[4] = {0, 1, 254, 255};
  auto fill = [&] {
    for (std::size_t i = 0; i < c.fb.stencil.size(); ++i) c.fb.stencil[i] = start[i % 4];
  };
  auto expect = [&](const std::uint8_t (&want)[4], const char* what) {
    for (std::size_t i = 0; i < c.fb.stencil.size(); ++i) {
      ASSERT_EQ(int(c.fb.stencil[i]), int(want[i % 4])) << what << " at " << i;
    }
  };
  fill();
  c.frag.stencil.pass = StencilOp::kIncrWrap;
  c.rect(glm::vec4(1.0f));
  expect({1, 2, 255, 0}, "incr wrap");
  fill();
  c.frag.stencil.pass = StencilOp::kDecrWrap;
  c.rect(glm::vec4(1.0f));
  expect({255, 0, 253, 254}, "decr wrap");
  fill();
  c.frag.stencil.pass = StencilOp::kIncr;  // GL 1.1's clamp, for contrast
  c.rect(glm::vec4(1.0f));
  expect({1, 2, 255, 255}, "incr");
  // Through a write mask of the low 4 bits: 0 - 1 = 255 writes 0x0f; 254 + 1 keeps 0xf0.
  fill();
  c.frag.stencil.write_mask = 0x0f;
  c.frag.stencil.pass = StencilOp::kDecrWrap;
  c.rect(glm::vec4(1.0f));
  expect({0x0f, 0x00, 0xfd, 0xfe}, "decr wrap masked");
  // The stencil test failing (kNever): fail's operation, and nothing passes.
  fill();
  c.frag.stencil.write_mask = 0xff;
  c.frag.stencil.func = CompareFunc::kNever;
  c.frag.stencil.fail = StencilOp::kIncrWrap;
  c.stats = {};
  c.rect(glm::vec4(1.0f));
  expect({1, 2, 255, 0}, "fail incr wrap");
  EXPECT_EQ(c.stats.pixels_shaded, 0u);
  EXPECT_EQ(c.stats.fragments, std::uint64_t(kW * kH));
}

INSTANTIATE_TEST_SUITE_P(Pipelines, BlendStateTest, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Fast" : "Reference"; });

}  // namespace
}  // namespace shadelab
