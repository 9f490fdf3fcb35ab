// SIMD fragment work for one group of horizontally adjacent pixels of one triangle: depth
// test, perspective-correct interpolation, Gouraud/flat colours or per-pixel Phong lighting,
// blending and the colour write. Each step is the reference's arithmetic lane by lane (double
// interpolation, float blending, round-half-away conversion), so results match it bitwise
// except for the powers in lighting. Per-target code (Highway).
#if defined(SHADELAB_FAST_FRAGMENT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SHADELAB_FAST_FRAGMENT_INL_H_
#undef SHADELAB_FAST_FRAGMENT_INL_H_
#else
#define SHADELAB_FAST_FRAGMENT_INL_H_
#endif

#include "fast/lighting-inl.h"
#include "fast/triangle.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DD = hn::ScalableTag<double>;
using DF = hn::Rebind<float, DD>;          // one float per double lane
using DU = hn::Rebind<std::uint32_t, DD>;  // one RGBA8 pixel per lane
using DI = hn::Rebind<std::int32_t, DD>;
using VD = hn::Vec<DD>;
using VF = hn::Vec<DF>;
using MF = hn::Mask<DF>;

/// Normalized perspective weights of a group (reference_raster.inl's q0, q1, q2).
struct Weights {
  VD q0, q1, q2;
};

HWY_INLINE Weights perspective_weights(const TriSetup& t, VD b0, VD b1, VD b2) {
  const DD dd;
  if (t.affine) return {b0, b1, b2};
  VD q0 = hn::Mul(b0, hn::Set(dd, double(t.v[0]->inv_w)));
  VD q1 = hn::Mul(b1, hn::Set(dd, double(t.v[1]->inv_w)));
  VD q2 = hn::Mul(b2, hn::Set(dd, double(t.v[2]->inv_w)));
  VD inv = hn::Div(hn::Set(dd, 1.0), hn::Add(hn::Add(q0, q1), q2));
  return {hn::Mul(q0, inv), hn::Mul(q1, inv), hn::Mul(q2, inv)};
}

/// Varying `k` at every lane. A value equal at the three vertices is taken as is: the
/// reference's weighted sum rounds back to it exactly (the weights sum to 1 within 1e-15).
HWY_INLINE VF varying(const TriSetup& t, const Weights& w, int k) {
  const DD dd;
  const DF df;
  float a0 = t.var[0][k], a1 = t.var[1][k], a2 = t.var[2][k];
  if (a0 == a1 && a1 == a2) return hn::Set(df, a0);
  VD s = hn::Add(hn::Add(hn::Mul(w.q0, hn::Set(dd, double(a0))), hn::Mul(w.q1, hn::Set(dd, double(a1)))),
                 hn::Mul(w.q2, hn::Set(dd, double(a2))));
  return hn::DemoteTo(df, s);
}

struct Rgba {
  VF c[4];
};

// Gouraud, flat or unlit colour: primary plus secondary (the colour sum, draw.cpp).
HWY_INLINE Rgba vertex_color(const DrawJob& job, const TriSetup& t, const Weights& w) {
  const DF df;
  const VaryingLayout& l = job.plan.layout;
  int color = t.front ? l.front_color : l.back_color;
  int secondary = t.front ? l.front_secondary : l.back_secondary;
  Rgba out;
  for (int c = 0; c < 4; ++c) {
    out.c[c] = t.flat ? hn::Set(df, t.flat[color + c]) : varying(t, w, color + c);
  }
  if (secondary < 0) return out;
  for (int c = 0; c < 3; ++c) {
    VF s = t.flat ? hn::Set(df, t.flat[secondary + c]) : varying(t, w, secondary + c);
    out.c[c] = hn::Add(out.c[c], s);
  }
  return out;
}

