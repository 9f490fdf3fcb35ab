// Texture internal formats (GL 1.1 section 3.8.1, tables 3.15 and 3.16): the base format of
// each internal format, the precision it is stored with (as Mesa's llvmpipe stores it:
// measured with glGetTexImage and the component-size queries), and the conversions of texel
// components into and out of that storage. Pure conversions: no GL state, no errors.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "shadelab/texture.hpp"

namespace shadelab::gl {

/// EXT_packed_depth_stencil (core in GL 3.0; GL 1.5's headers do not name it): depth and
/// stencil in one pixel, GL_UNSIGNED_INT_24_8's depth in the high 24 bits and stencil in the
/// low 8, and the texture format that holds both.
inline constexpr GLenum kDepthStencil = 0x84F9;       // GL_DEPTH_STENCIL_EXT
inline constexpr GLenum kUnsignedInt24_8 = 0x84FA;    // GL_UNSIGNED_INT_24_8_EXT
inline constexpr GLenum kDepth24Stencil8 = 0x88F0;    // GL_DEPTH24_STENCIL8_EXT
inline constexpr GLenum kTextureStencilSize = 0x88F1;  // GL_TEXTURE_STENCIL_SIZE_EXT

/// How an internal format is kept: its base format and the bits of each of the base format's
/// components, in their order (R, G, B, A; L; L, A; I; A). 8 bits or fewer are kept in the
/// core's RGBA8 level (bit-replicated, as llvmpipe expands them for sampling); more bits are
/// kept beside it (TexImage::wide) for glGetTexImage.
struct StoredFormat {
  TextureFormat base = TextureFormat::kRgba;
  int components = 4;
  std::uint8_t bits[4] = {8, 8, 8, 8};
  /// A depth format (GL 1.4, ARB_depth_texture): one component of bits[0] bits (what
  /// GL_TEXTURE_DEPTH_SIZE reports), kept as floats in TextureLevel::depth_values (llvmpipe
  /// reads back the floats given, whatever the size); `base` is unused.
  bool depth = false;
  /// A depth-stencil format (EXT_packed_depth_stencil): the stencil's bits besides (what
  /// GL_TEXTURE_STENCIL_SIZE reports), its indices kept in TexImage::stencil for
  /// glGetTexImage; sampling reads the depth.
  int stencil_bits = 0;

  bool wide() const;  ///< some component has more than 8 bits
};

/// The stored format of a glTexImage internal format (1-4 and the GL 1.1 names); false for
/// anything else.
bool stored_format(GLint internal_format, StoredFormat& out);

/// Which of an RGBA colour's components a base format keeps, in its order: L and I take R.
/// Returns the number written.
int base_components(TextureFormat base, const float rgba[4], float out[4]);

/// A component in [0, 1] quantized to `bits` bits (as Mesa's float-to-unorm); an
/// unsigned byte is converted exactly as Mesa's unorm-to-unorm conversion does (rounded when
/// narrowing, bits replicated when widening).
std::uint16_t quantize(float v, int bits);
std::uint16_t quantize_byte(std::uint8_t v, int bits);

/// An n-bit stored value as an 8-bit one (bits replicated up to 8, rounded down from more)
/// and back.
std::uint8_t stored_to_byte(std::uint16_t k, int bits);
std::uint16_t byte_to_stored(std::uint8_t b, int bits);

/// An n-bit stored value as a 16-bit one (bits replicated) and as a float in [0, 1].
std::uint16_t stored_to_ushort(std::uint16_t k, int bits);
float stored_to_float(std::uint16_t k, int bits);

/// The core's RGBA8 texel of base-format components already reduced to bytes (texture.hpp's
/// expansion: L as (L, L, L, 1), I as (I, I, I, I), A as (0, 0, 0, A), RGB with alpha 1).
void expand_texel(TextureFormat base, const std::uint8_t* components, std::uint8_t rgba[4]);

/// glGetTexImage's RGBA of a texel's base-format components (GL 1.1 section 6.1.4, table
/// 6.1 as Mesa applies it): L and I in R with G = B = 0, A = 1 where the format has none.
void texel_to_rgba(TextureFormat base, const float* components, float rgba[4]);

/// A depth in [0, 1] as a depth texture of `bits` bits keeps it (Mesa 22 on llvmpipe, measured:
/// Z16, Z24 and Z32 unorm storage, d (2^bits - 1) truncated, read back as k / (2^bits - 1)).
float stored_depth_value(float d, int bits);

/// GL_TEXTURE_{RED,GREEN,BLUE,ALPHA,LUMINANCE,INTENSITY,DEPTH}_SIZE of a stored format.
int component_size(const StoredFormat& f, GLenum pname);

}  // namespace shadelab::gl
