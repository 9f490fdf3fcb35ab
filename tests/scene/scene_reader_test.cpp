// The scene reader on valid input: every value lands in its field, OpenGL's defaults (SPEC
// section 3) fill the rest, transforms compose in GL call order, and the camera's matrices.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "shadelab/scene_io.hpp"

namespace shadelab {
namespace {

Scene load(const std::string& text) {
  LoadResult r = parse_scene(text, "s.json", ".");
  EXPECT_TRUE(r.scene) << r.diagnostics.to_string();
  return r.scene ? *r.scene : Scene{};
}

glm::vec3 apply(const glm::mat4& m, glm::vec3 p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }

void expect_near(glm::vec3 a, glm::vec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(SceneReader, EmptySceneHasOpenGLDefaults) {
  Scene s = load("{}");
  EXPECT_EQ(s.width, 640);
  EXPECT_EQ(s.height, 480);
  EXPECT_EQ(s.background, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(s.camera.eye, glm::vec3(0, 0, 8));
  EXPECT_EQ(s.camera.target, glm::vec3(0, 0, 0));
  EXPECT_EQ(s.camera.up, glm::vec3(0, 1, 0));
  EXPECT_EQ(s.camera.projection, Camera::Projection::kPerspective);
  EXPECT_EQ(s.camera.fovy_degrees, 30.0f);
  EXPECT_EQ(s.camera.near_plane, 0.1f);
  EXPECT_EQ(s.camera.far_plane, 100.0f);
  EXPECT_EQ(s.light_model.ambient, glm::vec4(0.2f, 0.2f, 0.2f, 1));  // GL_LIGHT_MODEL_AMBIENT
  EXPECT_FALSE(s.light_model.local_viewer);
  EXPECT_FALSE(s.light_model.two_side);
  EXPECT_TRUE(s.lights.empty());
  EXPECT_TRUE(s.objects.empty());
}

TEST(SceneReader, LightsTakeOpenGLDefaultsByIndex) {
  Scene s = load(R"({"lights": [{}, {"position": [2, 4, 6, 1]}, {"diffuse": [1, 1, 0]}]})");
  ASSERT_EQ(s.lights.size(), 3u);
  const Light& l0 = s.lights[0].light;
  EXPECT_EQ(l0.diffuse, glm::vec4(1, 1, 1, 1));  // GL_LIGHT0: white diffuse and specular
  EXPECT_EQ(l0.specular, glm::vec4(1, 1, 1, 1));
  EXPECT_EQ(l0.ambient, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(l0.position, glm::vec4(0, 0, 1, 0));
  EXPECT_EQ(l0.spot_direction, glm::vec3(0, 0, -1));
  EXPECT_EQ(l0.spot_cutoff, 180.0f);
  EXPECT_EQ(l0.spot_exponent, 0.0f);
  EXPECT_EQ(l0.constant_attenuation, 1.0f);
  EXPECT_EQ(l0.linear_attenuation, 0.0f);
  EXPECT_EQ(l0.quadratic_attenuation, 0.0f);
  EXPECT_TRUE(l0.enabled);
  EXPECT_FALSE(s.lights[0].eye_space);
  const Light& l1 = s.lights[1].light;
  EXPECT_EQ(l1.diffuse, glm::vec4(0, 0, 0, 1));  // GL_LIGHT1..: black
  EXPECT_EQ(l1.specular, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(l1.position, glm::vec4(2, 4, 6, 1));
  EXPECT_EQ(s.lights[2].light.diffuse, glm::vec4(1, 1, 0, 1));  // alpha defaults to 1
  EXPECT_EQ(s.lights[2].light.specular, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(default_light(0).diffuse, glm::vec4(1));
  EXPECT_EQ(default_light(7).specular, glm::vec4(0, 0, 0, 1));
}

TEST(SceneReader, EveryKeyLandsInItsField) {
  Scene s = load(R"({
    "caption": "test",
    "image": {"width": 320, "height": 200, "background": [0.1, 0.2, 0.3, 0.5], "samples": 4},
    "camera": {"eye": [1, 2, 3], "target": [0, 1, 0], "up": [0, 0, 1], "projection": "orthographic",
               "fovy": 45, "ortho_height": 6, "near": 0.5, "far": 50},
    "light_model": {"ambient": [0.9, 0.9, 0.9], "local_viewer": true, "two_side": true,
                    "separate_specular": true},
    "lights": [{"position": [0, 0, 8, 1], "ambient": [0.1, 0, 0], "space": "eye", "enabled": false,
                "attenuation": {"constant": 0, "linear": 0.5, "quadratic": 0.25},
                "spot": {"direction": [0, 0, -2], "cutoff": 30, "exponent": 100}}]
  })");
  EXPECT_EQ(s.caption, "test");
  EXPECT_EQ(s.width, 320);
  EXPECT_EQ(s.height, 200);
  EXPECT_EQ(s.samples, 4);
  EXPECT_EQ(s.background, glm::vec4(0.1f, 0.2f, 0.3f, 0.5f));
  EXPECT_EQ(s.camera.eye, glm::vec3(1, 2, 3));
  EXPECT_EQ(s.camera.target, glm::vec3(0, 1, 0));
  EXPECT_EQ(s.camera.up, glm::vec3(0, 0, 1));
  EXPECT_EQ(s.camera.projection, Camera::Projection::kOrthographic);
  EXPECT_EQ(s.camera.fovy_degrees, 45.0f);
  EXPECT_EQ(s.camera.ortho_height, 6.0f);
  EXPECT_EQ(s.camera.near_plane, 0.5f);
  EXPECT_EQ(s.camera.far_plane, 50.0f);
  EXPECT_EQ(s.light_model.ambient, glm::vec4(0.9f, 0.9f, 0.9f, 1));
  EXPECT_TRUE(s.light_model.local_viewer);
  EXPECT_TRUE(s.light_model.two_side);
  EXPECT_TRUE(s.light_model.separate_specular);
  ASSERT_EQ(s.lights.size(), 1u);
  const Light& l = s.lights[0].light;
  EXPECT_TRUE(s.lights[0].eye_space);
  EXPECT_FALSE(l.enabled);
  EXPECT_EQ(l.ambient, glm::vec4(0.1f, 0, 0, 1));
  EXPECT_EQ(l.diffuse, glm::vec4(1, 1, 1, 1));  // still light 0's default
  EXPECT_EQ(l.constant_attenuation, 0.0f);
  EXPECT_EQ(l.linear_attenuation, 0.5f);
  EXPECT_EQ(l.quadratic_attenuation, 0.25f);
  EXPECT_EQ(l.spot_direction, glm::vec3(0, 0, -2));
  EXPECT_EQ(l.spot_cutoff, 30.0f);
  EXPECT_EQ(l.spot_exponent, 100.0f);
}

TEST(SceneReader, ObjectsMaterialsAndBlending) {
  Scene s = load(R"({
    "materials": {"glass": {"ambient": [0.7, 1, 0.85, 0.3], "diffuse": [0.7, 1, 0.85, 0.3],
                            "specular": [1, 1, 1], "shininess": 100, "specular_model": "phong"}},
    "objects": [
      {"shape": "cube", "material": "glass"},
      {"name": "pot", "shape": {"type": "teapot", "tessellation": 2}, "material": "shiny_red",
       "back_material": {"diffuse": [0, 0, 1], "diffuse_model": "oren-nayar", "roughness": 0.5},
       "shading": "phong", "cull": "back", "blend": "additive"},
      {"shape": "tetrahedron", "lighting": false, "color": [1, 0, 0, 0.5], "shading": "flat"},
      {"shape": "sphere", "material": {"emission": [1, 1, 0.75]}, "blend": "none"}
    ]
  })");
  ASSERT_EQ(s.objects.size(), 4u);
  const SceneObject& glass = s.objects[0];
  EXPECT_EQ(glass.name, "objects[0]");
  EXPECT_EQ(glass.front.diffuse, glm::vec4(0.7f, 1, 0.85f, 0.3f));
  EXPECT_EQ(glass.front.shininess, 100.0f);
  EXPECT_EQ(glass.front.specular_model, SpecularModel::kPhong);
  EXPECT_EQ(glass.front.emission, glm::vec4(0, 0, 0, 1));  // unset keys keep GL's defaults
  EXPECT_FALSE(glass.back);
  EXPECT_EQ(glass.shading, ShadingMode::kGouraud);
  EXPECT_EQ(glass.cull, CullMode::kNone);
  EXPECT_TRUE(glass.blend.enabled);  // auto: diffuse alpha 0.3
  EXPECT_EQ(glass.blend.src, BlendFactor::kSrcAlpha);
  EXPECT_EQ(glass.blend.dst, BlendFactor::kOneMinusSrcAlpha);
  EXPECT_EQ(glass.mesh->triangles.size(), 12u);
  const SceneObject& pot = s.objects[1];
  EXPECT_EQ(pot.name, "pot");
  EXPECT_EQ(pot.front.shininess, 125.0f);  // the shiny_red preset
  ASSERT_TRUE(pot.back);
  EXPECT_EQ(pot.back->diffuse, glm::vec4(0, 0, 1, 1));
  EXPECT_EQ(pot.back->ambient, glm::vec4(0.2f, 0.2f, 0.2f, 1));
  EXPECT_EQ(pot.back->diffuse_model, DiffuseModel::kOrenNayar);
  EXPECT_EQ(pot.back->roughness, 0.5f);
  EXPECT_EQ(pot.shading, ShadingMode::kPhong);
  EXPECT_EQ(pot.cull, CullMode::kBack);
  EXPECT_TRUE(pot.blend.enabled);
  EXPECT_EQ(pot.blend.src, BlendFactor::kOne);
  EXPECT_EQ(pot.blend.dst, BlendFactor::kOne);
  EXPECT_LE(pot.mesh->triangles.size(), 32u * 2 * 2 * 2);
  const SceneObject& unlit = s.objects[2];
  EXPECT_FALSE(unlit.lighting);
  EXPECT_EQ(unlit.color, glm::vec4(1, 0, 0, 0.5f));
  EXPECT_EQ(unlit.shading, ShadingMode::kFlat);
  EXPECT_TRUE(unlit.blend.enabled);  // auto, unlit: the colour's alpha
  EXPECT_EQ(s.objects[3].front.emission, glm::vec4(1, 1, 0.75f, 1));
  EXPECT_EQ(s.objects[3].front.diffuse, glm::vec4(0.8f, 0.8f, 0.8f, 1));  // GL's default material
  EXPECT_FALSE(s.objects[3].blend.enabled);
}

TEST(SceneReader, TransformsComposeInOpenGLCallOrder) {
  Scene s = load(R"({"objects": [
    {"shape": "cube", "transform": {"translate": [1, 0, 0], "rotate": [90, 0, 0, 1], "scale": 2}},
    {"shape": "cube", "transform": {"rotate": [[90, 0, 0, 1], [90, 1, 0, 0]]}},
    {"shape": "cube", "transform": {"scale": [1, 2, 3], "translate": [0, 0, -5]}},
    {"shape": "cube"}
  ]})");
  ASSERT_EQ(s.objects.size(), 4u);
  // T * R * S: (1, 0, 0) scaled to (2, 0, 0), turned 90 degrees about z to (0, 2, 0), moved by +x.
  expect_near(apply(s.objects[0].model, {1, 0, 0}), {1, 2, 0});
  // Rz * Rx: x first, so (0, 1, 0) goes to (0, 0, 1), which z leaves alone (the other order
  // would give (-1, 0, 0)).
  expect_near(apply(s.objects[1].model, {0, 1, 0}), {0, 0, 1});
  expect_near(apply(s.objects[2].model, {1, 1, 1}), {1, 2, -2});  // key order does not matter
  EXPECT_EQ(s.objects[3].model, glm::mat4(1.0f));
}

TEST(SceneCamera, MatricesAreLookAtAndPerspectiveOrOrtho) {
  Camera c;  // eye (0, 0, 8) looking at the origin
  expect_near(apply(c.view_matrix(), {0, 0, 0}), {0, 0, -8});
  expect_near(apply(c.view_matrix(), {0, 0, 8}), {0, 0, 0});
  c.eye = {8, 0, 0};  // looking down -x: world -z is on the eye's right (+x)
  expect_near(apply(c.view_matrix(), {0, 0, -1}), {1, 0, -8});
  c.fovy_degrees = 90;
  c.near_plane = 1;
  c.far_plane = 3;
  glm::vec4 top = c.projection_matrix(2.0f) * glm::vec4(0, 1, -1, 1);  // the near plane's top
  EXPECT_NEAR(top.y / top.w, 1.0f, 1e-6f);
  EXPECT_NEAR(top.z / top.w, -1.0f, 1e-6f);
  glm::vec4 right = c.projection_matrix(2.0f) * glm::vec4(2, 0, -1, 1);  // aspect 2: x reaches 2
  EXPECT_NEAR(right.x / right.w, 1.0f, 1e-6f);
  c.projection = Camera::Projection::kOrthographic;
  c.ortho_height = 4;
  glm::vec4 corner = c.projection_matrix(2.0f) * glm::vec4(4, 2, -3, 1);  // half sizes 4 x 2
  EXPECT_NEAR(corner.x, 1.0f, 1e-6f);
  EXPECT_NEAR(corner.y, 1.0f, 1e-6f);
  EXPECT_NEAR(corner.z, 1.0f, 1e-6f);  // the far plane
}

}  // namespace
}  // namespace shadelab
