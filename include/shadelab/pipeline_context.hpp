// The fast pipeline's context (part of pipeline.hpp): its worker threads and the buffers
// draws reuse, deferred draws and clears left to the draws (llvmpipe's way), and the counts
// of RenderStats. Draws go through draw_triangles (pipeline.hpp); one draw at a time per
// context, and nothing here is global.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include <glm/vec4.hpp>

#include "shadelab/framebuffer.hpp"

namespace shadelab {

/// Counters and timings for `shadelab render --stats`.
struct RenderStats {
  std::uint64_t triangles_in = 0;       ///< triangles submitted
  std::uint64_t triangles_culled = 0;   ///< back-face culled or degenerate
  std::uint64_t triangles_clipped = 0;  ///< crossing a clip plane (then split)
  std::uint64_t triangles_rasterized = 0;
  std::uint64_t vertices_lit = 0;
  std::uint64_t fragments = 0;        ///< covered samples that passed stipple and scissor
  /// Of `fragments`, those the fast pipeline handed one at a time to the reference's
  /// per-fragment operations (stencil, capture, shadow maps) instead of its SIMD blocks.
  std::uint64_t fragments_reference = 0;
  std::uint64_t pixels_shaded = 0;    ///< fragments that passed every test and were written
  std::uint64_t draws = 0;            ///< draw_triangles calls (PipelineContext::take_counts)
  std::uint64_t draws_deferred = 0;   ///< of them, those that waited for finish_draws
  double ms_vertex = 0, ms_raster = 0, ms_resolve = 0, ms_total = 0;
  bool interrupted = false;  ///< render_scene stopped at RenderOptions::deadline
  /// Exact transparency: fragments not blended because RenderOptions::max_fragment_memory was
  /// spent.
  std::uint64_t fragments_dropped = 0;
};

/// The fast pipeline's worker threads and reusable buffers (src/fast/, docs/performance.md).
/// Keep one alive across draws and frames: steady-state drawing then allocates nothing. Not
/// thread-safe: one draw at a time per context.
class PipelineContext {
 public:
  /// `threads` workers including the caller; 0: $SHADELAB_THREADS if set, else all cores.
  explicit PipelineContext(int threads = 0);
  ~PipelineContext();
  PipelineContext(const PipelineContext&) = delete;
  PipelineContext& operator=(const PipelineContext&) = delete;
  int threads() const;
  /// The SIMD instruction set the fast pipeline dispatches to on this CPU ("AVX3", "AVX2",
  /// "SSE4", "SSSE3" or the portable fallback, "SCALAR" or "EMU128" as the Highway in use names it): the best one compiled that the CPU runs, or
  /// the one $SHADELAB_SIMD names ("avx512", "avx2", "sse4", "ssse3", "scalar"; read when the
  /// first context is made, ignored when that target is not available).
  static std::string simd_target();
  /// The framebuffer's tiles: squares of kTileSize pixels, numbered row by row from pixel
  /// (0, 0), (width + kTileSize - 1) / kTileSize to a row.
  static constexpr int kTileSize = 64;
  /// The tiles the last draw_triangles through this context may have written to (those its
  /// triangles reached, in increasing order), or will write to when it is deferred; no pixel
  /// outside them changed.
  std::span<const int> last_draw_tiles() const;
  /// Deferred drawing, llvmpipe's way (off by default; the GL library turns it on). While on,
  /// draw_triangles through this context transforms, lights, sets up and bins a draw's
  /// triangles when called and leaves rasterizing them to finish_draws, which draws every
  /// waiting draw tile by tile: in each tile, every draw's triangles in submission order,
  /// while the tile is in the cache. A frame's draws then pass over the framebuffer once
  /// rather than once each; the pixels are the same. A draw waits only when nothing it reads
  /// stays the caller's after the call (no shadow maps, fragment capture or texture but a
  /// kept one, ShadeState::texture_kept), no
  /// counts are asked of it (stats null), and it and the queue are small (a long draw pays for
  /// its own pass); any other draw first finishes the waiting ones. Call finish_draws (or
  /// apply_pending_clears, which calls it) before anything else reads or writes the
  /// framebuffer, and before it is resized or destroyed. Turning it off finishes the waiting
  /// draws.
  void set_deferred(bool on);
  /// Rasterizes every waiting draw (set_deferred), applying the pending clears of the tiles
  /// they reach.
  void finish_draws();
  /// How many draws wait for finish_draws.
  std::size_t deferred_draws() const;
  /// How many draws were made through the context. The waiting ones are always the last
  /// `deferred_draws()` of them (any other draw first finishes them), so draw number k (from
  /// 1) is drawn once `draws_made() - deferred_draws()` reaches k: what it reads may then go.
  std::uint64_t draws_made() const;
  /// Counting (off by default): every draw through the context adds its triangle, fragment
  /// and draw counts (RenderStats; fragments by path, draws deferred or not) to totals that
  /// take_counts returns and resets. Deferred draws count when finish_draws draws them.
  void set_counting(bool on);
  RenderStats take_counts();
  /// Clears left to the draws, as llvmpipe does (the GL library's glClear): a tile flagged in
  /// `tiles` is cleared (colour to `color` with kColor, depth to `depth` with kDepth) by the
  /// next draw_triangles through this context that draws into it, just before its first
  /// triangle, while the tile is in the cache; its flag is then reset. Whoever flags tiles
  /// sizes `tiles` to the framebuffer's and calls apply_pending_clears before anything else
  /// reads or writes the framebuffer; tiles are flagged only while no draw waits (call
  /// finish_draws first: waiting draws come before the clear). Empty: nothing pending.
  struct PendingClears {
    static constexpr std::uint8_t kColor = 1, kDepth = 2;
    std::vector<std::uint8_t> tiles;
    std::uint32_t color = 0;  ///< the pixel's RGBA8 bytes
    float depth = 1.0f;
  };
  PendingClears& pending_clears();
  /// Leaves a clear of `fb`'s colour (PendingClears::kColor, to `color`) and / or depth
  /// (kDepth, to `depth`) pending on every tile: each tile is cleared by the next draw into
  /// it, while it is in the cache, and apply_pending_clears clears the others (call it before
  /// reading `fb`). Waiting draws are finished first.
  void clear_later(Framebuffer& fb, std::uint8_t what, glm::vec4 color, float depth);
  /// Finishes the waiting draws, then applies the pending clears of the buffers in `what`
  /// (PendingClears::kColor, kDepth: both by default) to `fb` now, on the context's threads;
  /// the others stay pending. Colour is written with streaming stores where it can be (it
  /// is not read first).
  void apply_pending_clears(Framebuffer& fb, std::uint8_t what = PendingClears::kColor | PendingClears::kDepth);
  /// Starts applying the pending clears of the buffers in `what` to the listed tiles of `fb`
  /// on one of the context's worker threads, and returns while it runs: memory-bound writes
  /// that then overlap the caller's own work (the GL library's glClear, for the tiles no draw
  /// reached since the clear before: the tiles it expects to stay as cleared). Every other
  /// call through the context waits for it to end first; until then `fb` must not be read,
  /// written, resized or destroyed. With one thread it does nothing (the clears stay
  /// pending). A listed tile that a draw reaches after all is cleared twice, which costs
  /// time, not correctness; tiles listed twice or not in `fb` are ignored.
  void clear_ahead(Framebuffer& fb, std::uint8_t what, std::span<const int> tiles);
  /// Runs fn(begin, end) over [0, count) in chunks of about `grain` items on the context's
  /// threads (the caller joins in); returns when every chunk is done. For front ends that
  /// prepare vertices before a draw. fn must be safe to run concurrently on disjoint ranges.
  /// fn is called through a reference (nothing is copied or allocated).
  template <class Fn>
  void parallel_for(std::size_t count, std::size_t grain, Fn&& fn) {
    using F = std::remove_reference_t<Fn>;
    parallel_for_ref(count, grain, [](void* f, std::size_t b, std::size_t e) { (*static_cast<F*>(f))(b, e); },
                     const_cast<void*>(static_cast<const void*>(&fn)));
  }
  struct Impl;
  Impl& impl() { return *impl_; }

 private:
  void parallel_for_ref(std::size_t count, std::size_t grain, void (*call)(void*, std::size_t, std::size_t),
                        void* fn);
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadelab
