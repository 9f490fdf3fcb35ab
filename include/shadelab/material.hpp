// Surface materials (glMaterial) and the options the lecture adds beyond OpenGL:
// the lecture's r.v specular form and Oren-Nayar diffuse. Plain data only.
#pragma once

#include <glm/vec4.hpp>

namespace shadelab {

/// How the specular term is computed.
enum class SpecularModel {
  kBlinn,  ///< OpenGL's half vector: (n . h)^shininess, h = normalize(L + V)
  kPhong,  ///< the lecture's reflection vector: (r . v)^shininess, r = 2 (n . L) n - L
};

/// How the diffuse term is computed.
enum class DiffuseModel {
  kLambert,    ///< max(0, n . L)
  kOrenNayar,  ///< Oren-Nayar (qualitative form) with `roughness` sigma in radians
};

/// Reflectances are RGBA in [0, 1]; the diffuse alpha is the alpha of the lit colour.
struct Material {
  glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1.0f};
  glm::vec4 diffuse{0.8f, 0.8f, 0.8f, 1.0f};
  glm::vec4 specular{0.0f, 0.0f, 0.0f, 1.0f};
  glm::vec4 emission{0.0f, 0.0f, 0.0f, 1.0f};
  float shininess = 0.0f;  ///< specular exponent, 0..128
  SpecularModel specular_model = SpecularModel::kBlinn;
  DiffuseModel diffuse_model = DiffuseModel::kLambert;
  float roughness = 0.0f;  ///< Oren-Nayar sigma, radians (0 = Lambert)
};

}  // namespace shadelab
