// One draw through the fast pipeline: plan, vertex stage over blocks of vertices, setup over
// contiguous triangle chunks (so each tile's bins keep submission order), then the non-empty
// tiles rasterized by whichever thread is free; or, deferred, the rasterization left to
// finish_draws, which draws the tiles of every waiting draw together. Every stage runs on the
// context's pool.
#include "fast/draw_fast.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <mutex>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "fast/context.hpp"
#include "fast/plan.hpp"
#include "fast/prims.hpp"
#include "fast/raster.hpp"
#include "fast/setup.hpp"
#include "fast/simd_targets.hpp"
#include "fast/vertex_stage.hpp"

namespace shadelab {

namespace {

// $SHADELAB_SIMD (avx512, avx2, sse4, ssse3, scalar) restricts the process's dispatch to one
// target, for benchmarks comparing them; read once, when the first context is made.
void apply_simd_environment() {
  static std::once_flag once;
  std::call_once(once, [] {
    const char* env = std::getenv("SHADELAB_SIMD");
    if (env && *env) fast::force_simd_target(env);
  });
}

}  // namespace

PipelineContext::PipelineContext(int threads)
    : impl_((apply_simd_environment(), std::make_unique<Impl>(fast::resolve_thread_count(threads)))) {}

std::string PipelineContext::simd_target() { return fast::current_simd_target(); }

PipelineContext::~PipelineContext() { impl_->pool.wait(); }  // clear_ahead's job uses Impl

int PipelineContext::threads() const { return impl_->pool.size(); }

std::span<const int> PipelineContext::last_draw_tiles() const { return impl_->tiles; }

PipelineContext::PendingClears& PipelineContext::pending_clears() {
  impl_->pool.wait();  // clear_ahead's job writes the flags
  return impl_->pending;
}

namespace fast {
namespace {

int tile_columns(const Framebuffer& fb) { return (fb.width + kTileSize - 1) / kTileSize; }

int tile_count(const Framebuffer& fb) { return tile_columns(fb) * ((fb.height + kTileSize - 1) / kTileSize); }

// Fills n pixels at `dst` with `value`, with streaming stores where the target has them and
// dst is aligned for them (the lines written need not be read first).
void stream_fill(std::uint32_t* dst, std::size_t n, std::uint32_t value) {
#if defined(__SSE2__)
  if ((reinterpret_cast<std::uintptr_t>(dst) & 15u) == 0) {
    const __m128i v = _mm_set1_epi32(int(value));
    for (; n >= 4; n -= 4, dst += 4) _mm_stream_si128(reinterpret_cast<__m128i*>(dst), v);
  }
#endif
  std::fill_n(dst, n, value);
}

// Applies the buffers in `only` of tile `tile`'s pending clear, if any, and resets their
// flags. With `stream`, colour is written with streaming stores (for a tile not drawn next),
// and the caller fences (fence_streams) before others read it.
void clear_tile(Framebuffer& fb, PipelineContext::PendingClears& p, int tile, std::uint8_t only, bool stream) {
  const std::uint8_t what = p.tiles[std::size_t(tile)] & only;
  if (!what) return;
  p.tiles[std::size_t(tile)] &= std::uint8_t(~what);
  const int columns = tile_columns(fb);
  const int x0 = (tile % columns) * kTileSize, y0 = (tile / columns) * kTileSize;
  const int x1 = std::min(fb.width, x0 + kTileSize), y1 = std::min(fb.height, y0 + kTileSize);
  auto* color = reinterpret_cast<std::uint32_t*>(fb.color.data());
  for (int y = y0; y < y1; ++y) {
    const std::size_t row = std::size_t(y) * std::size_t(fb.width);
    if (what & PipelineContext::PendingClears::kColor) {
      if (stream) stream_fill(color + row + x0, std::size_t(x1 - x0), p.color);
      else std::fill(color + row + x0, color + row + x1, p.color);
    }
    if (what & PipelineContext::PendingClears::kDepth) std::fill(&fb.depth[row + std::size_t(x0)], &fb.depth[row + std::size_t(x1)], p.depth);
  }
}

void fence_streams() {
#if defined(__SSE2__)
  _mm_sfence();  // streaming stores are seen by whoever reads the framebuffer next
#endif
}

// Whether `p` holds flags for `fb`'s tiles (anything else is nothing pending).
bool pending_for(const PipelineContext::PendingClears& p, const Framebuffer& fb) {
  return !p.tiles.empty() && p.tiles.size() == std::size_t(tile_count(fb));
}

}  // namespace
}  // namespace fast

void PipelineContext::apply_pending_clears(Framebuffer& fb, std::uint8_t what) {
  finish_draws();
  PendingClears& p = impl_->pending;
  if (!fast::pending_for(p, fb)) return;
  parallel_for(p.tiles.size(), 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) fast::clear_tile(fb, p, int(t), what, true);
    fast::fence_streams();
  });
}

