// Triangle setup and binning for the fast pipeline (setup.cpp): reads the vertex stage's
// output, writes a chunk's per-tile bins. Draws no pixels.
#pragma once

#include <cstddef>

#include "fast/draw_job.hpp"

namespace shadelab::fast {

/// Empties a chunk for a new draw over `tiles` tiles (keeping its storage).
void reset_chunk(SetupChunk& chunk, std::size_t tiles);

/// Sets up triangles [begin, end) of the draw into `chunk`: clipping, facing, culling, and
/// binning in submission order.
void setup_range(const DrawJob& job, SetupChunk& chunk, std::size_t begin, std::size_t end);

/// Bins one triangle (window vertices in fan order) as bin entry `entry` into the tiles its
/// pixel box covers (after the tiles no pixel centre of it can reach are left out).
void bin_triangle(const DrawJob& job, SetupChunk& chunk, const RasterVertex& a, const RasterVertex& b,
                  const RasterVertex& c, std::uint32_t entry);

/// Bins an aliased line's counter-clockwise parallelogram a, b, c, d (d - c = a - b;
/// TriSetup::parallelogram) as bin entry `entry` into the tiles whose pixel centres it can
/// cover.
void bin_parallelogram(const DrawJob& job, SetupChunk& chunk, const RasterVertex& a, const RasterVertex& b,
                       const RasterVertex& c, const RasterVertex& d, std::uint32_t entry);

}  // namespace shadelab::fast
