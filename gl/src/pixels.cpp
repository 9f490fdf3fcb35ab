// Client pixel memory (GL 1.1 sections 3.6.3, 4.3.2): its layout under glPixelStore, and the
// conversion of its elements to and from floats (table 2.6). No GL state but the pixel
// transfer state unpack_rgba_image is given (texture images), no framebuffer.
#include "gl/src/pixels.hpp"

#include "gl/src/pixel_transfer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace shadelab::gl {

int color_format_components(GLenum format) {
  switch (format) {
    case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA: case GL_LUMINANCE: return 1;
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_RGB: case GL_BGR: return 3;
    case GL_RGBA: case GL_BGRA: return 4;
    default: return 0;
  }
}

int pixel_type_size(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: case kUnsignedInt24_8: return 4;
    default: {
      const PackedType* p = packed_type(type);
      return p ? p->bytes : 0;
    }
  }
}

namespace {

constexpr PackedType kPackedTypes[] = {
    {GL_UNSIGNED_BYTE_3_3_2, 1, 3, {3, 3, 2, 0}, false},
    {GL_UNSIGNED_BYTE_2_3_3_REV, 1, 3, {3, 3, 2, 0}, true},
    {GL_UNSIGNED_SHORT_5_6_5, 2, 3, {5, 6, 5, 0}, false},
    {GL_UNSIGNED_SHORT_5_6_5_REV, 2, 3, {5, 6, 5, 0}, true},
    {GL_UNSIGNED_SHORT_4_4_4_4, 2, 4, {4, 4, 4, 4}, false},
    {GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, 4, {4, 4, 4, 4}, true},
    {GL_UNSIGNED_SHORT_5_5_5_1, 2, 4, {5, 5, 5, 1}, false},
    {GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, 4, {5, 5, 5, 1}, true},
    {GL_UNSIGNED_INT_8_8_8_8, 4, 4, {8, 8, 8, 8}, false},
    {GL_UNSIGNED_INT_8_8_8_8_REV, 4, 4, {8, 8, 8, 8}, true},
    {GL_UNSIGNED_INT_10_10_10_2, 4, 4, {10, 10, 10, 2}, false},
    {GL_UNSIGNED_INT_2_10_10_10_REV, 4, 4, {10, 10, 10, 2}, true},
};

}  // namespace

int PackedType::shift(int k) const {
  int below = 0;  // bits of the fields before k
  for (int i = 0; i < k; ++i) below += bits[i];
  return rev ? below : 8 * bytes - below - bits[k];
}

float PackedType::unit(std::uint32_t e, int k) const {
  const int b = bits[k];
  const std::uint32_t f = field(e, k);
  if (b >= 8) return float(double(f) / double((1u << b) - 1u));
  std::uint32_t byte = 0;  // the field's bits repeated from the top of the byte down
  for (int at = 8 - b; at > -b; at -= b) byte |= at >= 0 ? f << at : f >> -at;
  return float(byte) * (1.0f / 255.0f);
}

std::uint32_t PackedType::field_from_byte(std::uint32_t v, int k) const {
  const int b = bits[k];
  if (b >= 8) return b == 8 ? v : (v << (b - 8)) | (v >> (16 - b));
  return (v * ((1u << b) - 1u) + 127u) / 255u;
}

const PackedType* packed_type(GLenum type) {
  for (const PackedType& p : kPackedTypes) {
    if (p.type == type) return &p;
  }
  return nullptr;
}

