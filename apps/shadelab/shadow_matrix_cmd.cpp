// `shadelab shadow-matrix`: prints the lecture's planar shadow matrix for a plane and a light,
// as its M[16] assignments and as a 4x4 matrix, for teaching.
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "shadelab/shadow.hpp"

namespace shadelab::cli {

namespace {

struct ShadowArgs {
  std::vector<float> plane{0, 0, 1, 5};
  std::vector<float> direction, point;
};

int run(const ShadowArgs& a) {
  if (a.direction.empty() == a.point.empty()) {
    std::cerr << "shadelab shadow-matrix: give exactly one of --direction and --point\n";
    return kExitBadInput;
  }
  Plane plane(a.plane[0], a.plane[1], a.plane[2], a.plane[3]);
  bool directional = !a.direction.empty();
  const std::vector<float>& l = directional ? a.direction : a.point;
  glm::vec3 v(l[0], l[1], l[2]);
  float denom = directional ? glm::dot(glm::vec3(plane), v) : plane.w + glm::dot(glm::vec3(plane), v);
  if (denom == 0.0f) {
    std::cerr << "shadelab shadow-matrix: "
              << (directional ? "the light direction is parallel to the plane"
                              : "the light lies on the plane")
              << ": no shadow projection exists\n";
    return kExitBadInput;
  }
  glm::mat4 m = directional ? directional_light_shadow(v, plane) : point_light_shadow(v, plane);
  std::printf("// plane %gx + %gy + %gz + %g = 0, %s (%g, %g, %g)\n", plane.x, plane.y, plane.z,
              plane.w, directional ? "directional light toward" : "point light at", v.x, v.y, v.z);
  std::printf("// %s\n", directional ? "directionalLightShadow (SPEC section 6)"
                                     : "translate(l) * pointSourceShadow * translate(-l) (SPEC section 6)");
  std::printf("GLfloat M[16];\n");
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) std::printf("M[%2d] = %10.6g;  ", col * 4 + row, m[col][row]);
    std::printf("\n");
  }
  std::printf("\n// as a matrix acting on (x, y, z, 1):\n");
  for (int row = 0; row < 4; ++row) {
    std::printf("| %10.6g %10.6g %10.6g %10.6g |\n", m[0][row], m[1][row], m[2][row], m[3][row]);
  }
  return kExitOk;
}

}  // namespace

Action add_shadow_matrix_command(CLI::App& app) {
  auto a = std::make_shared<ShadowArgs>();
  CLI::App* cmd = app.add_subcommand("shadow-matrix", "Print the lecture's planar shadow matrix");
  cmd->add_option("--plane", a->plane, "Plane a,b,c,d of a x + b y + c z + d = 0")
      ->delimiter(',')->expected(4)->capture_default_str();
  cmd->add_option("--direction", a->direction, "Directional light toward dx,dy,dz")
      ->delimiter(',')->expected(3);
  cmd->add_option("--point", a->point, "Point light at lx,ly,lz")->delimiter(',')->expected(3);
  cmd->footer("Examples (the lecture's plane z + 5 = 0):\n"
              "  shadelab shadow-matrix --plane 0,0,1,5 --direction 1,1,1\n"
              "  shadelab shadow-matrix --plane 0,0,1,5 --point 2,3,4");
  return [a] { return run(*a); };
}

}  // namespace shadelab::cli
