// The lighting equation term by term (SPEC section 3), each expected value worked out by hand
// from the formula with the numbers written out.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/trigonometric.hpp>

#include "shadelab/lighting.hpp"

namespace shadelab {
namespace {

constexpr float kEps = 1e-5f;

Material bare() {  // everything black: tests switch on one term at a time
  Material m;
  m.ambient = m.diffuse = m.specular = m.emission = {0, 0, 0, 1};
  return m;
}

LightModel dark_model() {
  LightModel lm;
  lm.ambient = {0, 0, 0, 1};
  return lm;
}

Light white_directional(glm::vec3 dir) {
  Light l = default_light(0);
  l.position = glm::vec4(dir, 0.0f);
  return l;
}

LitColor lit(const LightModel& lm, std::vector<Light> lights, const Material& m,
             glm::vec3 p = {0, 0, 0}, glm::vec3 n = {0, 0, 1}) {
  return light_point(lm, lights, m, {p, n});
}

TEST(Lighting, DefaultsMatchTheSpecTable) {
  Light l0 = default_light(0), l1 = default_light(1);
  EXPECT_EQ(l0.diffuse, glm::vec4(1, 1, 1, 1));
  EXPECT_EQ(l0.specular, glm::vec4(1, 1, 1, 1));
  EXPECT_EQ(l1.diffuse, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(l1.specular, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(l0.ambient, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(l0.position, glm::vec4(0, 0, 1, 0));
  EXPECT_EQ(l0.spot_direction, glm::vec3(0, 0, -1));
  EXPECT_EQ(l0.spot_cutoff, 180.0f);
  EXPECT_EQ(l0.constant_attenuation, 1.0f);
  Material m;
  EXPECT_EQ(m.ambient, glm::vec4(0.2f, 0.2f, 0.2f, 1));
  EXPECT_EQ(m.diffuse, glm::vec4(0.8f, 0.8f, 0.8f, 1));
  EXPECT_EQ(m.shininess, 0.0f);
  EXPECT_EQ(LightModel{}.ambient, glm::vec4(0.2f, 0.2f, 0.2f, 1));
}

TEST(Lighting, EmissionAndGlobalAmbient) {
  Material m = bare();
  m.emission = {0.1f, 0.2f, 0.3f, 1};
  m.ambient = {0.5f, 0.5f, 0.5f, 1};
  LightModel lm;
  lm.ambient = {0.9f, 0.9f, 0.9f, 1};  // the lecture's globalAmbient
  LitColor c = lit(lm, {}, m);
  EXPECT_NEAR(c.primary.r, 0.1f + 0.5f * 0.9f, kEps);
  EXPECT_NEAR(c.primary.b, 0.3f + 0.5f * 0.9f, kEps);
}

TEST(Lighting, LambertFromTheLecturesDirection) {
  // Light from (1, 1, 1), normal (0, 0, 1): n . L = 1 / sqrt(3).
  Material m = bare();
  m.diffuse = {0.8f, 0.6f, 0.4f, 1};
  LitColor c = lit(dark_model(), {white_directional({1, 1, 1})}, m);
  EXPECT_NEAR(c.primary.r, 0.8f / std::sqrt(3.0f), kEps);
  EXPECT_NEAR(c.primary.g, 0.6f / std::sqrt(3.0f), kEps);
}

TEST(Lighting, LightBehindKeepsOnlyItsAmbient) {
  Material m = bare();
  m.ambient = {0.5f, 0.5f, 0.5f, 1};
  m.diffuse = {1, 1, 1, 1};
  m.specular = {1, 1, 1, 1};
  Light l = white_directional({0, 0, -1});
  l.ambient = {0.2f, 0.2f, 0.2f, 1};
  LitColor c = lit(dark_model(), {l}, m);
  EXPECT_NEAR(c.primary.r, 0.5f * 0.2f, kEps);
}

TEST(Lighting, BlinnSpecularShinyTeapotValues) {
  // Infinite viewer V = (0, 0, 1), light from (0, 1, 1)/sqrt2: h = normalize(0, .7071, 1.7071),
  // n . h = 1.7071 / sqrt(.5 + 2.9142) = cos(22.5 deg) = .92388; .92388^125 = 5.03e-5.
  // Diffuse .41 * cos(45 deg) = .28991; specular adds 5.03e-5.
  Material m = bare();
  m.diffuse = {.41f, .135f, .067f, 1};
  m.specular = {1, 1, 1, 1};
  m.shininess = 125;
  LitColor c = lit(dark_model(), {white_directional({0, 1, 1})}, m);
  float spec = std::pow(std::cos(glm::radians(22.5f)), 125.0f);
  EXPECT_NEAR(c.primary.r, 0.41f * 0.70710678f + spec, kEps);
  // Straight on (light along n): n . h = 1, the full white highlight, clamped to 1.
  LitColor h = lit(dark_model(), {white_directional({0, 0, 1})}, m);
  EXPECT_NEAR(h.primary.r, 1.0f, kEps);
  EXPECT_NEAR(h.primary.b, 1.0f, kEps);
}

TEST(Lighting, PhongReflectionVectorDiffersFromBlinn) {
  // Light at 45 degrees, viewer along n: Blinn uses cos(22.5) = .92388, Phong uses r . v with
  // r = 2 (n.L) n - L = (0, -.7071, .7071): r . v = .70711. Shininess 10.
  Material m = bare();
  m.specular = {1, 1, 1, 1};
  m.shininess = 10;
  LitColor blinn = lit(dark_model(), {white_directional({0, 1, 1})}, m);
  m.specular_model = SpecularModel::kPhong;
  LitColor phong = lit(dark_model(), {white_directional({0, 1, 1})}, m);
  EXPECT_NEAR(blinn.primary.r, std::pow(0.92387953f, 10.0f), 1e-4);
  EXPECT_NEAR(phong.primary.r, std::pow(0.70710678f, 10.0f), 1e-4);
}

TEST(Lighting, ShininessZeroGivesFullSpecularOnTheLitSide) {
  Material m = bare();
  m.specular = {0.3f, 0.3f, 0.3f, 1};
  LitColor c = lit(dark_model(), {white_directional({1, 0, 1})}, m);
  EXPECT_NEAR(c.primary.r, 0.3f, kEps);  // (n.h)^0 = 1
}

TEST(Lighting, LocalViewerChangesTheHighlight) {
  // Point (2, 0, -4) seen from the origin: local V = normalize(-2, 0, 4) = (-.4472, 0, .8944);
  // light along n = (0, 0, 1): h = normalize(-.4472, 0, 1.8944): n.h = .97325; ^20 = .5818.
  Material m = bare();
  m.specular = {1, 1, 1, 1};
  m.shininess = 20;
  LightModel lm = dark_model();
  LitColor far = lit(lm, {white_directional({0, 0, 1})}, m, {2, 0, -4});
  lm.local_viewer = true;
  LitColor near = lit(lm, {white_directional({0, 0, 1})}, m, {2, 0, -4});
  EXPECT_NEAR(far.primary.r, 1.0f, kEps);
  float h = 1.8944272f / std::sqrt(0.4472136f * 0.4472136f + 1.8944272f * 1.8944272f);
  EXPECT_NEAR(near.primary.r, std::pow(h, 20.0f), 1e-4);
}

TEST(Lighting, AttenuationTermsAndTheLecturesLinearHalf) {
  // Positional light 4 units above the point, along n: d = 4.
  Material m = bare();
  m.diffuse = {1, 1, 1, 1};
  m.ambient = {1, 1, 1, 1};
  Light l = default_light(0);
  l.position = {0, 0, 4, 1};
  l.ambient = {0.1f, 0.1f, 0.1f, 1};
  l.constant_attenuation = 0;
  l.linear_attenuation = 0.5f;  // the lecture: constant 0, linear .5, quadratic 0
  LitColor c = lit(dark_model(), {l}, m);
  EXPECT_NEAR(c.primary.r, (0.1f + 1.0f) / (0.5f * 4), kEps);  // ambient attenuated too
  l.constant_attenuation = 1;
  l.linear_attenuation = 0.25f;
  l.quadratic_attenuation = 0.125f;
  c = lit(dark_model(), {l}, m);
  EXPECT_NEAR(c.primary.r, 1.1f / (1 + 0.25f * 4 + 0.125f * 16), kEps);
  // A directional light is never attenuated.
  Light d = white_directional({0, 0, 1});
  d.linear_attenuation = 5;
  EXPECT_NEAR(lit(dark_model(), {d}, m).primary.r, 1.0f, kEps);
}

TEST(Lighting, SpotInsideOutsideEdgeAndExponent) {
  Material m = bare();
  m.diffuse = {1, 1, 1, 1};
  m.ambient = {1, 1, 1, 1};
  Light l = default_light(0);
  l.position = {0, 0, 1, 1};
  l.ambient = {0.5f, 0.5f, 0.5f, 1};
  l.spot_direction = {0, 0, -1};
  l.spot_cutoff = 30;
  // Point (tan 20 deg, 0, 0): 20 degrees off the axis, d = 1 / cos 20.
  float x20 = std::tan(glm::radians(20.0f));
  glm::vec3 p20(x20, 0, 0);
  float nl = std::cos(glm::radians(20.0f));  // n . L
  EXPECT_NEAR(lit(dark_model(), {l}, m, p20).primary.r, std::min(1.0f, 0.5f + nl), kEps);
  l.spot_exponent = 10;
  float spot = std::pow(std::cos(glm::radians(20.0f)), 10.0f);
  EXPECT_NEAR(lit(dark_model(), {l}, m, p20).primary.r, spot * (0.5f + nl), 1e-4);
  l.spot_exponent = 100;
  spot = std::pow(std::cos(glm::radians(20.0f)), 100.0f);
  EXPECT_NEAR(lit(dark_model(), {l}, m, p20).primary.r, spot * (0.5f + nl), 1e-4);
  // Outside the cone: nothing at all, ambient included.
  glm::vec3 p40(std::tan(glm::radians(40.0f)), 0, 0);
  EXPECT_NEAR(lit(dark_model(), {l}, m, p40).primary.r, 0.0f, kEps);
  // Just inside the edge (29.9 degrees) is lit, just outside (30.1) is not.
  l.spot_exponent = 0;
  EXPECT_GT(lit(dark_model(), {l}, m, {std::tan(glm::radians(29.9f)), 0, 0}).primary.r, 0.5f);
  EXPECT_EQ(lit(dark_model(), {l}, m, {std::tan(glm::radians(30.1f)), 0, 0}).primary.r, 0.0f);
  // Cutoff 180 ignores the direction.
  l.spot_cutoff = 180;
  l.spot_direction = {1, 0, 0};
  EXPECT_NEAR(lit(dark_model(), {l}, m, p20).primary.r, std::min(1.0f, 0.5f + nl), kEps);
}

TEST(Lighting, SpotAppliesToDirectionalLightsToo) {
  Material m = bare();
  m.diffuse = {1, 1, 1, 1};
  Light l = white_directional({0, 0, 1});
  l.spot_cutoff = 10;
  l.spot_direction = {1, 0, 0};  // -L . D = 0 < cos 10: outside
  EXPECT_EQ(lit(dark_model(), {l}, m).primary.r, 0.0f);
}

TEST(Lighting, ClampingAlphaAndSeparateSpecular) {
  Material m = bare();
  m.diffuse = {0.7f, 1, 0.85f, 0.3f};  // the lecture's transparent material
  m.specular = {1, 1, 1, 1};
  m.shininess = 100;
  Light a = white_directional({0, 0, 1}), b = white_directional({0, 0, 1});
  LitColor c = lit(dark_model(), {a, b}, m);
  EXPECT_EQ(c.primary.g, 1.0f);  // 2 + 2 clamped
  EXPECT_NEAR(c.primary.a, 0.3f, kEps);
  LightModel lm = dark_model();
  lm.separate_specular = true;
  LitColor s = lit(lm, {white_directional({0, 0, 1})}, m);
  EXPECT_NEAR(s.primary.r, 0.7f, kEps);  // the highlight moved out of the primary colour
  EXPECT_NEAR(s.secondary.r, 1.0f, kEps);
}

TEST(Lighting, LectureLightColoursAndDisabledLights) {
  // The lecture's two lights together on a material with ambient 1 and diffuse .25, both
  // along n: grey (ambient .1, white diffuse) + pale red ambient (.1, 0, 0) with yellow (1, 1, 0)
  // diffuse: red .1 + .25 + .1 + .25, green .1 + .25 + 0 + .25, blue .1 + .25 + 0 + 0.
  Material m = bare();
  m.ambient = {1, 1, 1, 1};
  m.diffuse = {0.25f, 0.25f, 0.25f, 1};
  Light grey = white_directional({0, 0, 1});
  grey.ambient = {0.1f, 0.1f, 0.1f, 1};
  Light yellow = white_directional({0, 0, 1});
  yellow.ambient = {0.1f, 0, 0, 1};
  yellow.diffuse = {1, 1, 0, 1};
  LitColor c = lit(dark_model(), {grey, yellow}, m);
  EXPECT_NEAR(c.primary.r, 0.1f + 0.25f + 0.1f + 0.25f, kEps);
  EXPECT_NEAR(c.primary.g, 0.1f + 0.25f + 0.0f + 0.25f, kEps);
  EXPECT_NEAR(c.primary.b, 0.1f + 0.25f, kEps);
  yellow.enabled = false;
  EXPECT_NEAR(lit(dark_model(), {grey, yellow}, m).primary.g, 0.35f, kEps);
}

TEST(Lighting, OrenNayarAtZeroRoughnessIsLambert) {
  Material m = bare();
  m.diffuse = {0.8f, 0.8f, 0.8f, 1};
  LitColor lambert = lit(dark_model(), {white_directional({1, 0.3f, 0.5f})}, m);
  m.diffuse_model = DiffuseModel::kOrenNayar;
  m.roughness = 0;
  EXPECT_EQ(lit(dark_model(), {white_directional({1, 0.3f, 0.5f})}, m).primary.r, lambert.primary.r);
  // Rough, light at 60 degrees and viewer along n (theta_r = 0, so tan(beta) = 0): only A
  // scales Lambert: A = 1 - .5 * .25 / (.25 + .33) = .78448.
  m.roughness = 0.5f;
  LitColor rough = lit(dark_model(), {white_directional({std::sqrt(3.0f), 0, 1})}, m);
  EXPECT_NEAR(rough.primary.r, 0.8f * 0.5f * (1 - 0.5f * 0.25f / 0.58f), 1e-5);
}

// An unnormalized normal makes the specular power overflow to infinity; a light outside its
// spot cone must still add nothing (no inf * 0 = NaN), and any NaN left clamps to 0.
TEST(Lighting, OverflowingSpecularOutsideTheConeAddsNothing) {
  Material m = bare();
  m.specular = {0, 1, 1, 1};  // a zero channel meets the infinite power too
  m.shininess = 128;
  m.specular_model = SpecularModel::kPhong;
  Light spot;
  spot.position = {0, 0, 5, 1};
  spot.spot_direction = {0, 0, 1};  // pointing away: the vertex is outside the cone
  spot.spot_cutoff = 30;
  spot.specular = {1, 1, 1, 1};
  LitColor c = light_point(dark_model(), std::vector<Light>{spot}, m, {{0, 0, 0}, {0, 0, 40}});
  for (int k = 0; k < 3; ++k) EXPECT_EQ(c.primary[k], 0.0f) << k;
  // Inside the cone the same overflow saturates to white where the material reflects.
  spot.spot_direction = {0, 0, -1};
  c = light_point(dark_model(), std::vector<Light>{spot}, m, {{0, 0, 0}, {0, 0, 40}});
  EXPECT_EQ(c.primary.g, 1.0f);
  EXPECT_FALSE(std::isnan(c.primary.r));
}

TEST(Lighting, TwoSidedIsTheCallersNegatedNormal) {
  Material m = bare();
  m.diffuse = {1, 1, 1, 1};
  Light l = white_directional({0, 0, -1});
  EXPECT_EQ(light_point(dark_model(), std::vector<Light>{l}, m, {{0, 0, 0}, {0, 0, 1}}).primary.r, 0.0f);
  EXPECT_NEAR(light_point(dark_model(), std::vector<Light>{l}, m, {{0, 0, 0}, {0, 0, -1}}).primary.r, 1.0f, kEps);
}

TEST(Lighting, ThirtyTwoLightsAndExplainSumsToTheResult) {
  Material m = bare();
  m.diffuse = {1, 1, 1, 1};
  m.emission = {0.01f, 0.01f, 0.01f, 1};
  std::vector<Light> lights(32, white_directional({0, 0, 1}));
  for (Light& l : lights) l.diffuse = {0.02f, 0.02f, 0.02f, 1};
  LitColor c = light_point(dark_model(), lights, m, {{0, 0, 0}, {0, 0, 1}});
  EXPECT_NEAR(c.primary.r, 0.01f + 32 * 0.02f, 1e-5);
  LightingBreakdown b = explain_point(dark_model(), lights, m, {{0, 0, 0}, {0, 0, 1}});
  ASSERT_EQ(b.lights.size(), 32u);
  glm::vec3 sum = b.emission + b.global_ambient;
  for (const LightTerm& t : b.lights) sum += t.ambient + t.diffuse + t.specular;
  EXPECT_NEAR(sum.r, b.unclamped.r, 1e-6);
  EXPECT_EQ(b.result.primary, c.primary);
}

}  // namespace
}  // namespace shadelab
