// The lecture's shadow matrices against its closed forms (SPEC section 6) on random planes,
// directions and lights: the projected point is the closed-form point and lies on the plane.
#include <gtest/gtest.h>

#include <random>

#include "shadelab/shadow.hpp"

namespace shadelab {
namespace {

glm::vec3 project(const glm::mat4& m, const glm::vec3& p) {
  glm::vec4 q = m * glm::vec4(p, 1.0f);
  return glm::vec3(q) / q.w;
}

TEST(PlanarShadow, DirectionalMatchesClosedFormAndLiesOnPlane) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  for (int i = 0; i < 200; ++i) {
    Plane plane(u(rng), u(rng), u(rng), u(rng));
    glm::vec3 dir(u(rng), u(rng), u(rng)), p(u(rng), u(rng), u(rng));
    float denom = plane.x * dir.x + plane.y * dir.y + plane.z * dir.z;
    if (std::abs(denom) < 0.2f) continue;
    float alpha = -(plane.x * p.x + plane.y * p.y + plane.z * p.z + plane.w) / denom;
    glm::vec3 expected = p + alpha * dir;
    glm::vec3 got = project(directional_light_shadow(dir, plane), p);
    EXPECT_NEAR(got.x, expected.x, 1e-3f);
    EXPECT_NEAR(got.y, expected.y, 1e-3f);
    EXPECT_NEAR(got.z, expected.z, 1e-3f);
    EXPECT_NEAR(glm::dot(glm::vec3(plane), got) + plane.w, 0.0f, 1e-3f);
  }
}

TEST(PlanarShadow, LectureExampleDirectional) {
  // Plane z + 5 = 0, light direction (1, 1, 1): (0, 0, 0) goes to (-5, -5, -5).
  glm::vec3 q = project(directional_light_shadow({1, 1, 1}, {0, 0, 1, 5}), {0, 0, 0});
  EXPECT_NEAR(q.x, -5.0f, 1e-6f);
  EXPECT_NEAR(q.y, -5.0f, 1e-6f);
  EXPECT_NEAR(q.z, -5.0f, 1e-6f);
}

TEST(PlanarShadow, PointMatchesClosedFormAndLiesOnPlane) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    Plane plane(u(rng), u(rng), u(rng), u(rng));
    glm::vec3 light(u(rng), u(rng), u(rng)), p(u(rng), u(rng), u(rng));
    // Closed form with the light at the origin: p' = -d p / (a x + b y + c z), after moving
    // the origin to the light (new_d = d + a lx + b ly + c lz).
    glm::vec3 rel = p - light;
    float new_d = plane.w + glm::dot(glm::vec3(plane), light);
    float denom = glm::dot(glm::vec3(plane), rel);
    if (std::abs(denom) < 0.2f || std::abs(new_d) < 0.2f) continue;
    glm::vec3 expected = light + (-new_d / denom) * rel;
    glm::vec3 got = project(point_light_shadow(light, plane), p);
    EXPECT_NEAR(got.x, expected.x, 2e-3f * (1 + std::abs(expected.x)));
    EXPECT_NEAR(got.y, expected.y, 2e-3f * (1 + std::abs(expected.y)));
    EXPECT_NEAR(got.z, expected.z, 2e-3f * (1 + std::abs(expected.z)));
    EXPECT_NEAR(glm::dot(glm::vec3(plane), got) + plane.w, 0.0f, 5e-3f * (1 + glm::length(got)));
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

TEST(PlanarShadow, PointBeyondTheLightHasNonPositiveW) {
  // Light at (0, 0, 2) above the plane z = 0; a point above the light projects with w < 0.
  glm::mat4 m = point_light_shadow({0, 0, 2}, {0, 0, 1, 0});
  EXPECT_GT((m * glm::vec4(0.5f, 0, 1, 1)).w, 0.0f);  // between plane and light
  EXPECT_LT((m * glm::vec4(0.5f, 0, 3, 1)).w, 0.0f);  // beyond the light
}

}  // namespace
}  // namespace shadelab
