// The lecture's row experiments say what the lecture says, asserted on pixels of the scene
// files the gallery renders: the mesh-size row and the spot cutoff row; and sweep's errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"
#include "support/test_support.hpp"

namespace shadelab {
namespace {

Image render_lecture(const std::string& file, std::vector<std::string> overrides,
                     std::optional<ShadingMode> mode = std::nullopt) {
  LoadOptions o;
  o.overrides = std::move(overrides);
  LoadResult r = load_scene_file(std::string(SHADELAB_SOURCE_DIR) + "/scenes/lecture/" + file, o);
  EXPECT_TRUE(r.scene) << r.diagnostics.to_string();
  return r.scene ? render_scene(*r.scene, RenderOptions{mode, std::nullopt}) : Image{};
}

int centre_red(const Image& img) { return img.pixel(img.width / 2, img.height / 2)[0]; }
int corner_red(const Image& img) { return img.pixel(img.width / 8, img.height / 8)[0]; }

TEST(LectureRows, MeshSizeGouraudNeedsVerticesPhongDoesNot) {
  auto wall = [](int n) {
    std::string s = std::to_string(n);
    return "objects[0].shape={\"type\":\"wall\",\"width\":8,\"height\":8,\"nx\":" + s + ",\"ny\":" + s + "}";
  };
  Image g1 = render_lecture("07-mesh-size.json", {wall(1), "image.width=101", "image.height=101"});
  Image g20 = render_lecture("07-mesh-size.json", {wall(20), "image.width=101", "image.height=101"});
  // 1x1: the centre is no brighter than the rest (no highlight); 20x20: a white highlight.
  EXPECT_LE(centre_red(g1), corner_red(g1) + 2);
  EXPECT_GE(centre_red(g20), 250);
  EXPECT_GT(centre_red(g20), corner_red(g20) + 100);
  for (int n : {1, 2, 4, 10, 20}) {
    Image p = render_lecture("07-mesh-size.json", {wall(n), "image.width=101", "image.height=101"},
                             ShadingMode::kPhong);
    EXPECT_GE(centre_red(p), 250) << n << " x " << n;
  }
}

TEST(LectureRows, SpotDiscRadiusFollowsTanCutoff) {
  // The spot is 2 units from the wall; the view is 4.287 units high (fovy 30 at distance 8).
  const int size = 200;
  double world_per_pixel = 2 * 8 * std::tan(15 * M_PI / 180) / size;
  double previous = 1e9;
  for (int cutoff : {50, 40, 30, 20}) {
    Image img = render_lecture("10-spot-cutoff.json",
                               {"lights[0].spot.cutoff=" + std::to_string(cutoff), "image.width=200",
                                "image.height=200", "light_model.ambient=[0,0,0]"});
    int y = size / 2, lit = 0;
    for (int x = size / 2; x < size && img.pixel(x, y)[0] > 0; ++x) ++lit;
    double measured = (lit + 0.5) * world_per_pixel;
    double expected = std::min(2.0 * std::tan(cutoff * M_PI / 180), 2.0);  // the wall ends at 2
    EXPECT_NEAR(measured, expected, 0.08) << "cutoff " << cutoff;
    EXPECT_LT(measured, previous + 1e-9);
    previous = measured;
  }
}

TEST(LectureRows, SpotExponentSharpensTheFalloff) {
  auto ratio = [](int e) {  // brightness halfway to the edge over brightness at the centre
    Image img = render_lecture("11-spot-exponent.json",
                               {"lights[0].spot.exponent=" + std::to_string(e), "image.width=200",
                                "image.height=200", "light_model.ambient=[0,0,0]"});
    return double(img.pixel(100 + 20, 100)[0]) / std::max(1, int(img.pixel(100, 100)[0]));
  };
  double r0 = ratio(0), r10 = ratio(10), r100 = ratio(100);
  EXPECT_GT(r0, r10);
  EXPECT_GT(r10, r100);
}

TEST(Sweep, BadKeyOrValueIsStatus2AgainstVary) {
  auto r = test::run_cli("sweep scenes/lecture/10-spot-cutoff.json --vary 'lights[0].spot.cutof=50,40' -o " +
                         test::output_dir() + "/sweep_bad.png");
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(r.err, "--vary: lights[0].spot: unknown key \"cutof\" (did you mean \"cutoff\"?)\n");
  auto v = test::run_cli("sweep scenes/lecture/10-spot-cutoff.json --vary 'lights[0].spot.cutoff=50,100' -o " +
                         test::output_dir() + "/sweep_bad.png");
  EXPECT_EQ(v.exit_status, 2);
  EXPECT_EQ(v.err, "--vary: lights[0].spot.cutoff: 100 is out of range (0..90, or 180)\n");
  auto s = test::run_cli("sweep scenes/lecture/10-spot-cutoff.json --vary shading=toon -o x.png");
  EXPECT_EQ(s.exit_status, 2);
  EXPECT_EQ(s.err, "--vary: shading: expected one of \"flat\", \"gouraud\", \"phong\", got \"toon\"\n");
  auto n = test::run_cli("sweep scenes/lecture/10-spot-cutoff.json --vary 'lights[0].spot.cutoff=50' --samples 5 -o x.png");
  EXPECT_EQ(n.exit_status, 2);
  EXPECT_EQ(n.err, "--set: image.samples: expected a square number (1, 4, 9, 16, 25, 36, 49, 64), got 5\n");
  EXPECT_FALSE(std::filesystem::exists(test::output_dir() + "/sweep_bad.png"));
}

}  // namespace
}  // namespace shadelab
