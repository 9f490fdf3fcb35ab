// The fast pipeline behind draw_triangles(..., PipelineContext*): vertex stage, setup and
// binning, tiles rasterized in parallel (docs/performance.md). Same contract as the reference
// draw_triangles; it falls back to the reference for viewports beyond its fixed-point range.
#pragma once

#include <cstddef>

#include "shadelab/pipeline.hpp"

namespace shadelab::fast {

/// The most draws that wait at once (PipelineContext::set_deferred): a full queue is drawn
/// before the next draw joins it.
inline constexpr std::size_t kMaxQueuedDraws = 256;

}  // namespace shadelab::fast

namespace shadelab::detail {

void draw_triangles_fast(PipelineContext& context, Framebuffer& fb, const glm::mat4& projection,
                         const Viewport& viewport, const FragmentState& fragment,
                         const ShadeState& shade, const VertexInput& vertices,
                         RenderStats* stats);

}  // namespace shadelab::detail