void PipelineContext::clear_ahead(Framebuffer& fb, std::uint8_t what, std::span<const int> tiles) {
  Impl& impl = *impl_;
  impl.pool.wait();  // the job before reads impl.ahead
  if (impl.pool.size() < 2 || tiles.empty() || !fast::pending_for(impl.pending, fb)) return;
  impl.ahead.pending = &impl.pending;
  impl.ahead.fb = &fb;
  impl.ahead.what = what & (PendingClears::kColor | PendingClears::kDepth);
  // Each of fb's tiles once (two threads must not clear one tile).
  std::vector<int>& list = impl.ahead.tiles;
  const int count = fast::tile_count(fb);
  list.clear();
  for (int t : tiles) {
    if (t >= 0 && t < count) list.push_back(t);
  }
  if (!std::is_sorted(list.begin(), list.end())) std::sort(list.begin(), list.end());
  list.erase(std::unique(list.begin(), list.end()), list.end());
  impl.pool.start(int(list.size()), impl.ahead);
}

void PipelineContext::Impl::ClearAhead::operator()(int item) const {
  fast::clear_tile(*fb, *pending, tiles[std::size_t(item)], what, true);
  fast::fence_streams();
}

void PipelineContext::clear_later(Framebuffer& fb, std::uint8_t what, glm::vec4 color, float depth) {
  finish_draws();  // drawn before the clear
  PendingClears& p = impl_->pending;
  if (!fast::pending_for(p, fb)) p.tiles.assign(std::size_t(fast::tile_count(fb)), 0);
  // Every tile is flagged: a value pending before for the same buffer is cleared over.
  what &= PendingClears::kColor | PendingClears::kDepth;
  const std::array<std::uint8_t, 4> bytes = Framebuffer::color_bytes(color);
  if (what & PendingClears::kColor) std::memcpy(&p.color, bytes.data(), 4);
  if (what & PendingClears::kDepth) p.depth = std::clamp(depth, 0.0f, 1.0f);
  for (std::uint8_t& t : p.tiles) t |= what;
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

// Deferred drawing's bounds. A draw with more triangles or vertices draws at once (after the
// waiting ones): it is long enough to pay for its own pass over the framebuffer, and its
// triangle indices would have to be copied. The queue's memory stays bounded by its vertex
// count (the vertex stage's output, 48 bytes and more a vertex) and its draw count
// (kMaxQueuedDraws, draw_fast.hpp: every draw keeps a bin per tile, 12 KB at 1920 x 1080); a
// full queue is drawn before the next draw joins it.
constexpr std::size_t kMaxDeferredTriangles = std::size_t(1) << 16;
constexpr std::size_t kMaxDeferredVertices = std::size_t(1) << 17;
constexpr std::size_t kMaxQueuedVertices = std::size_t(1) << 20;

// Window coordinates stay within the viewport (up to rounding) after clipping; these bounds
// keep snapped coordinates in 32 bits and edge functions below 2^53 (exact in doubles).
bool in_fixed_point_range(const Framebuffer& fb, const Viewport& vp) {
  constexpr long kMaxSize = 1 << 15, kMaxCoordinate = 1 << 22;
  return vp.width <= kMaxSize && vp.height <= kMaxSize && fb.width <= kMaxSize &&
         fb.height <= kMaxSize && std::labs(long(vp.x)) + vp.width <= kMaxCoordinate &&
         std::labs(long(vp.y)) + vp.height <= kMaxCoordinate;
}

void vertex_stage(PipelineContext::Impl& impl, DrawJob& job) {
  const std::size_t n = job.in->positions.size();
  job.vertices.resize(n);
  job.outcodes.resize(n);
  job.user_outcodes.resize(job.plan.user_plane_count ? n : 0);
  job.varyings.resize(n * std::size_t(job.plan.layout.count));
  int blocks = int((n + kVertexBlock - 1) / kVertexBlock);
  impl.pool.run(blocks, [&](int b, int worker) {
    std::size_t begin = std::size_t(b) * kVertexBlock;
    run_vertex_range(job, begin, std::min(n, begin + kVertexBlock), impl.workers[std::size_t(worker)]);
  });
}

// Sets up the draw's items (its triangles, then lines, then points) in contiguous chunks, each
// on one thread; filled triangles by setup_range, the rest by setup_prims.
void setup_stage(PipelineContext::Impl& impl, DrawJob& job) {
  const std::size_t n = job.plan.prims ? setup_items(*job.in) : job.triangles.size();
  const std::size_t filled = job.plan.prims && detail::PrimAssembler::unfilled(*job.frag) ? 0 : job.triangles.size();
  job.tiles_x = (job.fb->width + kTileSize - 1) / kTileSize;
  job.tiles_y = (job.fb->height + kTileSize - 1) / kTileSize;
  const std::size_t tiles = std::size_t(job.tiles_x) * std::size_t(job.tiles_y);
  const bool sequential = job.plan.prims && sequential_setup(job);
  job.chunk_count = n >= kParallelSetup && !sequential ? impl.pool.size() : 1;
  if (job.chunks.size() < std::size_t(job.chunk_count)) job.chunks.resize(std::size_t(job.chunk_count));
  std::uint32_t stipple = job.in->stipple_counter ? *job.in->stipple_counter : 0u;
  impl.pool.run(job.chunk_count, [&](int c, int) {
    SetupChunk& chunk = job.chunks[std::size_t(c)];
    reset_chunk(chunk, tiles);
    const std::size_t begin = n * std::size_t(c) / std::size_t(job.chunk_count);
    const std::size_t end = n * std::size_t(c + 1) / std::size_t(job.chunk_count);
    if (begin < filled) setup_range(job, chunk, begin, std::min(end, filled));
    std::uint32_t counter = stipple;  // only one chunk when the stipple runs on
    if (job.plan.prims) setup_prims(job, chunk, begin, end, counter);
    if (job.chunk_count == 1) stipple = counter;
  });
  if (job.in->stipple_counter) *job.in->stipple_counter = stipple;
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

PixelTarget framebuffer_target(Framebuffer& fb) {
  return {fb.depth.data(), reinterpret_cast<std::uint32_t*>(fb.color.data()), std::size_t(fb.width), 0, 0,
          fb.stencil.data(), std::size_t(fb.width)};
}

// Draws tile `tile` of every job in `jobs`, in order, on one thread. A tile with a pending
// clear, wholly inside the framebuffer and drawn on the SIMD path alone, is drawn in the
// worker's tile buffer: its cleared parts made there, the others copied in, the draws made
// in the cache, and the tile written out once with streaming stores. Clearing it in the
// framebuffer would first read every line of it from memory (the stores of a clear fetch the
// lines they write), and evict it again when the next tile is drawn. Any other tile is
// cleared in place (when pending) and drawn in the framebuffer. Depth is read and written
// only under the depth test: when no draw of the tile tests it, the tile's depth is neither
// loaded, cleared nor written out, and its pending clear stays pending (for a later draw or
// apply_pending_clears).
template <class Jobs>
void draw_tile(PipelineContext::Impl& impl, Framebuffer& fb, int tile, const Jobs& jobs, WorkerScratch& ws) {
  using Clears = PipelineContext::PendingClears;
  Clears& p = impl.pending;
  bool with_depth = false, simd = true;
  for (const DrawJob* job : jobs) {
    with_depth = with_depth || job->frag->depth_test;
    simd = simd && !job->plan.scalar_fragments;
  }
  const std::uint8_t used = with_depth ? Clears::kColor | Clears::kDepth : Clears::kColor;
  const std::uint8_t what = pending_for(p, fb) ? p.tiles[std::size_t(tile)] & used : 0;
  const int columns = tile_columns(fb);
  const int x0 = (tile % columns) * kTileSize, y0 = (tile / columns) * kTileSize;
  if (what == 0 || !simd || x0 + kTileSize > fb.width || y0 + kTileSize > fb.height) {
    if (what) clear_tile(fb, p, tile, used, false);
    ws.target = framebuffer_target(fb);
    ws.bound.start(x0, y0, false, simd, (what & Clears::kDepth) != 0, p.depth);
    for (const DrawJob* job : jobs) raster_tile(*job, tile, ws);
    return;
  }
  p.tiles[std::size_t(tile)] &= std::uint8_t(~what);
  if (!ws.tile) ws.tile = std::make_unique<TileBuffer>();
  TileBuffer& b = *ws.tile;
  const std::size_t first = std::size_t(y0) * std::size_t(fb.width) + std::size_t(x0);
  const TileRows rows{reinterpret_cast<std::uint32_t*>(fb.color.data()) + first, fb.depth.data() + first,
                      std::size_t(fb.width)};
  load_tile(b, rows, what, p.color, p.depth, with_depth);
  ws.target = {b.depth, b.color, std::size_t(kTileSize), x0, y0, fb.stencil.data(), std::size_t(fb.width)};
  ws.bound.start(x0, y0, true, true, (what & Clears::kDepth) != 0, p.depth);
  for (const DrawJob* job : jobs) raster_tile(*job, tile, ws);
  store_tile(b, rows, with_depth);
  fence_streams();
}

// Rasterizes `tiles` (indices of framebuffer tiles) with draw_tile; jobs_of(tile) names the
// draws to make in it. Each thread draws a contiguous run of the list (the pool's shares),
// so threads do not draw side by side: the framebuffer's rows need not start on a cache line
// (a vector's storage is 16-byte aligned), so two tiles next to each other share a line in
// every row, and two threads writing them pass those lines back and forth (the full-screen
// Gouraud fill ran no faster on two threads than on one, claiming tiles in order).
template <class JobsOf>
void raster_tiles(PipelineContext::Impl& impl, Framebuffer& fb, std::span<const int> tiles, const JobsOf& jobs_of) {
  impl.pool.run(int(tiles.size()), [&](int i, int worker) {
    const int tile = tiles[std::size_t(i)];
    draw_tile(impl, fb, tile, jobs_of(tile), impl.workers[std::size_t(worker)]);
  });
}

// Whether a draw may wait for finish_draws: nothing it reads may change or end before then
// (shadow maps, a capture and a texture not kept are the caller's), and its counts are not
// asked for.
bool deferrable(const PipelineContext::Impl& impl, const FragmentState& frag, const ShadeState& shade,
                const VertexInput& in, const RenderStats* stats) {
  return impl.deferred && !stats && !frag.capture && (!shade.textured() || shade.texture_kept) &&
         shade.shadow_maps.empty() &&
         setup_items(in) <= kMaxDeferredTriangles && in.positions.size() <= kMaxDeferredVertices;
}

void add_counts(RenderStats& to, const RenderStats& from) {
  to.triangles_in += from.triangles_in;
  to.triangles_culled += from.triangles_culled;
  to.triangles_clipped += from.triangles_clipped;
  to.triangles_rasterized += from.triangles_rasterized;
  to.fragments += from.fragments;
  to.fragments_reference += from.fragments_reference;
  to.pixels_shaded += from.pixels_shaded;
}

// The workers' fragment counts of the rasterization just done, into the context's totals
// (set_counting); the workers' counts start again.
void count_raster(PipelineContext::Impl& impl) {
  if (!impl.counting) return;
  for (WorkerScratch& w : impl.workers) {
    add_counts(impl.totals, w.stats);
    w.stats = RenderStats{};
  }
}

}  // namespace

}  // namespace fast

