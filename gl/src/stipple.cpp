// glPolygonStipple and glGetPolygonStipple (GL 1.1 sections 3.5.2 and 6.1.5): the 32 x 32
// pattern read from and written to client memory as a GL_BITMAP image through the unpack and
// pack pixel-store state (pixels.hpp's BitmapLayout). State only: the core pipeline applies
// it to polygons (FragmentState::stipple, draw_state.cpp).
#include "gl/generated/exec.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/context.hpp"
#include "gl/src/pixels.hpp"

namespace shadelab::gl {

namespace {

constexpr int kSize = 32;

// The pattern's rows from a GL_BITMAP image laid out as `store` says.
std::array<std::uint32_t, kSize> unpack_pattern(const PixelStore& store, const GLubyte* mask) {
  const BitmapLayout l = bitmap_layout(store, kSize);
  std::array<std::uint32_t, kSize> rows{};
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) rows[std::size_t(y)] |= (mask[l.byte(x, y)] & l.mask(x)) ? 1u << x : 0u;
  }
  return rows;
}

}  // namespace

// Row y of the image is row y of the pattern (the bottom row first); its first bit is the
// leftmost pixel. A null pointer reads nothing (no buffer object can stand behind it in GL
// 1.1), as Mesa leaves the pattern then.
void exec::PolygonStipple(GlContext& c, const GLubyte* mask) {
  if (mask) c.raster.stipple = unpack_pattern(c.unpack, mask);
}

// In a display list, the pattern is kept as the unpack state of the moment reads it (GL 1.1
// section 5.4): 32 rows of 4 bytes, most significant bit first, which the replay reads with
// the default unpack state (config.toml's default_unpack). A null pointer stays null.
void save::PolygonStipple(GlContext& c, const GLubyte* mask) {
  if (!mask) return record::PolygonStipple(c, nullptr, 0);
  const std::array<std::uint32_t, kSize> rows = unpack_pattern(c.unpack, mask);
  GLubyte bytes[kSize * 4] = {};
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      if ((rows[std::size_t(y)] >> x) & 1u) bytes[y * 4 + x / 8] |= GLubyte(0x80u >> (x % 8));
    }
  }
  record::PolygonStipple(c, bytes, sizeof bytes);
}

// Every byte a row's bits fall in is written whole, its bits outside the pattern zero (as
// Mesa's bitmap packing does when GL_PACK_SKIP_PIXELS is not a multiple of 8).
void exec::GetPolygonStipple(GlContext& c, GLubyte* mask) {
  if (!mask) return;
  const BitmapLayout l = bitmap_layout(c.pack, kSize);
  for (int y = 0; y < kSize; ++y) {
    const std::uint32_t row = c.raster.stipple[std::size_t(y)];
    for (std::size_t i = l.byte(0, y); i <= l.byte(kSize - 1, y); ++i) mask[i] = 0;
    for (int x = 0; x < kSize; ++x) {
      if ((row >> x) & 1u) mask[l.byte(x, y)] |= GLubyte(l.mask(x));
    }
  }
}

}  // namespace shadelab::gl
