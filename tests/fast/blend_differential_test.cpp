// The fast pipeline against the reference with GL 1.4's blending and stencil state: any blend
// equation, factors (the constant colour's too) apart for alpha or not, a constant colour,
// and the wrapping stencil operations (RandomDraws::blend_extras), on 1, 2 and 3 threads,
// every SIMD target, deferred; every equation and factor pair on the SIMD path alone; the
// blend kernels chosen only for the state they implement; and drawing without the depth test
// (2D programs: the kernels kOpaque and kBlend), opaque and blended, on every target. Coverage, depth and stencil
// identical, colours within 1/255, the same fragments counted as passing.
#include <gtest/gtest.h>

#include "differential.hpp"
#include "fast/plan.hpp"
#include "fast/simd_targets.hpp"

namespace shadelab {
namespace {

using test::random_cases;
using test::compare_buffers;
using test::compare_scene;
using test::RandomDraw;
using test::RandomDraws;
using test::render;
using test::Result;
using test::simd_only;

// One random scene whose draws carry GL 1.4's blend and stencil state (and, with `extras`,
// GL 1.1's other per-fragment state).
std::string check_blend_seed(unsigned seed, const std::vector<PipelineContext*>& contexts, bool extras) {
  RandomDraws random(seed);
  glm::ivec2 size = random.size();
  Framebuffer initial = random.framebuffer(size);
  for (std::size_t i = 0; i < initial.stencil.size(); i += 3) initial.stencil[i] = std::uint8_t(255 - initial.stencil[i]);
  std::vector<RandomDraw> draws;
  for (int i = random.integer(1, 4); i > 0; --i) {
    draws.push_back(random.draw(size));
    if (extras) random.fragment_extras(draws.back(), size);
    random.blend_extras(draws.back());
  }
  return compare_scene("seed " + std::to_string(seed), initial, draws, contexts);
}

TEST(FastBlend, RandomDrawsMatchTheReference) {
  PipelineContext one(1), two(2), three(3);
  for (unsigned seed = 9000; seed < 9000 + random_cases(300); ++seed) {
    ASSERT_EQ(check_blend_seed(seed, {&one, &two, &three}, seed % 3 == 0), "");
  }
}

TEST(FastBlend, EverySimdTargetMatchesTheReference) {
  PipelineContext two(2);
  for (const std::string& target : fast::available_simd_targets()) {
    ASSERT_TRUE(fast::force_simd_target(target));
    for (unsigned seed = 9400; seed < 9460; ++seed) {
      std::string diff = check_blend_seed(seed, {&two}, seed % 2 == 0);
      EXPECT_EQ(diff, "") << target;
      if (!diff.empty()) break;
    }
  }
  fast::force_simd_target("");
}

// Every equation with every pair of colour factors, the alpha factors going through every
// factor too, on the SIMD path alone (no texture, stencil or capture): the blend, and only
// the blend, decides the colours.
TEST(FastBlend, EveryEquationAndFactorPairOnTheSimdPath) {
  PipelineContext two(2);
  constexpr int kFactors = 15;
  for (int equation = 0; equation < 5; ++equation) {
    std::uint64_t blended = 0;
    for (int pair = 0; pair < kFactors * kFactors; ++pair) {
      const unsigned seed = unsigned(20000 + equation * 1000 + pair);
      RandomDraws random(seed);
      glm::ivec2 size{random.integer(20, 60), random.integer(16, 40)};
      Framebuffer initial = random.framebuffer(size);
      RandomDraw d = random.draw(size);
      simd_only(d);
      BlendState& b = d.frag.blend;
      b = {true, BlendFactor(pair / kFactors), BlendFactor(pair % kFactors)};
      b.src_alpha = BlendFactor((pair * 7) % kFactors);
      b.dst_alpha = BlendFactor((pair * 11 + 3) % kFactors);
      b.equation = BlendEquation(equation);
      b.color = random.color(0.0f);
      Result ref = render(initial, {d}, nullptr);
      Result fast = render(initial, {d}, &two);
      const std::string where = "equation " + std::to_string(equation) + " pair " + std::to_string(pair);
      ASSERT_EQ(compare_buffers(fast.fb, ref.fb), "") << where;
      ASSERT_EQ(fast.stats.pixels_shaded, ref.stats.pixels_shaded) << where;
      blended += ref.stats.pixels_shaded;
    }
    EXPECT_GT(blended, 10000u) << "equation " << equation;
  }
}

// EXT_blend_equation_separate: alpha blended by its own equation, every pair of equations.
TEST(FastBlend, SeparateAlphaEquationsOnTheSimdPath) {
  PipelineContext two(2);
  std::uint64_t blended = 0;
  for (int pair = 0; pair < 25; ++pair) {
    RandomDraws random(unsigned(27000 + pair));
    glm::ivec2 size{random.integer(20, 60), random.integer(16, 40)};
    Framebuffer initial = random.framebuffer(size);
    RandomDraw d = random.draw(size);
    simd_only(d);
    BlendState& b = d.frag.blend;
    b = {true, BlendFactor::kSrcAlpha, BlendFactor::kOneMinusSrcAlpha};
    b.dst_alpha = BlendFactor::kOneMinusDstAlpha;
    b.equation = BlendEquation(pair / 5);
    b.separate_equations = true;
    b.equation_alpha = BlendEquation(pair % 5);
    Result ref = render(initial, {d}, nullptr);
    Result fast = render(initial, {d}, &two);
    ASSERT_EQ(compare_buffers(fast.fb, ref.fb), "") << "equations " << pair / 5 << ", " << pair % 5;
    blended += ref.stats.pixels_shaded;
  }
  EXPECT_GT(blended, 2000u);
}

// Deferred draws keep their blend state (the constant colour, the equation) as it was made.
TEST(FastBlend, DeferredDrawsKeepTheirBlendState) {
  PipelineContext two(2);
  two.set_deferred(true);
  for (unsigned seed = 9600; seed < 9680; ++seed) {
    RandomDraws random(seed);
    glm::ivec2 size{random.integer(60, 300), random.integer(60, 200)};
    Framebuffer initial = random.framebuffer(size);
    std::vector<RandomDraw> draws;
    for (int i = random.integer(1, 5); i > 0; --i) {
      draws.push_back(random.draw(size));
      random.blend_extras(draws.back());
      simd_only(draws.back());
    }
    Result ref = render(initial, draws, nullptr);
    Framebuffer fast = initial;
    FragmentState frag;
    for (const RandomDraw& d : draws) {
      frag = d.frag;
      VertexInput in = d.input();
      draw_triangles(fast, d.projection, d.viewport, frag, d.shade, in, nullptr, &two);
      frag.blend.color = glm::vec4(0.5f);
      frag.blend.equation = BlendEquation::kReverseSubtract;
    }
    two.finish_draws();
    ASSERT_EQ(compare_buffers(fast, ref.fb), "") << "seed " << seed;
  }
}

// The kernel make_plan chooses for a draw the kernels could take (depth kLess written, every
// channel written, nothing else on) with the blend state `b`.
fast::BlockKernel kernel_for(const BlendState& b, bool depth_test = true) {
  FragmentState frag;
  frag.blend = b;
  frag.depth_test = depth_test;
  ShadeState shade;
  shade.lighting = false;
  return test::planned_kernel(frag, shade);
}

TEST(FastBlend, BlendKernelsOnlyForSourceOver) {
  using fast::BlockKernel;
  const BlendState over{true, BlendFactor::kSrcAlpha, BlendFactor::kOneMinusSrcAlpha};
  EXPECT_EQ(kernel_for(over), BlockKernel::kBlendLess);
  EXPECT_EQ(kernel_for(BlendState{}), BlockKernel::kOpaqueLess);  // blending off
  BlendState b = over;
  b.equation = BlendEquation::kSubtract;
  EXPECT_EQ(kernel_for(b), BlockKernel::kGeneral);
  b = over;
  b.equation = BlendEquation::kMax;
  EXPECT_EQ(kernel_for(b), BlockKernel::kGeneral);
  b = over;
  b.src_alpha = BlendFactor::kOne;
  EXPECT_EQ(kernel_for(b), BlockKernel::kGeneral);
  b = over;
  b.dst_alpha = BlendFactor::kZero;
  EXPECT_EQ(kernel_for(b), BlockKernel::kGeneral);
  b = over;
  b.color = glm::vec4(0.5f);  // unused by these factors: still the kernel
  EXPECT_EQ(kernel_for(b), BlockKernel::kBlendLess);
  EXPECT_EQ(kernel_for(BlendState{true, BlendFactor::kConstantAlpha, BlendFactor::kOneMinusConstantAlpha}),
            BlockKernel::kGeneral);
  // Without the depth test: the depth-less kernels, for the same blend states only.
  EXPECT_EQ(kernel_for(over, false), BlockKernel::kBlend);
  EXPECT_EQ(kernel_for(BlendState{}, false), BlockKernel::kOpaque);
  b = over;
  b.equation = BlendEquation::kSubtract;
  EXPECT_EQ(kernel_for(b, false), BlockKernel::kGeneral);
}

// Draws without the depth test, opaque or blended source over (what the kernels kOpaque and
// kBlend draw), over random framebuffers whose depth they must leave alone: the same colours,
// depth and counts as the reference on every SIMD target, triangles inside the framebuffer and
// across its edges alike.
TEST(FastBlend, DrawsWithoutTheDepthTestMatchTheReferenceOnEveryTarget) {
  PipelineContext two(2);
  const BlendState over{true, BlendFactor::kSrcAlpha, BlendFactor::kOneMinusSrcAlpha};
  for (const std::string& target : fast::available_simd_targets()) {
    ASSERT_TRUE(fast::force_simd_target(target));
    std::uint64_t shaded = 0;
    for (unsigned seed = 9800; seed < 9800 + random_cases(60); ++seed) {
      RandomDraws random(seed);
      glm::ivec2 size = random.size();
      Framebuffer initial = random.framebuffer(size);
      std::vector<RandomDraw> draws;
      for (int i = random.integer(1, 4); i > 0; --i) {
        draws.push_back(random.draw(size));
        RandomDraw& d = draws.back();
        simd_only(d);
        d.frag.depth_test = false;
        d.frag.depth_write = seed % 2 == 0;  // no depth written either way
        d.frag.blend = i % 2 ? over : BlendState{};
        d.shade.fog.enabled = false;
        d.frag.alpha_test.enabled = false;
        d.frag.logic_op.enabled = false;
        d.frag.stipple.enabled = false;
        d.frag.scissor.enabled = false;
        for (bool& m : d.frag.color_mask) m = true;
      }
      Result ref = render(initial, draws, nullptr);
      Result fast = render(initial, draws, &two);
      const std::string diff = compare_buffers(fast.fb, ref.fb);
      EXPECT_EQ(diff, "") << target << " seed " << seed;
      EXPECT_EQ(fast.stats.pixels_shaded, ref.stats.pixels_shaded) << target << " seed " << seed;
      if (!diff.empty()) break;
      shaded += ref.stats.pixels_shaded;
    }
    EXPECT_GT(shaded, 10000u) << target;
  }
  fast::force_simd_target("");
}

}  // namespace
}  // namespace shadelab