void PipelineContext::set_deferred(bool on) {
  if (!on) finish_draws();
  impl_->deferred = on;
}

std::size_t PipelineContext::deferred_draws() const { return impl_->queued; }

std::uint64_t PipelineContext::draws_made() const { return impl_->made; }

void PipelineContext::set_counting(bool on) { impl_->counting = on; }

RenderStats PipelineContext::take_counts() {
  RenderStats out = impl_->totals;
  impl_->totals = RenderStats{};
  return out;
}

void PipelineContext::finish_draws() {
  Impl& impl = *impl_;
  impl.pool.wait();  // clear_ahead's job ends first
  if (impl.queued == 0) return;
  const fast::DrawJob& first = *impl.jobs[0];
  if (first.fb->width != first.fb_width || first.fb->height != first.fb_height) {
    impl.queued = impl.queued_vertices = 0;  // resized under the queue (against the contract):
    return;                                  // its tiles are no longer the framebuffer's
  }
  const std::size_t tiles = std::size_t(first.tiles_x) * std::size_t(first.tiles_y);
  if (impl.tile_jobs.size() < tiles) impl.tile_jobs.resize(tiles);
  for (std::size_t t = 0; t < tiles; ++t) impl.tile_jobs[t].clear();
  for (std::size_t j = 0; j < impl.queued; ++j) {
    for (int t : impl.jobs[j]->tiles) impl.tile_jobs[std::size_t(t)].push_back(impl.jobs[j].get());
  }
  impl.tiles.clear();
  for (std::size_t t = 0; t < tiles; ++t) {
    if (!impl.tile_jobs[t].empty()) impl.tiles.push_back(int(t));
  }
  for (fast::WorkerScratch& w : impl.workers) w.stats = RenderStats{};
  fast::raster_tiles(impl, *first.fb, impl.tiles, [&](int tile) -> const std::vector<const fast::DrawJob*>& {
    return impl.tile_jobs[std::size_t(tile)];
  });
  fast::count_raster(impl);
  impl.tiles.assign(impl.jobs[impl.queued - 1]->tiles.begin(), impl.jobs[impl.queued - 1]->tiles.end());
  impl.queued = 0;
  impl.queued_vertices = 0;
}

