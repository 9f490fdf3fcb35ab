// Per-tile triangle setup (the reference rasterizer's orientation, fill rule and pixel box)
// and the per-fragment reference path, which reproduces reference_raster.inl's fragment and
// draw.cpp's fragment handling exactly.
#include "fast/triangle.hpp"

#include <algorithm>
#include <atomic>

#include "pipeline/fragment_ops.hpp"

namespace shadelab::fast {

namespace {

detail::WindowVertex window_vertex(const RasterVertex& v, const detail::Attribs* attr) {
  return {v.x, v.y, v.z, v.inv_w, attr};
}

// The triangle's vertices and varyings; for a clipped triangle or a piece, whether the fill
// offset applies and its coverage.
void resolve(const DrawJob& job, int chunk, std::uint32_t entry, const RasterVertex* v[3],
             const float* var[3], TriSetup& t, bool& offset) {
  const std::size_t stride = std::size_t(job.plan.layout.count);
  std::uint32_t index = entry & kBinIndexMask;
  t.coverage = nullptr;
  t.polygon = true;
  offset = true;
  if (entry & kBinClipped) {
    const SetupChunk& ch = job.chunks[std::size_t(chunk)];
    const ClippedTriangle& ct = ch.clipped[index];
    #pragma GCC unroll 3
    for (int k = 0; k < 3; ++k) {
      v[k] = &ch.clip_vertices[ct.v[k]];
      var[k] = &ch.clip_varyings[ct.v[k] * stride];
    }
    t.provoking_index = ct.provoking;
    if (ct.coverage != ClippedTriangle::kNoCoverage) t.coverage = &ch.coverage[ct.coverage];
    offset = ct.offset;
    t.polygon = ct.polygon;
    t.parallelogram = ct.parallelogram;
    return;
  }
  t.parallelogram = false;
  const Triangle& tri = job.triangles[index];
  #pragma GCC unroll 3
  for (int k = 0; k < 3; ++k) {
    v[k] = &job.vertices[tri[k]];
    var[k] = &job.varyings[tri[k] * stride];
  }
  t.provoking_index = tri[2];
}

// The pixels whose centres lie in the box of the triangle (and of `fourth`, a parallelogram's
// fourth corner, when given), cut to the tile and to the draw's pixel box (the framebuffer
// and the scissor box).
bool pixel_box(const DrawJob& job, int tx, int ty, TriSetup& t, const detail::FixedPoint* fourth) {
  std::int64_t min_x = std::min({t.v[0]->sx, t.v[1]->sx, t.v[2]->sx});
  std::int64_t max_x = std::max({t.v[0]->sx, t.v[1]->sx, t.v[2]->sx});
  std::int64_t min_y = std::min({t.v[0]->sy, t.v[1]->sy, t.v[2]->sy});
  std::int64_t max_y = std::max({t.v[0]->sy, t.v[1]->sy, t.v[2]->sy});
  if (fourth) {
    min_x = std::min(min_x, fourth->x), max_x = std::max(max_x, fourth->x);
    min_y = std::min(min_y, fourth->y), max_y = std::max(max_y, fourth->y);
  }
  const DrawPlan& p = job.plan;
  t.x0 = std::max({tx, p.box_x0, first_centre(min_x)});
  t.x1 = std::min({p.box_x1, tx + kTileSize - 1, last_centre(max_x)});
  t.y0 = std::max({ty, p.box_y0, first_centre(min_y)});
  t.y1 = std::min({p.box_y1, ty + kTileSize - 1, last_centre(max_y)});
  return t.x0 <= t.x1 && t.y0 <= t.y1;
}

// A point's box as a TriSetup whose three vertices are the point: weights zero, the depth
// plane and every varying's plane flat at the point's values (what the piece's triangle
// gives each of its fragments: a + 0 (a - a) + 0 (a - a)).
bool setup_box(const DrawJob& job, int chunk, std::uint32_t entry, int tx, int ty, TriSetup& t) {
  const SetupChunk& ch = job.chunks[std::size_t(chunk)];
  const std::uint32_t index = entry & kBinIndexMask;
  const PointBox& b = ch.boxes[index];
  t.x0 = std::max(tx, b.box.x0), t.x1 = std::min(tx + kTileSize - 1, b.box.x1);
  t.y0 = std::max(ty, b.box.y0), t.y1 = std::min(ty + kTileSize - 1, b.box.y1);
  if (t.x0 > t.x1 || t.y0 > t.y1) return false;
  const float* var = &ch.box_varyings[std::size_t(index) * std::size_t(job.plan.layout.count)];
  t.box_at = {0.0, 0.0, 0, 0, b.z, b.inv_w};
  #pragma GCC unroll 3
  for (int k = 0; k < 3; ++k) {
    t.v[k] = &t.box_at, t.var[k] = var;
    t.dx[k] = t.dy[k] = t.ox[k] = t.oy[k] = 0;
    t.threshold[k] = 0.0;
  }
  t.flat = var;  // the colours' planes flat at the point's (set_up's a2, a0 - a2, a1 - a2 are a, 0, 0)
  t.front = true;
  t.area = 1;
  t.inv_area = 1.0;
  t.affine = true;
  t.depth = detail::depth_plane(b.z, b.z, b.z);
  t.offset = 0.0f;
  t.coverage = nullptr;
  t.polygon = false;
  t.parallelogram = false;
  t.provoking_index = b.vertex;
  t.box = true;
  return true;
}

}  // namespace

bool setup_triangle(const DrawJob& job, int chunk, std::uint32_t entry, int tx, int ty,
                    TriSetup& t) {
  const RasterVertex* v[3];
  const float* var[3];
  bool offset;
  if (entry & kBinBox) return setup_box(job, chunk, entry, tx, ty, t);
  t.box = false;
  resolve(job, chunk, entry, v, var, t, offset);
  const RasterVertex &a = *v[0], &b = *v[1], &c = *v[2];
  std::int64_t area = (std::int64_t(b.sx) - a.sx) * (std::int64_t(c.sy) - a.sy) -
                      (std::int64_t(b.sy) - a.sy) * (std::int64_t(c.sx) - a.sx);
  if (area == 0) return false;
  int i1 = area > 0 ? 1 : 2, i2 = area > 0 ? 2 : 1;  // counter-clockwise, as the reference
  t.v[0] = v[0], t.v[1] = v[i1], t.v[2] = v[i2];
  t.var[0] = var[0], t.var[1] = var[i1], t.var[2] = var[i2];
  t.area = area > 0 ? area : -area;
  t.inv_area = 1.0 / double(t.area);
  t.affine = t.v[0]->inv_w == t.v[1]->inv_w && t.v[1]->inv_w == t.v[2]->inv_w;
  // A parallelogram's fourth corner, opposite v[1]; turned clockwise, it covers nothing
  // (reference_raster.inl's rasterize_parallelogram).
  detail::FixedPoint fourth{};
  if (t.parallelogram) {
    if (area < 0) return false;
    fourth = {std::int64_t(a.sx) + c.sx - b.sx, std::int64_t(a.sy) + c.sy - b.sy};
  }
  if (!pixel_box(job, tx, ty, t, t.parallelogram ? &fourth : nullptr)) return false;
  t.depth = detail::depth_plane(t.v[0]->z, t.v[1]->z, t.v[2]->z);
  #pragma GCC unroll 3
  for (int e = 0; e < 3; ++e) {
    const RasterVertex &p = *t.v[kEdgeFrom[e]], &q = *t.v[kEdgeTo[e]];
    t.ox[e] = p.sx, t.oy[e] = p.sy;
    t.dx[e] = std::int64_t(q.sx) - p.sx;
    t.dy[e] = std::int64_t(q.sy) - p.sy;
    t.threshold[e] = detail::owns_edge({p.sx, p.sy}, {q.sx, q.sy}) ? 0.0 : 1.0;
  }
  if (t.parallelogram) {
    // Side c -> d is edge 2 (a -> b) turned round: its value area - e2 (and d -> a's area -
    // e0), covered where that is at least its own threshold.
    const detail::FixedPoint pa{a.sx, a.sy}, pc{c.sx, c.sy};
    t.threshold[1] = -0x1p62;
    t.upper[0] = double(t.area) - (detail::owns_edge(fourth, pa) ? 0.0 : 1.0);
    t.upper[1] = 0x1p62;
    t.upper[2] = double(t.area) - (detail::owns_edge(pc, fourth) ? 0.0 : 1.0);
  }
  t.front = (entry & kBinFront) != 0;
  const std::size_t stride = std::size_t(job.plan.layout.count);
  t.flat = job.plan.flat ? &job.varyings[t.provoking_index * stride] : nullptr;
  t.offset = 0.0f;
  if (job.frag->polygon_offset && offset) {  // from the fan's vertex order, as draw.cpp
    t.offset = detail::polygon_offset(window_vertex(a, nullptr), window_vertex(b, nullptr),
                                      window_vertex(c, nullptr), *job.frag);
  }
  return true;
}

void prefetch_setup(const DrawJob& job, int chunk, std::uint32_t entry, bool vertices) {
  const std::size_t stride = std::size_t(job.plan.layout.count);
  const std::uint32_t index = entry & kBinIndexMask;
  if (entry & kBinBox) {  // the record and its varyings, with no load to wait for
    const SetupChunk& ch = job.chunks[std::size_t(chunk)];
    if (vertices) return;
    __builtin_prefetch(&ch.boxes[index]);
    if (stride) __builtin_prefetch(&ch.box_varyings[index * stride]);
    return;
  }
  if (entry & kBinClipped) {
    const SetupChunk& ch = job.chunks[std::size_t(chunk)];
    if (!vertices) return __builtin_prefetch(&ch.clipped[index]);
    const ClippedTriangle& ct = ch.clipped[index];
    for (int k = 0; k < 3; ++k) {
      __builtin_prefetch(&ch.clip_vertices[ct.v[k]]);
      if (stride) __builtin_prefetch(&ch.clip_varyings[ct.v[k] * stride]);
    }
    return;
  }
  if (!vertices) return __builtin_prefetch(&job.triangles[index]);
  const Triangle& tri = job.triangles[index];
  for (int k = 0; k < 3; ++k) {
    __builtin_prefetch(&job.vertices[tri[k]]);
    if (stride) __builtin_prefetch(&job.varyings[tri[k] * stride]);
  }
}

void expand_triangle(const DrawJob& job, const TriSetup& t, WorkerScratch& ws) {
  const VaryingLayout& l = job.plan.layout;
  for (int k = 0; k < 3; ++k) expand_varyings(l, t.var[k], ws.attribs[k]);
  if (!t.flat) return;
  detail::Attribs provoking;
  expand_varyings(l, t.flat, provoking);
  for (detail::Attribs& a : ws.attribs) {
    for (int i = detail::kFrontColor; i < detail::kEyePosition; ++i) a[i] = provoking[i];
  }
}

namespace {

// reference_raster.inl's fragment at pixel (x, y): perspective-correct attributes in double.
detail::Fragment reference_fragment(const DrawJob& job, const TriSetup& t, WorkerScratch& ws,
                                    int x, int y, double w0, double w1, float z) {
  detail::WindowVertex wv[3];
  const detail::WindowVertex* v[3];
  for (int k = 0; k < 3; ++k) {
    wv[k] = window_vertex(*t.v[k], &ws.attribs[k]);
    v[k] = &wv[k];
  }
  detail::Fragment frag;
  frag.x = x;
  frag.y = y;
  frag.z = z;
  double b0 = w0 * t.inv_area, b1 = w1 * t.inv_area;
  double b2 = 1.0 - b0 - b1;
  double q0 = b0, q1 = b1, q2 = b2;
  if (!t.affine) {
    q0 = b0 * v[0]->inv_w, q1 = b1 * v[1]->inv_w, q2 = b2 * v[2]->inv_w;
    double inv = 1.0 / (q0 + q1 + q2);
    q0 *= inv;
    q1 *= inv;
    q2 *= inv;
  }
  for (int i = 0; i < detail::kAttrCount; ++i) {
    frag.attr[i] = static_cast<float>(q0 * (*v[0]->attr)[i] + q1 * (*v[1]->attr)[i] +
                                      q2 * (*v[2]->attr)[i]);
  }
  if (job.plan.textured) {
    const detail::FloatWeights tw = detail::texcoord_weights(v, w0, w1, t.inv_area, t.affine);
    detail::FixedPoint p[3];
    for (int k = 0; k < 3; ++k) p[k] = {t.v[k]->sx, t.v[k]->sy};
    for (int u = 0; u < kMaxTextureUnits; ++u) {
      if (!job.plan.texture[u].texture) continue;
      const int first = detail::kTexCoord + 4 * u;
      detail::fragment_texcoords(v, tw, first, frag);
      frag.texture_derivatives[std::size_t(u)] = detail::texture_derivatives(v, p, x, y, job.fb->height, first);
    }
  }
  return frag;
}

// draw.cpp's capture branch; the counters are shared by every tile's thread.
void capture(FragmentCapture& cap, std::size_t px, float z, const glm::vec4& color,
             const BlendState& blend, RenderStats& stats) {
  std::atomic_ref<std::size_t> count(cap.count);
  if (count.fetch_add(1) >= cap.limit) {
    count.fetch_sub(1);
    std::atomic_ref<std::size_t>(cap.dropped).fetch_add(1);
    return;
  }
  cap.pixels[px].push_back({z, color, blend});
  ++stats.pixels_shaded;
}

}  // namespace

void scalar_fragment(const DrawJob& job, const TriSetup& t, WorkerScratch& ws, int x, int y,
                     double w0, double w1, float z) {
  Framebuffer& fb = *job.fb;
  const FragmentState& frag = *job.frag;
  float factor = 1.0f;
  if (t.coverage) {  // draw_prims.cpp's smooth lines and points
    factor = detail::coverage_at(*t.coverage, x + 0.5, y + 0.5);
    if (factor < 0.0f) return;
  }
  std::size_t px = std::size_t(y) * std::size_t(fb.width) + std::size_t(x);
  ++ws.stats.fragments;
  ++ws.stats.fragments_reference;
  // draw.cpp's order: with the alpha test, the colour first (GL 1.1 section 4.1.3).
  glm::vec4 color;
  if (job.plan.alpha_test) {
    color = detail::shade_fragment(*job.shade, reference_fragment(job, t, ws, x, y, w0, w1, z), t.front);
    color.a *= factor;
    if (!detail::alpha_test(frag.alpha_test, color.a)) return;
  }
  if (!detail::depth_stencil_test(fb, px, z, frag)) return;
  if (!job.plan.writes_color) {
    ++ws.stats.pixels_shaded;
    return;
  }
  if (!job.plan.alpha_test) {
    color = detail::shade_fragment(*job.shade, reference_fragment(job, t, ws, x, y, w0, w1, z), t.front);
    color.a *= factor;
  }
  if (frag.capture) return capture(*frag.capture, px, z, color, frag.blend, ws.stats);
  detail::write_color(fb, px, color, frag);
  ++ws.stats.pixels_shaded;
}

}  // namespace shadelab::fast
