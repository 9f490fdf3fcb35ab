// Wavefront OBJ loading on small files written here: quads split as OpenGL does, the file's
// normals or smooth ones, shapes merged, and the exact diagnostics for broken files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <glm/geometric.hpp>

#include "shadelab/shapes.hpp"

namespace shadelab {
namespace {

/// Writes `text` to a fresh file named after the running test and returns its path.
std::string write_obj(const std::string& text, const std::string& suffix = ".obj") {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  auto dir = std::filesystem::path(::testing::TempDir()) / "shadelab-obj-test";
  std::filesystem::create_directories(dir);
  auto path = dir / (std::string(info->name()) + suffix);
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

const char* kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ObjLoader, QuadSplitAsOpenGLWithSmoothNormals) {
  std::string path = write_obj(std::string(kSquare) + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n");
  Mesh m;
  Diagnostics d;
  ASSERT_TRUE(load_obj(path, m, d)) << d.to_string();
  EXPECT_TRUE(d.empty());
  ASSERT_EQ(m.positions.size(), 4u);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 3}));  // (a, b, d), (b, c, d)
  EXPECT_EQ(m.triangles[1], (Triangle{1, 2, 3}));
  EXPECT_EQ(m.positions[2], glm::vec3(1, 1, 0));
  EXPECT_EQ(m.texcoords[2], glm::vec2(1, 1));
  for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));  // (1,0,0) x (0,1,0)
}

TEST(ObjLoader, VertexColoursWhenEveryVertexHasOne) {
  // `v x y z r g b` (a common extension): kept, clamped to 0..1, alpha 1.
  std::string path = write_obj("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 2\nf 1 2 3\n");
  Mesh m;
  Diagnostics d;
  ASSERT_TRUE(load_obj(path, m, d)) << d.to_string();
  ASSERT_EQ(m.colors.size(), 3u);
  EXPECT_EQ(m.colors[0], glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(m.colors[2], glm::vec4(0, 0, 1, 1));
  // A file where some vertex has none: no colours at all (the object's colour applies).
  path = write_obj("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "-partial.obj");
  ASSERT_TRUE(load_obj(path, m, d)) << d.to_string();
  EXPECT_TRUE(m.colors.empty());
}

TEST(ObjLoader, FileNormalsAreNormalizedAndSplitVertices) {
  // The two triangles share positions 1 and 3 but not normals: 6 vertices.
  std::string path = write_obj(std::string(kSquare) + "vn 0 0 2\nvn 0 3 4\nf 1//1 2//1 3//1\nf 1//2 3//2 4//2\n");
  Mesh m;
  Diagnostics d;
  ASSERT_TRUE(load_obj(path, m, d)) << d.to_string();
  ASSERT_EQ(m.positions.size(), 6u);
  ASSERT_EQ(m.triangles.size(), 2u);
  for (std::uint32_t v : m.triangles[0]) EXPECT_EQ(m.normals[v], glm::vec3(0, 0, 1));
  for (std::uint32_t v : m.triangles[1]) EXPECT_NEAR(glm::length(m.normals[v] - glm::vec3(0, 0.6f, 0.8f)), 0.0f, 1e-6f);
}

TEST(ObjLoader, SmoothNormalsJoinAcrossTextureSeams) {
  // Faces (0,0,1)-facing and (0,1,0)-facing share the edge v1 v2 but with other texture
  // coordinates: four vertices there, all with (0, 1, 1) / sqrt 2.
  std::string path = write_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\n"
      "f 1/1 2/2 3/3\nf 2/4 1/4 4/4\n");
  Mesh m;
  Diagnostics d;
  ASSERT_TRUE(load_obj(path, m, d)) << d.to_string();
  ASSERT_EQ(m.positions.size(), 6u);
  float h = 1.0f / std::sqrt(2.0f);
  int shared = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    if (m.positions[i].y != 0.0f || m.positions[i].z != 0.0f) continue;  // v1 and v2 lie on the x axis
    ++shared;
    EXPECT_NEAR(glm::length(m.normals[i] - glm::vec3(0, h, h)), 0.0f, 1e-6f);
  }
  EXPECT_EQ(shared, 4);
}

