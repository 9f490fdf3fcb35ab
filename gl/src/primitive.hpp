// How OpenGL's polygon primitives fall apart into triangles (GL 1.1 section 2.6.1): which
// vertices form each triangle, in an order that keeps the primitive's winding, and which
// vertex is the provoking one (its colour is the flat-shaded colour, section 2.13.7).
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