std::uint32_t load_packed(const unsigned char* p, int bytes, bool swap_bytes) {
  unsigned char b[4] = {0, 0, 0, 0};
  for (int k = 0; k < bytes; ++k) b[k] = p[swap_bytes ? bytes - 1 - k : k];
  switch (bytes) {
    case 1: return b[0];
    case 2: {
      std::uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    default: {
      std::uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
  }
}

bool byte_order(GLenum format, ByteOrder& out) {
  const bool bgr = format == GL_BGRA || format == GL_BGR;
  out.components = format == GL_RGBA || format == GL_BGRA ? 4 : format == GL_RGB || format == GL_BGR ? 3 : 0;
  out.red = bgr ? 2 : 0;
  out.blue = bgr ? 0 : 2;
  return out.components != 0;
}

PixelLayout pixel_layout(const PixelStore& s, int components, int type_size, int width) {
  std::size_t n = std::size_t(components), size = std::size_t(type_size);
  std::size_t row_pixels = std::size_t(s.row_length > 0 ? s.row_length : width);
  std::size_t row_bytes = n * size * row_pixels;
  std::size_t align = std::size_t(s.alignment);
  // Rows start on multiples of the alignment unless a component is at least that large.
  if (size < align) row_bytes = (row_bytes + align - 1) / align * align;
  PixelLayout l;
  l.row_stride = row_bytes;
  l.pixel_stride = n * size;
  l.start = std::size_t(s.skip_rows) * row_bytes + std::size_t(s.skip_pixels) * n * size;
  return l;
}

BitmapLayout bitmap_layout(const PixelStore& s, int width) {
  const std::size_t bits = std::size_t(s.row_length > 0 ? s.row_length : width);
  const std::size_t align = std::size_t(s.alignment);
  BitmapLayout l;
  l.row_stride = (bits + 8 * align - 1) / (8 * align) * align;
  l.start = std::size_t(s.skip_rows) * l.row_stride;
  l.skip_bits = std::size_t(s.skip_pixels);
  l.lsb_first = s.lsb_first;
  return l;
}

std::size_t image_stride(const PixelStore& s, GLenum format, GLenum type, int width, int height) {
  const std::size_t rows = std::size_t(s.image_height > 0 ? s.image_height : height);
  if (type == GL_BITMAP) return rows * bitmap_layout(s, width).row_stride;
  return rows * pixel_layout(s, elements_per_pixel(format, type), pixel_type_size(type), width).row_stride;
}

namespace {

template <class T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

template <class T>
void store(unsigned char* p, T v) {
  std::memcpy(p, &v, sizeof v);
}

// [0, 1] to an unsigned integer of `max`, rounded; [-1, 1] to a signed one, GL 1.1's
// ((2^b - 1) c - 1) / 2.
double to_unsigned(float v, double max) { return std::floor(std::clamp(double(v), 0.0, 1.0) * max + 0.5); }
double to_signed(float v, double max) {
  return std::floor((std::clamp(double(v), -1.0, 1.0) * max - 1.0) / 2.0 + 0.5);
}

}  // namespace

std::vector<unsigned char> copy_image(const PixelStore& unpack, int width, int height,
                                      int components, int type_size, const void* pixels) {
  const PixelLayout in = pixel_layout(unpack, components, type_size, width);
  const std::size_t row = in.pixel_stride * std::size_t(width);
  std::vector<unsigned char> out(row * std::size_t(height));
  const auto* src = static_cast<const unsigned char*>(pixels);
  for (int y = 0; y < height; ++y) std::memcpy(&out[row * std::size_t(y)], src + in.offset(0, y), row);
  if (unpack.swap_bytes && type_size > 1) {  // GL 1.1 section 3.6.3: each component's bytes reversed
    for (std::size_t i = 0; i + std::size_t(type_size) <= out.size(); i += std::size_t(type_size)) {
      std::reverse(out.begin() + std::ptrdiff_t(i), out.begin() + std::ptrdiff_t(i) + type_size);
    }
  }
  return out;
}

float read_component(const unsigned char* p, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return float(load<GLubyte>(p) / 255.0);
    case GL_BYTE: return float(std::max(-1.0, load<GLbyte>(p) / 127.0));
    case GL_UNSIGNED_SHORT: return float(load<GLushort>(p) / 65535.0);
    case GL_SHORT: return float(std::max(-1.0, load<GLshort>(p) / 32767.0));
    case GL_UNSIGNED_INT: return float(load<GLuint>(p) / 4294967295.0);
    case GL_INT: return float(std::max(-1.0, load<GLint>(p) / 2147483647.0));
    case GL_FLOAT: return load<GLfloat>(p);
    default: return 0.0f;
  }
}

void write_component(unsigned char* p, GLenum type, float v) {
  switch (type) {
    case GL_UNSIGNED_BYTE: store(p, GLubyte(to_unsigned(v, 255.0))); break;
    case GL_BYTE: store(p, GLbyte(to_signed(v, 255.0))); break;
    case GL_UNSIGNED_SHORT: store(p, GLushort(to_unsigned(v, 65535.0))); break;
    case GL_SHORT: store(p, GLshort(to_signed(v, 65535.0))); break;
    case GL_UNSIGNED_INT: store(p, GLuint(to_unsigned(v, 4294967295.0))); break;
    case GL_INT: store(p, GLint(to_signed(v, 4294967295.0))); break;
    case GL_FLOAT: store(p, GLfloat(v)); break;
    default: break;
  }
}

void unpack_rgba(const unsigned char* p, GLenum format, GLenum type, float rgba[4], bool swap_bytes) {
  const int size = pixel_type_size(type);
  const PackedType* packed = packed_type(type);
  const std::uint32_t element = packed ? load_packed(p, size, swap_bytes) : 0;
  auto c = [&](int i) {
    if (packed) return packed->unit(element, i);
    if (!swap_bytes || size == 1) return read_component(p + i * size, type);
    unsigned char b[4] = {0, 0, 0, 0};
    for (int k = 0; k < size; ++k) b[k] = p[i * size + size - 1 - k];
    return read_component(b, type);
  };
  rgba[0] = rgba[1] = rgba[2] = 0.0f;
  rgba[3] = 1.0f;
  switch (format) {
    case GL_RED: rgba[0] = c(0); break;
    case GL_GREEN: rgba[1] = c(0); break;
    case GL_BLUE: rgba[2] = c(0); break;
    case GL_ALPHA: rgba[3] = c(0); break;
    case GL_LUMINANCE: rgba[0] = rgba[1] = rgba[2] = c(0); break;
    case GL_LUMINANCE_ALPHA: rgba[0] = rgba[1] = rgba[2] = c(0), rgba[3] = c(1); break;
    case GL_RGB: case GL_RGBA: for (int i = 0; i < color_format_components(format); ++i) rgba[i] = c(i); break;
    case GL_BGR: case GL_BGRA:
      rgba[2] = c(0), rgba[1] = c(1), rgba[0] = c(2);
      if (format == GL_BGRA) rgba[3] = c(3);
      break;
    default: break;
  }
}

int format_components(GLenum format) {
  if (format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX || format == GL_DEPTH_COMPONENT || format == kDepthStencil) {
    return 1;
  }
  return color_format_components(format);
}

int elements_per_pixel(GLenum format, GLenum type) { return packed_type(type) ? 1 : format_components(format); }

GLenum packed_format_error(GLenum format, GLenum type) {
  if (type == kUnsignedInt24_8) return format == kDepthStencil ? GL_NO_ERROR : GL_INVALID_OPERATION;
  const PackedType* p = packed_type(type);
  if (!p) return GL_NO_ERROR;
  const bool fits = p->components == 3 ? format == GL_RGB : format == GL_RGBA || format == GL_BGRA;
  return fits ? GL_NO_ERROR : GL_INVALID_OPERATION;
}

bool is_color_format(GLenum format) { return color_format_components(format) > 0; }

GLenum format_type_error(GLenum format, GLenum type) {
  if (format_components(format) == 0) return GL_INVALID_ENUM;
  if (type == GL_BITMAP) {
    return format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX ? GL_NO_ERROR : GL_INVALID_ENUM;
  }
  if (pixel_type_size(type) == 0) return GL_INVALID_ENUM;
  // Mesa's order: a packed type with a format it does not pack first, then the format's types.
  if (const GLenum e = packed_format_error(format, type); e != GL_NO_ERROR) return e;
  return format == kDepthStencil && type != kUnsignedInt24_8 ? GL_INVALID_ENUM : GL_NO_ERROR;
}

namespace {

// A colour index of `type` at `p` (GL 1.1 section 3.6.3: integers as they are, floats too).
double read_index(const unsigned char* p, GLenum type, bool swap_bytes) {
  unsigned char b[4] = {0, 0, 0, 0};
  const int size = pixel_type_size(type);
  for (int k = 0; k < size; ++k) b[k] = p[swap_bytes ? size - 1 - k : k];
  switch (type) {
    case GL_UNSIGNED_BYTE: return load<GLubyte>(b);
    case GL_BYTE: return load<GLbyte>(b);
    case GL_UNSIGNED_SHORT: return load<GLushort>(b);
    case GL_SHORT: return load<GLshort>(b);
    case GL_UNSIGNED_INT: return load<GLuint>(b);
    case GL_INT: return load<GLint>(b);
    case GL_FLOAT: return load<GLfloat>(b);
    default: return 0.0;
  }
}

// Bit x of row y of a GL_BITMAP image (GL 1.1 section 3.6.3: rows of whole bytes padded to
// the alignment, skip pixels counted in bits, the most significant bit first unless
// GL_UNPACK_LSB_FIRST).
int bitmap_bit(const PixelStore& s, const unsigned char* p, int row_pixels, int x, int y) {
  const std::size_t row_bits = std::size_t(s.row_length > 0 ? s.row_length : row_pixels);
  const std::size_t align = std::size_t(s.alignment);
  const std::size_t row_bytes = ((row_bits + 7) / 8 + align - 1) / align * align;
  const std::size_t bit = std::size_t(s.skip_pixels) + std::size_t(x);
  const unsigned char byte = p[std::size_t(s.skip_rows + y) * row_bytes + bit / 8];
  return (byte >> (s.lsb_first ? bit % 8 : 7 - bit % 8)) & 1;
}

}  // namespace

void unpack_rgba_image(const GlContext& c, const PixelStore& store, int row_pixels, int x0, int y0, int width,
                       int height, GLenum format, GLenum type, const void* pixels, float* out) {
  const auto* in = static_cast<const unsigned char*>(pixels);
  const bool index = format == GL_COLOR_INDEX;
  const PixelLayout layout =
      type == GL_BITMAP ? PixelLayout{} : pixel_layout(store, index ? 1 : elements_per_pixel(format, type), pixel_type_size(type), row_pixels);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x, out += 4) {
      glm::vec4 rgba;
      if (type == GL_BITMAP || index) {
        const double i = type == GL_BITMAP ? bitmap_bit(store, in, row_pixels, x0 + x, y0 + y)
                                           : read_index(in + layout.offset(x0 + x, y0 + y), type, store.swap_bytes);
        rgba = index_to_rgba(c.pixel, shift_index(c.pixel, std::int64_t(i)));
      } else {
        unpack_rgba(in + layout.offset(x0 + x, y0 + y), format, type, &rgba[0], store.swap_bytes);
        rgba = transfer_color(c.pixel, rgba);
      }
      for (int k = 0; k < 4; ++k) out[k] = std::clamp(rgba[k], 0.0f, 1.0f);
    }
  }
}

