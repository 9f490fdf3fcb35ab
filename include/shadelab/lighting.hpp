// The OpenGL 1.x lighting equation (SPEC section 3; OpenGL 1.5 spec section 2.14.1), the one
// function that flat, Gouraud and Phong shading all call. Everything here is in eye space.
// It computes colours only: no transforms, no rasterization, no state. This is the definition
// (src/lighting/lighting.cpp); the fast pipeline's SIMD form (src/fast/lighting-inl.h) is held
// to it by differential tests, as lighting.cpp's opening comment says.
#pragma once

#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shadelab/light.hpp"
#include "shadelab/material.hpp"

namespace shadelab {

/// Result of lighting one point. `primary` is clamped to [0, 1]; its alpha is the material's
/// diffuse alpha. With separate specular colour the specular sum is in `secondary` (clamped)
/// and left out of `primary`; otherwise `secondary` is zero.
struct LitColor {
  glm::vec4 primary{0.0f};
  glm::vec3 secondary{0.0f};
};

/// One light's contribution, as the lab's "explain this pixel" shows it. The three colour
/// parts already include attenuation and spot factor.
struct LightTerm {
  int light = 0;             ///< index into the lights span
  float attenuation = 1.0f;  ///< 1 / (kc + kl d + kq d^2), 1 for directional lights
  float spot = 1.0f;         ///< spot factor, 1 without a cone, 0 outside it
  float n_dot_l = 0.0f;      ///< diffuse cosine before clamping at zero
  glm::vec3 ambient{0.0f}, diffuse{0.0f}, specular{0.0f};
};

/// Every part of the equation for one point: sum (before clamping) and the clamped result.
struct LightingBreakdown {
  glm::vec3 emission{0.0f};
  glm::vec3 global_ambient{0.0f};
  std::vector<LightTerm> lights;  ///< enabled lights only, in order
  glm::vec3 unclamped{0.0f};      ///< emission + global ambient + every light term
  LitColor result;
};

/// Which side of a surface is lit: the back side uses the negated normal (two-sided lighting).
struct LightingInput {
  glm::vec3 position{0.0f};  ///< eye-space point
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  ///< eye-space normal, unit length (caller normalizes)
  /// Optional per-light visibility in [0, 1] (shadow maps), one per light: it scales that
  /// light's diffuse and specular terms; a fully shadowed point keeps the light's ambient.
  const float* visibility = nullptr;
};

/// The spot factor (GL 1.5 eq. 2.5): 1 without a cone (cutoff 180), (-L . D)^exponent inside
/// it, 0 outside it or when the spot direction is zero. `to_light` is the unit vector from the
/// point to the light.
float spot_factor(const Light& light, const glm::vec3& to_light);

/// The lighting equation at one point. `lights` are in eye space; disabled ones are skipped.
LitColor light_point(const LightModel& model, std::span<const Light> lights,
                     const Material& material, const LightingInput& in);

/// The same computation as light_point, with every term recorded.
LightingBreakdown explain_point(const LightModel& model, std::span<const Light> lights,
                                const Material& material, const LightingInput& in);

}  // namespace shadelab
