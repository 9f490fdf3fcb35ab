// The explain panel as text: columns of red, green and blue, the light terms indented under
// their light, values to three decimals and the result in 8-bit units as the frame stores it.
#include "explain_text.hpp"

#include <cmath>
#include <cstdio>

#include "shadelab/explain.hpp"

namespace shadelab::cli {
namespace {

std::string rgb(const glm::vec3& c) {
  char b[64];
  std::snprintf(b, sizeof b, "%7.3f %7.3f %7.3f", double(c.r), double(c.g), double(c.b));
  return b;
}

std::string bytes(const glm::vec3& c) {
  auto byte = [](float v) { return int(std::lround(std::fmin(std::fmax(v, 0.0f), 1.0f) * 255.0f)); };
  return "(" + std::to_string(byte(c.r)) + ", " + std::to_string(byte(c.g)) + ", " + std::to_string(byte(c.b)) + ")";
}

std::string line(const std::string& label, const glm::vec3& c, const std::string& after = "") {
  std::string s = "  " + label;
  if (s.size() < 34) s.resize(34, ' ');
  return s + rgb(c) + after + "\n";
}

std::string vec(const glm::vec3& v) {
  char b[80];
  std::snprintf(b, sizeof b, "(%.3f, %.3f, %.3f)", double(v.x), double(v.y), double(v.z));
  return b;
}

const char* shading_name(ShadingMode m) {
  return m == ShadingMode::kFlat ? "flat" : m == ShadingMode::kGouraud ? "gouraud" : "phong";
}

}  // namespace

std::string explain_text(const Scene& scene, int x, int y,
                         const std::optional<std::array<std::uint8_t, 3>>& shown) {
  const std::string where = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
  std::string frame;
  if (shown) {
    frame = "(" + std::to_string((*shown)[0]) + ", " + std::to_string((*shown)[1]) + ", " +
            std::to_string((*shown)[2]) + ")";
  }
  if (x < 0 || y < 0 || x >= scene.width || y >= scene.height) {
    return where + ": outside the " + std::to_string(scene.width) + " x " + std::to_string(scene.height) + " frame\n";
  }
  std::optional<PixelExplanation> e = explain_pixel(scene, x, y);
  if (!e) {
    std::string s = where + ": the background " + bytes(glm::vec3(scene.background));
    return s + (shown ? "; the frame shows " + frame : "") + "\n";
  }
  std::string s = where + ": " + e->object + ", " + shading_name(e->shading) + " shading, " +
                  (e->back_face ? "back" : "front") + " face\n";
  s += "  eye-space point " + vec(e->position) + ", normal " + vec(e->normal) + "\n";
  if (!e->lit) {
    s += "  unlit: its colour is the vertex colour, not lighting\n";
    return s + (shown ? "  the frame shows " + frame + "\n" : "");
  }
  const LightingBreakdown& b = e->breakdown;
  s += "  the lighting equation at this point";
  s += e->shading == ShadingMode::kPhong   ? ":\n"
       : e->shading == ShadingMode::kFlat ? " (flat shading gives the triangle one colour, lit at its last vertex):\n"
                                          : " (gouraud shading interpolates the vertices' colours):\n";
  s += line("emission", b.emission);
  s += line("global ambient", b.global_ambient);
  for (const LightTerm& t : b.lights) {
    char head[160];
    std::snprintf(head, sizeof head, "  light %d: attenuation %.3f, spot %.3f, N.L %.3f\n", t.light,
                  double(t.attenuation), double(t.spot), double(t.n_dot_l));
    s += head;
    s += line("  ambient", t.ambient);
    s += line("  diffuse", t.diffuse);
    s += line("  specular", t.specular);
  }
  s += line("sum", b.unclamped);
  const glm::vec3 result(b.result.primary);
  s += line("colour (clamped to 0..1)", result, "  = " + bytes(result));
  if (glm::vec3(b.result.secondary) != glm::vec3(0.0f)) s += line("separate specular", b.result.secondary);
  if (shown) {
    std::string label = "  the frame shows";
    label.resize(34 + 23, ' ');
    s += label + "  = " + frame + "\n";
  }
  return s;
}

}  // namespace shadelab::cli
