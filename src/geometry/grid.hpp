// Private helpers for the built-in shapes: appending vertices, sampling a parametric surface on
// a grid of (nu + 1) x (nv + 1) vertices and joining it with quads of a stated winding.
// Building blocks only: no shape of its own, no transforms, no materials.
#pragma once

#include <algorithm>
#include <cstdint>

#include "shadelab/mesh.hpp"

namespace shadelab::detail {

/// The most segments along any one parameter of a built-in shape; larger counts are clamped so
/// that a bad parameter cannot ask for billions of vertices.
constexpr int kMaxSegments = 4096;

/// `count` clamped to [lo, kMaxSegments].
inline int clamp_count(int count, int lo) { return std::clamp(count, lo, kMaxSegments); }

/// One vertex of a built-in shape (object space).
struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;  ///< unit length
  glm::vec2 texcoord;
};

/// Appends `v` (position, normal, texture coordinate) and returns its index.
std::uint32_t add_vertex(Mesh& mesh, const Vertex& v);

/// Which side of the grid is its front. kAlongUV: the quad (i, j), (i+1, j), (i+1, j+1), (i, j+1)
/// is counter-clockwise seen from the side cross(dP/du, dP/dv) points to. kAlongVU: the other side.
enum class Winding { kAlongUV, kAlongVU };

/// Adds the nu x nv quads over a grid of vertices starting at `base` (row-major, u fastest),
/// each through add_quad, so the provoking vertex is the quad's last corner.
void add_grid_quads(Mesh& mesh, std::uint32_t base, int nu, int nv, Winding winding);

/// Samples vertex(i, j) for 0 <= i <= nu, 0 <= j <= nv (u fastest), adds the quads between them
/// and returns the index of the first vertex. nv = 0 adds one row of vertices and no quads.
template <class F>
std::uint32_t add_grid(Mesh& mesh, int nu, int nv, Winding winding, F&& vertex) {
  auto base = static_cast<std::uint32_t>(mesh.positions.size());
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i) add_vertex(mesh, vertex(i, j));
  }
  add_grid_quads(mesh, base, nu, nv, winding);
  return base;
}

/// cos and sin of the angle 2 pi i / n, with i = n giving exactly the values of i = 0 so that a
/// closed ring's seam vertices coincide bit for bit.
glm::vec2 unit_circle(int i, int n);

}  // namespace shadelab::detail
