// The Utah teapot: counts, glutSolidTeapot's size and orientation (bounds worked out from
// Newell's data by hand), finite unit normals even where patches collapse to a point, and faces
// counter-clockwise from outside (agreeing with the analytic normals, the body facing out).
#include <gtest/gtest.h>

#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "shadelab/shapes.hpp"

namespace shadelab {
namespace {

glm::vec3 face_normal(const Mesh& m, const Triangle& t) {
  return glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
}

glm::vec3 centroid(const Mesh& m, const Triangle& t) {
  return (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0f;
}

/// Triangles with area: the patches that collapse to a point (lid knob, bottom centre) give a
/// zero-area triangle per segment there, which draws nothing.
bool has_area(const Mesh& m, const Triangle& t) { return glm::length(face_normal(m, t)) > 1e-10f; }

TEST(Teapot, CountsAndFiniteUnitNormals) {
  // 32 patches of (3 + 1)^2 vertices and 2 x 3 x 3 triangles.
  Mesh m = make_teapot({1.0f, 3});
  EXPECT_EQ(m.positions.size(), 32u * 16);
  EXPECT_EQ(m.triangles.size(), 32u * 18);
  ASSERT_EQ(m.normals.size(), m.positions.size());
  ASSERT_EQ(m.texcoords.size(), m.positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(m.positions[i][k]) && std::isfinite(m.normals[i][k])) << i;
    EXPECT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-5f) << i;
    EXPECT_TRUE(m.texcoords[i].x >= 0.0f && m.texcoords[i].x <= 1.0f && m.texcoords[i].y >= 0.0f &&
                m.texcoords[i].y <= 1.0f);
  }
  for (const Triangle& t : m.triangles) {
    for (std::uint32_t v : t) ASSERT_LT(v, m.positions.size());
  }
}

TEST(Teapot, SizedAndTurnedLikeGlutSolidTeapot) {
  // Data (z up): bottom z = 0, knob top z = 3.15, handle back x = -3, body radius 2, spout tip
  // near x = 3.4. GLUT: (x, y, z) -> 0.5 (x, z - 1.5, -y). So y in [-0.75, 0.825], x from
  // -1.5 to about 1.7, z in [-1, 1].
  Mesh m = make_teapot({1.0f, 10});
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const glm::vec3& p : m.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  EXPECT_NEAR(lo.y, -0.75f, 1e-4f);
  EXPECT_NEAR(hi.y, 0.825f, 1e-4f);
  EXPECT_NEAR(lo.x, -1.5f, 1e-3f);
  EXPECT_NEAR(hi.x, 1.7f, 0.03f);
  EXPECT_NEAR(lo.z, -1.0f, 0.01f);
  EXPECT_NEAR(hi.z, 1.0f, 0.01f);
  // The spout's tip (largest x) lies on the plane of symmetry, above the middle.
  std::size_t tip = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) tip = m.positions[i].x > m.positions[tip].x ? i : tip;
  EXPECT_NEAR(m.positions[tip].z, 0.0f, 1e-3f);
  EXPECT_GT(m.positions[tip].y, 0.4f);
}

TEST(Teapot, SizeScalesPositionsOnly) {
  Mesh a = make_teapot({1.0f, 4}), b = make_teapot({3.0f, 4});
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i) {
    EXPECT_NEAR(glm::length(b.positions[i] - 3.0f * a.positions[i]), 0.0f, 1e-5f);
    EXPECT_EQ(a.normals[i], b.normals[i]);
  }
}

TEST(Teapot, FacesAgreeWithAnalyticNormals) {
  Mesh m = make_teapot({1.0f, 8});
  int with_area = 0, disagree = 0;
  for (const Triangle& t : m.triangles) {
    if (!has_area(m, t)) continue;
    ++with_area;
    glm::vec3 n = m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]];
    disagree += glm::dot(face_normal(m, t), n) <= 0.0f;
  }
  EXPECT_GT(with_area, 32 * 128 - 8 * 8 - 1);  // at most one collapsed triangle per segment of 8 patches
  EXPECT_EQ(disagree, 0);
}

TEST(Teapot, BodyBottomAndLidFaceOutward) {
  Mesh m = make_teapot({1.0f, 8});
  int body = 0, bottom = 0, knob = 0;
  for (const Triangle& t : m.triangles) {
    if (!has_area(m, t)) continue;
    glm::vec3 c = centroid(m, t), n = face_normal(m, t);
    glm::vec2 radial(c.x, c.z);
    // The body between bottom and rim (y from -0.675 to 0.45), front and back, away from the
    // handle (x < -0.75) and spout (x > 0.85): faces point away from the axis.
    if (c.y > -0.6f && c.y < 0.4f && std::abs(c.x) < 0.7f && glm::length(radial) > 0.72f) {
      ++body;
      EXPECT_GT(glm::dot(glm::vec2(n.x, n.z), radial), 0.0f) << c.x << " " << c.y << " " << c.z;
    }
    if (c.y < -0.74f) {  // the bottom (data z below 0.02; the body ends at z = 0.15) faces down
      ++bottom;
      EXPECT_LT(n.y, 0.0f);
    }
    if (c.y > 0.82f) {  // the top of the knob faces up
      ++knob;
      EXPECT_GT(n.y, 0.0f);
    }
  }
  EXPECT_GT(body, 100);
  EXPECT_GT(bottom, 50);
  EXPECT_GT(knob, 4);
}

TEST(Teapot, EnclosesAPositiveVolume) {
  // Sum of signed tetrahedra (origin, triangle): positive when the faces point outward. The body
  // is roughly a solid of revolution of radius 0.9 and height 1.1: pi 0.81 1.1 = 2.8.
  Mesh m = make_teapot({1.0f, 12});
  double volume = 0.0;
  for (const Triangle& t : m.triangles) {
    volume += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]])) / 6.0;
  }
  EXPECT_GT(volume, 2.0);
  EXPECT_LT(volume, 4.0);
}

TEST(Teapot, CollapsedPatchCornersGetTheAxisNormal) {
  // Knob top (0, 0.825, 0) faces up, bottom centre (0, -0.75, 0) faces down.
  Mesh m = make_teapot({1.0f, 6});
  int top = 0, bottom = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3& p = m.positions[i];
    if (std::abs(p.x) > 1e-5f || std::abs(p.z) > 1e-5f) continue;
    if (std::abs(p.y - 0.825f) < 1e-5f) {
      ++top;
      EXPECT_GT(m.normals[i].y, 0.999f);
    }
    if (std::abs(p.y + 0.75f) < 1e-5f) {
      ++bottom;
      EXPECT_LT(m.normals[i].y, -0.999f);
    }
  }
  EXPECT_EQ(top, 4 * 7);  // 4 lid patches, a whole edge of 7 vertices each
  EXPECT_EQ(bottom, 4 * 7);
}

TEST(Teapot, BadTessellationIsClamped) {
  Mesh m = make_teapot({1.0f, -5});
  EXPECT_EQ(m.positions.size(), 32u * 4);
  EXPECT_EQ(m.triangles.size(), 32u * 2);
  for (const glm::vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

}  // namespace
}  // namespace shadelab
