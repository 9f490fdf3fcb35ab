// Shadow maps for each light kind: a sphere over a floor seen from above. The shadowed pixel
// keeps only the light's ambient (0 here) while the pixel beside it has the value the lighting
// equation predicts; the lit floor is uniform (no acne); a cube resting on the floor casts a
// shadow that starts at its base (no peter-panning beyond two pixels).
#include <gtest/gtest.h>

#include <cmath>

#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"

namespace shadelab {
namespace {

constexpr int kSize = 64;
constexpr float kView = 8.0f;  // the picture shows x, z in [-4, 4]

Image render(const std::string& light, const std::string& caster) {
  LoadResult r = parse_scene(R"({
    "image": {"width": 64, "height": 64},
    "camera": {"eye": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1],
               "projection": "orthographic", "ortho_height": 8},
    "light_model": {"ambient": [0, 0, 0]},
    "lights": [)" + light + R"(],
    "objects": [
      {"name": "floor", "shape": {"type": "plane", "size": 8, "n": 8}, "shading": "phong",
       "material": {"ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0]}},
      )" + caster + R"(
    ]})", "shadow.json", ".");
  EXPECT_TRUE(r.scene) << r.diagnostics.to_string();
  return r.scene ? render_scene(*r.scene) : Image{};
}

// Red channel at world (x, z) on the floor.
int at(const Image& img, float x, float z) {
  int px = int((x + kView / 2) / kView * kSize), py = int((z + kView / 2) / kView * kSize);
  return img.pixel(std::clamp(px, 0, kSize - 1), std::clamp(py, 0, kSize - 1))[0];
}

const char* kSphere = R"({"name": "ball", "shape": {"type": "sphere", "radius": 0.7, "slices": 32, "stacks": 16},
   "transform": {"translate": [0, 2, 0]}, "material": {"diffuse": [0, 0, 1]}})";

TEST(ShadowMap, DirectionalUnderAndBesideAndNoAcne) {
  Image img = render(R"({"position": [1, 1, 0, 0], "diffuse": [0.8, 0.8, 0.8], "shadow": true})", kSphere);
  // The shadow's centre is 2 units toward -x (light direction (1, 1, 0)); beside it, lit.
  int lit = int(std::lround(0.8f * std::sqrt(0.5f) * 255));  // 144
  EXPECT_EQ(at(img, -2, 0), 0);
  EXPECT_EQ(at(img, 2.5f, 0), lit);
  // Uniform lit floor: every floor pixel away from the shadow and the ball is exactly `lit`.
  for (float z = -3.5f; z <= 3.5f; z += 0.5f) {
    for (float x = -3.5f; x <= 3.5f; x += 0.5f) {
      bool near_shadow = std::hypot(x + 2, z) < 1.3f, near_ball = std::hypot(x, z) < 1.0f;
      if (!near_shadow && !near_ball) {
        ASSERT_EQ(at(img, x, z), lit) << x << "," << z;
      }
    }
  }
}

TEST(ShadowMap, SpotLight) {
  Image img = render(R"({"position": [2, 4, 0, 1], "diffuse": [1, 1, 1], "shadow": true,
                         "spot": {"direction": [-1, -2, 0], "cutoff": 60}})", kSphere);
  // The light (2, 4) through the ball's centre (0, 2) hits the floor at x = -2.
  EXPECT_EQ(at(img, -2, 0), 0);
  // Beside the shadow at (-2, 1.6): n . L = 4 / |(4, 4, -1.6)|.
  float expected = 4.0f / std::sqrt(16 + 16 + 1.6f * 1.6f) * 255;
  EXPECT_NEAR(at(img, -2, 1.6f), expected, 12);  // the pixel centre is within half a pixel
}

TEST(ShadowMap, PointLightCubeMap) {
  Image img = render(R"({"position": [-2, 4, 0, 1], "diffuse": [1, 1, 1], "shadow": true})", kSphere);
  EXPECT_EQ(at(img, 2, 0), 0);  // mirrored: shadow toward +x
  float expected = 4.0f / std::sqrt(16 + 16 + 1.6f * 1.6f) * 255;
  EXPECT_NEAR(at(img, 2, 1.6f), expected, 12);
  EXPECT_GT(at(img, -2, 0), 200);  // right under the light, lit
}

TEST(ShadowMap, ContactShadowStartsAtTheBase) {
  Image img = render(R"({"position": [1, 1, 0, 0], "diffuse": [0.8, 0.8, 0.8], "shadow": true})",
                     R"({"name": "box", "shape": {"type": "cube", "size": 1}, "transform": {"translate": [0, 0.5, 0]},
                         "material": {"diffuse": [0, 0, 1]}})");
  // The cube's -x face is at x = -0.5; its shadow covers x in [-1.5, -0.5]. Tolerance: the
  // shadow reaches to within two pixels (0.25 units) of the base.
  EXPECT_EQ(at(img, -0.5f - 0.25f, 0), 0);
  EXPECT_EQ(at(img, -1.0f, 0), 0);
  EXPECT_GT(at(img, -1.5f - 0.25f, 0), 100);
}

}  // namespace
}  // namespace shadelab
