// Mesh helpers: smooth vertex normals, OpenGL's quad split, and a parametric grid builder
// that picks each quad's winding so its face agrees with the surface normal.
#include "geometry/grid.hpp"

#include <glm/geometric.hpp>

namespace shadelab {

void compute_smooth_normals(Mesh& mesh) {
  mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
  for (const Triangle& t : mesh.triangles) {
    if (t[0] >= mesh.positions.size() || t[1] >= mesh.positions.size() ||
        t[2] >= mesh.positions.size()) {
      continue;
    }
    glm::vec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                             mesh.positions[t[2]] - mesh.positions[t[0]]);
    float len = glm::length(n);
    if (!(len > 0.0f) || !std::isfinite(len)) continue;  // degenerate faces add nothing
    for (std::uint32_t v : t) mesh.normals[v] += n / len;
  }
  for (glm::vec3& n : mesh.normals) {
    float len = glm::length(n);
    n = (len > 0.0f && std::isfinite(len)) ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
  }
}

void add_quad(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  mesh.triangles.push_back({a, b, d});
  mesh.triangles.push_back({b, c, d});
}

namespace detail {

void add_grid_quads(Mesh& mesh, std::uint32_t base, int nu, int nv) {
  auto at = [&](int i, int j) { return base + std::uint32_t(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      const auto& p = mesh.positions;
      const auto& n = mesh.normals;
      // The diagonals' cross product is the quad's normal, even when two corners coincide.
      glm::vec3 face = glm::cross(p[c] - p[a], p[d] - p[b]);
      glm::vec3 smooth = n[a] + n[b] + n[c] + n[d];
      if (glm::dot(face, smooth) >= 0.0f) {
        add_quad(mesh, a, b, c, d);
      } else {
        add_quad(mesh, a, d, c, b);
      }
    }
  }
}

}  // namespace detail
}  // namespace shadelab
