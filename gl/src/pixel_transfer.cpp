// Pixel transfer (GL 1.1 sections 3.6.2-3.6.3): glPixelTransfer, glPixelMap, glGetPixelMap,
// glPixelZoom, the transfer operations themselves and images unpacked through them. State and
// arithmetic only; drawpix.cpp, bitmap.cpp and readpix.cpp use them with the framebuffer.
#include "gl/src/pixel_transfer.hpp"

#include <algorithm>
#include <cmath>

#include "gl/generated/exec.hpp"
#include "gl/src/convert.hpp"
#include "gl/src/pixels.hpp"

namespace shadelab::gl {
namespace {

float clamp01(float v) { return v == v ? std::clamp(v, 0.0f, 1.0f) : 0.0f; }

// The value a map gives for a component in [0, 1] (section 3.6.3: index = c (size - 1)).
float lookup(const std::vector<float>& map, float c) {
  const float scaled = clamp01(c) * float(map.size() - 1);
  return map[std::size_t(std::nearbyint(scaled))];
}

float masked(const std::vector<float>& map, std::int64_t index) {
  return map[std::size_t(index & std::int64_t(map.size() - 1))];
}

// The slot of a pixel map enum in PixelMaps, or -1.
int map_slot(GLenum map) {
  return map >= GL_PIXEL_MAP_I_TO_I && map <= GL_PIXEL_MAP_A_TO_A ? int(map - GL_PIXEL_MAP_I_TO_I) : -1;
}

bool is_index_map(int slot) { return slot == PixelMaps::kItoI || slot == PixelMaps::kStoS; }

// The sizes glPixelMap accepts, Mesa's checks in Mesa's order: 1 to 256 entries, a power of two
// for S_TO_S and the I_TO_R ... I_TO_A maps (Mesa does not ask it of I_TO_I).
GLenum map_size_error(GLenum map, GLsizei size) {
  if (size < 1 || size > kMaxPixelMapTable) return GL_INVALID_VALUE;
  const bool power_of_two = (size & (size - 1)) == 0;
  if (map >= GL_PIXEL_MAP_S_TO_S && map <= GL_PIXEL_MAP_I_TO_A && !power_of_two) return GL_INVALID_VALUE;
  return map_slot(map) < 0 ? GL_INVALID_ENUM : GL_NO_ERROR;
}

// Stores a map given as floats (colour values already mapped to [0, 1] from integer types):
// colour values are clamped to [0, 1], S_TO_S values rounded to integers (GLint's range, as
// Mesa stores them), I_TO_I kept.
void store_map(GlContext& c, GLenum map, GLsizei size, const float* values) {
  if (const GLenum e = map_size_error(map, size); e != GL_NO_ERROR) return c.set_error(e);
  if (!values) return;
  const int slot = map_slot(map);
  std::vector<float> m(values, values + size);
  for (float& v : m) {
    if (slot == PixelMaps::kStoS) v = std::round(std::clamp(finite_or_zero(v), -2147483648.0f, 2147483520.0f));
    else if (!is_index_map(slot)) v = clamp01(v);
  }
  c.pixel.maps.maps[std::size_t(slot)] = std::move(m);
}

const std::vector<float>* find_map(GlContext& c, GLenum map) {
  const int slot = map_slot(map);
  if (slot < 0) {
    c.set_error(GL_INVALID_ENUM);
    return nullptr;
  }
  return &c.pixel.maps.maps[std::size_t(slot)];
}

// Colour map entries scaled to [0, 1] by `to_float` (Mesa's conversions: unsigned shorts
// times the single-precision 1 / 65535, unsigned ints times the double 1 / (2^32 - 1)); index
// map entries kept as integers.
template <class T, class ToFloat>
void map_from_integers(GlContext& c, GLenum map, GLsizei size, const T* values, ToFloat to_float) {
  if (const GLenum e = map_size_error(map, size); e != GL_NO_ERROR) return c.set_error(e);
  if (!values) return;
  std::vector<float> f(static_cast<std::size_t>(size));
  const bool index = is_index_map(map_slot(map));
  for (GLsizei i = 0; i < size; ++i) f[std::size_t(i)] = index ? float(values[i]) : to_float(values[i]);
  store_map(c, map, size, f.data());
}

void set_transfer(GlContext& c, GLenum pname, float v) {
  PixelTransfer& t = c.pixel;
  switch (pname) {
    case GL_MAP_COLOR: t.map_color = v != 0.0f; return;
    case GL_MAP_STENCIL: t.map_stencil = v != 0.0f; return;
    // Truncated, as Mesa converts the parameter.
    case GL_INDEX_SHIFT: t.index_shift = GLint(std::clamp(finite_or_zero(v), -2e9f, 2e9f)); return;
    case GL_INDEX_OFFSET: t.index_offset = GLint(std::clamp(finite_or_zero(v), -2e9f, 2e9f)); return;
    case GL_RED_SCALE: t.scale[0] = v; return;
    case GL_GREEN_SCALE: t.scale[1] = v; return;
    case GL_BLUE_SCALE: t.scale[2] = v; return;
    case GL_ALPHA_SCALE: t.scale[3] = v; return;
    case GL_RED_BIAS: t.bias[0] = v; return;
    case GL_GREEN_BIAS: t.bias[1] = v; return;
    case GL_BLUE_BIAS: t.bias[2] = v; return;
    case GL_ALPHA_BIAS: t.bias[3] = v; return;
    case GL_DEPTH_SCALE: t.depth_scale = v; return;
    case GL_DEPTH_BIAS: t.depth_bias = v; return;
    default: c.set_error(GL_INVALID_ENUM);
  }
}

// The colour of one pixel of a colour-format image (section 3.6.4's conversion to RGBA).
glm::vec4 image_color(const ClientImage& img, int x, int y, GLenum format) {
  auto e = [&](int k) { return img.component(x, y, k); };
  switch (format) {
    case GL_RED: return {e(0), 0.0f, 0.0f, 1.0f};
    case GL_GREEN: return {0.0f, e(0), 0.0f, 1.0f};
    case GL_BLUE: return {0.0f, 0.0f, e(0), 1.0f};
    case GL_ALPHA: return {0.0f, 0.0f, 0.0f, e(0)};
    case GL_LUMINANCE: return {e(0), e(0), e(0), 1.0f};
    case GL_LUMINANCE_ALPHA: return {e(0), e(0), e(0), e(1)};
    case GL_RGB: return {e(0), e(1), e(2), 1.0f};
    case GL_BGR: return {e(2), e(1), e(0), 1.0f};
    case GL_BGRA: return {e(2), e(1), e(0), e(3)};
    default: return {e(0), e(1), e(2), e(3)};
  }
}

glm::vec4 clamped(glm::vec4 v) {
  for (int i = 0; i < 4; ++i) v[i] = clamp01(v[i]);
  return v;
}

}  // namespace

glm::vec4 transfer_color(const PixelTransfer& t, glm::vec4 rgba) {
  for (int i = 0; i < 4; ++i) rgba[i] = rgba[i] * t.scale[std::size_t(i)] + t.bias[std::size_t(i)];
  if (!t.map_color) return rgba;
  for (int i = 0; i < 4; ++i) rgba[i] = lookup(t.maps.maps[std::size_t(PixelMaps::kRtoR + i)], rgba[i]);
  return rgba;
}

std::int64_t shift_index(const PixelTransfer& t, std::int64_t index) {
  const int shift = std::clamp(t.index_shift, -63, 63);
  index = std::clamp<std::int64_t>(index, -(std::int64_t(1) << 32), std::int64_t(1) << 32);
  // Shifts of negative values as multiplications and floored divisions (no undefined shifts).
  if (shift > 0) index = index * (std::int64_t(1) << std::min(shift, 30));
  else if (shift < 0) index = index >> -shift;
  return index + t.index_offset;
}

glm::vec4 index_to_rgba(const PixelTransfer& t, std::int64_t index) {
  const auto& m = t.maps.maps;
  return {masked(m[PixelMaps::kItoR], index), masked(m[PixelMaps::kItoR + 1], index),
          masked(m[PixelMaps::kItoR + 2], index), masked(m[PixelMaps::kItoR + 3], index)};
}

std::uint8_t transfer_stencil(const PixelTransfer& t, std::int64_t index) {
  std::uint8_t s = std::uint8_t(shift_index(t, index) & 0xff);
  if (t.map_stencil) s = std::uint8_t(std::int64_t(masked(t.maps.maps[PixelMaps::kStoS], s)) & 0xff);
  return s;
}

float transfer_depth(const PixelTransfer& t, float depth) {
  return clamp01(depth * t.depth_scale + t.depth_bias);
}

void unpack_color_image(const GlContext& c, const void* pixels, int width, int height, GLenum format,
                        GLenum type, std::vector<glm::vec4>& out) {
  const ClientImage img(c.unpack, pixels, width, format, type);
  out.resize(std::size_t(width) * std::size_t(height));
  const bool index = format == GL_COLOR_INDEX;
  for (int y = 0; y < height; ++y) {
    glm::vec4* row = &out[std::size_t(y) * std::size_t(width)];
    for (int x = 0; x < width; ++x) {
      row[x] = clamped(index ? index_to_rgba(c.pixel, shift_index(c.pixel, img.index(x, y)))
                             : transfer_color(c.pixel, image_color(img, x, y, format)));
    }
  }
}

namespace {

// A depth element in [0, 1] (table 2.6). Unsigned bytes and shorts are scaled in single
// precision, as llvmpipe reads them from the depth texture Mesa makes of the image.
float depth_element(const ClientImage& img, int x, int y, GLenum type) {
  if (type == GL_UNSIGNED_BYTE) return float(img.index(x, y)) * (1.0f / 255.0f);
  if (type == GL_UNSIGNED_SHORT) return float(img.index(x, y)) * (1.0f / 65535.0f);
  return img.component(x, y, 0);
}

}  // namespace

void unpack_depth_image(const GlContext& c, const void* pixels, int width, int height, GLenum type,
                        std::vector<float>& out) {
  const ClientImage img(c.unpack, pixels, width, GL_DEPTH_COMPONENT, type);
  out.resize(std::size_t(width) * std::size_t(height));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      out[std::size_t(y) * std::size_t(width) + std::size_t(x)] = transfer_depth(c.pixel, depth_element(img, x, y, type));
    }
  }
}

