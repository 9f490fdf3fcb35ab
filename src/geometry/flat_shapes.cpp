// The flat-faced built-in shapes: cube, the lecture's tetrahedron, the mesh-size wall and the
// floor plane. Object space, one normal per face, texture coordinates over [0, 1] per face.
#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/grid.hpp"
#include "shadelab/shapes.hpp"

namespace shadelab {

using detail::clamp_count;
using detail::Vertex;
using detail::Winding;

Mesh make_cube(float size) {
  Mesh m;
  float h = 0.5f * size;
  const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::vec3& n : normals) {
    // Two axes spanning the face with a x b = n, so (u, v) turns counter-clockwise from outside.
    glm::vec3 a = std::abs(n.y) > 0.5f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    glm::vec3 b = glm::cross(n, a);
    a = glm::cross(b, n);
    detail::add_grid(m, 1, 1, Winding::kAlongUV, [&](int i, int j) {
      glm::vec2 uv{float(i), float(j)};
      return Vertex{h * (n + (2.0f * uv.x - 1.0f) * a + (2.0f * uv.y - 1.0f) * b), n, uv};
    });
  }
  return m;
}

Mesh make_tetrahedron() {
  // The lecture's vertices and faces in its glVertex order, with its glNormal3f per face. Checked
  // by hand: (v1 - v0) x (v2 - v0) is (-4,-4,4) for (v0,v1,v2), (4,4,4) for (v1,v3,v2), (-4,4,-4)
  // for (v0,v2,v3) and (4,-4,-4) for (v0,v3,v1): each a positive multiple of the lecture's
  // normal, which points away from the centre (the origin). So every face is counter-clockwise
  // seen from outside as the lecture gives it; back-face culling would keep all four.
  const glm::vec3 v[4] = {{-1, -1, -1}, {1, -1, 1}, {-1, 1, 1}, {1, 1, -1}};
  const int faces[4][3] = {{0, 1, 2}, {1, 3, 2}, {0, 2, 3}, {0, 3, 1}};
  const glm::vec3 normals[4] = {{-1, -1, 1}, {1, 1, 1}, {-1, 1, -1}, {1, -1, -1}};
  const glm::vec2 texcoords[3] = {{0, 0}, {1, 0}, {0, 1}};
  Mesh m;
  for (int f = 0; f < 4; ++f) {
    auto base = static_cast<std::uint32_t>(m.positions.size());
    for (int k = 0; k < 3; ++k) {
      detail::add_vertex(m, {v[faces[f][k]], glm::normalize(normals[f]), texcoords[k]});
    }
    m.triangles.push_back({base, base + 1, base + 2});
  }
  return m;
}

Mesh make_wall(const WallParams& p) {
  int nx = clamp_count(p.nx, 1), ny = clamp_count(p.ny, 1);
  Mesh m;
  detail::add_grid(m, nx, ny, Winding::kAlongUV, [&](int i, int j) {
    glm::vec2 uv(float(i) / float(nx), float(j) / float(ny));
    return Vertex{{p.width * (uv.x - 0.5f), p.height * (uv.y - 0.5f), 0.0f}, {0, 0, 1}, uv};
  });
  return m;
}

Mesh make_plane(float size, int n) {
  n = clamp_count(n, 1);
  // u along +x, v along -z: seen from above (+y) with -z up the screen, (s, t) is upright.
  Mesh m;
  detail::add_grid(m, n, n, Winding::kAlongUV, [&](int i, int j) {
    glm::vec2 uv(float(i) / float(n), float(j) / float(n));
    return Vertex{{size * (uv.x - 0.5f), 0.0f, size * (0.5f - uv.y)}, {0, 1, 0}, uv};
  });
  return m;
}

}  // namespace shadelab
