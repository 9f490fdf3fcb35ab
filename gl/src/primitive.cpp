// Triangle decomposition of GL_TRIANGLES .. GL_POLYGON (GL 1.1 section 2.6.1) with provoking
// vertices (section 2.13.7), Mesa's decomposition with edge flags for the polygon modes
// (section 3.5.4), line segments, and how much of a long primitive can be drawn before glEnd.
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

void decompose_lines(GLenum mode, std::uint32_t n, bool continued, bool close,
                     std::vector<PrimitiveLine>& out) {
  if (mode == GL_LINES) {
    for (std::uint32_t i = 0; i + 2 <= n; i += 2) out.push_back({{i, i + 1}, true});
    return;
  }
  const std::uint32_t first = mode == GL_LINE_LOOP && continued ? 1 : 0;
  for (std::uint32_t i = first; i + 2 <= n; ++i) out.push_back({{i, i + 1}, i == 0 && !continued});
  if (mode == GL_LINE_LOOP && close && n >= 2) out.push_back({{n - 1, 0}, false});
}

namespace {

constexpr std::uint8_t kAll = 7, kE01 = 1, kE12 = 2, kE20 = 4, kRestart = 8;

void add(std::vector<UnfilledTriangle>& out, std::uint32_t a, std::uint32_t b, std::uint32_t c,
         std::uint8_t flags) {
  out.push_back({{a, b, c}, flags});
}

}  // namespace

void decompose_unfilled(GLenum mode, std::uint32_t n, bool odd_strip_start,
                        std::vector<UnfilledTriangle>& out) {
  switch (mode) {
    case GL_QUADS:
      for (std::uint32_t i = 0; i + 4 <= n; i += 4) {
        add(out, i, i + 1, i + 3, kRestart | kE01 | kE20);
        add(out, i + 1, i + 2, i + 3, kE01 | kE12);
      }
      break;
    case GL_QUAD_STRIP:
      for (std::uint32_t i = 0; i + 4 <= n; i += 2) {
        add(out, i + 2, i, i + 3, kRestart | kE01 | kE20);
        add(out, i, i + 1, i + 3, kE01 | kE12);
      }
      break;
    case GL_POLYGON:
      for (std::uint32_t i = 0; i + 3 <= n; ++i) {
        std::uint8_t flags = kE01;
        if (i == 0) flags |= kRestart | kE20;
        if (i + 3 == n) flags |= kE12;
        add(out, i + 1, i + 2, 0, flags);
      }
      break;
    default: {  // triangles, strips and fans: every edge, the stipple restarting each time
      std::vector<PrimitiveTriangle> tris;
      decompose(mode, n, odd_strip_start, QuadSplit::kFromFirst, tris);
      for (const PrimitiveTriangle& t : tris) add(out, t.v[0], t.v[1], t.v[2], kRestart | kAll);
      break;
    }
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
    case GL_LINES:
      return {n - n % 2, false, n % 2};
    case GL_LINE_STRIP:
      return n >= 2 ? PartialFlush{n, false, 1} : PartialFlush{};
    case GL_LINE_LOOP:
      return n >= 2 ? PartialFlush{n, true, 1} : PartialFlush{};
    default:
      return {n, false, 0};  // points: nothing to keep
  }
}

}  // namespace shadelab::gl
