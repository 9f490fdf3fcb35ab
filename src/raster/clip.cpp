// Homogeneous clipping of convex polygons against the view volume and the user clip planes
// (GL 1.5 section 2.12).
// Clipping in clip space keeps attributes exact: they are linear there before the divide.
#include "pipeline/stages.hpp"

#include <glm/matrix.hpp>

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

// Distance to plane i: a fixed plane, or user plane i - kPlaneCount.
double distance(const glm::vec4& c, int i, std::span<const glm::vec4> user) {
  if (i < kPlaneCount) return plane_distance(c, i);
  const glm::vec4& p = user[std::size_t(i - kPlaneCount)];
  return double(p.x) * c.x + double(p.y) * c.y + double(p.z) * c.z + double(p.w) * c.w;
}

// The point where edge a-b meets `plane`, a inside. t and the position are computed in double,
// and the coordinate the plane fixes is set exactly: with huge coordinates (1e30) the
// interpolated value would otherwise lose every digit to cancellation.
ClipVertex intersect(const ClipVertex& a, const ClipVertex& b, int plane, std::span<const glm::vec4> user) {
  double da = distance(a.clip, plane, user), db = distance(b.clip, plane, user);
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
    case 6: out.clip.w = kMinW; break;
    default: break;  // a user plane fixes no coordinate
  }
  for (int i = 0; i < kAttrCount; ++i) {
    out.attr[i] = static_cast<float>(a.attr[i] + (double(b.attr[i]) - a.attr[i]) * t);
  }
  return out;
}

}  // namespace

bool clip_polygon(std::vector<ClipVertex>& poly, std::vector<ClipVertex>& scratch,
                  std::span<const glm::vec4> user) {
  bool cut = false;
  const int planes = kPlaneCount + int(user.size());
  for (int plane = 0; plane < planes && !poly.empty(); ++plane) {
    bool all_inside = true;
    for (const ClipVertex& v : poly) all_inside &= distance(v.clip, plane, user) >= 0.0;
    if (all_inside) continue;
    cut = true;
    scratch.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const ClipVertex& a = poly[i];
      const ClipVertex& b = poly[(i + 1) % poly.size()];
      double da = distance(a.clip, plane, user), db = distance(b.clip, plane, user);
      if (da >= 0.0) scratch.push_back(a);
      // Always interpolate from the inside vertex so the new point is the same for both
      // triangles sharing this edge (no cracks along clipped shared edges).
      if ((da >= 0.0) != (db >= 0.0)) {
        scratch.push_back(da >= 0.0 ? intersect(a, b, plane, user) : intersect(b, a, plane, user));
      }
    }
    poly.swap(scratch);
  }
  if (poly.size() < 3) poly.clear();
  return cut;
}

std::uint32_t clip_outcode(const glm::vec4& c, std::span<const glm::vec4> user) {
  std::uint32_t code = 0;
  const int planes = kPlaneCount + int(user.size());
  for (int i = 0; i < planes; ++i) {
    if (!(distance(c, i, user) >= 0.0)) code |= 1u << i;
  }
  return code;
}

int clip_space_planes(const ClipPlanes& planes, const glm::mat4& projection,
                      std::array<glm::vec4, ClipPlanes::kCount>& out) {
  if (!planes.enabled) return 0;
  // A clip-space point c = P e is inside when dot(plane_eye, P^-1 c) >= 0: the clip-space
  // plane is the row vector plane_eye P^-1, as Mesa keeps user planes.
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(projection));
  int n = 0;
  for (int i = 0; i < ClipPlanes::kCount; ++i) {
    if (planes.enabled & (1u << i)) out[std::size_t(n++)] = glm::vec4(glm::dvec4(planes.eye[std::size_t(i)]) * inverse);
  }
  return n;
}

}  // namespace shadelab::detail
