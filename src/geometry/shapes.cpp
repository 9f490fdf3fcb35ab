// The built-in shapes: sphere, cylinder, cone, torus, cube, the lecture's tetrahedron, wall,
// plane and disk. Object space, unit normals, texture coordinates, counter-clockwise fronts.
#include <algorithm>
#include <numbers>

#include <glm/geometric.hpp>

#include "geometry/grid.hpp"
#include "shadelab/shapes.hpp"

namespace shadelab {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
int at_least(int v, int lo) { return std::max(v, lo); }

void add_cap(Mesh& mesh, float radius, float y, int slices, bool up, bool colors) {
  detail::add_grid(mesh, slices, 1, [&](float u, float v, glm::vec3& p, glm::vec3& n) {
    float t = 2.0f * kPi * u, r = radius * v;
    p = {r * std::cos(t), y, r * std::sin(t)};
    n = {0.0f, up ? 1.0f : -1.0f, 0.0f};
  });
  if (colors) {
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= slices; ++i) {
        float t = 2.0f * kPi * float(i) / float(slices);
        mesh.colors.push_back({std::cos(t), 0.0f, std::sin(t), 1.0f});
      }
  }
}

}  // namespace

Mesh make_sphere(const SphereParams& p) {
  Mesh m;
  detail::add_grid(m, at_least(p.slices, 3), at_least(p.stacks, 2),
                   [&](float u, float v, glm::vec3& pos, glm::vec3& n) {
                     float phi = 2.0f * kPi * u, theta = kPi * (v - 0.5f);
                     n = {std::cos(theta) * std::cos(phi), std::sin(theta), -std::cos(theta) * std::sin(phi)};
                     pos = p.radius * n;
                   });
  return m;
}

Mesh make_cylinder(const CylinderParams& p) {
  Mesh m;
  int slices = at_least(p.slices, 3);
  detail::add_grid(m, slices, at_least(p.stacks, 1), [&](float u, float v, glm::vec3& pos, glm::vec3& n) {
    float t = 2.0f * kPi * u;  // the lecture's t: vertex (cos t, y, sin t)
    n = {std::cos(t), 0.0f, std::sin(t)};
    pos = {p.radius * n.x, p.height * v, p.radius * n.z};
  });
  if (p.angle_colors) {
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      m.colors.push_back({m.normals[i].x, 0.0f, m.normals[i].z, 1.0f});
    }
  }
  if (p.caps) {
    add_cap(m, p.radius, 0.0f, slices, false, p.angle_colors);
    add_cap(m, p.radius, p.height, slices, true, p.angle_colors);
  }
  return m;
}

Mesh make_cone(const ConeParams& p) {
  Mesh m;
  int slices = at_least(p.slices, 3);
  float slant = std::sqrt(p.height * p.height + p.radius * p.radius);
  detail::add_grid(m, slices, at_least(p.stacks, 1), [&](float u, float v, glm::vec3& pos, glm::vec3& n) {
    float t = 2.0f * kPi * u;
    float r = p.radius * (1.0f - v);
    pos = {r * std::cos(t), p.height * v, r * std::sin(t)};
    n = slant > 0.0f ? glm::vec3(p.height * std::cos(t), p.radius, p.height * std::sin(t)) / slant
                     : glm::vec3(0, 1, 0);
  });
  if (p.cap) add_cap(m, p.radius, 0.0f, slices, false, false);
  return m;
}

Mesh make_torus(const TorusParams& p) {
  Mesh m;
  detail::add_grid(m, at_least(p.rings, 3), at_least(p.sides, 3),
                   [&](float u, float v, glm::vec3& pos, glm::vec3& n) {
                     float phi = 2.0f * kPi * u, theta = 2.0f * kPi * v;
                     n = {std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), std::sin(theta)};
                     float ring = p.major_radius + p.minor_radius * std::cos(theta);
                     pos = {ring * std::cos(phi), ring * std::sin(phi), p.minor_radius * std::sin(theta)};
                   });
  return m;
}

Mesh make_cube(float size) {
  Mesh m;
  float h = 0.5f * size;
  const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::vec3& n : normals) {
    // Two axes spanning the face, chosen so that a x b = n (counter-clockwise from outside).
    glm::vec3 a = std::abs(n.y) > 0.5f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    glm::vec3 b = glm::cross(n, a);
    a = glm::cross(b, n);
    detail::add_grid(m, 1, 1, [&](float u, float v, glm::vec3& pos, glm::vec3& nn) {
      pos = h * (n + (2 * u - 1) * a + (2 * v - 1) * b);
      nn = n;
    });
  }
  return m;
}

Mesh make_tetrahedron() {
  // The lecture's vertices and faces, in its glVertex order, with its glNormal3f per face.
  // Seen from outside, faces (0,1,2) and (1,3,2) are counter-clockwise and (0,2,3) and (0,3,1)
  // too: the lecture's order is consistent, so culling would keep all four front faces.
  const glm::vec3 v[4] = {{-1, -1, -1}, {1, -1, 1}, {-1, 1, 1}, {1, 1, -1}};
  const int faces[4][3] = {{0, 1, 2}, {1, 3, 2}, {0, 2, 3}, {0, 3, 1}};
  const glm::vec3 normals[4] = {{-1, -1, 1}, {1, 1, 1}, {-1, 1, -1}, {1, -1, -1}};
  Mesh m;
  for (int f = 0; f < 4; ++f) {
    auto base = static_cast<std::uint32_t>(m.positions.size());
    for (int k = 0; k < 3; ++k) {
      m.positions.push_back(v[faces[f][k]]);
      m.normals.push_back(glm::normalize(normals[f]));
      m.texcoords.push_back({k == 1 ? 1.0f : 0.0f, k == 2 ? 1.0f : 0.0f});
    }
    m.triangles.push_back({base, base + 1, base + 2});
  }
  return m;
}

Mesh make_wall(const WallParams& p) {
  Mesh m;
  detail::add_grid(m, at_least(p.nx, 1), at_least(p.ny, 1), [&](float u, float v, glm::vec3& pos, glm::vec3& n) {
    pos = {p.width * (u - 0.5f), p.height * (v - 0.5f), 0.0f};
    n = {0, 0, 1};
  });
  return m;
}

Mesh make_plane(float size, int n) {
  Mesh m;
  n = at_least(n, 1);
  detail::add_grid(m, n, n, [&](float u, float v, glm::vec3& pos, glm::vec3& nn) {
    pos = {size * (u - 0.5f), 0.0f, size * (0.5f - v)};
    nn = {0, 1, 0};
  });
  return m;
}

Mesh make_disk(const DiskParams& p) {
  Mesh m;
  detail::add_grid(m, at_least(p.slices, 3), at_least(p.loops, 1), [&](float u, float v, glm::vec3& pos, glm::vec3& n) {
    float t = 2.0f * kPi * u, r = p.inner_radius + (p.outer_radius - p.inner_radius) * v;
    pos = {r * std::cos(t), r * std::sin(t), 0.0f};
    n = {0, 0, 1};
  });
  return m;
}

}  // namespace shadelab
