// Named material presets: the lecture's materials and the classic OpenGL material table
// (brass ... yellow rubber). Lookup only; scenes refer to presets by name.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "shadelab/material.hpp"

namespace shadelab {

struct MaterialPreset {
  std::string name;         ///< e.g. "brass", "shiny_red"
  std::string description;  ///< one line: where it comes from
  Material material;
};

/// Every preset, in a stable order (the lecture's first, then the classic table).
const std::vector<MaterialPreset>& material_presets();

/// The preset called `name`, if any.
std::optional<Material> find_material_preset(const std::string& name);

/// The preset names, in the same order as material_presets().
std::vector<std::string> material_preset_names();

}  // namespace shadelab