/// Per-pixel Phong for lanes of any width: the interpolated eye position `p` and normal `n`,
/// re-normalized, lit; out[0..3] = red, green, blue (secondary added when separate) and alpha.
template <class D>
HWY_INLINE void phong_lanes(const DrawJob& job, const TriSetup& t, D d, const V3<D>& p, V3<D> n,
                            hn::Vec<D> out[4]) {
  V3<D> up{hn::Zero(d), hn::Zero(d), hn::Set(d, 1.0f)};
  n = normalize_or(d, n, up, nullptr);
  bool back = !t.front && job.plan.two_side;
  LitIn<D> in;
  in.p = p;
  in.n = back ? V3<D>{hn::Neg(n.x), hn::Neg(n.y), hn::Neg(n.z)} : n;
  const MaterialParams& m = back ? job.plan.lighting.back : job.plan.lighting.front;
  LitOut<D> lit = light_lanes(d, job.plan.lighting, m, in);
  out[0] = lit.primary.x;
  out[1] = lit.primary.y;
  out[2] = lit.primary.z;
  out[3] = hn::Set(d, m.alpha);
  if (!job.plan.lighting.separate_specular) return;
  out[0] = hn::Add(out[0], lit.secondary.x);
  out[1] = hn::Add(out[1], lit.secondary.y);
  out[2] = hn::Add(out[2], lit.secondary.z);
}

/// The interpolated eye position (first three) and normal (last three) of a group.
HWY_INLINE void phong_inputs(const DrawJob& job, const TriSetup& t, const Weights& w, VF v[6]) {
  const VaryingLayout& l = job.plan.layout;
  for (int k = 0; k < 3; ++k) {
    v[k] = varying(t, w, l.eye_position + k);
    v[3 + k] = varying(t, w, l.eye_normal + k);
  }
}

// Per-pixel Phong for one group.
HWY_INLINE Rgba phong_color(const DrawJob& job, const TriSetup& t, const Weights& w) {
  const DF df;
  VF v[6];
  phong_inputs(job, t, w, v);
  Rgba out;
  phong_lanes(job, t, df, V3<DF>{v[0], v[1], v[2]}, V3<DF>{v[3], v[4], v[5]}, out.c);
  return out;
}

/// fragment_ops.cpp's compare(func, incoming, stored).
HWY_INLINE MF depth_compare(CompareFunc func, VF z, VF stored) {
  const DF df;
  switch (func) {
    case CompareFunc::kNever: return hn::FirstN(df, 0);
    case CompareFunc::kLess: return hn::Lt(z, stored);
    case CompareFunc::kEqual: return hn::Eq(z, stored);
    case CompareFunc::kLequal: return hn::Le(z, stored);
    case CompareFunc::kGreater: return hn::Gt(z, stored);
    case CompareFunc::kNotequal: return hn::Ne(z, stored);
    case CompareFunc::kGequal: return hn::Ge(z, stored);
    case CompareFunc::kAlways: break;
  }
  return hn::FirstN(df, hn::Lanes(df));
}

HWY_INLINE VF one_minus(VF v) { return hn::Sub(hn::Set(DF(), 1.0f), v); }

/// fragment_ops.cpp's blend_factor for channel c.
HWY_INLINE VF blend_factor(BlendFactor f, int c, const Rgba& src, const Rgba& dst) {
  const DF df;
  switch (f) {
    case BlendFactor::kZero: return hn::Zero(df);
    case BlendFactor::kOne: return hn::Set(df, 1.0f);
    case BlendFactor::kSrcColor: return src.c[c];
    case BlendFactor::kOneMinusSrcColor: return one_minus(src.c[c]);
    case BlendFactor::kDstColor: return dst.c[c];
    case BlendFactor::kOneMinusDstColor: return one_minus(dst.c[c]);
    case BlendFactor::kSrcAlpha: return src.c[3];
    case BlendFactor::kOneMinusSrcAlpha: return one_minus(src.c[3]);
    case BlendFactor::kDstAlpha: return dst.c[3];
    case BlendFactor::kOneMinusDstAlpha: return one_minus(dst.c[3]);
    case BlendFactor::kSrcAlphaSaturate: {
      if (c == 3) return hn::Set(df, 1.0f);
      VF b = one_minus(dst.c[3]);  // std::min(a, b) = (b < a) ? b : a
      return hn::IfThenElse(hn::Lt(b, src.c[3]), b, src.c[3]);
    }
  }
  return hn::Set(df, 1.0f);
}

