// Built-in shapes and mesh helpers: vertex and triangle counts worked out by hand, unit normals,
// indices in range, closed shapes watertight with outward faces, the lecture's tetrahedron and
// cylinder colours, walls and disks.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <tuple>

#include <glm/geometric.hpp>

#include "shadelab/shapes.hpp"

namespace shadelab {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

glm::vec3 face_normal(const Mesh& m, const Triangle& t) {
  return glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
}

glm::vec3 centroid(const Mesh& m, const Triangle& t) {
  return (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0f;
}

/// Sizes agree, indices in range, positions finite, normals finite and unit length, no
/// zero-area triangle.
void expect_well_formed(const Mesh& m) {
  ASSERT_EQ(m.normals.size(), m.positions.size());
  ASSERT_EQ(m.texcoords.size(), m.positions.size());
  ASSERT_TRUE(m.colors.empty() || m.colors.size() == m.positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(m.positions[i][k]) && std::isfinite(m.normals[i][k])) << i;
    ASSERT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-5f) << i;
  }
  for (const Triangle& t : m.triangles) {
    for (std::uint32_t v : t) ASSERT_LT(v, m.positions.size());
    ASSERT_GT(glm::length(face_normal(m, t)), 0.0f);
  }
}

/// "" when every edge, after merging vertices with identical positions, is used by exactly two
/// triangles in opposite directions; otherwise a description of the first bad edge.
std::string watertight_problem(const Mesh& m) {
  std::map<std::tuple<float, float, float>, int> ids;
  auto id = [&](std::uint32_t v) {
    const glm::vec3& p = m.positions[v];
    return ids.emplace(std::make_tuple(p.x, p.y, p.z), int(ids.size())).first->second;
  };
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : m.triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{id(t[k]), id(t[(k + 1) % 3])}];
  }
  for (const auto& [edge, count] : directed) {
    auto back = directed.find({edge.second, edge.first});
    if (count != 1 || back == directed.end() || back->second != 1) {
      return "edge " + std::to_string(edge.first) + "->" + std::to_string(edge.second) + " used " +
             std::to_string(count) + " times, reverse " + std::to_string(back == directed.end() ? 0 : back->second);
    }
  }
  return "";
}

/// Every face's geometric normal agrees in sign with its vertices' normals.
void expect_faces_agree_with_normals(const Mesh& m) {
  for (const Triangle& t : m.triangles) {
    glm::vec3 smooth = m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]];
    ASSERT_GT(glm::dot(face_normal(m, t), smooth), 0.0f);
  }
}

TEST(MeshHelpers, AddQuadSplitsAsOpenGLDoes) {
  Mesh m;
  add_quad(m, 4, 5, 6, 7);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.triangles[0], (Triangle{4, 5, 7}));
  EXPECT_EQ(m.triangles[1], (Triangle{5, 6, 7}));
}

TEST(MeshHelpers, SmoothNormalsAverageUnitFaceNormals) {
  // A big triangle facing +z and a small one facing +y share the edge v0 v1; the shared
  // vertices get (0, 1, 1) / sqrt 2 whatever the areas. v4 is used by no face, v5 only by a
  // degenerate one: both get (0, 0, 1). The index 9 is out of range and ignored.
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 3, 0}, {0, 0, 1}, {5, 5, 5}, {2, 0, 0}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 5}, {0, 1, 9}};
  compute_smooth_normals(m);
  ASSERT_EQ(m.normals.size(), 6u);
  float h = 1.0f / std::sqrt(2.0f);
  const glm::vec3 expected[6] = {{0, h, h}, {0, h, h}, {0, 0, 1}, {0, 1, 0}, {0, 0, 1}, {0, 0, 1}};
  for (int i = 0; i < 6; ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(m.normals[i][k], expected[i][k], 1e-6f) << i;
  }
}

TEST(ShapeSphere, CountsPolesAndRadialNormals) {
  // 8 slices, 4 stacks: 3 inner rings of 9 (seam repeated) and 8 copies of each pole;
  // 2 rows of 16 triangles between rings and 8 at each pole.
  Mesh m = make_sphere({2.0f, 8, 4});
  EXPECT_EQ(m.positions.size(), 3u * 9 + 2 * 8);
  EXPECT_EQ(m.triangles.size(), 2u * 16 + 2 * 8);
  expect_well_formed(m);
  EXPECT_EQ(watertight_problem(m), "");
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3& p = m.positions[i];
    EXPECT_NEAR(glm::length(p), 2.0f, 1e-5f);
    EXPECT_NEAR(glm::length(m.normals[i] - p / 2.0f), 0.0f, 1e-5f);
    // t runs from the south pole (0) to the north pole (1): y = r sin(pi (t - 1/2)).
    EXPECT_NEAR(p.y, 2.0f * std::sin(kPi * (m.texcoords[i].y - 0.5f)), 1e-5f);
  }
  for (const Triangle& t : m.triangles) EXPECT_GT(glm::dot(face_normal(m, t), centroid(m, t)), 0.0f);
  expect_faces_agree_with_normals(m);
}

