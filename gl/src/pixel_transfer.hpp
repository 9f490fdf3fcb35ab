// GL 1.1's pixel transfer operations (section 3.6.3, figure 3.7; section 4.3.2 for reading):
// scale and bias of colour and depth, index shift and offset, the colour, index-to-RGBA and
// stencil maps; and client images unpacked through them, as glDrawPixels and glTexImage* take
// them. Reads the transfer state it is given; no framebuffer, no GL errors.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "gl/src/context.hpp"

namespace shadelab::gl {

/// Scale and bias, then (GL_MAP_COLOR) the R_TO_R ... A_TO_A maps, on an RGBA colour (section
/// 3.6.3). The map index is the clamped component times the map's size - 1, rounded to the
/// nearest even integer at halves (as Mesa's readback does).
glm::vec4 transfer_color(const PixelTransfer& t, glm::vec4 rgba);

/// Index shift and offset (section 3.6.3): shifted left by GL_INDEX_SHIFT bits (right when
/// negative), then GL_INDEX_OFFSET added.
std::int64_t shift_index(const PixelTransfer& t, std::int64_t index);

/// A colour index as RGBA through the I_TO_R ... I_TO_A maps (an RGBA context converts colour
/// indices this way whether GL_MAP_COLOR is set or not); the index is masked by each map's
/// size - 1.
glm::vec4 index_to_rgba(const PixelTransfer& t, std::int64_t index);

/// A stencil index after shift and offset and, with GL_MAP_STENCIL, the S_TO_S map, kept to the
/// stencil buffer's 8 bits (Mesa computes in bytes).
std::uint8_t transfer_stencil(const PixelTransfer& t, std::int64_t index);

/// A depth value after GL_DEPTH_SCALE and GL_DEPTH_BIAS, clamped to [0, 1].
float transfer_depth(const PixelTransfer& t, float depth);

/// The pixels of a client image (glPixelStore's unpack layout), row 0 first, as glDrawPixels
/// makes fragments of them (section 3.6.4). Colour formats: components converted (table 2.6),
/// missing ones 0 (alpha 1), luminance into R, G and B, then transfer_color; GL_COLOR_INDEX:
/// shift_index and index_to_rgba. Every colour is clamped to [0, 1]. `pixels` is not null.
void unpack_color_image(const GlContext& c, const void* pixels, int width, int height, GLenum format,
                        GLenum type, std::vector<glm::vec4>& out);
/// GL_DEPTH_COMPONENT images: converted (table 2.6), transfer_depth.
void unpack_depth_image(const GlContext& c, const void* pixels, int width, int height, GLenum type,
                        std::vector<float>& out);
/// GL_DEPTH_STENCIL images of GL_UNSIGNED_INT_24_8 pixels (EXT_packed_depth_stencil): the high
/// 24 bits as a depth through transfer_depth, the low 8 as a stencil index through
/// transfer_stencil.
void unpack_depth_stencil_image(const GlContext& c, const void* pixels, int width, int height,
                                std::vector<float>& depths, std::vector<std::uint8_t>& stencil);
/// GL_STENCIL_INDEX images: transfer_stencil of each index.
void unpack_stencil_image(const GlContext& c, const void* pixels, int width, int height, GLenum type,
                          std::vector<std::uint8_t>& out);

}  // namespace shadelab::gl