namespace {

// Bytes per row of a GL_BITMAP image (GL 1.1 section 3.6.3: a multiple of the alignment).
std::size_t bitmap_row_bytes(const PixelStore& s, int width) {
  const std::size_t bits = std::size_t(s.row_length > 0 ? s.row_length : width);
  const std::size_t align = std::size_t(s.alignment);
  return (bits + 8 * align - 1) / (8 * align) * align;
}

// Where bit x of row y of a GL_BITMAP image is: its byte and the bit's mask in it.
std::size_t bitmap_byte(const PixelStore& s, std::size_t row_bytes, int x, int y, unsigned& mask) {
  const std::size_t bit = std::size_t(s.skip_pixels) + std::size_t(x);
  mask = s.lsb_first ? 1u << (bit % 8) : 0x80u >> (bit % 8);
  return (std::size_t(s.skip_rows) + std::size_t(y)) * row_bytes + bit / 8;
}

}  // namespace

ClientImage::ClientImage(const PixelStore& store, const void* pixels, int width, GLenum format, GLenum type)
    : base_(static_cast<const unsigned char*>(pixels)), store_(store), type_(type),
      components_(elements_per_pixel(format, type)), size_(pixel_type_size(type)), packed_(packed_type(type)) {
  if (type == GL_BITMAP) bitmap_row_ = bitmap_row_bytes(store, width);
  else layout_ = pixel_layout(store, components_, size_, width);
}

