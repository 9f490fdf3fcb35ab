// Client pixel memory as OpenGL 1.1 lays it out (sections 3.6.3, 4.3.2): formats, element
// types, glPixelStore's row length, skips, alignment, byte swapping and bit order, and the
// conversion of elements to and from [0, 1] (table 2.6). Shared by everything that reads or
// writes client images: glDrawPixels, glBitmap, glReadPixels, glTexImage*, glPolygonStipple.
// No GL state besides the PixelStore it is given, no GL errors, no pixel transfer (that is
// pixel_transfer.hpp's).
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

/// Bytes of one element of `type`: a component of GL_UNSIGNED_BYTE .. GL_FLOAT, a whole pixel
/// of a packed type; 0 for others.
int pixel_type_size(GLenum type);

/// A packed pixel type of GL 1.2 (GL 1.5 section 3.6.4, tables 3.8-3.11): each pixel one
/// element of `bytes` bytes holding `components` fields of `bits[k]` bits. The format's first
/// component is in the most significant bits, or with a _REV type in the least significant.
struct PackedType {
  GLenum type;
  int bytes, components;
  int bits[4];
  bool rev;
  /// Where field k starts, counted from the element's least significant bit.
  int shift(int k) const;
  /// Field k of element `e`, as an integer of bits[k] bits.
  std::uint32_t field(std::uint32_t e, int k) const { return (e >> shift(k)) & ((1u << bits[k]) - 1u); }
  /// Field k of element `e` in [0, 1]: the integer over 2^bits - 1, except that a field of
  /// fewer than 8 bits is first widened to 8 by repeating its bits, as Mesa converts packed
  /// pixels to bytes (so that a pixel drawn or a texel stored from it has that byte exactly).
  float unit(std::uint32_t e, int k) const;
  /// An 8-bit component as field k, as Mesa's unorm conversion rounds it (more bits than 8:
  /// the byte's bits repeated).
  std::uint32_t field_from_byte(std::uint32_t v, int k) const;
};
/// The packed type `type` is, or nullptr.
const PackedType* packed_type(GLenum type);
/// Elements per pixel of `format` in `type`: 1 for a packed type, else format_components.
int elements_per_pixel(GLenum format, GLenum type);
/// A packed element of `bytes` bytes at `p`, its bytes reversed first when `swap_bytes`.
std::uint32_t load_packed(const unsigned char* p, int bytes, bool swap_bytes);

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

/// Where red, green and blue (and alpha) lie in a pixel of bytes of GL_RGBA, GL_BGRA, GL_RGB or
/// GL_BGR: the byte paths of texture uploads, glReadPixels and glDrawPixels.
struct ByteOrder {
  int components = 0;  ///< 4 or 3
  int red = 0, blue = 2;
  bool rgba() const { return components == 4 && red == 0; }  ///< the colour buffer's own order
};
/// False for any other format.
bool byte_order(GLenum format, ByteOrder& out);

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

/// Bytes from one image of a 3D client image of `format` and `type` to the next (GL 1.5
/// section 3.8.1): GL_*_IMAGE_HEIGHT rows (`height` while it is 0) of the row stride
/// pixel_layout (or, for GL_BITMAP, bitmap_layout) gives. GL_*_SKIP_IMAGES skips whole ones.
std::size_t image_stride(const PixelStore& store, GLenum format, GLenum type, int width, int height);

/// Component of `type` at `p` as a float: unsigned integers map to [0, 1], signed ones to
/// [-1, 1] as Mesa converts them (c / (2^(b-1) - 1), at least -1: the rule of later GL
/// versions; GL 1.1's table 2.6 has (2c + 1) / (2^b - 1)), floats are kept.
float read_component(const unsigned char* p, GLenum type);

/// Writes `v` as a component of `type` (integers from [0, 1] or [-1, 1], rounded).
void write_component(unsigned char* p, GLenum type, float v);

/// A client image of width x height pixels of `components` components of `type_size` bytes,
/// read with the unpack state `unpack` (skips, row length, alignment, byte swapping) and
/// returned tightly packed (rows of width pixels, alignment 1, native byte order): what a
/// display list keeps of an image (GL 1.1 section 5.4), replayed with DefaultUnpack.
std::vector<unsigned char> copy_image(const PixelStore& unpack, int width, int height,
                                      int components, int type_size, const void* pixels);

/// The bits of a GL_BITMAP image of width x height read with the unpack state `unpack`
/// (skips, row length, alignment, GL_UNPACK_LSB_FIRST), returned as rows of (width + 7) / 8
/// bytes, most significant bit first: what a display list keeps of a bitmap (glBitmap,
/// glDrawPixels of GL_BITMAP, glPolygonStipple), replayed with DefaultUnpack.
std::vector<unsigned char> copy_bitmap(const PixelStore& unpack, int width, int height, const void* pixels);

/// An unpacked colour pixel of `format` as RGBA (missing colour components 0, alpha 1), its
/// components' bytes swapped first when `swap_bytes` (GL_UNPACK_SWAP_BYTES).
void unpack_rgba(const unsigned char* p, GLenum format, GLenum type, float rgba[4], bool swap_bytes = false);

