// Per-fragment operations after shading (GL 1.5 chapter 4.1): stencil test, depth test,
// blending and the colour mask, on one framebuffer pixel. Private to the pipeline.
#pragma once

#include <glm/vec4.hpp>

#include "shadelab/pipeline.hpp"

namespace shadelab::detail {

bool compare(CompareFunc func, float incoming, float stored);
bool compare_stencil(CompareFunc func, unsigned ref, unsigned stored);

/// Runs the stencil and depth tests for the fragment at pixel index `i` with depth `z`,
/// updating stencil and depth as GL specifies. Returns true if the fragment survives.
bool depth_stencil_test(Framebuffer& fb, std::size_t i, float z, const FragmentState& state);

/// Blends `src` (unclamped colour, alpha) into pixel `i` and writes it through the colour mask.
void write_color(Framebuffer& fb, std::size_t i, glm::vec4 src, const FragmentState& state);

}  // namespace shadelab::detail
