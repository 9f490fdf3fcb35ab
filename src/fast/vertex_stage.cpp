// The fast vertex stage: per-vertex lighting (SIMD over vertices, structure of arrays),
// projection, clip outcodes, the viewport transform and snapping, with the reference's float
// and double operations in the reference's order. Compiled once per SIMD target (Highway).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fast/vertex_stage.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include <cmath>
#include <cstring>

#include "fast/lighting-inl.h"
#include "fast/plan.hpp"
#include "fast/vertex_stage.hpp"
#include "hwy/highway.h"
#include "shadelab/lighting.hpp"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

namespace {

constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(float);

// One batch of vertices in structure-of-arrays form.
struct Batch {
  alignas(64) float x[kMaxLanes], y[kMaxLanes], z[kMaxLanes], w[kMaxLanes];
  alignas(64) float nx[kMaxLanes], ny[kMaxLanes], nz[kMaxLanes];
  alignas(64) float out[7][kMaxLanes];  // lit r, g, b and secondary r, g, b (scratch)
  std::size_t first = 0, count = 0;
};

void gather(const VertexInput& in, std::size_t first, std::size_t count, std::size_t lanes,
            Batch& b) {
  b.first = first;
  b.count = count;
  for (std::size_t j = 0; j < lanes; ++j) {
    std::size_t i = first + (j < count ? j : count - 1);  // pad with the last vertex
    const glm::vec4& p = in.positions[i];
    b.x[j] = p.x;
    b.y[j] = p.y;
    b.z[j] = p.z;
    b.w[j] = p.w;
    glm::vec3 n = in.normals.empty() ? glm::vec3(0, 0, 1) : in.normals[i];
    b.nx[j] = n.x;
    b.ny[j] = n.y;
    b.nz[j] = n.z;
  }
}

// Lights the batch with one material into the colour slots at `color` / `secondary`.
void light_batch(DrawJob& job, Batch& b, const MaterialParams& m, bool back, int color,
                 int secondary) {
  using D = hn::ScalableTag<float>;
  const D d;
  const std::size_t lanes = hn::Lanes(d);
  auto sign = [&](const float* v) { return back ? hn::Neg(hn::Load(d, v)) : hn::Load(d, v); };
  LitIn<D> in{{hn::Load(d, b.x), hn::Load(d, b.y), hn::Load(d, b.z)},
                        {sign(b.nx), sign(b.ny), sign(b.nz)}};
  LitOut<D> out = light_lanes<Form::kReference>(d, job.plan.lighting, m, in);
  hn::Store(out.primary.x, d, b.out[0]);
  hn::Store(out.primary.y, d, b.out[1]);
  hn::Store(out.primary.z, d, b.out[2]);
  hn::Store(out.secondary.x, d, b.out[3]);
  hn::Store(out.secondary.y, d, b.out[4]);
  hn::Store(out.secondary.z, d, b.out[5]);
  const int stride = job.plan.layout.count;
  for (std::size_t j = 0; j < b.count && j < lanes; ++j) {
    float* v = &job.varyings[(b.first + j) * stride];
    float* c = v + color;
    c[0] = b.out[0][j];
    c[1] = b.out[1][j];
    c[2] = b.out[2][j];
    c[3] = m.alpha;
    if (secondary >= 0) {
      for (int k = 0; k < 3; ++k) v[secondary + k] = b.out[3 + k][j];
    }
  }
}

// clip.cpp's plane_distance(c, plane) >= 0 for the seven planes, in double as there; bit k
// of a lane's code is set when the vertex is outside plane k.
template <class DD, class VD>
HWY_INLINE void outcodes(DD dd, VD x, VD y, VD z, VD w, std::uint32_t* codes) {
  auto zero = hn::Zero(dd);
  std::uint8_t bits[7];
  hn::StoreMaskBits(dd, hn::Ge(hn::Add(w, x), zero), &bits[0]);
  hn::StoreMaskBits(dd, hn::Ge(hn::Sub(w, x), zero), &bits[1]);
  hn::StoreMaskBits(dd, hn::Ge(hn::Add(w, y), zero), &bits[2]);
  hn::StoreMaskBits(dd, hn::Ge(hn::Sub(w, y), zero), &bits[3]);
  hn::StoreMaskBits(dd, hn::Ge(hn::Add(w, z), zero), &bits[4]);
  hn::StoreMaskBits(dd, hn::Ge(hn::Sub(w, z), zero), &bits[5]);
  hn::StoreMaskBits(dd, hn::Ge(hn::Sub(w, hn::Set(dd, double(kMinClipW))), zero), &bits[6]);
  const std::uint8_t all = std::uint8_t((1u << hn::Lanes(dd)) - 1u);
  if ((bits[0] & bits[1] & bits[2] & bits[3] & bits[4] & bits[5] & bits[6]) == all) {
    for (std::size_t j = 0; j < hn::Lanes(dd); ++j) codes[j] = 0;  // every lane inside every plane
    return;
  }
  for (std::size_t j = 0; j < hn::Lanes(dd); ++j) {
    std::uint32_t c = 0;
    for (int k = 0; k < 7; ++k) c |= ((~bits[k] >> j) & 1u) << k;
    codes[j] = c;
  }
}

// llround(v) for every lane: round half away from zero, exactly.
template <class DD, class VD>
HWY_INLINE VD round_half_away(DD dd, VD v) {
  VD a = hn::Abs(v);
  VD t = hn::Trunc(a);
  VD r = hn::Add(t, hn::IfThenElseZero(hn::Ge(hn::Sub(a, t), hn::Set(dd, 0.5)), hn::Set(dd, 1.0)));
  return hn::CopySign(r, v);
}

// Projection, outcodes, viewport transform and snapping for lanes [j, j + Lanes(dd)).
void transform_lanes(DrawJob& job, const Batch& b, std::size_t j) {
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const std::size_t lanes = hn::Lanes(dd);
  const glm::mat4& m = job.projection;
  auto x = hn::LoadU(df, b.x + j), y = hn::LoadU(df, b.y + j);
  auto z = hn::LoadU(df, b.z + j), w = hn::LoadU(df, b.w + j);
  // glm's mat4 * vec4: (m0 x + m1 y) + (m2 z + m3 w), column by column.
  auto row = [&](int r) {
    auto a0 = hn::Add(hn::Mul(hn::Set(df, m[0][r]), x), hn::Mul(hn::Set(df, m[1][r]), y));
    auto a1 = hn::Add(hn::Mul(hn::Set(df, m[2][r]), z), hn::Mul(hn::Set(df, m[3][r]), w));
    return hn::Add(a0, a1);
  };
  auto cx = row(0), cy = row(1), cz = row(2), cw = row(3);
  auto px = hn::PromoteTo(dd, cx), py = hn::PromoteTo(dd, cy);
  auto pz = hn::PromoteTo(dd, cz), pw = hn::PromoteTo(dd, cw);
  std::uint32_t codes[kMaxLanes];
  outcodes(dd, px, py, pz, pw, codes);
  // draw.cpp's to_window.
  const Viewport& vp = job.viewport;
  auto inv_w = hn::Div(hn::Set(df, 1.0f), cw);
  auto inv_wd = hn::PromoteTo(dd, inv_w);
  auto half = hn::Set(dd, 0.5), one = hn::Set(dd, 1.0);
  auto wx = hn::Add(hn::Mul(hn::Mul(hn::Add(hn::Mul(px, inv_wd), one), half), hn::Set(dd, double(vp.width))),
                    hn::Set(dd, double(vp.x)));
  auto wy = hn::Add(hn::Mul(hn::Mul(hn::Add(hn::Mul(py, inv_wd), one), half), hn::Set(dd, double(vp.height))),
                    hn::Set(dd, double(vp.y)));
  auto nz = hn::Mul(cz, inv_w);
  auto wz = hn::Add(hn::Mul(hn::Mul(nz, hn::Set(df, 0.5f)), hn::Set(df, vp.far_depth - vp.near_depth)),
                    hn::Set(df, 0.5f * (vp.far_depth + vp.near_depth)));
  auto sub = hn::Set(dd, double(detail::kSubpixelOne));
  alignas(64) double ox[kMaxLanes], oy[kMaxLanes], sx[kMaxLanes], sy[kMaxLanes];
  alignas(64) float oz[kMaxLanes], oiw[kMaxLanes];
  hn::Store(wx, dd, ox);
  hn::Store(wy, dd, oy);
  hn::Store(round_half_away(dd, hn::Mul(wx, sub)), dd, sx);
  hn::Store(round_half_away(dd, hn::Mul(wy, sub)), dd, sy);
  hn::StoreU(wz, df, oz);
  hn::StoreU(inv_w, df, oiw);
  for (std::size_t k = 0; k < lanes && j + k < b.count; ++k) {
    std::size_t i = b.first + j + k;
    RasterVertex& v = job.vertices[i];
    v.x = ox[k];
    v.y = oy[k];
    v.z = oz[k];
    v.inv_w = oiw[k];
    job.outcodes[i] = std::uint8_t(codes[k]);
    // Vertices outside the view volume are only used through the clipper.
    bool inside = codes[k] == 0;
    v.sx = inside ? std::int32_t(sx[k]) : 0;
    v.sy = inside ? std::int32_t(sy[k]) : 0;
  }
}

// draw.cpp's vertex_colors for one vertex with light_point (shadow maps, other materials).
void scalar_vertex_lighting(DrawJob& job, std::size_t i, WorkerScratch& ws) {
  const ShadeState& shade = *job.shade;
  const VertexInput& in = *job.in;
  const VaryingLayout& l = job.plan.layout;
  glm::vec3 pos(in.positions[i]);
  glm::vec3 n = in.normals.empty() ? glm::vec3(0, 0, 1) : in.normals[i];
  const float* vis = shadow_visibility(shade, pos, n, ws.visibility);
  LitColor f = light_point(shade.model, shade.lights, shade.front, {pos, n, vis});
  LitColor bk = shade.model.two_side ? light_point(shade.model, shade.lights, shade.back, {pos, -n, vis}) : f;
  float* v = &job.varyings[i * std::size_t(l.count)];
  std::memcpy(v + l.front_color, &f.primary, sizeof(float) * 4);
  std::memcpy(v + l.back_color, &bk.primary, sizeof(float) * 4);
  if (l.front_secondary >= 0) std::memcpy(v + l.front_secondary, &f.secondary, sizeof(float) * 3);
  if (l.back_secondary >= 0) std::memcpy(v + l.back_secondary, &bk.secondary, sizeof(float) * 3);
}

// The given colours (lighting off, or Phong's unused ones).
void given_colors(DrawJob& job, std::size_t i) {
  const VertexInput& in = *job.in;
  const VaryingLayout& l = job.plan.layout;
  float* v = &job.varyings[i * std::size_t(l.count)];
  glm::vec4 c = in.colors.empty() ? in.constant_color : in.colors[i];
  std::memcpy(v + l.front_color, &c, sizeof(float) * 4);
  if (l.back_color != l.front_color) std::memcpy(v + l.back_color, &in.back_colors[i], sizeof(float) * 4);
  if (l.front_secondary >= 0) std::memcpy(v + l.front_secondary, &in.secondary_colors[i], sizeof(float) * 3);
  if (l.back_secondary != l.front_secondary) {
    std::memcpy(v + l.back_secondary, &in.back_secondary_colors[i], sizeof(float) * 3);
  }
}

// Eye position (dehomogenized), normal, texture and fog coordinates for one vertex.
void other_varyings(DrawJob& job, std::size_t i) {
  const VertexInput& in = *job.in;
  const VaryingLayout& l = job.plan.layout;
  float* v = &job.varyings[i * std::size_t(l.count)];
  if (l.eye_position >= 0) {
    glm::vec4 p = in.positions[i];
    glm::vec3 e = p.w != 0.0f ? glm::vec3(p) / p.w : glm::vec3(p);
    std::memcpy(v + l.eye_position, &e, sizeof(float) * 3);
  }
  if (l.eye_normal >= 0) {
    glm::vec3 n = in.normals.empty() ? glm::vec3(0.0f) : in.normals[i];
    std::memcpy(v + l.eye_normal, &n, sizeof(float) * 3);
  }
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    if (l.texcoord[u] < 0) continue;
    const std::span<const glm::vec4> coords = in.texcoords[std::size_t(u)];
    const glm::vec4 t = coords.empty() ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : coords[i];
    std::memcpy(v + l.texcoord[u], &t, sizeof(float) * 4);
  }
  if (l.fog >= 0) v[l.fog] = detail::fog_coordinate(in, i);
}

