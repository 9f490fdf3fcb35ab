// Private interfaces between the pipeline's stages: the clip-space vertex with its attributes,
// the clipper, and the reference rasterizer. Not part of the public API. Stateless functions:
// each stage takes what it works on and keeps nothing between calls.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "shadelab/pipeline.hpp"

namespace shadelab::detail {

/// Attribute slots carried from vertices to pixels; all interpolate linearly in clip space.
enum Attr : int {
  kFrontColor = 0,      // 4: lit front colour (or vertex colour when unlit)
  kBackColor = 4,       // 4: lit back colour (two-sided lighting)
  kFrontSecondary = 8,  // 3: separate specular, front
  kBackSecondary = 11,  // 3: separate specular, back
  kEyePosition = 14,    // 3: for per-pixel (Phong) lighting
  kEyeNormal = 17,      // 3
  kTexCoord = 20,       // 4 per texture unit: s, t, r, q (divided by q per fragment)
  kFogCoord = kTexCoord + 4 * kMaxTextureUnits,  // 1: fog coordinate (eye-space distance), never flat
  kAttrCount,
};
using Attribs = std::array<float, kAttrCount>;

struct ClipVertex {
  glm::vec4 clip;
  Attribs attr;
};

/// Clips a convex polygon against -w <= x, y, z <= w and w >= epsilon (Sutherland-Hodgman in
/// homogeneous coordinates), then against `user` planes given in clip space (inside where
/// dot(plane, clip) >= 0). `poly` is replaced by the clipped polygon (possibly empty).
/// Returns true if any plane cut the polygon. Plane i's bit in clip_outcode is bit i: the
/// seven fixed planes, then the user planes in order.
bool clip_polygon(std::vector<ClipVertex>& poly, std::vector<ClipVertex>& scratch,
                  std::span<const glm::vec4> user = {});

/// Bit i set when clip coordinates `c` are outside plane i of clip_polygon.
std::uint32_t clip_outcode(const glm::vec4& c, std::span<const glm::vec4> user);

/// The user clip planes of `planes` in clip space (eye-space planes times the inverse
/// projection) into `out`; returns how many are enabled.
int clip_space_planes(const ClipPlanes& planes, const glm::mat4& projection,
                      std::array<glm::vec4, ClipPlanes::kCount>& out);

/// A vertex after the viewport transform: window x, y, depth, and 1/w_clip.
struct WindowVertex {
  double x, y;
  float z;
  float inv_w;
  const Attribs* attr;
};

/// Per-fragment inputs the rasterizer hands to the shading callback.
struct Fragment {
  int x, y;
  float z;
  Attribs attr;  // perspective-correct
  // Per texture unit, the differences of s / q and t / q over the fragment's 2x2 quad,
  // llvmpipe's (for the level of detail); computed only for the units the rasterizer is asked
  // for.
  std::array<TextureDerivatives, kMaxTextureUnits> texture_derivatives;
};

/// The viewport mapping of a clipped vertex (draw.cpp); its attributes stay in `v`.
WindowVertex to_window(const ClipVertex& v, const Viewport& vp);

/// glPolygonOffset's depth offset for the window-space triangle a, b, c (draw.cpp).
float polygon_offset(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                     const FragmentState& f);

/// Rasterizes one triangle with the top-left fill rule at pixel centres (8 sub-pixel bits),
/// calling `emit(fragment)` for every covered pixel inside the scissor [0, width) x [0, height).
/// Triangles with zero area produce nothing. Returns the number of covered pixels.
/// For each texture unit whose bit is set in `texture_units`, fragments also carry the unit's
/// texture coordinates in the fast pipeline's float arithmetic and their quad's differences.
template <class Emit>
std::uint64_t rasterize_triangle(const WindowVertex& a, const WindowVertex& b,
                                 const WindowVertex& c, int width, int height, unsigned texture_units,
                                 Emit&& emit);

/// The bits of the units of `shade` that have a texture (rasterize_triangle's texture_units).
inline unsigned textured_units(const ShadeState& shade) {
  unsigned bits = 0;
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    if (shade.textures[std::size_t(u)].texture) bits |= 1u << u;
  }
  return bits;
}

/// A vertex's fog coordinate (draw.cpp): VertexInput::fog_coords[i], or |z| of its eye-space
/// position (Mesa's default GL_EYE_PLANE_ABSOLUTE_NV distance).
float fog_coordinate(const VertexInput& in, std::size_t i);

/// The colour of one fragment before the fragment operations (draw.cpp): lit per pixel for
/// Phong, else its interpolated or flat colour; then textured; then the secondary colour
/// added; then fogged. Unclamped.
glm::vec4 shade_fragment(const ShadeState& shade, const Fragment& f, bool front);

}  // namespace shadelab::detail

#include "raster/reference_raster.inl"
