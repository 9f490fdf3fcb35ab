// The colour buffers drawn into and read from (GL 1.1 section 4.2.1: glDrawBuffer, glReadBuffer;
// section 4.3.2 for reading) and what a context's visual gives it. A single-buffered context
// (OSMesa's buffer, a single-buffered drawable) has one colour buffer, which every buffer name
// of its visual draws into and reads from. A double-buffered drawable has two: the back one,
// drawn into unless the program names the front one, and the front one, which is what the
// surface's image shows (the last swap's back buffer, and what was drawn into the front since).
// The front buffer becomes a colour buffer of the context only while the program draws into it
// or reads from it; GL_FRONT_AND_BACK draws each drawing twice, from the same depth and stencil.
// GL_NONE draws nothing.
#include <utility>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {
namespace {

bool is_aux(GLenum b) { return b >= GL_AUX0 && b <= GL_AUX3; }

// Names of the left buffers; shadelab's visuals are never stereo and have no auxiliary
// buffers. A single-buffered context takes the back names too, as Mesa's does (its back
// buffer is the front one).
bool is_left(GLenum b) {
  return b == GL_FRONT || b == GL_BACK || b == GL_LEFT || b == GL_FRONT_LEFT || b == GL_BACK_LEFT ||
         b == GL_FRONT_AND_BACK;
}

bool is_right(GLenum b) { return b == GL_RIGHT || b == GL_FRONT_RIGHT || b == GL_BACK_RIGHT; }

// The error for a colour buffer name (GL_NO_ERROR when the visual has it): an enum that is no
// buffer name is GL_INVALID_ENUM, a buffer the visual lacks GL_INVALID_OPERATION (Mesa's codes).
GLenum buffer_error(GLenum b) {
  if (b == GL_NONE || is_left(b)) return GL_NO_ERROR;
  if (is_right(b) || is_aux(b)) return GL_INVALID_OPERATION;
  return GL_INVALID_ENUM;
}

}  // namespace

void configure_buffers(GlContext& c, bool double_buffered, int accum_bits, int samples) {
  c.double_buffered = double_buffered;
  c.ms = {};
  c.ms.count = samples > 0 ? 4 : 0;  // the one count the configurations offer
  // Section 4.2.1: initially the back buffer of a double-buffered visual, else the front.
  c.buffers.draw_buffer = c.buffers.read_buffer = double_buffered ? GL_BACK : GL_FRONT;
  // Mesa allocates a 16-bit signed accumulation buffer for any accumulation bits asked for.
  c.buffers.accum_bits = accum_bits > 0 ? 16 : 0;
}

bool draws_color(const GlContext& c) { return c.buffers.draw_buffer != GL_NONE; }

namespace {

// Whether the front buffer is a buffer of its own: a double-buffered drawable is bound.
bool has_front(const GlContext& c) { return c.double_buffered && c.surface && c.user.data; }

bool names_front(GLenum b) { return b == GL_FRONT || b == GL_FRONT_LEFT || b == GL_LEFT || b == GL_FRONT_AND_BACK; }

// The front buffer when it is not in fb.color: read from the surface's image at first use.
void fetch_front(GlContext& c) {
  if (c.front_in_fb || c.other_color.size() == c.fb.color.size()) return;
  read_user_buffer(c, c.other_color);
}

}  // namespace

bool draws_both_buffers(const GlContext& c) {
  return has_front(c) && (c.buffers.draw_buffer == GL_FRONT_AND_BACK || c.buffers.draw_buffer == GL_LEFT);
}

void exchange_color_buffers(GlContext& c) {
  settle_clears(c);
  if (c.front_in_fb) present(c);  // the image shows the front buffer
  std::swap(c.fb.color, c.other_color);
  c.front_in_fb = !c.front_in_fb;
  // The front buffer is the image as presented; the back one is all to be presented at the
  // swap. Neither is known to hold a clear colour; the depth buffer is as it was.
  const std::uint8_t changed = c.front_in_fb ? 0 : TileMap::kChanged;
  for (std::uint8_t& f : c.tiles.flags) f = std::uint8_t(changed | (f & TileMap::kDepthClear));
}

void select_draw_buffer(GlContext& c) {
  if (!has_front(c)) return;  // one colour buffer, or none bound (selected at the binding)
  const GLenum b = c.buffers.draw_buffer;
  const bool front = b == GL_FRONT || b == GL_FRONT_LEFT;
  if (front != c.front_in_fb) {
    fetch_front(c);
    exchange_color_buffers(c);
  } else if (draws_both_buffers(c)) {
    fetch_front(c);
  }
}

void leave_drawable(GlContext& c) {
  if (c.front_in_fb) {  // presented when the context was unbound: only the back is the context's
    std::swap(c.fb.color, c.other_color);
    c.front_in_fb = false;
  }
  c.other_color = {};
}

void swapped_color_buffers(GlContext& c) {
  if (c.front_in_fb) {  // a front buffer read again when the swap followed a resize: stale now
    std::swap(c.fb.color, c.other_color);
    c.front_in_fb = false;
    for (std::uint8_t& f : c.tiles.flags) f = std::uint8_t(TileMap::kChanged | (f & TileMap::kDepthClear));
  }
  c.other_color = {};
  select_draw_buffer(c);
}

const ColorBuffer& read_color_buffer(GlContext& c) {
  settle_clears(c);
  if (!has_front(c) || names_front(c.buffers.read_buffer) == c.front_in_fb) return c.fb.color;
  fetch_front(c);
  return c.other_color;
}

DepthStencilCopy save_depth_stencil(GlContext& c) {
  settle_clears(c);
  return {c.fb.depth, c.fb.stencil};
}

void restore_depth_stencil(GlContext& c, DepthStencilCopy& saved) {
  settle_clears(c);
  c.fb.depth.swap(saved.depth);
  c.fb.stencil.swap(saved.stencil);
}

void exec::DrawBuffer(GlContext& c, GLenum mode) {
  if (const GLenum e = buffer_error(mode); e != GL_NO_ERROR) return c.set_error(e);
  c.buffers.draw_buffer = mode;
  select_draw_buffer(c);
}

void exec::ReadBuffer(GlContext& c, GLenum mode) {
  if (const GLenum e = buffer_error(mode); e != GL_NO_ERROR) return c.set_error(e);
  c.buffers.read_buffer = mode;
}

}  // namespace shadelab::gl
