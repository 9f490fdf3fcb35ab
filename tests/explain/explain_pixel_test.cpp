// explain_pixel against the renderer: on a Phong-shaded scene the explained colour is the
// rendered pixel (within 2/255, the ray and the rasterizer interpolate slightly differently);
// the parts sum to the unclamped total; the background explains nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "shadelab/explain.hpp"
#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"

namespace shadelab {
namespace {

const char* kScene = R"({
  "image": {"width": 96, "height": 72, "background": [0, 0, 0]},
  "camera": {"eye": [0, 0.5, 6], "target": [0, 0, 0], "fovy": 30},
  "light_model": {"ambient": [0.1, 0.1, 0.1], "local_viewer": true},
  "lights": [
    {"position": [2, 2, 3, 1], "diffuse": [1, 0.8, 0.6], "specular": [1, 1, 1],
     "attenuation": {"constant": 0.5, "linear": 0.1}},
    {"position": [-3, 1, 2, 1], "diffuse": [0.2, 0.4, 1], "specular": [0.5, 0.5, 1],
     "spot": {"direction": [3, -1, -2], "cutoff": 40, "exponent": 4}}
  ],
  "objects": [
    {"name": "ball", "shape": {"type": "sphere", "radius": 1.2, "slices": 64, "stacks": 32},
     "material": {"ambient": [0.3, 0.2, 0.2], "diffuse": [0.7, 0.5, 0.4], "specular": [0.8, 0.8, 0.8],
                  "shininess": 30, "emission": [0.05, 0, 0]},
     "shading": "phong"}
  ]
})";

Scene load() {
  LoadResult r = parse_scene(kScene, "explain.json", ".");
  EXPECT_TRUE(r.scene) << r.diagnostics.to_string();
  return *r.scene;
}

TEST(ExplainPixel, PhongPixelsAreTheExplainedColour) {
  Scene scene = load();
  RenderOptions options;
  options.samples = 1;
  Image img = render_scene(scene, options);
  int explained = 0;
  for (int y = 4; y < scene.height; y += 7) {
    for (int x = 4; x < scene.width; x += 7) {
      std::optional<PixelExplanation> e = explain_pixel(scene, x, y);
      const std::uint8_t* px = img.pixel(x, y);
      if (!e) {
        EXPECT_EQ(px[0] + px[1] + px[2], 0) << x << "," << y;  // the black background
        continue;
      }
      ++explained;
      EXPECT_EQ(e->object, "ball");
      glm::vec4 c = e->breakdown.result.primary;
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(std::lround(c[k] * 255.0f), px[k], 2) << "pixel " << x << "," << y << " channel " << k;
      }
      // The parts add up to the total before clamping.
      glm::vec3 sum = e->breakdown.emission + e->breakdown.global_ambient;
      for (const LightTerm& t : e->breakdown.lights) sum += t.ambient + t.diffuse + t.specular;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(sum[k], e->breakdown.unclamped[k], 1e-5f);
    }
  }
  EXPECT_GT(explained, 20);
}

TEST(ExplainPixel, OutsideTheImageOrOnTheBackgroundThereIsNothing) {
  Scene scene = load();
  EXPECT_FALSE(explain_pixel(scene, 0, 0));
  EXPECT_FALSE(explain_pixel(scene, -1, 10));
  EXPECT_FALSE(explain_pixel(scene, scene.width, 10));
  std::optional<PixelExplanation> centre = explain_pixel(scene, scene.width / 2, scene.height / 2);
  ASSERT_TRUE(centre);
  EXPECT_FALSE(centre->back_face);
  EXPECT_GT(centre->normal.z, 0.8f);  // facing the camera
  EXPECT_NEAR(glm::length(centre->normal), 1.0f, 1e-5f);
  EXPECT_EQ(centre->breakdown.lights.size(), 2u);
}

}  // namespace
}  // namespace shadelab
