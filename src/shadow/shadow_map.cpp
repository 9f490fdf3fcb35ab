// Shadow-map lookups: a point is moved along its normal by about a texel (the automatic,
// slope-aware bias that keeps lit surfaces free of acne), projected into the light's map and
// compared with (2 pcf + 1)^2 neighbouring depths (percentage-closer filtering).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "shadelab/pipeline.hpp"

namespace shadelab {

float ShadowMap::visibility(const glm::vec3& p, const glm::vec3& n) const {
  if (size <= 0 || faces.empty()) return 1.0f;
  float texel = perspective ? texel_at_unit * glm::length(p - light_eye) : texel_at_unit;
  glm::vec3 q = bias < 0.0f ? p + n * (2.0f * texel) : p;
  float depth_bias = bias < 0.0f ? 1e-5f : bias;
  for (const Face& f : faces) {
    glm::vec4 c = f.eye_to_clip * glm::vec4(q, 1.0f);
    if (c.w <= 0.0f) continue;
    float x = c.x / c.w, y = c.y / c.w, z = c.z / c.w;
    if (std::abs(x) > 1.0f || std::abs(y) > 1.0f) continue;  // another face, or outside the map
    if (z > 1.0f) return 1.0f;  // beyond everything the map saw
    float u = (x * 0.5f + 0.5f) * size, v = (y * 0.5f + 0.5f) * size;
    float d = z * 0.5f + 0.5f - depth_bias;
    int iu = int(std::floor(u)), iv = int(std::floor(v)), lit = 0, total = 0;
    for (int dy = -pcf; dy <= pcf; ++dy) {
      for (int dx = -pcf; dx <= pcf; ++dx) {
        int tu = std::clamp(iu + dx, 0, size - 1), tv = std::clamp(iv + dy, 0, size - 1);
        lit += d <= f.depth[std::size_t(tv) * size + tu];
        ++total;
      }
    }
    return float(lit) / float(total);
  }
  return 1.0f;  // outside every face: the map does not cover it, so nothing occludes it
}

}  // namespace shadelab
