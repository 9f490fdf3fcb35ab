// Whole renders checked against values worked out by hand: a lit wall's colour in every
// shading mode, a spot light's lit radius, flat shading's provoking vertex, the mesh-size
// effect (Gouraud misses a highlight that Phong finds), and blending order.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <glm/trigonometric.hpp>

#include "shadelab/render.hpp"
#include "shadelab/shapes.hpp"

namespace shadelab {
namespace {

// An orthographic camera looking down -z at a 4 x 4 window onto the plane z = 0.
Scene wall_scene(int nx, int size = 64) {
  Scene s;
  s.width = s.height = size;
  s.camera.projection = Camera::Projection::kOrthographic;
  s.camera.ortho_height = 4.0f;
  s.camera.eye = {0, 0, 8};
  SceneObject wall;
  wall.mesh = std::make_shared<Mesh>(make_wall({4.0f, 4.0f, nx, nx}));
  s.objects.push_back(wall);
  return s;
}

int red(const Image& img, int x, int y) { return img.pixel(x, y)[0]; }

TEST(RenderAnalytic, DirectionalLightOnWallInEveryMode) {
  // Global ambient .2 * ambient .2 = .04, plus diffuse .8 * 1 * (n.L = 1) = .8: .84 -> 214.
  Scene s = wall_scene(3);
  SceneLight l;
  l.light = default_light(0);  // white, from +z
  s.lights.push_back(l);
  for (ShadingMode m : {ShadingMode::kFlat, ShadingMode::kGouraud, ShadingMode::kPhong}) {
    Image img = render_scene(s, RenderOptions{m, std::nullopt});
    EXPECT_EQ(red(img, 32, 32), 214) << int(m);
    EXPECT_EQ(red(img, 3, 60), 214) << int(m);
  }
}

TEST(RenderAnalytic, SpotLitRadiusFollowsTanCutoff) {
  // Spot at (0, 0, 2) pointing down -z onto the wall: lit where atan(r / 2) <= cutoff,
  // i.e. r <= 2 tan(cutoff). Pixels are 4/64 world units; check just inside and outside.
  for (float cutoff : {20.0f, 30.0f, 40.0f}) {
    Scene s = wall_scene(1);
    s.light_model.ambient = glm::vec4(0, 0, 0, 1);
    SceneLight l;
    l.light = default_light(0);
    l.light.position = {0, 0, 2, 1};
    l.light.spot_cutoff = cutoff;
    s.lights.push_back(l);
    Image img = render_scene(s, RenderOptions{ShadingMode::kPhong, std::nullopt});
    float radius = 2.0f * std::tan(glm::radians(cutoff));
    auto at = [&](float r) {  // red at world distance r to the right of the centre
      int x = int(std::floor((r + 2.0f) / 4.0f * 64.0f));
      return red(img, x, 31);
    };
    EXPECT_GT(at(radius - 0.15f), 0) << cutoff;
    EXPECT_EQ(at(radius + 0.15f), 0) << cutoff;
  }
}

TEST(RenderAnalytic, FlatShadingUsesTheProvokingVertex) {
  // One triangle, lighting off, vertex colours red, green, blue: flat shading paints it with
  // the LAST vertex's colour (blue).
  Scene s = wall_scene(1);
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = {{-2, -2, 0}, {2, -2, 0}, {-2, 2, 0}};
  mesh->colors = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
  mesh->triangles = {{0, 1, 2}};
  s.objects[0].mesh = mesh;
  s.objects[0].lighting = false;
  s.objects[0].shading = ShadingMode::kFlat;
  Image img = render_scene(s);
  const std::uint8_t* p = img.pixel(10, 50);
  EXPECT_EQ(p[0], 0);
  EXPECT_EQ(p[1], 0);
  EXPECT_EQ(p[2], 255);
}

TEST(RenderAnalytic, MeshSizeHighlightGouraudVersusPhong) {
  // The lecture's experiment: a shiny white wall lit by a point light straight in front of its
  // centre. Gouraud on a 1x1 wall interpolates the corners' dull colour, so no highlight in the
  // middle; a 20x20 wall and Phong shading both show it.
  auto centre = [](int n, ShadingMode mode) {
    Scene s = wall_scene(n);
    s.light_model.ambient = glm::vec4(0, 0, 0, 1);
    s.objects[0].front.ambient = glm::vec4(0, 0, 0, 1);
    s.objects[0].front.diffuse = glm::vec4(0, 0, 0, 1);
    s.objects[0].front.specular = glm::vec4(1, 1, 1, 1);
    s.objects[0].front.shininess = 100;
    s.light_model.local_viewer = true;
    SceneLight l;
    l.light = default_light(0);
    l.light.position = {0, 0, 8, 1};
    s.lights.push_back(l);
    s.camera.projection = Camera::Projection::kPerspective;
    s.camera.fovy_degrees = 28.0f;
    return red(render_scene(s, RenderOptions{mode, std::nullopt}), 32, 32);
  };
  EXPECT_LT(centre(1, ShadingMode::kGouraud), 40);
  EXPECT_GT(centre(20, ShadingMode::kGouraud), 200);
  EXPECT_GT(centre(1, ShadingMode::kPhong), 250);
}

TEST(RenderAnalytic, TransparentObjectBlendsOverOpaque) {
  // A red opaque wall behind a half-transparent unlit green wall: .5 * green + .5 * red.
  Scene s = wall_scene(1);
  s.objects[0].lighting = false;
  s.objects[0].color = {1, 0, 0, 1};
  SceneObject glass = s.objects[0];
  glass.color = {0, 1, 0, 0.5f};
  glass.model = glm::mat4(1.0f);
  glass.model[3] = glm::vec4(0, 0, 1, 1);  // in front
  glass.blend = {true, BlendFactor::kSrcAlpha, BlendFactor::kOneMinusSrcAlpha};
  s.objects.insert(s.objects.begin(), glass);  // listed first, drawn after the opaque wall
  Image img = render_scene(s);
  EXPECT_EQ(img.pixel(32, 32)[0], 128);
  EXPECT_EQ(img.pixel(32, 32)[1], 128);
}

}  // namespace
}  // namespace shadelab

namespace shadelab {
namespace {

// The lab's render time limit: objects not started by the deadline are left out, and said so.
TEST(RenderDeadline, ObjectsAfterTheDeadlineAreNotDrawn) {
  Scene s = wall_scene(1, 16);
  s.background = {0.0f, 0.0f, 1.0f, 1.0f};
  RenderOptions late;
  late.deadline = std::chrono::steady_clock::now() - std::chrono::seconds(1);
  RenderStats stats;
  Image img = render_scene(s, late, &stats);
  EXPECT_TRUE(stats.interrupted);
  EXPECT_EQ(img.pixel(8, 8)[2], 255);  // only the background
  RenderOptions in_time;
  in_time.deadline = std::chrono::steady_clock::now() + std::chrono::hours(1);
  RenderStats ok;
  img = render_scene(s, in_time, &ok);
  EXPECT_FALSE(ok.interrupted);
  EXPECT_NE(img.pixel(8, 8)[2], 255);  // the wall
}

}  // namespace
}  // namespace shadelab
