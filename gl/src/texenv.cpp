// The texture environment's GL_COMBINE parameters (GL 1.3 section 3.8.13, tables 3.24-3.26;
// ARB_texture_env_combine, ARB_texture_env_dot3, ARB_texture_env_crossbar): glTexEnv's and
// glGetTexEnv's GL_COMBINE_RGB / _ALPHA, GL_SOURCEn_RGB / _ALPHA, GL_OPERANDn_RGB / _ALPHA,
// GL_RGB_SCALE and GL_ALPHA_SCALE of the active unit, checked as Mesa checks them, and their
// form in the core (TextureCombine), which computes the environment on both pipelines.
#include "gl/src/context.hpp"
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

}  // namespace

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

}  // namespace shadelab::gl
