// --set overrides: set, create, append, bare strings, malformed assignments and paths, and bad
// values reported against "--set" rather than the file.
#include <gtest/gtest.h>

#include "shadelab/scene_io.hpp"

namespace shadelab {
namespace {

LoadResult parse(const std::string& text, std::vector<std::string> overrides) {
  LoadOptions o;
  o.overrides = std::move(overrides);
  return parse_scene(text, "s.json", ".", o);
}

std::string errors(const std::string& text, std::vector<std::string> overrides) {
  return parse(text, std::move(overrides)).diagnostics.to_string();
}

TEST(SceneOverrides, SetReplacesAValue) {
  LoadResult r = parse("{\"lights\": [{\"spot\": {\"cutoff\": 30}}]}",
                       {"lights[0].spot.cutoff=45", "lights[0].diffuse=[0, 0, 1]"});
  ASSERT_TRUE(r.scene) << r.diagnostics.to_string();
  EXPECT_EQ(r.scene->lights[0].light.spot_cutoff, 45.0f);
  EXPECT_EQ(r.scene->lights[0].light.diffuse, glm::vec4(0, 0, 1, 1));
}

TEST(SceneOverrides, CreatesWhatIsMissingAndAppends) {
  LoadResult r = parse("{\"lights\": [{}]}", {"camera.eye=[1,2,3]", "lights[1].diffuse=[1,0,0]",
                                              "objects[0].shape=teapot", "objects[0].shading=flat",
                                              "objects[1]={\"shape\": \"cube\"}"});
  ASSERT_TRUE(r.scene) << r.diagnostics.to_string();
  EXPECT_EQ(r.scene->camera.eye, glm::vec3(1, 2, 3));
  ASSERT_EQ(r.scene->lights.size(), 2u);
  EXPECT_EQ(r.scene->lights[1].light.diffuse, glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(r.scene->lights[1].light.specular, glm::vec4(0, 0, 0, 1));  // light 1's default
  ASSERT_EQ(r.scene->objects.size(), 2u);
  EXPECT_EQ(r.scene->objects[0].shading, ShadingMode::kFlat);
  EXPECT_EQ(r.scene->objects[1].mesh->triangles.size(), 12u);
}

TEST(SceneOverrides, BareWordsAreStrings) {
  LoadResult r = parse("{}", {"caption=a teapot, lit", "camera.projection=orthographic"});
  ASSERT_TRUE(r.scene) << r.diagnostics.to_string();
  EXPECT_EQ(r.scene->caption, "a teapot, lit");
  EXPECT_EQ(r.scene->camera.projection, Camera::Projection::kOrthographic);
}

TEST(SceneOverrides, BadValuesAreReportedAgainstSet) {
  EXPECT_EQ(errors("{}", {"lights[0].spot.cutoff=200"}),
            "--set: lights[0].spot.cutoff: 200 is out of range (0..90, or 180)\n");
  EXPECT_EQ(errors("{}", {"image.width=wide"}), "--set: image.width: expected a number, got a string\n");
  EXPECT_EQ(errors("{}", {"image.width=1e999"}), "--set: image.width: expected a finite number\n");
  EXPECT_EQ(errors("{}", {"camera.eyes=[1,2,3]"}),
            "--set: camera: unknown key \"eyes\" (did you mean \"eye\"?)\n");
  // The file's own errors keep their positions; override errors come after them.
  EXPECT_EQ(errors("{\"image\": {\"width\": 0}}", {"image.height=0"}),
            "s.json:1:21: image.width: 0 is out of range (1..16384)\n"
            "--set: image.height: 0 is out of range (1..16384)\n");
}

TEST(SceneOverrides, PathsThatCannotBeFollowed) {
  EXPECT_EQ(errors("{}", {"lights[3].enabled=false"}),
            "--set: lights: index 3 is beyond the end (the array has 0 elements; [0] appends)\n");
  EXPECT_EQ(errors("{\"image\": {\"width\": 3}}", {"image.width.x=3"}),
            "--set: image.width: expected an object to set \"x\" in, got a number\n");
  EXPECT_EQ(errors("{\"camera\": {}}", {"camera[0]=1"}),
            "--set: camera: expected an array to take element [0] of, got an object\n");
}

TEST(SceneOverrides, MalformedAssignments) {
  const char* bad[] = {"no-equals-sign", "=5", "a..b=1", "a.=1", ".a=1", "a[x]=1", "a[]=1",
                       "a[1=1", "a[1]b=1", "lights[99999999999999999999].enabled=false"};
  for (const char* o : bad) {
    EXPECT_EQ(errors("{}", {o}),
              std::string("--set: expected KEY.PATH=VALUE (e.g. lights[0].spot.cutoff=30), got \"") + o + "\"\n");
  }
}

}  // namespace
}  // namespace shadelab
