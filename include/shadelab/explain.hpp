// "Explain this pixel": which surface a pixel of a rendered scene shows, and how the lighting
// equation makes its colour there (the lab's click-to-explain). Never prints or throws.
#pragma once

#include <optional>
#include <string>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shadelab/lighting.hpp"
#include "shadelab/scene.hpp"

namespace shadelab {

struct PixelExplanation {
  std::string object;          ///< the object's name (or "#index" when it has none)
  int object_index = 0;
  ShadingMode shading = ShadingMode::kGouraud;  ///< how the renderer shades this object
  bool lit = true;             ///< false: the object is unlit (its colour is not from lighting)
  bool back_face = false;      ///< the pixel shows the surface's back side
  glm::vec3 position{0.0f};    ///< eye-space point under the pixel centre
  glm::vec3 normal{0.0f};      ///< eye-space unit normal used (negated for a lit back face)
  float depth = 0.0f;          ///< distance along the view ray (eye units)
  /// The lighting equation at that point with the normal interpolated there, as Phong
  /// shading evaluates it; flat and Gouraud shading interpolate vertex colours instead, so
  /// their pixels differ from this by the interpolation.
  LightingBreakdown breakdown;
};

/// The surface under the centre of pixel (x, y) of `scene` rendered at its own size, (0, 0)
/// being the top-left pixel: the nearest triangle hit by the camera ray (one sample per
/// pixel; planar shadows, shadow maps and textures are not part of the breakdown). Nothing
/// when the pixel shows the background or lies outside the image.
std::optional<PixelExplanation> explain_pixel(const Scene& scene, int x, int y);

}  // namespace shadelab