/// The RGBA of a width x height window whose first pixel is (x0, y0) of a client image of
/// `format` (a colour format or GL_COLOR_INDEX) and `type` (GL_BITMAP with GL_COLOR_INDEX
/// too), laid out by `store` with rows of `row_pixels` pixels (when store.row_length is 0):
/// width * height * 4 floats, row by row, into `out`, through the pixel transfer operations
/// as glDrawPixels applies them (GL 1.1 section 3.8.1: transfer_color, or shift_index and
/// index_to_rgba for indices; clamped to [0, 1]).
void unpack_rgba_image(const GlContext& c, const PixelStore& store, int row_pixels, int x0, int y0, int width,
                       int height, GLenum format, GLenum type, const void* pixels, float* out);

/// Elements per pixel of any GL 1.1 pixel format (GL_COLOR_INDEX, GL_STENCIL_INDEX and
/// GL_DEPTH_COMPONENT have one, and GL_DEPTH_STENCIL's one packed element; the colour formats
/// as color_format_components); 0 for others.
int format_components(GLenum format);

/// Whether `format` holds colour components (as opposed to an index or a depth).
bool is_color_format(GLenum format);

/// The error a format/type pair of glDrawPixels, glReadPixels or glTexImage draws when the
/// enums themselves are wrong (GL 1.5 tables 3.5-3.8; Mesa's codes): GL_INVALID_ENUM for an
/// unknown format or type and for GL_BITMAP with anything but an index format,
/// GL_INVALID_OPERATION for a packed type with a format of other than its components
/// (packed_format_error), GL_DEPTH_STENCIL with any type but GL_UNSIGNED_INT_24_8
/// GL_INVALID_ENUM; GL_NO_ERROR otherwise.
GLenum format_type_error(GLenum format, GLenum type);
/// GL_INVALID_OPERATION when `type` is packed and `format` is not one it packs (GL_RGB for
/// the 3-component types, GL_RGBA and GL_BGRA for the 4-component ones, GL_DEPTH_STENCIL for
/// GL_UNSIGNED_INT_24_8); else GL_NO_ERROR.
GLenum packed_format_error(GLenum format, GLenum type);

/// A client image of `width`-pixel rows as glPixelStore's parameters lay it out (GL 1.1
/// section 3.6.3 for unpacking, 4.3.2 for packing: the same layout). Pixel (x, y) is the x-th
/// pixel of the y-th row after the skipped ones; elements are read with bytes swapped when
/// GL_*_SWAP_BYTES is set, GL_BITMAP bits in the order GL_*_LSB_FIRST gives.
class ClientImage {
 public:
  ClientImage(const PixelStore& store, const void* pixels, int width, GLenum format, GLenum type);

  /// Component k of pixel (x, y) as a colour component or depth: table 2.6's conversion
  /// (unsigned integers to [0, 1], signed to [-1, 1]), floats as they are, field k of a packed
  /// type's element over its largest value. Not for GL_BITMAP.
  float component(int x, int y, int k) const;
  /// The element of pixel (x, y) of an index image as an integer (floats truncated), or its
  /// bit for GL_BITMAP.
  std::int64_t index(int x, int y) const;
  /// The bit of pixel (x, y) of a GL_BITMAP image.
  bool bit(int x, int y) const;

 private:
  const unsigned char* element(int x, int y, int k, unsigned char swapped[4]) const;

  const unsigned char* base_;
  PixelStore store_;
  GLenum type_;
  int components_, size_;
  const PackedType* packed_;
  PixelLayout layout_;
  std::size_t bitmap_row_ = 0;  // bytes per row of a GL_BITMAP image
};

/// Writes elements of a client image laid out as ClientImage reads them (the pack direction:
/// glReadPixels, glGetTexImage): bytes swapped when GL_PACK_SWAP_BYTES is set, GL_BITMAP bits in
/// GL_PACK_LSB_FIRST's order (the other bits of a byte kept).
class ClientImageWriter {
 public:
  ClientImageWriter(const PixelStore& store, void* pixels, int width, GLenum format, GLenum type);
  /// Element k of pixel (x, y): `bytes` holds it in the element type, native byte order (a
  /// packed type's pixel is its element 0).
  void put(int x, int y, int k, const unsigned char* bytes);
  void put_bit(int x, int y, bool on);
  int element_size() const { return size_; }

 private:
  unsigned char* base_;
  PixelStore store_;
  int size_;
  PixelLayout layout_;
  std::size_t bitmap_row_ = 0;
};

/// A GL_BITMAP image of width x height as one byte (0 or 1) per pixel, row 0 first: glBitmap's
/// and glPolygonStipple's unpacking (GL 1.1 sections 3.7, 3.5.2).
void unpack_bitmap(const PixelStore& store, const void* pixels, int width, int height,
                   std::vector<std::uint8_t>& out);

}  // namespace shadelab::gl
