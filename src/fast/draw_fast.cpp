// One draw through the fast pipeline: plan, vertex stage over blocks of vertices, setup over
// contiguous triangle chunks (so each tile's bins keep submission order), then the non-empty
// tiles rasterized by whichever thread is free. Every stage runs on the context's pool.
#include "fast/draw_fast.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>

#include "fast/context.hpp"
#include "fast/plan.hpp"
#include "fast/raster.hpp"
#include "fast/setup.hpp"
#include "fast/vertex_stage.hpp"

namespace shadelab {

PipelineContext::PipelineContext(int threads)
    : impl_(std::make_unique<Impl>(fast::resolve_thread_count(threads))) {}

PipelineContext::~PipelineContext() = default;

int PipelineContext::threads() const { return impl_->pool.size(); }

std::span<const int> PipelineContext::last_draw_tiles() const { return impl_->tiles; }

PipelineContext::PendingClears& PipelineContext::pending_clears() { return impl_->pending; }

namespace fast {
namespace {

int tile_columns(const Framebuffer& fb) { return (fb.width + kTileSize - 1) / kTileSize; }

int tile_count(const Framebuffer& fb) { return tile_columns(fb) * ((fb.height + kTileSize - 1) / kTileSize); }

// Applies tile `tile`'s pending clear, if any, and resets its flag.
void clear_tile(Framebuffer& fb, PipelineContext::PendingClears& p, int tile) {
  const std::uint8_t what = p.tiles[std::size_t(tile)];
  if (!what) return;
  p.tiles[std::size_t(tile)] = 0;
  const int columns = tile_columns(fb);
  const int x0 = (tile % columns) * kTileSize, y0 = (tile / columns) * kTileSize;
  const int x1 = std::min(fb.width, x0 + kTileSize), y1 = std::min(fb.height, y0 + kTileSize);
  auto* color = reinterpret_cast<std::uint32_t*>(fb.color.data());
  for (int y = y0; y < y1; ++y) {
    const std::size_t row = std::size_t(y) * std::size_t(fb.width);
    if (what & PipelineContext::PendingClears::kColor) std::fill(color + row + x0, color + row + x1, p.color);
    if (what & PipelineContext::PendingClears::kDepth) std::fill(&fb.depth[row + std::size_t(x0)], &fb.depth[row + std::size_t(x1)], p.depth);
  }
}

// Whether `p` holds flags for `fb`'s tiles (anything else is nothing pending).
bool pending_for(const PipelineContext::PendingClears& p, const Framebuffer& fb) {
  return !p.tiles.empty() && p.tiles.size() == std::size_t(tile_count(fb));
}

}  // namespace
}  // namespace fast

void PipelineContext::apply_pending_clears(Framebuffer& fb) {
  PendingClears& p = impl_->pending;
  if (!fast::pending_for(p, fb)) return;
  parallel_for(p.tiles.size(), 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) fast::clear_tile(fb, p, int(t));
  });
}

void PipelineContext::parallel_for_ref(std::size_t count, std::size_t grain,
                                       void (*call)(void*, std::size_t, std::size_t), void* fn) {
  if (count == 0) return;
  grain = std::max<std::size_t>(grain, 1);
  std::size_t chunks = std::min<std::size_t>((count + grain - 1) / grain, 1u << 20);
  impl_->pool.run(int(chunks), [&](int c, int) {
    std::size_t begin = count * std::size_t(c) / chunks, end = count * std::size_t(c + 1) / chunks;
    if (begin < end) call(fn, begin, end);
  });
}

