// Triangle setup and binning: clip tests from the vertex outcodes (the clipper itself for the
// few triangles that cross the view volume), facing and culling from the reference's window
// area, then each triangle's index into every tile its pixel box touches, in submission order.
#include "fast/setup.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace shadelab::fast {

namespace {

using detail::ClipVertex;

// Twice a triangle's signed window area: signed_area's loop below unrolled, the same sums in
// the same order. Inlined (as keep is) into the per-triangle loop, which calls nothing else
// for a culled triangle: as functions of their own, the two were 9% of the 1M-triangle
// sphere's samples on one thread.
[[gnu::always_inline]] inline double triangle_area(const RasterVertex& p, const RasterVertex& q,
                                                   const RasterVertex& r) {
  double a = 0.0;
  a += p.x * q.y - q.x * p.y;
  a += q.x * r.y - r.x * q.y;
  a += r.x * p.y - p.x * r.y;
  return a;
}

// Twice the signed window area, as draw.cpp's signed_area sums it.
double signed_area(const RasterVertex* const* v, std::size_t n) {
  if (n == 3) return triangle_area(*v[0], *v[1], *v[2]);
  double a = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const RasterVertex& p = *v[i];
    const RasterVertex& q = *v[(i + 1) % n];
    a += p.x * q.y - q.x * p.y;
  }
  return a;
}

// Facing and culling; false when the polygon is dropped (and counted).
[[gnu::always_inline]] inline bool keep(const DrawJob& job, double area, bool& front, RenderStats& stats) {
  if (area == 0.0 || !std::isfinite(area)) {
    ++stats.triangles_culled;
    return false;
  }
  front = (area > 0.0) == job.frag->front_ccw;
  CullMode cull = job.frag->cull;
  if ((cull == CullMode::kBack && !front) || (cull == CullMode::kFront && front)) {
    ++stats.triangles_culled;
    return false;
  }
  ++stats.triangles_rasterized;
  return true;
}

// True when some pixel centre of the tile may pass edge a->b (conservative, exact integers).
bool tile_touches_edge(const RasterVertex& a, const RasterVertex& b, std::int64_t threshold,
                       int tx, int ty) {
  std::int64_t dx = std::int64_t(b.sx) - a.sx, dy = std::int64_t(b.sy) - a.sy;
  std::int64_t px = std::int64_t(tx) * kTileSize * detail::kSubpixelOne + detail::kSubpixelOne / 2;
  std::int64_t py = std::int64_t(ty) * kTileSize * detail::kSubpixelOne + detail::kSubpixelOne / 2;
  // The edge function grows with y by dx and falls with x by dy: its largest value on the
  // tile's centres is at the corner picked by those signs.
  std::int64_t span = std::int64_t(kTileSize - 1) * detail::kSubpixelOne;
  std::int64_t cx = dy < 0 ? px + span : px, cy = dx > 0 ? py + span : py;
  return dx * (cy - a.sy) - dy * (cx - a.sx) >= threshold;
}

}  // namespace

