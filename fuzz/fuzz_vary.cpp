// `shadelab sweep --vary` expressions: the first input line is one KEY=V1,V2,... expression,
// the second (when present) another, as a user gives them; whatever parses is swept over a
// small scene and laid out as a contact sheet, as `shadelab sweep` does.
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "fuzz_util.hpp"
#include "shadelab/contact_sheet.hpp"
#include "sweep.hpp"

namespace {

const char* kScene = R"({
  "image": {"width": 12, "height": 8},
  "lights": [{"position": [1, 1, 1, 0]}, {"position": [0, 2, 2, 1], "spot": {"cutoff": 30}}],
  "materials": {"red": {"diffuse": [0.8, 0.1, 0.1], "specular": [1, 1, 1], "shininess": 20}},
  "objects": [{"name": "ball", "shape": {"type": "sphere", "slices": 8, "stacks": 4}, "material": "red"}]
})";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string scene = [] {
    std::string path = (shadelab::fuzz::scratch() / "sweep.json").string();
    std::ofstream(path) << kScene;
    return path;
  }();
  static const std::unique_ptr<shadelab::Font> font = shadelab::Font::load(shadelab::Font::kDefaultPath, nullptr);
  if (!font) __builtin_trap();  // fonts-dejavu-core is part of the set-up
  shadelab::cli::SweepRequest request;
  request.scene = scene;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  std::size_t cells = 1;
  for (std::string line; std::getline(lines, line) && request.vary.size() < 2;) {
    shadelab::cli::Variation v;
    std::string error;
    if (!shadelab::cli::parse_variation(line, v, &error)) {
      if (error.empty()) __builtin_trap();  // a refusal always says why
      return 0;
    }
    if (v.values.empty()) __builtin_trap();
    cells *= v.values.size();
    request.vary.push_back(std::move(v));
  }
  if (request.vary.empty() || cells > 16) return 0;  // keep each input's sweep small
  shadelab::Diagnostics diags;
  std::optional<shadelab::Image> sheet = shadelab::cli::run_sweep(request, *font, diags, nullptr);
  if (!sheet && diags.items().empty()) __builtin_trap();  // a failed sweep always says why
  return 0;
}
