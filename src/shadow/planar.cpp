// The lecture's planar shadow matrices (SPEC section 6), written exactly as its M[16] arrays.
#include "shadelab/shadow.hpp"

#include <glm/gtc/type_ptr.hpp>

namespace shadelab {

glm::mat4 directional_light_shadow(const glm::vec3& dir, const Plane& plane) {
  float dx = dir.x, dy = dir.y, dz = dir.z;
  float a = plane.x, b = plane.y, c = plane.z, d = plane.w;
  float m[16];
  m[0] = b * dy + c * dz; m[4] = -b * dx;          m[8] = -c * dx;           m[12] = -d * dx;
  m[1] = -a * dy;         m[5] = a * dx + c * dz;  m[9] = -c * dy;           m[13] = -d * dy;
  m[2] = -a * dz;         m[6] = -b * dz;          m[10] = a * dx + b * dy;  m[14] = -d * dz;
  m[3] = 0;               m[7] = 0;                m[11] = 0;                m[15] = a * dx + b * dy + c * dz;
  return glm::make_mat4(m);
}

glm::mat4 point_light_shadow(const glm::vec3& light, const Plane& plane) {
  float a = plane.x, b = plane.y, c = plane.z, d = plane.w;
  float new_d = d + a * light.x + b * light.y + c * light.z;  // the plane seen from the light
  float m[16] = {1, 0, 0, -a / new_d,  0, 1, 0, -b / new_d,  0, 0, 1, -c / new_d,  0, 0, 0, 0};
  glm::mat4 to_light(1.0f), from_light(1.0f);
  to_light[3] = glm::vec4(light, 1.0f);
  from_light[3] = glm::vec4(-light, 1.0f);
  return to_light * glm::make_mat4(m) * from_light;
}

}  // namespace shadelab
