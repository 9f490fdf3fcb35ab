// The OpenGL 1.x lighting equation (GL 1.5 spec, section 2.14.1), once, for every shading
// mode. light_point and explain_point share one implementation; explain_point records terms.
// This is the definition; tests/lighting/lighting_test.cpp checks it term by term against
// values worked out by hand. Elsewhere the equation is only called or, once, re-expressed:
// - The reference pipeline (src/pipeline/draw.cpp, whose shade_fragment the fast pipeline's
//   per-fragment path shares), the fast pipeline's vertex stage where its SIMD form does not
//   apply (src/fast/vertex_stage.cpp), "explain this pixel" (src/explain) and the GL library
//   (gl/src/draw.cpp's light_vertex, gl/src/raster_pos.cpp) call light_point; the GL library
//   keeps no copy of the equation.
// - The fast pipeline's batched SIMD form, src/fast/lighting-inl.h (its per-draw constants
//   from src/fast/lighting_setup.cpp), evaluates the same equation over SIMD lanes: per
//   vertex operation for operation but for the powers, per pixel within a few float
//   roundings. The fast pipeline's differential tests hold it to light_point through the
//   reference pipeline:
//   tests/fast/differential_test.cpp (FastDifferential: randomized lit draws in every shading
//   mode, on 1 to 3 threads and on every SIMD target; overflowing specular powers; non-finite
//   normals) and tests/fast/scene_differential_test.cpp (FastScenes: every scene file in every
//   shading mode), each pixel within 1/255. A change here must be made there too.
#include "shadelab/lighting.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace shadelab {

float spot_factor(const Light& light, const glm::vec3& to_light) {
  if (light.spot_cutoff == 180.0f) return 1.0f;
  glm::vec3 d = light.spot_direction;
  float len = glm::length(d);
  if (!(len > 0.0f)) return 0.0f;
  float c = glm::dot(-to_light, d / len);
  float cos_cutoff = std::cos(glm::radians(light.spot_cutoff));
  if (c < cos_cutoff) return 0.0f;
  // pow(0, 0) is 1 in C, as the GL equation wants for exponent 0 at the cone's centre line.
  return std::pow(std::max(c, 0.0f), light.spot_exponent);
}

