// Every class of bad scene input gives its exact message: file:line:column (counted by hand in
// the literal text), key path, what was expected, what was found; all problems in one pass.
#include <gtest/gtest.h>

#include "shadelab/scene_io.hpp"

namespace shadelab {
namespace {

std::string errors(const std::string& text, LoadOptions options = {}) {
  LoadResult r = parse_scene(text, "s.json", ".", options);
  EXPECT_EQ(r.scene.has_value(), r.diagnostics.empty());
  return r.diagnostics.to_string();
}

TEST(SceneErrors, OutOfRange) {
  EXPECT_EQ(errors("{\"lights\": [{\"spot\": {\"cutoff\": 120}}]}"),
            "s.json:1:33: lights[0].spot.cutoff: 120 is out of range (0..90, or 180)\n");
  EXPECT_EQ(errors("{\"materials\": {\"red\": {\"shininess\": 200}}}"),
            "s.json:1:37: materials.red.shininess: 200 is out of range (0..128)\n");
  EXPECT_EQ(errors("{\"image\": {\"width\": -5}}"),
            "s.json:1:21: image.width: -5 is out of range (1..16384)\n");
  EXPECT_EQ(errors("{\"camera\": {\"fovy\": 180}}"),
            "s.json:1:21: camera.fovy: 180 is out of range (greater than 0 and less than 180)\n");
  EXPECT_EQ(errors("{\"camera\": {\"near\": 0}}"),
            "s.json:1:21: camera.near: 0 is out of range (greater than 0, at most 1e+06)\n");
  EXPECT_EQ(errors("{\"lights\": [{\"attenuation\": {\"linear\": -0.5}}]}"),
            "s.json:1:40: lights[0].attenuation.linear: -0.5 is out of range (0 or more)\n");
  EXPECT_EQ(errors("{\"lights\": [{\"attenuation\": {\"quadratic\": 1e31}}]}"),
            "s.json:1:43: lights[0].attenuation.quadratic: 1e+31 is too large (at most 1e+30)\n");
  EXPECT_EQ(errors("{\"materials\": {\"m\": {\"diffuse\": [0.5, 1.5, 0]}}}"),
            "s.json:1:39: materials.m.diffuse[1]: 1.5 is out of range (0..1)\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": {\"type\": \"sphere\", \"slices\": 2}}]}"),
            "s.json:1:53: objects[0].shape.slices: 2 is out of range (3..4096)\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": {\"type\": \"disk\", \"inner_radius\": 2}}]}"),
            "s.json:1:57: objects[0].shape.inner_radius: outer_radius (1) must be greater than "
            "inner_radius (2)\n");
}

TEST(SceneErrors, WrongTypesAndCounts) {
  EXPECT_EQ(errors("{\"image\": {\"width\": \"big\"}}"),
            "s.json:1:21: image.width: expected a number, got a string\n");
  EXPECT_EQ(errors("{\"image\": {\"width\": 2.5}}"),
            "s.json:1:21: image.width: expected an integer, got 2.5\n");
  EXPECT_EQ(errors("{\"image\": {\"background\": [1, 0]}}"),
            "s.json:1:26: image.background: expected an array of 3 or 4 numbers, got 2 numbers\n");
  EXPECT_EQ(errors("{\"image\": {\"background\": {\"r\": 1}}}"),
            "s.json:1:26: image.background: expected an array of 3 or 4 numbers, got an object\n");
  EXPECT_EQ(errors("{\"lights\": [{\"position\": [1, 1, 1]}]}"),
            "s.json:1:26: lights[0].position: expected an array of 4 numbers, got 3 numbers\n");
  EXPECT_EQ(errors("{\"lights\": {\"position\": [1, 1, 1, 0]}}"),
            "s.json:1:12: lights: expected an array, got an object\n");
  EXPECT_EQ(errors("{\"light_model\": {\"two_side\": 1}}"),
            "s.json:1:30: light_model.two_side: expected a boolean, got a number\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": \"cube\", \"material\": 3}]}"),
            "s.json:1:44: objects[0].material: expected a material name or a material object, got a number\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": \"cube\", \"transform\": {\"scale\": \"big\"}}]}"),
            "s.json:1:55: objects[0].transform.scale: expected a number or an array of 3 numbers, got a string\n");
  EXPECT_EQ(errors("[]"), "s.json:1:1: expected an object, got an array\n");
  EXPECT_EQ(errors("{\"caption\": null}"), "s.json:1:13: caption: expected a string, got null\n");
}

