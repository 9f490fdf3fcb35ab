// Light sources as OpenGL 1.x defines them (SPEC sections 1 and 3): colours, a homogeneous
// position, attenuation and a spot cone. Plain data only; the lighting equation lives in
// lighting.hpp. This header does not decide which coordinate space a light is in.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace shadelab {

/// One light. Colours are RGBA intensities (usually in [0, 1]).
/// `position` is homogeneous: w = 0 makes a directional light whose (x, y, z) points from the
/// scene toward the light; w != 0 makes a positional light at (x/w, y/w, z/w).
/// When handed to the lighting function, `position` and `spot_direction` are in eye space.
struct Light {
  glm::vec4 ambient{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec4 diffuse{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec4 specular{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec4 position{0.0f, 0.0f, 1.0f, 0.0f};
  glm::vec3 spot_direction{0.0f, 0.0f, -1.0f};  ///< need not be unit length
  float spot_exponent = 0.0f;                    ///< 0..128
  float spot_cutoff = 180.0f;                    ///< degrees: 0..90, or exactly 180 (no spot)
  float constant_attenuation = 1.0f;             ///< k_c >= 0
  float linear_attenuation = 0.0f;               ///< k_l >= 0, per unit of eye-space distance
  float quadratic_attenuation = 0.0f;            ///< k_q >= 0
  bool enabled = true;
};

/// OpenGL's default for GL_LIGHTi: light 0 has white diffuse and specular, the others black.
Light default_light(int index);

/// The lighting model (glLightModel): global ambient, viewer, two-sidedness, colour control.
struct LightModel {
  glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1.0f};  ///< GL_LIGHT_MODEL_AMBIENT
  bool local_viewer = false;  ///< false: V = (0, 0, 1) in eye space; true: V = -normalize(p)
  bool two_side = false;      ///< back faces use the back material and the negated normal
  bool separate_specular = false;  ///< GL_SEPARATE_SPECULAR_COLOR: specular added after texturing
};

}  // namespace shadelab
