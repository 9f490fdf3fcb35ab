// glDrawPixels and glCopyPixels (GL 1.1 sections 3.6.4, 4.3.3): an image (from client memory
// through unpacking and pixel transfer, or from the framebuffer through the transfer
// operations) made into fragments at the current raster position, zoomed by glPixelZoom,
// which then go through texturing, fog and every per-fragment operation (the core's
// draw_fragments); stencil images are written into the stencil buffer through its write mask.
// Where the specification lets an implementation choose, llvmpipe's choice is taken (the
// position rounded to the nearest pixel, the zoomed pixels whose centres the rectangle covers
// with its left and bottom edges included).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "gl/generated/exec.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/capture.hpp"
#include "gl/src/dlist.hpp"
#include "gl/src/draw_state.hpp"
#include "gl/src/pixel_transfer.hpp"
#include "gl/src/pixels.hpp"
#include "gl/src/query_state.hpp"
#include "gl/src/texture.hpp"

namespace shadelab::gl {
namespace {

// An image after unpacking and the transfer operations: colours, depths or stencil indices
// (one of them filled) of its pixels [x0, x0 + w) x [y0, y0 + h), the only ones that make
// fragments (a copy keeps only what lies in the framebuffer).
struct PixelImage {
  int width = 0, height = 0;
  int x0 = 0, y0 = 0, w = 0, h = 0;
  std::vector<glm::vec4> colors;
  std::vector<float> depths;
  std::vector<std::uint8_t> stencil;