void unpack_depth_stencil_image(const GlContext& c, const void* pixels, int width, int height,
                                std::vector<float>& depths, std::vector<std::uint8_t>& stencil) {
  const ClientImage img(c.unpack, pixels, width, kDepthStencil, kUnsignedInt24_8);
  const std::size_t n = std::size_t(width) * std::size_t(height);
  depths.resize(n);
  stencil.resize(n);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const auto v = std::uint32_t(img.index(x, y));
      const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
      depths[i] = transfer_depth(c.pixel, float(double(v >> 8) / 16777215.0));
      stencil[i] = transfer_stencil(c.pixel, v & 0xffu);
    }
  }
}

void unpack_stencil_image(const GlContext& c, const void* pixels, int width, int height, GLenum type,
                          std::vector<std::uint8_t>& out) {
  const ClientImage img(c.unpack, pixels, width, GL_STENCIL_INDEX, type);
  out.resize(std::size_t(width) * std::size_t(height));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      out[std::size_t(y) * std::size_t(width) + std::size_t(x)] = transfer_stencil(c.pixel, img.index(x, y));
    }
  }
}

void exec::PixelTransferf(GlContext& c, GLenum pname, GLfloat param) { set_transfer(c, pname, param); }
void exec::PixelTransferi(GlContext& c, GLenum pname, GLint param) { set_transfer(c, pname, float(param)); }

