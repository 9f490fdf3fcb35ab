// The colour buffers drawn into and read from (GL 1.1 section 4.2.1: glDrawBuffer, glReadBuffer;
// section 4.3.2 for reading) and what a context's visual gives it. A context has one colour
// buffer (OSMesa's, or a drawable's back buffer); every buffer name of its visual draws into
// and reads from it, GL_NONE draws nothing. State only.
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

void configure_buffers(GlContext& c, bool double_buffered, int accum_bits) {
  c.double_buffered = double_buffered;
  // Section 4.2.1: initially the back buffer of a double-buffered visual, else the front.
  c.buffers.draw_buffer = c.buffers.read_buffer = double_buffered ? GL_BACK : GL_FRONT;
  // Mesa allocates a 16-bit signed accumulation buffer for any accumulation bits asked for.
  c.buffers.accum_bits = accum_bits > 0 ? 16 : 0;
}

bool draws_color(const GlContext& c) { return c.buffers.draw_buffer != GL_NONE; }

void exec::DrawBuffer(GlContext& c, GLenum mode) {
  if (const GLenum e = buffer_error(mode); e != GL_NO_ERROR) return c.set_error(e);
  c.buffers.draw_buffer = mode;
}

void exec::ReadBuffer(GlContext& c, GLenum mode) {
  if (const GLenum e = buffer_error(mode); e != GL_NO_ERROR) return c.set_error(e);
  c.buffers.read_buffer = mode;
}

}  // namespace shadelab::gl
