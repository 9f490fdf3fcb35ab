// Clipping and the viewport transform for lines, points and polygons drawn as lines or points,
// in float arithmetic in the order Mesa's draw module uses (GL 1.1 sections 2.10-2.11): the
// pixels of a line depend on exactly where its clipped ends land. Filled triangles keep
// clip.cpp's double-precision clipper. No rasterization here.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>

#include "raster/prim_setup.hpp"

namespace shadelab::detail {

/// A vertex of a line, a point or a polygon drawn in point or line mode: clip coordinates,
/// llvmpipe's window position (y down), window depth, 1/w and the attributes.
struct PrimVertex {
  glm::vec4 clip;
  DownPoint win;
  float z;
  float inv_w;
  Attribs attr;
  bool edge;  ///< polygons: the edge from this vertex to the next is drawn
  float point_size;  ///< an attenuated point's derived size (PointState::attenuated), pixels
};

/// The planes a draw clips against, in clip space and in Mesa's order: the view volume's six
/// (x <= w, x >= -w, y <= w, y >= -w, z >= -w, z <= w), the enabled user clip planes (eye-space
/// planes times the inverse projection, as Mesa keeps them), and last a guard keeping w
/// positive. Bit i of a vertex's outcode: outside plane i.
struct ClipSpace {
  static constexpr int kViewPlanes = 6;
  std::array<glm::vec4, kViewPlanes + ClipPlanes::kCount + 1> plane;
  int user_count = 0;
  int count = kViewPlanes + 1;

  ClipSpace(const ClipPlanes& user, const glm::mat4& projection);
  /// dot(clip, plane i) in float, Mesa's order of operations.
  float distance(const glm::vec4& clip, int i) const;
  std::uint32_t outcode(const glm::vec4& clip) const;
  /// Whether plane i is a user plane: an edge along it is drawn in line mode.
  bool user_plane(int i) const { return i >= kViewPlanes && i < kViewPlanes + user_count; }
};

/// llvmpipe's viewport transform for one viewport and framebuffer height, Mesa's viewport
/// state: scale (w/2, -h/2, (f - n)/2), translate (x + w/2, H - (y + h/2), (n + f)/2) for a
/// buffer whose rows run top to bottom.
struct DownTransform {
  DownTransform(const Viewport& vp, int fb_height);
  float half_width, half_height, tx, ty, sz, tz;
};

/// A clip position's window position (down), window depth and 1/w.
struct DownVertex {
  DownPoint win;
  float z, inv_w;
};

/// llvmpipe's viewport transform: window x and y (down) and depth from clip coordinates,
/// (c / w) * scale + translate per coordinate. `fused`: in one rounding (a fused multiply-add),
/// as Mesa's compiled vertex stage computes it for the vertices a draw is given; the ends
/// clipping makes are computed in two (Mesa's clipper is C code).
DownVertex to_down_window(const glm::vec4& clip, const DownTransform& t, bool fused = true);
/// The same for v.clip, into v.win, v.z and v.inv_w.
void to_down_window(PrimVertex& v, const Viewport& vp, int fb_height, bool fused = true);

/// Clips the segment a-b; false when nothing is left. Ends that move are interpolated in clip
/// space (all attributes) and transformed again; `a` and `b` are replaced by the clipped ends.
bool clip_segment(const ClipSpace& planes, std::uint32_t outcode_a, std::uint32_t outcode_b,
                  PrimVertex& a, PrimVertex& b, const Viewport& vp, int fb_height);

/// Clips a convex polygon (Sutherland-Hodgman over the planes in `outcodes`, Mesa's draw
/// module's vertex order and interpolation): `poly` is replaced by the clipped polygon, each
/// vertex's `edge` telling whether the edge from it to the next is drawn (an edge along a view
/// plane is not, one along a user plane is). Empty when nothing is left.
void clip_edged_polygon(const ClipSpace& planes, std::uint32_t outcodes, std::vector<PrimVertex>& poly,
                        std::vector<PrimVertex>& scratch, const Viewport& vp, int fb_height);

}  // namespace shadelab::detail
