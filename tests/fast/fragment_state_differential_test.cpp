// The fast pipeline against the reference with GL's other per-fragment state: random draws
// with fog, scissor boxes, the alpha test, logic ops and polygon stipples
// (RandomDraws::fragment_extras) on 1, 2 and 3 threads, every SIMD target, and deferred over
// pending clears. Coverage, depth and stencil identical, colours within 1/255.
#include <gtest/gtest.h>

#include "differential.hpp"
#include "fast/simd_targets.hpp"

namespace shadelab {
namespace {

using test::random_cases;
using test::check_seed;
using test::compare_buffers;
using test::RandomDraw;
using test::RandomDraws;
using test::render;
using test::Result;
using test::simd_only;

TEST(FastFragmentState, RandomDrawsMatchTheReference) {
  PipelineContext one(1), two(2), three(3);
  for (unsigned seed = 6000; seed < 6000 + random_cases(300); ++seed) ASSERT_EQ(check_seed(seed, {&one, &two, &three}, true), "");
}

TEST(FastFragmentState, EverySimdTargetMatchesTheReference) {
  PipelineContext two(2);
  for (const std::string& target : fast::available_simd_targets()) {
    ASSERT_TRUE(fast::force_simd_target(target));
    for (unsigned seed = 7000; seed < 7060; ++seed) {
      std::string diff = check_seed(seed, {&two}, true);
      EXPECT_EQ(diff, "") << target;
      if (!diff.empty()) break;
    }
  }
  fast::force_simd_target("");
}

// Each state alone on the SIMD path (no texture, stencil or capture), with enough fragments
// that every state decides some of them; fogged draws also through the kernels compiled for
// the usual state (BlockKernel), which take fog.
TEST(FastFragmentState, EachStateAloneOnTheSimdPath) {
  PipelineContext two(2);
  for (int which = 0; which < 5; ++which) {
    std::uint64_t changed = 0;
    int kernels = 0;
    for (unsigned seed = 8000; seed < 8040; ++seed) {
      RandomDraws random(seed);
      glm::ivec2 size{random.integer(40, 200), random.integer(30, 150)};
      Framebuffer initial = random.framebuffer(size);
      RandomDraw d = random.draw(size);
      simd_only(d);
      RandomDraw extras = d;
      random.fragment_extras(extras, size);
      switch (which) {
        case 0: d.shade.fog = extras.shade.fog, d.shade.fog.enabled = true; break;
        case 1: d.frag.scissor = {true, size.x / 4, size.y / 3, size.x / 2, size.y / 2}; break;
        case 2: d.frag.alpha_test = {true, CompareFunc(seed % 8), random.uniform(0, 1)}; break;
        case 3: d.frag.logic_op = {true, LogicOp(seed % 16)}; break;
        default: d.frag.stipple = extras.frag.stipple, d.frag.stipple.enabled = true; break;
      }
      if (which == 3 && d.shade.shading == ShadingMode::kPhong) d.shade.shading = ShadingMode::kGouraud;
      kernels += test::planned_kernel(d.frag, d.shade) != fast::BlockKernel::kGeneral;
      Result ref = render(initial, {d}, nullptr);
      Result fast = render(initial, {d}, &two);
      ASSERT_EQ(compare_buffers(fast.fb, ref.fb), "") << "state " << which << " seed " << seed;
      ASSERT_EQ(fast.stats.fragments, ref.stats.fragments) << "state " << which << " seed " << seed;
      ASSERT_EQ(fast.stats.pixels_shaded, ref.stats.pixels_shaded) << "state " << which << " seed " << seed;
      changed += ref.stats.pixels_shaded;
    }
    EXPECT_GT(changed, 1000u) << "state " << which;
    if (which == 0) {
      EXPECT_GT(kernels, 5) << "fogged draws through a kernel";
    }
  }
}

// Deferred draws keep their own copy of the state (the stipple pattern, the scissor box):
// drawn tile by tile later, over pending clears, they match the reference.
TEST(FastFragmentState, DeferredDrawsMatchTheReference) {
  PipelineContext two(2);
  two.set_deferred(true);
  for (unsigned seed = 8500; seed < 8500 + random_cases(100); ++seed) {
    RandomDraws random(seed);
    glm::ivec2 size{random.integer(60, 300), random.integer(60, 200)};
    Framebuffer initial = random.framebuffer(size);
    std::vector<RandomDraw> draws;
    for (int i = random.integer(1, 5); i > 0; --i) {
      draws.push_back(random.draw(size));
      random.fragment_extras(draws.back(), size);
      simd_only(draws.back());
    }
    Framebuffer cleared = initial;
    cleared.clear_color(glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
    cleared.clear_depth(1.0f);
    Result ref = render(cleared, draws, nullptr);
    Framebuffer fast = initial;
    two.clear_later(fast, PipelineContext::PendingClears::kColor | PipelineContext::PendingClears::kDepth,
                    glm::vec4(0.25f, 0.5f, 0.75f, 1.0f), 1.0f);
    FragmentState frag;  // every draw's state changes after it is made: the copy is drawn
    for (const RandomDraw& d : draws) {
      frag = d.frag;
      VertexInput in = d.input();
      draw_triangles(fast, d.projection, d.viewport, frag, d.shade, in, nullptr, &two);
      frag.stipple.rows.fill(0);
      frag.scissor = {true, 0, 0, 1, 1};
    }
    two.apply_pending_clears(fast);
    ASSERT_EQ(compare_buffers(fast, ref.fb), "") << "seed " << seed;
  }
}

}  // namespace
}  // namespace shadelab
