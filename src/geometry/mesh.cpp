// Mesh helpers: smooth vertex normals, OpenGL's quad split, and the grid builder that the
// built-in shapes share (geometry/grid.hpp).
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "geometry/grid.hpp"

namespace shadelab {

void compute_smooth_normals(Mesh& mesh) {
  const std::size_t n = mesh.positions.size();
  mesh.normals.assign(n, glm::vec3(0.0f));
  for (const Triangle& t : mesh.triangles) {
    if (t[0] >= n || t[1] >= n || t[2] >= n) continue;
    const auto& p = mesh.positions;
    glm::vec3 face = glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
    float len = glm::length(face);
    if (!(len > 0.0f) || !std::isfinite(len)) continue;  // degenerate faces add nothing
    for (std::uint32_t v : t) mesh.normals[v] += face / len;
  }
  for (glm::vec3& normal : mesh.normals) {
    float len = glm::length(normal);
    normal = (len > 0.0f && std::isfinite(len)) ? normal / len : glm::vec3(0.0f, 0.0f, 1.0f);
  }
}

void add_quad(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  mesh.triangles.push_back({a, b, d});
  mesh.triangles.push_back({b, c, d});
}

namespace detail {

std::uint32_t add_vertex(Mesh& mesh, const Vertex& v) {
  mesh.positions.push_back(v.position);
  mesh.normals.push_back(v.normal);
  mesh.texcoords.push_back(v.texcoord);
  return static_cast<std::uint32_t>(mesh.positions.size() - 1);
}

void add_grid_quads(Mesh& mesh, std::uint32_t base, int nu, int nv, Winding winding) {
  auto at = [&](int i, int j) { return base + std::uint32_t(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (winding == Winding::kAlongUV) {
        add_quad(mesh, a, b, c, d);
      } else {
        add_quad(mesh, a, d, c, b);
      }
    }
  }
}

glm::vec2 unit_circle(int i, int n) {
  if (n <= 0 || i % n == 0) return {1.0f, 0.0f};
  double t = 2.0 * std::numbers::pi * double(i % n) / double(n);  // double: cos(pi/2) ~ 6e-17
  return {float(std::cos(t)), float(std::sin(t))};
}

}  // namespace detail
}  // namespace shadelab
