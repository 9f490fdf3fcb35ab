// The vertex path's state in a context (GL 1.1 sections 2.6-2.7): the primitive between
// glBegin and glEnd with what glBegin fixed for it (transforms, enabled lights), its vertices
// as they arrived, and the buffers the two vertex paths (draw.cpp's glBegin/glEnd and
// array_mesh.cpp's vertex arrays) reuse from draw to draw. Plain data; those two files fill
// and read it, and nothing here transforms, lights or draws.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/src/capture.hpp"
#include "gl/src/primitive.hpp"
#include "shadelab/detail/default_init.hpp"
#include "shadelab/light.hpp"
#include "shadelab/texture.hpp"
#include "shadelab/mesh.hpp"
#include "shadelab/vertex_input.hpp"

namespace shadelab::gl {

/// One vertex of a primitive being specified: its eye-space position and normal (lighting
/// state cannot change between glBegin and glEnd).
struct PrimitiveVertex {
  glm::vec4 eye;
  glm::vec3 normal{0.0f};  // eye space, or as given while Primitive::object_normals
};

/// A vertex's colours, lit as it arrived (or the current colour, unlit).
struct VertexColors {
  glm::vec4 front, back;
  glm::vec3 front_secondary, back_secondary;
};

/// The primitive between glBegin and glEnd, with what stays fixed while it is specified.
struct Primitive {
  bool active = false;  // inside glBegin/glEnd
  GLenum mode = GL_TRIANGLES;
  std::vector<PrimitiveVertex> vertices;
  // The vertices' colours, one per vertex, unless lighting is deferred (then empty): records
  // of a lit primitive are less than half as large, to write in glVertex and read in glEnd.
  std::vector<VertexColors> colors;
  // Per texture unit, the vertices' texture coordinates (s, t, r, q) after generation and the
  // unit's texture matrix, one per vertex while the unit's bit is in `textured` (else empty);
  // q divides per fragment.
  std::array<std::vector<glm::vec4>, kMaxTextureUnits> texcoords;
  // The vertices' fog coordinates (their absolute values), one per vertex while fog uses them
  // (GL_FOG_COORDINATE source, fixed at glBegin), else empty.
  std::vector<float> fog_coords;
  bool fog_coordinates = false;
  bool odd_strip_start = false;  // a flushed triangle strip continues with an odd triangle
  // Begun by a display list being executed: llvmpipe then splits quads from their second
  // vertex (docs/gl-conformance.md).
  bool in_list = false;
  // Drawn by glDrawElements: llvmpipe then splits quads from their second vertex
  // (docs/gl-conformance.md).
  bool from_elements = false;
  bool continued = false;  // a part of the primitive was drawn before (line stipple, loops)
  // Edge flags of the vertices (section 2.6.2), one per vertex while the polygon modes draw
  // edges (polygon primitives with a face in GL_LINE or GL_POINT mode), else empty.
  std::vector<std::uint8_t> edges;
  bool edge_flags = false;
  std::uint32_t stipple_counter = 0;  // the line stipple's position across parts
  // Lighting left to the pipeline (SIMD, at draw time): while the material stays what it was
  // at glBegin. A material change inside the primitive lights the vertices so far and ends
  // the deferral (settle_lighting).
  bool deferred_lighting = false;
  // While lighting is deferred (smooth shading): normals kept as given and transformed to eye
  // space by draw_vertices, not by each glVertex call.
  bool object_normals = false;
  // The units whose texture coordinates are kept (textured_units: a texture applies, or
  // GL_FEEDBACK reports unit 0's).
  unsigned textured = 0;
  // Fixed at glBegin:
  glm::mat4 modelview{1.0f};
  glm::mat3 normal_matrix{1.0f};
  float rescale = 1.0f;
  std::array<bool, kMaxTextureUnits> identity_texture_matrix{};
  std::array<glm::mat4, kMaxTextureUnits> texture_matrix{};
  std::vector<Light> lights;  // enabled lights only
  // A frame being captured (capture.hpp), lit: each vertex's materials, as it arrived.
  bool capture_lit = false;
  std::vector<VertexMaterials> capture_materials;
};

/// Reused buffers of the vertex-array path (array_mesh.cpp's draw_array_mesh): one entry per
/// array element from the draw's smallest index to its largest, so a shared vertex is
/// transformed and lit once.
// Every array is written in full after each resize (resizing zeroes nothing).
struct ArrayScratch {
  detail::ScratchVector<glm::vec4> positions, colors;
  detail::ScratchVector<glm::vec3> normals;
  // Per texture unit: (s, t, r, q) after the unit's texture matrix, and before it.
  std::array<detail::ScratchVector<glm::vec4>, kMaxTextureUnits> texcoords, raw_texcoords;
  detail::ScratchVector<glm::vec3> secondary;      // GL_COLOR_SUM unlit: clamped secondary colours
  detail::ScratchVector<float> fog;                // GL_FOG_COORDINATE fog: |fog coordinate|
  detail::ScratchVector<std::uint32_t> sequence;  // the draw's k-th element - the smallest element
  detail::ScratchVector<std::uint8_t> finite;     // per vertex: its clip coordinates are finite
  detail::ScratchVector<Triangle> triangles;
  std::vector<PrimitiveTriangle> pieces;
};

/// Reused buffers of the glBegin/glEnd path (draw.cpp's draw_vertices): the arrays of one
/// draw_triangles call, kept across primitives so that drawing allocates nothing once they
/// have grown.
struct ImmediateScratch {
  // Every element is written after each resize (Batch::set): growing costs no zeroing.
  detail::ScratchVector<glm::vec4> positions, colors, back_colors;
  detail::ScratchVector<glm::vec3> normals, secondary, back_secondary;
  std::array<detail::ScratchVector<glm::vec4>, kMaxTextureUnits> texcoords;  // per texture unit
  detail::ScratchVector<float> fog;
  std::vector<Triangle> triangles;
  std::vector<PrimitiveTriangle> pieces;
  std::vector<std::uint8_t> triangle_flags;  // polygon modes: per triangle, its edges
  std::vector<UnfilledTriangle> unfilled;
  std::vector<PrimitiveLine> line_pieces;
  std::vector<LineSegment> lines;
  std::vector<std::uint32_t> points;
  std::vector<std::uint8_t> finite;  // per vertex: its clip coordinates are finite
  std::vector<VertexMaterials> capture_materials;  // per vertex of the batch, when captured
};

}  // namespace shadelab::gl
