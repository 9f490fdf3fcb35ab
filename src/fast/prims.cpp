// Lines, points and unfilled polygons on the fast pipeline: each vertex's clip coordinates
// (the reference's projection) and its varyings expanded into the reference's attributes, the
// reference's primitive assembly, and each piece it makes stored in the setup chunk as clipped
// triangles are (window vertices, compact varyings) and binned (an aliased line's
// parallelogram as one entry); aliased points, whose fragments all take the point's values,
// stored as boxes of pixels (PointBox) instead.
#include "fast/prims.hpp"

#include <algorithm>
#include <cmath>

#include "fast/setup.hpp"

namespace shadelab::fast {

namespace {

using detail::Piece;
using detail::PrimAssembler;
using detail::PrimVertex;

// Corner k of a piece as a window vertex. An aliased line's corners lie on the 1/256-pixel
// grid already (line_quad): their snap is exact.
RasterVertex raster_corner(const Piece& p, int k) {
  const detail::PieceCorner& c = p.corner[k];
  RasterVertex r;
  r.x = c.x;
  r.y = c.y;
  if (p.parallelogram) {
    r.sx = std::int32_t(c.x * double(detail::kSubpixelOne));
    r.sy = std::int32_t(c.y * double(detail::kSubpixelOne));
  } else {
    const detail::FixedPoint s = detail::snap(c.x, c.y);
    r.sx = std::int32_t(s.x);
    r.sy = std::int32_t(s.y);
  }
  r.z = c.z;
  r.inv_w = c.inv_w;
  return r;
}

class ChunkSink final : public detail::PieceSink {
 public:
  ChunkSink(const DrawJob& job, SetupChunk& chunk) : job_(job), chunk_(chunk) {}

  void piece(const Piece& p) override {
    const VaryingLayout& l = job_.plan.layout;
    const std::size_t base = chunk_.clip_vertices.size(), stride = std::size_t(l.count);
    // A parallelogram's fourth corner follows from the other three: it is binned, not stored.
    const int corners = p.parallelogram || p.triangles == 1 ? 3 : 4;
    chunk_.clip_varyings.resize(chunk_.clip_varyings.size() + std::size_t(corners) * stride);
    float* var = chunk_.clip_varyings.data() + base * stride;
    for (int k = 0; k < corners; ++k, var += stride) {
      chunk_.clip_vertices.push_back(raster_corner(p, k));
      compact_varyings(l, p.corner[k].attr, var);
    }
    std::uint32_t coverage = ClippedTriangle::kNoCoverage;
    if (p.coverage.kind != detail::Coverage::Kind::kNone) {
      coverage = std::uint32_t(chunk_.coverage.size());
      chunk_.coverage.push_back(p.coverage);
    }
    if (p.parallelogram) {  // one entry, one plane
      ClippedTriangle ct;
      for (int k = 0; k < 3; ++k) ct.v[k] = std::uint32_t(base + std::size_t(k));
      ct.provoking = p.provoking;
      ct.coverage = coverage;
      ct.offset = false;
      ct.polygon = false;
      ct.parallelogram = true;
      const std::uint32_t entry = std::uint32_t(chunk_.clipped.size()) | kBinClipped | (p.front ? kBinFront : 0);
      chunk_.clipped.push_back(ct);
      const RasterVertex* c = &chunk_.clip_vertices[base];
      bin_parallelogram(job_, chunk_, c[0], c[1], c[2], raster_corner(p, 3), entry);
      return;
    }
    for (int t = 0; t < p.triangles; ++t) {
      ClippedTriangle ct;
      for (int k = 0; k < 3; ++k) ct.v[k] = std::uint32_t(base + p.tri[t][k]);
      ct.provoking = p.provoking;
      ct.coverage = coverage;
      ct.offset = p.offset;
      ct.polygon = p.polygon;
      const std::uint32_t index = std::uint32_t(chunk_.clipped.size());
      chunk_.clipped.push_back(ct);
      const std::uint32_t entry = index | kBinClipped | (p.front ? kBinFront : 0);
      bin_triangle(job_, chunk_, chunk_.clip_vertices[ct.v[0]], chunk_.clip_vertices[ct.v[1]],
                   chunk_.clip_vertices[ct.v[2]], entry);
    }
  }

