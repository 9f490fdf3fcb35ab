// Scene files on disk: every scene in the repository loads; OBJ meshes are resolved against the
// scene's folder, loaded once and shared, counted before loading; file-level errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "shadelab/scene_io.hpp"

namespace shadelab {
namespace {

namespace fs = std::filesystem;

// A fresh folder for one test's files.
fs::path scratch(const std::string& name) {
  fs::path dir = fs::path(testing::TempDir()) / ("shadelab_scene_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

const char* kSquareObj =
    "# a unit square as one quad: two triangles\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "f 1 2 3 4\n";

TEST(SceneFiles, EverySceneInTheRepositoryLoads) {
  int count = 0;
  for (const auto& f : fs::recursive_directory_iterator(fs::path(SHADELAB_SOURCE_DIR) / "scenes")) {
    // rows.json is the gallery's list of rows, not a scene.
    if (f.path().extension() != ".json" || f.path().filename() == "rows.json") continue;
    LoadResult r = load_scene_file(f.path().string());
    EXPECT_TRUE(r.scene) << r.diagnostics.to_string();
    ++count;
  }
  EXPECT_GE(count, 24);
}

TEST(SceneFiles, ExampleMeshIsLoadedOnceAndShared) {
  LoadResult r = load_scene_file(std::string(SHADELAB_SOURCE_DIR) + "/scenes/examples/obj-mesh.json");
  ASSERT_TRUE(r.scene) << r.diagnostics.to_string();
  ASSERT_EQ(r.scene->objects.size(), 2u);
  EXPECT_EQ(r.scene->objects[0].mesh, r.scene->objects[1].mesh);  // the same shared_ptr
  EXPECT_EQ(r.scene->objects[0].mesh->triangles.size(), 8u);      // the octahedron's faces
}

TEST(SceneFiles, MeshPathsAreRelativeToTheSceneFile) {
  fs::path dir = scratch("relative");
  fs::create_directories(dir / "meshes");
  write(dir / "meshes" / "square.obj", kSquareObj);
  write(dir / "scene.json", "{\"objects\": [{\"shape\": {\"type\": \"mesh\", \"file\": \"meshes/square.obj\"}}]}");
  LoadResult r = load_scene_file((dir / "scene.json").string());
  ASSERT_TRUE(r.scene) << r.diagnostics.to_string();
  EXPECT_EQ(r.scene->objects[0].mesh->triangles.size(), 2u);
}

TEST(SceneFiles, MeshErrorsNameTheFileValue) {
  fs::path dir = scratch("mesh_errors");
  write(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n");
  std::string scene = "{\"objects\": [{\"shape\": {\"type\": \"mesh\", \"file\": \"nope.obj\"}},\n"
                      "             {\"shape\": {\"type\": \"mesh\", \"file\": \"bad.obj\"}}]}";
  std::string d = dir.string();
  EXPECT_EQ(parse_scene(scene, "s.json", d).diagnostics.to_string(),
            "s.json:1:49: objects[0].shape.file: " + d + "/nope.obj: cannot open mesh file: No such file "
            "or directory\n"
            "s.json:2:49: objects[1].shape.file: " + d + "/bad.obj:3: face refers to vertex 9 but the file "
            "has 2\n");
}

TEST(SceneFiles, MeshTrianglesAreCountedBeforeLoading) {
  fs::path dir = scratch("mesh_limit");
  write(dir / "square.obj", kSquareObj);
  LoadOptions o;
  o.max_triangles = 3;
  std::string scene = "{\"objects\": [{\"shape\": {\"type\": \"mesh\", \"file\": \"square.obj\"}},\n"
                      "             {\"shape\": {\"type\": \"mesh\", \"file\": \"square.obj\"}}]}";
  // The second use of the file counts again (each object is drawn).
  EXPECT_EQ(parse_scene(scene, "s.json", dir.string(), o).diagnostics.to_string(),
            "s.json:2:49: objects[1].shape.file: the scene would have 4 triangles, more than the limit "
            "of 3\n");
  o.max_triangles = 1;  // the file's face lines give 2 before it is loaded
  EXPECT_EQ(parse_scene(scene, "s.json", dir.string(), o).diagnostics.to_string(),
            "s.json:1:49: objects[0].shape.file: the scene would have 2 triangles, more than the limit "
            "of 1\n"
            "s.json:2:49: objects[1].shape.file: the scene would have 2 triangles, more than the limit "
            "of 1\n");
}

TEST(SceneFiles, FileLevelErrorsHaveNoLine) {
  EXPECT_EQ(load_scene_file("no/such/scene.json").diagnostics.to_string(),
            "no/such/scene.json: cannot open scene file: No such file or directory\n");
  fs::path dir = scratch("file_errors");
  EXPECT_EQ(load_scene_file(dir.string()).diagnostics.to_string(),
            dir.string() + ": cannot open scene file: Is a directory\n");
  // A file that never ends is read only up to the limit.
  EXPECT_EQ(load_scene_file("/dev/zero").diagnostics.to_string(),
            "/dev/zero: the file is longer than 16777216 bytes, the limit for a scene\n");
}

}  // namespace
}  // namespace shadelab
