// What a PipelineContext owns: the thread pool and every buffer a draw reuses (vertex
// output, bins, per-thread scratch), so that drawing in steady state allocates nothing.
#pragma once

#include <vector>

#include "fast/draw_job.hpp"
#include "fast/thread_pool.hpp"
#include "shadelab/pipeline.hpp"

namespace shadelab {

struct PipelineContext::Impl {
  explicit Impl(int threads) : pool(threads), workers(std::size_t(threads)) {}
  fast::ThreadPool pool;
  fast::DrawJob job;
  std::vector<fast::WorkerScratch> workers;  ///< one per pool thread
  std::vector<int> tiles;                    ///< the current draw's non-empty tiles
  PendingClears pending;                     ///< clears left to the draws
};

}  // namespace shadelab
