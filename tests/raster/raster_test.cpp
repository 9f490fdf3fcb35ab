// Properties of the reference rasterizer through draw_triangles: no cracks and no double
// coverage (counted with additive blending), the top-left fill rule, perspective-correct
// interpolation, near-plane clipping, depth order, huge coordinates; and the parallelogram an
// aliased line is drawn as (reference_raster.inl), against its two triangles.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/stages.hpp"
#include "shadelab/pipeline.hpp"

namespace shadelab {
namespace {

constexpr int kW = 64, kH = 48;

// Draws unlit triangles (clip = eye with an identity projection unless given) adding 1/255 of
// red per covered pixel, so the red channel counts coverage.
struct CoverageCanvas {
  Framebuffer fb;
  FragmentState frag;
  CoverageCanvas(int w = kW, int h = kH) {
    fb.resize(w, h);
    fb.clear_color(glm::vec4(0, 0, 0, 1));
    frag.depth_test = false;
    frag.blend = {true, BlendFactor::kOne, BlendFactor::kOne};
  }
  void draw(const std::vector<glm::vec4>& pos, const std::vector<Triangle>& tris,
            const glm::mat4& projection = glm::mat4(1.0f)) {
    ShadeState shade;
    shade.lighting = false;
    VertexInput in;
    in.positions = pos;
    in.constant_color = glm::vec4(1.0f / 255.0f, 0, 0, 1);
    in.triangles = tris;
    draw_triangles(fb, projection, Viewport{0, 0, fb.width, fb.height}, frag, shade, in);
  }
  int count(int x, int y) const { return fb.color[(std::size_t(y) * fb.width + x) * 4]; }
};

// NDC coordinate of pixel-space x (0..w) so tests can place vertices in pixel units.
float ndc(float pixel, int size) { return pixel / size * 2.0f - 1.0f; }
glm::vec4 px(float x, float y) { return {ndc(x, kW), ndc(y, kH), 0.0f, 1.0f}; }

TEST(Raster, JitteredGridHasNoCracksAndNoOverlap) {
  // A square of 8x6 cells with randomly moved interior vertices: every pixel centre strictly
  // inside the square must be covered exactly once.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> jitter(-2.4f, 2.4f);
  const int nx = 8, ny = 6;
  std::vector<glm::vec4> pos;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      float x = 4.0f + i * 7.0f, y = 3.0f + j * 7.0f;  // square [4, 60] x [3, 45]
      bool interior = i > 0 && i < nx && j > 0 && j < ny;
      pos.push_back(px(x + (interior ? jitter(rng) : 0.0f), y + (interior ? jitter(rng) : 0.0f)));
    }
  }
  std::vector<Triangle> tris;
  auto at = [&](int i, int j) { return std::uint32_t(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      tris.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      tris.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  CoverageCanvas c;
  c.draw(pos, tris);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      bool inside = x + 0.5f > 4 && x + 0.5f < 60 && y + 0.5f > 3 && y + 0.5f < 45;
      ASSERT_EQ(c.count(x, y), inside ? 1 : 0) << "pixel " << x << "," << y;
    }
  }
}

TEST(Raster, ClosedOctahedronCoversEachPixelTwice) {
  // Front and back surfaces of a closed mesh (no culling, no depth test): exactly 2 inside.
  std::vector<glm::vec4> pos = {{0.7f, 0, 0, 1}, {-0.7f, 0, 0, 1}, {0, 0.7f, 0, 1},
                                {0, -0.7f, 0, 1}, {0, 0, 0.7f, 1}, {0, 0, -0.7f, 1}};
  glm::mat4 rot = glm::rotate(glm::mat4(1.0f), 0.37f, glm::vec3(0.3f, 1.0f, 0.2f));
  for (auto& p : pos) p = rot * p;
  std::vector<Triangle> tris = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  CoverageCanvas c;
  c.draw(pos, tris);
  int inside = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      int n = c.count(x, y);
      ASSERT_TRUE(n == 0 || n == 2) << "pixel " << x << "," << y << " covered " << n;
      inside += n == 2;
    }
  }
  EXPECT_GT(inside, 300);
}

