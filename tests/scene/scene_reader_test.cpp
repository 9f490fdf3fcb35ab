// The scene reader: values landing in the right fields with OpenGL's defaults, and every class
// of bad input giving its exact message with file, line, column and key path.
#include <gtest/gtest.h>

#include <filesystem>

#include "shadelab/scene_io.hpp"

namespace shadelab {
namespace {

LoadResult parse(const std::string& text, std::vector<std::string> overrides = {}) {
  LoadOptions o;
  o.overrides = std::move(overrides);
  return parse_scene(text, "s.json", ".", o);
}

std::string errors(const std::string& text, std::vector<std::string> overrides = {}) {
  return parse(text, std::move(overrides)).diagnostics.to_string();
}

TEST(SceneReader, ValuesAndDefaults) {
  LoadResult r = parse(R"({
    "image": {"width": 320, "height": 200, "samples": 4},
    "light_model": {"local_viewer": true},
    "lights": [{}, {"position": [1, 2, 3, 1], "space": "eye",
                    "spot": {"cutoff": 30, "exponent": 10}}],
    "materials": {"red": {"diffuse": [1, 0, 0, 0.5], "shininess": 20}},
    "objects": [{"shape": {"type": "sphere", "slices": 8, "stacks": 4}, "material": "red",
                 "transform": {"translate": [1, 0, 0], "scale": 2}},
                {"shape": "cube", "material": "brass", "shading": "phong"}]
  })");
  ASSERT_TRUE(r.scene) << r.diagnostics.to_string();
  const Scene& s = *r.scene;
  EXPECT_EQ(s.width, 320);
  EXPECT_EQ(s.samples, 4);
  EXPECT_TRUE(s.light_model.local_viewer);
  EXPECT_EQ(s.light_model.ambient, glm::vec4(0.2f, 0.2f, 0.2f, 1));
  EXPECT_EQ(s.lights[0].light.diffuse, glm::vec4(1, 1, 1, 1));  // GL_LIGHT0 is white
  EXPECT_EQ(s.lights[1].light.diffuse, glm::vec4(0, 0, 0, 1));  // the others black
  EXPECT_TRUE(s.lights[1].eye_space);
  EXPECT_EQ(s.lights[1].light.spot_cutoff, 30.0f);
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].front.diffuse, glm::vec4(1, 0, 0, 0.5f));
  EXPECT_TRUE(s.objects[0].blend.enabled);  // auto: diffuse alpha below 1
  EXPECT_EQ(s.objects[0].mesh->triangles.size(), 2u * 8 * 4);
  // translate * scale: the point (1, 0, 0) goes to (1 + 2, 0, 0).
  glm::vec4 p = s.objects[0].model * glm::vec4(1, 0, 0, 1);
  EXPECT_FLOAT_EQ(p.x, 3.0f);
  EXPECT_NEAR(s.objects[1].front.shininess, 27.8974f, 1e-4);  // the brass preset
  EXPECT_EQ(s.objects[1].shading, ShadingMode::kPhong);
  EXPECT_FALSE(s.objects[1].blend.enabled);
}

TEST(SceneReader, OutOfRangeTypesAndCounts) {
  EXPECT_EQ(errors("{\"lights\": [{\"spot\": {\"cutoff\": 120}}]}"),
            "s.json:1:33: lights[0].spot.cutoff: 120 is out of range (0..90, or 180)\n");
  EXPECT_EQ(errors("{\"materials\": {\"red\": {\"shininess\": 200}}}"),
            "s.json:1:37: materials.red.shininess: 200 is out of range (0..128)\n");
  EXPECT_EQ(errors("{\"image\": {\"width\": -5}}"),
            "s.json:1:21: image.width: -5 is out of range (1..16384)\n");
  EXPECT_EQ(errors("{\"image\": {\"width\": 2.5}}"),
            "s.json:1:21: image.width: expected an integer, got 2.5\n");
  EXPECT_EQ(errors("{\"image\": {\"width\": \"big\"}}"),
            "s.json:1:21: image.width: expected a number, got a string\n");
  EXPECT_EQ(errors("{\"image\": {\"background\": [1, 0]}}"),
            "s.json:1:26: image.background: expected an array of 3 or 4 numbers, got 2 numbers\n");
  EXPECT_EQ(errors("{\"lights\": [{\"attenuation\": {\"constant\": 0}}]}"),
            "s.json:1:29: lights[0].attenuation: constant, linear and quadratic are all 0: the "
            "light would be infinitely bright\n");
}

