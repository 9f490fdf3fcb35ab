// Pixel memory layout and component conversion (GL 1.1 sections 3.6.3, 4.3.2), and
// glReadPixels, which packs the framebuffer into client memory. Reads the framebuffer only.
#include "gl/src/pixels.hpp"

#include "gl/generated/exec.hpp"

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
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: return 4;
    default: return 0;
  }
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
    case GL_BYTE: return float((2.0 * load<GLbyte>(p) + 1.0) / 255.0);
    case GL_UNSIGNED_SHORT: return float(load<GLushort>(p) / 65535.0);
    case GL_SHORT: return float((2.0 * load<GLshort>(p) + 1.0) / 65535.0);
    case GL_UNSIGNED_INT: return float(load<GLuint>(p) / 4294967295.0);
    case GL_INT: return float((2.0 * load<GLint>(p) + 1.0) / 4294967295.0);
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

void unpack_rgba(const unsigned char* p, GLenum format, GLenum type, float rgba[4]) {
  int size = pixel_type_size(type);
  auto c = [&](int i) { return read_component(p + i * size, type); };
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

namespace {

// The components of `format` taken from a framebuffer pixel (GL 1.1 section 4.3.2:
// luminance is R + G + B, clamped).
int pack_color(const std::uint8_t* px, GLenum format, float out[4]) {
  float r = px[0] / 255.0f, g = px[1] / 255.0f, b = px[2] / 255.0f, a = px[3] / 255.0f;
  float l = std::min(r + g + b, 1.0f);
  switch (format) {
    case GL_RED: out[0] = r; return 1;
    case GL_GREEN: out[0] = g; return 1;
    case GL_BLUE: out[0] = b; return 1;
    case GL_ALPHA: out[0] = a; return 1;
    case GL_LUMINANCE: out[0] = l; return 1;
    case GL_LUMINANCE_ALPHA: out[0] = l, out[1] = a; return 2;
    case GL_RGB: out[0] = r, out[1] = g, out[2] = b; return 3;
    case GL_BGR: out[0] = b, out[1] = g, out[2] = r; return 3;
    case GL_RGBA: out[0] = r, out[1] = g, out[2] = b, out[3] = a; return 4;
    case GL_BGRA: out[0] = b, out[1] = g, out[2] = r, out[3] = a; return 4;
    default: return 0;
  }
}

// One framebuffer pixel as `format`/`type` at `dst`.
void pack_pixel(const GlContext& c, std::size_t i, GLenum format, GLenum type, unsigned char* dst) {
  int size = pixel_type_size(type);
  if (format == GL_DEPTH_COMPONENT) return write_component(dst, type, c.fb.depth[i]);
  if (format == GL_STENCIL_INDEX) {
    // Stencil indices are integers, not normalized (GL 1.1 section 4.3.2).
    std::uint8_t s = c.fb.stencil[i];
    if (type == GL_FLOAT) return store(dst, GLfloat(s));
    if (size == 1) return store(dst, GLubyte(s));
    if (size == 2) return store(dst, GLushort(s));
    return store(dst, GLuint(s));
  }
  float v[4];
  int n = pack_color(&c.fb.color[i * 4], format, v);
  for (int k = 0; k < n; ++k) write_component(dst + k * size, type, v[k]);
}

int read_components(GLenum format) {
  if (format == GL_DEPTH_COMPONENT || format == GL_STENCIL_INDEX) return 1;
  return color_format_components(format);
}

}  // namespace

// Pixels outside the framebuffer are left as they are in client memory (GL leaves them
// undefined).
void exec::ReadPixels(GlContext& c, GLint x, GLint y, GLsizei width, GLsizei height, GLenum format,
                      GLenum type, void* pixels) {
  if (width < 0 || height < 0) return c.set_error(GL_INVALID_VALUE);
  if (format == GL_COLOR_INDEX) return c.set_error(GL_INVALID_OPERATION);  // RGBA mode
  int n = read_components(format), size = pixel_type_size(type);
  if (n == 0 || size == 0) return c.set_error(GL_INVALID_ENUM);
  if ((format == GL_DEPTH_COMPONENT && c.depth_bits == 0) ||
      (format == GL_STENCIL_INDEX && c.stencil_bits == 0)) {
    return c.set_error(GL_INVALID_OPERATION);
  }
  if (width == 0 || height == 0) return;
  if (!pixels) return c.set_error(GL_INVALID_VALUE);
  settle_clears(c);
  PixelLayout layout = pixel_layout(c.pack, n, size, width);
  auto* out = static_cast<unsigned char*>(pixels);
  int x0 = std::max(0, -x), y0 = std::max(0, -y);
  int x1 = int(std::min<long long>(width, (long long)c.fb.width - x));
  int y1 = int(std::min<long long>(height, (long long)c.fb.height - y));
  for (int j = y0; j < y1; ++j) {
    for (int i = x0; i < x1; ++i) {
      std::size_t px = std::size_t(y + j) * std::size_t(c.fb.width) + std::size_t(x + i);
      pack_pixel(c, px, format, type, out + layout.offset(i, j));
    }
  }
}

}  // namespace shadelab::gl
