// Per-light and per-material constants for the SIMD lighting kernel, computed with glm exactly
// as src/lighting/lighting.cpp computes them for every point (so the kernel's results match).
#include "fast/lighting_setup.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "shadelab/lighting.hpp"

namespace shadelab::fast {

namespace {

void put3(float out[3], const glm::vec3& v) {
  out[0] = v.x;
  out[1] = v.y;
  out[2] = v.z;
}

MaterialParams material_params(const LightModel& model, const Material& m) {
  MaterialParams p;
  put3(p.base, glm::vec3(m.emission) + glm::vec3(m.ambient) * glm::vec3(model.ambient));
  put3(p.ambient, glm::vec3(m.ambient));
  put3(p.diffuse, glm::vec3(m.diffuse));
  put3(p.specular, glm::vec3(m.specular));
  p.alpha = std::clamp(m.diffuse.a, 0.0f, 1.0f);
  p.shininess = m.shininess;
  p.phong_specular = m.specular_model == SpecularModel::kPhong;
  return p;
}

void directional(const Light& light, bool local_viewer, LightParams& p) {
  glm::vec3 dir = glm::vec3(light.position);
  float len = glm::length(dir);
  glm::vec3 to_light = len > 0.0f ? dir / len : glm::vec3(0.0f);
  put3(p.pos, to_light);
  p.const_spot = spot_factor(light, to_light);
  p.const_half = !local_viewer;
  glm::vec3 h = to_light + glm::vec3(0.0f, 0.0f, 1.0f);  // v = (0, 0, 1) for an infinite viewer
  float h_len = glm::length(h);
  put3(p.half, h_len > 0.0f ? h / h_len : glm::vec3(0.0f));
}

void positional(const Light& light, LightParams& p) {
  p.positional = true;
  put3(p.pos, glm::vec3(light.position) / light.position.w);
  p.kc = light.constant_attenuation;
  p.kl = light.linear_attenuation;
  p.kq = light.quadratic_attenuation;
  if (light.spot_cutoff == 180.0f) return;
  p.spot = true;
  glm::vec3 d = light.spot_direction;
  float len = glm::length(d);
  p.spot_dark = !(len > 0.0f);
  if (!p.spot_dark) put3(p.spot_dir, d / len);
  p.cos_cutoff = std::cos(glm::radians(light.spot_cutoff));
  p.spot_exponent = light.spot_exponent;
}

}  // namespace

bool simd_supports(const Material& m) {
  return m.diffuse_model == DiffuseModel::kLambert || m.roughness == 0.0f;
}

void make_lighting_setup(const LightModel& model, std::span<const Light> lights,
                         const Material& front, const Material& back, LightingSetup& out) {
  out.lights.clear();
  for (const Light& light : lights) {
    if (!light.enabled) continue;
    LightParams p;
    if (light.position.w != 0.0f) positional(light, p);
    else directional(light, model.local_viewer, p);
    put3(p.ambient, glm::vec3(light.ambient));
    put3(p.diffuse, glm::vec3(light.diffuse));
    put3(p.specular, glm::vec3(light.specular));
    for (int side = 0; side < 2; ++side) {
      const Material& m = side == 0 ? front : back;
      put3(p.product[side][0], glm::vec3(m.ambient) * glm::vec3(light.ambient));
      put3(p.product[side][1], glm::vec3(m.diffuse) * glm::vec3(light.diffuse));
      put3(p.product[side][2], glm::vec3(m.specular) * glm::vec3(light.specular));
      const float* a = p.product[side][0];
      p.ambient_product[side] = !(a[0] == 0.0f && a[1] == 0.0f && a[2] == 0.0f);
    }
    out.lights.push_back(p);
  }
  out.front = material_params(model, front);
  out.back = material_params(model, back);
  out.back.side = 1;
  out.local_viewer = model.local_viewer;
  out.separate_specular = model.separate_specular;
}

}  // namespace shadelab::fast
