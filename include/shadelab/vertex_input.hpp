// What one draw is given (part of pipeline.hpp): eye-space vertices with their attributes
// and the triangles, line segments and points over them. Views of the caller's arrays:
// nothing here owns, copies or transforms them.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shadelab/mesh.hpp"
#include "shadelab/texture.hpp"

namespace shadelab {

/// One line segment of a draw: its two vertices; the second provokes (flat shading takes its
/// colour, GL 1.1 section 2.13.7). With kRestartStipple, the line stipple pattern starts
/// again at this segment (each segment of GL_LINES, the first of a strip or loop).
struct LineSegment {
  static constexpr std::uint32_t kRestartStipple = 1;
  std::uint32_t v[2];
  std::uint32_t flags = kRestartStipple;
};

/// Per-triangle flags for polygons drawn in GL_LINE / GL_POINT mode (VertexInput::
/// triangle_flags): which of its edges are edges of the polygon it comes from, with the edge
/// flag of their first vertex set (GL 1.1 section 2.6.2), and whether the line stipple
/// pattern starts again with it.
enum TriangleFlag : std::uint8_t {
  kTriangleEdge01 = 1,  ///< the edge from vertex 0 to vertex 1 (in point mode: vertex 0)
  kTriangleEdge12 = 2,  ///< ... from vertex 1 to vertex 2 (vertex 1)
  kTriangleEdge20 = 4,  ///< ... from vertex 2 to vertex 0 (vertex 2)
  kTriangleEdges = 7,
  kTriangleRestartStipple = 8,
};

/// Vertices in eye space and the triangles over them.
/// - `normals` (unit, eye space) are needed when lighting.
/// - `colors`: per-vertex colours used when lighting is off (empty: `constant_color`).
/// - `back_colors` / `secondary_colors`: optional pre-lit colours for back faces and the
///   separate specular colour, for front ends that light vertices themselves (the GL library).
struct VertexInput {
  std::span<const glm::vec4> positions;
  std::span<const glm::vec3> normals;
  std::span<const glm::vec4> colors;
  std::span<const glm::vec4> back_colors;
  std::span<const glm::vec3> secondary_colors;
  std::span<const glm::vec3> back_secondary_colors;
  /// (s, t, r, q) per vertex for each texture unit: s / q and t / q index the unit's texture,
  /// divided per fragment (GL 1.1 section 3.8), so that projected texture coordinates
  /// interpolate as GL says. Empty: (0, 0, 0, 1).
  std::array<std::span<const glm::vec4>, kMaxTextureUnits> texcoords;
  /// Fog coordinate per vertex (eye-space distance); empty: |z| of `positions`.
  std::span<const float> fog_coords;
  glm::vec4 constant_color{1.0f};
  std::span<const Triangle> triangles;  ///< last index of each is the provoking vertex
  /// Per triangle, TriangleFlag bits for the polygon modes (empty: every edge drawn, the stipple
  /// restarting at each triangle).
  std::span<const std::uint8_t> triangle_flags;
  std::span<const LineSegment> lines;  ///< drawn after the triangles (a draw has one kind)
  std::span<const std::uint32_t> points;
  /// Line stipple across draws: in, the pattern position for a first segment that does not
  /// restart it; out, the position after the last segment (a long GL_LINE_STRIP drawn in
  /// parts). Null: 0 in, nothing out.
  std::uint32_t* stipple_counter = nullptr;
};

}  // namespace shadelab
