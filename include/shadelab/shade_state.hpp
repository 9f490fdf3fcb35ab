// How one draw colours its fragments (part of pipeline.hpp): whether and how it lights (the
// one lighting function of lighting.hpp, with its lights and materials), the texture and its
// environment, shadow maps and fog. Plain data and the shadow maps' lookup: the pipeline
// does the lighting, texturing and fogging.
#pragma once

#include <array>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shadelab/light.hpp"
#include "shadelab/material.hpp"
#include "shadelab/scene.hpp"
#include "shadelab/texture.hpp"

namespace shadelab {

/// A depth map seen from one light (shadow mapping): one face for directional and spot lights,
/// six (a cube) for point lights. Built by render_scene; looked up during lighting.
struct ShadowMap {
  struct Face {
    glm::mat4 eye_to_clip{1.0f};  ///< camera eye space -> the light's clip space
    std::vector<float> depth;     ///< size x size window depths, row 0 at the bottom
  };
  int size = 0;                    ///< 0: this light casts no shadow
  std::vector<Face> faces;
  bool perspective = false;
  glm::vec3 light_eye{0.0f};       ///< light position in eye space (perspective maps)
  float texel_at_unit = 0.0f;      ///< world size of a texel at distance 1 (or everywhere, ortho)
  float bias = -1.0f;              ///< depth bias; < 0: automatic (normal offset, slope-scaled)
  int pcf = 1;                     ///< filter radius: (2 pcf + 1)^2 depth comparisons

  /// Fraction of the light reaching eye-space point `p` with unit normal `n` (0 in shadow).
  float visibility(const glm::vec3& p, const glm::vec3& n) const;
};

enum class FogMode { kLinear, kExp, kExp2 };

/// Fog (GL 1.1 section 3.9), as Mesa's fixed-function programs compute it: every vertex has
/// a fog coordinate (VertexInput::fog_coords, or by default the distance |z| of its eye-space
/// position from the eye plane, Mesa's GL_EYE_PLANE_ABSOLUTE_NV), interpolated per fragment
/// like any other attribute; each fragment computes its factor f from it (GL_LINEAR:
/// (end - c) / (end - start); GL_EXP: e^(-density c); GL_EXP2: e^(-(density c)^2)), clamps
/// it to [0, 1] and takes f C + (1 - f) C_fog as its red, green and blue; alpha is kept.
struct FogState {
  bool enabled = false;
  FogMode mode = FogMode::kExp;
  glm::vec3 color{0.0f};  ///< in [0, 1]
  float start = 0.0f, end = 1.0f, density = 1.0f;
};

/// One texture unit of a draw (GL 1.3 section 3.8.13): the texture it samples (null: the unit
/// is off and passes its colour on) and its environment.
struct TextureUnit {
  const Texture* texture = nullptr;
  TextureEnvMode env = TextureEnvMode::kModulate;
  glm::vec4 env_color{0.0f};  ///< GL_TEXTURE_ENV_COLOR (kBlend, kCombine's constant), in [0, 1]
  TextureCombine combine;     ///< kCombine's functions, sources, operands and scales
  /// The unit's GL_TEXTURE_LOD_BIAS (GL 1.4, glTexEnv GL_TEXTURE_FILTER_CONTROL), added to the
  /// texture's own (texture_lod).
  float lod_bias = 0.0f;
};

/// How colours are made. With `lighting` the pipeline lights vertices or pixels (by `shading`)
/// with the one lighting function; without it, vertex colours are used as given.
struct ShadeState {
  bool lighting = true;
  ShadingMode shading = ShadingMode::kGouraud;
  LightModel model;
  std::span<const Light> lights;  ///< eye space
  Material front;
  Material back;  ///< used for back faces when model.two_side
  /// Texturing: each unit whose texture is set (and complete) textures the fragments with its
  /// environment, unit 0 first, before the secondary colour is added. Unit u samples at
  /// VertexInput::texcoords[u].
  std::array<TextureUnit, kMaxTextureUnits> textures;
  /// The caller keeps the units' textures alive and unchanged until the context's
  /// finish_draws (the GL library finishes the waiting draws before it changes a texture and
  /// keeps the textures of waiting draws alive): a textured draw may then wait
  /// (PipelineContext::set_deferred).
  bool texture_kept = false;
  /// Whether any unit has a texture.
  bool textured() const {
    for (const TextureUnit& u : textures) {
      if (u.texture) return true;
    }
    return false;
  }
  /// Units whose texture is incomplete (GL 1.5 section 3.8.10) set off, as if disabled.
  void drop_incomplete_textures() {
    for (TextureUnit& u : textures) {
      if (u.texture && !u.texture->complete()) u.texture = nullptr;
    }
  }
  /// Shadow maps by light index (empty, or as long as `lights`; size 0 = unshadowed light).
  std::span<const ShadowMap> shadow_maps;
  /// Fog, applied after texturing and the colour sum.
  FogState fog;
};

}  // namespace shadelab
