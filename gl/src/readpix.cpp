// glReadPixels (GL 1.1 section 4.3.2): the framebuffer's colour, depth or stencil values packed
// into client memory with glPixelStore's pack parameters, through the pixel transfer
// operations, in every GL 1.1 format and type. Values are those Mesa's llvmpipe returns, byte
// for byte (measured on Mesa 22.3): colours without transfer operations are converted from
// their 8 bits exactly, luminance and transferred colours in single precision, depth from its
// 24 (or 16) stored bits. Reads the framebuffer only.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "gl/generated/exec.hpp"
#include "gl/src/pixel_transfer.hpp"
#include "gl/src/pixels.hpp"

namespace shadelab::gl {
namespace {

template <class T>
void put(ClientImageWriter& w, int x, int y, int k, T v) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof v);
  w.put(x, y, k, bytes);
}

// Element k of a pixel from the 8-bit component v, exactly: v / 255 in the type's range,
// rounded (signed types as GL 1.1's ((2^b - 1) c - 1) / 2).
void put_exact(ClientImageWriter& w, int x, int y, int k, GLenum type, std::uint32_t v) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return put(w, x, y, k, GLubyte(v));
    case GL_BYTE: return put(w, x, y, k, GLbyte(v >> 1));
    case GL_UNSIGNED_SHORT: return put(w, x, y, k, GLushort(v * 257u));
    case GL_SHORT: return put(w, x, y, k, GLshort(v * 128u + (v >> 1)));
    case GL_UNSIGNED_INT: return put(w, x, y, k, GLuint(v * 0x01010101u));
    case GL_INT: return put(w, x, y, k, GLint(v * 8421504u + (v >> 1)));
    default: return put(w, x, y, k, GLfloat(float(v) * (1.0f / 255.0f)));
  }
}

// Mesa's rounding of [0, 1] to 8 bits: f (255 / 256) + 2^15 in single precision puts the
// rounded value in the low byte.
GLubyte float_to_ubyte(float f) {
  if (!(f > 0.0f)) return 0;
  if (f >= 1.0f) return 255;
  const float t = f * (255.0f / 256.0f) + 32768.0f;
  std::uint32_t bits;
  std::memcpy(&bits, &t, 4);
  return GLubyte(bits);
}

// Element k from a clamped float, in single precision as Mesa's packing of transferred and
// luminance values does (at 1.0 Mesa's 32-bit integer types overflow to 0 and INT_MIN; the
// specification's largest value is written instead).
void put_float(ClientImageWriter& w, int x, int y, int k, GLenum type, float f) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return put(w, x, y, k, float_to_ubyte(f));
    case GL_BYTE: return put(w, x, y, k, GLbyte(std::nearbyint(f * 127.0f)));
    case GL_UNSIGNED_SHORT: return put(w, x, y, k, GLushort(std::nearbyint(f * 65535.0f)));
    case GL_SHORT: return put(w, x, y, k, GLshort(std::nearbyint(f * 32767.0f)));
    case GL_UNSIGNED_INT:
      return put(w, x, y, k, f >= 1.0f ? GLuint(0xffffffffu) : GLuint(std::int64_t(f * 4294967295.0f)));
    case GL_INT: return put(w, x, y, k, f >= 1.0f ? GLint(0x7fffffff) : GLint(f * 2147483647.0f));
    default: return put(w, x, y, k, GLfloat(f));
  }
}

// A packed pixel from its components in the format's order: `bytes8` the 8-bit components
// (exact) or `unit` the transferred values in [0, 1], rounded as Mesa packs floats: to 8 bits
// as float_to_ubyte, to other widths half away from zero.
void put_packed(ClientImageWriter& w, int x, int y, const PackedType& p, const std::uint32_t* bytes8, const float* unit) {
  std::uint32_t e = 0;
  for (int k = 0; k < p.components; ++k) {
    const std::uint32_t max = (1u << p.bits[k]) - 1u;
    std::uint32_t f = 0;
    if (bytes8) f = p.field_from_byte(bytes8[k], k);
    else if (p.bits[k] == 8) f = float_to_ubyte(unit[k]);
    else f = std::uint32_t(std::round(unit[k] * float(max)));
    e |= f << p.shift(k);
  }
  switch (p.bytes) {
    case 1: return put(w, x, y, 0, GLubyte(e));
    case 2: return put(w, x, y, 0, GLushort(e));
    default: return put(w, x, y, 0, GLuint(e));
  }
}

