// Triangle meshes as the pipeline consumes them: object-space vertices with optional
// normals, texture coordinates and colours. No transforms, no lighting here.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace shadelab {

/// Indices of one triangle, counter-clockwise seen from its front. The LAST index is the
/// provoking vertex (OpenGL's rule for triangles, strips, fans turned around, quads): flat
/// shading lights the triangle once, at that vertex.
using Triangle = std::array<std::uint32_t, 3>;

/// `normals`, `texcoords` and `colors` are either empty or as long as `positions`.
struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;    ///< unit length, object space
  std::vector<glm::vec2> texcoords;  ///< (s, t)
  std::vector<glm::vec4> colors;     ///< RGBA per vertex (used when lighting is off)
  std::vector<Triangle> triangles;
};

/// Fills `normals` with smooth vertex normals: each vertex gets the normalized sum of the unit
/// normals of the faces that use it (a vertex shared by no face gets (0, 0, 1)).
void compute_smooth_normals(Mesh& mesh);

/// Appends a quad (a, b, c, d counter-clockwise) as two triangles (a, b, d) and (b, c, d),
/// both with d as provoking vertex, as OpenGL splits GL_QUADS.
void add_quad(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d);

}  // namespace shadelab