namespace {

glm::vec3 rgb(const glm::vec4& v) { return glm::vec3(v); }

// Oren-Nayar's qualitative model: the Lambert cosine scaled by A + B max(0, cos(phi_i - phi_r))
// sin(alpha) tan(beta). At roughness 0, A = 1 and B = 0: exactly Lambert.
float oren_nayar(float sigma, const glm::vec3& n, const glm::vec3& l, const glm::vec3& v,
                 float n_dot_l) {
  float s2 = sigma * sigma;
  float a = 1.0f - 0.5f * s2 / (s2 + 0.33f);
  float b = 0.45f * s2 / (s2 + 0.09f);
  if (b == 0.0f) return n_dot_l * a;
  float n_dot_v = std::clamp(glm::dot(n, v), -1.0f, 1.0f);
  float theta_i = std::acos(std::clamp(n_dot_l, -1.0f, 1.0f));
  float theta_r = std::acos(n_dot_v);
  // cos(phi_i - phi_r): the angle between l and v projected onto the tangent plane.
  glm::vec3 lp = l - n * n_dot_l, vp = v - n * n_dot_v;
  float lp_len = glm::length(lp), vp_len = glm::length(vp);
  float cos_phi = (lp_len > 0.0f && vp_len > 0.0f) ? glm::dot(lp, vp) / (lp_len * vp_len) : 0.0f;
  float alpha = std::max(theta_i, theta_r), beta = std::min(theta_i, theta_r);
  return n_dot_l * (a + b * std::max(0.0f, cos_phi) * std::sin(alpha) * std::tan(beta));
}

// The specular cosine raised to the shininess; f_i (n . L > 0) is checked by the caller.
float specular_factor(const Material& m, const glm::vec3& n, const glm::vec3& l,
                      const glm::vec3& v) {
  float c;
  if (m.specular_model == SpecularModel::kPhong) {
    glm::vec3 r = 2.0f * glm::dot(n, l) * n - l;  // mirror of L about n
    c = glm::dot(r, v);
  } else {
    glm::vec3 h = l + v;
    float len = glm::length(h);
    c = len > 0.0f ? glm::dot(n, h / len) : 0.0f;
  }
  return c > 0.0f ? std::pow(c, m.shininess) : 0.0f;
}

// One light's term, with attenuation and spot applied (GL 1.5 eq. 2.4, inside the sum).
LightTerm light_term(int index, const Light& light, const Material& m, const glm::vec3& p,
                     const glm::vec3& n, const glm::vec3& v, float visibility) {
  LightTerm t;
  t.light = index;
  glm::vec3 to_light;
  if (light.position.w != 0.0f) {
    glm::vec3 delta = glm::vec3(light.position) / light.position.w - p;
    float d = glm::length(delta);
    to_light = d > 0.0f ? delta / d : glm::vec3(0.0f);
    float denom = light.constant_attenuation + light.linear_attenuation * d +
                  light.quadratic_attenuation * d * d;
    t.attenuation = denom > 0.0f ? 1.0f / denom : 0.0f;
  } else {
    glm::vec3 dir = glm::vec3(light.position);
    float len = glm::length(dir);
    to_light = len > 0.0f ? dir / len : glm::vec3(0.0f);
  }
  t.spot = spot_factor(light, to_light);
  float scale = t.attenuation * t.spot;
  t.n_dot_l = glm::dot(n, to_light);
  t.ambient = scale * rgb(m.ambient) * rgb(light.ambient);
  // A light whose attenuation times spot factor is 0 adds nothing more (as Mesa skips it), so
  // that an overflowing specular power never meets a zero factor (inf * 0).
  if (t.n_dot_l > 0.0f && visibility > 0.0f && scale > 0.0f) {
    scale *= visibility;  // shadowed: only the ambient term stays
    float diffuse = m.diffuse_model == DiffuseModel::kOrenNayar
                        ? oren_nayar(m.roughness, n, to_light, v, t.n_dot_l)
                        : t.n_dot_l;
    t.diffuse = scale * diffuse * rgb(m.diffuse) * rgb(light.diffuse);
    t.specular = scale * specular_factor(m, n, to_light, v) * rgb(m.specular) *
                 rgb(light.specular);
  }
  return t;
}

// Clamps to [0, 1]; NaN (from inf - inf with unnormalized normals or huge colours) becomes 0.
float clamp01(float x) { return x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0f; }
glm::vec3 clamp01(const glm::vec3& c) { return {clamp01(c.x), clamp01(c.y), clamp01(c.z)}; }

// The whole equation. `terms`, when given, receives each enabled light's term.
LitColor evaluate(const LightModel& model, std::span<const Light> lights, const Material& m,
                  const LightingInput& in, LightingBreakdown* breakdown) {
  glm::vec3 v = model.local_viewer ? -in.position : glm::vec3(0.0f, 0.0f, 1.0f);
  float v_len = glm::length(v);
  v = v_len > 0.0f ? v / v_len : glm::vec3(0.0f, 0.0f, 1.0f);
  glm::vec3 emission = rgb(m.emission);
  glm::vec3 global_ambient = rgb(m.ambient) * rgb(model.ambient);
  glm::vec3 primary = emission + global_ambient, specular(0.0f);
  for (std::size_t i = 0; i < lights.size(); ++i) {
    if (!lights[i].enabled) continue;
    float visible = in.visibility ? in.visibility[i] : 1.0f;
    LightTerm t = light_term(static_cast<int>(i), lights[i], m, in.position, in.normal, v, visible);
    primary += t.ambient + t.diffuse;
    specular += t.specular;
    if (breakdown) breakdown->lights.push_back(t);
  }
  LitColor out;
  float alpha = std::clamp(m.diffuse.a, 0.0f, 1.0f);
  if (model.separate_specular) {
    out.primary = glm::vec4(clamp01(primary), alpha);
    out.secondary = clamp01(specular);
  } else {
    out.primary = glm::vec4(clamp01(primary + specular), alpha);
  }
  if (breakdown) {
    breakdown->emission = emission;
    breakdown->global_ambient = global_ambient;
    breakdown->unclamped = primary + specular;
    breakdown->result = out;
  }
  return out;
}

}  // namespace

LitColor light_point(const LightModel& model, std::span<const Light> lights,
                     const Material& material, const LightingInput& in) {
  return evaluate(model, lights, material, in, nullptr);
}

LightingBreakdown explain_point(const LightModel& model, std::span<const Light> lights,
                                const Material& material, const LightingInput& in) {
  LightingBreakdown b;
  evaluate(model, lights, material, in, &b);
  return b;
}

}  // namespace shadelab
