// The link between the context's framebuffer and the caller's OSMesa buffer: the rectangle
// changed since the last flush is copied out at glFinish / glFlush and when the current
// context changes (in the buffer's format, row length and Y direction), the buffer is read in at OSMesaMakeCurrent, and depth values are exported in
// Mesa's layout for OSMesaGetDepthBuffer. No drawing here.
#include <algorithm>
#include <cmath>
#include <cstring>

#include <GL/osmesa.h>

#include "gl/src/context.hpp"
#include "gl/src/osmesa_context.hpp"

namespace shadelab::gl {
namespace {

// Byte positions of R, G, B, A within a pixel of an OSMesa format (-1: absent).
struct Swizzle {
  int bytes;
  int r, g, b, a;
};

Swizzle swizzle_of(GLenum format) {
  switch (format) {
    case OSMESA_BGRA: return {4, 2, 1, 0, 3};
    case OSMESA_ARGB: return {4, 1, 2, 3, 0};
    case OSMESA_RGB: return {3, 0, 1, 2, -1};
    case OSMESA_BGR: return {3, 2, 1, 0, -1};
    default: return {4, 0, 1, 2, 3};
  }
}

// Start of framebuffer row y in the caller's buffer.
unsigned char* user_row(const UserBuffer& u, int y, int bytes) {
  std::size_t row_pixels = std::size_t(u.row_length > 0 ? u.row_length : u.width);
  std::size_t row = std::size_t(u.y_up ? y : u.height - 1 - y);
  return static_cast<unsigned char*>(u.data) + row * row_pixels * std::size_t(bytes);
}

}  // namespace

void mark_dirty(GlContext& c, int x0, int y0, int x1, int y1) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0);
  x1 = std::min(x1, c.fb.width), y1 = std::min(y1, c.fb.height);
  if (x0 >= x1 || y0 >= y1) return;
  DirtyRect& d = c.dirty;
  if (d.empty()) {
    d = {x0, y0, x1, y1};
    return;
  }
  d = {std::min(d.x0, x0), std::min(d.y0, y0), std::max(d.x1, x1), std::max(d.y1, y1)};
}

void present(GlContext& c) {
  DirtyRect d = c.dirty;
  c.dirty = {};
  const UserBuffer& u = c.user;
  if (d.empty() || !u.data) return;
  Swizzle s = swizzle_of(u.format);
  auto rows = [&](std::size_t begin, std::size_t end) {
    for (int y = d.y0 + int(begin); y < d.y0 + int(end); ++y) {
      const std::uint8_t* src = &c.fb.color[(std::size_t(y) * std::size_t(c.fb.width) + std::size_t(d.x0)) * 4];
      unsigned char* dst = user_row(u, y, s.bytes) + std::size_t(d.x0) * std::size_t(s.bytes);
      if (u.format == OSMESA_RGBA) {
        std::memcpy(dst, src, std::size_t(d.x1 - d.x0) * 4);
        continue;
      }
      for (int x = d.x0; x < d.x1; ++x, src += 4, dst += s.bytes) {
        dst[s.r] = src[0], dst[s.g] = src[1], dst[s.b] = src[2];
        if (s.a >= 0) dst[s.a] = src[3];
      }
    }
  };
  std::size_t n = std::size_t(d.y1 - d.y0);
  std::size_t pixels = n * std::size_t(d.x1 - d.x0);
  if (c.pipeline && pixels >= (1u << 16)) c.pipeline->parallel_for(n, std::max<std::size_t>(1, n / 16), rows);
  else rows(0, n);
}

// The caller's buffer is the colour buffer, as in classic OSMesa: its pixels are read in
// when it is bound (formats without alpha read as opaque).
void import_user_buffer(GlContext& c) {
  const UserBuffer& u = c.user;
  Swizzle s = swizzle_of(u.format);
  for (int y = 0; y < c.fb.height; ++y) {
    const unsigned char* src = user_row(u, y, s.bytes);
    std::uint8_t* dst = &c.fb.color[std::size_t(y) * std::size_t(c.fb.width) * 4];
    for (int x = 0; x < c.fb.width; ++x, src += s.bytes, dst += 4) {
      dst[0] = src[s.r], dst[1] = src[s.g], dst[2] = src[s.b];
      dst[3] = s.a >= 0 ? src[s.a] : 255;
    }
  }
}

// Mesa's depth layouts (checked against libOSMesa 22.3): 16-bit depth as GLushort; 24-bit
// depth in the low bits of a GLuint with the 8-bit stencil value in the high byte.
void export_depth(GlContext& c) {
  std::size_t n = c.fb.depth.size();
  int bytes = c.depth_bits == 16 ? 2 : 4;
  c.depth_export.resize(n * std::size_t(bytes));
  for (std::size_t i = 0; i < n; ++i) {
    double d = std::clamp(double(c.fb.depth[i]), 0.0, 1.0);
    if (bytes == 2) {
      auto v = static_cast<std::uint16_t>(std::lround(d * 65535.0));
      std::memcpy(&c.depth_export[i * 2], &v, 2);
      continue;
    }
    auto v = static_cast<std::uint32_t>(std::lround(d * 16777215.0));
    if (c.stencil_bits > 0) v |= std::uint32_t(c.fb.stencil[i]) << 24;
    std::memcpy(&c.depth_export[i * 4], &v, 4);
  }
}

}  // namespace shadelab::gl