TEST(ObjLoader, ShapesMergedPolygonsFannedRelativeIndices) {
  // A pentagon fanned so that every triangle ends in its first vertex (GL_POLYGON's provoking
  // vertex), then a second object using relative indices.
  std::string path = write_obj(
      "o a\nv 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\n"
      "o b\nv 0 0 1\nv 1 0 1\nv 0 1 1\nf -3 -2 -1\n");
  Mesh m;
  Diagnostics d;
  ASSERT_TRUE(load_obj(path, m, d)) << d.to_string();
  ASSERT_EQ(m.positions.size(), 8u);
  ASSERT_EQ(m.triangles.size(), 4u);
  EXPECT_EQ(m.triangles[0], (Triangle{1, 2, 0}));
  EXPECT_EQ(m.triangles[1], (Triangle{2, 3, 0}));
  EXPECT_EQ(m.triangles[2], (Triangle{3, 4, 0}));
  EXPECT_EQ(m.positions[m.triangles[3][0]], glm::vec3(0, 0, 1));
  for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(ObjLoader, OutOfRangeVertexIsReportedWithItsLine) {
  std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                     "f 1 2 3\nf 1 2 12\n";
  std::string path = write_obj(text);
  Mesh m;
  m.positions = {{7, 7, 7}};
  Diagnostics d;
  EXPECT_FALSE(load_obj(path, m, d));
  ASSERT_EQ(d.size(), 1u);
  const Diagnostic& e = d.items()[0];
  EXPECT_EQ(e.message, "face refers to vertex 12 but the file has 8");
  EXPECT_EQ(e.location.file, path);
  EXPECT_EQ(e.location.line, 10);
  EXPECT_EQ(e.location.column, 0);
  EXPECT_EQ(e.key_path, "");
  EXPECT_EQ(m.positions.size(), 1u);  // untouched on failure
}

TEST(ObjLoader, OutOfRangeNormalAndQuadAreReported) {
  std::string path = write_obj(std::string(kSquare) + "vn 0 0 1\nf 1//1 2//3 3//1\nf 1 2 3 9\n");
  Mesh m;
  Diagnostics d;
  EXPECT_FALSE(load_obj(path, m, d));
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d.items()[0].message, "face refers to normal 3 but the file has 1");
  EXPECT_EQ(d.items()[1].message, "face refers to vertex 9 but the file has 4");
  EXPECT_EQ(d.items()[1].location.line, 7);
}

TEST(ObjLoader, ManyProblemsAreCountedAfterTen) {
  std::string text = kSquare;
  for (int i = 0; i < 15; ++i) text += "f 1 2 5\n";
  Mesh m;
  Diagnostics d;
  EXPECT_FALSE(load_obj(write_obj(text), m, d));
  ASSERT_EQ(d.size(), 11u);
  EXPECT_EQ(d.items()[10].message, "5 more problems");
}

TEST(ObjLoader, MissingFileAndDirectory) {
  Mesh m;
  Diagnostics d;
  auto missing = (std::filesystem::path(::testing::TempDir()) / "shadelab-obj-test-missing.obj").string();
  std::filesystem::remove(missing);
  EXPECT_FALSE(load_obj(missing, m, d));
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d.items()[0].message, "cannot open mesh file: No such file or directory");
  EXPECT_EQ(d.items()[0].location.file, missing);
  EXPECT_EQ(d.items()[0].location.line, 0);
  Diagnostics dir;
  EXPECT_FALSE(load_obj(::testing::TempDir(), m, dir));
  ASSERT_EQ(dir.size(), 1u);
  EXPECT_EQ(dir.items()[0].message, "cannot read mesh file: Is a directory");
}

TEST(ObjLoader, NoTrianglesIsAnError) {
  Mesh m;
  Diagnostics d;
  EXPECT_FALSE(load_obj(write_obj(std::string(kSquare) + "l 1 2\nf 1 2\n"), m, d));
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d.items()[0].message, "mesh has no triangles");
}

TEST(ObjLoader, NonFiniteNumbersAreReported) {
  // 1e999 overflows to infinity.
  Mesh m;
  Diagnostics d;
  EXPECT_FALSE(load_obj(write_obj("v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n"), m, d));
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d.items()[0].message, "vertex 2 has a coordinate that is not a finite number");
  EXPECT_EQ(d.items()[0].location.line, 2);
}

TEST(ObjLoader, GarbageNeverCrashes) {
  Mesh m;
  Diagnostics zero;
  EXPECT_FALSE(load_obj(write_obj(std::string(kSquare) + "f 0 1 2\n"), m, zero));
  ASSERT_EQ(zero.size(), 1u);
  EXPECT_EQ(zero.items()[0].message.rfind("cannot parse mesh file: ", 0), 0u) << zero.items()[0].message;
  std::string junk;
  for (int i = 0; i < 4096; ++i) junk += char((i * 7919 + 13) % 256);
  Diagnostics d;
  load_obj(write_obj(junk + "\nf 1 2 3 4 5 6\nv 1\nf -9 -8 -7\n"), m, d);
  EXPECT_FALSE(d.empty());
}

}  // namespace
}  // namespace shadelab