TEST(ShapeSphere, SmallestAndBadCountsAreClamped) {
  // slices 3, stacks 2: one ring of 4 and 3 copies of each pole, 3 triangles per pole.
  Mesh m = make_sphere({1.0f, 0, -7});
  EXPECT_EQ(m.positions.size(), 4u + 6);
  EXPECT_EQ(m.triangles.size(), 6u);
  expect_well_formed(m);
  EXPECT_EQ(watertight_problem(m), "");
}

TEST(ShapeCylinder, CappedIsClosedAndOutward) {
  // 6 slices, 2 stacks: side 7 x 3 vertices, 24 triangles; each cap a centre and 6 rim
  // vertices, 6 triangles.
  Mesh m = make_cylinder({1.0f, 2.0f, 6, 2, true, false});
  EXPECT_EQ(m.positions.size(), 21u + 14);
  EXPECT_EQ(m.triangles.size(), 24u + 12);
  expect_well_formed(m);
  EXPECT_EQ(watertight_problem(m), "");
  expect_faces_agree_with_normals(m);
  for (const Triangle& t : m.triangles) {
    glm::vec3 c = centroid(m, t), n = face_normal(m, t);
    EXPECT_GT(glm::dot(n, c - glm::vec3(0.0f, 1.0f, 0.0f)), 0.0f);  // away from the middle of the axis
  }
  EXPECT_TRUE(m.colors.empty());
}

TEST(ShapeCylinder, SideFollowsTheLecturesAngleAndColours) {
  // Side vertex (cos t, y, sin t) with t = 2 pi s, t = y / height, colour (cos t, 0, sin t, 1);
  // the caps' rims the same by their angle, their centres (0, 0, 0, 1).
  Mesh m = make_cylinder({1.0f, 2.0f, 36, 1, true, true});
  expect_well_formed(m);
  ASSERT_EQ(m.colors.size(), m.positions.size());
  std::size_t side = 37u * 2;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3& p = m.positions[i];
    const glm::vec4& c = m.colors[i];
    if (i < side) {
      float t = 2.0f * kPi * m.texcoords[i].x;
      EXPECT_NEAR(p.x, std::cos(t), 1e-5f);
      EXPECT_NEAR(p.z, std::sin(t), 1e-5f);
      EXPECT_NEAR(p.y, 2.0f * m.texcoords[i].y, 1e-6f);
      EXPECT_NEAR(m.normals[i].y, 0.0f, 1e-6f);
    }
    bool centre = p.x == 0.0f && p.z == 0.0f;
    glm::vec4 expected = centre ? glm::vec4(0, 0, 0, 1) : glm::vec4(p.x, 0, p.z, 1);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(c[k], expected[k], 1e-6f) << i;
  }
  EXPECT_EQ(m.positions[0], glm::vec3(1.0f, 0.0f, 0.0f));  // t starts at 0
}

TEST(ShapeCylinder, OpenTubeHasBorders) {
  Mesh m = make_cylinder({1.0f, 2.0f, 5, 1, false, false});
  EXPECT_EQ(m.positions.size(), 12u);
  EXPECT_EQ(m.triangles.size(), 10u);
  EXPECT_NE(watertight_problem(m), "");
  expect_faces_agree_with_normals(m);
}

TEST(ShapeCone, ApexPerSliceAndSlantNormals) {
  // 8 slices, 2 stacks: rings at y = 0 and 1 (9 each), 8 apex copies, cap 1 + 8;
  // 16 side triangles, 8 at the apex, 8 in the cap.
  Mesh m = make_cone({1.0f, 2.0f, 8, 2, true});
  EXPECT_EQ(m.positions.size(), 18u + 8 + 9);
  EXPECT_EQ(m.triangles.size(), 16u + 8 + 8);
  expect_well_formed(m);
  EXPECT_EQ(watertight_problem(m), "");
  expect_faces_agree_with_normals(m);
  // Radius 1, height 2: the side normal is (2 cos t, 1, 2 sin t) / sqrt 5, so y = 1 / sqrt 5.
  int apex = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    if (m.normals[i].y > -0.5f) {  // not the cap
      EXPECT_NEAR(m.normals[i].y, 1.0f / std::sqrt(5.0f), 1e-6f) << i;
    }
    apex += m.positions[i] == glm::vec3(0.0f, 2.0f, 0.0f);
  }
  EXPECT_EQ(apex, 8);
}

