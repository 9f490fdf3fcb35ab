// The Utah teapot: Newell's Bezier patches evaluated on a grid with analytic normals, turned
// and scaled as glutSolidTeapot(size) does (lid toward +y, spout toward +x, centred).
#include <array>

#include <glm/geometric.hpp>

#include "geometry/grid.hpp"
#include "geometry/teapot_data.hpp"
#include "shadelab/shapes.hpp"

namespace shadelab {

namespace {

using Patch = std::array<glm::vec3, 16>;

void bernstein(float t, float b[4], float d[4]) {
  float s = 1.0f - t;
  b[0] = s * s * s;
  b[1] = 3 * t * s * s;
  b[2] = 3 * t * t * s;
  b[3] = t * t * t;
  d[0] = -3 * s * s;
  d[1] = 3 * s * s - 6 * t * s;
  d[2] = 6 * t * s - 3 * t * t;
  d[3] = 3 * t * t;
}

// Position and the two partial derivatives of a bicubic patch (rows along u).
void evaluate(const Patch& c, float u, float v, glm::vec3& p, glm::vec3& pu, glm::vec3& pv) {
  float bu[4], du[4], bv[4], dv[4];
  bernstein(u, bu, du);
  bernstein(v, bv, dv);
  p = pu = pv = glm::vec3(0.0f);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      p += bu[i] * bv[j] * c[i * 4 + j];
      pu += du[i] * bv[j] * c[i * 4 + j];
      pv += bu[i] * dv[j] * c[i * 4 + j];
    }
  }
}

// Unit normal at (u, v); where a derivative vanishes (the lid's knob, the bottom's centre)
// the normal of a nearby point stands in.
glm::vec3 patch_normal(const Patch& c, float u, float v) {
  for (float eps : {0.0f, 1e-3f, 1e-2f}) {
    glm::vec3 p, pu, pv;
    evaluate(c, u + (u < 0.5f ? eps : -eps), v + (v < 0.5f ? eps : -eps), p, pu, pv);
    glm::vec3 n = glm::cross(pu, pv);
    float len = glm::length(n);
    if (len > 1e-6f) return n / len;
  }
  return {0.0f, 0.0f, 1.0f};
}

// Does the patch's cross(pu, pv) point out of the teapot? The centroid of a patch's control
// points lies inside the body, spout, handle or lid it belongs to; the bottom is flat and
// faces down.
bool faces_outward(const Patch& c, int index) {
  glm::vec3 centroid(0.0f);
  for (const glm::vec3& q : c) centroid += q / 16.0f;
  glm::vec3 p, pu, pv;
  evaluate(c, 0.5f, 0.5f, p, pu, pv);
  glm::vec3 out = index >= 28 ? glm::vec3(0, 0, -1) : p - centroid;
  return glm::dot(patch_normal(c, 0.5f, 0.5f), out) >= 0.0f;
}

}  // namespace

Mesh make_teapot(const TeapotParams& params) {
  int n = std::max(params.tessellation, 1);
  float s = 0.5f * params.size;
  Mesh m;
  for (int k = 0; k < 32; ++k) {
    Patch c;
    for (int i = 0; i < 16; ++i) {
      const float* q = detail::kTeapotVertices[detail::kTeapotPatches[k][i] - 1];
      c[i] = {q[0], q[1], q[2]};
    }
    float sign = faces_outward(c, k) ? 1.0f : -1.0f;
    detail::add_grid(m, n, n, [&](float u, float v, glm::vec3& pos, glm::vec3& nrm) {
      glm::vec3 p, pu, pv;
      evaluate(c, u, v, p, pu, pv);
      glm::vec3 d = sign * patch_normal(c, u, v);
      // glutSolidTeapot: rotate -90 degrees about x (z up becomes y up), lower by 1.5, scale.
      pos = s * glm::vec3(p.x, p.z - 1.5f, -p.y);
      nrm = {d.x, d.z, -d.y};
    });
  }
  return m;
}

}  // namespace shadelab
