// glBitmap (GL 1.1 section 3.7): a bitmap unpacked with glPixelStore's unpack parameters makes
// a fragment, with the raster position's colour, depth and texture coordinates, wherever its
// bit is 1; they go through texturing, fog and every per-fragment operation (the core's
// draw_fragments). glPixelZoom does not apply. The raster position then moves by (xmove, ymove)
// (what GLUT's bitmap fonts advance by), unless it is invalid.
#include <algorithm>
#include <cmath>
#include <vector>

#include "gl/generated/exec.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/capture.hpp"
#include "gl/src/dlist.hpp"
#include "gl/src/draw_state.hpp"
#include "gl/src/pixels.hpp"

namespace shadelab::gl {
namespace {

// The bitmap's lower left pixel: floor(raster position - origin), with Mesa's (and SGI's)
// small epsilon so that a position a hair below an integer takes that integer.
int corner(float raster, float origin) {
  const float v = raster + 0.0001f - origin;  // may be NaN or infinite after large moves
  return v == v ? int(std::floor(std::clamp(v, -1e9f, 1e9f))) : 0;
}

// Only the part of the bitmap inside the framebuffer is unpacked and drawn.
void draw_bitmap(GlContext& c, GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, const GLubyte* bits) {
  const RasterPosition& r = c.raster_pos;
  const long long x = corner(r.window.x, xorig), y = corner(r.window.y, yorig);
  const int x0 = int(std::clamp<long long>(-x, 0, width)), y0 = int(std::clamp<long long>(-y, 0, height));
  const int x1 = int(std::clamp<long long>(c.fb.width - x, x0, width));
  const int y1 = int(std::clamp<long long>(c.fb.height - y, y0, height));
  if (x0 >= x1 || y0 >= y1) return;
  const ClientImage image(c.unpack, bits, width, GL_COLOR_INDEX, GL_BITMAP);
  std::vector<std::uint8_t> mask(std::size_t(x1 - x0) * std::size_t(y1 - y0));
  for (int j = y0; j < y1; ++j) {
    for (int i = x0; i < x1; ++i) mask[std::size_t(j - y0) * std::size_t(x1 - x0) + std::size_t(i - x0)] = image.bit(i, j);
  }
  FragmentRect rect;
  rect.x = int(x + x0);
  rect.y = int(y + y0);
  rect.width = x1 - x0;
  rect.height = y1 - y0;
  const glm::vec4 color = r.color;
  rect.colors = std::span<const glm::vec4>(&color, 1);
  rect.depth = r.window.z;
  rect.mask = mask;
  rect.texcoords = r.texcoords;  // s / q and t / q are taken per fragment by the core
  rect.fog_coord = r.distance;  // section 3.7: the raster position's (Mesa takes 0)
  draw_rectangle(c, rect);
}

}  // namespace

void exec::Bitmap(GlContext& c, GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove,
                  GLfloat ymove, const GLubyte* bitmap) {
  if (width < 0 || height < 0) return c.set_error(GL_INVALID_VALUE);
  RasterPosition& r = c.raster_pos;
  if (!r.valid) return;
  if (c.render_mode == GL_FEEDBACK) feedback_raster_position(c, GL_BITMAP_TOKEN);
  else if (c.render_mode == GL_RENDER && width > 0 && height > 0 && bitmap) {
    capture_pixels(c);
    draw_bitmap(c, width, height, xorig, yorig, bitmap);
  }
  r.window.x += xmove;
  r.window.y += ymove;
}

// In a display list the bitmap is kept as the unpack state of the moment reads it (GL 1.1
// section 5.4), tightly packed, most significant bit first.
void save::Bitmap(GlContext& c, GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove,
                  GLfloat ymove, const GLubyte* bitmap) {
  const bool readable = bitmap && width >= 0 && height >= 0;
  std::vector<unsigned char> bits;
  if (readable) bits = copy_bitmap(c.unpack, width, height, bitmap);
  record::Bitmap(c, width, height, xorig, yorig, xmove, ymove, readable ? bits.data() : nullptr, bits.size());
}

}  // namespace shadelab::gl