void exec::PixelZoom(GlContext& c, GLfloat xfactor, GLfloat yfactor) {
  c.pixel.zoom_x = finite_or_zero(xfactor);
  c.pixel.zoom_y = finite_or_zero(yfactor);
}

void exec::PixelMapfv(GlContext& c, GLenum map, GLsizei mapsize, const GLfloat* values) {
  store_map(c, map, mapsize, values);
}

void exec::PixelMapuiv(GlContext& c, GLenum map, GLsizei mapsize, const GLuint* values) {
  map_from_integers(c, map, mapsize, values, [](GLuint v) { return float(v * (1.0 / 4294967295.0)); });
}

void exec::PixelMapusv(GlContext& c, GLenum map, GLsizei mapsize, const GLushort* values) {
  map_from_integers(c, map, mapsize, values, [](GLushort v) { return float(v) * (1.0f / 65535.0f); });
}

void exec::GetPixelMapfv(GlContext& c, GLenum map, GLfloat* values) {
  const std::vector<float>* m = find_map(c, map);
  if (!m || !values) return;
  std::copy(m->begin(), m->end(), values);
}

// Colour maps as the whole unsigned range (truncated, as Mesa); index maps as integers (Mesa
// returns S_TO_S's float bits and scales I_TO_I like a colour: shadelab follows the
// specification, section 6.1.3).
void exec::GetPixelMapuiv(GlContext& c, GLenum map, GLuint* values) {
  const std::vector<float>* m = find_map(c, map);
  if (!m || !values) return;
  const bool index = is_index_map(map_slot(map));
  for (std::size_t i = 0; i < m->size(); ++i) {
    const double v = finite_or_zero((*m)[i]);  // an I_TO_I value given as NaN reads 0
    values[i] = index ? GLuint(std::int64_t(std::clamp(v, -2147483648.0, 4294967295.0)))
                      : GLuint(std::clamp(v, 0.0, 1.0) * 4294967295.0);
  }
}

// Colour maps rounded to the unsigned short range, index maps truncated and clamped to it
// (Mesa's conversions).
void exec::GetPixelMapusv(GlContext& c, GLenum map, GLushort* values) {
  const std::vector<float>* m = find_map(c, map);
  if (!m || !values) return;
  const bool index = is_index_map(map_slot(map));
  for (std::size_t i = 0; i < m->size(); ++i) {
    const float v = finite_or_zero((*m)[i]);
    values[i] = index ? GLushort(std::clamp(v, 0.0f, 65535.0f)) : GLushort(std::lround(clamp01(v) * 65535.0f));
  }
}

}  // namespace shadelab::gl