const unsigned char* ClientImage::element(int x, int y, int k, unsigned char swapped[4]) const {
  const unsigned char* p = base_ + layout_.offset(x, y) + std::size_t(k) * std::size_t(size_);
  if (!store_.swap_bytes || size_ == 1) return p;
  for (int i = 0; i < size_; ++i) swapped[i] = p[size_ - 1 - i];
  return swapped;
}

float ClientImage::component(int x, int y, int k) const {
  if (packed_) return packed_->unit(load_packed(base_ + layout_.offset(x, y), size_, store_.swap_bytes), k);
  unsigned char swapped[4];
  return read_component(element(x, y, k, swapped), type_);
}

std::int64_t ClientImage::index(int x, int y) const {
  if (type_ == GL_BITMAP) return bit(x, y) ? 1 : 0;
  unsigned char tmp[4];
  const unsigned char* p = element(x, y, 0, tmp);
  switch (type_) {
    case GL_UNSIGNED_BYTE: return load<GLubyte>(p);
    case GL_BYTE: return load<GLbyte>(p);
    case GL_UNSIGNED_SHORT: return load<GLushort>(p);
    case GL_SHORT: return load<GLshort>(p);
    case GL_UNSIGNED_INT: case kUnsignedInt24_8: return load<GLuint>(p);
    case GL_INT: return load<GLint>(p);
    case GL_FLOAT: {
      const float f = load<GLfloat>(p);
      return f == f ? std::int64_t(std::clamp(f, -4e18f, 4e18f)) : 0;
    }
    default: return 0;
  }
}