  // The stored index of image pixel (x, y), or -1 when it makes no fragment.
  long long at(int x, int y) const {
    if (x < x0 || y < y0 || x >= x0 + w || y >= y0 + h) return -1;
    return (long long)(y - y0) * w + (x - x0);
  }
};

// The window pixels a zoomed row or column of `n` image pixels covers from `start` (section
// 3.6.4): those whose centre lies in [start, start + n zoom) (in [start + n zoom, start) when
// the zoom is negative), clipped to [0, limit); and the image pixel each shows.
struct ZoomedSpan {
  int first = 0, end = 0;  // window pixels [first, end)
  int start;
  float zoom;
  int n;
  int source(int pixel) const {
    const double s = std::floor((double(pixel) + 0.5 - start) / zoom);
    return int(std::clamp(s, 0.0, double(n - 1)));  // a centre on the far edge shows the last one
  }
};

ZoomedSpan zoomed_span(int start, int n, float zoom, int limit) {
  ZoomedSpan z{0, 0, start, zoom, n};
  // The far edge in single precision, as Mesa places its quad.
  const float far_edge = float(start) + float(n) * zoom;
  const double lo = std::min<double>(start, far_edge), hi = std::max<double>(start, far_edge);
  z.first = int(std::clamp(std::ceil(lo - 0.5), 0.0, double(limit)));
  z.end = int(std::clamp(std::ceil(hi - 0.5), 0.0, double(limit)));
  if (z.end < z.first) z.end = z.first;
  return z;
}

// write_stencil into the buffers in fb.
void write_stencil_buffer(GlContext& c, const PixelImage& img, const ZoomedSpan& xs, const ZoomedSpan& ys) {
  settle_clears(c);
  const std::uint8_t mask = std::uint8_t(c.raster.stencil_write_mask & 0xffu);
  const bool depths = !img.depths.empty() && c.raster.depth_mask;
  int x0 = 0, y0 = 0, x1 = c.fb.width, y1 = c.fb.height;
  scissor_box(c, x0, y0, x1, y1);  // unchanged when every pixel passes
  x0 = std::max(xs.first, x0), x1 = std::min(xs.end, x1);
  y0 = std::max(ys.first, y0), y1 = std::min(ys.end, y1);
  for (int y = y0; y < y1; ++y) {
    const int sy = ys.source(y);
    for (int x = x0; x < x1; ++x) {
      const long long i = img.at(xs.source(x), sy);
      if (i < 0) continue;
      const std::size_t p = std::size_t(y) * std::size_t(c.fb.width) + std::size_t(x);
      std::uint8_t& s = c.fb.stencil[p];
      s = std::uint8_t((s & ~mask) | (img.stencil[std::size_t(i)] & mask));
      if (depths) c.fb.depth[p] = img.depths[std::size_t(i)];
    }
  }
  if (depths) mark_dirty(c, x0, y0, x1, y1);  // no longer known to hold the cleared depth
}

// A stencil image written through the write mask and the scissor box: the pixel ownership
// and scissor tests and nothing else apply (section 4.3.1; llvmpipe draws it with the
// scissor on and every other test off). A GL_DEPTH_STENCIL image (depths too) writes its
// depths the same way, through the depth write mask, and no colour (as llvmpipe draws it:
// depth test always passing, colour writes off).
void write_stencil(GlContext& c, const PixelImage& img, const ZoomedSpan& xs, const ZoomedSpan& ys) {
  for_each_sample_buffer(c, [&] { write_stencil_buffer(c, img, xs, ys); });
}

// The zoomed image's fragments with their colours (or the raster colour and their depths)
// through draw_fragments.
void draw_fragments_of(GlContext& c, const PixelImage& img, const ZoomedSpan& xs, const ZoomedSpan& ys) {
  const RasterPosition& r = c.raster_pos;
  FragmentRect rect;
  rect.x = xs.first, rect.y = ys.first;
  rect.width = xs.end - xs.first, rect.height = ys.end - ys.first;
  const std::size_t n = std::size_t(rect.width) * std::size_t(rect.height);
  std::vector<glm::vec4> colors;
  std::vector<float> depths;
  std::vector<std::uint8_t> mask;
  const bool color = !img.colors.empty();
  if (color) colors.resize(n);
  else depths.resize(n);
  const bool whole = img.w == img.width && img.h == img.height;
  if (!whole) mask.resize(n);
  for (int y = 0; y < rect.height; ++y) {
    const int sy = ys.source(ys.first + y);
    for (int x = 0; x < rect.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(rect.width) + std::size_t(x);
      const long long s = img.at(xs.source(xs.first + x), sy);
      if (!whole) mask[i] = s >= 0;
      if (s < 0) continue;
      if (color) colors[i] = img.colors[std::size_t(s)];
      else depths[i] = img.depths[std::size_t(s)];
    }
  }
  const glm::vec4 raster_color = r.color;
  rect.colors = color ? std::span<const glm::vec4>(colors) : std::span<const glm::vec4>(&raster_color, 1);
  rect.depth = r.window.z;
  rect.depths = depths;
  rect.mask = mask;
  rect.texcoords = r.texcoords;  // s / q and t / q are taken per fragment by the core
  rect.fog_coord = r.distance;  // section 3.6.4: the raster position's (Mesa takes 0)
  draw_rectangle(c, rect);
}

// A depth value as llvmpipe writes a fragment's own depth into its 24-bit (or 16-bit) buffer:
// scaled in single precision and rounded to the nearest (glReadPixels then returns those bits).
float stored_depth(const GlContext& c, float d) {
  const float max = c.depth_bits == 16 ? 65535.0f : 16777215.0f;
  return float(double(std::nearbyint(d * max)) / double(max));
}

// Draws an image with its lower left corner at window pixel (x, y), zoomed (section 3.6.4).
void draw_image(GlContext& c, int x, int y, PixelImage& img) {
  for (float& d : img.depths) d = stored_depth(c, d);
  const ZoomedSpan xs = zoomed_span(x, img.width, c.pixel.zoom_x, c.fb.width);
  const ZoomedSpan ys = zoomed_span(y, img.height, c.pixel.zoom_y, c.fb.height);
  if (xs.first >= xs.end || ys.first >= ys.end) return;
  if (!img.stencil.empty()) write_stencil(c, img, xs, ys);
  else draw_fragments_of(c, img, xs, ys);
}

// The raster position rounded to a pixel, as Mesa rounds it (halves away from zero). glBitmap
// may have moved it anywhere, even to infinity.
int raster_pixel(float v) { return v == v ? int(std::lround(std::clamp(v, -1e9f, 1e9f))) : 0; }

GLenum draw_error(const GlContext& c, GLsizei width, GLsizei height, GLenum format, GLenum type) {
  if (width < 0 || height < 0) return GL_INVALID_VALUE;
  if (const GLenum e = format_type_error(format, type); e != GL_NO_ERROR) return e;
  if (((format == GL_STENCIL_INDEX || format == kDepthStencil) && c.stencil_bits == 0) ||
      ((format == GL_DEPTH_COMPONENT || format == kDepthStencil) && c.depth_bits == 0)) {
    return GL_INVALID_OPERATION;
  }
  return GL_NO_ERROR;
}

void unpack_image(const GlContext& c, const void* pixels, GLenum format, GLenum type, PixelImage& img) {
  if (format == kDepthStencil) unpack_depth_stencil_image(c, pixels, img.width, img.height, img.depths, img.stencil);
  else if (format == GL_STENCIL_INDEX) unpack_stencil_image(c, pixels, img.width, img.height, type, img.stencil);
  else if (format == GL_DEPTH_COMPONENT) unpack_depth_image(c, pixels, img.width, img.height, type, img.depths);
  else unpack_color_image(c, pixels, img.width, img.height, format, type, img.colors);
}

// The framebuffer's pixels of a copy (section 4.3.3: as glReadPixels reads them, through the
// transfer operations); pixels outside the framebuffer make no fragments (GL leaves them
// undefined).
void read_source(const GlContext& c, const ColorBuffer& color, int sx, int sy, GLenum type, PixelImage& img) {
  img.x0 = int(std::clamp<long long>(-(long long)sx, 0, img.width));
  img.y0 = int(std::clamp<long long>(-(long long)sy, 0, img.height));
  img.w = int(std::clamp<long long>((long long)c.fb.width - sx, img.x0, img.width)) - img.x0;
  img.h = int(std::clamp<long long>((long long)c.fb.height - sy, img.y0, img.height)) - img.y0;
  const std::size_t n = std::size_t(img.w) * std::size_t(img.h);
  if (type == GL_COLOR) img.colors.resize(n);
  if (type == GL_DEPTH || type == kDepthStencil) img.depths.resize(n);
  if (type == GL_STENCIL || type == kDepthStencil) img.stencil.resize(n);
  for (int y = 0; y < img.h; ++y) {
    for (int x = 0; x < img.w; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(img.w) + std::size_t(x);
      const std::size_t p = std::size_t(sy + img.y0 + y) * std::size_t(c.fb.width) + std::size_t(sx + img.x0 + x);
      if (type == GL_DEPTH || type == kDepthStencil) img.depths[i] = transfer_depth(c.pixel, c.fb.depth[p]);
      if (type == GL_STENCIL || type == kDepthStencil) img.stencil[i] = transfer_stencil(c.pixel, c.fb.stencil[p]);
      if (type == GL_COLOR) {
        const std::uint8_t* px = &color[p * 4];
        const glm::vec4 v = transfer_color(c.pixel, glm::vec4(px[0], px[1], px[2], px[3]) * (1.0f / 255.0f));
        img.colors[i] = glm::clamp(v, glm::vec4(0.0f), glm::vec4(1.0f));
      }
    }
  }
}

GLenum copy_error(const GlContext& c, GLsizei width, GLsizei height, GLenum type) {
  if (width < 0 || height < 0) return GL_INVALID_VALUE;
  if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL && type != kDepthStencil) return GL_INVALID_ENUM;
  if ((type == GL_COLOR && c.buffers.read_buffer == GL_NONE) ||
      ((type == GL_DEPTH || type == kDepthStencil) && c.depth_bits == 0) ||
      ((type == GL_STENCIL || type == kDepthStencil) && c.stencil_bits == 0)) {
    return GL_INVALID_OPERATION;
  }
  return GL_NO_ERROR;
}

// The usual glDrawPixels: unsigned-byte RGB(A) or BGR(A) pixels with no pixel transfer at zoom
// 1, whose fragments nothing but the ownership and scissor tests touch (no texture, colour
// sum, fog, alpha, stencil or depth test, blending, logic op or masked channel, no query
// counting them): the colour buffer takes their bytes (draw_fragments writes the same: a byte
// goes to a float and back exactly), row by row in place. False, with nothing drawn, otherwise.
bool draw_bytes(GlContext& c, int x, int y, int width, int height, GLenum format, GLenum type, const void* pixels) {
  const RasterState& r = c.raster;
  if (type != GL_UNSIGNED_BYTE || c.pixel.changes_color() || c.pixel.zoom_x != 1.0f || c.pixel.zoom_y != 1.0f) return false;
  ByteOrder order;
  if (!byte_order(format, order) || !draws_color(c) || draws_both_buffers(c) || (r.depth_test && c.depth_bits > 0) || (r.stencil_test && c.stencil_bits > 0)) return false;
  if (r.blend || r.alpha_test || r.color_logic_op || c.fog.enabled || c.fog.color_sum) return false;
  for (bool m : r.color_mask) {
    if (!m) return false;
  }
  if (textured_units(c) != 0 || query_counts(c) != nullptr || c.ms.count > 0) return false;
  int x0 = 0, y0 = 0, x1 = c.fb.width, y1 = c.fb.height;
  scissor_box(c, x0, y0, x1, y1);  // unchanged when every pixel passes
  x0 = std::max<long long>(x0, x), y0 = std::max<long long>(y0, y);
  x1 = int(std::min<long long>(x1, (long long)x + width)), y1 = int(std::min<long long>(y1, (long long)y + height));
  capture_pixels(c);
  if (x0 >= x1 || y0 >= y1) return true;
  settle_clears(c);
  const int n = order.components, red = order.red, blue = order.blue;
  const PixelLayout layout = pixel_layout(c.unpack, n, 1, width);
  const auto* in = static_cast<const unsigned char*>(pixels);
  for (int j = y0; j < y1; ++j) {
    const unsigned char* src = in + layout.offset(x0 - x, j - y);
    std::uint8_t* dst = &c.fb.color[(std::size_t(j) * std::size_t(c.fb.width) + std::size_t(x0)) * 4];
    if (order.rgba()) {
      std::memcpy(dst, src, std::size_t(x1 - x0) * 4);
      continue;
    }
    for (int i = x0; i < x1; ++i, src += n, dst += 4) {
      dst[0] = src[red], dst[1] = src[1], dst[2] = src[blue], dst[3] = n == 4 ? src[3] : 255;
    }
  }
  mark_dirty(c, x0, y0, x1, y1);
  return true;
}

}  // namespace

