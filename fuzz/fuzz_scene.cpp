// Scene files: any bytes through the reader (small limits, files confined to an empty
// folder); whatever parses is rendered at its (small) size on one thread.
#include <cstdint>
#include <string_view>

#include "fuzz_util.hpp"
#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  shadelab::LoadOptions options;
  options.max_pixels = 64 * 64;
  options.max_triangles = 20000;
  options.max_lights = 16;
  options.confine_files = true;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  shadelab::LoadResult r =
      shadelab::parse_scene(text, "fuzz.json", shadelab::fuzz::scratch().string(), options);
  if (!r.scene) return 0;
  shadelab::RenderOptions render;
  render.threads = 1;
  (void)shadelab::render_scene(*r.scene, render);
  return 0;
}
