// The fast pipeline's lines, points and unfilled polygons: the reference's primitive assembly
// (raster/prims.hpp) run at setup, its pieces binned as clipped triangles are, so that they
// are rasterized and shaded by the same SIMD block path as every triangle. Draws no pixels.
#pragma once

#include <cstddef>
#include <cstdint>

#include "fast/draw_job.hpp"

namespace shadelab::fast {

/// How many items a draw sets up: its triangles, then its lines, then its points, in that
/// order (a GL draw has one kind).
std::size_t setup_items(const VertexInput& in);

/// Whether the draw's items must be set up on one thread, in order (the line stipple's
/// pattern runs on from one line to the next).
bool sequential_setup(const DrawJob& job);

/// Sets up items [begin, end) of the draw that are lines, points, or triangles of a draw with
/// a face in GL_LINE or GL_POINT mode, into `chunk`. `stipple`: the line stipple's position,
/// in and out (sequential setup only).
void setup_prims(const DrawJob& job, SetupChunk& chunk, std::size_t begin, std::size_t end,
                 std::uint32_t& stipple);

}  // namespace shadelab::fast
