// The round built-in shapes: sphere, cylinder, cone, torus and disk. Object space, unit normals,
// texture coordinates, counter-clockwise fronts, no degenerate triangles at poles and apexes.
#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/grid.hpp"
#include "shadelab/shapes.hpp"

namespace shadelab {

namespace {

using detail::clamp_count;
using detail::unit_circle;
using detail::Vertex;
using detail::Winding;

/// A flat disk of `slices` wedges at height y around the y axis, facing +y (`up`) or -y: one
/// centre vertex and a ring. Texture coordinates map it onto [0, 1]^2 as seen from outside (as
/// gluDisk does). With `colors` the rim gets the lecture's (cos t, 0, sin t, 1) and the centre
/// the mean of the rim's colours, (0, 0, 0, 1).
void add_cap(Mesh& m, float radius, float y, int slices, bool up, bool colors) {
  float facing = up ? 1.0f : -1.0f;
  auto centre = detail::add_vertex(m, {{0.0f, y, 0.0f}, {0.0f, facing, 0.0f}, {0.5f, 0.5f}});
  for (int i = 0; i < slices; ++i) {
    glm::vec2 cs = unit_circle(i, slices);
    glm::vec2 st(0.5f + 0.5f * cs.x, 0.5f - 0.5f * facing * cs.y);
    detail::add_vertex(m, {{radius * cs.x, y, radius * cs.y}, {0.0f, facing, 0.0f}, st});
  }
  for (int i = 0; i < slices; ++i) {
    std::uint32_t a = centre + 1 + std::uint32_t(i), b = centre + 1 + std::uint32_t((i + 1) % slices);
    // The angle turns from +x toward +z: clockwise seen from +y. The rim vertex is provoking.
    m.triangles.push_back(up ? Triangle{centre, b, a} : Triangle{centre, a, b});
  }
  if (colors) {
    m.colors.push_back({0.0f, 0.0f, 0.0f, 1.0f});
    for (int i = 0; i < slices; ++i) m.colors.push_back({unit_circle(i, slices).x, 0.0f, unit_circle(i, slices).y, 1.0f});
  }
}

/// Triangles joining a ring of slices + 1 vertices at `ring` to per-slice copies of a pole at
/// `pole`: (ring_i, ring_i+1, pole_i), or (pole_i, ring_i+1, ring_i) when `reversed` (the
/// triangles that the grid's quads would keep, with the same provoking vertex).
void add_pole_fan(Mesh& m, std::uint32_t ring, std::uint32_t pole, int slices, bool reversed) {
  for (std::uint32_t i = 0; i < std::uint32_t(slices); ++i) {
    m.triangles.push_back(reversed ? Triangle{pole + i, ring + i + 1, ring + i}
                                   : Triangle{ring + i, ring + i + 1, pole + i});
  }
}

}  // namespace

Mesh make_sphere(const SphereParams& p) {
  int slices = clamp_count(p.slices, 3), stacks = clamp_count(p.stacks, 2);
  // phi = 2 pi u turns from +x toward -z and theta rises from the south pole: cross(dP/du, dP/dv)
  // points outward. The poles get one vertex per slice (texture s at the slice's middle).
  auto vertex = [&](int i, int j) {
    glm::vec2 phi = unit_circle(i, slices);
    glm::vec2 theta = unit_circle(2 * j - stacks, 4 * stacks);  // angle pi (j / stacks - 1/2)
    glm::vec3 n(theta.x * phi.x, theta.y, -theta.x * phi.y);
    return Vertex{p.radius * n, n, {float(i) / float(slices), float(j) / float(stacks)}};
  };
  Mesh m;
  auto rings = detail::add_grid(m, slices, stacks - 2, Winding::kAlongUV, [&](int i, int j) { return vertex(i, j + 1); });
  auto south = std::uint32_t(m.positions.size());
  for (int i = 0; i < slices; ++i) {
    detail::add_vertex(m, {{0.0f, -p.radius, 0.0f}, {0.0f, -1.0f, 0.0f}, {(float(i) + 0.5f) / float(slices), 0.0f}});
  }
  auto north = std::uint32_t(m.positions.size());
  for (int i = 0; i < slices; ++i) {
    detail::add_vertex(m, {{0.0f, p.radius, 0.0f}, {0.0f, 1.0f, 0.0f}, {(float(i) + 0.5f) / float(slices), 1.0f}});
  }
  add_pole_fan(m, rings, south, slices, true);
  add_pole_fan(m, rings + std::uint32_t((stacks - 2) * (slices + 1)), north, slices, false);
  return m;
}

Mesh make_cylinder(const CylinderParams& p) {
  int slices = clamp_count(p.slices, 3), stacks = clamp_count(p.stacks, 1);
  // The lecture's t runs from 0 in steps of 2 pi / slices, vertex (cos t, y, sin t): seen from
  // outside, t turns clockwise as y rises, so the front is the (v, u) side.
  Mesh m;
  detail::add_grid(m, slices, stacks, Winding::kAlongVU, [&](int i, int j) {
    glm::vec2 cs = unit_circle(i, slices);
    float v = float(j) / float(stacks);
    return Vertex{{p.radius * cs.x, p.height * v, p.radius * cs.y}, {cs.x, 0.0f, cs.y}, {float(i) / float(slices), v}};
  });
  if (p.angle_colors) {
    for (const glm::vec3& n : m.normals) m.colors.push_back({n.x, 0.0f, n.z, 1.0f});
  }
  if (p.caps) {
    add_cap(m, p.radius, 0.0f, slices, false, p.angle_colors);
    add_cap(m, p.radius, p.height, slices, true, p.angle_colors);
  }
  return m;
}

Mesh make_cone(const ConeParams& p) {
  int slices = clamp_count(p.slices, 3), stacks = clamp_count(p.stacks, 1);
  float slant = std::hypot(p.height, p.radius);
  auto side_normal = [&](glm::vec2 cs) {
    bool ok = slant > 0.0f && std::isfinite(slant);
    return ok ? glm::vec3(p.height * cs.x, p.radius, p.height * cs.y) / slant : glm::vec3(0.0f, 1.0f, 0.0f);
  };
  // Rings 0 .. stacks - 1 of the side (turning like the cylinder's); the apex gets one vertex per
  // slice with the normal of the slice's middle, so its triangles are neither degenerate nor NaN.
  Mesh m;
  auto rings = detail::add_grid(m, slices, stacks - 1, Winding::kAlongVU, [&](int i, int j) {
    glm::vec2 cs = unit_circle(i, slices);
    float v = float(j) / float(stacks), r = p.radius * (1.0f - v);
    return Vertex{{r * cs.x, p.height * v, r * cs.y}, side_normal(cs), {float(i) / float(slices), v}};
  });
  auto apex = std::uint32_t(m.positions.size());
  for (int i = 0; i < slices; ++i) {
    glm::vec2 middle = unit_circle(2 * i + 1, 2 * slices);
    detail::add_vertex(m, {{0.0f, p.height, 0.0f}, side_normal(middle), {(float(i) + 0.5f) / float(slices), 1.0f}});
  }
  add_pole_fan(m, rings + std::uint32_t((stacks - 1) * (slices + 1)), apex, slices, true);
  if (p.cap) add_cap(m, p.radius, 0.0f, slices, false, false);
  return m;
}

Mesh make_torus(const TorusParams& p) {
  int rings = clamp_count(p.rings, 3), sides = clamp_count(p.sides, 3);
  // As glutSolidTorus: phi around the z axis (u), theta around the tube (v); cross(dP/du, dP/dv)
  // points out of the tube.
  Mesh m;
  detail::add_grid(m, rings, sides, Winding::kAlongUV, [&](int i, int j) {
    glm::vec2 phi = unit_circle(i, rings), theta = unit_circle(j, sides);
    glm::vec3 n(theta.x * phi.x, theta.x * phi.y, theta.y);
    float ring = p.major_radius + p.minor_radius * theta.x;
    glm::vec3 pos(ring * phi.x, ring * phi.y, p.minor_radius * theta.y);
    return Vertex{pos, n, {float(i) / float(rings), float(j) / float(sides)}};
  });
  return m;
}

Mesh make_disk(const DiskParams& p) {
  int slices = clamp_count(p.slices, 3), loops = clamp_count(p.loops, 1);
  // Radii given the wrong way round are swapped; a negative inner radius means a full disk.
  float outer = std::max(p.inner_radius, p.outer_radius);
  float inner = std::max(0.0f, std::min(p.inner_radius, p.outer_radius));
  bool centre = !(inner > 0.0f);  // a full disk: one centre vertex, a fan of triangles around it
  // Rings of `slices` vertices (no seam: texture coordinates are planar, as gluDisk's).
  auto vertex = [&](int i, float r) {
    glm::vec2 cs = unit_circle(i, slices);
    glm::vec2 st = outer > 0.0f ? 0.5f + 0.5f * (r / outer) * cs : glm::vec2(0.5f);
    return Vertex{{r * cs.x, r * cs.y, 0.0f}, {0.0f, 0.0f, 1.0f}, st};
  };
  Mesh m;
  if (centre) detail::add_vertex(m, vertex(0, 0.0f));
  int first = centre ? 1 : 0;
  for (int k = first; k <= loops; ++k) {
    float r = inner + (outer - inner) * float(k) / float(loops);
    for (int i = 0; i < slices; ++i) detail::add_vertex(m, vertex(i, r));
  }
  auto at = [&](int k, int i) { return std::uint32_t(first + (k - first) * slices + i % slices); };
  for (int i = 0; i < slices; ++i) {
    if (centre) m.triangles.push_back({0, at(1, i), at(1, i + 1)});  // counter-clockwise from +z
    for (int k = first + 1; k <= loops; ++k) {
      add_quad(m, at(k - 1, i), at(k, i), at(k, i + 1), at(k - 1, i + 1));
    }
  }
  return m;
}

}  // namespace shadelab