// Which of R, G, B, A (0-3; 4 for luminance) each element of a colour format holds.
int color_slots(GLenum format, int slots[4]) {
  switch (format) {
    case GL_RED: slots[0] = 0; return 1;
    case GL_GREEN: slots[0] = 1; return 1;
    case GL_BLUE: slots[0] = 2; return 1;
    case GL_ALPHA: slots[0] = 3; return 1;
    case GL_LUMINANCE: slots[0] = 4; return 1;
    case GL_LUMINANCE_ALPHA: slots[0] = 4, slots[1] = 3; return 2;
    case GL_RGB: slots[0] = 0, slots[1] = 1, slots[2] = 2; return 3;
    case GL_BGR: slots[0] = 2, slots[1] = 1, slots[2] = 0; return 3;
    case GL_BGRA: slots[0] = 2, slots[1] = 1, slots[2] = 0, slots[3] = 3; return 4;
    default: slots[0] = 0, slots[1] = 1, slots[2] = 2, slots[3] = 3; return 4;
  }
}

float clamp01(float v) { return v == v ? std::clamp(v, 0.0f, 1.0f) : 0.0f; }

// A colour buffer pixel in [0, 1], as Mesa computes it to the last bit (times 1 / 255).
glm::vec4 unit_color(const std::uint8_t* px) {
  glm::vec4 v;
  for (int k = 0; k < 4; ++k) v[k] = float(px[k]) * (1.0f / 255.0f);
  return v;
}

struct ReadRect {
  int x, y;          // framebuffer position of the image's pixel (0, 0)
  int x0, y0, x1, y1;  // the image pixels inside the framebuffer
};

// The usual read, 8-bit RGBA, RGB, BGRA or BGR with no transfer operation: the colour buffer's
// bytes are the answer (put_exact's GL_UNSIGNED_BYTE), copied row by row (RGBA rows with
// memcpy) into the client image of `width` pixels a row laid out by the pack parameters.
// False, with nothing written, for any other read.
bool read_bytes(const GlContext& c, const ColorBuffer& color, const ReadRect& r, int width, GLenum format, GLenum type,
                void* pixels) {
  if (type != GL_UNSIGNED_BYTE || c.pixel.changes_color()) return false;
  ByteOrder order;
  if (!byte_order(format, order)) return false;
  if (r.x1 <= r.x0 || r.y1 <= r.y0) return true;  // nothing of the framebuffer in it
  const int n = order.components, red = order.red, blue = order.blue;
  const PixelLayout layout = pixel_layout(c.pack, n, 1, width);
  auto* out = static_cast<unsigned char*>(pixels);
  for (int j = r.y0; j < r.y1; ++j) {
    const std::uint8_t* src = &color[(std::size_t(r.y + j) * std::size_t(c.fb.width) + std::size_t(r.x + r.x0)) * 4];
    unsigned char* dst = out + layout.offset(r.x0, j);
    if (order.rgba()) {
      std::memcpy(dst, src, std::size_t(r.x1 - r.x0) * 4);
      continue;
    }
    for (int i = r.x0; i < r.x1; ++i, src += 4, dst += n) {
      dst[0] = src[red], dst[1] = src[1], dst[2] = src[blue];
      if (n == 4) dst[3] = src[3];
    }
  }
  return true;
}

