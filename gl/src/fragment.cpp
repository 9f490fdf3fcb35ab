// Per-fragment state and clearing (GL 1.1 sections 4.1-4.2): glScissor, glAlphaFunc,
// glDepthFunc, glDepthMask, glColorMask, glLogicOp, glStencil* (with GL 1.4's wrapping
// operations), glCullFace, glFrontFace, glPolygonOffset, glClear* (blending: blend.cpp). Stores state; the core pipeline applies it per
// fragment. glClear clears the framebuffer tile by tile (with the pipeline, each tile is
// cleared by the draw that next draws into it), or the scissor box's pixels at once.
#include <algorithm>
#include <cmath>
#include <bit>
#include <cstddef>
#include <cstring>
#include <array>
#include <type_traits>

#include "gl/generated/exec.hpp"
#include "gl/src/capture.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {
namespace {

bool is_compare_func(GLenum f) { return f >= GL_NEVER && f <= GL_ALWAYS; }

// GL 1.1's operations and GL 1.4's wrapping ones (section 4.1.5).
bool is_stencil_op(GLenum op) {
  return op == GL_KEEP || op == GL_ZERO || op == GL_REPLACE || op == GL_INCR || op == GL_DECR ||
         op == GL_INVERT || op == GL_INCR_WRAP || op == GL_DECR_WRAP;
}

float clamp01(float v) { return v == v ? std::clamp(v, 0.0f, 1.0f) : 0.0f; }

// Runs fn over ranges of the framebuffer's pixels (after the deferred draws), on the
// pipeline's threads when it has them (a full-HD clear writes 18 MB).
template <class Fn>
void for_pixels(GlContext& c, const Fn& fn) {
  std::size_t n = std::size_t(c.fb.width) * std::size_t(c.fb.height);
  make_pipeline(c);
  if (c.pipeline) c.pipeline->finish_draws();  // they come first
  if (c.pipeline && n >= (1u << 16)) c.pipeline->parallel_for(n, 1u << 15, fn);
  else fn(0, n);
}

// Each of the n values at `p` becomes (value & keep) | set: a clear through a write mask, in
// 64-bit words.
template <class T>
void masked_fill(T* p, std::size_t n, T set, T keep) {
  static_assert(8 % sizeof(T) == 0);
  constexpr std::size_t kPerWord = 8 / sizeof(T);
  std::uint64_t set_word = 0, keep_word = 0;
  for (std::size_t k = 0; k < kPerWord; ++k) {
    set_word |= std::uint64_t(set) << (8 * sizeof(T) * k), keep_word |= std::uint64_t(keep) << (8 * sizeof(T) * k);
  }
  std::size_t i = 0;
  for (; i + kPerWord <= n; i += kPerWord) {
    std::uint64_t w;
    std::memcpy(&w, p + i, 8);
    w = (w & keep_word) | set_word;
    std::memcpy(p + i, &w, 8);
  }
  for (; i < n; ++i) {  // through memcpy too: a caller's colour buffer need not be aligned
    T v;
    std::memcpy(&v, p + i, sizeof(T));
    v = T((v & keep) | set);
    std::memcpy(p + i, &v, sizeof(T));
  }
}

// Lists in c.tiles.list the tiles a clear must write: all of them, or with `same_value`
// (the clear writes the value the tiles flagged `flag` hold) those not flagged. Every tile
// is then flagged; a colour clear also marks every tile changed, since the caller may have
// written into its buffer since the last flush (in Mesa, glClear writes the buffer itself).
void list_tiles_to_clear(GlContext& c, std::uint8_t flag, bool same_value) {
  TileMap& m = c.tiles;
  const std::uint8_t set = flag == TileMap::kColorClear ? std::uint8_t(flag | TileMap::kChanged) : flag;
  m.list.clear();
  for (std::size_t t = 0; t < m.flags.size(); ++t) {
    if (!(same_value && (m.flags[t] & flag))) m.list.push_back(int(t));
    m.flags[t] |= set;
  }
}

// Clears the listed tiles of `buffer` (one T per pixel: colour, what = kColor, or depth) to
// `value`: with the pipeline, left to the draws (PipelineContext::PendingClears: a tile is
// cleared by the draw that next draws into it, while the tile is in the cache, and tiles
// holding the clear colour reach the caller's buffer without being read, present.cpp);
// without it, at once.
template <class T>
void clear_listed_tiles(GlContext& c, std::uint8_t what, T* buffer, T value) {
  if (c.pipeline) {
    c.pipeline->finish_draws();  // draws made before the clear: before it in every tile
    PipelineContext::PendingClears& p = c.pipeline->pending_clears();
    p.tiles.resize(c.tiles.flags.size());  // zeroed with the tile map (reset_tiles)
    if constexpr (std::is_same_v<T, float>) p.depth = value;
    else p.color = value;
    for (int t : c.tiles.list) p.tiles[std::size_t(t)] |= what;
    return;
  }
  const std::size_t width = std::size_t(c.fb.width);
  for_listed_tiles(c, [&](int x0, int y0, int x1, int y1) {
    for (int y = y0; y < y1; ++y) {
      T* row = buffer + std::size_t(y) * width;
      std::fill(row + x0, row + x1, value);
    }
  });
}

// Lists in c.tiles.ahead the tiles of the caller's buffer (lent as the colour buffer) that
// no draw reached since the last colour clear: those a frame like the last one leaves as
// cleared. glClear has them cleared on a worker thread while the caller goes on to its next
// draw (PipelineContext::clear_ahead), instead of at the next flush after the frame's
// rasterization. (In a buffer the framebuffer copies out, a cleared tile is filled with the
// clear colour in the caller's buffer at the flush, never in the framebuffer.)
void list_tiles_to_clear_ahead(GlContext& c) {
  TileMap& m = c.tiles;
  m.ahead.clear();
  if (!c.pipeline || c.pipeline->threads() < 2 || !c.fb.color.attached()) return;
  for (std::size_t t = 0; t < m.flags.size(); ++t) {
    if (m.flags[t] & TileMap::kColorClear) m.ahead.push_back(int(t));
  }
}

// The colour buffer cleared through the colour mask (GL 1.1 section 4.2.3). Unmasked, tiles
// that still hold the same clear colour are left as they are, unless the colour buffer is
// the caller's own buffer (the caller may have written into it since).
void clear_color(GlContext& c) {
  const auto& mask = c.raster.color_mask;
  const std::array<std::uint8_t, 4> bytes = Framebuffer::color_bytes(c.raster.clear_color);  // the core's rounding
  const std::uint8_t* px = bytes.data();
  make_pipeline(c);
  bool all = mask[0] && mask[1] && mask[2] && mask[3];
  if (all) {  // whole pixels, tile by tile
    std::uint32_t value;
    std::memcpy(&value, px, 4);
    list_tiles_to_clear_ahead(c);
    list_tiles_to_clear(c, TileMap::kColorClear, value == c.tiles.clear_color && !c.fb.color.attached());
    c.tiles.clear_color = value;
    clear_listed_tiles(c, PipelineContext::PendingClears::kColor, reinterpret_cast<std::uint32_t*>(c.fb.color.data()), value);
    return;
  }
  settle_clears(c);
  std::array<std::uint8_t, 4> set{}, keep{};
  for (std::size_t k = 0; k < 4; ++k) set[k] = mask[k] ? px[k] : 0, keep[k] = mask[k] ? 0 : 0xff;
  std::uint32_t set_word, keep_word;
  std::memcpy(&set_word, set.data(), 4);
  std::memcpy(&keep_word, keep.data(), 4);
  for_pixels(c, [&](std::size_t begin, std::size_t end) {
    masked_fill(reinterpret_cast<std::uint32_t*>(c.fb.color.data()) + begin, end - begin, set_word, keep_word);
  });
  for (std::uint8_t& f : c.tiles.flags) f = TileMap::kChanged | (f & TileMap::kDepthClear);
}

// Tiles that still hold the same clear depth are left as they are. The value is the one
// Mesa's depth buffer holds: truncated to its 24 (or 16) bits, as llvmpipe clears (glReadPixels
// of depth returns it to the bit).
void clear_depth(GlContext& c) {
  const double max = c.depth_bits == 16 ? 65535.0 : 16777215.0;
  const float d = float(std::floor(std::clamp(c.raster.clear_depth, 0.0, 1.0) * max) / max);
  make_pipeline(c);
  list_tiles_to_clear(c, TileMap::kDepthClear, std::bit_cast<std::uint32_t>(d) == std::bit_cast<std::uint32_t>(c.tiles.clear_depth));
  c.tiles.clear_depth = d;
  clear_listed_tiles(c, PipelineContext::PendingClears::kDepth, c.fb.depth.data(), d);
}

void clear_stencil(GlContext& c) {
  std::uint8_t write = std::uint8_t(c.raster.stencil_write_mask & 0xffu);
  std::uint8_t value = std::uint8_t(c.raster.clear_stencil & 0xff);
  for_pixels(c, [&](std::size_t begin, std::size_t end) {
    std::uint8_t* stencil = c.fb.stencil.data();
    if (write == 0xffu) return void(std::memset(stencil + begin, value, end - begin));
    masked_fill(stencil + begin, end - begin, std::uint8_t(value & write), std::uint8_t(~write));
  });
}

// A clear inside the scissor box (GL 1.1 section 4.2.3: the clear honours the pixel
// ownership and scissor tests and the write masks): the box's pixels written at once, after
// the waiting draws and clears, and its tiles marked changed (no longer known cleared); depth
// to `d`.
void clear_box_to(GlContext& c, bool color, bool depth, bool stencil, int x0, int y0, int x1, int y1, float d) {
  make_pipeline(c);
  settle_clears(c);
  if (x0 >= x1 || y0 >= y1) return;
  const std::array<std::uint8_t, 4> px = Framebuffer::color_bytes(c.raster.clear_color);
  const auto& mask = c.raster.color_mask;
  const std::uint8_t write = std::uint8_t(c.raster.stencil_write_mask & 0xffu);
  const std::uint8_t s = std::uint8_t(c.raster.clear_stencil & 0xff);
  const bool whole_pixels = mask[0] && mask[1] && mask[2] && mask[3];
  std::uint32_t word;
  std::memcpy(&word, px.data(), 4);
  auto rows = [&](std::size_t begin, std::size_t end) {
    for (std::size_t y = begin; y < end; ++y) {
      const std::size_t row = y * std::size_t(c.fb.width);
      if (whole_pixels && (!stencil || write == 0xffu)) {  // the row at once (colour as words)
        const std::size_t a = row + std::size_t(x0), n = std::size_t(x1 - x0);
        if (color) std::fill_n(reinterpret_cast<std::uint32_t*>(c.fb.color.data()) + a, n, word);
        if (depth) std::fill_n(c.fb.depth.data() + a, n, d);
        if (stencil) std::memset(c.fb.stencil.data() + a, s, n);
        continue;
      }
      for (std::size_t i = row + std::size_t(x0); i < row + std::size_t(x1); ++i) {
        for (std::size_t k = 0; color && k < 4; ++k) {
          if (mask[k]) c.fb.color[i * 4 + k] = px[k];
        }
        if (depth) c.fb.depth[i] = d;
        if (stencil) c.fb.stencil[i] = std::uint8_t((c.fb.stencil[i] & ~write) | (s & write));
      }
    }
  };
  const std::size_t area = std::size_t(x1 - x0) * std::size_t(y1 - y0);
  if (c.pipeline && area >= (1u << 16)) c.pipeline->parallel_for(std::size_t(y1 - y0), 16, [&](std::size_t b, std::size_t e) { rows(std::size_t(y0) + b, std::size_t(y0) + e); });
  else rows(std::size_t(y0), std::size_t(y1));
  mark_dirty(c, x0, y0, x1, y1);
}

void clear_box(GlContext& c, bool color, bool depth, bool stencil, int x0, int y0, int x1, int y1) {
  clear_box_to(c, color, depth, stencil, x0, y0, x1, y1, std::clamp(float(c.raster.clear_depth), 0.0f, 1.0f));
}

// Every sample of the multisample buffer cleared as the colour buffer and sample 0's depth
// and stencil (the framebuffer's) were: the same buffers, box, values and write masks.
void clear_samples(GlContext& c, bool color, bool depth, bool stencil, bool scissored, int x0, int y0, int x1, int y1) {
  if (!color && !depth && !stencil) return;
  // The depth sample 0 holds: the box's clamped value, or the whole buffer's stored one.
  const float d = scissored ? std::clamp(float(c.raster.clear_depth), 0.0f, 1.0f) : c.tiles.clear_depth;
  if (!scissored) x0 = y0 = 0, x1 = c.fb.width, y1 = c.fb.height;
  make_pipeline(c);
  for (int k = 0; k < c.ms.count; ++k) {
    enter_sample(c, k);
    clear_box_to(c, color, depth && k > 0, stencil && k > 0, x0, y0, x1, y1, d);
    leave_sample(c);
  }
  const auto& m = c.raster.color_mask;
  if (color && !scissored && m[0] && m[1] && m[2] && m[3]) {  // every sample and pixel the clear
    std::fill(c.ms.unresolved.begin(), c.ms.unresolved.end(), std::uint8_t(0));  // colour: resolved
    c.ms.any_unresolved = false;
  }
}

}  // namespace

