// glFog{f,i}[v] (GL 1.1 section 3.9): the fog mode, density, start, end, index and colour, and
// GL 1.4's fog coordinate source (section 3.10).
// State only: the core pipeline fogs fragments (ShadeState::fog, draw_state.cpp's fog_state).
// Mesa's rules: a scalar glFog call with a vector parameter (GL_FOG_COLOR) sets its first
// component (the others zero); glFogiv's colour maps integers to [-1, 1]; the colour is
// clamped to [0, 1] when stored; a negative density is GL_INVALID_VALUE.
#include <algorithm>
#include <cmath>

#include "gl/generated/exec.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {
namespace {

float clamp_unit(float v) { return v == v ? std::clamp(v, 0.0f, 1.0f) : 0.0f; }

// Table 2.6's signed integer conversion, (2i + 1) / (2^32 - 1), as Mesa's INT_TO_FLOAT.
float int_to_float(GLint i) { return float((2.0 * double(i) + 1.0) / 4294967295.0); }

// The four parameters of any glFog call, as floats.
void fog(GlContext& c, GLenum pname, const GLfloat* p) {
  FogSettings& f = c.fog;
  switch (pname) {
    case GL_FOG_MODE: {
      // A float past the integers names no mode (Mesa's (GLint) cast gives INT_MIN there).
      const GLenum mode = std::isfinite(p[0]) && std::fabs(p[0]) < 2e9f ? GLenum(GLint(p[0])) : 0;
      if (mode != GL_LINEAR && mode != GL_EXP && mode != GL_EXP2) return c.set_error(GL_INVALID_ENUM);
      f.mode = mode;
      return;
    }
    case GL_FOG_DENSITY:
      if (p[0] < 0.0f) return c.set_error(GL_INVALID_VALUE);
      f.density = p[0];
      return;
    case GL_FOG_START: f.start = p[0]; return;
    case GL_FOG_END: f.end = p[0]; return;
    case GL_FOG_INDEX: f.index = p[0]; return;
    case GL_FOG_COLOR:
      f.color = {clamp_unit(p[0]), clamp_unit(p[1]), clamp_unit(p[2]), clamp_unit(p[3])};
      return;
    case GL_FOG_COORDINATE_SOURCE: {  // GL 1.4 section 3.10
      const GLenum source = std::isfinite(p[0]) && std::fabs(p[0]) < 2e9f ? GLenum(GLint(p[0])) : 0;
      if (source != GL_FOG_COORDINATE && source != GL_FRAGMENT_DEPTH) return c.set_error(GL_INVALID_ENUM);
      f.coord_source = source;
      return;
    }
    default: c.set_error(GL_INVALID_ENUM);
  }
}

}  // namespace

// How many values glFogfv / glFogiv read for `pname` (display lists copy them).
std::size_t save_count::Fogfv(GLenum pname) { return pname == GL_FOG_COLOR ? 4 : 1; }
std::size_t save_count::Fogiv(GLenum pname) { return pname == GL_FOG_COLOR ? 4 : 1; }

void exec::Fogf(GlContext& c, GLenum pname, GLfloat param) {
  const GLfloat p[4] = {param, 0.0f, 0.0f, 0.0f};
  fog(c, pname, p);
}

void exec::Fogi(GlContext& c, GLenum pname, GLint param) {
  const GLfloat p[4] = {GLfloat(param), 0.0f, 0.0f, 0.0f};
  fog(c, pname, p);
}

void exec::Fogfv(GlContext& c, GLenum pname, const GLfloat* params) {
  if (!params) return;  // nothing to read (Mesa would fault)
  const int n = pname == GL_FOG_COLOR ? 4 : 1;
  GLfloat p[4] = {};
  std::copy(params, params + n, p);
  fog(c, pname, p);
}

void exec::Fogiv(GlContext& c, GLenum pname, const GLint* params) {
  if (!params) return;
  GLfloat p[4] = {};
  if (pname == GL_FOG_COLOR) {
    for (int i = 0; i < 4; ++i) p[i] = int_to_float(params[i]);
  } else {
    p[0] = GLfloat(params[0]);
  }
  fog(c, pname, p);
}

}  // namespace shadelab::gl
