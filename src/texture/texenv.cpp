// The texture environments: a fragment's colour combined with a texel by GL_MODULATE,
// GL_DECAL, GL_BLEND, GL_REPLACE and GL_ADD (GL 1.1 table 3.22, GL 1.3's GL_ADD) and the
// GL_COMBINE environment's sources, operands and functions (GL 1.5 section 3.8.13, tables
// 3.20-3.21), in Mesa's arithmetic (its fixed-function program's saturate; DOT3 on
// (2a - 1) and (2b - 1)). The definition; fast/texenv-inl.h is its SIMD form, proven equal by
// the texture differential tests.
#include "shadelab/texture.hpp"

#include <algorithm>
#include <cmath>

namespace shadelab {

namespace {

// [0, 1], NaN to 0 (Mesa's fixed-function program's saturate).
float saturate(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

}  // namespace

glm::vec4 apply_texture_env(TextureEnvMode mode, TextureFormat format, const glm::vec4& f,
                            const glm::vec4& t, const glm::vec4& env) {
  glm::vec3 cf(f), ct(t), cc(env);
  bool has_color = format != TextureFormat::kAlpha;
  bool has_alpha = format == TextureFormat::kAlpha || format == TextureFormat::kLuminanceAlpha ||
                   format == TextureFormat::kIntensity || format == TextureFormat::kRgba;
  float at = t.a;
  switch (mode) {
    case TextureEnvMode::kReplace:
      return glm::vec4(has_color ? ct : cf, has_alpha ? at : f.a);
    case TextureEnvMode::kModulate:
      return glm::vec4(has_color ? cf * ct : cf, has_alpha ? f.a * at : f.a);
    case TextureEnvMode::kDecal:  // defined for RGB and RGBA only; others keep the fragment
      if (format == TextureFormat::kRgb) return glm::vec4(ct, f.a);
      if (format == TextureFormat::kRgba) return glm::vec4(cf * (1.0f - at) + ct * at, f.a);
      return f;
    case TextureEnvMode::kBlend: {
      glm::vec3 c = has_color ? cf * (1.0f - ct) + cc * ct : cf;
      float a = format == TextureFormat::kIntensity ? f.a * (1.0f - at) + env.a * at
                                                    : (has_alpha ? f.a * at : f.a);
      return glm::vec4(c, a);
    }
    case TextureEnvMode::kAdd: {  // GL 1.3 table 3.23; sums saturated, as Mesa's program does
      const glm::vec3 sum(saturate(cf.r + ct.r), saturate(cf.g + ct.g), saturate(cf.b + ct.b));
      const glm::vec3 c = has_color ? sum : cf;
      const float a = format == TextureFormat::kIntensity ? saturate(f.a + at) : (has_alpha ? f.a * at : f.a);
      return glm::vec4(c, a);
    }
    case TextureEnvMode::kCombine: return f;  // apply_texture_combine's
  }
  return f;
}

namespace {

glm::vec4 combine_source(CombineSource s, const CombineInputs& in) {
  switch (s) {
    case CombineSource::kTexture: return in.texels[in.unit];
    case CombineSource::kConstant: return in.constant;
    case CombineSource::kPrimaryColor: return in.primary;
    case CombineSource::kPrevious: return in.previous;
    default: return in.texels[int(s) - int(CombineSource::kTexture0)];
  }
}

// An operand's three colour components (or its alpha three times).
glm::vec3 rgb_operand(CombineOperand o, const glm::vec4& v) {
  switch (o) {
    case CombineOperand::kSrcColor: return glm::vec3(v);
    case CombineOperand::kOneMinusSrcColor: return glm::vec3(1.0f) - glm::vec3(v);
    case CombineOperand::kSrcAlpha: return glm::vec3(v.a);
    case CombineOperand::kOneMinusSrcAlpha: return glm::vec3(1.0f - v.a);
  }
  return glm::vec3(v);
}

float alpha_operand(CombineOperand o, const glm::vec4& v) {
  return o == CombineOperand::kOneMinusSrcAlpha || o == CombineOperand::kOneMinusSrcColor ? 1.0f - v.a : v.a;
}

template <class T>
T combine_function(CombineFunction f, const T& a0, const T& a1, const T& a2) {
  switch (f) {
    case CombineFunction::kReplace: return a0;
    case CombineFunction::kModulate: return a0 * a1;
    case CombineFunction::kAdd: return a0 + a1;
    case CombineFunction::kAddSigned: return a0 + a1 - T(0.5f);
    case CombineFunction::kInterpolate: return a0 * a2 + a1 * (T(1.0f) - a2);
    case CombineFunction::kSubtract: return a0 - a1;
    default: return a0;  // the dot products: apply_texture_combine's
  }
}

bool needs_clamp(CombineFunction f) {
  return f != CombineFunction::kReplace && f != CombineFunction::kModulate && f != CombineFunction::kInterpolate;
}

// The scale, then the clamp Mesa applies (after scaling, or after the functions that need it).
float finish(float v, float scale, bool clamp) {
  if (scale != 1.0f) return saturate(v * scale);
  return clamp ? saturate(v) : v;
}

}  // namespace

glm::vec4 apply_texture_combine(const TextureCombine& c, const CombineInputs& in) {
  glm::vec3 a[3];
  float b[3];
  for (int i = 0; i < 3; ++i) {
    a[i] = rgb_operand(c.rgb_operand[i], combine_source(c.rgb_source[i], in));
    b[i] = alpha_operand(c.alpha_operand[i], combine_source(c.alpha_source[i], in));
  }
  glm::vec3 rgb;
  const bool dot = c.rgb == CombineFunction::kDot3Rgb || c.rgb == CombineFunction::kDot3Rgba;
  float product = 0.0f;
  if (dot) {  // (2 a0 - 1) . (2 a1 - 1), Mesa's form of 4 ((r0 - 0.5)(r1 - 0.5) + ...)
    const glm::vec3 p = (a[0] * 2.0f - glm::vec3(1.0f)) * (a[1] * 2.0f - glm::vec3(1.0f));
    product = (p.x + p.y) + p.z;
    rgb = glm::vec3(product);
  } else {
    rgb = combine_function(c.rgb, a[0], a[1], a[2]);
  }
  const bool clamp_rgb = needs_clamp(c.rgb);
  glm::vec4 out(finish(rgb.r, c.rgb_scale, clamp_rgb), finish(rgb.g, c.rgb_scale, clamp_rgb),
                finish(rgb.b, c.rgb_scale, clamp_rgb), 0.0f);
  if (c.rgb == CombineFunction::kDot3Rgba) {
    out.a = finish(product, c.alpha_scale, true);  // alpha scaled by GL_ALPHA_SCALE (Mesa's)
  } else {
    out.a = finish(combine_function(c.alpha, b[0], b[1], b[2]), c.alpha_scale, needs_clamp(c.alpha));
  }
  return out;
}

}  // namespace shadelab
