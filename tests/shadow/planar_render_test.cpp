// Planar shadows in scenes: one uniform darkness where shadow triangles overlap (each pixel
// darkened once), nothing outside the receiver, nothing from a light below the plane.
#include <gtest/gtest.h>

#include <set>

#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"

namespace shadelab {
namespace {

// Looking straight down at a white unlit floor (y = 0) under two overlapping cubes, with a
// half-transparent black shadow from a light straight above (or below).
Scene floor_scene(float floor_size, const std::string& light_position) {
  std::string text = R"({
    "image": {"width": 64, "height": 64, "background": [0, 0, 1]},
    "camera": {"eye": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1],
               "projection": "orthographic", "ortho_height": 8},
    "lights": [{"position": )" + light_position + R"(}],
    "objects": [
      {"name": "floor", "shape": {"type": "plane", "size": )" + std::to_string(floor_size) + R"(},
       "lighting": false, "color": [1, 1, 1]},
      {"name": "a", "shape": {"type": "cube", "size": 2}, "transform": {"translate": [-0.5, 2, 0]},
       "lighting": false, "color": [1, 0, 0]},
      {"name": "b", "shape": {"type": "cube", "size": 2}, "transform": {"translate": [0.5, 4, 0]},
       "lighting": false, "color": [1, 0, 0]}
    ],
    "shadows": [{"plane": [0, 1, 0, 0], "light": 0, "color": [0, 0, 0, 0.5], "receiver": "floor"}]
  })";
  LoadResult r = parse_scene(text, "shadow.json", ".");
  EXPECT_TRUE(r.scene) << r.diagnostics.to_string();
  return r.scene ? *r.scene : Scene{};
}

// Cubes seen from above hide their own shadow; render with the cubes moved out of the picture
// by looking only at what the floor shows: drop the cubes' own pixels (red).
std::set<int> floor_reds(const Image& img) {
  std::set<int> values;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = img.pixel(x, y);
      if (p[0] == p[1] && p[1] == p[2]) values.insert(p[0]);  // grey: floor, lit or shadowed
    }
  return values;
}

TEST(PlanarShadowRender, OverlappingCastersDarkenOnce) {
  Scene s = floor_scene(7, "[0, 1, 0.3, 0]");  // slanted so the shadows show beside the cubes
  Image img = render_scene(s);
  // White floor and one shadow level, 255 * 0.5 = 127.5 -> 128: never 64 (darkened twice).
  EXPECT_EQ(floor_reds(img), (std::set<int>{128, 255}));
}

TEST(PlanarShadowRender, NothingOutsideTheReceiver) {
  Scene s = floor_scene(2, "[0, 1, 0.3, 0]");  // a floor smaller than the shadow
  Image img = render_scene(s);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = img.pixel(x, y);
      bool background = p[2] == 255 && p[0] == 0;
      bool grey = p[0] == p[1] && p[1] == p[2];
      bool red = p[0] == 255 && p[1] == 0;
      ASSERT_TRUE(background || grey || red) << x << "," << y;  // no shadow-tinted background
    }
}

TEST(PlanarShadowRender, LightBelowThePlaneCastsNothing) {
  Scene s = floor_scene(7, "[0, -1, 0.3, 0]");
  EXPECT_EQ(floor_reds(render_scene(s)), (std::set<int>{255}));
  Scene p = floor_scene(7, "[0, -3, 0, 1]");  // a point light under the floor
  EXPECT_EQ(floor_reds(render_scene(p)), (std::set<int>{255}));
}

TEST(PlanarShadowRender, ReceiverMustExist) {
  LoadResult r = parse_scene(R"({"lights": [{}], "objects": [{"name": "floor", "shape": "cube"}],
    "shadows": [{"plane": [0, 1, 0, 0], "receiver": "flor"}]})", "s.json", ".");
  EXPECT_EQ(r.diagnostics.to_string(),
            "s.json:2:53: shadows[0].receiver: no object named \"flor\" (did you mean \"floor\"?)\n");
}

}  // namespace
}  // namespace shadelab