// The scissor box cut to the framebuffer, [x0, x1) x [y0, y1), when the scissor test leaves
// some pixel of the framebuffer out (else false: a clear writes every pixel).
bool scissor_box(const GlContext& c, int& x0, int& y0, int& x1, int& y1) {
  const RasterState& r = c.raster;
  if (!r.scissor_test) return false;
  const long w = c.fb.width, h = c.fb.height;
  x0 = int(std::clamp<long>(r.scissor_x, 0, w)), y0 = int(std::clamp<long>(r.scissor_y, 0, h));
  x1 = int(std::clamp<long>(long(r.scissor_x) + r.scissor_width, 0, w));
  y1 = int(std::clamp<long>(long(r.scissor_y) + r.scissor_height, 0, h));
  return !(x0 == 0 && y0 == 0 && x1 == w && y1 == h);
}

void exec::ClearColor(GlContext& c, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  c.raster.clear_color = glm::vec4(clamp01(r), clamp01(g), clamp01(b), clamp01(a));
}

void exec::ClearDepth(GlContext& c, GLdouble depth) {
  c.raster.clear_depth = depth == depth ? std::clamp(depth, 0.0, 1.0) : 0.0;
}

void exec::ClearStencil(GlContext& c, GLint s) { c.raster.clear_stencil = s; }