namespace {

// Bins the convex polygon v[0..n-1] (counter-clockwise, n = 3 or 4) into the tiles of its
// pixel box that some edge test does not rule out.
template <int n>
[[gnu::always_inline]] inline void bin_convex(const DrawJob& job, SetupChunk& chunk, const RasterVertex* const* v,
                                              std::uint32_t entry) {
  const DrawPlan& p = job.plan;
  std::int64_t min_x = v[0]->sx, max_x = v[0]->sx, min_y = v[0]->sy, max_y = v[0]->sy;
  for (int k = 1; k < n; ++k) {
    min_x = std::min<std::int64_t>(min_x, v[k]->sx), max_x = std::max<std::int64_t>(max_x, v[k]->sx);
    min_y = std::min<std::int64_t>(min_y, v[k]->sy), max_y = std::max<std::int64_t>(max_y, v[k]->sy);
  }
  // The pixels whose centres lie in the polygon's box, in the framebuffer and the scissor box.
  int x0 = std::max(p.box_x0, first_centre(min_x)), x1 = std::min(p.box_x1, last_centre(max_x));
  int y0 = std::max(p.box_y0, first_centre(min_y)), y1 = std::min(p.box_y1, last_centre(max_y));
  if (x0 > x1 || y0 > y1) return;
  int tx0 = x0 >> kTileShift, tx1 = x1 >> kTileShift, ty0 = y0 >> kTileShift, ty1 = y1 >> kTileShift;
  if (tx0 == tx1 && ty0 == ty1) {  // most triangles of a big mesh: one tile, no edge tests
    chunk.bins[std::size_t(ty0) * job.tiles_x + tx0].push_back(entry);
    return;
  }
  bool test_tiles = (tx1 - tx0 + 1) * (ty1 - ty0 + 1) > 2;
  // The edges' thresholds (0 if owned, else 1).
  std::int64_t t[4];
  for (int e = 0; e < n; ++e) {
    const RasterVertex &a = *v[e], &b = *v[(e + 1) % n];
    t[e] = detail::owns_edge({a.sx, a.sy}, {b.sx, b.sy}) ? 0 : 1;
  }
  for (int ty = ty0; ty <= ty1; ++ty) {
    for (int tx = tx0; tx <= tx1; ++tx) {
      bool touches = true;
      for (int e = 0; e < n && test_tiles; ++e) touches = touches && tile_touches_edge(*v[e], *v[(e + 1) % n], t[e], tx, ty);
      if (touches) chunk.bins[std::size_t(ty) * job.tiles_x + tx].push_back(entry);
    }
  }
}

std::int64_t snapped_area(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c) {
  return (std::int64_t(b.sx) - a.sx) * (std::int64_t(c.sy) - a.sy) -
         (std::int64_t(b.sy) - a.sy) * (std::int64_t(c.sx) - a.sx);
}

}  // namespace

void bin_triangle(const DrawJob& job, SetupChunk& chunk, const RasterVertex& a,
                  const RasterVertex& b, const RasterVertex& c, std::uint32_t entry) {
  const std::int64_t area = snapped_area(a, b, c);
  if (area == 0) return;  // the rasterizer draws nothing
  const RasterVertex* v[3] = {&a, area > 0 ? &b : &c, area > 0 ? &c : &b};
  bin_convex<3>(job, chunk, v, entry);
}

void bin_parallelogram(const DrawJob& job, SetupChunk& chunk, const RasterVertex& a, const RasterVertex& b,
                       const RasterVertex& c, const RasterVertex& d, std::uint32_t entry) {
  // Clockwise (inside out), it covers nothing (setup_triangle).
  if (snapped_area(a, b, c) <= 0) return;
  const RasterVertex* v[4] = {&a, &b, &c, &d};
  bin_convex<4>(job, chunk, v, entry);
}

