// The fast rasterizer's entry points: raster_tile (raster.cpp) draws every triangle binned into
// one tile, in submission order, into the job's framebuffer, touching no pixel outside that
// tile; load_tile and store_tile (tile_io.cpp) move a whole tile between the framebuffer and a
// tile buffer.
#pragma once

#include "fast/draw_job.hpp"

namespace shadelab::fast {

/// Rasterizes tile `tile` (row-major index) with the best SIMD target this CPU runs.
void raster_tile(const DrawJob& job, int tile, WorkerScratch& ws);

/// A whole tile between the framebuffer and a tile buffer, rows of kTileSize pixels from
/// `color` and `depth` (the tile's first pixel) `stride` pixels apart, with the widest
/// vectors this CPU has.
struct TileRows {
  std::uint32_t* color;
  float* depth;
  std::size_t stride;
};

/// Fills the tile buffer: colour with `clear_color` where `clear` has
/// PendingClears::kColor, else from `from`; depth likewise, when `with_depth` (otherwise the
/// buffer's depth is left as it is: no draw of the tile reads or writes depth).
void load_tile(TileBuffer& b, const TileRows& from, std::uint8_t clear, std::uint32_t clear_color,
               float clear_depth, bool with_depth);

/// Writes the tile buffer's colour, and its depth when `with_depth`, out to `to` with
/// streaming stores (the lines are not read first; to's rows should start on 16 bytes, else
/// they are copied plainly). The caller fences them (SSE2's sfence) before another thread
/// reads them.
void store_tile(const TileBuffer& b, const TileRows& to, bool with_depth);

}  // namespace shadelab::fast