TEST(SceneErrors, UnknownKeysNamesAndChoicesSuggest) {
  EXPECT_EQ(errors("{\"lights\": [{\"spot\": {\"cutof\": 20}}]}"),
            "s.json:1:23: lights[0].spot: unknown key \"cutof\" (did you mean \"cutoff\"?)\n");
  EXPECT_EQ(errors("{\"zzz\": 1}"), "s.json:1:2: unknown key \"zzz\"\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": \"teapt\"}]}"),
            "s.json:1:24: objects[0].shape: unknown shape \"teapt\" (did you mean \"teapot\"?)\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": {\"type\": \"spher\"}}]}"),
            "s.json:1:33: objects[0].shape.type: unknown shape \"spher\" (did you mean \"sphere\"?)\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": {\"type\": \"cube\", \"radius\": 1}}]}"),
            "s.json:1:41: objects[0].shape: unknown key \"radius\"\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": \"cube\", \"material\": \"shinyred\"}]}"),
            "s.json:1:44: objects[0].material: unknown material \"shinyred\" (did you mean \"shiny_red\"?)\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": \"cube\", \"shading\": \"gourad\"}]}"),
            "s.json:1:43: objects[0].shading: expected one of \"flat\", \"gouraud\", \"phong\", got "
            "\"gourad\" (did you mean \"gouraud\"?)\n");
  EXPECT_EQ(errors("{\"lights\": [{\"space\": \"camera\"}]}"),
            "s.json:1:23: lights[0].space: expected one of \"world\", \"eye\", got \"camera\"\n");
}

TEST(SceneErrors, MissingRequiredKeysPointAtTheObject) {
  EXPECT_EQ(errors("{\"objects\": [{\"name\": \"x\"}]}"),
            "s.json:1:14: objects[0]: missing required key \"shape\"\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": {\"size\": 2}}]}"),
            "s.json:1:24: objects[0].shape: missing required key \"type\"\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": \"mesh\"}]}"),
            "s.json:1:24: objects[0].shape: missing required key \"file\"\n");
}

TEST(SceneErrors, ProjectionMatrix) {
  EXPECT_EQ(errors("{\"camera\": {\"projection_matrix\": [1, 0, 0, 0]}}"),
            "s.json:1:34: camera.projection_matrix: expected an array of 16 numbers, got 4 numbers\n");
  EXPECT_EQ(errors("{\"camera\": {\"projection_matrix\": [1,0,0,0, 0,1,0,0, 0,0,0,0, 0,0,0,1]}}"),
            "s.json:1:34: camera.projection_matrix: the matrix is not invertible (it maps the view volume "
            "onto a plane)\n");
  // A valid one replaces fovy and the planes: glFrustum(-1, 2, -1, 1, 1, 10) as written.
  LoadResult r = parse_scene(
      "{\"camera\": {\"fovy\": 60, \"projection_matrix\": [1,0,0,0, 0,1,0,0, 0.333333,0,-1.222222,-1, "
      "0,0,-2.222222,0]}}",
      "s.json", ".");
  ASSERT_TRUE(r.scene) << r.diagnostics.to_string();
  EXPECT_FLOAT_EQ(r.scene->camera.projection_matrix(2.0f)[2][0], 0.333333f);
  EXPECT_FLOAT_EQ(r.scene->camera.projection_matrix(2.0f)[3][2], -2.222222f);
}

TEST(SceneErrors, GeometricNonsense) {
  EXPECT_EQ(errors("{\"camera\": {\"eye\": [0, 5, 0]}}"),
            "s.json:1:12: camera: up is parallel to the view direction (from eye to target)\n");
  EXPECT_EQ(errors("{\"camera\": {\"up\": [0, 0, 2]}}"),
            "s.json:1:19: camera.up: up is parallel to the view direction (from eye to target)\n");
  EXPECT_EQ(errors("{\"camera\": {\"target\": [0, 0, 8]}}"),
            "s.json:1:23: camera.target: eye and target are the same point: there is no view direction\n");
  EXPECT_EQ(errors("{\"camera\": {\"near\": 5, \"far\": 2}}"),
            "s.json:1:31: camera.far: far (2) must be greater than near (5)\n");
  EXPECT_EQ(errors("{\"camera\": {\"near\": 200}}"),
            "s.json:1:21: camera.near: far (100) must be greater than near (200)\n");
  EXPECT_EQ(errors("{\"lights\": [{\"position\": [0, 0, 0, 0]}]}"),
            "s.json:1:26: lights[0].position: a directional light (w = 0) needs a direction: x, y, z must "
            "not all be 0\n");
  EXPECT_EQ(errors("{\"lights\": [{\"spot\": {\"direction\": [0, 0, 0]}}]}"),
            "s.json:1:36: lights[0].spot.direction: must not be the zero vector\n");
  EXPECT_EQ(errors("{\"lights\": [{\"attenuation\": {\"constant\": 0}}]}"),
            "s.json:1:29: lights[0].attenuation: constant, linear and quadratic are all 0: the "
            "light would be infinitely bright\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": \"cube\", \"transform\": {\"rotate\": [30, 0, 0, 0]}}]}"),
            "s.json:1:56: objects[0].transform.rotate: the rotation axis must not be the zero vector\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": \"cube\", \"transform\": {\"scale\": [1, 0, 1]}}]}"),
            "s.json:1:55: objects[0].transform.scale: scale factors must not be 0\n");
  EXPECT_EQ(errors("{\"image\": {\"samples\": 8}}"),
            "s.json:1:23: image.samples: expected a square number (1, 4, 9, 16, 25, 36, 49, 64), got 8\n");
}