TEST(SceneReader, UnknownKeysNamesAndChoicesSuggest) {
  EXPECT_EQ(errors("{\"lights\": [{\"spot\": {\"cutof\": 20}}]}"),
            "s.json:1:23: lights[0].spot: unknown key \"cutof\" (did you mean \"cutoff\"?)\n");
  EXPECT_EQ(errors("{\"zzz\": 1}"), "s.json:1:2: unknown key \"zzz\"\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": \"teapt\"}]}"),
            "s.json:1:24: objects[0].shape: unknown shape \"teapt\" (did you mean \"teapot\"?)\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": \"cube\", \"material\": \"bras\"}]}"),
            "s.json:1:44: objects[0].material: unknown material \"bras\" (did you mean \"brass\"?)\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": \"cube\", \"shading\": \"gourad\"}]}"),
            "s.json:1:43: objects[0].shading: expected one of \"flat\", \"gouraud\", \"phong\", got "
            "\"gourad\" (did you mean \"gouraud\"?)\n");
  EXPECT_EQ(errors("{\"objects\": [{\"name\": \"x\"}]}"),
            "s.json:1:14: objects[0]: missing required key \"shape\"\n");
}

TEST(SceneReader, CollectsEveryErrorInOnePass) {
  EXPECT_EQ(parse("{\"image\": {\"width\": 0, \"height\": 0}, \"camera\": {\"fovy\": 200}}")
                .diagnostics.size(),
            3u);
}

TEST(SceneReader, SyntaxErrorsNestingAndHugeNumbers) {
  EXPECT_EQ(errors("{\n  \"image\": {\"width\": 10,}\n}"),
            "s.json:2:25: syntax error while parsing object key - unexpected '}'; expected string literal\n");
  EXPECT_EQ(errors(""), "s.json:1:1: syntax error while parsing value - unexpected end of input; "
                        "expected '[', '{', or a literal\n");
  EXPECT_EQ(errors(std::string(100, '[') + std::string(100, ']')),
            "s.json:1:65: nesting deeper than 64 levels\n");
  EXPECT_EQ(errors("{\"image\": {\"width\": 1e999}}"), "s.json:1:21: expected a finite number\n");
  EXPECT_EQ(errors("{\"image\": {}, \"image\": {}}"),
            "s.json:1:15: duplicate key \"image\" (first at line 1)\n");
}

TEST(SceneReader, OverridesSetCreateAppendAndReportAgainstSet) {
  LoadResult r = parse("{\"lights\": [{}]}", {"lights[0].spot.cutoff=30", "lights[1].diffuse=[1,0,0]",
                                               "camera.projection=orthographic"});
  ASSERT_TRUE(r.scene) << r.diagnostics.to_string();
  EXPECT_EQ(r.scene->lights[0].light.spot_cutoff, 30.0f);
  EXPECT_EQ(r.scene->lights[1].light.diffuse, glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(r.scene->camera.projection, Camera::Projection::kOrthographic);
  EXPECT_EQ(errors("{}", {"lights[0].spot.cutoff=200"}),
            "--set: lights[0].spot.cutoff: 200 is out of range (0..90, or 180)\n");
  EXPECT_EQ(errors("{}", {"lights[3].enabled=false"}),
            "--set: lights: index 3 is beyond the end (0 elements)\n");
  EXPECT_EQ(errors("{}", {"lights[99999999999999999999].enabled=false"}),
            "--set: expected KEY.PATH=VALUE (e.g. lights[0].spot.cutoff=30), got "
            "\"lights[99999999999999999999].enabled=false\"\n");
  EXPECT_EQ(errors("{}", {"no-equals-sign"}),
            "--set: expected KEY.PATH=VALUE (e.g. lights[0].spot.cutoff=30), got \"no-equals-sign\"\n");
}

TEST(SceneReader, LimitsAndMissingFiles) {
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": {\"type\": \"sphere\", \"slices\": 4096, \"stacks\": 4096}}]}"),
            "s.json:1:24: objects[0].shape: the scene would have 33554432 triangles, more than the "
            "limit of 20000000\n");
  EXPECT_EQ(errors("{\"objects\": [{\"shape\": {\"type\": \"mesh\", \"file\": \"nope.obj\"}}]}"),
            "s.json:1:49: objects[0].shape.file: ./nope.obj: cannot open mesh file: No such file or directory\n");
  LoadResult r = load_scene_file("no/such/scene.json");
  EXPECT_EQ(r.diagnostics.to_string(), "no/such/scene.json: cannot open scene file: No such file or directory\n");
}

TEST(SceneReader, EverySceneInTheRepositoryLoads) {
  int count = 0;
  for (const auto& f : std::filesystem::recursive_directory_iterator(std::string(SHADELAB_SOURCE_DIR) + "/scenes")) {
    if (f.path().extension() != ".json" || f.path().filename() == "rows.json") continue;
    LoadResult r = load_scene_file(f.path().string());
    EXPECT_TRUE(r.scene) << r.diagnostics.to_string();
    ++count;
  }
  EXPECT_GE(count, 19);
}

}  // namespace
}  // namespace shadelab
