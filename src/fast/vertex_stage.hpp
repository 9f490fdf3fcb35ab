// The fast vertex stage's entry point (vertex_stage.cpp): lights, projects, outcodes and maps
// to window space a range of a draw's vertices, writing job.vertices, varyings and outcodes. It must not rasterize or touch the framebuffer:
// clipping, setup and binning come after it (setup.cpp).
#pragma once

#include <cstddef>

#include "fast/draw_job.hpp"

namespace shadelab::fast {

/// Processes vertices [begin, end) with the best SIMD target this CPU runs.
void run_vertex_range(DrawJob& job, std::size_t begin, std::size_t end, WorkerScratch& ws);

}  // namespace shadelab::fast
