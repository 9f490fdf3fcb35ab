// The fast rasterizer: one tile at a time, every binned triangle in submission order, pixel
// groups as wide as the SIMD target's double lanes. Edge functions are exact integers held in
// doubles (below 2^53), so coverage is the reference's; depth is its double arithmetic.
// Compiled once per SIMD target (Highway), chosen at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fast/raster.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include <algorithm>
#include <bit>
#include <cstring>

#include "fast/fragment-inl.h"
#include "fast/raster.hpp"
#include "fast/triangle.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

namespace {

constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(float);

// A group's depth and colour, in the framebuffer or, past its right edge, in a local copy.
struct GroupPixels {
  float* depth = nullptr;
  std::uint32_t* color = nullptr;
  alignas(64) float depth_copy[kMaxLanes];
  alignas(64) std::uint32_t color_copy[kMaxLanes];
  int valid = 0;  // lanes inside the framebuffer, when copied
};

void open_group(const DrawJob& job, std::size_t index, int valid, int lanes, GroupPixels& g) {
  Framebuffer& fb = *job.fb;
  g.depth = job.frag->depth_test ? &fb.depth[index] : nullptr;
  g.color = job.plan.writes_color ? reinterpret_cast<std::uint32_t*>(&fb.color[index * 4]) : nullptr;
  g.valid = valid > 0 && valid < lanes ? valid : 0;
  if (!g.valid) return;
  std::size_t n = std::size_t(unsigned(g.valid));
  if (g.depth) g.depth = static_cast<float*>(std::memcpy(g.depth_copy, g.depth, n * sizeof(float)));
  if (g.color) g.color = static_cast<std::uint32_t*>(std::memcpy(g.color_copy, g.color, n * 4));
}

void close_group(const DrawJob& job, std::size_t index, const GroupPixels& g) {
  if (!g.valid) return;
  std::size_t n = std::size_t(g.valid);
  if (g.depth) std::memcpy(&job.fb->depth[index], g.depth, n * sizeof(float));
  if (g.color) std::memcpy(&job.fb->color[index * 4], g.color, n * 4);
}

// Per-pixel Phong lights two groups at once where a float vector holds both (16 lanes with
// AVX-512, 8 with AVX2): a group's interpolated position and normal wait here, after its depth
// test, until a second group joins it or the triangle ends. The lanes compute exactly what
// they would alone; only the write of the first group's colour is later, and no other
// fragment of the same triangle touches its pixels.
using DF2 = hn::ScalableTag<float>;
constexpr bool kPairPhong = HWY_TARGET != HWY_SCALAR;

struct PhongPair {
  alignas(64) float in[6][kMaxLanes];  // position x y z, normal x y z; group k at k * lanes(DF)
  std::size_t index[2];                // framebuffer index of each group's first pixel
  MF live[2];
  int count = 0;
};

void flush_phong(const DrawJob& job, const TriSetup& t, PhongPair& pair) {
  if (pair.count == 0) return;
  const DF df;
  const std::size_t half = hn::Lanes(df);
  alignas(64) float lit[4][kMaxLanes];
  if (pair.count == 2 && hn::Lanes(DF2()) == 2 * half) {
    const DF2 d2;
    hn::Vec<DF2> out[4];
    phong_lanes(job, t, d2, V3<DF2>{hn::Load(d2, pair.in[0]), hn::Load(d2, pair.in[1]), hn::Load(d2, pair.in[2])},
                V3<DF2>{hn::Load(d2, pair.in[3]), hn::Load(d2, pair.in[4]), hn::Load(d2, pair.in[5])}, out);
    for (int c = 0; c < 4; ++c) hn::Store(out[c], d2, lit[c]);
  } else {
    for (int k = 0; k < pair.count; ++k) {
      VF out[4];
      const std::size_t o = std::size_t(k) * half;
      phong_lanes(job, t, df,
                  V3<DF>{hn::LoadU(df, pair.in[0] + o), hn::LoadU(df, pair.in[1] + o), hn::LoadU(df, pair.in[2] + o)},
                  V3<DF>{hn::LoadU(df, pair.in[3] + o), hn::LoadU(df, pair.in[4] + o), hn::LoadU(df, pair.in[5] + o)},
                  out);
      for (int c = 0; c < 4; ++c) hn::StoreU(out[c], df, lit[c] + o);
    }
  }
  for (int k = 0; k < pair.count; ++k) {
    const std::size_t o = std::size_t(k) * half;
    Rgba color;
    for (int c = 0; c < 4; ++c) color.c[c] = hn::LoadU(df, lit[c] + o);
    write_colors(*job.frag, color, pair.live[k],
                 reinterpret_cast<std::uint32_t*>(&job.fb->color[pair.index[k] * 4]));
  }
  pair.count = 0;
}

// A triangle's fragment counts, kept in registers while it is drawn (RenderStats at the end).
struct GroupCounts {
  std::uint64_t fragments = 0, shaded = 0;
};

// The SIMD fragment path for the covered lanes `bits` of one group.
void simd_group(const DrawJob& job, const TriSetup& t, GroupCounts& counts, PhongPair& pair, int x,
                int y, unsigned bits, VD b0, VD b1, VF z) {
  const DF df;
  const FragmentState& fs = *job.frag;
  std::size_t index = std::size_t(y) * std::size_t(job.fb->width) + std::size_t(x);
  GroupPixels g;
  open_group(job, index, job.fb->width - x, int(hn::Lanes(df)), g);
  std::uint8_t cover = std::uint8_t(bits);
  MF live = hn::LoadMaskBits(df, &cover);
  if (fs.depth_test) {
    live = hn::And(live, depth_compare(fs.depth_func, z, hn::LoadU(df, g.depth)));
    if (fs.depth_write) hn::BlendedStore(z, live, df, g.depth);
  }
  std::uint8_t passed = 0;
  hn::StoreMaskBits(df, live, &passed);
  counts.fragments += unsigned(std::popcount(bits));
  counts.shaded += unsigned(std::popcount(unsigned(passed)));
  if (passed && job.plan.writes_color) {
    const DD dd;
    Weights w = perspective_weights(t, b0, b1, hn::Sub(hn::Sub(hn::Set(dd, 1.0), b0), b1));
    if (kPairPhong && job.plan.phong && !g.valid) {  // whole group inside: its pixels, not a copy
      VF in[6];
      phong_inputs(job, t, w, in);
      const std::size_t o = std::size_t(pair.count) * hn::Lanes(df);
      for (int k = 0; k < 6; ++k) hn::StoreU(in[k], df, pair.in[k] + o);
      pair.index[pair.count] = index;
      pair.live[pair.count] = live;
      if (++pair.count == 2) flush_phong(job, t, pair);
      return;
    }
    Rgba color = job.plan.phong ? phong_color(job, t, w) : vertex_color(job, t, w);
    write_colors(fs, color, live, g.color);
  }
  close_group(job, index, g);
}

// Reference per-fragment operations for the covered lanes (stencil, capture, textures...).
void scalar_group(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, int x, int y,
                  unsigned bits, VD e0, VD e1, VF z) {
  alignas(64) double w0[kMaxLanes], w1[kMaxLanes];
  alignas(64) float zs[kMaxLanes];
  hn::Store(e0, DD(), w0);
  hn::Store(e1, DD(), w1);
  hn::StoreU(z, DF(), zs);
  for (; bits; bits &= bits - 1) {
    int lane = std::countr_zero(bits);
    scalar_fragment(job, t, ws, x + lane, y, w0[lane], w1[lane], zs[lane]);
  }
}

// Coverage, then depth (reference_raster.inl: b = w * (1 / area), b2 = 1 - b0 - b1, z = sum b z).
void group(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, GroupCounts& counts, PhongPair& pair,
           int x, int y, const VD e[3], const VD thr[3]) {
  const DD dd;
  const DF df;
  auto cov = hn::And(hn::And(hn::Ge(e[0], thr[0]), hn::Ge(e[1], thr[1])), hn::Ge(e[2], thr[2]));
  if (hn::AllFalse(dd, cov)) return;
  std::uint8_t cover = 0;
  hn::StoreMaskBits(dd, cov, &cover);
  unsigned bits = cover;
  int valid = job.fb->width - x;
  if (valid < int(hn::Lanes(dd))) bits &= (1u << valid) - 1u;
  if (!bits) return;
  VD inv_area = hn::Set(dd, t.inv_area);
  VD b0 = hn::Mul(e[0], inv_area), b1 = hn::Mul(e[1], inv_area);
  VD b2 = hn::Sub(hn::Sub(hn::Set(dd, 1.0), b0), b1);
  VD zd = hn::Add(hn::Add(hn::Mul(b0, hn::Set(dd, double(t.v[0]->z))), hn::Mul(b1, hn::Set(dd, double(t.v[1]->z)))),
                  hn::Mul(b2, hn::Set(dd, double(t.v[2]->z))));
  VF z = clamp_unit(hn::Add(hn::DemoteTo(df, zd), hn::Set(df, t.offset)));  // draw.cpp's emit
  if (job.plan.scalar_fragments) return scalar_group(job, t, ws, x, y, bits, e[0], e[1], z);
  simd_group(job, t, counts, pair, x, y, bits, b0, b1, z);
}

void raster_triangle(const DrawJob& job, const TriSetup& t, WorkerScratch& ws) {
  const DD dd;
  const int lanes = int(hn::Lanes(dd));
  if (job.plan.scalar_fragments) expand_triangle(job, t, ws);
  VD lane_step[3], group_step[3], thr[3];
  for (int e = 0; e < 3; ++e) {
    double a = double(-t.dy[e] * detail::kSubpixelOne);  // edge change one pixel right
    lane_step[e] = hn::Mul(hn::Iota(dd, 0.0), hn::Set(dd, a));
    group_step[e] = hn::Set(dd, a * lanes);
    thr[e] = hn::Set(dd, t.threshold[e]);
  }
  const int gx0 = t.x0 & ~(lanes - 1);
  PhongPair pair;
  GroupCounts counts;
  for (int y = t.y0; y <= t.y1; ++y) {
    VD e[3];
    for (int k = 0; k < 3; ++k) e[k] = hn::Add(hn::Set(dd, double(edge_at(t, k, gx0, y))), lane_step[k]);
    for (int x = gx0; x <= t.x1; x += lanes) {
      group(job, t, ws, counts, pair, x, y, e, thr);
      for (int k = 0; k < 3; ++k) e[k] = hn::Add(e[k], group_step[k]);
    }
  }
  flush_phong(job, t, pair);
  ws.stats.fragments += counts.fragments;
  ws.stats.pixels_shaded += counts.shaded;
}

}  // namespace

void RasterTile(const DrawJob& job, int tile, WorkerScratch& ws) {
  const int tx = (tile % job.tiles_x) * kTileSize, ty = (tile / job.tiles_x) * kTileSize;
  TriSetup t;
  for (int c = 0; c < job.chunk_count; ++c) {
    for (std::uint32_t entry : job.chunks[std::size_t(c)].bins[std::size_t(tile)]) {
      if (setup_triangle(job, c, entry, tx, ty, t)) raster_triangle(job, t, ws);
    }
  }
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace shadelab::fast {

HWY_EXPORT(RasterTile);

void raster_tile(const DrawJob& job, int tile, WorkerScratch& ws) {
  HWY_DYNAMIC_DISPATCH(RasterTile)(job, tile, ws);
}

}  // namespace shadelab::fast
#endif
