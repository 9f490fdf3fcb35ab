// Rendering a whole Scene to an Image: the scene front end of the pipeline (pipeline.hpp).
// Orders the draws (opaque first, then blended objects back to front) and never prints.
#pragma once

#include <optional>

#include "shadelab/image.hpp"
#include "shadelab/pipeline.hpp"
#include "shadelab/scene.hpp"

namespace shadelab {

struct RenderOptions {
  std::optional<ShadingMode> shading;  ///< overrides every object's shading mode
  std::optional<int> samples;          ///< overrides Scene::samples (a square number)
};

/// Renders `scene` at scene.width x scene.height.
Image render_scene(const Scene& scene, const RenderOptions& options = {},
                   RenderStats* stats = nullptr);

}  // namespace shadelab
