// explain_pixel: a ray through the pixel centre against every triangle in eye space (the same
// camera, projection and light transforms as render_scene), then explain_point there.
#include "shadelab/explain.hpp"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace shadelab {

namespace {

struct Hit {
  float t = std::numeric_limits<float>::infinity();
  int object = -1;
  std::size_t triangle = 0;
  float u = 0, v = 0;  // barycentric weights of the triangle's second and third vertices
};

// Moller-Trumbore in double: distance along `dir` from `origin`, or nothing.
bool intersect(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& a,
               const glm::dvec3& b, const glm::dvec3& c, double& t, double& u, double& v) {
  glm::dvec3 e1 = b - a, e2 = c - a;
  glm::dvec3 p = glm::cross(dir, e2);
  double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-14) return false;
  double inv = 1.0 / det;
  glm::dvec3 s = origin - a;
  u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  glm::dvec3 q = glm::cross(s, e1);
  v = glm::dot(dir, q) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  t = glm::dot(e2, q) * inv;
  return t > 0.0;
}

}  // namespace

std::optional<PixelExplanation> explain_pixel(const Scene& scene, int x, int y) {
  if (x < 0 || y < 0 || x >= scene.width || y >= scene.height) return std::nullopt;
  glm::mat4 view = scene.camera.view_matrix();
  glm::mat4 projection = scene.camera.projection_matrix(float(scene.width) / float(std::max(scene.height, 1)));
  glm::mat4 inverse_projection = glm::inverse(projection);
  // The pixel centre in normalized device coordinates (GL's y axis points up).
  double nx = (x + 0.5) / scene.width * 2.0 - 1.0;
  double ny = 1.0 - (y + 0.5) / scene.height * 2.0;
  glm::vec4 near_point = inverse_projection * glm::vec4(float(nx), float(ny), -1.0f, 1.0f);
  glm::vec4 far_point = inverse_projection * glm::vec4(float(nx), float(ny), 1.0f, 1.0f);
  glm::dvec3 origin = glm::dvec3(glm::vec3(near_point) / near_point.w);
  glm::dvec3 dir = glm::normalize(glm::dvec3(glm::vec3(far_point) / far_point.w) - origin);

  Hit best;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& obj = scene.objects[o];
    if (!obj.mesh) continue;
    glm::mat4 modelview = view * obj.model;
    const Mesh& m = *obj.mesh;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const Triangle& tri = m.triangles[t];
      glm::dvec3 p[3];
      for (int k = 0; k < 3; ++k) p[k] = glm::dvec3(glm::vec3(modelview * glm::vec4(m.positions[tri[k]], 1.0f)));
      double d, u, v;
      if (intersect(origin, dir, p[0], p[1], p[2], d, u, v) && d < best.t) {
        best = {float(d), int(o), t, float(u), float(v)};
      }
    }
  }
  if (best.object < 0) return std::nullopt;

  const SceneObject& obj = scene.objects[std::size_t(best.object)];
  const Mesh& m = *obj.mesh;
  const Triangle& tri = m.triangles[best.triangle];
  glm::mat4 modelview = view * obj.model;
  glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(modelview)));
  float w0 = 1.0f - best.u - best.v;
  glm::vec3 eye[3];
  for (int k = 0; k < 3; ++k) eye[k] = glm::vec3(modelview * glm::vec4(m.positions[tri[k]], 1.0f));
  // Facing as the rasterizer decides it: counter-clockwise in window space is the front.
  glm::vec4 c[3];
  for (int k = 0; k < 3; ++k) c[k] = projection * glm::vec4(eye[k], 1.0f);
  glm::vec2 w[3];
  for (int k = 0; k < 3; ++k) w[k] = glm::vec2(c[k]) / c[k].w;
  float area = (w[1].x - w[0].x) * (w[2].y - w[0].y) - (w[2].x - w[0].x) * (w[1].y - w[0].y);

  PixelExplanation e;
  e.object = obj.name;
  if (e.object.empty()) e.object.append("#").append(std::to_string(best.object));
  e.object_index = best.object;
  e.shading = obj.shading;
  e.lit = obj.lighting;
  e.back_face = area < 0.0f;
  e.depth = best.t;
  e.position = glm::vec3(origin + double(best.t) * dir);
  glm::vec3 n;
  if (m.normals.size() == m.positions.size()) {
    n = w0 * m.normals[tri[0]] + best.u * m.normals[tri[1]] + best.v * m.normals[tri[2]];
    n = normal_matrix * n;
  } else {
    n = glm::cross(eye[1] - eye[0], eye[2] - eye[0]);
  }
  float len = glm::length(n);
  n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
  bool two_side = scene.light_model.two_side;
  const Material& material = e.back_face && two_side && obj.back ? *obj.back : obj.front;
  if (e.back_face && two_side) n = -n;
  e.normal = n;
  std::vector<Light> lights;
  for (const SceneLight& sl : scene.lights) {
    Light l = sl.light;
    if (!sl.eye_space) {  // as render_scene: world-space lights go through the view matrix
      l.position = view * l.position;
      l.spot_direction = glm::mat3(view) * l.spot_direction;
    }
    lights.push_back(l);
  }
  e.breakdown = explain_point(scene.light_model, lights, material, {e.position, n, nullptr});
  return e;
}

}  // namespace shadelab
