// Lines, points and polygons in GL_LINE / GL_POINT mode, and user clip planes: the fast
// pipeline against the reference on random draws (random_draws.hpp's prim_draw), on 1, 2 and
// 3 threads and every SIMD target. Coverage, depth and stencil identical, colours within 1/255.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "differential.hpp"
#include "fast/simd_targets.hpp"

namespace shadelab {
namespace {

using test::random_cases;
using test::compare_scene;
using test::RandomDraw;
using test::RandomDraws;

std::string check_prims(unsigned seed, const std::vector<PipelineContext*>& contexts) {
  RandomDraws random(seed);
  glm::ivec2 size = random.size();
  Framebuffer initial = random.framebuffer(size);
  std::vector<RandomDraw> draws;
  for (int i = random.integer(1, 3); i > 0; --i) {
    draws.push_back(random.prim_draw(size));
    // Fog, scissor, alpha test, logic op and polygon stipple (which lines and points ignore).
    if (random.chance(0.4)) random.fragment_extras(draws.back(), size);
  }
  return compare_scene("prim seed " + std::to_string(seed), initial, draws, contexts);
}

TEST(FastPrims, RandomLinesPointsAndPolygonModesMatchTheReference) {
  PipelineContext one(1), two(2), three(3);
  for (unsigned seed = 1; seed <= random_cases(200); ++seed) {
    std::string diff = check_prims(seed, {&one, &two, &three});
    ASSERT_EQ(diff, "");
  }
}

TEST(FastPrims, EverySimdTargetMatchesTheReference) {
  PipelineContext two(2);
  for (const std::string& target : fast::available_simd_targets()) {
    ASSERT_TRUE(fast::force_simd_target(target));
    for (unsigned seed = 2000; seed < 2060; ++seed) {
      std::string diff = check_prims(seed, {&two});
      EXPECT_EQ(diff, "") << target;
      if (!diff.empty()) break;
    }
  }
  fast::force_simd_target("");
}

// A draw of aliased points over prim_draw's vertices and state (smooth points mostly
// turned off): pixel-exact positions (centres, corners, anywhere, some off the framebuffer)
// in most, fragment extras (the scissor box among them) and a texture in some.
RandomDraw point_draw(RandomDraws& random, glm::ivec2 size) {
  RandomDraw d = random.prim_draw(size);
  d.triangles.clear(), d.triangle_flags.clear(), d.lines.clear(), d.points.clear();
  d.frag.front_mode = d.frag.back_mode = PolygonMode::kFill;
  if (random.chance(0.9)) d.frag.point.smooth = false;
  if (random.chance(0.7)) {
    d.projection = glm::ortho(0.0f, float(size.x), 0.0f, float(size.y), -1.0f, 1.0f);
    d.viewport = {0, 0, size.x, size.y};
    for (glm::vec4& p : d.positions) {
      float x = random.uniform(-6, float(size.x) + 6), y = random.uniform(-6, float(size.y) + 6);
      if (random.chance(0.4)) x = std::floor(x), y = std::floor(y);
      else if (random.chance(0.4)) x = std::floor(x) + 0.5f, y = std::floor(y) + 0.5f;
      p = {x, y, random.uniform(-0.9f, 0.9f), 1.0f};
    }
  }
  for (std::uint32_t i = 0; i < d.positions.size(); ++i) {
    d.points.push_back(i);
    if (random.chance(0.1)) d.points.push_back(std::uint32_t(random.integer(0, int(d.positions.size()) - 1)));
  }
  if (random.chance(0.4)) random.fragment_extras(d, size);
  if (random.chance(0.3) && !d.texcoords.empty()) test::bind_random_texture(random, d);
  return d;
}

// Aliased points, which the fast pipeline draws as boxes of pixels (PointBox), in
// framebuffers whose tiles and blocks their squares straddle: the reference's pixels, depths,
// stencil values and counts, on every SIMD target.
TEST(FastPrims, PointsAsBoxesMatchTheReference) {
  PipelineContext one(1), two(2);
  for (const std::string& target : fast::available_simd_targets()) {
    ASSERT_TRUE(fast::force_simd_target(target));
    for (unsigned seed = 5000; seed < 5000 + random_cases(50); ++seed) {
      RandomDraws random(seed);
      const glm::ivec2 size = test::tiles_and_more(random, {1, 3}, {1, 2});
      Framebuffer initial = random.framebuffer(size);
      std::vector<RandomDraw> draws;
      for (int i = random.integer(1, 3); i > 0; --i) draws.push_back(point_draw(random, size));
      const std::string diff = compare_scene("point seed " + std::to_string(seed), initial, draws, {&one, &two});
      EXPECT_EQ(diff, "") << target;
      if (!diff.empty()) break;
    }
  }
  fast::force_simd_target("");
}

// Triangles clipped by user planes: the same polygons in both pipelines.
TEST(FastPrims, UserClipPlanesOnTrianglesMatchTheReference) {
  PipelineContext two(2);
  for (unsigned seed = 3000; seed < 3000 + random_cases(150); ++seed) {
    RandomDraws random(seed);
    glm::ivec2 size = random.size();
    Framebuffer initial = random.framebuffer(size);
    std::vector<RandomDraw> draws;
    for (int i = random.integer(1, 3); i > 0; --i) {
      draws.push_back(random.draw(size));
      random.clip_planes(draws.back().frag);
    }
    std::string diff = compare_scene("clip seed " + std::to_string(seed), initial, draws, {&two});
    ASSERT_EQ(diff, "");
  }
}

// A line strip drawn in two draws continues its stipple pattern: the counter runs on.
TEST(FastPrims, StippleRunsOnAcrossDraws) {
  Framebuffer a, b;
  a.resize(64, 16);
  a.clear_color(glm::vec4(0, 0, 0, 1));
  a.clear_depth(1.0f);
  b = a;
  FragmentState f;
  f.depth_test = false;
  f.line.stipple = true;
  f.line.pattern = 0x00ff;
  f.line.factor = 3;
  ShadeState shade;
  shade.lighting = false;
  const std::vector<glm::vec4> pos = {{2.5f, 8.5f, 0, 1}, {20.5f, 8.5f, 0, 1}, {41.5f, 8.5f, 0, 1}, {60.5f, 8.5f, 0, 1}};
  const glm::mat4 proj = glm::ortho(0.0f, 64.0f, 0.0f, 16.0f, -1.0f, 1.0f);
  const Viewport vp{0, 0, 64, 16};
  const std::vector<LineSegment> whole = {{{0, 1}}, {{1, 2}, 0}, {{2, 3}, 0}};
  const std::vector<LineSegment> first = {{{0, 1}}, {{1, 2}, 0}}, second = {{{2, 3}, 0}};
  for (PipelineContext* ctx : {static_cast<PipelineContext*>(nullptr), new PipelineContext(2)}) {
    VertexInput in;
    in.positions = pos;
    in.lines = whole;
    draw_triangles(a, proj, vp, f, shade, in, nullptr, ctx);
    std::uint32_t counter = 0;
    in.stipple_counter = &counter;
    in.lines = first;
    draw_triangles(b, proj, vp, f, shade, in, nullptr, ctx);
    EXPECT_EQ(counter, 39u);  // 18 + 21 pixels along x
    in.lines = second;
    draw_triangles(b, proj, vp, f, shade, in, nullptr, ctx);
    if (ctx) ctx->finish_draws();
    EXPECT_EQ(counter, 58u);
    EXPECT_TRUE(a.color == b.color);
    // The pattern: 3 pixels on per bit, 24 on then 24 off along the row.
    int lit = 0;
    for (int x = 0; x < 64; ++x) lit += a.color[std::size_t(8 * 64 + x) * 4] > 0;
    EXPECT_EQ(lit, 24 + 10);  // pixels 2..25 and 50..59 of the 58 drawn
    delete ctx;
  }
}

}  // namespace
}  // namespace shadelab
