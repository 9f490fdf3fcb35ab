// How OpenGL's primitives fall apart into triangles and segments (GL 1.1 section 2.6.1): which
// vertices form each triangle, in an order that keeps the primitive's winding, and which
// vertex is the provoking one (its colour is the flat-shaded colour, section 2.13.7); which
// edges of each triangle belong to the polygon (section 3.5.4's polygon modes).
// Pure index arithmetic: no state, no drawing.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>

namespace shadelab::gl {

/// One triangle of a primitive: vertex indices counter-clockwise when the primitive is, and
/// the provoking vertex (not necessarily one of the three: a quad's first triangle).
struct PrimitiveTriangle {
  std::uint32_t v[3];
  std::uint32_t provoking;
};

/// GL_TRIANGLES .. GL_POLYGON, the modes that make polygons.
bool is_polygon_mode(GLenum mode);

/// Which diagonal splits a GL_QUADS quad a b c d. Mesa's llvmpipe uses both: a-c when it
/// hands the quads to its rasterizer directly, b-d when they go through its draw pipeline
/// (some vertex of the draw outside the view volume). See docs/gl-conformance.md.
enum class QuadSplit { kFromFirst, kFromSecond };

/// Appends the triangles of `count` vertices of `mode`. Polygons are split into fans from
/// their first vertex, quad-strip quads along the diagonal from their first to their last
/// vertex, and quads as `quad_split` says, the way Mesa's llvmpipe splits them (which matters
/// for smooth shading). Provoking vertices: the last of each triangle, strip triangle, fan
/// triangle, quad and quad-strip quad; the first vertex of a polygon. `odd_strip_start`: the
/// first triangle of a triangle strip is an odd one (a strip continued after a partial flush).
void decompose(GLenum mode, std::uint32_t count, bool odd_strip_start, QuadSplit quad_split,
               std::vector<PrimitiveTriangle>& out);

/// GL_LINES, GL_LINE_LOOP and GL_LINE_STRIP.
inline bool is_line_mode(GLenum mode) {
  return mode == GL_LINES || mode == GL_LINE_LOOP || mode == GL_LINE_STRIP;
}

/// One segment of a line primitive: its vertices (the second provokes) and whether the line
/// stipple starts again with it (each GL_LINES segment, the first of a strip or loop).
struct PrimitiveLine {
  std::uint32_t v[2];
  bool restart;
};

/// Appends the segments of `count` vertices of GL_LINES, GL_LINE_STRIP or GL_LINE_LOOP.
/// `continued`: the vertices continue a strip or loop drawn in part before: no restart, and a
/// loop's vertex 0 (its first, kept for closing it) is not part of the strip; `close`: a
/// loop's closing segment, from its last vertex to vertex 0, is added.
void decompose_lines(GLenum mode, std::uint32_t count, bool continued, bool close,
                     std::vector<PrimitiveLine>& out);

/// A triangle of a polygon primitive drawn with some face in GL_LINE or GL_POINT mode, in the
/// vertex order Mesa's draw pipeline gives it (which decides the order and direction its edges
/// are drawn in): edges are TriangleFlag bits (kEdge01 for v[0] to v[1], ...), set for the
/// polygon's own edges; `restart` starts the line stipple again (every triangle of GL_TRIANGLES
/// and the strips and fans, the first of each quad and of a polygon). The last vertex
/// provokes.
struct UnfilledTriangle {
  std::uint32_t v[3];
  std::uint8_t flags;
};

/// Appends the triangles of `count` vertices of a polygon mode, decomposed as Mesa's draw
/// pipeline does: quads (a, b, d) and (b, c, d), quad-strip quads (c, a, d) and (a, b, d),
/// polygons (v[i+1], v[i+2], v[0]), strips and fans as decompose().
void decompose_unfilled(GLenum mode, std::uint32_t count, bool odd_strip_start,
                        std::vector<UnfilledTriangle>& out);

/// When a long primitive is drawn before glEnd: how many leading vertices `count` may be
/// drawn now (0: none yet) and which of them the rest of the primitive still needs
/// (`keep_first`: vertex 0; `keep_last`: that many last vertices).
struct PartialFlush {
  std::uint32_t drawable = 0;
  bool keep_first = false;
  std::uint32_t keep_last = 0;
};
PartialFlush partial_flush(GLenum mode, std::uint32_t count);

}  // namespace shadelab::gl
