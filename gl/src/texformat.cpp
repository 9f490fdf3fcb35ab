// Internal formats and their storage (GL 1.1 section 3.8.1): which base format and how many
// bits each GL 1.1 internal format keeps. The sizes are llvmpipe's (Mesa 22, measured with
// glGetTexLevelParameter's component sizes and glGetTexImage): GL_ALPHA4, GL_LUMINANCE4,
// GL_INTENSITY4 and GL_LUMINANCE6_ALPHA2 keep 8 bits, GL_RGBA2 keeps 4, 12-bit formats keep
// 16, GL_RGB10 keeps 10.
#include "gl/src/texformat.hpp"

#include <algorithm>
#include <cmath>

namespace shadelab::gl {
namespace {

StoredFormat make(TextureFormat base, std::initializer_list<int> bits) {
  StoredFormat f;
  f.base = base;
  f.components = int(bits.size());
  int i = 0;
  for (int b : bits) f.bits[i++] = std::uint8_t(b);
  for (; i < 4; ++i) f.bits[i] = 0;
  return f;
}

bool alpha_or_luminance(GLint internal, StoredFormat& out) {
  using F = TextureFormat;
  switch (internal) {
    // GL 1.3's generic compressed formats are stored uncompressed, as their base formats.
    case GL_ALPHA: case GL_ALPHA4: case GL_ALPHA8: case GL_COMPRESSED_ALPHA: out = make(F::kAlpha, {8}); return true;
    case GL_ALPHA12: case GL_ALPHA16: out = make(F::kAlpha, {16}); return true;
    case 1: case GL_LUMINANCE: case GL_LUMINANCE4: case GL_LUMINANCE8: case GL_COMPRESSED_LUMINANCE: out = make(F::kLuminance, {8}); return true;
    case GL_LUMINANCE12: case GL_LUMINANCE16: out = make(F::kLuminance, {16}); return true;
    case 2: case GL_LUMINANCE_ALPHA: case GL_LUMINANCE6_ALPHA2: case GL_LUMINANCE8_ALPHA8:
    case GL_COMPRESSED_LUMINANCE_ALPHA:
      out = make(F::kLuminanceAlpha, {8, 8});
      return true;
    case GL_LUMINANCE4_ALPHA4: out = make(F::kLuminanceAlpha, {4, 4}); return true;
    case GL_LUMINANCE12_ALPHA4: case GL_LUMINANCE12_ALPHA12: case GL_LUMINANCE16_ALPHA16:
      out = make(F::kLuminanceAlpha, {16, 16});
      return true;
    case GL_INTENSITY: case GL_INTENSITY4: case GL_INTENSITY8: case GL_COMPRESSED_INTENSITY: out = make(F::kIntensity, {8}); return true;
    case GL_INTENSITY12: case GL_INTENSITY16: out = make(F::kIntensity, {16}); return true;
    default: return false;
  }
}

bool rgb_or_rgba(GLint internal, StoredFormat& out) {
  using F = TextureFormat;
  switch (internal) {
    case 3: case GL_RGB: case GL_RGB8: case GL_COMPRESSED_RGB: out = make(F::kRgb, {8, 8, 8}); return true;
    case GL_R3_G3_B2: out = make(F::kRgb, {3, 3, 2}); return true;
    case GL_RGB4: out = make(F::kRgb, {4, 4, 4}); return true;
    case GL_RGB5: out = make(F::kRgb, {5, 5, 5}); return true;
    case GL_RGB10: out = make(F::kRgb, {10, 10, 10}); return true;
    case GL_RGB12: case GL_RGB16: out = make(F::kRgb, {16, 16, 16}); return true;
    case 4: case GL_RGBA: case GL_RGBA8: case GL_COMPRESSED_RGBA: out = make(F::kRgba, {8, 8, 8, 8}); return true;
    case GL_RGBA2: case GL_RGBA4: out = make(F::kRgba, {4, 4, 4, 4}); return true;
    case GL_RGB5_A1: out = make(F::kRgba, {5, 5, 5, 1}); return true;
    case GL_RGB10_A2: out = make(F::kRgba, {10, 10, 10, 2}); return true;
    case GL_RGBA12: case GL_RGBA16: out = make(F::kRgba, {16, 16, 16, 16}); return true;
    default: return false;
  }
}

std::uint32_t max_of(int bits) { return (1u << bits) - 1u; }

// Bit replication of an n-bit value to `to` bits (n <= to): Mesa's EXTEND_NORMALIZED_INT.
std::uint32_t replicate(std::uint32_t k, int n, int to) {
  std::uint32_t r = 0;
  int have = 0;
  while (have < to) r = (r << n) | k, have += n;
  return r >> (have - to);
}

// Rounded narrowing of an n-bit value to `to` bits: (k max_to + half) / max_n.
std::uint32_t narrow(std::uint32_t k, int n, int to) {
  const std::uint64_t from_max = max_of(n), to_max = max_of(to);
  return std::uint32_t((std::uint64_t(k) * to_max + (from_max >> 1)) / from_max);
}

}  // namespace

bool StoredFormat::wide() const {
  for (int i = 0; i < components; ++i) {
    if (bits[i] > 8) return true;
  }
  return false;
}

// GL 1.4's depth formats, with the sizes Mesa 22 reports for them (GL_DEPTH_COMPONENT: 24), and
// EXT_packed_depth_stencil's (24 bits of depth, 8 of stencil).
bool depth_format(GLint internal, StoredFormat& out) {
  int bits = 0, stencil = 0;
  switch (internal) {
    case GL_DEPTH_COMPONENT: case GL_DEPTH_COMPONENT24: bits = 24; break;
    case GL_DEPTH_COMPONENT16: bits = 16; break;
    case GL_DEPTH_COMPONENT32: bits = 32; break;
    case GLint(kDepthStencil): case GLint(kDepth24Stencil8): bits = 24, stencil = 8; break;
    default: return false;
  }
  out = make(TextureFormat::kLuminance, {bits});
  out.depth = true;
  out.stencil_bits = stencil;
  return true;
}

float stored_depth_value(float d, int bits) {
  const double max = bits >= 32 ? 4294967295.0 : double((1u << bits) - 1u);
  const double v = d > 0.0f ? (d < 1.0f ? double(d) : 1.0) : 0.0;
  return float(std::floor(v * max) / max);
}

bool stored_format(GLint internal_format, StoredFormat& out) {
  return alpha_or_luminance(internal_format, out) || rgb_or_rgba(internal_format, out) ||
         depth_format(internal_format, out);
}

int base_components(TextureFormat base, const float rgba[4], float out[4]) {
  switch (base) {
    case TextureFormat::kAlpha: out[0] = rgba[3]; return 1;
    case TextureFormat::kLuminance: case TextureFormat::kIntensity: out[0] = rgba[0]; return 1;
    case TextureFormat::kLuminanceAlpha: out[0] = rgba[0], out[1] = rgba[3]; return 2;
    case TextureFormat::kRgb: std::copy(rgba, rgba + 3, out); return 3;
    case TextureFormat::kRgba: std::copy(rgba, rgba + 4, out); return 4;
  }
  return 0;
}

// Mesa's _mesa_float_to_unorm: the product in float, rounded half to even (0.3f gives 76,
// 0.9f gives 230 at 8 bits).
std::uint16_t quantize(float v, int bits) {
  const float c = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // NaN to 0
  return std::uint16_t(std::nearbyint(c * float(max_of(bits))));
}

std::uint16_t quantize_byte(std::uint8_t v, int bits) {
  return std::uint16_t(bits >= 8 ? replicate(v, 8, bits) : narrow(v, 8, bits));
}

std::uint8_t stored_to_byte(std::uint16_t k, int bits) {
  return std::uint8_t(bits <= 8 ? replicate(k, bits, 8) : narrow(k, bits, 8));
}

std::uint16_t byte_to_stored(std::uint8_t b, int bits) { return std::uint16_t(b >> (8 - bits)); }

std::uint16_t stored_to_ushort(std::uint16_t k, int bits) { return std::uint16_t(replicate(k, bits, 16)); }

// In float arithmetic, k times the reciprocal, as Mesa's _mesa_unorm_to_float (so 108 / 255
// is 0.423529446, not the nearest float to the quotient).
float stored_to_float(std::uint16_t k, int bits) { return float(k) * (1.0f / float(max_of(bits))); }

void expand_texel(TextureFormat base, const std::uint8_t* c, std::uint8_t rgba[4]) {
  switch (base) {
    case TextureFormat::kAlpha: rgba[0] = rgba[1] = rgba[2] = 0, rgba[3] = c[0]; return;
    case TextureFormat::kLuminance: rgba[0] = rgba[1] = rgba[2] = c[0], rgba[3] = 255; return;
    case TextureFormat::kLuminanceAlpha: rgba[0] = rgba[1] = rgba[2] = c[0], rgba[3] = c[1]; return;
    case TextureFormat::kIntensity: rgba[0] = rgba[1] = rgba[2] = rgba[3] = c[0]; return;
    case TextureFormat::kRgb: rgba[0] = c[0], rgba[1] = c[1], rgba[2] = c[2], rgba[3] = 255; return;
    case TextureFormat::kRgba: std::copy(c, c + 4, rgba); return;
  }
}

void texel_to_rgba(TextureFormat base, const float* c, float rgba[4]) {
  rgba[0] = rgba[1] = rgba[2] = 0.0f;
  rgba[3] = 1.0f;
  switch (base) {
    case TextureFormat::kAlpha: rgba[3] = c[0]; return;
    case TextureFormat::kLuminance: case TextureFormat::kIntensity: rgba[0] = c[0]; return;
    case TextureFormat::kLuminanceAlpha: rgba[0] = c[0], rgba[3] = c[1]; return;
    case TextureFormat::kRgb: std::copy(c, c + 3, rgba); return;
    case TextureFormat::kRgba: std::copy(c, c + 4, rgba); return;
  }
}

int component_size(const StoredFormat& f, GLenum pname) {
  using F = TextureFormat;
  if (pname == kTextureStencilSize) return f.stencil_bits;
  if (f.depth || pname == GL_TEXTURE_DEPTH_SIZE) return f.depth && pname == GL_TEXTURE_DEPTH_SIZE ? f.bits[0] : 0;
  const bool rgb = f.base == F::kRgb || f.base == F::kRgba;
  switch (pname) {
    case GL_TEXTURE_RED_SIZE: return rgb ? f.bits[0] : 0;
    case GL_TEXTURE_GREEN_SIZE: return rgb ? f.bits[1] : 0;
    case GL_TEXTURE_BLUE_SIZE: return rgb ? f.bits[2] : 0;
    case GL_TEXTURE_ALPHA_SIZE:
      return f.base == F::kRgba ? f.bits[3] : f.base == F::kAlpha ? f.bits[0] : f.base == F::kLuminanceAlpha ? f.bits[1] : 0;
    case GL_TEXTURE_LUMINANCE_SIZE: return f.base == F::kLuminance || f.base == F::kLuminanceAlpha ? f.bits[0] : 0;
    case GL_TEXTURE_INTENSITY_SIZE: return f.base == F::kIntensity ? f.bits[0] : 0;
    default: return 0;
  }
}

}  // namespace shadelab::gl
