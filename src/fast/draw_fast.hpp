// The fast pipeline behind draw_triangles(..., PipelineContext*): vertex stage, setup and
// binning, tiles rasterized in parallel (docs/performance.md). Same contract as the reference
// draw_triangles; it falls back to the reference for viewports beyond its fixed-point range.
#pragma once

#include "shadelab/pipeline.hpp"

namespace shadelab::detail {

void draw_triangles_fast(PipelineContext& context, Framebuffer& fb, const glm::mat4& projection,
                         const Viewport& viewport, const FragmentState& fragment,
                         const ShadeState& shade, const VertexInput& vertices,
                         RenderStats* stats);

}  // namespace shadelab::detail