TEST(Raster, FillRuleOnPixelCentres) {
  // Axis-aligned square whose edges pass exactly through pixel centres: x from 2.5 to 6.5,
  // y from 1.5 to 4.5. Left (x=2.5) and bottom (y=1.5, y up) centres are in; right and top
  // are out: columns 2..5, rows 1..3 -- what Mesa's llvmpipe draws for this square.
  std::vector<glm::vec4> pos = {px(2.5f, 1.5f), px(6.5f, 1.5f), px(6.5f, 4.5f), px(2.5f, 4.5f)};
  CoverageCanvas c;
  c.draw(pos, {{0, 1, 2}, {0, 2, 3}});
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 10; ++x) {
      bool in = x >= 2 && x <= 5 && y >= 1 && y <= 3;
      EXPECT_EQ(c.count(x, y), in ? 1 : 0) << "pixel " << x << "," << y;
    }
  }
}

TEST(Raster, SharedDiagonalThroughCentresDrawnOnce) {
  // Two triangles sharing a diagonal that passes through pixel centres (x = y).
  std::vector<glm::vec4> pos = {px(0.5f, 0.5f), px(20.5f, 0.5f), px(20.5f, 20.5f), px(0.5f, 20.5f)};
  CoverageCanvas c;
  c.draw(pos, {{0, 1, 2}, {0, 2, 3}});
  for (int i = 1; i < 20; ++i) EXPECT_EQ(c.count(i, i), 1) << "diagonal pixel " << i;
}

TEST(Raster, WindingDoesNotChangeCoverage) {
  CoverageCanvas ccw, cw;
  std::vector<glm::vec4> pos = {px(3.2f, 2.7f), px(40.1f, 9.3f), px(17.6f, 33.9f)};
  ccw.draw(pos, {{0, 1, 2}});
  cw.draw(pos, {{0, 2, 1}});
  EXPECT_EQ(ccw.fb.color, cw.fb.color);
}

TEST(Raster, PerspectiveCorrectInterpolation) {
  // A floor quad from z = -1 to z = -9 (eye space) seen by a perspective camera, red = 0 at
  // the near edge and 1 at the far edge. At a pixel whose centre sees depth z_e, the exact
  // value is (-1 - z_e) / 8, while screen-linear interpolation would give something else.
  Framebuffer fb;
  fb.resize(kW, kH);
  fb.clear_color(glm::vec4(0));
  glm::mat4 proj = glm::perspective(glm::radians(60.0f), float(kW) / kH, 0.5f, 20.0f);
  std::vector<glm::vec4> pos = {{-4, -1, -1, 1}, {4, -1, -1, 1}, {4, -1, -9, 1}, {-4, -1, -9, 1}};
  std::vector<glm::vec4> colors = {{0, 0, 0, 1}, {0, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, 1}};
  std::vector<Triangle> tris = {{0, 1, 2}, {0, 2, 3}};
  ShadeState shade;
  shade.lighting = false;
  VertexInput in;
  in.positions = pos;
  in.colors = colors;
  in.triangles = tris;
  FragmentState frag;
  draw_triangles(fb, proj, Viewport{0, 0, kW, kH}, frag, shade, in);
  // Pixel row y: the ray through its centre hits the plane y_e = -1 at z_e = -1 / t, where
  // t = tan(30 deg) * ndc_y (ndc_y < 0 below the horizon).
  int checked = 0;
  for (int y = 0; y < kH / 2; ++y) {
    float ndc_y = (y + 0.5f) / kH * 2.0f - 1.0f;
    float z_e = 1.0f / (std::tan(glm::radians(30.0f)) * ndc_y);  // negative
    if (z_e > -1.0f || z_e < -9.0f) continue;
    float expected = (-1.0f - z_e) / 8.0f;
    int actual = fb.color[(std::size_t(y) * kW + kW / 2) * 4];
    EXPECT_NEAR(actual, expected * 255.0f, 1.01f) << "row " << y;
    ++checked;
  }
  EXPECT_GT(checked, 5);
}

