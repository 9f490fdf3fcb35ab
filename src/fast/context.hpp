// What a PipelineContext owns: the thread pool and every buffer a draw reuses (vertex
// output, bins, per-thread scratch), so that drawing in steady state allocates nothing. It must not hold
// per-draw state across draws (a draw's job is filled afresh) nor anything of a front end.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "fast/draw_job.hpp"
#include "fast/thread_pool.hpp"
#include "shadelab/pipeline.hpp"

namespace shadelab {

struct PipelineContext::Impl {
  explicit Impl(int threads) : pool(threads), workers(std::size_t(threads)) {}
  fast::ThreadPool pool;
  /// Draw jobs, reused from draw to draw and frame to frame: jobs[0, queued) are the deferred
  /// draws waiting for finish_draws, in submission order; the next draw fills jobs[queued].
  std::vector<std::unique_ptr<fast::DrawJob>> jobs;
  std::size_t queued = 0;
  std::size_t queued_vertices = 0;  ///< the deferred draws' vertices, together
  std::uint64_t made = 0;           ///< draws made (draws_made)
  bool deferred = false;            ///< set_deferred
  std::vector<fast::WorkerScratch> workers;  ///< one per pool thread
  std::vector<int> tiles;                    ///< the last draw's non-empty tiles
  std::vector<std::vector<const fast::DrawJob*>> tile_jobs;  ///< finish_draws: per tile, its draws
  PendingClears pending;                     ///< clears left to the draws
  bool counting = false;                     ///< set_counting
  RenderStats totals;                        ///< take_counts
  /// clear_ahead's job, run on the workers while the caller goes on: clears tiles[item].
  struct ClearAhead {
    PendingClears* pending = nullptr;
    Framebuffer* fb = nullptr;
    std::uint8_t what = 0;
    std::vector<int> tiles;
    void operator()(int item) const;
  } ahead;
};

}  // namespace shadelab
