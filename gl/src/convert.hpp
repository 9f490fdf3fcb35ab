// Number conversions that OpenGL defines between its argument types: integer colours to
// floats (GL 1.1 table 2.6), floats back to integers for glGet (section 6.1.2), and the
// clamping shadelab applies so that no value can make the pipeline misbehave. No state.
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace shadelab::gl {

/// A signed integer colour component mapped linearly to [-1, 1]: (2c + 1) / (2^32 - 1).
inline float int_to_color(GLint i) { return float((2.0 * double(i) + 1.0) / 4294967295.0); }

/// The inverse mapping for glGet of colours, normals and depth values: [-1, 1] to the full
/// integer range (values outside are clamped), truncated as Mesa does.
inline GLint color_to_int(double f) {
  if (!(f == f)) return 0;
  return GLint(std::clamp(f, -1.0, 1.0) * 2147483647.0);
}

/// Other floating-point state as an integer: rounded to the nearest, halves away from zero
/// (as Mesa's glGetIntegerv: a zoom of -2.5 reads -3), clamped to GLint.
inline GLint round_to_int(double f) {
  if (!(f == f)) return 0;
  double r = std::round(f);
  r = std::clamp(r, double(std::numeric_limits<GLint>::min()),
                 double(std::numeric_limits<GLint>::max()));
  return GLint(r);
}

/// glGetIntegerv's conversion of floating-point state, as Mesa's: (int) lroundf(f), rounded
/// half away from zero, wrapped to 32 bits past the GLint range (1e10 gives 1410065408), 0
/// past the long range or for NaN.
inline GLint lround_to_int(double f) {
  if (!(std::fabs(f) < 9.2e18)) return 0;
  return GLint(std::uint32_t(std::uint64_t(std::llround(f))));
}

/// glGet*v's output: `n` float values as the caller's type (colours mapped as colours when
/// `color`, other values rounded, for integer types).
template <class T>
void write_gl_values(const float* v, int n, bool color, T* out) {
  for (int i = 0; i < n; ++i) {
    if constexpr (std::is_integral_v<T>) {
      out[i] = color ? color_to_int(v[i]) : round_to_int(v[i]);
    } else {
      out[i] = v[i];
    }
  }
}

/// NaN becomes 0; everything else is kept (colours are clamped later).
inline float finite_or_zero(float v) { return std::isnan(v) ? 0.0f : v; }

/// Unsigned byte colour component to [0, 1].
inline float ubyte_to_float(GLubyte v) { return float(v) / 255.0f; }

/// Integer components of glColor and glNormal to floats (GL 1.1 table 2.6), evaluated in the
/// precision Mesa evaluates them, so that glGet returns the same floats: signed types map
/// (2c + 1) / (2^b - 1), unsigned ones c / (2^b - 1). Mesa's signed 32-bit form divides by
/// 2^32 - 2, not 2^32 - 1; the difference is below a float's precision for every GLint but
/// changes how the division rounds, so it is kept.
inline float color_component(GLbyte v) { return (2.0f * float(v) + 1.0f) * (1.0f / 255.0f); }
inline float color_component(GLshort v) { return (2.0f * float(v) + 1.0f) * (1.0f / 65535.0f); }
inline float color_component(GLint v) { return float(double(2.0f * float(v) + 1.0f) * (1.0 / 4294967294.0)); }
inline float color_component(GLubyte v) { return ubyte_to_float(v); }
inline float color_component(GLushort v) { return float(v) * (1.0f / 65535.0f); }
inline float color_component(GLuint v) { return float(double(v) * (1.0 / 4294967295.0)); }
inline float color_component(GLfloat v) { return v; }
inline float color_component(GLdouble v) { return float(v); }

// GL parameters given as integers or floats, as floats: integers as colours (int_to_color)
// where `color`, else as they are.
template <class T>
inline void to_floats(const T* in, int n, bool color, float* out) {
  for (int i = 0; i < n; ++i) {
    if constexpr (std::is_integral_v<T>) {
      out[i] = color ? int_to_color(in[i]) : float(in[i]);
    } else {
      out[i] = float(in[i]);
    }
  }
}

}  // namespace shadelab::gl
