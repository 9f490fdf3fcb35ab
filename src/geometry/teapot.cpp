// The Utah teapot: Newell's 32 Bezier patches evaluated on a grid with analytic normals, turned
// and scaled as GLUT 3.7's glutSolidTeapot(size) does (lid toward +y, spout toward +x, centred;
// freeglut 3's sits 0.0375 size lower, which libshadelab-glut follows: gl/glut/teapot_gen.cpp).
#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/grid.hpp"
#include "geometry/teapot_data.hpp"
#include "shadelab/shapes.hpp"

namespace shadelab {

namespace {

/// Segments per patch parameter at most: 32 * 257^2 vertices is about two million.
constexpr int kMaxTessellation = 256;

/// Control points of one patch in the data's space (z up), row-major: row i along u. Evaluated
/// in double: the lid's knob and the bottom's centre collapse a whole patch edge to one point,
/// and only then do its samples come out bit-identical (and its vanishing derivative as zero).
using Patch = std::array<glm::dvec3, 16>;

Patch patch(int k) {
  Patch c;
  for (int i = 0; i < 16; ++i) {
    const float* q = detail::kTeapotVertices[detail::kTeapotPatches[k][i] - 1];
    c[i] = {q[0], q[1], q[2]};
  }
  return c;
}

/// Cubic Bernstein polynomials at t and their derivatives.
void bernstein(double t, double b[4], double d[4]) {
  double s = 1.0 - t;
  b[0] = s * s * s;
  b[1] = 3.0 * t * s * s;
  b[2] = 3.0 * t * t * s;
  b[3] = t * t * t;
  d[0] = -3.0 * s * s;
  d[1] = 3.0 * s * s - 6.0 * t * s;
  d[2] = 6.0 * t * s - 3.0 * t * t;
  d[3] = 3.0 * t * t;
}

/// Position and the partial derivatives dP/du, dP/dv of a bicubic patch.
void evaluate(const Patch& c, double u, double v, glm::dvec3& p, glm::dvec3& pu, glm::dvec3& pv) {
  double bu[4], du[4], bv[4], dv[4];
  bernstein(u, bu, du);
  bernstein(v, bv, dv);
  p = pu = pv = glm::dvec3(0.0);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      p += bu[i] * bv[j] * c[i * 4 + j];
      pu += du[i] * bv[j] * c[i * 4 + j];
      pv += bu[i] * dv[j] * c[i * 4 + j];
    }
  }
}

/// Outward unit normal at (u, v), data space. In Newell's data every patch has cross(dP/du,
/// dP/dv) pointing into the teapot (checked patch by patch; the tests check the mesh), so the
/// outward normal is cross(dP/dv, dP/du). Where an edge of the patch collapses to a point (the
/// lid's knob, the bottom's centre) one derivative vanishes: a point a little inside stands in.
glm::vec3 outward_normal(const Patch& c, double u, double v) {
  constexpr double kStep = 1e-3;
  double inward_u = u < 0.5 ? kStep : -kStep, inward_v = v < 0.5 ? kStep : -kStep;
  const glm::dvec2 tries[4] = {{0, 0}, {inward_u, 0}, {0, inward_v}, {inward_u, inward_v}};
  for (const glm::dvec2& d : tries) {
    glm::dvec3 p, pu, pv;
    evaluate(c, u + d.x, v + d.y, p, pu, pv);
    glm::dvec3 n = glm::cross(pv, pu);
    double len = glm::length(n);
    if (len > 1e-9 && std::isfinite(len)) return glm::vec3(n / len);
  }
  return {0.0f, 0.0f, 1.0f};  // not reached with Newell's data
}

}  // namespace

Mesh make_teapot(const TeapotParams& params) {
  int n = std::clamp(params.tessellation, 1, kMaxTessellation);
  float s = 0.5f * params.size;
  Mesh m;
  for (int k = 0; k < 32; ++k) {
    Patch c = patch(k);
    // Texture coordinates are the patch's (u, v); the front is the side cross(dP/dv, dP/du)
    // points to, hence the (v, u) winding.
    detail::add_grid(m, n, n, detail::Winding::kAlongVU, [&](int i, int j) {
      double u = double(i) / double(n), v = double(j) / double(n);
      glm::dvec3 p, pu, pv;
      evaluate(c, u, v, p, pu, pv);
      glm::vec3 d = outward_normal(c, u, v), q(p);
      // GLUT 3.7's glutSolidTeapot: rotate 270 degrees about x (z up becomes y up,
      // (x, y, z) -> (x, z, -y)), scale by size / 2, after moving the data down by 1.5 along z.
      return detail::Vertex{s * glm::vec3(q.x, q.z - 1.5f, -q.y), {d.x, d.z, -d.y}, {float(u), float(v)}};
    });
  }
  return m;
}

}  // namespace shadelab