TEST(ShapeTorus, ClosedWithNormalsOutOfTheTube) {
  // 8 rings, 6 sides: 9 x 7 vertices, 2 x 8 x 6 triangles.
  Mesh m = make_torus({1.0f, 0.25f, 6, 8});
  EXPECT_EQ(m.positions.size(), 63u);
  EXPECT_EQ(m.triangles.size(), 96u);
  expect_well_formed(m);
  EXPECT_EQ(watertight_problem(m), "");
  auto tube_centre = [](glm::vec3 p) { return glm::normalize(glm::vec3(p.x, p.y, 0.0f)); };  // major radius 1
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    glm::vec3 d = m.positions[i] - tube_centre(m.positions[i]);
    EXPECT_NEAR(glm::length(d), 0.25f, 1e-5f);
    EXPECT_NEAR(glm::length(m.normals[i] - d / 0.25f), 0.0f, 1e-5f);
  }
  for (const Triangle& t : m.triangles) {
    glm::vec3 c = centroid(m, t);
    EXPECT_GT(glm::dot(face_normal(m, t), c - tube_centre(c)), 0.0f);
  }
}

TEST(ShapeCube, TwentyFourVerticesOutwardFaces) {
  Mesh m = make_cube(2.0f);
  EXPECT_EQ(m.positions.size(), 24u);
  EXPECT_EQ(m.triangles.size(), 12u);
  expect_well_formed(m);
  EXPECT_EQ(watertight_problem(m), "");
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(std::abs(m.positions[i][k]), 1.0f);
    EXPECT_EQ(glm::dot(m.normals[i], m.positions[i]), 1.0f);  // an axis, on the vertex's face
  }
  for (const Triangle& t : m.triangles) {
    glm::vec3 n = glm::normalize(face_normal(m, t));
    EXPECT_EQ(n, m.normals[t[0]]);
    EXPECT_GT(glm::dot(n, centroid(m, t)), 0.0f);
  }
}

TEST(ShapeTetrahedron, LecturesVerticesOrderAndNormals) {
  const glm::vec3 v[4] = {{-1, -1, -1}, {1, -1, 1}, {-1, 1, 1}, {1, 1, -1}};
  const int faces[4][3] = {{0, 1, 2}, {1, 3, 2}, {0, 2, 3}, {0, 3, 1}};
  const glm::vec3 normals[4] = {{-1, -1, 1}, {1, 1, 1}, {-1, 1, -1}, {1, -1, -1}};
  Mesh m = make_tetrahedron();
  ASSERT_EQ(m.triangles.size(), 4u);
  expect_well_formed(m);
  EXPECT_EQ(watertight_problem(m), "");
  float s = 1.0f / std::sqrt(3.0f);
  for (int f = 0; f < 4; ++f) {
    const Triangle& t = m.triangles[f];
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(m.positions[t[k]], v[faces[f][k]]) << f;
      EXPECT_NEAR(glm::length(m.normals[t[k]] - s * normals[f]), 0.0f, 1e-6f) << f;
    }
    // Counter-clockwise from outside: the face normal is 4 times the lecture's (worked by hand).
    EXPECT_EQ(face_normal(m, t), 4.0f * normals[f]) << f;
  }
}

TEST(ShapeWall, GridBoundsTexcoordsAndSplit) {
  // 4 x 2 quads, 2 wide, 3 high: 5 x 3 shared vertices, 16 triangles.
  Mesh m = make_wall({2.0f, 3.0f, 4, 2});
  EXPECT_EQ(m.positions.size(), 15u);
  EXPECT_EQ(m.triangles.size(), 16u);
  expect_well_formed(m);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3& p = m.positions[i];
    EXPECT_EQ(p.z, 0.0f);
    EXPECT_EQ(m.normals[i], glm::vec3(0, 0, 1));
    EXPECT_NEAR(m.texcoords[i].x, (p.x + 1.0f) / 2.0f, 1e-6f);
    EXPECT_NEAR(m.texcoords[i].y, (p.y + 1.5f) / 3.0f, 1e-6f);
  }
  EXPECT_EQ(m.positions.front(), glm::vec3(-1.0f, -1.5f, 0.0f));
  EXPECT_EQ(m.positions.back(), glm::vec3(1.0f, 1.5f, 0.0f));
  // First quad: corners 0, 1, 6, 5 (rows of 5), split as GL_QUADS into (0,1,5) and (1,6,5).
  EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 5}));
  EXPECT_EQ(m.triangles[1], (Triangle{1, 6, 5}));
  for (const Triangle& t : m.triangles) EXPECT_GT(face_normal(m, t).z, 0.0f);
}