TEST(Raster, NearPlaneClipping) {
  // A triangle reaching behind the eye: only the part in front of the near plane is drawn,
  // and nothing is drawn where it would wrap around (w < 0).
  Framebuffer fb;
  fb.resize(kW, kH);
  fb.clear_color(glm::vec4(0, 0, 0, 1));
  glm::mat4 proj = glm::perspective(glm::radians(60.0f), float(kW) / kH, 1.0f, 50.0f);
  std::vector<glm::vec4> pos = {{-1, -1, -5, 1}, {1, -1, -5, 1}, {0, -1, 5, 1}};
  ShadeState shade;
  shade.lighting = false;
  VertexInput in;
  in.positions = pos;
  std::vector<Triangle> tris = {{0, 1, 2}};
  in.triangles = tris;
  FragmentState frag;
  RenderStats stats;
  draw_triangles(fb, proj, Viewport{0, 0, kW, kH}, frag, shade, in, &stats);
  EXPECT_EQ(stats.triangles_clipped, 1u);
  int lit = 0, upper = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      bool on = fb.color[(std::size_t(y) * kW + x) * 4] == 255;
      lit += on;
      upper += on && y >= kH / 2;  // the floor is below the eye: nothing above the horizon
    }
  }
  EXPECT_GT(lit, 100);
  EXPECT_EQ(upper, 0);
}

TEST(Raster, DepthTestKeepsNearestWhateverTheOrder) {
  for (int order = 0; order < 2; ++order) {
    Framebuffer fb;
    fb.resize(16, 16);
    fb.clear_color(glm::vec4(0));
    fb.clear_depth(1.0f);
    std::vector<glm::vec4> pos = {{-1, -1, 0.5f, 1}, {3, -1, 0.5f, 1}, {-1, 3, 0.5f, 1},
                                  {-1, -1, -0.5f, 1}, {3, -1, -0.5f, 1}, {-1, 3, -0.5f, 1}};
    std::vector<glm::vec4> colors(6, glm::vec4(1, 0, 0, 1));
    for (int i = 3; i < 6; ++i) colors[i] = glm::vec4(0, 1, 0, 1);  // the nearer one (z = -0.5)
    std::vector<Triangle> tris = order ? std::vector<Triangle>{{3, 4, 5}, {0, 1, 2}}
                                       : std::vector<Triangle>{{0, 1, 2}, {3, 4, 5}};
    ShadeState shade;
    shade.lighting = false;
    VertexInput in;
    in.positions = pos;
    in.colors = colors;
    in.triangles = tris;
    draw_triangles(fb, glm::mat4(1.0f), Viewport{0, 0, 16, 16}, FragmentState{}, shade, in);
    EXPECT_EQ(fb.color[(8 * 16 + 8) * 4 + 1], 255) << "order " << order;
    EXPECT_EQ(fb.color[(8 * 16 + 8) * 4 + 0], 0) << "order " << order;
    EXPECT_FLOAT_EQ(fb.depth[8 * 16 + 8], 0.25f);  // window z = (-0.5 + 1) / 2
  }
}

TEST(Raster, HugeCoordinatesCoverTheScreenOnce) {
  std::vector<glm::vec4> pos = {{-1e30f, -1e30f, 0, 1}, {1e30f, -1e30f, 0, 1}, {0, 1e30f, 0, 1}};
  CoverageCanvas c;
  c.draw(pos, {{0, 1, 2}});
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) ASSERT_EQ(c.count(x, y), 1) << x << "," << y;
}

TEST(Raster, CullingByWindowWinding) {
  std::vector<glm::vec4> pos = {px(2, 2), px(30, 2), px(2, 30)};  // counter-clockwise
  for (CullMode mode : {CullMode::kNone, CullMode::kBack, CullMode::kFront}) {
    CoverageCanvas c;
    c.frag.cull = mode;
    c.draw(pos, {{0, 1, 2}});
    EXPECT_EQ(c.count(5, 5), mode == CullMode::kFront ? 0 : 1);
    CoverageCanvas d;
    d.frag.cull = mode;
    d.draw(pos, {{0, 2, 1}});  // clockwise: a back face
    EXPECT_EQ(d.count(5, 5), mode == CullMode::kBack ? 0 : 1);
  }
}

using PixelFragments = std::map<std::pair<int, int>, detail::Fragment>;

