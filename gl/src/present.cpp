// The link between the context's framebuffer and the caller's OSMesa buffer: the tiles
// changed since the last flush are copied out at glFinish / glFlush and when the current
// context changes (in the buffer's format, row length and Y direction), the buffer is read in
// at OSMesaMakeCurrent, and depth values are exported in Mesa's layout for
// OSMesaGetDepthBuffer. No drawing here.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <GL/osmesa.h>

#include "gl/src/context.hpp"
#include "gl/src/osmesa_context.hpp"

namespace shadelab::gl {
namespace {

// Byte positions of R, G, B, A within a pixel of an OSMesa format (-1: absent).
struct Swizzle {
  int bytes;
  int r, g, b, a;
};

Swizzle swizzle_of(GLenum format) {
  switch (format) {
    case OSMESA_BGRA: return {4, 2, 1, 0, 3};
    case OSMESA_ARGB: return {4, 1, 2, 3, 0};
    case OSMESA_RGB: return {3, 0, 1, 2, -1};
    case OSMESA_BGR: return {3, 2, 1, 0, -1};
    default: return {4, 0, 1, 2, 3};
  }
}

// Start of framebuffer row y in the caller's buffer.
unsigned char* user_row(const UserBuffer& u, int y, int bytes) {
  std::size_t row_pixels = std::size_t(u.row_length > 0 ? u.row_length : u.width);
  std::size_t row = std::size_t(u.y_up ? y : u.height - 1 - y);
  return static_cast<unsigned char*>(u.data) + row * row_pixels * std::size_t(bytes);
}

// memcpy into the caller's buffer with streaming stores where the target has them: the
// buffer is written, never read here, so its lines need not be read into the cache first
// (the copy and the fill of a full-HD frame would read 8 MB to overwrite them).
void stream_copy(unsigned char* dst, const unsigned char* src, std::size_t n) {
#if defined(__SSE2__)
  while (n > 0 && (reinterpret_cast<std::uintptr_t>(dst) & 15u) != 0) *dst++ = *src++, --n;
  for (; n >= 16; n -= 16, dst += 16, src += 16) {
    _mm_stream_si128(reinterpret_cast<__m128i*>(dst), _mm_loadu_si128(reinterpret_cast<const __m128i*>(src)));
  }
#endif
  std::memcpy(dst, src, n);
}

}  // namespace

void make_pipeline(GlContext& c) {
  if (c.pipeline || c.use_reference) return;
  c.pipeline = std::make_unique<PipelineContext>();
  c.pipeline->set_deferred(true);
  c.pipeline->set_counting(!c.stats_path.empty());
}

void settle_clears(GlContext& c) {
  if (c.pipeline) c.pipeline->apply_pending_clears(c.fb);
  resolve_samples(c);
}

namespace {

// A multisample pass's tiles: their resolved colour is to be brought up to date.
void mark_unresolved(GlContext& c, int tile) {
  SampleBuffers& s = c.ms;
  if (s.active < 0) return;
  if (s.unresolved.size() != c.tiles.flags.size()) s.unresolved.assign(c.tiles.flags.size(), 0);
  s.unresolved[std::size_t(tile)] = 1;
  s.any_unresolved = true;
}

}  // namespace

void reset_tiles(GlContext& c) {
  constexpr int kSize = PipelineContext::kTileSize;
  TileMap& m = c.tiles;
  m.columns = (c.fb.width + kSize - 1) / kSize;
  m.flags.assign(std::size_t(m.columns) * std::size_t((c.fb.height + kSize - 1) / kSize), 0);
  if (c.pipeline) c.pipeline->pending_clears().tiles.assign(m.flags.size(), 0);
  // A new or resized framebuffer: the multisample buffer is made again from it at first use.
  SampleBuffers& s = c.ms;
  s.color.clear(), s.depth.clear(), s.stencil.clear(), s.unresolved.clear();
  s.width = s.height = 0;
  s.any_unresolved = false;
}

void mark_dirty(GlContext& c, int x0, int y0, int x1, int y1) {
  constexpr int kSize = PipelineContext::kTileSize;
  x0 = std::max(x0, 0), y0 = std::max(y0, 0);
  x1 = std::min(x1, c.fb.width), y1 = std::min(y1, c.fb.height);
  if (x0 >= x1 || y0 >= y1) return;
  TileMap& m = c.tiles;
  for (int ty = y0 / kSize; ty <= (y1 - 1) / kSize; ++ty) {
    for (int tx = x0 / kSize; tx <= (x1 - 1) / kSize; ++tx) {
      const int t = ty * m.columns + tx;
      m.flags[std::size_t(t)] = TileMap::kChanged;  // and no longer known cleared
      mark_unresolved(c, t);
    }
  }
}

void mark_drawn(GlContext& c) {
  for (int t : c.pipeline->last_draw_tiles()) {
    c.tiles.flags[std::size_t(t)] = TileMap::kChanged;
    mark_unresolved(c, t);
  }
}

void mark_all_changed(GlContext& c) {
  for (std::uint8_t& f : c.tiles.flags) f |= TileMap::kChanged;
}

void present(GlContext& c) {
  const UserBuffer& u = c.user;
  if (!u.data) return;
  resolve_samples(c);
  TileMap& m = c.tiles;
  if (c.fb.color.attached()) {
    // The caller's buffer is the colour buffer: what was drawn is there; colour clears still
    // pending are written now (depth clears stay pending).
    if (c.pipeline) c.pipeline->apply_pending_clears(c.fb, PipelineContext::PendingClears::kColor);
    for (std::uint8_t& f : m.flags) f &= std::uint8_t(~TileMap::kChanged);
    return;
  }
  if (c.pipeline) c.pipeline->finish_draws();  // pending clears stay pending
  const Swizzle s = swizzle_of(u.format);
  // Tiles holding nothing but the clear colour are filled with it in the caller's format
  // (writing without reading the framebuffer); the others are copied.
  for (bool cleared : {true, false}) {
    m.list.clear();
    for (std::size_t t = 0; t < m.flags.size(); ++t) {
      const std::uint8_t f = m.flags[t];
      if ((f & TileMap::kChanged) && ((f & TileMap::kColorClear) != 0) == cleared) m.list.push_back(int(t));
    }
    if (cleared && !m.list.empty()) {  // a row of the clear colour in the caller's format
      const auto* clear = reinterpret_cast<const std::uint8_t*>(&m.clear_color);
      m.clear_row.resize(std::size_t(c.fb.width) * std::size_t(s.bytes));
      for (std::size_t i = 0; i < m.clear_row.size(); i += std::size_t(s.bytes)) {
        unsigned char* p = &m.clear_row[i];
        p[s.r] = clear[0], p[s.g] = clear[1], p[s.b] = clear[2];
        if (s.a >= 0) p[s.a] = clear[3];
      }
    }
    for_listed_tiles(c, [&](int x0, int y0, int x1, int y1) {
      for (int y = y0; y < y1; ++y) {
        const std::uint8_t* src = &c.fb.color[(std::size_t(y) * std::size_t(c.fb.width) + std::size_t(x0)) * 4];
        unsigned char* dst = user_row(u, y, s.bytes) + std::size_t(x0) * std::size_t(s.bytes);
        if (cleared) {
          stream_copy(dst, m.clear_row.data(), std::size_t(x1 - x0) * std::size_t(s.bytes));
        } else if (u.format == OSMESA_RGBA) {
          stream_copy(dst, src, std::size_t(x1 - x0) * 4);
        } else {
          for (int x = x0; x < x1; ++x, src += 4, dst += s.bytes) {
            dst[s.r] = src[0], dst[s.g] = src[1], dst[s.b] = src[2];
            if (s.a >= 0) dst[s.a] = src[3];
          }
        }
      }
#if defined(__SSE2__)
      _mm_sfence();  // the streaming stores are seen before the flush returns
#endif
    });
  }
  for (std::uint8_t& f : m.flags) f &= std::uint8_t(~TileMap::kChanged);
}

bool lends_color(const GlContext& c) {
  const UserBuffer& u = c.user;
  return u.data && u.format == OSMESA_RGBA && u.y_up && (u.row_length == 0 || u.row_length == u.width) &&
         u.width == c.fb.width && u.height == c.fb.height;
}

// The caller's buffer is the colour buffer, as in classic OSMesa. In the framebuffer's own
// layout (RGBA bytes, rows from the bottom, no padding) it is used as it is; otherwise its
// pixels are read in (formats without alpha read as opaque) and copied out at each flush.
void import_user_buffer(GlContext& c) {
  const UserBuffer& u = c.user;
  if (lends_color(c)) {
    c.fb.color.attach(static_cast<std::uint8_t*>(u.data), c.fb.color.size());
    return;
  }
  c.fb.color.detach();
  read_user_buffer(c, c.fb.color);
}

void read_user_buffer(const GlContext& c, ColorBuffer& into) {
  const UserBuffer& u = c.user;
  const std::size_t width = std::size_t(c.fb.width);
  if (into.size() != width * std::size_t(c.fb.height) * 4) into.assign(width * std::size_t(c.fb.height) * 4, 0);
  Swizzle s = swizzle_of(u.format);
  for (int y = 0; y < c.fb.height; ++y) {
    const unsigned char* src = user_row(u, y, s.bytes);
    std::uint8_t* dst = &into[std::size_t(y) * width * 4];
    for (std::size_t x = 0; x < width; ++x, src += s.bytes, dst += 4) {
      dst[0] = src[s.r], dst[1] = src[s.g], dst[2] = src[s.b];
      dst[3] = s.a >= 0 ? src[s.a] : 255;
    }
  }
}

// Mesa's depth layouts (checked against libOSMesa 22.3): 16-bit depth as GLushort; 24-bit
// depth in the low bits of a GLuint with the 8-bit stencil value in the high byte.
void export_depth(GlContext& c) {
  settle_clears(c);
  std::size_t n = c.fb.depth.size();
  int bytes = c.depth_bits == 16 ? 2 : 4;
  c.depth_export.resize(n * std::size_t(bytes));
  for (std::size_t i = 0; i < n; ++i) {
    double d = std::clamp(double(c.fb.depth[i]), 0.0, 1.0);
    if (bytes == 2) {
      auto v = static_cast<std::uint16_t>(std::lround(d * 65535.0));
      std::memcpy(&c.depth_export[i * 2], &v, 2);
      continue;
    }
    auto v = static_cast<std::uint32_t>(std::lround(d * 16777215.0));
    if (c.stencil_bits > 0) v |= std::uint32_t(c.fb.stencil[i]) << 24;
    std::memcpy(&c.depth_export[i * 4], &v, 4);
  }
}

}  // namespace shadelab::gl
