// A validated scene: what the renderer draws. Built by the scene reader (scene_io.hpp) or by
// code; holds no file positions and no unvalidated values. World space unless stated.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shadelab/light.hpp"
#include "shadelab/material.hpp"
#include "shadelab/mesh.hpp"
#include "shadelab/texture.hpp"

namespace shadelab {

/// How colour is spread over a polygon (SPEC section 4).
enum class ShadingMode {
  kFlat,     ///< lit once per triangle, at its provoking (last) vertex
  kGouraud,  ///< lit per vertex, colours interpolated
  kPhong,    ///< normal and position interpolated, lit per pixel
};

enum class CullMode { kNone, kBack, kFront };

/// OpenGL blend factors (glBlendFunc, glBlendFuncSeparate): GL 1.1's, then the constant colour
/// factors of GL 1.4 (the imaging subset's, made core). Every factor is accepted as a source
/// and a destination factor (GL 1.4 allows the colour of the same side too).
enum class BlendFactor : std::uint8_t {
  kZero, kOne, kSrcColor, kOneMinusSrcColor, kDstColor, kOneMinusDstColor,
  kSrcAlpha, kOneMinusSrcAlpha, kDstAlpha, kOneMinusDstAlpha, kSrcAlphaSaturate,
  kConstantColor, kOneMinusConstantColor, kConstantAlpha, kOneMinusConstantAlpha,
};

/// glBlendEquation (GL 1.4 section 4.1.7): how the weighted source and destination combine.
/// kMin and kMax take the smaller or larger of the two colours themselves, ignoring the factors.
enum class BlendEquation : std::uint8_t { kAdd, kSubtract, kReverseSubtract, kMin, kMax };

/// When enabled, each channel becomes `equation(src * src_factor, dst * dst_factor)`: red,
/// green and blue with `src` / `dst`, alpha with `src_alpha` / `dst_alpha`
/// (glBlendFuncSeparate). `color` is glBlendColor's constant, in [0, 1]; the pipeline uses it
/// in the colour buffer's precision (8 bits, as llvmpipe stores it).
struct BlendState {
  bool enabled = false;
  BlendFactor src = BlendFactor::kSrcAlpha;
  BlendFactor dst = BlendFactor::kOneMinusSrcAlpha;
  BlendFactor src_alpha = BlendFactor::kSrcAlpha;
  BlendFactor dst_alpha = BlendFactor::kOneMinusSrcAlpha;
  BlendEquation equation = BlendEquation::kAdd;
  /// EXT_blend_equation_separate: alpha's own equation when set (else `equation` blends alpha
  /// too).
  bool separate_equations = false;
  BlendEquation equation_alpha = BlendEquation::kAdd;
  glm::vec4 color{0.0f};

  BlendState() = default;
  /// glBlendFunc's blend: the same factors for every channel, added.
  BlendState(bool on, BlendFactor s, BlendFactor d) : enabled(on), src(s), dst(d), src_alpha(s), dst_alpha(d) {}

  /// The usual transparency: glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), added, for
  /// every channel (the fast pipeline's blend kernels).
  bool source_over() const {
    return src == BlendFactor::kSrcAlpha && dst == BlendFactor::kOneMinusSrcAlpha && src_alpha == src &&
           dst_alpha == dst && equation == BlendEquation::kAdd && alpha_equation() == BlendEquation::kAdd;
  }
  /// The equation that blends alpha.
  BlendEquation alpha_equation() const { return separate_equations ? equation_alpha : equation; }
};

/// Look-at camera. Angles in degrees; distances in world units.
struct Camera {
  enum class Projection { kPerspective, kOrthographic };
  glm::vec3 eye{0.0f, 0.0f, 8.0f};
  glm::vec3 target{0.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  Projection projection = Projection::kPerspective;
  float fovy_degrees = 30.0f;  ///< vertical field of view (perspective)
  float ortho_height = 4.0f;   ///< height of the view volume (orthographic)
  float near_plane = 0.1f;
  float far_plane = 100.0f;
  /// A projection given as a matrix (camera.projection_matrix: a GL program's glFrustum or
  /// glOrtho that the parameters above cannot express); it replaces them when set.
  std::optional<glm::mat4> matrix;

  glm::mat4 view_matrix() const;
  glm::mat4 projection_matrix(float aspect) const;  ///< aspect = width / height
};

/// A light with the space its position and spot direction are given in.
struct SceneLight {
  Light light;
  bool eye_space = false;  ///< false: world space (moved by the camera), true: eye space
  bool shadow = false;     ///< cast shadow-mapped shadows
  float shadow_bias = -1;  ///< depth bias; < 0: automatic (normal offset)
  int shadow_map_size = 1024;
  int shadow_pcf = 1;      ///< percentage-closer filter radius: (2 r + 1)^2 samples
};

struct SceneObject {
  std::string name;
  std::shared_ptr<const Mesh> mesh;
  glm::mat4 model{1.0f};  ///< object to world
  Material front;
  std::optional<Material> back;  ///< used by two-sided lighting; front material if absent
  ShadingMode shading = ShadingMode::kGouraud;
  CullMode cull = CullMode::kNone;  ///< OpenGL's default: no culling
  BlendState blend;                 ///< enabled => drawn after opaque objects, back to front
  bool lighting = true;             ///< false: vertex colours, else `color`, unlit
  glm::vec4 color{1.0f};            ///< colour when lighting is off and the mesh has none
  std::shared_ptr<const Texture> texture;  ///< applied with `texture_env` when set
  TextureEnvMode texture_env = TextureEnvMode::kModulate;
  glm::vec2 texture_repeat{1.0f};  ///< texture coordinates are multiplied by this (tiling)
};

/// A planar projected shadow (SPEC section 6): every object but the receiver is flattened onto
/// `plane` from light `light`, drawn unlit in `color`, only on the receiver's pixels (stencil),
/// each pixel darkened once, pulled in front of the plane by a polygon offset. Lights on the
/// plane's negative side (below it) cast nothing: the receiver's upper side is unlit.
struct PlanarShadow {
  glm::vec4 plane{0.0f, 1.0f, 0.0f, 0.0f};  ///< a x + b y + c z + d = 0, world space
  int light = 0;
  glm::vec4 color{0.0f, 0.0f, 0.0f, 0.5f};
  std::string receiver;  ///< name of the object the shadow falls on
};

struct Scene {
  std::string caption;  ///< free text describing the scene (shown by the gallery)
  int width = 640;
  int height = 480;
  /// Anti-aliasing: samples per pixel, a square number n*n (1, 4, 9, ... 64); the scene is
  /// rendered on an n-times larger grid and each n x n block averaged (supersampling).
  int samples = 1;
  glm::vec4 background{0.0f, 0.0f, 0.0f, 1.0f};
  Camera camera;
  LightModel light_model;
  std::vector<SceneLight> lights;
  std::vector<SceneObject> objects;
  std::vector<PlanarShadow> shadows;
  /// How blended objects are ordered: kSorted = whole objects back to front (the lecture's
  /// method); kExact = every fragment sorted by depth per pixel, so intersecting and
  /// interleaved transparent surfaces blend in true order.
  enum class Transparency { kSorted, kExact } transparency = Transparency::kSorted;
};

}  // namespace shadelab