template <class Raster>
PixelFragments fragments_of(Raster&& raster) {
  PixelFragments out;
  raster([&](const detail::Fragment& f) { EXPECT_TRUE(out.emplace(std::pair{f.x, f.y}, f).second); });
  return out;
}

TEST(Raster, ParallelogramCoversItsTwoTrianglesWithTheFirstOnesPlane) {
  // Random parallelograms a, b, c, d = a + c - b on 1/256-pixel corners (lines' sides through
  // pixel centres among them), in both windings: the pixels are those of triangles (a, b, c)
  // and (a, c, d) together (clockwise: none); every fragment takes (a, b, c)'s plane, those
  // of (a, b, c) bit for bit, those past its diagonal within rounding of the plane extended
  // (d's values are the plane's there).
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> pos(0, 40 * 256), side(-12 * 256, 12 * 256);
  std::uniform_real_distribution<float> value(-2.0f, 2.0f);
  int drawn = 0, past_diagonal = 0;
  for (int round = 0; round < 400; ++round) {
    // Every fourth: a 2-pixel line's corners, its ends on pixel centres' columns.
    const bool line = round % 4 == 0;
    const int ax = line ? (pos(rng) & ~255) + 128 : pos(rng), ay = line ? (pos(rng) & ~255) + 128 : pos(rng);
    const int ux = line ? side(rng) & ~255 : side(rng), uy = side(rng);
    const int vx = line ? 0 : side(rng), vy = line ? 512 : side(rng);
    const double k = 1.0 / 256.0;
    detail::Attribs attr[4]{};
    float z[4];
    for (int i = 0; i < 3; ++i) {
      z[i] = value(rng) * 0.25f + 0.5f;
      for (float& a : attr[i]) a = value(rng);
    }
    z[3] = z[0] + z[2] - z[1];
    for (int j = 0; j < detail::kAttrCount; ++j) attr[3][std::size_t(j)] = attr[0][std::size_t(j)] + attr[2][std::size_t(j)] - attr[1][std::size_t(j)];
    const double x[4] = {ax * k, (ax + ux) * k, (ax + ux + vx) * k, (ax + vx) * k};
    const double y[4] = {ay * k, (ay + uy) * k, (ay + uy + vy) * k, (ay + vy) * k};
    detail::WindowVertex v[4];
    for (int i = 0; i < 4; ++i) v[i] = {x[i], y[i], z[i], 1.0f, &attr[i]};
    const bool ccw = (double(ux) * (uy + vy) - double(uy) * (ux + vx)) > 0;
    const PixelFragments quad = fragments_of([&](auto emit) { detail::rasterize_parallelogram(v[0], v[1], v[2], v[3], kW, kH, 0, emit); });
    const PixelFragments first = fragments_of([&](auto emit) { detail::rasterize_triangle(v[0], v[1], v[2], kW, kH, 0, emit); });
    const PixelFragments second = fragments_of([&](auto emit) { detail::rasterize_triangle(v[0], v[2], v[3], kW, kH, 0, emit); });
    if (!ccw) {
      EXPECT_TRUE(quad.empty()) << "round " << round;
      continue;
    }
    ASSERT_EQ(quad.size(), first.size() + second.size()) << "round " << round;
    drawn += int(quad.size());
    for (const auto& [at, f] : quad) {
      const auto in_first = first.find(at);
      if (in_first != first.end()) {
        ASSERT_EQ(f.z, in_first->second.z) << "round " << round;
        ASSERT_EQ(f.attr, in_first->second.attr) << "round " << round;
        continue;
      }
      const auto in_second = second.find(at);
      ASSERT_NE(in_second, second.end()) << "round " << round << " pixel " << at.first << "," << at.second;
      ++past_diagonal;
      EXPECT_NEAR(f.z, in_second->second.z, 1e-5f) << "round " << round;
      for (int j = 0; j < detail::kAttrCount; ++j) {
        EXPECT_NEAR(f.attr[std::size_t(j)], in_second->second.attr[std::size_t(j)], 1e-4f) << "round " << round;
      }
    }
  }
  EXPECT_GT(drawn, 5000);
  EXPECT_GT(past_diagonal, 2000);
}

}  // namespace
}  // namespace shadelab
