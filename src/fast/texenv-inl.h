// Texture environments on the SIMD path: a fragment's colour combined with its units' texels
// by GL_MODULATE, GL_DECAL, GL_BLEND, GL_REPLACE, GL_ADD (apply_texture_env) and GL_COMBINE
// (apply_texture_combine), each the reference's operation by operation in float, so that every
// target gives the reference's colours bit for bit. It combines colours only: the texels come
// from texture-inl.h. Per-target code (Highway).
#if defined(SHADELAB_FAST_TEXENV_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SHADELAB_FAST_TEXENV_INL_H_
#undef SHADELAB_FAST_TEXENV_INL_H_
#else
#define SHADELAB_FAST_TEXENV_INL_H_
#endif

#include "fast/block-inl.h"
#include "fast/triangle.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

/// texture.cpp's saturate: [0, 1], NaN to 0.
HWY_INLINE VB saturate(VB v) {
  const DB db;
  const VB zero = hn::Zero(db), one = hn::Set(db, 1.0f);
  return hn::IfThenElse(hn::Gt(v, zero), hn::IfThenElse(hn::Lt(v, one), v, one), zero);
}

/// apply_texture_env: the fragment's colour `f` combined with the texel `t` by the
/// environment mode, as the texture's base format says (GL 1.1 table 3.22).
HWY_INLINE void texture_env(const TexturePlan& tp, VB f[4], const VB t[4]) {
  const DB db;
  const bool has_color = tp.format != TextureFormat::kAlpha;
  const bool has_alpha = tp.format == TextureFormat::kAlpha || tp.format == TextureFormat::kLuminanceAlpha ||
                         tp.format == TextureFormat::kIntensity || tp.format == TextureFormat::kRgba;
  const VB one = hn::Set(db, 1.0f);
  switch (tp.env) {
    case TextureEnvMode::kReplace:
      if (has_color) f[0] = t[0], f[1] = t[1], f[2] = t[2];
      if (has_alpha) f[3] = t[3];
      return;
    case TextureEnvMode::kModulate:
      if (has_color) f[0] = hn::Mul(f[0], t[0]), f[1] = hn::Mul(f[1], t[1]), f[2] = hn::Mul(f[2], t[2]);
      if (has_alpha) f[3] = hn::Mul(f[3], t[3]);
      return;
    case TextureEnvMode::kDecal:
      if (tp.format == TextureFormat::kRgb) {
        f[0] = t[0], f[1] = t[1], f[2] = t[2];
      } else if (tp.format == TextureFormat::kRgba) {
        const VB keep = hn::Sub(one, t[3]);
        #pragma GCC unroll 3
        for (int c = 0; c < 3; ++c) f[c] = hn::Add(hn::Mul(f[c], keep), hn::Mul(t[c], t[3]));
      }
      return;
    case TextureEnvMode::kBlend: {
      VB alpha = f[3];
      if (tp.format == TextureFormat::kIntensity) {
        alpha = hn::Add(hn::Mul(f[3], hn::Sub(one, t[3])), hn::Mul(hn::Set(db, tp.env_color[3]), t[3]));
      } else if (has_alpha) {
        alpha = hn::Mul(f[3], t[3]);
      }
      if (has_color) {
        #pragma GCC unroll 3
        for (int c = 0; c < 3; ++c) {
          f[c] = hn::Add(hn::Mul(f[c], hn::Sub(one, t[c])), hn::Mul(hn::Set(db, tp.env_color[c]), t[c]));
        }
      }
      f[3] = alpha;
      return;
    }
    case TextureEnvMode::kAdd: {
      if (has_color) {
        #pragma GCC unroll 3
        for (int c = 0; c < 3; ++c) f[c] = saturate(hn::Add(f[c], t[c]));
      }
      if (tp.format == TextureFormat::kIntensity) f[3] = saturate(hn::Add(f[3], t[3]));
      else if (has_alpha) f[3] = hn::Mul(f[3], t[3]);
      return;
    }
    case TextureEnvMode::kCombine: return;  // texture_combine's
  }
}

