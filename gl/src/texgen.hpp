// Texture coordinate generation for the vertex path (GL 1.1 section 2.10.4): the coordinates
// glTexGen's enabled modes make for one vertex. No state changes here.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/src/context.hpp"

namespace shadelab::gl {

/// Whether an enabled coordinate uses GL_SPHERE_MAP, GL_NORMAL_MAP or GL_REFLECTION_MAP
/// (which read the eye-space normal).
bool texgen_needs_normal(const TextureUnitState& t);

/// `current` with each enabled coordinate replaced by its generated value: object linear
/// from the object-space position, eye linear from the eye-space one, sphere map (s, t) and
/// reflection map (s, t, r) from the eye-space position and normal, normal map (s, t, r) the
/// eye-space normal (the normal transformed, and normalized or rescaled as
/// enabled; read only when texgen_needs_normal). The texture matrix applies afterwards.
glm::vec4 generate_texcoords(const TextureUnitState& t, glm::vec4 current, const glm::vec4& object, const glm::vec4& eye,
                             const glm::vec3& eye_normal);

}  // namespace shadelab::gl