// Clears the framebuffer, or the scissor box's part of it, through the colour, depth and
// stencil write masks (colour not at all with glDrawBuffer(GL_NONE)), and the accumulation
// buffer (its scissor box's part) when the context has one.
void exec::Clear(GlContext& c, GLbitfield mask) {
  const GLbitfield known = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT |
                           GL_ACCUM_BUFFER_BIT;
  if (mask & ~known) return c.set_error(GL_INVALID_VALUE);
  if (c.render_mode != GL_RENDER) return;  // nothing is drawn in selection or feedback mode (as Mesa)
  int x0, y0, x1, y1;
  const bool scissored = scissor_box(c, x0, y0, x1, y1);
  capture_clear(c, mask, scissored);
  if ((mask & GL_COLOR_BUFFER_BIT) && draws_both_buffers(c)) {  // the front buffer's colour first
    exchange_color_buffers(c);
    if (scissored) clear_box(c, true, false, false, x0, y0, x1, y1);
    else clear_color(c);
    exchange_color_buffers(c);
  }
  const bool color = (mask & GL_COLOR_BUFFER_BIT) && draws_color(c);
  const bool depth = (mask & GL_DEPTH_BUFFER_BIT) && c.raster.depth_mask && c.depth_bits > 0;
  const bool stencil = (mask & GL_STENCIL_BUFFER_BIT) && c.stencil_bits > 0;
  if (scissored) {
    clear_box(c, color, depth, stencil, x0, y0, x1, y1);
    if (mask & GL_ACCUM_BUFFER_BIT) clear_accum(c);
    if (c.ms.count > 0) clear_samples(c, color, depth, stencil, true, x0, y0, x1, y1);
    return;
  }
  c.tiles.ahead.clear();
  if (color) clear_color(c);
  if (depth) clear_depth(c);
  if (stencil) clear_stencil(c);
  if (mask & GL_ACCUM_BUFFER_BIT) clear_accum(c);
  if (c.ms.count > 0) clear_samples(c, color, depth, stencil, false, 0, 0, 0, 0);
  // Started last: the clears above would wait for it.
  if (!c.tiles.ahead.empty()) c.pipeline->clear_ahead(c.fb, shadelab::PipelineContext::PendingClears::kColor, c.tiles.ahead);
}