bool ClientImage::bit(int x, int y) const {
  unsigned mask = 0;
  return (base_[bitmap_byte(store_, bitmap_row_, x, y, mask)] & mask) != 0;
}

ClientImageWriter::ClientImageWriter(const PixelStore& store, void* pixels, int width, GLenum format, GLenum type)
    : base_(static_cast<unsigned char*>(pixels)), store_(store), size_(pixel_type_size(type)) {
  if (type == GL_BITMAP) bitmap_row_ = bitmap_row_bytes(store, width);
  else layout_ = pixel_layout(store, elements_per_pixel(format, type), size_, width);
}

void ClientImageWriter::put(int x, int y, int k, const unsigned char* bytes) {
  unsigned char* p = base_ + layout_.offset(x, y) + std::size_t(k) * std::size_t(size_);
  for (int i = 0; i < size_; ++i) p[i] = bytes[store_.swap_bytes ? size_ - 1 - i : i];
}

void ClientImageWriter::put_bit(int x, int y, bool on) {
  unsigned mask = 0;
  unsigned char& b = base_[bitmap_byte(store_, bitmap_row_, x, y, mask)];
  b = static_cast<unsigned char>(on ? (b | mask) : (b & ~mask));
}

std::vector<unsigned char> copy_bitmap(const PixelStore& unpack, int width, int height, const void* pixels) {
  const std::size_t row = (std::size_t(width) + 7) / 8;
  std::vector<unsigned char> out(row * std::size_t(height), 0);
  const ClientImage image(unpack, pixels, width, GL_COLOR_INDEX, GL_BITMAP);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (image.bit(x, y)) out[std::size_t(y) * row + std::size_t(x) / 8] |= static_cast<unsigned char>(0x80u >> (x % 8));
    }
  }
  return out;
}

void unpack_bitmap(const PixelStore& store, const void* pixels, int width, int height,
                   std::vector<std::uint8_t>& out) {
  out.assign(std::size_t(width) * std::size_t(height), 0);
  if (!pixels) return;
  const ClientImage image(store, pixels, width, GL_COLOR_INDEX, GL_BITMAP);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) out[std::size_t(y) * std::size_t(width) + std::size_t(x)] = image.bit(x, y);
  }
}

}  // namespace shadelab::gl
