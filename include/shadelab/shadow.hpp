// Planar projected shadows (SPEC section 6): the lecture's two matrices that flatten geometry
// onto a plane along a directional light or from a point light. Matrices only; drawing the
// shadow (stencil-masked, offset, blended once) is the renderer's business.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace shadelab {

/// Plane a x + b y + c z + d = 0 as (a, b, c, d).
using Plane = glm::vec4;

/// The lecture's directionalLightShadow: projects p to p + alpha (dx, dy, dz) with
/// alpha = -(a x + b y + c z + d) / (a dx + b dy + c dz), i.e. along the light's direction
/// `dir` = (dx, dy, dz) (pointing toward the light, as GL_POSITION with w = 0) onto `plane`.
/// Column-major like the lecture's M[16]; undefined (w = 0) when dir is parallel to the plane.
glm::mat4 directional_light_shadow(const glm::vec3& dir, const Plane& plane);

/// The lecture's pointSourceShadow wrapped in translate(light) * M * translate(-light):
/// projects p onto `plane` along the line from the point light at `light`.
/// new_d = d + a lx + b ly + c lz; points on the light's side map to w > 0, and points beyond
/// the light (or the light below the plane) give w <= 0, which a renderer must discard.
glm::mat4 point_light_shadow(const glm::vec3& light, const Plane& plane);

}  // namespace shadelab
