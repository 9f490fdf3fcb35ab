// Texturing through whole renders: with the separate specular colour a highlight stays white on
// a dark texture (GL 1.2's colour sum), without it the texture darkens the highlight too.
#include <gtest/gtest.h>

#include <memory>

#include "shadelab/render.hpp"
#include "shadelab/shapes.hpp"

namespace shadelab {
namespace {

TEST(TextureRender, SeparateSpecularKeepsHighlightsWhiteOnADarkTexture) {
  auto dark = std::make_shared<Texture>();
  TextureLevel texel;  // a dark brown texel everywhere
  texel.width = texel.height = 1;
  texel.rgba = {40, 20, 10, 255};
  dark->levels.push_back(texel);
  dark->min_filter = dark->mag_filter = TextureFilter::kNearest;
  Scene s;
  s.width = s.height = 32;
  s.camera.projection = Camera::Projection::kOrthographic;
  SceneLight l;
  l.light = default_light(0);  // along the view direction: full highlight at every pixel
  s.lights.push_back(l);
  SceneObject wall;
  wall.mesh = std::make_shared<Mesh>(make_wall({4, 4, 1, 1}));
  wall.front.specular = {1, 1, 1, 1};
  wall.front.shininess = 10;
  wall.texture = dark;
  s.objects.push_back(wall);
  Image single = render_scene(s);
  // Single colour: (emission 0 + .2*.2 + .8 + 1) clamped to 1, modulated: 40, 20, 10.
  EXPECT_EQ(single.pixel(16, 16)[0], 40);
  EXPECT_EQ(single.pixel(16, 16)[2], 10);
  s.light_model.separate_specular = true;
  Image separate = render_scene(s);
  // Primary .84 * texel, plus the white specular 1 added after texturing: clamped white.
  EXPECT_EQ(separate.pixel(16, 16)[0], 255);
  EXPECT_EQ(separate.pixel(16, 16)[2], 255);
}

}  // namespace
}  // namespace shadelab