namespace fast {

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

constexpr std::size_t kVertexBlock = 2048;   // vertices per vertex-stage work item
constexpr std::size_t kParallelSetup = 4096;  // fewer triangles are set up on one thread

// Window coordinates stay within the viewport (up to rounding) after clipping; these bounds
// keep snapped coordinates in 32 bits and edge functions below 2^53 (exact in doubles).
bool in_fixed_point_range(const Framebuffer& fb, const Viewport& vp) {
  constexpr long kMaxSize = 1 << 15, kMaxCoordinate = 1 << 22;
  return vp.width <= kMaxSize && vp.height <= kMaxSize && fb.width <= kMaxSize &&
         fb.height <= kMaxSize && std::labs(long(vp.x)) + vp.width <= kMaxCoordinate &&
         std::labs(long(vp.y)) + vp.height <= kMaxCoordinate;
}

void vertex_stage(PipelineContext::Impl& impl) {
  DrawJob& job = impl.job;
  const std::size_t n = job.in->positions.size();
  job.vertices.resize(n);
  job.outcodes.resize(n);
  job.varyings.resize(n * std::size_t(job.plan.layout.count));
  int blocks = int((n + kVertexBlock - 1) / kVertexBlock);
  impl.pool.run(blocks, [&](int b, int worker) {
    std::size_t begin = std::size_t(b) * kVertexBlock;
    run_vertex_range(job, begin, std::min(n, begin + kVertexBlock), impl.workers[std::size_t(worker)]);
  });
}

void setup_stage(PipelineContext::Impl& impl) {
  DrawJob& job = impl.job;
  const std::size_t n = job.in->triangles.size();
  job.tiles_x = (job.fb->width + kTileSize - 1) / kTileSize;
  job.tiles_y = (job.fb->height + kTileSize - 1) / kTileSize;
  const std::size_t tiles = std::size_t(job.tiles_x) * std::size_t(job.tiles_y);
  job.chunk_count = n >= kParallelSetup ? impl.pool.size() : 1;
  if (job.chunks.size() < std::size_t(job.chunk_count)) job.chunks.resize(std::size_t(job.chunk_count));
  impl.pool.run(job.chunk_count, [&](int c, int) {
    SetupChunk& chunk = job.chunks[std::size_t(c)];
    reset_chunk(chunk, tiles);
    setup_range(job, chunk, n * std::size_t(c) / std::size_t(job.chunk_count),
                n * std::size_t(c + 1) / std::size_t(job.chunk_count));
  });
  impl.tiles.clear();
  for (std::size_t t = 0; t < tiles; ++t) {
    for (int c = 0; c < job.chunk_count; ++c) {
      if (!job.chunks[std::size_t(c)].bins[t].empty()) {
        impl.tiles.push_back(int(t));
        break;
      }
    }
  }
}

void add_counts(RenderStats& to, const RenderStats& from) {
  to.triangles_in += from.triangles_in;
  to.triangles_culled += from.triangles_culled;
  to.triangles_clipped += from.triangles_clipped;
  to.triangles_rasterized += from.triangles_rasterized;
  to.fragments += from.fragments;
  to.pixels_shaded += from.pixels_shaded;
}

}  // namespace

}  // namespace fast

void detail::draw_triangles_fast(PipelineContext& context, Framebuffer& fb,
                                 const glm::mat4& projection, const Viewport& viewport,
                                 const FragmentState& fragment, const ShadeState& shade,
                                 const VertexInput& in, RenderStats* stats_out) {
  PipelineContext::Impl& impl = context.impl();
  if (!fast::in_fixed_point_range(fb, viewport)) {  // the reference draws: any tile may change
    context.apply_pending_clears(fb);
    impl.tiles.resize(std::size_t(fast::tile_count(fb)));
    for (std::size_t t = 0; t < impl.tiles.size(); ++t) impl.tiles[t] = int(t);
    return draw_triangles(fb, projection, viewport, fragment, shade, in, stats_out);
  }
  RenderStats local;
  RenderStats& stats = stats_out ? *stats_out : local;
  // An incomplete texture is as if texturing were off (GL 1.1 section 3.8.9).
  ShadeState effective = shade;
  if (effective.texture && !effective.texture->complete()) effective.texture = nullptr;
  fast::DrawJob& job = impl.job;
  job.fb = &fb;
  job.frag = &fragment;
  job.shade = &effective;
  job.in = &in;
  job.projection = projection;
  job.viewport = viewport;
  fast::make_plan(job);
  for (fast::WorkerScratch& w : impl.workers) w.stats = RenderStats{};

  auto t0 = fast::Clock::now();
  fast::vertex_stage(impl);
  if (job.plan.vertex_lighting) stats.vertices_lit += in.positions.size() * (job.plan.two_side ? 2 : 1);
  stats.ms_vertex += fast::ms_since(t0);

  auto t1 = fast::Clock::now();
  fast::setup_stage(impl);
  // Tiles are claimed alternately from the first and the second half of the list, so that
  // threads do not draw side by side: the framebuffer's rows need not start on a cache line
  // (a vector's storage is 16-byte aligned), so two tiles next to each other share a line in
  // every row, and two threads writing them pass those lines back and forth (the full-screen
  // Gouraud fill ran no faster on two threads than on one, claiming tiles in order).
  // A tile's pending clear is applied by the thread that draws it, just before drawing.
  const std::size_t tiles = impl.tiles.size(), half = (tiles + 1) / 2;
  const bool pending = fast::pending_for(impl.pending, fb);
  impl.pool.run(int(tiles), [&](int i, int worker) {
    const std::size_t k = (std::size_t(i) % 2) * half + std::size_t(i) / 2;
    if (pending) fast::clear_tile(fb, impl.pending, impl.tiles[k]);
    fast::raster_tile(job, impl.tiles[k], impl.workers[std::size_t(worker)]);
  });
  for (int c = 0; c < job.chunk_count; ++c) fast::add_counts(stats, job.chunks[std::size_t(c)].stats);
  for (const fast::WorkerScratch& w : impl.workers) fast::add_counts(stats, w.stats);
  stats.ms_raster += fast::ms_since(t1);
  job.shade = nullptr;  // `effective` ends here
}

}  // namespace shadelab