void exec::DepthFunc(GlContext& c, GLenum func) {
  if (!is_compare_func(func)) return c.set_error(GL_INVALID_ENUM);
  c.raster.depth_func = func;
}

void exec::DepthMask(GlContext& c, GLboolean flag) { c.raster.depth_mask = flag != GL_FALSE; }

void exec::ColorMask(GlContext& c, GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
  c.raster.color_mask = {r != 0, g != 0, b != 0, a != 0};
}

void exec::CullFace(GlContext& c, GLenum mode) {
  if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK) return c.set_error(GL_INVALID_ENUM);
  c.raster.cull_mode = mode;
}

void exec::FrontFace(GlContext& c, GLenum mode) {
  if (mode != GL_CW && mode != GL_CCW) return c.set_error(GL_INVALID_ENUM);
  c.raster.front_face = mode;
}

// The reference is clamped to the stencil range [0, 255] (GL 1.1 section 4.1.4).
void exec::StencilFunc(GlContext& c, GLenum func, GLint ref, GLuint mask) {
  if (!is_compare_func(func)) return c.set_error(GL_INVALID_ENUM);
  c.raster.stencil_func = func;
  c.raster.stencil_ref = std::clamp(ref, 0, 255);
  c.raster.stencil_value_mask = mask;
}

