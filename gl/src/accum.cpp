// The accumulation buffer (GL 1.1 section 4.2.4): glAccum, glClearAccum and its part of
// glClear. Like Mesa's (the software accumulation of Mesa 22's state tracker, measured on
// llvmpipe), it holds 16-bit signed values, v / 32767 per channel: colours are accumulated
// truncated to it, and values that leave its range wrap as Mesa's do (the specification
// leaves them undefined). GL_RETURN writes back clamped and rounded, through the colour mask.
// Every operation covers the whole buffer, or the scissor box's part of it when the scissor
// test is on (as Mesa's, which works on the draw buffer's scissored bounds).
#include <algorithm>
#include <cstdint>
#include <cstring>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"
#include "gl/src/convert.hpp"

namespace shadelab::gl {
namespace {

// C's (GLshort) of a float on x86, as Mesa's arithmetic gets it: truncated to a 32-bit integer
// (the "integer indefinite" 0x80000000 when it does not fit), then to its low 16 bits.
std::int16_t to_short(float f) {
  const std::int32_t i = (f >= -2147483648.0f && f < 2147483648.0f) ? std::int32_t(f) : INT32_MIN;
  return std::int16_t(std::uint16_t(std::uint32_t(i) & 0xffffu));
}

std::int16_t wrap(std::int32_t i) { return std::int16_t(std::uint16_t(std::uint32_t(i) & 0xffffu)); }

// Mesa's 8-bit rounding of a clamped float (see readpix.cpp).
std::uint8_t to_ubyte(float f) {
  if (!(f > 0.0f)) return 0;
  if (f >= 1.0f) return 255;
  const float t = f * (255.0f / 256.0f) + 32768.0f;
  std::uint32_t bits;
  std::memcpy(&bits, &t, 4);
  return std::uint8_t(bits);
}

struct Region {
  int x0, y0, x1, y1;
};

Region region(const GlContext& c) {
  Region r{0, 0, c.fb.width, c.fb.height};
  if (scissor_box(c, r.x0, r.y0, r.x1, r.y1)) return r;
  return {0, 0, c.fb.width, c.fb.height};
}

std::vector<std::int16_t>& accum_buffer(GlContext& c) {
  std::vector<std::int16_t>& a = c.buffers.accum;
  const std::size_t n = std::size_t(c.fb.width) * std::size_t(c.fb.height) * 4;
  if (a.size() != n) a.assign(n, 0);  // a new size: the contents are undefined
  return a;
}

// Runs fn(accum values, colour bytes) over the four channels of every pixel of the region.
template <class Color, class Fn>
void for_region(GlContext& c, Color& color, const Fn& fn) {
  std::vector<std::int16_t>& a = accum_buffer(c);
  const Region r = region(c);
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      const std::size_t i = (std::size_t(y) * std::size_t(c.fb.width) + std::size_t(x)) * 4;
      fn(&a[i], &color[i]);
    }
  }
}

// GL_LOAD and GL_ACCUM: the read buffer's colours times `value` (none to read: nothing).
void load_or_accumulate(GlContext& c, float value, bool load) {
  if (c.buffers.read_buffer == GL_NONE) return;
  const float scale = value * 32767.0f;
  for_region(c, read_color_buffer(c), [&](std::int16_t* acc, const std::uint8_t* rgba) {
    for (int k = 0; k < 4; ++k) {
      const std::int16_t v = to_short(float(rgba[k]) * (1.0f / 255.0f) * scale);
      acc[k] = load ? v : wrap(std::int32_t(acc[k]) + v);
    }
  });
}

// GL_RETURN: the accumulated values times `value` into the colour buffer, clamped, through the
// colour mask.
void accum_return(GlContext& c, float value) {
  if (!draws_color(c)) return;
  const float scale = value / 32767.0f;
  const auto& mask = c.raster.color_mask;
  for_each_draw_buffer(c, [&](bool) {
    for_region(c, c.fb.color, [&](std::int16_t* acc, std::uint8_t* rgba) {
      for (int k = 0; k < 4; ++k) {
        if (mask[std::size_t(k)]) rgba[k] = to_ubyte(float(acc[k]) * scale);
      }
    });
    const Region r = region(c);
    mark_dirty(c, r.x0, r.y0, r.x1, r.y1);
  });
}

}  // namespace

void clear_accum(GlContext& c) {
  if (c.buffers.accum_bits == 0) return;
  std::int16_t v[4];
  // Mesa's FLOAT_TO_SHORT: ((int)(65535 c) - 1) / 2.
  for (int k = 0; k < 4; ++k) v[k] = std::int16_t((int(65535.0f * c.buffers.accum_clear[k]) - 1) / 2);
  for_region(c, c.fb.color, [&](std::int16_t* acc, const std::uint8_t*) { std::copy(v, v + 4, acc); });
}

void exec::ClearAccum(GlContext& c, GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha) {
  const float v[4] = {red, green, blue, alpha};
  for (int k = 0; k < 4; ++k) c.buffers.accum_clear[k] = std::clamp(finite_or_zero(v[k]), -1.0f, 1.0f);
}

void exec::Accum(GlContext& c, GLenum op, GLfloat value) {
  if (op != GL_ACCUM && op != GL_LOAD && op != GL_RETURN && op != GL_MULT && op != GL_ADD) {
    return c.set_error(GL_INVALID_ENUM);
  }
  if (c.buffers.accum_bits == 0) return c.set_error(GL_INVALID_OPERATION);
  if (c.render_mode != GL_RENDER) return;  // nothing is drawn in selection or feedback mode (as Mesa)
  settle_clears(c);  // the colour buffer as drawn so far
  value = finite_or_zero(value);
  switch (op) {
    case GL_ACCUM:
      if (value != 0.0f) load_or_accumulate(c, value, false);
      return;
    case GL_LOAD: return load_or_accumulate(c, value, true);
    case GL_RETURN: return accum_return(c, value);
    case GL_ADD: {
      if (value == 0.0f) return;
      const std::int16_t incr = to_short(value * 32767.0f);
      return for_region(c, c.fb.color, [&](std::int16_t* acc, const std::uint8_t*) {
        for (int k = 0; k < 4; ++k) acc[k] = wrap(std::int32_t(acc[k]) + incr);
      });
    }
    default:  // GL_MULT
      if (value == 1.0f) return;
      return for_region(c, c.fb.color, [&](std::int16_t* acc, const std::uint8_t*) {
        for (int k = 0; k < 4; ++k) acc[k] = to_short(float(acc[k]) * value);
      });
  }
}

}  // namespace shadelab::gl