void detail::draw_triangles_fast(PipelineContext& context, Framebuffer& fb,
                                 const glm::mat4& projection, const Viewport& viewport,
                                 const FragmentState& fragment, const ShadeState& shade,
                                 const VertexInput& in, RenderStats* stats_out) {
  PipelineContext::Impl& impl = context.impl();
  impl.pool.wait();  // clear_ahead's job ends first
  ++impl.made;
  if (!fast::in_fixed_point_range(fb, viewport)) {  // the reference draws: any tile may change
    context.apply_pending_clears(fb);
    impl.tiles.resize(std::size_t(fast::tile_count(fb)));
    for (std::size_t t = 0; t < impl.tiles.size(); ++t) impl.tiles[t] = int(t);
    if (!impl.counting) return draw_triangles(fb, projection, viewport, fragment, shade, in, stats_out);
    RenderStats counts;  // every fragment on the reference's path
    draw_triangles(fb, projection, viewport, fragment, shade, in, &counts);
    counts.fragments_reference = counts.fragments;
    fast::add_counts(impl.totals, counts);
    ++impl.totals.draws;
    if (stats_out) {
      fast::add_counts(*stats_out, counts);
      stats_out->vertices_lit += counts.vertices_lit;
      stats_out->ms_vertex += counts.ms_vertex;
      stats_out->ms_raster += counts.ms_raster;
    }
    return;
  }
  RenderStats local;
  RenderStats& stats = stats_out ? *stats_out : local;
  // An incomplete texture is as if texturing were off (GL 1.1 section 3.8.9).
  ShadeState effective = shade;
  effective.drop_incomplete_textures();
  const bool defer = fast::deferrable(impl, fragment, effective, in, stats_out);
  // Deferred draws wait in the queue while it has room; anything else draws after them.
  if (impl.queued > 0 && (!defer || impl.queued == fast::kMaxQueuedDraws || impl.jobs[0]->fb != &fb ||
                          impl.queued_vertices + in.positions.size() > fast::kMaxQueuedVertices)) {
    context.finish_draws();
  }
  if (impl.jobs.size() <= impl.queued) impl.jobs.push_back(std::make_unique<fast::DrawJob>());
  fast::DrawJob& job = *impl.jobs[impl.queued];
  job.fb = &fb;
  job.fb_width = fb.width;
  job.fb_height = fb.height;
  job.shade_copy = effective;
  job.shade = &job.shade_copy;
  job.in = &in;
  job.triangles = in.triangles;
  job.frag = &fragment;
  if (defer) {  // owns what it reads after returning
    job.frag_copy = fragment;
    job.frag = &job.frag_copy;
    job.light_copy.assign(shade.lights.begin(), shade.lights.end());
    job.shade_copy.lights = job.light_copy;
    job.triangle_copy.resize(in.triangles.size());
    std::copy(in.triangles.begin(), in.triangles.end(), job.triangle_copy.begin());
    job.triangles = job.triangle_copy;
  }
  job.counted = stats_out != nullptr;
  job.projection = projection;
  job.viewport = viewport;
  fast::make_plan(job);
  for (fast::WorkerScratch& w : impl.workers) w.stats = RenderStats{};

  auto t0 = fast::Clock::now();
  fast::vertex_stage(impl, job);
  if (job.plan.vertex_lighting) stats.vertices_lit += in.positions.size() * (job.plan.two_side ? 2 : 1);
  stats.ms_vertex += fast::ms_since(t0);

  auto t1 = fast::Clock::now();
  fast::setup_stage(impl, job);
  job.in = nullptr;
  for (int c = 0; c < job.chunk_count; ++c) fast::add_counts(stats, job.chunks[std::size_t(c)].stats);
  if (impl.counting) {
    for (int c = 0; c < job.chunk_count; ++c) fast::add_counts(impl.totals, job.chunks[std::size_t(c)].stats);
    ++impl.totals.draws;
    impl.totals.draws_deferred += defer;
  }
  if (defer) {
    job.tiles.assign(impl.tiles.begin(), impl.tiles.end());
    ++impl.queued;
    impl.queued_vertices += in.positions.size();
    stats.ms_raster += fast::ms_since(t1);
    return;
  }
  const fast::DrawJob* const only[1] = {&job};
  fast::raster_tiles(impl, fb, impl.tiles, [&](int) { return std::span<const fast::DrawJob* const>(only); });
  for (const fast::WorkerScratch& w : impl.workers) fast::add_counts(stats, w.stats);
  fast::count_raster(impl);
  stats.ms_raster += fast::ms_since(t1);
  job.frag = nullptr;  // the caller's, as are the lights of shade_copy and the triangles
  job.shade_copy.lights = {};
  job.triangles = {};
}

}  // namespace shadelab
