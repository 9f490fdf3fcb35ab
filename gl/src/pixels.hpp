// Client pixel memory as OpenGL 1.1 lays it out (section 3.6.3): formats, component types,
// row alignment and skips, and conversion of components to and from [0, 1] (table 2.6, 4.3.2).
// Used by glReadPixels (pack) and glTexImage2D (unpack). No state, no GL errors.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/src/context.hpp"

namespace shadelab::gl {

/// Components per pixel of a colour format (GL_RGBA, GL_RGB, GL_BGR(A), GL_RED, GL_GREEN,
/// GL_BLUE, GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA); 0 for others.
int color_format_components(GLenum format);

/// Bytes of one component of `type` (GL_UNSIGNED_BYTE .. GL_FLOAT); 0 for others.
int pixel_type_size(GLenum type);

/// Where pixel (x, y) of an image starts, relative to the client pointer.
struct PixelLayout {
  std::size_t start = 0;       // bytes before pixel (0, 0): the skips
  std::size_t row_stride = 0;  // bytes from one row to the next (alignment applied)
  std::size_t pixel_stride = 0;
  std::size_t offset(int x, int y) const {
    return start + std::size_t(y) * row_stride + std::size_t(x) * pixel_stride;
  }
};
PixelLayout pixel_layout(const PixelStore& store, int components, int type_size, int width);

/// Where the bits of a GL_BITMAP image lie (GL 1.1 section 3.6.3, bitmaps): one bit per
/// pixel, rows of ceil(l / 8) bytes (l the row length, or the width) padded to the alignment,
/// GL_*_SKIP_PIXELS counted in bits, GL_*_LSB_FIRST choosing the bit order in a byte.
struct BitmapLayout {
  std::size_t start = 0;       // bytes before row 0 (the skipped rows)
  std::size_t row_stride = 0;  // bytes from one row to the next
  std::size_t skip_bits = 0;   // bits before pixel 0 of a row
  bool lsb_first = false;
  std::size_t byte(int x, int y) const { return start + std::size_t(y) * row_stride + (skip_bits + std::size_t(x)) / 8; }
  unsigned mask(int x) const {
    const unsigned bit = unsigned((skip_bits + std::size_t(x)) % 8);
    return lsb_first ? 1u << bit : 0x80u >> bit;
  }
};
BitmapLayout bitmap_layout(const PixelStore& store, int width);

/// Component of `type` at `p` as a float: unsigned integers map to [0, 1], signed ones to
/// [-1, 1], floats are kept.
float read_component(const unsigned char* p, GLenum type);

/// Writes `v` as a component of `type` (integers from [0, 1] or [-1, 1], rounded).
void write_component(unsigned char* p, GLenum type, float v);

/// A client image of width x height pixels of `components` components of `type_size` bytes,
/// read with the unpack state `unpack` (skips, row length, alignment, byte swapping) and
/// returned tightly packed (rows of width pixels, alignment 1, native byte order): what a
/// display list keeps of an image (GL 1.1 section 5.4), replayed with DefaultUnpack.
std::vector<unsigned char> copy_image(const PixelStore& unpack, int width, int height,
                                      int components, int type_size, const void* pixels);

/// An unpacked colour pixel of `format` as RGBA (missing colour components 0, alpha 1).
void unpack_rgba(const unsigned char* p, GLenum format, GLenum type, float rgba[4]);

}  // namespace shadelab::gl