TEST(ShapePlane, FloorFacingUp) {
  Mesh m = make_plane(4.0f, 3);
  EXPECT_EQ(m.positions.size(), 16u);
  EXPECT_EQ(m.triangles.size(), 18u);
  expect_well_formed(m);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_EQ(m.positions[i].y, 0.0f);
    EXPECT_LE(std::abs(m.positions[i].x), 2.0f);
    EXPECT_LE(std::abs(m.positions[i].z), 2.0f);
    EXPECT_EQ(m.normals[i], glm::vec3(0, 1, 0));
  }
  for (const Triangle& t : m.triangles) EXPECT_GT(face_normal(m, t).y, 0.0f);
}

TEST(ShapeDisk, FullDiskHasOneCentreVertex) {
  // 8 slices, 2 loops: centre + 2 rings of 8; 8 fan triangles + 16 in the outer loop.
  Mesh m = make_disk({0.0f, 1.0f, 8, 2});
  EXPECT_EQ(m.positions.size(), 17u);
  EXPECT_EQ(m.triangles.size(), 24u);
  expect_well_formed(m);
  int centres = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3& p = m.positions[i];
    centres += p == glm::vec3(0.0f);
    EXPECT_LE(glm::length(p), 1.0f + 1e-6f);
    EXPECT_NEAR(m.texcoords[i].x, 0.5f + 0.5f * p.x, 1e-6f);  // planar, as gluDisk
    EXPECT_NEAR(m.texcoords[i].y, 0.5f + 0.5f * p.y, 1e-6f);
  }
  EXPECT_EQ(centres, 1);
  for (const Triangle& t : m.triangles) EXPECT_GT(face_normal(m, t).z, 0.0f);
}

TEST(ShapeDisk, AnnulusKeepsTheHole) {
  // 8 slices, 2 loops from 0.5 to 1: 3 rings of 8, 2 x 16 triangles.
  Mesh m = make_disk({0.5f, 1.0f, 8, 2});
  EXPECT_EQ(m.positions.size(), 24u);
  EXPECT_EQ(m.triangles.size(), 32u);
  expect_well_formed(m);
  for (const glm::vec3& p : m.positions) EXPECT_GE(glm::length(p), 0.5f - 1e-6f);
  for (const Triangle& t : m.triangles) EXPECT_GT(face_normal(m, t).z, 0.0f);
}

TEST(ShapeParameters, BadCountsAreClampedNotFatal) {
  EXPECT_EQ(make_wall({2.0f, 2.0f, 0, -5}).positions.size(), 4u);
  EXPECT_EQ(make_plane(1.0f, -3).triangles.size(), 2u);
  EXPECT_EQ(make_disk({0.0f, 1.0f, 0, 0}).triangles.size(), 3u);
  EXPECT_EQ(make_cylinder({1.0f, 1.0f, 1, 0, false, false}).triangles.size(), 6u);
  EXPECT_EQ(make_cone({1.0f, 1.0f, 2, -1, false}).triangles.size(), 3u);
  EXPECT_EQ(make_torus({1.0f, 0.5f, 0, 0}).triangles.size(), 18u);
  // Counts beyond 4096 segments are clamped: 4097 x 2 vertices, not two billion.
  EXPECT_EQ(make_wall({1.0f, 1.0f, INT_MAX, 1}).positions.size(), 4097u * 2);
  Mesh swapped = make_disk({2.0f, 1.0f, 5, 1});  // inner > outer: the annulus from 1 to 2
  expect_well_formed(swapped);
  for (const glm::vec3& p : swapped.positions) EXPECT_GE(glm::length(p), 1.0f - 1e-6f);
  for (const Triangle& t : swapped.triangles) EXPECT_GT(face_normal(swapped, t).z, 0.0f);
}

}  // namespace
}  // namespace shadelab
