// Shadow maps for a scene's lights (private to the scene front end): depth drawn from each
// light that casts shadows. It only builds the maps; lighting reads them through
// ShadowMap::visibility.
#pragma once

#include <vector>

#include "shadelab/pipeline.hpp"
#include "shadelab/scene.hpp"

namespace shadelab::detail {

/// One map per light (size 0 for lights without "shadow"); empty when no light casts shadows.
/// `view` is the camera's view matrix: maps are looked up with camera eye-space points.
std::vector<ShadowMap> build_shadow_maps(const Scene& scene, const glm::mat4& view);

}  // namespace shadelab::detail