void exec::DrawPixels(GlContext& c, GLsizei width, GLsizei height, GLenum format, GLenum type,
                      const void* pixels) {
  if (const GLenum e = draw_error(c, width, height, format, type); e != GL_NO_ERROR) return c.set_error(e);
  if (!c.raster_pos.valid) return;
  if (c.render_mode != GL_RENDER) return feedback_raster_position(c, GL_DRAW_PIXEL_TOKEN);
  if (width == 0 || height == 0) return;
  // Mesa reports a missing image as a failed allocation of the texture it would make of it.
  if (!pixels) return c.set_error(GL_OUT_OF_MEMORY);
  const int x = raster_pixel(c.raster_pos.window.x), y = raster_pixel(c.raster_pos.window.y);
  if (draw_bytes(c, x, y, width, height, format, type, pixels)) return;
  PixelImage img;
  img.width = img.w = width, img.height = img.h = height;
  unpack_image(c, pixels, format, type, img);
  capture_pixels(c);
  draw_image(c, raster_pixel(c.raster_pos.window.x), raster_pixel(c.raster_pos.window.y), img);
}

// In a display list the image is kept as the unpack state of the moment reads it (GL 1.1
// section 5.4), tightly packed (GL_BITMAP images as rows of bytes, most significant bit
// first); the transfer operations apply when the list runs. An image the command will reject
// is not read.
void save::DrawPixels(GlContext& c, GLsizei width, GLsizei height, GLenum format, GLenum type, const void* pixels) {
  const bool readable = pixels && width >= 0 && height >= 0 && format_type_error(format, type) == GL_NO_ERROR;
  std::vector<unsigned char> image;
  if (readable && type == GL_BITMAP) image = copy_bitmap(c.unpack, width, height, pixels);
  else if (readable) image = copy_image(c.unpack, width, height, elements_per_pixel(format, type), pixel_type_size(type), pixels);
  record::DrawPixels(c, width, height, format, type, readable ? image.data() : nullptr, image.size());
}

// The source is read whole before anything is drawn, so overlapping rectangles copy what was
// there (section 4.3.3).
void exec::CopyPixels(GlContext& c, GLint x, GLint y, GLsizei width, GLsizei height, GLenum type) {
  if (const GLenum e = copy_error(c, width, height, type); e != GL_NO_ERROR) return c.set_error(e);
  if (!c.raster_pos.valid) return;
  if (c.render_mode != GL_RENDER) return feedback_raster_position(c, GL_COPY_PIXEL_TOKEN);
  if (width == 0 || height == 0) return;
  settle_clears(c);
  PixelImage img;
  img.width = width, img.height = height;
  read_source(c, type == GL_COLOR ? read_color_buffer(c) : c.fb.color, x, y, type, img);
  capture_pixels(c);
  draw_image(c, raster_pixel(c.raster_pos.window.x), raster_pixel(c.raster_pos.window.y), img);
}

}  // namespace shadelab::gl