 private:
  const DrawJob& job_;
  SetupChunk& chunk_;
};

// Vertex i as the reference's vertex stage makes it: clip coordinates, window position and
// the attributes the draw carries.
PrimVertex prim_vertex(const DrawJob& job, const PrimAssembler& assembler, std::uint32_t i) {
  PrimVertex v = assembler.make_vertex(job.projection * job.in->positions[i], job.in->positions[i].z);
  const VaryingLayout& l = job.plan.layout;
  expand_varyings(l, &job.varyings[std::size_t(i) * std::size_t(l.count)], v.attr);
  return v;
}

// Whether a vertex's varyings are all finite: a point drawn as a box takes them as they are,
// where the piece's triangle weighs them (0 times an infinity is not a number).
bool finite_varyings(const DrawJob& job, std::uint32_t i) {
  const std::size_t stride = std::size_t(job.plan.layout.count);
  const float* v = &job.varyings[std::size_t(i) * stride];
  bool finite = true;
  for (std::size_t k = 0; k < stride; ++k) finite = finite && std::isfinite(v[k]);
  return finite;
}

// Point i of a draw with plain points as a box (PointBox), its pixels cut to the draw's pixel
// box, binned into the tiles it covers.
void box_point(const DrawJob& job, PrimAssembler& assembler, SetupChunk& chunk, std::uint32_t i) {
  const glm::vec4& position = job.in->positions[i];
  detail::PointPixels px;
  if (!assembler.point_pixels(job.projection * position, position.z, px)) return;
  const DrawPlan& p = job.plan;
  detail::PixelBox& b = px.box;
  b.x0 = std::max(b.x0, p.box_x0), b.x1 = std::min(b.x1, p.box_x1);
  b.y0 = std::max(b.y0, p.box_y0), b.y1 = std::min(b.y1, p.box_y1);
  if (b.x0 > b.x1 || b.y0 > b.y1) return;
  const PointBox box{b, px.z, px.inv_w, i};
  const std::uint32_t entry = std::uint32_t(chunk.boxes.size()) | kBinBox;
  chunk.boxes.push_back(box);
  // Its varyings beside the others' (box_varyings): a tile reads its boxes' in the order it
  // reads the boxes, without first reading which vertex each is.
  const std::size_t stride = std::size_t(job.plan.layout.count);
  const float* var = &job.varyings[std::size_t(i) * stride];
  chunk.box_varyings.insert(chunk.box_varyings.end(), var, var + stride);
  for (int ty = b.y0 >> kTileShift; ty <= b.y1 >> kTileShift; ++ty) {
    for (int tx = b.x0 >> kTileShift; tx <= b.x1 >> kTileShift; ++tx) {
      chunk.bins[std::size_t(ty) * std::size_t(job.tiles_x) + std::size_t(tx)].push_back(entry);
    }
  }
}

}  // namespace

std::size_t setup_items(const VertexInput& in) { return in.triangles.size() + in.lines.size() + in.points.size(); }

bool sequential_setup(const DrawJob& job) {
  const FragmentState& f = *job.frag;
  const bool line_edges = f.front_mode == PolygonMode::kLine || f.back_mode == PolygonMode::kLine;
  return f.line.stipple && (!job.in->lines.empty() || (line_edges && !job.triangles.empty()));
}

void setup_prims(const DrawJob& job, SetupChunk& chunk, std::size_t begin, std::size_t end, std::uint32_t& stipple) {
  const VertexInput& in = *job.in;
  const std::size_t n = job.vertices.size(), triangles = job.triangles.size(), lines = in.lines.size();
  const bool unfilled = PrimAssembler::unfilled(*job.frag);
  if (!unfilled) begin = std::max(begin, triangles);
  if (begin >= end) return;
  PrimAssembler assembler(*job.frag, job.viewport, job.projection, job.fb_height, job.plan.flat, stipple);
  assembler.interpolate_only(attribute_slots(job.plan.layout));  // compact_varyings reads no other
  ChunkSink sink(job, chunk);
  // Plain points as boxes, on the SIMD path (the reference's per-fragment path weighs the
  // piece's corners).
  const bool boxes = assembler.plain_points() && !job.plan.scalar_fragments && !job.plan.coverage;
  for (std::size_t item = begin; item < end; ++item) {
    if (item < triangles) {
      ++chunk.stats.triangles_in;
      const Triangle& t = job.triangles[item];
      if (t[0] >= n || t[1] >= n || t[2] >= n) continue;
      const PrimVertex v[3] = {prim_vertex(job, assembler, t[0]), prim_vertex(job, assembler, t[1]),
                               prim_vertex(job, assembler, t[2])};
      const std::uint8_t flags = item < in.triangle_flags.size()
                                     ? in.triangle_flags[item]
                                     : std::uint8_t(kTriangleEdges | kTriangleRestartStipple);
      assembler.triangle(v, flags, t[2], sink);
    } else if (item < triangles + lines) {
      const LineSegment& s = in.lines[item - triangles];
      if (s.v[0] >= n || s.v[1] >= n) continue;
      assembler.line(prim_vertex(job, assembler, s.v[0]), prim_vertex(job, assembler, s.v[1]), s.flags, s.v[1], sink);
    } else {
      const std::uint32_t i = in.points[item - triangles - lines];
      if (i >= n) continue;
      if (boxes && finite_varyings(job, i)) box_point(job, assembler, chunk, i);
      else assembler.point(prim_vertex(job, assembler, i), i, sink);
    }
  }
  stipple = assembler.stipple_counter();
}

}  // namespace shadelab::fast
