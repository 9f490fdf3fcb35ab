// "Explain this pixel" as text (`shadelab run --explain`): the surface a pixel shows and every
// term of the lighting equation there, one per line, as the lab's explain panel lays it out.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "shadelab/scene.hpp"

namespace shadelab::cli {

/// The breakdown of pixel (x, y) (from the top left) of `scene`, ending with a newline;
/// `shown`: the pixel as the program's frame shows it (RGB), printed beside the result.
std::string explain_text(const Scene& scene, int x, int y,
                         const std::optional<std::array<std::uint8_t, 3>>& shown);

}  // namespace shadelab::cli
