// Decides, once per draw, what the fast pipeline's stages must carry and compute: the varying
// layout, which lighting runs where, and whether fragments need the per-fragment reference
// operations. No drawing here.
#pragma once

#include <vector>

#include "fast/draw_job.hpp"

namespace shadelab::fast {

/// Fills job.plan from the job's fragment and shade state and vertex input.
void make_plan(DrawJob& job);

/// The reference's per-light shadow visibility at eye-space point p with normal n (draw.cpp's
/// shadow_visibility), in `buffer`; null when no light has a shadow map.
const float* shadow_visibility(const ShadeState& shade, const glm::vec3& p, const glm::vec3& n,
                               std::vector<float>& buffer);

/// True when some light has a shadow map that can darken it.
bool has_shadow_maps(const ShadeState& shade);

}  // namespace shadelab::fast
