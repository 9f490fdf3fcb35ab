// The texture environment (GL 1.1 section 3.8.9; GL 1.5 sections 3.8.8, 3.8.13): glTexEnv* and
// glGetTexEnv* of the active unit: the mode, the colour, GL 1.4's GL_TEXTURE_FILTER_CONTROL
// bias and GL 1.3's GL_COMBINE parameters (tables 3.24-3.26; ARB_texture_env_combine,
// ARB_texture_env_dot3, ARB_texture_env_crossbar: GL_COMBINE_RGB / _ALPHA, GL_SOURCEn_RGB /
// _ALPHA, GL_OPERANDn_RGB / _ALPHA, GL_RGB_SCALE, GL_ALPHA_SCALE), checked as Mesa checks them,
// and the combine's form in the core (TextureCombine), which computes the environment on both
// pipelines (texture.hpp's apply_texture_env, apply_texture_combine).
#include <algorithm>

#include "gl/generated/exec.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/context.hpp"
#include "gl/src/convert.hpp"
#include "gl/src/texture.hpp"

namespace shadelab::gl {
namespace {

// The term (0 to 2) of a GL_SOURCEn_* / GL_OPERANDn_* pname from `first`, or -1.
int term(GLenum pname, GLenum first) { return pname >= first && pname < first + 3 ? int(pname - first) : -1; }

bool combine_function(GLenum f, bool rgb) {
  switch (f) {
    case GL_REPLACE: case GL_MODULATE: case GL_ADD: case GL_ADD_SIGNED: case GL_INTERPOLATE: case GL_SUBTRACT:
      return true;
    case GL_DOT3_RGB: case GL_DOT3_RGBA: return rgb;  // GL_COMBINE_RGB only
    default: return false;
  }
}

// GL_TEXTUREi of the crossbar (GL 1.4) names one of shadelab's units.
bool combine_source(GLenum s) {
  return s == GL_TEXTURE || s == GL_CONSTANT || s == GL_PRIMARY_COLOR || s == GL_PREVIOUS ||
         (s >= GL_TEXTURE0 && s < GL_TEXTURE0 + GLenum(kMaxTextureUnits));
}

bool combine_operand(GLenum o, bool rgb) {
  if (o == GL_SRC_ALPHA || o == GL_ONE_MINUS_SRC_ALPHA) return true;
  return rgb && (o == GL_SRC_COLOR || o == GL_ONE_MINUS_SRC_COLOR);
}

CombineFunction core_function(GLenum f) {
  switch (f) {
    case GL_REPLACE: return CombineFunction::kReplace;
    case GL_ADD: return CombineFunction::kAdd;
    case GL_ADD_SIGNED: return CombineFunction::kAddSigned;
    case GL_INTERPOLATE: return CombineFunction::kInterpolate;
    case GL_SUBTRACT: return CombineFunction::kSubtract;
    case GL_DOT3_RGB: return CombineFunction::kDot3Rgb;
    case GL_DOT3_RGBA: return CombineFunction::kDot3Rgba;
    default: return CombineFunction::kModulate;
  }
}

CombineSource core_source(GLenum s) {
  switch (s) {
    case GL_TEXTURE: return CombineSource::kTexture;
    case GL_CONSTANT: return CombineSource::kConstant;
    case GL_PRIMARY_COLOR: return CombineSource::kPrimaryColor;
    case GL_PREVIOUS: return CombineSource::kPrevious;
    default: return CombineSource(int(CombineSource::kTexture0) + int(s - GL_TEXTURE0));
  }
}

CombineOperand core_operand(GLenum o) {
  switch (o) {
    case GL_ONE_MINUS_SRC_COLOR: return CombineOperand::kOneMinusSrcColor;
    case GL_SRC_ALPHA: return CombineOperand::kSrcAlpha;
    case GL_ONE_MINUS_SRC_ALPHA: return CombineOperand::kOneMinusSrcAlpha;
    default: return CombineOperand::kSrcColor;
  }
}

// An enum given as a float (glTexEnvf), truncated as glTexEnv's mode is.
GLenum as_enum(float v) { return v == v && v >= 0.0f && v < 4294967296.0f ? GLenum(v) : GLenum(0); }

// glTexEnv's GL_COMBINE parameters: false when `pname` is not one of them; else true, with
// the active unit's state set from `v` or the error of a wrong value raised.
bool tex_env_combine(GlContext& c, GLenum pname, float v) {
  TexEnvCombine& s = c.textures.unit().combine;
  const GLenum e = as_enum(v);
  int i;
  if (pname == GL_COMBINE_RGB || pname == GL_COMBINE_ALPHA) {
    const bool rgb = pname == GL_COMBINE_RGB;
    if (!combine_function(e, rgb)) return c.set_error(GL_INVALID_ENUM), true;
    (rgb ? s.rgb : s.alpha) = e;
  } else if ((i = term(pname, GL_SOURCE0_RGB)) >= 0 || (i = term(pname, GL_SOURCE0_ALPHA)) >= 0) {
    if (!combine_source(e)) return c.set_error(GL_INVALID_ENUM), true;
    (pname < GL_SOURCE0_ALPHA ? s.source_rgb : s.source_alpha)[std::size_t(i)] = e;
  } else if ((i = term(pname, GL_OPERAND0_RGB)) >= 0 || (i = term(pname, GL_OPERAND0_ALPHA)) >= 0) {
    const bool rgb = pname < GL_OPERAND0_ALPHA;
    if (!combine_operand(e, rgb)) return c.set_error(GL_INVALID_ENUM), true;
    (rgb ? s.operand_rgb : s.operand_alpha)[std::size_t(i)] = e;
  } else if (pname == GL_RGB_SCALE || pname == GL_ALPHA_SCALE) {
    if (v != 1.0f && v != 2.0f && v != 4.0f) return c.set_error(GL_INVALID_VALUE), true;
    (pname == GL_RGB_SCALE ? s.rgb_scale : s.alpha_scale) = v;
  } else {
    return false;
  }
  return true;
}

// glGetTexEnv's GL_COMBINE parameters: false when `pname` is not one of them.
bool get_tex_env_combine(const TextureUnitState& u, GLenum pname, float& out) {
  const TexEnvCombine& s = u.combine;
  int i;
  if (pname == GL_COMBINE_RGB) out = float(s.rgb);
  else if (pname == GL_COMBINE_ALPHA) out = float(s.alpha);
  else if ((i = term(pname, GL_SOURCE0_RGB)) >= 0) out = float(s.source_rgb[std::size_t(i)]);
  else if ((i = term(pname, GL_SOURCE0_ALPHA)) >= 0) out = float(s.source_alpha[std::size_t(i)]);
  else if ((i = term(pname, GL_OPERAND0_RGB)) >= 0) out = float(s.operand_rgb[std::size_t(i)]);
  else if ((i = term(pname, GL_OPERAND0_ALPHA)) >= 0) out = float(s.operand_alpha[std::size_t(i)]);
  else if (pname == GL_RGB_SCALE) out = s.rgb_scale;
  else if (pname == GL_ALPHA_SCALE) out = s.alpha_scale;
  else return false;
  return true;
}

// glTexEnv (GL 1.1 section 3.8.9). A scalar GL_TEXTURE_ENV_COLOR sets (v, 0, 0, 0), as Mesa's.
// GL 1.4's GL_TEXTURE_FILTER_CONTROL target holds the unit's GL_TEXTURE_LOD_BIAS, kept as
// given (section 3.8.8 clamps the sum when sampling).
void tex_env(GlContext& c, GLenum target, GLenum pname, const float* v) {
  if (target == kPointSprite) {  // ARB_point_sprite: the active unit's coordinate replacement
    if (pname != kCoordReplace) return c.set_error(GL_INVALID_ENUM);
    if (!v) return c.set_error(GL_INVALID_VALUE);
    const GLint on = enum_param(v[0], false);
    if (on != GL_TRUE && on != GL_FALSE) return c.set_error(GL_INVALID_VALUE);
    const auto bit = std::uint8_t(1u << c.textures.active);
    c.prims.coord_replace = std::uint8_t(on ? c.prims.coord_replace | bit : c.prims.coord_replace & ~bit);
    return;
  }
  if (target == GL_TEXTURE_FILTER_CONTROL) {
    if (pname != GL_TEXTURE_LOD_BIAS) return c.set_error(GL_INVALID_ENUM);
    if (!v) return c.set_error(GL_INVALID_VALUE);
    c.textures.unit().lod_bias = finite_or_zero(v[0]);
    return;
  }
  if (target != GL_TEXTURE_ENV) return c.set_error(GL_INVALID_ENUM);
  if (!v) return c.set_error(GL_INVALID_VALUE);
  if (pname == GL_TEXTURE_ENV_MODE) {
    const GLint m = enum_param(v[0], false);
    if (m != GL_MODULATE && m != GL_DECAL && m != GL_BLEND && m != GL_REPLACE && m != GL_ADD && m != GL_COMBINE) {
      return c.set_error(GL_INVALID_ENUM);  // (GL_ADD, GL_COMBINE: GL 1.3)
    }
    c.textures.unit().env_mode = GLenum(m);
  } else if (pname == GL_TEXTURE_ENV_COLOR) {
    for (int i = 0; i < 4; ++i) c.textures.unit().env_color[i] = std::clamp(finite_or_zero(v[i]), 0.0f, 1.0f);
  } else if (!tex_env_combine(c, pname, v[0])) {
    c.set_error(GL_INVALID_ENUM);
  }
}

// glGetTexEnv. The bias is rounded by glGetTexEnviv, as the specification converts floats
// (section 6.1.2); Mesa 22 truncates it.
template <class T>
void get_tex_env(GlContext& c, GLenum target, GLenum pname, T* params) {
  float v[4] = {float(c.textures.unit().env_mode), 0, 0, 0};
  int n = 1;
  if (target == GL_TEXTURE_FILTER_CONTROL) {
    if (pname != GL_TEXTURE_LOD_BIAS) return c.set_error(GL_INVALID_ENUM);
    v[0] = c.textures.unit().lod_bias;
  } else if (target == kPointSprite) {
    if (pname != kCoordReplace) return c.set_error(GL_INVALID_ENUM);
    v[0] = (c.prims.coord_replace >> c.textures.active & 1u) ? 1.0f : 0.0f;
  } else if (target != GL_TEXTURE_ENV) {
    return c.set_error(GL_INVALID_ENUM);
  } else if (pname == GL_TEXTURE_ENV_COLOR) {
    for (int i = 0; i < 4; ++i) v[i] = c.textures.unit().env_color[i];
    n = 4;
  } else if (pname != GL_TEXTURE_ENV_MODE && !get_tex_env_combine(c.textures.unit(), pname, v[0])) {
    return c.set_error(GL_INVALID_ENUM);
  }
  if (!params) return c.set_error(GL_INVALID_VALUE);
  write_gl_values(v, n, pname == GL_TEXTURE_ENV_COLOR, params);
}

}  // namespace


TextureCombine core_combine(const TexEnvCombine& s) {
  TextureCombine c;
  c.rgb = core_function(s.rgb);
  c.alpha = core_function(s.alpha);
  for (std::size_t i = 0; i < 3; ++i) {
    c.rgb_source[i] = core_source(s.source_rgb[i]);
    c.alpha_source[i] = core_source(s.source_alpha[i]);
    c.rgb_operand[i] = core_operand(s.operand_rgb[i]);
    c.alpha_operand[i] = core_operand(s.operand_alpha[i]);
  }
  c.rgb_scale = s.rgb_scale;
  c.alpha_scale = s.alpha_scale;
  return c;
}

void exec::TexEnvf(GlContext& c, GLenum target, GLenum pname, GLfloat param) {
  const float v[4] = {param, 0, 0, 0};
  tex_env(c, target, pname, v);
}
void exec::TexEnvi(GlContext& c, GLenum target, GLenum pname, GLint param) {
  const float v[4] = {float(param), 0, 0, 0};
  tex_env(c, target, pname, v);
}
void exec::TexEnvfv(GlContext& c, GLenum target, GLenum pname, const GLfloat* params) { tex_env(c, target, pname, params); }
void exec::TexEnviv(GlContext& c, GLenum target, GLenum pname, const GLint* params) {
  float v[4] = {0, 0, 0, 0};
  int n = pname == GL_TEXTURE_ENV_COLOR ? 4 : 1;
  if (params) to_floats(params, n, pname == GL_TEXTURE_ENV_COLOR, v);
  tex_env(c, target, pname, params ? v : nullptr);
}
std::size_t save_count::TexEnvfv(GLenum pname) { return pname == GL_TEXTURE_ENV_COLOR ? 4 : 1; }
std::size_t save_count::TexEnviv(GLenum pname) { return pname == GL_TEXTURE_ENV_COLOR ? 4 : 1; }

void exec::GetTexEnvfv(GlContext& c, GLenum target, GLenum pname, GLfloat* params) { get_tex_env(c, target, pname, params); }
void exec::GetTexEnviv(GlContext& c, GLenum target, GLenum pname, GLint* params) { get_tex_env(c, target, pname, params); }

}  // namespace shadelab::gl
