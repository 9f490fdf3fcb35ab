// LoadOptions::confine_files: scenes from untrusted sources (the lab) may name mesh and texture
// files only inside their own folder; neither ../ nor a symbolic link leads out of it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "shadelab/scene_io.hpp"
#include "support/test_support.hpp"

namespace shadelab {
namespace {

namespace fs = std::filesystem;

TEST(ConfineFiles, OnlyFilesInsideTheScenesFolder) {
  fs::path root = fs::path(test::output_dir()) / "confine";
  fs::remove_all(root);
  fs::create_directories(root / "scene");
  fs::create_directories(root / "secret");
  const char* obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(root / "scene" / "ok.obj") << obj;
  std::ofstream(root / "secret" / "private.obj") << obj;
  fs::create_symlink(root / "secret" / "private.obj", root / "scene" / "link.obj");

  LoadOptions confined;
  confined.confine_files = true;
  auto load = [&](const std::string& file, const LoadOptions& o) {
    std::string text = R"({"objects": [{"shape": {"type": "mesh", "file": ")" + file + R"("}}]})";
    return parse_scene(text, "lab.json", (root / "scene").string(), o);
  };
  EXPECT_TRUE(load("ok.obj", confined).scene);
  LoadResult up = load("../secret/private.obj", confined);
  ASSERT_FALSE(up.scene);
  EXPECT_EQ(up.diagnostics.items()[0].key_path, "objects[0].shape.file");
  EXPECT_EQ(up.diagnostics.items()[0].message, "\"../secret/private.obj\" is outside the scene's folder");
  EXPECT_FALSE(load("link.obj", confined).scene);  // a symbolic link out of the folder
  EXPECT_FALSE(load((root / "secret" / "private.obj").string(), confined).scene);  // absolute
  // Scene files a user renders themselves may name any file.
  EXPECT_TRUE(load("../secret/private.obj", LoadOptions{}).scene);
}

}  // namespace
}  // namespace shadelab