void exec::StencilOp(GlContext& c, GLenum fail, GLenum zfail, GLenum zpass) {
  if (!is_stencil_op(fail) || !is_stencil_op(zfail) || !is_stencil_op(zpass)) {
    return c.set_error(GL_INVALID_ENUM);
  }
  c.raster.stencil_fail = fail;
  c.raster.stencil_zfail = zfail;
  c.raster.stencil_zpass = zpass;
}

void exec::StencilMask(GlContext& c, GLuint mask) { c.raster.stencil_write_mask = mask; }

void exec::PolygonOffset(GlContext& c, GLfloat factor, GLfloat units) {
  c.raster.offset_factor = factor;
  c.raster.offset_units = units;
}

// GL 1.1 section 4.1.2: a negative width or height is GL_INVALID_VALUE; the box is kept as
// given (x and y may be negative) and cut to the framebuffer where it is used.
void exec::Scissor(GlContext& c, GLint x, GLint y, GLsizei width, GLsizei height) {
  if (width < 0 || height < 0) return c.set_error(GL_INVALID_VALUE);
  c.raster.scissor_x = x, c.raster.scissor_y = y;
  c.raster.scissor_width = width, c.raster.scissor_height = height;
}

// GL 1.1 section 4.1.3: the reference is clamped to [0, 1].
void exec::AlphaFunc(GlContext& c, GLenum func, GLclampf ref) {
  if (!is_compare_func(func)) return c.set_error(GL_INVALID_ENUM);
  c.raster.alpha_func = func;
  c.raster.alpha_ref = clamp01(ref);
}

// GL 1.1 section 4.1.7: one of the sixteen operations, GL_CLEAR .. GL_SET.
void exec::LogicOp(GlContext& c, GLenum opcode) {
  if (opcode < GL_CLEAR || opcode > GL_SET) return c.set_error(GL_INVALID_ENUM);
  c.raster.logic_op = opcode;
}

}  // namespace shadelab::gl
