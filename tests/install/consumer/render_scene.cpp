// A C++ program built against the installed core library through find_package(shadelab): it
// reads a scene from text, renders it with the fast pipeline and encodes the picture as PNG. A
// red sphere lit head-on by a white directional light (no ambient) on a blue background: the
// centre pixel is the diffuse red (N.L = 1), a corner the background. Prints "ok", or what
// differs (exit status 1).
#include <cstdio>
#include <cstdlib>

#include "shadelab/image.hpp"
#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"

namespace {

constexpr const char* kScene = R"({
  "image": {"width": 48, "height": 48, "background": [0, 0, 1]},
  "camera": {"eye": [0, 0, 8], "target": [0, 0, 0], "fovy": 20},
  "light_model": {"ambient": [0, 0, 0, 1]},
  "lights": [{"position": [0, 0, 1, 0], "diffuse": [1, 1, 1, 1]}],
  "objects": [{"shape": {"type": "sphere", "radius": 1, "slices": 48, "stacks": 24},
               "material": {"ambient": [0, 0, 0, 1], "diffuse": [1, 0, 0, 1]},
               "shading": "phong"}]
})";

bool expect_pixel(const shadelab::Image& image, int x, int y, int r, int g, int b) {
  const std::uint8_t* p = image.pixel(x, y);
  if (std::abs(p[0] - r) <= 2 && std::abs(p[1] - g) <= 2 && std::abs(p[2] - b) <= 2) return true;
  std::printf("pixel (%d, %d) is (%d, %d, %d), expected (%d, %d, %d)\n", x, y, p[0], p[1], p[2], r,
              g, b);
  return false;
}

}  // namespace

int main() {
  const shadelab::LoadResult loaded = shadelab::parse_scene(kScene, "inline.json", ".");
  if (!loaded.scene) {
    std::printf("the scene was refused:\n%s", loaded.diagnostics.to_string().c_str());
    return 1;
  }
  const shadelab::Image image = shadelab::render_scene(*loaded.scene);
  bool ok = image.width == 48 && image.height == 48;
  ok = ok && expect_pixel(image, 24, 24, 255, 0, 0) && expect_pixel(image, 0, 0, 0, 0, 255);
  const std::vector<std::uint8_t> png = shadelab::encode_png(image);
  ok = ok && png.size() > 8 && png[1] == 'P' && png[2] == 'N' && png[3] == 'G';
  std::printf("%s\n", ok ? "ok" : "FAIL");
  return ok ? 0 : 1;
}
