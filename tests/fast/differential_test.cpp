// The fast pipeline against the reference: randomized draws (random_draws.hpp) rendered by
// draw_triangles with and without a PipelineContext (1, 2 and 3 threads, and every SIMD
// target this CPU runs). Coverage, depth and stencil must be identical, colours within 1/255.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <limits>
#include <sstream>

#include "differential.hpp"
#include "fast/draw_fast.hpp"
#include "fast/simd_targets.hpp"
#include "random_draws.hpp"

namespace shadelab {
namespace {

using test::random_cases;
using test::compare_buffers;
using test::compare_captures;
using test::RandomDraw;
using test::RandomDraws;
using test::render;
using test::Result;
using test::check_seed;
using test::simd_only;

TEST(FastDifferential, RandomDrawsMatchTheReference) {
  PipelineContext one(1), two(2), three(3);
  for (unsigned seed = 1; seed <= random_cases(400); ++seed) {
    std::string diff = check_seed(seed, {&one, &two, &three});
    ASSERT_EQ(diff, "");
  }
}

TEST(FastDifferential, EverySimdTargetMatchesTheReference) {
  PipelineContext two(2);
  for (const std::string& target : fast::available_simd_targets()) {
    ASSERT_TRUE(fast::force_simd_target(target));
    EXPECT_EQ(fast::current_simd_target(), target);
    for (unsigned seed = 1000; seed < 1080; ++seed) {
      std::string diff = check_seed(seed, {&two});
      EXPECT_EQ(diff, "") << target;
      if (!diff.empty()) break;
    }
  }
  fast::force_simd_target("");
}

// Coverage counted exactly: unlit additive drawing of 1/255 per fragment, no depth test.
TEST(FastDifferential, CoverageCountsAreIdentical) {
  PipelineContext three(3);
  for (unsigned seed = 2000; seed < 2000 + random_cases(150); ++seed) {
    RandomDraws random(seed);
    glm::ivec2 size = random.size();
    Framebuffer initial;
    initial.resize(size.x, size.y);
    std::vector<RandomDraw> draws;
    for (int i = random.integer(1, 3); i > 0; --i) {
      RandomDraw d = random.draw(size);
      d.frag = FragmentState{};
      d.frag.cull = CullMode(random.integer(0, 2));
      d.frag.depth_test = false;
      d.frag.blend = {true, BlendFactor::kOne, BlendFactor::kOne};
      d.shade.lighting = false;
      for (TextureUnit& u : d.shade.textures) u.texture = nullptr;
      d.colors.clear();
      d.back_colors.clear();
      // No secondary colour either: its interpolated sum is within a step of the
      // reference's, not equal (compare_buffers' tolerance), and would hide a count.
      d.secondary.clear();
      d.back_secondary.clear();
      d.constant_color = glm::vec4(1.0f / 255.0f, 1.0f / 255.0f, 1.0f / 255.0f, 1.0f / 255.0f);
      draws.push_back(std::move(d));
    }
    Result ref = render(initial, draws, nullptr);
    Result fast = render(initial, draws, &three);
    ASSERT_EQ(fast.fb.color, ref.fb.color) << "seed " << seed;
  }
}

// Deferred drawing (PipelineContext::set_deferred): the draws of a scene wait and are drawn
// tile by tile at finish_draws, over tiles with pending clears (drawn in a worker's tile
// buffer when the SIMD path draws them alone). The reference draws the same draws at once
// over the same framebuffer with those tiles cleared first. Textured, captured and shadowed
// draws cannot wait and finish the queue in between; long runs of draws fill it.
TEST(FastDifferential, DeferredDrawsMatchTheReference) {
  PipelineContext one(1), two(2);
  one.set_deferred(true);
  two.set_deferred(true);
  int buffered_scenes = 0;
  for (unsigned seed = 4000; seed < 4000 + random_cases(250); ++seed) {
    RandomDraws random(seed);
    glm::ivec2 size = random.size();
    if (random.chance(0.3)) size = {random.integer(128, 330), random.integer(128, 260)};
    Framebuffer initial = random.framebuffer(size);
    std::vector<RandomDraw> draws;
    const int count = random.chance(0.1) ? random.integer(60, 140) : random.integer(1, 6);
    for (int i = count; i > 0; --i) draws.push_back(random.draw(size));
    // Pending clears on some tiles, applied to the reference's framebuffer beforehand.
    const int columns = (size.x + PipelineContext::kTileSize - 1) / PipelineContext::kTileSize;
    const int tiles = columns * ((size.y + PipelineContext::kTileSize - 1) / PipelineContext::kTileSize);
    PipelineContext::PendingClears clears;
    clears.tiles.resize(std::size_t(tiles));
    const std::array<std::uint8_t, 4> bytes = {std::uint8_t(random.integer(0, 255)), std::uint8_t(random.integer(0, 255)),
                                               std::uint8_t(random.integer(0, 255)), std::uint8_t(random.integer(0, 255))};
    std::memcpy(&clears.color, bytes.data(), 4);
    clears.depth = random.uniform(0.0f, 1.0f);
    Framebuffer cleared = initial;
    for (int t = 0; t < tiles; ++t) {
      const std::uint8_t what = std::uint8_t(random.integer(0, 3));
      clears.tiles[std::size_t(t)] = what;
      const int x0 = (t % columns) * PipelineContext::kTileSize, y0 = (t / columns) * PipelineContext::kTileSize;
      for (int y = y0; y < std::min(size.y, y0 + PipelineContext::kTileSize); ++y) {
        for (int x = x0; x < std::min(size.x, x0 + PipelineContext::kTileSize); ++x) {
          const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
          if (what & PipelineContext::PendingClears::kColor) std::memcpy(&cleared.color[i * 4], bytes.data(), 4);
          if (what & PipelineContext::PendingClears::kDepth) cleared.depth[i] = clears.depth;
        }
      }
    }
    buffered_scenes += size.x >= PipelineContext::kTileSize && size.y >= PipelineContext::kTileSize;
    Result ref = render(cleared, draws, nullptr);
    for (PipelineContext* ctx : {&one, &two}) {
      Result fast;
      fast.fb = initial;
      fast.capture.pixels.resize(std::size_t(size.x) * std::size_t(size.y));
      ctx->pending_clears() = clears;
      std::size_t waited = 0;
      for (const RandomDraw& d : draws) {
        FragmentState frag = d.frag;
        if (d.capture) frag.capture = &fast.capture;
        VertexInput in = d.input();
        draw_triangles(fast.fb, d.projection, d.viewport, frag, d.shade, in, nullptr, ctx);
        waited = std::max(waited, ctx->deferred_draws());
      }
      ctx->apply_pending_clears(fast.fb);
      ASSERT_EQ(ctx->deferred_draws(), 0u);
      ASSERT_LE(waited, fast::kMaxQueuedDraws);
      const std::string where = "seed " + std::to_string(seed) + " threads " + std::to_string(ctx->threads()) + ": ";
      ASSERT_EQ(compare_buffers(fast.fb, ref.fb) + compare_captures(fast.capture, ref.capture), "") << where;
    }
  }
  EXPECT_GT(buffered_scenes, int(random_cases(250)) / 5);
}

// A wall of small quads at random depths, then large layers at the wall's farthest depth,
// or a few float steps in front of it, flat or sloped, with GL_LESS or GL_LEQUAL, opaque or
// blended, over tiles with pending clears (drawn in tile buffers, where the tile's largest
// depth lets a layer that fails everywhere go undrawn: raster.cpp's behind_tile), untextured
// or textured (alpha-tested or not). Layers that pass anywhere must be drawn there: the same
// as the reference.
TEST(FastDifferential, TileDepthBoundHidesOnlyWhatFailsEverywhere) {
  PipelineContext ctx(2);
  ctx.set_deferred(true);
  const glm::ivec2 size{2 * PipelineContext::kTileSize + 40, 2 * PipelineContext::kTileSize};
  auto quad = [](RandomDraw& d, glm::vec2 lo, glm::vec2 hi, const float z[4], const glm::vec4& color) {
    const auto first = std::uint32_t(d.positions.size());
    const glm::vec2 corners[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
    for (int k = 0; k < 4; ++k) d.positions.emplace_back(corners[k], z[k], 1.0f), d.colors.push_back(color);
    d.triangles.push_back({first, first + 1, first + 2});
    d.triangles.push_back({first, first + 2, first + 3});
  };
  for (unsigned seed = 0; seed < 80; ++seed) {
    RandomDraws random(9000 + seed);
    const Framebuffer initial = random.framebuffer(size);
    const Viewport viewport{0, 0, size.x, size.y};
    std::vector<RandomDraw> draws(1);
    RandomDraw& wall = draws[0];  // until the layers are pushed
    wall.viewport = viewport;
    wall.shade.lighting = false;
    // NDC depths: the wall's in [-0.2, 0.2]; its farthest is where the layers go.
    float farthest = -1.0f;
    const int n = random.integer(4, 12);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const float z = random.chance(0.5) ? 0.2f : random.uniform(-0.2f, 0.2f);
        const float zs[4] = {z, z, z, z};
        farthest = std::max(farthest, z);
        const float step = 2.0f / float(n);
        quad(wall, {-1.0f + step * float(i), -1.0f + step * float(j)}, {-1.0f + step * float(i + 1), -1.0f + step * float(j + 1)},
             zs, random.color());
      }
    }
    const int layers = random.integer(1, 3);
    for (int l = 0; l < layers; ++l) {
      RandomDraw layer;
      layer.viewport = viewport;
      layer.shade.lighting = false;
      layer.frag.depth_func = random.chance(0.5) ? CompareFunc::kLess : CompareFunc::kLequal;
      layer.frag.blend.enabled = random.chance(0.5);
      // At the farthest depth, or a few floats in front of it at one corner (sloped).
      float zs[4] = {farthest, farthest, farthest, farthest};
      if (random.chance(0.5)) {
        zs[random.integer(0, 3)] = farthest - float(random.integer(1, 4)) * std::numeric_limits<float>::epsilon();
        if (random.chance(0.5)) zs[random.integer(0, 3)] = farthest + 0.1f;
      }
      quad(layer, {-1.0f, -1.0f}, {1.0f, 1.0f}, zs, random.color(0.2f));
      if (random.chance(0.4)) {  // textured (the textured kernel), alpha-tested sometimes
        layer.texture = std::make_shared<Texture>();
        TextureLevel level;
        level.width = level.height = 2;
        for (int k = 0; k < 16; ++k) level.rgba.push_back(std::uint8_t(random.integer(0, 255)));
        layer.texture->levels.push_back(level);
        layer.texture->min_filter = layer.texture->mag_filter =
            random.chance(0.5) ? TextureFilter::kNearest : TextureFilter::kLinear;
        layer.texcoords = {{0, 0, 0, 1}, {3, 0, 0, 1}, {3, 3, 0, 1}, {0, 3, 0, 1}};
        layer.shade.textures[0].texture = layer.texture.get();
        if (random.chance(0.5)) layer.frag.alpha_test = {true, CompareFunc::kGreater, 0.4f};
      }
      draws.push_back(layer);
    }
    const int columns = (size.x + PipelineContext::kTileSize - 1) / PipelineContext::kTileSize;
    const int tiles = columns * ((size.y + PipelineContext::kTileSize - 1) / PipelineContext::kTileSize);
    PipelineContext::PendingClears clears;
    clears.tiles.assign(std::size_t(tiles), PipelineContext::PendingClears::kColor | PipelineContext::PendingClears::kDepth);
    clears.color = 0xff204060u;
    clears.depth = 1.0f;
    Framebuffer cleared = initial;
    cleared.clear_color(glm::vec4(0x60, 0x40, 0x20, 0xff) / 255.0f);
    cleared.clear_depth(1.0f);
    Result ref = render(cleared, draws, nullptr);
    ASSERT_EQ(compare_buffers(render_cleared_later(initial, draws, ctx, clears), ref.fb), "") << "seed " << seed;
  }
}

// Textured and untextured quads (the textured and depth-testing kernels, which skip the blocks
// their tiles' depth bounds show hidden: raster-inl.h's block_bounds) at a few shared depths or
// sloped, mostly GL_LESS and GL_LEQUAL (equal depths pass one and fail the other), sometimes
// alpha-tested, blended or not writing depth; among them depth tests that raise a stored depth
// (GL_GREATER, GL_ALWAYS, GL_NOTEQUAL, GL_GEQUAL), which the bounds must follow. Tiles with and
// without a pending depth clear (in the tile buffer, or in place with unknown depth), over a
// noisy depth buffer sometimes, and sometimes more draws than the queue holds. On every SIMD
// target (blocks of 1 to 8 pixels a row). The same as the reference.
TEST(FastDifferential, BlockDepthBoundsSkipOnlyHiddenBlocks) {
  PipelineContext ctx(2);
  ctx.set_deferred(true);
  const CompareFunc others[] = {CompareFunc::kGreater, CompareFunc::kAlways, CompareFunc::kNotequal,
                                CompareFunc::kGequal, CompareFunc::kEqual};
  const float levels[] = {-0.5f, -0.2f, 0.0f, 0.2f, 0.5f};
  int textured_kernel = 0, cases = 0;
  const std::vector<std::string> targets = fast::available_simd_targets();
  for (unsigned seed = 0; seed < random_cases(12) * targets.size(); ++seed, ++cases) {
    const std::string& target = targets[seed % targets.size()];
    ASSERT_TRUE(fast::force_simd_target(target));
    RandomDraws random(9500 + seed);
    const glm::ivec2 size = test::tiles_and_more(random, {2, 3}, {1, 2});
    const Framebuffer initial = random.framebuffer(size);
    const Viewport viewport{0, 0, size.x, size.y};
    std::vector<RandomDraw> draws;
    const int count = random.chance(0.15) ? int(fast::kMaxQueuedDraws) + random.integer(-10, 60)
                                          : random.integer(10, 90);
    for (int k = 0; k < count; ++k) {
      RandomDraw d;
      d.viewport = viewport;
      d.shade.lighting = false;
      const float p = float(random.uniform(0.0f, 1.0f));
      d.frag.depth_func = p < 0.45f ? CompareFunc::kLess : p < 0.85f ? CompareFunc::kLequal : others[random.integer(0, 4)];
      d.frag.depth_write = random.chance(0.9);
      const bool textured = random.chance(0.75);
      for (int q = random.integer(1, 3); q > 0; --q) {
        glm::vec2 lo{random.uniform(-1.2f, 0.8f), random.uniform(-1.2f, 0.8f)};
        glm::vec2 hi = lo + glm::vec2(random.uniform(0.05f, 1.5f), random.uniform(0.05f, 1.5f));
        if (random.chance(0.15)) lo = {-1.0f, -1.0f}, hi = {1.0f, 1.0f};
        float z[4];
        const float level = levels[random.integer(0, 4)];
        for (float& v : z) v = level;
        if (random.chance(0.3)) {
          for (float& v : z) v = level + random.uniform(-0.3f, 0.3f);
        }
        const auto first = std::uint32_t(d.positions.size());
        const glm::vec2 corners[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
        for (int c = 0; c < 4; ++c) {
          d.positions.emplace_back(corners[c], z[c], 1.0f);
          d.colors.push_back(random.color(0.5f));
          d.texcoords.emplace_back(float(c == 1 || c == 2) * 2.0f, float(c >= 2) * 2.0f, 0.0f, 1.0f);
        }
        d.triangles.push_back({first, first + 1, first + 2});
        d.triangles.push_back({first, first + 2, first + 3});
      }
      if (textured) {
        test::bind_random_texture(random, d);
        d.shade.texture_kept = true;  // deferred: drawn together, tile by tile
        if (random.chance(0.6)) d.frag.alpha_test = {true, CompareFunc::kGreater, 0.5f};
      } else {
        d.texcoords.clear();
        d.frag.blend.enabled = random.chance(0.3);
      }
      textured_kernel += fast::kernel_textured(test::planned_kernel(d.frag, d.shade));
      draws.push_back(std::move(d));
    }
    const int columns = (size.x + PipelineContext::kTileSize - 1) / PipelineContext::kTileSize;
    const int tiles = columns * ((size.y + PipelineContext::kTileSize - 1) / PipelineContext::kTileSize);
    PipelineContext::PendingClears clears;
    clears.tiles.resize(std::size_t(tiles));
    clears.color = 0xff102030u;
    clears.depth = random.chance(0.5) ? 1.0f : random.uniform(0.3f, 1.0f);
    Framebuffer cleared = initial;
    for (int t = 0; t < tiles; ++t) {
      const std::uint8_t what = random.chance(0.7) ? PipelineContext::PendingClears::kColor | PipelineContext::PendingClears::kDepth
                                                   : std::uint8_t(random.integer(0, 1));
      clears.tiles[std::size_t(t)] = what;
      const int x0 = (t % columns) * PipelineContext::kTileSize, y0 = (t / columns) * PipelineContext::kTileSize;
      for (int y = y0; y < std::min(size.y, y0 + PipelineContext::kTileSize); ++y) {
        for (int x = x0; x < std::min(size.x, x0 + PipelineContext::kTileSize); ++x) {
          const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
          if (what & PipelineContext::PendingClears::kColor) std::memcpy(&cleared.color[i * 4], &clears.color, 4);
          if (what & PipelineContext::PendingClears::kDepth) cleared.depth[i] = clears.depth;
        }
      }
    }
    Result ref = render(cleared, draws, nullptr);
    ASSERT_EQ(compare_buffers(render_cleared_later(initial, draws, ctx, clears), ref.fb), "")
        << "seed " << seed << ", " << target;
  }
  fast::force_simd_target("");
  EXPECT_GT(textured_kernel, cases * 20);
}

// A textured quad of 40 x 40 pixels inside one tile (too small for the tile's depth bound),
// then the same quad behind it: the blocks whose every pixel the first one covers are not
// rasterized again (their fragments are not counted), in the tile buffer and in place; the
// blocks along its edges are. The image is the reference's.
TEST(FastDifferential, BlockDepthBoundsSkipAHiddenQuad) {
  const glm::ivec2 size{2 * PipelineContext::kTileSize, PipelineContext::kTileSize};
  for (const std::string& target : fast::available_simd_targets()) {
    ASSERT_TRUE(fast::force_simd_target(target));
    for (bool cleared : {true, false}) {
      PipelineContext ctx(1);
      ctx.set_deferred(true);
      ctx.set_counting(true);
      std::vector<RandomDraw> draws;
      for (float z : {-0.5f, 0.5f}) {
        RandomDraw d;
        d.viewport = {0, 0, size.x, size.y};
        d.shade.lighting = false;
        // Pixels 10 to 49 in x and y (window x = (ndc + 1) * 64, y = (ndc + 1) * 32).
        const glm::vec2 lo{-1.0f + 10.0f / 64.0f, -1.0f + 20.0f / 64.0f}, hi{-1.0f + 50.0f / 64.0f, -1.0f + 100.0f / 64.0f};
        const glm::vec2 corners[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
        for (int c = 0; c < 4; ++c) {
          d.positions.emplace_back(corners[c], z, 1.0f);
          d.colors.emplace_back(1.0f);
          d.texcoords.emplace_back(float(c == 1 || c == 2), float(c >= 2), 0.0f, 1.0f);
        }
        d.triangles = {{0, 1, 2}, {0, 2, 3}};
        d.texture = std::make_shared<Texture>();
        TextureLevel level;
        level.width = level.height = 2;
        level.rgba = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
        d.texture->levels.push_back(level);
        d.texture->min_filter = TextureFilter::kNearest;  // complete without mipmaps
        d.shade.textures[0].texture = d.texture.get();
        d.shade.texture_kept = true;  // the two draws wait, to be drawn in one pass over the tile
        ASSERT_EQ(test::planned_kernel(d.frag, d.shade), fast::BlockKernel::kTextured2D);
        draws.push_back(std::move(d));
      }
      Framebuffer initial;
      initial.resize(size.x, size.y);
      initial.clear_color(glm::vec4(0.0f));
      initial.clear_depth(1.0f);
      Result ref = render(initial, draws, nullptr);
      PipelineContext::PendingClears clears;
      if (cleared) {  // a pending clear: the tile is drawn in the tile buffer
        clears.tiles.assign(2, PipelineContext::PendingClears::kColor | PipelineContext::PendingClears::kDepth);
        clears.color = 0;
        clears.depth = 1.0f;
      }
      ASSERT_EQ(compare_buffers(render_cleared_later(initial, draws, ctx, clears), ref.fb), "");
      const RenderStats counts = ctx.take_counts();
      // The first quad's 1,600 fragments; of the second's, at most its edge blocks' (two
      // columns of blocks, 8 pixels wide at most, and a row of blocks above and below).
      EXPECT_GE(counts.fragments, 1600u) << target << ", cleared " << cleared;
      EXPECT_LE(counts.fragments, 1600u + 2 * 40 * 8 + 2 * 40 * 2) << target << ", cleared " << cleared;
    }
  }
  fast::force_simd_target("");
}

// The rasterizer visits only the blocks of a row that a wide triangle's edges can cover
// (raster-inl.h's row_span): fans of slivers (a disc, whose
// triangles' boxes are mostly empty), long thin triangles at every angle, large triangles
// with horizontal and vertical edges, vertices on pixel centres and on the lines between
// pixels (the fill rule's ties), in framebuffers that end inside a block, drawn by the
// kernels (the stencil and textured ones among them) and the general path (a colour channel
// masked) on every SIMD target: the
// fragments counted, depth, stencil and colours are the reference's.
TEST(FastDifferential, RowSpansCoverTheEdgesPixels) {
  PipelineContext two(2);
  const std::vector<std::string> targets = fast::available_simd_targets();
  int general = 0, stencil = 0, kernels = 0;
  for (unsigned seed = 0; seed < random_cases(16) * targets.size(); ++seed) {
    const std::string& target = targets[seed % targets.size()];
    ASSERT_TRUE(fast::force_simd_target(target));
    RandomDraws random(9800 + seed);
    const glm::ivec2 size = test::tiles_and_more(random, {1, 4}, {1, 3});
    const Framebuffer initial = random.framebuffer(size);
    // A point of the window snapped to a pixel's centre, its corner or anywhere, in NDC.
    auto point = [&](glm::vec2 window) {
      const float snap = float(random.uniform(0.0f, 1.0f));
      if (snap < 0.3f) window = glm::floor(window) + 0.5f;
      else if (snap < 0.5f) window = glm::floor(window);
      return window / glm::vec2(size) * 2.0f - 1.0f;
    };
    auto anywhere = [&] {  // (statements: the draws are the same whatever the compiler)
      const float x = random.uniform(-0.2f, 1.2f) * float(size.x);
      return glm::vec2(x, random.uniform(-0.2f, 1.2f) * float(size.y));
    };
    std::vector<RandomDraw> draws;
    for (int n = random.integer(2, 5); n > 0; --n) {
      RandomDraw d;
      d.viewport = {0, 0, size.x, size.y};
      d.shade.lighting = false;
      const bool one_colour = random.chance(0.4);
      const glm::vec4 colour = random.color(0.4f);
      auto vertex = [&](glm::vec2 ndc) {
        d.positions.emplace_back(ndc, random.uniform(-0.9f, 0.9f), 1.0f);
        d.colors.push_back(one_colour ? colour : random.color(0.4f));
        const float s = random.uniform(-1.0f, 2.0f);
        d.texcoords.emplace_back(s, random.uniform(-1.0f, 2.0f), 0.0f, 1.0f);
        return std::uint32_t(d.positions.size() - 1);
      };
      const int shape = random.integer(0, 3);
      if (shape == 0) {  // a disc of slivers around a centre
        const glm::vec2 centre = anywhere();
        const float radius = random.uniform(10.0f, 1.5f * float(std::max(size.x, size.y)));
        const int slices = random.integer(16, 128);
        const std::uint32_t middle = vertex(point(centre));
        std::uint32_t previous = vertex(point(centre + glm::vec2(radius, 0.0f)));
        for (int k = 1; k <= slices; ++k) {
          const float a = 6.2831853f * float(k) / float(slices);
          const std::uint32_t next = vertex(point(centre + radius * glm::vec2(std::cos(a), std::sin(a))));
          d.triangles.push_back({middle, previous, next});
          previous = next;
        }
      } else if (shape == 1) {  // long thin triangles at any angle, either winding
        for (int k = random.integer(5, 40); k > 0; --k) {
          const glm::vec2 a = anywhere(), b = anywhere();
          const glm::vec2 across = glm::normalize(glm::vec2(a.y - b.y, b.x - a.x) + 1e-6f);
          const glm::vec2 end = random.chance(0.5) ? a : b;
          const glm::vec2 c = end + across * random.uniform(-3.0f, 3.0f);
          d.triangles.push_back({vertex(point(a)), vertex(point(b)), vertex(point(c))});
        }
      } else {  // large triangles with horizontal and vertical edges, and any others
        for (int k = random.integer(1, 6); k > 0; --k) {
          const glm::vec2 a = anywhere(), b = anywhere();
          const glm::vec2 c = shape == 2 ? glm::vec2(a.x, b.y) : anywhere();
          d.triangles.push_back({vertex(point(a)), vertex(point(b)), vertex(point(c))});
        }
      }
      const int state = random.integer(0, 5);
      d.frag.depth_test = state != 0;
      d.frag.depth_func = random.chance(0.5) ? CompareFunc::kLess : CompareFunc::kLequal;
      d.frag.blend.enabled = random.chance(0.25);
      if (state == 3) {  // the stencil kernel: the stencil test and its operations
        d.frag.stencil.enabled = true;
        d.frag.stencil.func = CompareFunc(random.integer(0, 7));
        d.frag.stencil.ref = random.integer(0, 3);
        d.frag.stencil.pass = StencilOp::kIncr;
        d.frag.stencil.depth_fail = StencilOp::kInvert;
      }
      if (state == 5) d.frag.color_mask[random.integer(0, 3)] = false;  // the general path
      if (state == 4) {  // the textured kernel
        test::bind_random_texture(random, d);
      } else {
        d.texcoords.clear();
      }
      const fast::BlockKernel kernel = test::planned_kernel(d.frag, d.shade);
      general += kernel == fast::BlockKernel::kGeneral;
      stencil += kernel == fast::BlockKernel::kStencil;
      kernels += kernel != fast::BlockKernel::kGeneral;
      draws.push_back(std::move(d));
    }
    const std::string diff = test::compare_scene("seed " + std::to_string(seed) + ", " + target, initial, draws, {&two});
    ASSERT_EQ(diff, "");
  }
  fast::force_simd_target("");
  EXPECT_GT(general, 0);
  EXPECT_GT(stencil, 0);
  EXPECT_GT(kernels, 0);
}

// The stencil kernel (BlockKernel::kStencil) against the reference on every SIMD target: every
// stencil function and operation, value and write masks, stencil values at 0 and 255 (where
// the clamped and wrapping operations part), with and without the depth test (any function,
// written or not), colours opaque, blended by source alpha or not written at all: the
// fragments counted, stencil, depth and colours are the reference's.
TEST(FastDifferential, StencilKernelMatchesTheReference) {
  PipelineContext two(2);
  const std::vector<std::string> targets = fast::available_simd_targets();
  int stencil_kernel = 0, masks_only = 0;
  for (unsigned seed = 0; seed < random_cases(24) * targets.size(); ++seed) {
    const std::string& target = targets[seed % targets.size()];
    ASSERT_TRUE(fast::force_simd_target(target));
    RandomDraws random(9900 + seed);
    const glm::ivec2 size = test::tiles_and_more(random, {1, 3}, {1, 2});
    Framebuffer initial = random.framebuffer(size);
    constexpr std::uint8_t kValues[] = {0, 1, 2, 3, 127, 254, 255};
    for (std::uint8_t& v : initial.stencil) v = kValues[random.integer(0, 6)];
    std::vector<RandomDraw> draws;
    for (int n = random.integer(2, 5); n > 0; --n) {
      RandomDraw d = random.draw(size);
      test::simd_only(d);
      if (d.shade.shading == ShadingMode::kPhong) d.shade.shading = ShadingMode::kGouraud;
      StencilState& s = d.frag.stencil;
      s.enabled = true;
      s.func = CompareFunc(random.integer(0, 7));
      s.ref = kValues[random.integer(0, 6)];
      s.value_mask = random.chance(0.5) ? 0xff : std::uint8_t(random.integer(0, 255));
      s.write_mask = random.chance(0.5) ? 0xff : std::uint8_t(random.integer(0, 255));
      s.fail = StencilOp(random.integer(0, 7));
      s.depth_fail = StencilOp(random.integer(0, 7));
      s.pass = StencilOp(random.integer(0, 7));
      d.frag.depth_test = random.chance(0.8);
      d.frag.depth_func = CompareFunc(random.integer(0, 7));
      d.frag.depth_write = random.chance(0.7);
      const bool colour = random.chance(0.7);
      for (bool& m : d.frag.color_mask) m = colour;
      d.frag.blend = {random.chance(0.3), BlendFactor::kSrcAlpha, BlendFactor::kOneMinusSrcAlpha};
      const fast::BlockKernel kernel = test::planned_kernel(d.frag, d.shade);
      stencil_kernel += kernel == fast::BlockKernel::kStencil;
      masks_only += kernel == fast::BlockKernel::kStencil && !colour;
      draws.push_back(std::move(d));
    }
    const std::string diff = test::compare_scene("seed " + std::to_string(seed) + ", " + target, initial, draws, {&two});
    ASSERT_EQ(diff, "");
  }
  fast::force_simd_target("");
  EXPECT_GT(stencil_kernel, 20);
  EXPECT_GT(masks_only, 5);
}

// The kernel make_plan chooses for an untextured stencil-tested draw: kStencil with every
// colour channel written (opaque or blended by source alpha) or none, fogged or not; the
// general path for some channels masked, another blend, the alpha test, a logic op or
// per-pixel lighting.
TEST(FastDifferential, TheStencilKernelOnlyWithoutOtherState) {
  auto kernel = [&](auto&& change) {
    FragmentState frag;
    ShadeState shade;
    shade.lighting = false;
    frag.stencil.enabled = true;
    change(frag, shade);
    return test::planned_kernel(frag, shade);
  };
  using fast::BlockKernel;
  EXPECT_EQ(kernel([](FragmentState&, ShadeState&) {}), BlockKernel::kStencil);
  EXPECT_EQ(kernel([](FragmentState& f, ShadeState&) {
              f.depth_func = CompareFunc::kGreater;
              f.depth_write = false;
              f.blend.enabled = true;
            }),
            BlockKernel::kStencil);
  EXPECT_EQ(kernel([](FragmentState& f, ShadeState&) {
              for (bool& m : f.color_mask) m = false;
              f.blend = {true, BlendFactor::kOne, BlendFactor::kOne};
            }),
            BlockKernel::kStencil);
  EXPECT_EQ(kernel([](FragmentState& f, ShadeState&) { f.color_mask[3] = false; }), BlockKernel::kGeneral);
  EXPECT_EQ(kernel([](FragmentState& f, ShadeState&) { f.blend = {true, BlendFactor::kOne, BlendFactor::kOne}; }),
            BlockKernel::kGeneral);
  EXPECT_EQ(kernel([](FragmentState& f, ShadeState&) { f.alpha_test = {true, CompareFunc::kGreater, 0.5f}; }),
            BlockKernel::kGeneral);
  EXPECT_EQ(kernel([](FragmentState& f, ShadeState&) { f.logic_op.enabled = true; }), BlockKernel::kGeneral);
  EXPECT_EQ(kernel([](FragmentState&, ShadeState& s) { s.fog.enabled = true; }), BlockKernel::kStencil);
  EXPECT_EQ(kernel([](FragmentState&, ShadeState& s) {
              s.lighting = true;
              s.shading = ShadingMode::kPhong;
            }),
            BlockKernel::kGeneral);
}

// clear_later: every tile cleared, by the draws into it (drawn after the clear) or by
// apply_pending_clears; a later clear_later's values replace the pending ones; a draw waiting
// before it is drawn before it. The same as clearing at once.
TEST(FastDifferential, ClearLaterIsAClear) {
  for (bool deferred : {false, true}) {
    PipelineContext ctx(2);
    ctx.set_deferred(deferred);
    RandomDraws random(31);
    const glm::ivec2 size{150, 100};
    const Framebuffer initial = random.framebuffer(size);
    RandomDraw before = random.draw(size), after = random.draw(size);
    simd_only(before);
    simd_only(after);
    const glm::vec4 first_color{0.2f, 0.4f, 0.6f, 0.8f}, color{0.9f, 0.1f, 0.3f, 1.0f};
    // The reference: draw, clear at once, draw.
    Framebuffer ref = initial;
    VertexInput in_before = before.input(), in_after = after.input();
    draw_triangles(ref, before.projection, before.viewport, before.frag, before.shade, in_before, nullptr, nullptr);
    ref.clear_color(color);
    ref.clear_depth(0.75f);
    draw_triangles(ref, after.projection, after.viewport, after.frag, after.shade, in_after, nullptr, nullptr);
    Framebuffer fast = initial;
    draw_triangles(fast, before.projection, before.viewport, before.frag, before.shade, in_before, nullptr, &ctx);
    ctx.clear_later(fast, PipelineContext::PendingClears::kColor, first_color, 0.0f);
    ctx.clear_later(fast, PipelineContext::PendingClears::kColor | PipelineContext::PendingClears::kDepth, color, 0.75f);
    draw_triangles(fast, after.projection, after.viewport, after.frag, after.shade, in_after, nullptr, &ctx);
    ctx.apply_pending_clears(fast);
    ASSERT_EQ(compare_buffers(fast, ref), "") << (deferred ? "deferred" : "at once");
  }
}

// A pending depth clear outlives draws that do not test depth: their tiles' colour is drawn
// (in the tile buffers) but their depth is left alone, still to be cleared; a later draw
// that tests depth, or apply_pending_clears, clears it first. Both orders, both ways of
// drawing (at once and deferred), against clearing at once.
TEST(FastDifferential, DepthClearWaitsForADrawThatTestsDepth) {
  for (bool deferred : {false, true}) {
    for (bool second_tests_depth : {false, true}) {
      PipelineContext ctx(2);
      ctx.set_deferred(deferred);
      RandomDraws random(77);
      const glm::ivec2 size{3 * PipelineContext::kTileSize, 2 * PipelineContext::kTileSize + 10};
      const Framebuffer initial = random.framebuffer(size);
      RandomDraw first = random.draw(size), second = random.draw(size);
      simd_only(first);
      simd_only(second);
      first.frag.depth_test = false;
      second.frag.depth_test = second_tests_depth;
      const glm::vec4 color{0.3f, 0.5f, 0.7f, 1.0f};
      Framebuffer ref = initial;
      ref.clear_color(color);
      ref.clear_depth(0.6f);
      VertexInput in_first = first.input(), in_second = second.input();
      draw_triangles(ref, first.projection, first.viewport, first.frag, first.shade, in_first, nullptr, nullptr);
      draw_triangles(ref, second.projection, second.viewport, second.frag, second.shade, in_second, nullptr, nullptr);
      Framebuffer fast = initial;
      ctx.clear_later(fast, PipelineContext::PendingClears::kColor | PipelineContext::PendingClears::kDepth, color, 0.6f);
      draw_triangles(fast, first.projection, first.viewport, first.frag, first.shade, in_first, nullptr, &ctx);
      ctx.finish_draws();
      draw_triangles(fast, second.projection, second.viewport, second.frag, second.shade, in_second, nullptr, &ctx);
      ctx.apply_pending_clears(fast);
      ASSERT_EQ(compare_buffers(fast, ref), "")
          << (deferred ? "deferred" : "at once") << (second_tests_depth ? ", then a depth-tested draw" : "");
    }
  }
}

// Clears started ahead on a worker (clear_ahead) are the clears left pending: for every
// list of tiles (none, some, every tile, a tile twice, tiles out of range), with draws made
// after it that reach cleared tiles and others, deferred or at once, on 1 to 4 threads (one
// thread: it does nothing), the image is the reference's; started again once the clears are
// applied, it clears nothing.
TEST(FastDifferential, ClearsStartedAheadAreTheClearsLeftPending) {
  RandomDraws random(43);
  const glm::ivec2 size{200, 140};  // 4 x 3 tiles, partial ones on two sides
  const Framebuffer initial = random.framebuffer(size);
  const glm::vec4 color{0.9f, 0.1f, 0.3f, 1.0f};
  const std::vector<std::vector<int>> lists = {{}, {0, 5, 11}, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, {3, 3, 7}, {-1, 2, 12, 400}};
  for (int threads = 1; threads <= 4; ++threads) {
    for (bool deferred : {false, true}) {
      for (std::size_t l = 0; l < lists.size(); ++l) {
        RandomDraw d = random.draw(size);
        simd_only(d);
        VertexInput in = d.input();
        Framebuffer ref = initial;
        ref.clear_color(color);
        ref.clear_depth(0.75f);
        draw_triangles(ref, d.projection, d.viewport, d.frag, d.shade, in, nullptr, nullptr);
        Framebuffer fast = initial;
        PipelineContext ctx(threads);  // ends before `fast` (it may still clear it)
        ctx.set_deferred(deferred);
        ctx.clear_later(fast, PipelineContext::PendingClears::kColor | PipelineContext::PendingClears::kDepth, color, 0.75f);
        ctx.clear_ahead(fast, PipelineContext::PendingClears::kColor, lists[l]);
        draw_triangles(fast, d.projection, d.viewport, d.frag, d.shade, in, nullptr, &ctx);
        ctx.finish_draws();
        // Drawn tiles' clears were applied: started again, it changes nothing.
        ctx.clear_ahead(fast, PipelineContext::PendingClears::kColor | PipelineContext::PendingClears::kDepth, lists[l]);
        ctx.apply_pending_clears(fast);
        ASSERT_EQ(compare_buffers(fast, ref), "") << threads << " threads, " << (deferred ? "deferred" : "at once")
                                                  << ", list " << l;
        // Started and never waited for: the context's end waits for it.
        ctx.clear_later(fast, PipelineContext::PendingClears::kColor, color, 0.0f);
        ctx.clear_ahead(fast, PipelineContext::PendingClears::kColor, lists[l]);
      }
    }
  }
}

// Draws wait only while deferred drawing is on, and only those that own what they read.
TEST(FastDifferential, OnlyDrawsThatOwnTheirInputsWait) {
  PipelineContext ctx(2);
  RandomDraws random(77);
  const glm::ivec2 size{96, 80};
  Framebuffer fb = random.framebuffer(size);
  RandomDraw d = random.draw(size);
  simd_only(d);
  VertexInput in = d.input();
  draw_triangles(fb, d.projection, d.viewport, d.frag, d.shade, in, nullptr, &ctx);
  EXPECT_EQ(ctx.deferred_draws(), 0u);  // off by default
  ctx.set_deferred(true);
  draw_triangles(fb, d.projection, d.viewport, d.frag, d.shade, in, nullptr, &ctx);
  draw_triangles(fb, d.projection, d.viewport, d.frag, d.shade, in, nullptr, &ctx);
  EXPECT_EQ(ctx.deferred_draws(), 2u);
  RenderStats stats;  // counts asked for: drawn at once, after the waiting draws
  draw_triangles(fb, d.projection, d.viewport, d.frag, d.shade, in, &stats, &ctx);
  EXPECT_EQ(ctx.deferred_draws(), 0u);
  draw_triangles(fb, d.projection, d.viewport, d.frag, d.shade, in, nullptr, &ctx);
  EXPECT_EQ(ctx.deferred_draws(), 1u);
  ctx.set_deferred(false);  // finishes the waiting draw
  EXPECT_EQ(ctx.deferred_draws(), 0u);
}

// Specular powers past the largest float: normals of length 2 to 3 (as GL draws them without
// GL_NORMALIZE) make the specular cosine exceed 1, and a shininess that is not a whole number
// takes exp(e log c), whose argument then passes Highway's Exp range. The reference's
// std::pow overflows to infinity and the colour clamps to 1; the fast pipeline must too,
// per vertex and per pixel (it made those vertices black).
TEST(FastDifferential, OverflowingSpecularPowersMatchTheReference) {
  PipelineContext two(2);
  int lit = 0;
  for (unsigned seed = 5000; seed < 5080; ++seed) {
    RandomDraws random(seed);
    glm::ivec2 size = random.size();
    Framebuffer initial = random.framebuffer(size);
    RandomDraw d = random.draw(size);
    d.shade.lighting = true;
    d.shade.shading = seed % 2 ? ShadingMode::kPhong : ShadingMode::kGouraud;
    simd_only(d);
    d.shade.front.shininess = d.shade.back.shininess = 109.25f;
    d.shade.front.specular = d.shade.back.specular = glm::vec4(0.5f, 0.25f, 0.75f, 1.0f);
    d.normals.resize(d.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    for (glm::vec3& n : d.normals) n = glm::normalize(n + glm::vec3(0.0f, 0.0f, 1e-3f)) * random.uniform(2.0f, 3.0f);
    Result ref = render(initial, {d}, nullptr);
    Result fast = render(initial, {d}, &two);
    lit += ref.stats.pixels_shaded > 0;
    EXPECT_EQ(compare_buffers(fast.fb, ref.fb), "") << "seed " << seed;
  }
  EXPECT_GT(lit, 30);
}

// Varyings that are not finite (an infinite or NaN normal, eye positions whose differences
// overflow) take the reference's own arithmetic in the fast path: per-pixel Phong draws with
// such vertices still match it.
TEST(FastDifferential, NonFiniteVaryingsMatchTheReference) {
  PipelineContext two(2);
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  int drawn = 0;
  for (unsigned seed = 3000; seed < 3060; ++seed) {
    RandomDraws random(seed);
    glm::ivec2 size = random.size();
    Framebuffer initial = random.framebuffer(size);
    RandomDraw d = random.draw(size);
    d.shade.lighting = true;
    d.shade.shading = ShadingMode::kPhong;
    simd_only(d);
    d.normals.resize(d.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    for (std::size_t v = 0; v < d.normals.size(); v += 3) d.normals[v] = glm::vec3(inf, 1.0f, 0.0f);
    for (std::size_t v = 1; v < d.normals.size(); v += 5) d.normals[v] = glm::vec3(0.0f, nan, 1.0f);
    Result ref = render(initial, {d}, nullptr);
    Result fast = render(initial, {d}, &two);
    drawn += ref.stats.pixels_shaded > 0;
    EXPECT_EQ(fast.stats.pixels_shaded, ref.stats.pixels_shaded) << "seed " << seed;
    EXPECT_EQ(compare_buffers(fast.fb, ref.fb), "") << "seed " << seed;
  }
  EXPECT_GT(drawn, 20);  // the draws do reach the fragment stage
}

}  // namespace
}  // namespace shadelab