// fragment_ops.cpp's unit(): v > 0 ? min(v, 1) : 0, so NaN becomes 0.
HWY_INLINE VF clamp_unit(VF v) {
  const DF df;
  VF hi = hn::IfThenElse(hn::Lt(v, hn::Set(df, 1.0f)), v, hn::Set(df, 1.0f));
  return hn::IfThenElseZero(hn::Gt(v, hn::Zero(df)), hi);
}

// lround(clamp(v, 0, 1) * 255) as an integer lane, without a float-to-int conversion: s =
// v * 255 lies in [0, 255], so s + 2^23 holds s rounded to an integer (half to even) in its
// low mantissa bits, exactly. lround rounds half away from zero, which differs only where s is
// exactly r + 0.5 (r even): one is added there. Checked against lround for every float in
// [0, 255].
HWY_INLINE hn::Vec<DU> to_unorm8(VF v) {
  const DF df;
  const DU du;
  const VF magic = hn::Set(df, 8388608.0f);
  VF s = hn::Mul(clamp_unit(v), hn::Set(df, 255.0f));
  VF y = hn::Add(s, magic);
  VF r = hn::Sub(y, magic);
  auto half_up = hn::RebindMask(du, hn::Eq(hn::Sub(s, r), hn::Set(df, 0.5f)));
  hn::Vec<DU> bits = hn::Sub(hn::BitCast(du, y), hn::BitCast(du, magic));
  return hn::Add(bits, hn::IfThenElseZero(half_up, hn::Set(du, 1u)));
}

HWY_INLINE VF channel(hn::Vec<DU> px, int c) {
  const DU du;
  hn::Vec<DU> v = hn::And(hn::ShiftRightSame(px, 8 * c), hn::Set(du, 0xffu));
  return hn::ConvertTo(DF(), hn::BitCast(DI(), v));
}

/// fragment_ops.cpp's write_color for the live lanes of a group at `pixels`.
HWY_INLINE void write_colors(const FragmentState& fs, Rgba src, MF live, std::uint32_t* pixels) {
  const DF df;
  const DU du;
  for (VF& c : src.c) c = clamp_unit(c);
  bool masked = !(fs.color_mask[0] && fs.color_mask[1] && fs.color_mask[2] && fs.color_mask[3]);
  hn::Vec<DU> old = (fs.blend.enabled || masked) ? hn::LoadU(du, pixels) : hn::Zero(du);
  Rgba out = src;
  if (fs.blend.enabled) {
    Rgba dst;
    for (int c = 0; c < 4; ++c) dst.c[c] = hn::Div(channel(old, c), hn::Set(df, 255.0f));
    for (int c = 0; c < 4; ++c) {
      out.c[c] = hn::Add(hn::Mul(src.c[c], blend_factor(fs.blend.src, c, src, dst)),
                         hn::Mul(dst.c[c], blend_factor(fs.blend.dst, c, src, dst)));
    }
  }
  hn::Vec<DU> packed;
  if (!masked) {
    packed = hn::Or(hn::Or(to_unorm8(out.c[0]), hn::ShiftLeft<8>(to_unorm8(out.c[1]))),
                    hn::Or(hn::ShiftLeft<16>(to_unorm8(out.c[2])), hn::ShiftLeft<24>(to_unorm8(out.c[3]))));
  } else {
    packed = hn::Zero(du);
    for (int c = 0; c < 4; ++c) {
      hn::Vec<DU> v = fs.color_mask[c] ? to_unorm8(out.c[c])
                                       : hn::And(hn::ShiftRightSame(old, 8 * c), hn::Set(du, 0xffu));
      packed = hn::Or(packed, hn::ShiftLeftSame(v, 8 * c));
    }
  }
  hn::BlendedStore(packed, hn::RebindMask(du, live), du, pixels);
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SHADELAB_FAST_FRAGMENT_INL_H_
