// Homogeneous clipping of convex polygons against the view volume (GL 1.5 section 2.12).
// Clipping in clip space keeps attributes exact: they are linear there before the divide.
#include "pipeline/stages.hpp"

namespace shadelab::detail {

namespace {

// Signed distance to each clip plane; inside where >= 0. The last plane keeps w away from
// zero so the perspective divide is always safe, whatever the projection matrix.
constexpr int kPlaneCount = 7;
constexpr float kMinW = 1e-6f;

double plane_distance(const glm::vec4& c, int plane) {
  double x = c.x, y = c.y, z = c.z, w = c.w;
  switch (plane) {
    case 0: return w + x;
    case 1: return w - x;
    case 2: return w + y;
    case 3: return w - y;
    case 4: return w + z;
    case 5: return w - z;
    default: return w - kMinW;
  }
}

// The point where edge a-b meets `plane`, a inside. t and the position are computed in double,
// and the coordinate the plane fixes is set exactly: with huge coordinates (1e30) the
// interpolated value would otherwise lose every digit to cancellation.
ClipVertex intersect(const ClipVertex& a, const ClipVertex& b, int plane) {
  double da = plane_distance(a.clip, plane), db = plane_distance(b.clip, plane);
  double t = da / (da - db);
  ClipVertex out;
  for (int i = 0; i < 4; ++i) {
    out.clip[i] = static_cast<float>(a.clip[i] + (double(b.clip[i]) - a.clip[i]) * t);
  }
  switch (plane) {
    case 0: out.clip.x = -out.clip.w; break;
    case 1: out.clip.x = out.clip.w; break;
    case 2: out.clip.y = -out.clip.w; break;
    case 3: out.clip.y = out.clip.w; break;
    case 4: out.clip.z = -out.clip.w; break;
    case 5: out.clip.z = out.clip.w; break;
    default: out.clip.w = kMinW; break;
  }
  for (int i = 0; i < kAttrCount; ++i) {
    out.attr[i] = static_cast<float>(a.attr[i] + (double(b.attr[i]) - a.attr[i]) * t);
  }
  return out;
}

}  // namespace

bool clip_polygon(std::vector<ClipVertex>& poly, std::vector<ClipVertex>& scratch) {
  bool cut = false;
  for (int plane = 0; plane < kPlaneCount && !poly.empty(); ++plane) {
    bool all_inside = true;
    for (const ClipVertex& v : poly) all_inside &= plane_distance(v.clip, plane) >= 0.0;
    if (all_inside) continue;
    cut = true;
    scratch.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const ClipVertex& a = poly[i];
      const ClipVertex& b = poly[(i + 1) % poly.size()];
      double da = plane_distance(a.clip, plane), db = plane_distance(b.clip, plane);
      if (da >= 0.0) scratch.push_back(a);
      // Always interpolate from the inside vertex so the new point is the same for both
      // triangles sharing this edge (no cracks along clipped shared edges).
      if ((da >= 0.0) != (db >= 0.0)) {
        scratch.push_back(da >= 0.0 ? intersect(a, b, plane) : intersect(b, a, plane));
      }
    }
    poly.swap(scratch);
  }
  if (poly.size() < 3) poly.clear();
  return cut;
}

}  // namespace shadelab::detail
