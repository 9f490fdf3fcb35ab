// The fast rasterizer's entry point (raster.cpp): draws every triangle binned into one tile,
// in submission order, into the job's framebuffer. Touches no pixel outside that tile.
#pragma once

#include "fast/draw_job.hpp"

namespace shadelab::fast {

/// Rasterizes tile `tile` (row-major index) with the best SIMD target this CPU runs.
void raster_tile(const DrawJob& job, int tile, WorkerScratch& ws);

}  // namespace shadelab::fast