TEST(SceneErrors, AllProblemsAreCollectedInFileOrder) {
  std::string text =
      "{\n"
      "  \"image\": {\"width\": 0, \"height\": 2.5},\n"
      "  \"camera\": {\"fovy\": 200, \"projection\": \"fisheye\"},\n"
      "  \"lights\": [{\"diffuse\": [1, 0]}, {\"spot\": {\"cutof\": 20}}],\n"
      "  \"materials\": {\"red\": {\"shininess\": 200, \"diffuse\": \"red\"}},\n"
      "  \"objects\": [{\"shape\": \"teapt\"}, {\"shape\": \"cube\", \"material\": \"redd\", \"shading\": \"gourad\"}]\n"
      "}\n";
  EXPECT_EQ(errors(text),
            "s.json:2:22: image.width: 0 is out of range (1..16384)\n"
            "s.json:2:35: image.height: expected an integer, got 2.5\n"
            "s.json:3:22: camera.fovy: 200 is out of range (greater than 0 and less than 180)\n"
            "s.json:3:41: camera.projection: expected one of \"perspective\", \"orthographic\", got \"fisheye\"\n"
            "s.json:4:26: lights[0].diffuse: expected an array of 3 or 4 numbers, got 2 numbers\n"
            "s.json:4:45: lights[1].spot: unknown key \"cutof\" (did you mean \"cutoff\"?)\n"
            "s.json:5:38: materials.red.shininess: 200 is out of range (0..128)\n"
            "s.json:5:54: materials.red.diffuse: expected an array of 3 or 4 numbers, got a string\n"
            "s.json:6:25: objects[0].shape: unknown shape \"teapt\" (did you mean \"teapot\"?)\n"
            "s.json:6:65: objects[1].material: unknown material \"redd\" (did you mean \"red\"?)\n"
            "s.json:6:84: objects[1].shading: expected one of \"flat\", \"gouraud\", \"phong\", got \"gourad\" "
            "(did you mean \"gouraud\"?)\n");
}

TEST(SceneErrors, LimitsOnPixelsLightsAndTriangles) {
  LoadOptions small;
  small.max_pixels = 10000;
  small.max_lights = 2;
  small.max_triangles = 10000;
  EXPECT_EQ(errors("{\"image\": {\"width\": 200, \"height\": 50}}", small),
            "");
  EXPECT_EQ(errors("{\"image\": {\"width\": 201, \"height\": 50}}", small),
            "s.json:1:11: image: 201 x 50 = 10050 pixels, more than the limit of 10000\n");
  EXPECT_EQ(errors("{\"image\": {\"width\": 100, \"height\": 50, \"samples\": 4}}", small),
            "s.json:1:11: image: 100 x 50 pixels x 4 samples = 20000, more than the limit of 10000\n");
  EXPECT_EQ(errors("{\"lights\": [{}, {}, {}]}", small),
            "s.json:1:12: lights: 3 lights, more than the limit of 2\n");
  // Summed over the scene: each teapot of tessellation 10 has at most 32 * 2 * 10 * 10 = 6400.
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": \"teapot\"}, {\"shape\": \"teapot\"}]}", small),
            "s.json:1:45: objects[1].shape: the scene would have 12800 triangles, more than the limit of "
            "10000\n");
  // Counted before anything is built: 4096 x 4096 x 2 triangles would need gigabytes.
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": {\"type\": \"sphere\", \"slices\": 4096, \"stacks\": 4096}}]}"),
            "s.json:1:24: objects[0].shape: the scene would have 33554432 triangles, more than the "
            "limit of 20000000\n");
}

}  // namespace
}  // namespace shadelab