// Colour (section 4.3.2): R, G, B, A from the colour buffer, the transfer operations,
// luminance R + G + B, clamping to [0, 1], conversion to the type.
void read_color(const GlContext& c, const ColorBuffer& color, const ReadRect& r, GLenum format, GLenum type,
                ClientImageWriter& w) {
  int slots[4];
  const int n = color_slots(format, slots);
  const bool luminance = format == GL_LUMINANCE || format == GL_LUMINANCE_ALPHA;
  const bool transfer = c.pixel.changes_color();
  const bool exact = !luminance && !transfer;
  const PackedType* packed = packed_type(type);  // never with luminance (format_type_error)
  for (int j = r.y0; j < r.y1; ++j) {
    for (int i = r.x0; i < r.x1; ++i) {
      const std::uint8_t* px = &color[(std::size_t(r.y + j) * std::size_t(c.fb.width) + std::size_t(r.x + i)) * 4];
      if (packed) {
        std::uint32_t bytes8[4];
        const glm::vec4 v = transfer ? transfer_color(c.pixel, unit_color(px)) : glm::vec4(0.0f);
        float unit[4];
        for (int k = 0; k < n; ++k) bytes8[k] = px[slots[k]], unit[k] = clamp01(v[slots[k]]);
        put_packed(w, i, j, *packed, transfer ? nullptr : bytes8, unit);
        continue;
      }
      if (exact) {
        for (int k = 0; k < n; ++k) put_exact(w, i, j, k, type, px[slots[k]]);
        continue;
      }
      glm::vec4 v = unit_color(px);
      if (transfer) v = transfer_color(c.pixel, v);
      const float l = v.r + v.g + v.b;
      for (int k = 0; k < n; ++k) put_float(w, i, j, k, type, clamp01(slots[k] == 4 ? l : v[slots[k]]));
    }
  }
}

// A stored depth value as Mesa's depth buffer holds it: 24 (or 16) bits.
std::uint32_t stored_depth(float d, int bits) {
  const double max = bits == 16 ? 65535.0 : 16777215.0;
  return std::uint32_t(std::lround(std::clamp(double(d), 0.0, 1.0) * max));
}

// Depth (section 4.3.2) with Mesa's conversions of depth values: truncated to 8 bits,
// rounded to 16, signed types from the truncated value; 32 bits unsigned from the stored bits
// when no scale or bias applies and no bytes are swapped (Mesa's fast path).
void put_depth(ClientImageWriter& w, int x, int y, GLenum type, std::uint32_t z, int bits, const GlContext& c) {
  const PixelTransfer& t = c.pixel;
  const bool plain = t.depth_scale == 1.0f && t.depth_bias == 0.0f && !c.pack.swap_bytes;
  float d = float(double(z) / (bits == 16 ? 65535.0 : 16777215.0));
  if (t.depth_scale != 1.0f || t.depth_bias != 0.0f) d = transfer_depth(t, d);
  switch (type) {
    case GL_UNSIGNED_BYTE: return put(w, x, y, 0, GLubyte(int(d * 255.0f)));
    case GL_BYTE: return put(w, x, y, 0, GLbyte((int(255.0f * d) - 1) / 2));
    case GL_UNSIGNED_SHORT: return put(w, x, y, 0, GLushort(std::nearbyint(d * 65535.0f)));
    case GL_SHORT: return put(w, x, y, 0, GLshort((int(65535.0f * d) - 1) / 2));
    case GL_UNSIGNED_INT:
      if (!plain) return put(w, x, y, 0, GLuint(double(d) * 4294967295.0));
      return put(w, x, y, 0, GLuint(bits == 16 ? (z << 16) | z : (z << 8) | (z >> 16)));
    case GL_INT: return put(w, x, y, 0, GLint(2147483647.0 * double(d)));
    default: return put(w, x, y, 0, GLfloat(d));
  }
}

// Stencil indices (section 4.3.2): shifted, offset and mapped, then masked to the type's bits
// (GL_BITMAP: the lowest bit).
void put_stencil(ClientImageWriter& w, int x, int y, GLenum type, std::uint8_t s) {
  switch (type) {
    case GL_BITMAP: return w.put_bit(x, y, (s & 1u) != 0);
    case GL_UNSIGNED_BYTE: return put(w, x, y, 0, GLubyte(s));
    case GL_BYTE: return put(w, x, y, 0, GLbyte(s & 0x7f));
    case GL_UNSIGNED_SHORT: return put(w, x, y, 0, GLushort(s));
    case GL_SHORT: return put(w, x, y, 0, GLshort(s));
    case GL_UNSIGNED_INT: return put(w, x, y, 0, GLuint(s));
    case GL_INT: return put(w, x, y, 0, GLint(s));
    default: return put(w, x, y, 0, GLfloat(s));
  }
}

