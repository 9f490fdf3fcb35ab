// The reference pipeline's lines, points and unfilled polygons: primitive assembly
// (raster/prims.cpp) hands it pieces, each rasterized as one or two triangles (an aliased
// line's as one parallelogram) by the reference rasterizer, their fragments through the same
// per-fragment path as the triangles'.
#include <algorithm>

#include "pipeline/reference_draw.hpp"

namespace shadelab::detail {

namespace {

class ReferenceSink final : public PieceSink {
 public:
  explicit ReferenceSink(const ReferenceDraw& ctx) : ctx_(ctx) {}

  void piece(const Piece& p) override {
    Framebuffer& fb = *ctx_.fb;
    WindowVertex w[4];
    for (int k = 0; k < 4; ++k) {
      const PieceCorner& c = p.corner[k];
      w[k] = {c.x, c.y, c.z, c.inv_w, &c.attr};
    }
    const Coverage* coverage = p.coverage.kind == Coverage::Kind::kNone ? nullptr : &p.coverage;
    const auto emit = [&](const Fragment& f) { reference_fragment(ctx_, f, p.front, 0.0f, coverage, p.polygon); };
    if (p.parallelogram) {
      rasterize_parallelogram(w[0], w[1], w[2], w[3], fb.width, fb.height, textured_units(*ctx_.shade), emit);
      return;
    }
    for (int t = 0; t < p.triangles; ++t) {
      const WindowVertex &a = w[p.tri[t][0]], &b = w[p.tri[t][1]], &c = w[p.tri[t][2]];
      const float offset = p.offset ? polygon_offset(a, b, c, *ctx_.fragment) : 0.0f;
      rasterize_triangle(a, b, c, fb.width, fb.height, textured_units(*ctx_.shade),
                         [&](const Fragment& f) { reference_fragment(ctx_, f, p.front, offset, coverage, p.polygon); });
    }
  }

 private:
  const ReferenceDraw& ctx_;
};

// Vertex i: its clip coordinates and attributes from the vertex stage, its eye-space z.
PrimVertex prim_vertex(const PrimAssembler& assembler, const VertexInput& in, const std::vector<ClipVertex>& verts,
                       std::uint32_t i) {
  PrimVertex p = assembler.make_vertex(verts[i].clip, in.positions[i].z);
  p.attr = verts[i].attr;
  return p;
}

}  // namespace

void draw_prims_reference(const ReferenceDraw& ctx, const glm::mat4& projection, const VertexInput& in,
                          const std::vector<ClipVertex>& verts) {
  const FragmentState& f = *ctx.fragment;
  const bool unfilled = PrimAssembler::unfilled(f) || f.observer;
  if (!unfilled && in.lines.empty() && in.points.empty()) return;
  const bool flat = ctx.shade->shading == ShadingMode::kFlat;
  PrimAssembler assembler(f, *ctx.viewport, projection, ctx.fb->height, flat,
                          in.stipple_counter ? *in.stipple_counter : 0u);
  ReferenceSink sink(ctx);
  const std::size_t n = verts.size();
  if (unfilled) {
    for (std::size_t i = 0; i < in.triangles.size(); ++i) {
      const Triangle& t = in.triangles[i];
      ++ctx.stats->triangles_in;
      if (t[0] >= n || t[1] >= n || t[2] >= n) continue;
      const PrimVertex v[3] = {prim_vertex(assembler, in, verts, t[0]), prim_vertex(assembler, in, verts, t[1]),
                               prim_vertex(assembler, in, verts, t[2])};
      const std::uint8_t flags = i < in.triangle_flags.size() ? in.triangle_flags[i]
                                                              : std::uint8_t(kTriangleEdges | kTriangleRestartStipple);
      assembler.triangle(v, flags, t[2], sink);
    }
  }
  for (const LineSegment& l : in.lines) {
    if (l.v[0] >= n || l.v[1] >= n) continue;
    assembler.line(prim_vertex(assembler, in, verts, l.v[0]), prim_vertex(assembler, in, verts, l.v[1]), l.flags,
                   l.v[1], sink);
  }
  for (std::uint32_t i : in.points) {
    if (i < n) assembler.point(prim_vertex(assembler, in, verts, i), i, sink);
  }
  if (in.stipple_counter) *in.stipple_counter = assembler.stipple_counter();
}

}  // namespace shadelab::detail
