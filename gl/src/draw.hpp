// The vertex path shared by glBegin/glEnd and the vertex arrays: per-vertex transformation and
// lighting with the core's light_point, then primitives handed to the core's draw_triangles.
// It never rasterizes or shades pixels itself.
#pragma once

#include <glm/vec4.hpp>

#include "gl/src/context.hpp"

namespace shadelab::gl {

/// Vertices gathered before a long primitive is drawn part way (bounds memory).
inline constexpr std::size_t kFlushVertices = 1u << 16;

/// Starts a primitive of a valid glBegin `mode`: fixes the transforms and the enabled lights.
void begin_primitive(GlContext& c, GLenum mode);

/// Transforms `object_position` by the modelview, lights it with the current normal, colour
/// and material (or takes the current colour when lighting is off), and adds it.
void emit_vertex(GlContext& c, const glm::vec4& object_position);

/// Draws what is left of the primitive, ends it and updates the caller's buffer.
void end_primitive(GlContext& c);

}  // namespace shadelab::gl