// A GL_UNSIGNED_INT_24_8 pixel (EXT_packed_depth_stencil): the depth buffer's 24 bits (a
// 16-bit buffer's widened, a scaled or biased depth converted again) over the stencil index
// after its transfer operations.
GLuint packed_depth_stencil(const GlContext& c, float depth, std::uint8_t stencil) {
  const PixelTransfer& t = c.pixel;
  std::uint32_t z = stored_depth(depth, c.depth_bits);
  if (c.depth_bits == 16 || t.depth_scale != 1.0f || t.depth_bias != 0.0f) {
    const float d = transfer_depth(t, float(double(z) / (c.depth_bits == 16 ? 65535.0 : 16777215.0)));
    z = std::uint32_t(std::lround(double(d) * 16777215.0));
  }
  return GLuint(z << 8 | transfer_stencil(t, stencil));
}

void read_depth_stencil(const GlContext& c, const ReadRect& r, GLenum format, GLenum type, ClientImageWriter& w) {
  for (int j = r.y0; j < r.y1; ++j) {
    for (int i = r.x0; i < r.x1; ++i) {
      const std::size_t px = std::size_t(r.y + j) * std::size_t(c.fb.width) + std::size_t(r.x + i);
      if (format == GL_DEPTH_COMPONENT) put_depth(w, i, j, type, stored_depth(c.fb.depth[px], c.depth_bits), c.depth_bits, c);
      else if (format == kDepthStencil) put(w, i, j, 0, packed_depth_stencil(c, c.fb.depth[px], c.fb.stencil[px]));
      else put_stencil(w, i, j, type, transfer_stencil(c.pixel, c.fb.stencil[px]));
    }
  }
}

// Mesa's checks, in Mesa's order.
GLenum read_error(const GlContext& c, GLsizei width, GLsizei height, GLenum format, GLenum type) {
  if (width < 0 || height < 0) return GL_INVALID_VALUE;
  if (const GLenum e = format_type_error(format, type); e != GL_NO_ERROR) return e;
  if (format == GL_COLOR_INDEX) return GL_INVALID_OPERATION;  // an RGBA context
  if (((format == GL_DEPTH_COMPONENT || format == kDepthStencil) && c.depth_bits == 0) ||
      ((format == GL_STENCIL_INDEX || format == kDepthStencil) && c.stencil_bits == 0)) {
    return GL_INVALID_OPERATION;
  }
  if (is_color_format(format) && c.buffers.read_buffer == GL_NONE) return GL_INVALID_OPERATION;
  return GL_NO_ERROR;
}

}  // namespace

// Pixels outside the framebuffer are left as they are in client memory (GL leaves them
// undefined).
void exec::ReadPixels(GlContext& c, GLint x, GLint y, GLsizei width, GLsizei height, GLenum format,
                      GLenum type, void* pixels) {
  if (const GLenum e = read_error(c, width, height, format, type); e != GL_NO_ERROR) return c.set_error(e);
  if (width == 0 || height == 0 || !pixels) return;
  settle_clears(c);
  ReadRect r{x, y, std::max(0, -x), std::max(0, -y),
             int(std::min<long long>(width, (long long)c.fb.width - x)),
             int(std::min<long long>(height, (long long)c.fb.height - y))};
  if (!is_color_format(format)) {
    ClientImageWriter w(c.pack, pixels, width, format, type);
    return read_depth_stencil(c, r, format, type, w);
  }
  const ColorBuffer& color = read_color_buffer(c);
  if (read_bytes(c, color, r, width, format, type, pixels)) return;
  ClientImageWriter w(c.pack, pixels, width, format, type);
  read_color(c, color, r, format, type, w);
}

}  // namespace shadelab::gl