// The user clip planes' outcode bits of vertices [first, first + count), from the reference's
// clip coordinates (draw.cpp's projection * position).
void user_outcodes(DrawJob& job, std::size_t first, std::size_t count) {
  const std::span<const glm::vec4> planes(job.plan.user_planes.data(), std::size_t(job.plan.user_plane_count));
  for (std::size_t i = first; i < first + count; ++i) {
    const glm::vec4 clip = job.projection * job.in->positions[i];
    job.user_outcodes[i] = std::uint8_t(detail::clip_outcode(clip, planes) >> 7);
  }
}

void colors(DrawJob& job, Batch& b, WorkerScratch& ws) {
  const DrawPlan& p = job.plan;
  const VaryingLayout& l = p.layout;
  if (l.front_color < 0) return;
  if (p.simd_vertex_lighting) {
    light_batch(job, b, p.lighting.front, false, l.front_color, l.front_secondary);
    if (p.two_side) light_batch(job, b, p.lighting.back, true, l.back_color, l.back_secondary);
    return;
  }
  for (std::size_t j = 0; j < b.count; ++j) {
    if (p.vertex_lighting) scalar_vertex_lighting(job, b.first + j, ws);
    else given_colors(job, b.first + j);
  }
}

}  // namespace

void VertexRange(DrawJob& job, std::size_t begin, std::size_t end, WorkerScratch& ws) {
  const std::size_t lanes = hn::Lanes(hn::ScalableTag<float>());
  const std::size_t dlanes = hn::Lanes(hn::ScalableTag<double>());
  Batch b;
  for (std::size_t first = begin; first < end; first += lanes) {
    std::size_t count = std::min(lanes, end - first);
    gather(*job.in, first, count, lanes, b);
    colors(job, b, ws);
    for (std::size_t j = 0; j < count; j += dlanes) transform_lanes(job, b, j);
    for (std::size_t j = 0; j < count; ++j) other_varyings(job, first + j);
    if (job.plan.user_plane_count) user_outcodes(job, first, count);
  }
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace shadelab::fast {

HWY_EXPORT(VertexRange);

void run_vertex_range(DrawJob& job, std::size_t begin, std::size_t end, WorkerScratch& ws) {
  HWY_DYNAMIC_DISPATCH(VertexRange)(job, begin, end, ws);
}

}  // namespace shadelab::fast
#endif
