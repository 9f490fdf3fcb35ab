// Rendering a whole Scene to an Image: the scene front end of the pipeline (pipeline.hpp).
// Orders the draws (opaque first, then blended objects back to front) and never prints.
#pragma once

#include <chrono>
#include <optional>

#include "shadelab/image.hpp"
#include "shadelab/pipeline.hpp"
#include "shadelab/scene.hpp"

namespace shadelab {

struct RenderOptions {
  std::optional<ShadingMode> shading;  ///< overrides every object's shading mode
  std::optional<int> samples;          ///< overrides Scene::samples (a square number)
  bool reference = false;  ///< draw with the reference pipeline instead of the fast one
  int threads = 0;         ///< fast pipeline threads; 0: $SHADELAB_THREADS, else all cores
  /// A fast-pipeline context kept across frames (no per-frame thread start or allocation);
  /// null: render_scene makes one for the frame. Ignored with `reference`.
  PipelineContext* context = nullptr;
  /// When set, objects not yet drawn by then are left out and RenderStats::interrupted is set
  /// (the lab's render time limit); an object already being drawn is finished.
  std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt;
  /// Memory for the per-pixel fragment lists of exact transparency (Scene::Transparency::kExact),
  /// in bytes. Fragments arriving once it is spent are not blended; RenderStats::
  /// fragments_dropped counts them.
  std::size_t max_fragment_memory = std::size_t(1) << 30;
};

/// Renders `scene` at scene.width x scene.height.
Image render_scene(const Scene& scene, const RenderOptions& options = {},
                   RenderStats* stats = nullptr);

}  // namespace shadelab
