// The state of GL 1.1's pixel operations, kept in GlContext: the current raster position
// (section 2.12), the pixel transfer modes, pixel maps and zoom (sections 3.6.2-3.6.3), the
// colour buffers drawn and read (section 4.2.1) and the accumulation buffer (section 4.2.4).
// Plain data with GL's initial values; the exec:: functions of raster_pos.cpp, pixel_transfer.cpp,
// buffers.cpp and accum.cpp change it. No behaviour here.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "shadelab/pipeline.hpp"

namespace shadelab::gl {

/// GL_MAX_PIXEL_MAP_TABLE: the largest pixel map (Mesa's).
inline constexpr int kMaxPixelMapTable = 256;

/// The current raster position (GL 1.1 section 2.12) and its associated data. When a
/// glRasterPos falls outside the view volume only `valid` changes (what Mesa keeps).
struct RasterPosition {
  glm::vec4 window{0.0f, 0.0f, 0.0f, 1.0f};  ///< window x, y, z and the clip-space w
  bool valid = true;
  glm::vec4 color{1.0f};                        ///< lit (clamped) or the current colour (as given)
  glm::vec4 secondary{0.0f, 0.0f, 0.0f, 1.0f};  ///< the separate specular colour when lit
  /// Per texture unit, after the unit's texture matrix.
  std::array<glm::vec4, kMaxTextureUnits> texcoords = FragmentRect::filled_texcoords();
  float distance = 0.0f;                        ///< eye-space distance from the eye (fog)
  float index = 1.0f;                           ///< GL_CURRENT_RASTER_INDEX (colour index mode only)
};

/// The ten pixel maps of GL 1.1 table 3.3, in the order of their enums
/// (GL_PIXEL_MAP_I_TO_I = 0x0C70 ... GL_PIXEL_MAP_A_TO_A = 0x0C79). Colour maps hold values in
/// [0, 1]; I_TO_I holds indices as given, S_TO_S rounded to integers (as Mesa stores them).
struct PixelMaps {
  static constexpr int kCount = 10;
  static constexpr int kItoI = 0, kStoS = 1, kItoR = 2, kRtoR = 6;
  std::array<std::vector<float>, kCount> maps{
      std::vector<float>{0.0f}, std::vector<float>{0.0f}, std::vector<float>{0.0f},
      std::vector<float>{0.0f}, std::vector<float>{0.0f}, std::vector<float>{0.0f},
      std::vector<float>{0.0f}, std::vector<float>{0.0f}, std::vector<float>{0.0f},
      std::vector<float>{0.0f}};
};

/// glPixelTransfer and glPixelZoom (GL 1.1 sections 3.6.3, 3.6.4).
struct PixelTransfer {
  std::array<float, 4> scale{1.0f, 1.0f, 1.0f, 1.0f};  ///< GL_RED_SCALE ... GL_ALPHA_SCALE
  std::array<float, 4> bias{0.0f, 0.0f, 0.0f, 0.0f};   ///< GL_RED_BIAS ... GL_ALPHA_BIAS
  float depth_scale = 1.0f, depth_bias = 0.0f;
  GLint index_shift = 0, index_offset = 0;
  bool map_color = false, map_stencil = false;
  float zoom_x = 1.0f, zoom_y = 1.0f;
  PixelMaps maps;

  /// Whether colours change in the transfer (scale, bias or maps).
  bool changes_color() const {
    return map_color || scale != std::array<float, 4>{1.0f, 1.0f, 1.0f, 1.0f} ||
           bias != std::array<float, 4>{0.0f, 0.0f, 0.0f, 0.0f};
  }
};

/// The colour buffers (GL 1.1 section 4.2.1) and the accumulation buffer (4.2.4). Every
/// colour buffer name a context accepts draws into and reads from its one colour buffer;
/// GL_NONE draws nothing.
struct BufferState {
  GLenum draw_buffer = GL_FRONT;
  GLenum read_buffer = GL_FRONT;
  /// Bits per accumulation channel: 16 (signed, as Mesa's RGBA_SNORM16 buffer) or 0 (none).
  int accum_bits = 0;
  glm::vec4 accum_clear{0.0f};  ///< glClearAccum, clamped to [-1, 1]
  /// The accumulation buffer, RGBA per pixel in framebuffer order, value / 32767 each;
  /// sized at its first use (and whenever the framebuffer's size changed).
  std::vector<std::int16_t> accum;
};

}  // namespace shadelab::gl