/// apply_texture_combine (texture.cpp) lane by lane, operation by operation: unit `unit`'s
/// GL_COMBINE environment over every unit's texel `texels` (zero without a texture), the
/// primary colour `primary` and the previous unit's colour `f`, which it replaces.
HWY_INLINE void texture_combine(const TexturePlan& tp, int unit, VB f[4], const VB texels[kMaxTextureUnits][4],
                                const VB primary[4]) {
  const DB db;
  const TextureCombine& c = tp.combine;
  const VB one = hn::Set(db, 1.0f), half = hn::Set(db, 0.5f), two = hn::Set(db, 2.0f);
  VB constant[4];
  for (int k = 0; k < 4; ++k) constant[k] = hn::Set(db, tp.env_color[k]);
  auto source = [&](CombineSource s) -> const VB* {
    switch (s) {
      case CombineSource::kTexture: return texels[unit];
      case CombineSource::kConstant: return constant;
      case CombineSource::kPrimaryColor: return primary;
      case CombineSource::kPrevious: return f;
      default: return texels[int(s) - int(CombineSource::kTexture0)];
    }
  };
  auto operand = [&](CombineOperand o, const VB* v, int k) {
    switch (o) {
      case CombineOperand::kSrcColor: return v[k];
      case CombineOperand::kOneMinusSrcColor: return hn::Sub(one, v[k]);
      case CombineOperand::kSrcAlpha: return v[3];
      case CombineOperand::kOneMinusSrcAlpha: return hn::Sub(one, v[3]);
    }
    return v[k];
  };
  auto function = [&](CombineFunction fn, VB a0, VB a1, VB a2) {
    switch (fn) {
      case CombineFunction::kReplace: return a0;
      case CombineFunction::kModulate: return hn::Mul(a0, a1);
      case CombineFunction::kAdd: return hn::Add(a0, a1);
      case CombineFunction::kAddSigned: return hn::Sub(hn::Add(a0, a1), half);
      case CombineFunction::kInterpolate: return hn::Add(hn::Mul(a0, a2), hn::Mul(a1, hn::Sub(one, a2)));
      case CombineFunction::kSubtract: return hn::Sub(a0, a1);
      default: return a0;
    }
  };
  auto clamps = [](CombineFunction fn) {
    return fn != CombineFunction::kReplace && fn != CombineFunction::kModulate && fn != CombineFunction::kInterpolate;
  };
  auto finish = [&](VB v, float scale, bool clamp) {
    if (scale != 1.0f) return saturate(hn::Mul(v, hn::Set(db, scale)));
    return clamp ? saturate(v) : v;
  };
  const VB* rs[3] = {source(c.rgb_source[0]), source(c.rgb_source[1]), source(c.rgb_source[2])};
  const VB* as[3] = {source(c.alpha_source[0]), source(c.alpha_source[1]), source(c.alpha_source[2])};
  VB out[4];
  if (c.rgb == CombineFunction::kDot3Rgb || c.rgb == CombineFunction::kDot3Rgba) {
    VB p[3];
    for (int k = 0; k < 3; ++k) {
      const VB a0 = hn::Sub(hn::Mul(operand(c.rgb_operand[0], rs[0], k), two), one);
      const VB a1 = hn::Sub(hn::Mul(operand(c.rgb_operand[1], rs[1], k), two), one);
      p[k] = hn::Mul(a0, a1);
    }
    const VB product = hn::Add(hn::Add(p[0], p[1]), p[2]);
    out[0] = out[1] = out[2] = finish(product, c.rgb_scale, true);
    if (c.rgb == CombineFunction::kDot3Rgba) out[3] = finish(product, c.alpha_scale, true);
  } else {
    for (int k = 0; k < 3; ++k) {
      const VB v = function(c.rgb, operand(c.rgb_operand[0], rs[0], k), operand(c.rgb_operand[1], rs[1], k),
                            operand(c.rgb_operand[2], rs[2], k));
      out[k] = finish(v, c.rgb_scale, clamps(c.rgb));
    }
  }
  if (c.rgb != CombineFunction::kDot3Rgba) {
    auto alpha = [&](int i) {
      return c.alpha_operand[i] == CombineOperand::kOneMinusSrcAlpha || c.alpha_operand[i] == CombineOperand::kOneMinusSrcColor
                 ? hn::Sub(one, as[i][3]) : as[i][3];
    };
    out[3] = finish(function(c.alpha, alpha(0), alpha(1), alpha(2)), c.alpha_scale, clamps(c.alpha));
  }
  for (int k = 0; k < 4; ++k) f[k] = out[k];
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SHADELAB_FAST_TEXENV_INL_H_
