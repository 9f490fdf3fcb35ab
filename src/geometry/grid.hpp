// Private helper for parametric shapes: samples f(u, v) on an (nu + 1) x (nv + 1) grid and adds
// the quads, each wound counter-clockwise as seen from the side its normals point to.
#pragma once

#include <cmath>

#include "shadelab/mesh.hpp"

namespace shadelab::detail {

/// Adds the quads over the grid of vertices starting at index `base` (row-major, u fastest).
void add_grid_quads(Mesh& mesh, std::uint32_t base, int nu, int nv);

/// f(u, v, position, normal) with u, v in [0, 1]; texture coordinates are (u, v).
template <class F>
void add_grid(Mesh& mesh, int nu, int nv, F&& f) {
  auto base = static_cast<std::uint32_t>(mesh.positions.size());
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i) {
      float u = float(i) / float(nu), v = float(j) / float(nv);
      glm::vec3 p, n;
      f(u, v, p, n);
      mesh.positions.push_back(p);
      mesh.normals.push_back(n);
      mesh.texcoords.push_back({u, v});
    }
  }
  add_grid_quads(mesh, base, nu, nv);
}

}  // namespace shadelab::detail