namespace {

// draw.cpp's to_window for a clipped vertex, snapped.
RasterVertex raster_vertex(const ClipVertex& v, const Viewport& vp) {
  detail::WindowVertex r = detail::to_window(v, vp);
  RasterVertex w;
  w.x = r.x;
  w.y = r.y;
  w.z = r.z;
  w.inv_w = r.inv_w;
  detail::FixedPoint s = detail::snap(w.x, w.y);
  w.sx = std::int32_t(s.x);
  w.sy = std::int32_t(s.y);
  return w;
}

// Whether the clipper would cut the triangle to nothing without making a vertex: some plane
// has every vertex outside it, and no earlier plane has any vertex outside.
bool trivially_outside(std::uint32_t all, std::uint32_t any) {
  return all != 0 && std::countr_zero(unsigned(all)) <= std::countr_zero(unsigned(any));
}

void setup_clipped(const DrawJob& job, SetupChunk& chunk, const Triangle& tri) {
  RenderStats& stats = chunk.stats;
  const VaryingLayout& l = job.plan.layout;
  chunk.poly.resize(3);
  for (int k = 0; k < 3; ++k) {
    ClipVertex& cv = chunk.poly[std::size_t(k)];
    cv.clip = job.projection * job.in->positions[tri[k]];
    expand_varyings(l, &job.varyings[std::size_t(tri[k]) * l.count], cv.attr);
  }
  const std::span<const glm::vec4> user(job.plan.user_planes.data(), std::size_t(job.plan.user_plane_count));
  if (detail::clip_polygon(chunk.poly, chunk.scratch, user)) ++stats.triangles_clipped;
  std::size_t n = chunk.poly.size();
  if (n == 0) return;
  std::size_t base = chunk.clip_vertices.size();
  for (const ClipVertex& cv : chunk.poly) {
    chunk.clip_vertices.push_back(raster_vertex(cv, job.viewport));
    chunk.clip_varyings.resize(chunk.clip_varyings.size() + std::size_t(l.count));
    compact_varyings(l, cv.attr, &chunk.clip_varyings[chunk.clip_varyings.size() - l.count]);
  }
  const RasterVertex* win[16];
  for (std::size_t i = 0; i < n; ++i) win[i] = &chunk.clip_vertices[base + i];
  bool front = false;
  if (!keep(job, signed_area(win, n), front, stats)) return;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    std::uint32_t index = std::uint32_t(chunk.clipped.size());
    chunk.clipped.push_back({{std::uint32_t(base), std::uint32_t(base + i), std::uint32_t(base + i + 1)}, tri[2]});
    std::uint32_t entry = index | kBinClipped | (front ? kBinFront : 0);
    bin_triangle(job, chunk, *win[0], *win[i], *win[i + 1], entry);
  }
}

}  // namespace

void reset_chunk(SetupChunk& chunk, std::size_t tiles) {
  if (chunk.bins.size() != tiles) chunk.bins.resize(tiles);
  for (auto& bin : chunk.bins) bin.clear();
  chunk.clip_vertices.clear();
  chunk.clip_varyings.clear();
  chunk.clipped.clear();
  chunk.coverage.clear();
  chunk.boxes.clear();
  chunk.box_varyings.clear();
  chunk.stats = RenderStats{};
}

void setup_range(const DrawJob& job, SetupChunk& chunk, std::size_t begin, std::size_t end) {
  const std::size_t n = job.vertices.size();
  RenderStats& stats = chunk.stats;
  for (std::size_t t = begin; t < end; ++t) {
    ++stats.triangles_in;
    const Triangle& tri = job.triangles[t];
    if (tri[0] >= n || tri[1] >= n || tri[2] >= n) continue;
    std::uint32_t oa = job.outcodes[tri[0]], ob = job.outcodes[tri[1]], oc = job.outcodes[tri[2]];
    if (!job.user_outcodes.empty()) {  // user clip planes: bits 7 and up, clip.cpp's order
      oa |= std::uint32_t(job.user_outcodes[tri[0]]) << 7;
      ob |= std::uint32_t(job.user_outcodes[tri[1]]) << 7;
      oc |= std::uint32_t(job.user_outcodes[tri[2]]) << 7;
    }
    if ((oa | ob | oc) != 0) {
      if (trivially_outside(oa & ob & oc, oa | ob | oc)) ++stats.triangles_clipped;
      else setup_clipped(job, chunk, tri);
      continue;
    }
    const RasterVertex &a = job.vertices[tri[0]], &b = job.vertices[tri[1]], &c = job.vertices[tri[2]];
    bool front = false;
    if (!keep(job, triangle_area(a, b, c), front, stats)) continue;
    bin_triangle(job, chunk, a, b, c, std::uint32_t(t) | (front ? kBinFront : 0));
  }
}

}  // namespace shadelab::fast
