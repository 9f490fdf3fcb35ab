// Triangle decomposition of GL_TRIANGLES .. GL_POLYGON (GL 1.1 section 2.6.1) with provoking
// vertices (section 2.13.7), and how much of a long primitive can be drawn before glEnd.
#include "gl/src/primitive.hpp"

namespace shadelab::gl {

bool is_polygon_mode(GLenum mode) { return mode >= GL_TRIANGLES && mode <= GL_POLYGON; }

namespace {

void add(std::vector<PrimitiveTriangle>& out, std::uint32_t a, std::uint32_t b, std::uint32_t c,
         std::uint32_t provoking) {
  out.push_back({{a, b, c}, provoking});
}

}  // namespace

void decompose(GLenum mode, std::uint32_t n, bool odd_strip_start, QuadSplit quad_split,
               std::vector<PrimitiveTriangle>& out) {
  switch (mode) {
    case GL_TRIANGLES:
      for (std::uint32_t i = 0; i + 3 <= n; i += 3) add(out, i, i + 1, i + 2, i + 2);
      break;
    case GL_TRIANGLE_STRIP:
      // Odd triangles swap their first two vertices to keep the strip's winding.
      for (std::uint32_t i = 0; i + 3 <= n; ++i) {
        bool odd = ((i & 1u) != 0) != odd_strip_start;
        if (odd) add(out, i + 1, i, i + 2, i + 2);
        else add(out, i, i + 1, i + 2, i + 2);
      }
      break;
    case GL_TRIANGLE_FAN:
      for (std::uint32_t i = 1; i + 2 <= n; ++i) add(out, 0, i, i + 1, i + 1);
      break;
    case GL_QUADS:
      // Quad (a, b, c, d): triangles (a, b, c), (a, c, d), or (a, b, d), (b, c, d); d provokes.
      for (std::uint32_t i = 0; i + 4 <= n; i += 4) {
        if (quad_split == QuadSplit::kFromFirst) {
          add(out, i, i + 1, i + 2, i + 3);
          add(out, i, i + 2, i + 3, i + 3);
        } else {
          add(out, i, i + 1, i + 3, i + 3);
          add(out, i + 1, i + 2, i + 3, i + 3);
        }
      }
      break;
    case GL_QUAD_STRIP:
      // Quad i has the boundary 2i, 2i+1, 2i+3, 2i+2; 2i+3 provokes it.
      for (std::uint32_t i = 0; i + 4 <= n; i += 2) {
        add(out, i, i + 1, i + 3, i + 3);
        add(out, i, i + 3, i + 2, i + 3);
      }
      break;
    case GL_POLYGON:
      for (std::uint32_t i = 1; i + 2 <= n; ++i) add(out, 0, i, i + 1, 0);
      break;
    default:
      break;  // points and lines make no polygons
  }
}

PartialFlush partial_flush(GLenum mode, std::uint32_t n) {
  switch (mode) {
    case GL_TRIANGLES: return {n - n % 3, false, n % 3};
    case GL_QUADS: return {n - n % 4, false, n % 4};
    case GL_TRIANGLE_STRIP: return n >= 3 ? PartialFlush{n, false, 2} : PartialFlush{};
    case GL_QUAD_STRIP:
      if (n < 4) return {};
      return n % 2 == 0 ? PartialFlush{n, false, 2} : PartialFlush{n - 1, false, 3};
    case GL_TRIANGLE_FAN:
    case GL_POLYGON: return n >= 3 ? PartialFlush{n, true, 1} : PartialFlush{};
    default: return {n, false, 0};  // points and lines: nothing to keep
  }
}

}  // namespace shadelab::gl
