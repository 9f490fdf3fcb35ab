// --set / --vary expressions: each input line is an override ("key.path=value") applied to a
// small valid scene, as `shadelab render --set` and each value of `shadelab sweep --vary` do.
#include <cstdint>
#include <sstream>
#include <string>

#include "fuzz_util.hpp"
#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"

namespace {

const char* kScene = R"({
  "image": {"width": 16, "height": 12},
  "lights": [{"position": [1, 1, 1, 0]}, {"position": [0, 2, 2, 1], "spot": {"cutoff": 30}}],
  "materials": {"red": {"diffuse": [0.8, 0.1, 0.1], "specular": [1, 1, 1], "shininess": 20}},
  "objects": [{"name": "ball", "shape": {"type": "sphere", "slices": 8, "stacks": 4}, "material": "red"},
              {"shape": "cube", "transform": {"translate": [1, 0, 0]}}]
})";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  shadelab::LoadOptions options;
  options.max_pixels = 64 * 64;
  options.max_triangles = 20000;
  options.max_lights = 16;
  options.confine_files = true;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line) && options.overrides.size() < 8;) {
    options.overrides.push_back(line);
  }
  shadelab::LoadResult r = shadelab::parse_scene(kScene, "fuzz.json", shadelab::fuzz::scratch().string(), options);
  if (!r.scene) return 0;
  shadelab::RenderOptions render;
  render.threads = 1;
  (void)shadelab::render_scene(*r.scene, render);
  return 0;
}
