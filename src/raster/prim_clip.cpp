// Clipping of lines and of polygons drawn as lines or points, and llvmpipe's viewport
// transform (GL 1.1 sections 2.10.1, 2.11), in float as Mesa's draw module computes them:
// distances are dot products in float, a clipped end is interpolated in clip space from the
// vertex its interpolation starts at, then divided by w and mapped to the window again.
#include "raster/prim_clip.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace shadelab::detail {

namespace {

constexpr float kMinW = 1e-6f;  // clip.cpp's guard: w stays positive

bool not_finite(float v) { return !std::isfinite(v); }

// Mesa's LINTERP(t, out, in) = out + t (in - out), per component, for the clip position and
// every attribute; the window position follows from the new clip position.
void interpolate(PrimVertex& dst, float t, const PrimVertex& out, const PrimVertex& in, const Viewport& vp,
                 int fb_height) {
  for (int i = 0; i < 4; ++i) dst.clip[i] = out.clip[i] + t * (in.clip[i] - out.clip[i]);
  for (int i = 0; i < kAttrCount; ++i) dst.attr[i] = out.attr[i] + t * (in.attr[i] - out.attr[i]);
  dst.point_size = out.point_size + t * (in.point_size - out.point_size);
  to_down_window(dst, vp, fb_height, false);
}

}  // namespace

ClipSpace::ClipSpace(const ClipPlanes& user, const glm::mat4& projection) {
  plane[0] = {-1, 0, 0, 1};
  plane[1] = {1, 0, 0, 1};
  plane[2] = {0, -1, 0, 1};
  plane[3] = {0, 1, 0, 1};
  plane[4] = {0, 0, 1, 1};
  plane[5] = {0, 0, -1, 1};
  std::array<glm::vec4, ClipPlanes::kCount> user_planes;
  user_count = clip_space_planes(user, projection, user_planes);
  for (int i = 0; i < user_count; ++i) plane[std::size_t(kViewPlanes + i)] = user_planes[std::size_t(i)];
  plane[std::size_t(kViewPlanes + user_count)] = {0, 0, 0, 1};
  count = kViewPlanes + user_count + 1;
}

namespace {

// Distance from plane p in float, Mesa's order of operations.
[[gnu::always_inline]] inline float plane_distance(const glm::vec4& c, const glm::vec4& p) {
  return c.x * p.x + c.y * p.y + c.z * p.z + c.w * p.w;
}

}  // namespace

float ClipSpace::distance(const glm::vec4& c, int i) const {
  if (i == count - 1) return c.w - kMinW;
  return plane_distance(c, plane[std::size_t(i)]);
}

std::uint32_t ClipSpace::outcode(const glm::vec4& c) const {
  // Every vertex of every line and point comes here: the planes without a call each.
  const int guard = count - 1;
  std::uint32_t code = !(c.w - kMinW >= 0.0f) ? 1u << guard : 0u;  // NaN is outside
  for (int i = 0; i < guard; ++i) {
    if (!(plane_distance(c, plane[std::size_t(i)]) >= 0.0f)) code |= 1u << i;
  }
  return code;
}

DownTransform::DownTransform(const Viewport& vp, int fb_height)
    : half_width(0.5f * float(vp.width)),
      half_height(0.5f * float(vp.height)),
      tx(half_width + float(vp.x)),
      ty(float(fb_height) - (half_height + float(vp.y))),
      sz(float(0.5 * (double(vp.far_depth) - double(vp.near_depth)))),
      tz(float(0.5 * (double(vp.near_depth) + double(vp.far_depth)))) {}

DownVertex to_down_window(const glm::vec4& clip, const DownTransform& t, bool fused) {
  const float inv_w = 1.0f / clip.w;
  const float x = clip.x * inv_w, y = clip.y * inv_w, z = clip.z * inv_w;
  if (fused) {
    return {{std::fma(x, t.half_width, t.tx), std::fma(y, -t.half_height, t.ty)}, std::fma(z, t.sz, t.tz), inv_w};
  }
  return {{x * t.half_width + t.tx, y * -t.half_height + t.ty}, z * t.sz + t.tz, inv_w};
}

void to_down_window(PrimVertex& v, const Viewport& vp, int fb_height, bool fused) {
  const DownVertex d = to_down_window(v.clip, DownTransform(vp, fb_height), fused);
  v.win = d.win;
  v.z = d.z;
  v.inv_w = d.inv_w;
}

bool clip_segment(const ClipSpace& planes, std::uint32_t oa, std::uint32_t ob, PrimVertex& a, PrimVertex& b,
                  const Viewport& vp, int fb_height) {
  if (oa & ob) return false;  // both ends outside one plane
  float t0 = 0.0f, t1 = 0.0f;
  for (std::uint32_t mask = oa | ob; mask; mask &= mask - 1) {
    const int i = std::countr_zero(mask);
    const float d0 = planes.distance(a.clip, i), d1 = planes.distance(b.clip, i);
    if (not_finite(d0) || not_finite(d1)) return false;
    if (d1 < 0.0f) t1 = std::max(t1, d1 / (d1 - d0));
    if (d0 < 0.0f) t0 = std::max(t0, d0 / (d0 - d1));
    if (t0 + t1 >= 1.0f) return false;
  }
  const PrimVertex a0 = a, b0 = b;
  if (oa) interpolate(a, t0, a0, b0, vp, fb_height);
  if (ob) interpolate(b, t1, b0, a0, vp, fb_height);
  return true;
}

void clip_edged_polygon(const ClipSpace& planes, std::uint32_t outcodes, std::vector<PrimVertex>& poly,
                        std::vector<PrimVertex>& scratch, const Viewport& vp, int fb_height) {
  for (std::uint32_t mask = outcodes; mask && poly.size() >= 3; mask &= mask - 1) {
    const int plane = std::countr_zero(mask);
    const std::size_t n = poly.size();
    scratch.clear();
    float d_prev = planes.distance(poly[0].clip, plane);
    if (not_finite(d_prev)) return poly.clear();
    for (std::size_t i = 1; i <= n; ++i) {
      const PrimVertex& prev = poly[i - 1];
      const PrimVertex& vert = poly[i % n];
      const float d = planes.distance(vert.clip, plane);
      if (not_finite(d)) return poly.clear();
      bool crosses;
      if (d_prev >= 0.0f) {
        scratch.push_back(prev);
        crosses = d < 0.0f;
      } else {
        crosses = !(d < 0.0f);
      }
      if (crosses) {
        PrimVertex& v = scratch.emplace_back();
        const float denom = d - d_prev;
        // Interpolated from the end nearer the plane.
        if (d < 0.0f) {  // leaving: the edge along the plane is drawn only for a user plane
          if (-d < d_prev) interpolate(v, d / denom, vert, prev, vp, fb_height);
          else interpolate(v, -d_prev / denom, prev, vert, vp, fb_height);
          v.edge = planes.user_plane(plane);
        } else {  // entering: the rest of the edge keeps its flag
          if (-d_prev < d) interpolate(v, -d_prev / denom, prev, vert, vp, fb_height);
          else interpolate(v, d / denom, vert, prev, vp, fb_height);
          v.edge = prev.edge;
        }
      }
      d_prev = d;
    }
    poly.swap(scratch);
  }
  if (poly.size() < 3) poly.clear();
}

}  // namespace shadelab::detail
