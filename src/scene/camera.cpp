// Camera matrices (gluLookAt / gluPerspective / glOrtho equivalents) and OpenGL's default
// lights.
#include <glm/gtc/matrix_transform.hpp>

#include "shadelab/scene.hpp"

namespace shadelab {

glm::mat4 Camera::view_matrix() const { return glm::lookAt(eye, target, up); }

glm::mat4 Camera::projection_matrix(float aspect) const {
  if (matrix) return *matrix;
  if (projection == Projection::kOrthographic) {
    float h = 0.5f * ortho_height, w = h * aspect;
    return glm::ortho(-w, w, -h, h, near_plane, far_plane);
  }
  return glm::perspective(glm::radians(fovy_degrees), aspect, near_plane, far_plane);
}

Light default_light(int index) {
  Light light;
  if (index == 0) {
    light.diffuse = glm::vec4(1.0f);
    light.specular = glm::vec4(1.0f);
  }
  return light;
}

}  // namespace shadelab
