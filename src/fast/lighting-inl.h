// The OpenGL lighting equation (src/lighting/lighting.cpp) over SIMD lanes, one point per lane.
// In its reference form (per-vertex lighting) every operation is the reference's float
// operation in the reference's order (no FMA), so results are bitwise light_point's except the
// powers (binary powering or exp(e log c) here, std::pow there); the per-pixel form is cheaper
// and within a few roundings of it (Form). The differential tests that hold it to light_point:
// FastDifferential (tests/fast/differential_test.cpp) and FastScenes
// (tests/fast/scene_differential_test.cpp).
// Per-target code: included by Highway dispatch units once per SIMD target.
#if defined(SHADELAB_FAST_LIGHTING_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SHADELAB_FAST_LIGHTING_INL_H_
#undef SHADELAB_FAST_LIGHTING_INL_H_
#else
#define SHADELAB_FAST_LIGHTING_INL_H_
#endif

#include <bit>

#include "fast/lighting_setup.hpp"
#include "hwy/contrib/math/math-inl.h"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class D>
struct V3 {
  hn::Vec<D> x, y, z;
};

/// Points to light: eye-space positions and unit normals (already flipped for back faces).
template <class D>
struct LitIn {
  V3<D> p, n;
};

/// Lit colours: primary rgb (alpha is the material's) and secondary rgb, clamped to [0, 1].
template <class D>
struct LitOut {
  V3<D> primary, secondary;
};

// glm::dot for vec3: (x*x' + y*y') + z*z'.
template <class D>
HWY_INLINE hn::Vec<D> dot3(const V3<D>& a, const V3<D>& b) {
  return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z));
}

// The same in fused multiply-adds where the target has them (per-pixel lighting).
template <class D>
HWY_INLINE hn::Vec<D> dot3_fused(const V3<D>& a, const V3<D>& b) {
  return hn::MulAdd(a.z, b.z, hn::MulAdd(a.y, b.y, hn::Mul(a.x, b.x)));
}

template <class D>
HWY_INLINE V3<D> splat3(D d, const float v[3]) {
  return {hn::Set(d, v[0]), hn::Set(d, v[1]), hn::Set(d, v[2])};
}

/// How the equation is evaluated.
/// - kReference (per-vertex lighting): as lighting.cpp, bitwise but for the powers. The
///   equation switches terms on and off (the specular term where n . L turns positive, spot
///   lights at their cone's edge), and a vertex there must fall on the reference's side,
///   since a Gouraud triangle spreads its colour over many pixels: evaluated per vertex in
///   the kPerPixel form, the Lok Yau Hall figure, whose dull specular is large at its
///   sphere's terminator, differed by 3/255 over ten pixels.
/// - kPerPixel (per-pixel Phong, light_per_pixel), within a few float roundings of it: a
///   vector is normalized by one reciprocal and three products instead of three divisions
///   (zero, infinite and NaN lengths give the reference's results; only a subnormal length,
///   whose reciprocal overflows, differs); light x material colours are premultiplied per
///   draw (LightParams::product) and accumulated by fused multiply-adds; Blinn's n . h for an
///   infinite viewer is (n . L + n.z) / sqrt(2 + 2 L.z), without forming and normalizing h;
///   dot products and the attenuation's polynomial are fused multiply-adds where the target
///   has them. Reciprocal square root and reciprocal estimates with a Newton step in place of
///   the square roots and divisions measured no faster.
enum class Form { kReference, kPerPixel };

// len > 0 ? v / len : fallback, with len = glm::length(v).
template <Form kForm, class D>
HWY_INLINE V3<D> normalize_or(D d, const V3<D>& v, const V3<D>& fallback, hn::Vec<D>* length) {
  hn::Vec<D> len = hn::Sqrt(kForm == Form::kPerPixel ? dot3_fused(v, v) : dot3(v, v));
  auto ok = hn::Gt(len, hn::Zero(d));
  if (length) *length = len;
  if constexpr (kForm == Form::kPerPixel) {
    const hn::Vec<D> inv = hn::Div(hn::Set(d, 1.0f), len);
    return {hn::IfThenElse(ok, hn::Mul(v.x, inv), fallback.x),
            hn::IfThenElse(ok, hn::Mul(v.y, inv), fallback.y),
            hn::IfThenElse(ok, hn::Mul(v.z, inv), fallback.z)};
  }
  return {hn::IfThenElse(ok, hn::Div(v.x, len), fallback.x),
          hn::IfThenElse(ok, hn::Div(v.y, len), fallback.y),
          hn::IfThenElse(ok, hn::Div(v.z, len), fallback.z)};
}

// One step of pow_positive's binary powering: the power squared, times c where the bit is
// set. A function, not a lambda: a lambda called seven times is a call, its vectors kept in
// memory.
template <class V>
HWY_INLINE V power_step(V power, V c, bool times_c) {
  power = hn::Mul(power, power);
  return times_c ? hn::Mul(power, c) : power;
}

// c^e for c > 0 (other lanes are garbage and must be masked by the caller). A whole exponent
// from 1 to 128 (shininess and spot exponents usually are) by binary powering: at most 7
// squarings and 7 products, each rounding once, so within about 2e-5 relative of the exact
// power (std::pow), against some 45 operations for exp(e log c), which is there for the
// others. The squarings are unrolled from the exponent's top bit down: each bit's test is a
// branch of its own, taken the same way for a whole draw (in a loop, one branch taking the
// exponent's bits in turn was mispredicted often enough to cost a tenth of per-pixel
// lighting's time).
template <class D>
HWY_INLINE hn::Vec<D> pow_positive(D d, hn::Vec<D> c, float e) {
  if (e >= 1.0f && e <= 128.0f && e == float(int(e))) {
    const unsigned n = unsigned(e);
    hn::Vec<D> power = c;  // c^(the bits of n above bit b), from the top bit down
    switch (std::bit_width(n)) {  // 1 to 8
      case 8: power = power_step(power, c, (n >> 6) & 1u); [[fallthrough]];
      case 7: power = power_step(power, c, (n >> 5) & 1u); [[fallthrough]];
      case 6: power = power_step(power, c, (n >> 4) & 1u); [[fallthrough]];
      case 5: power = power_step(power, c, (n >> 3) & 1u); [[fallthrough]];
      case 4: power = power_step(power, c, (n >> 2) & 1u); [[fallthrough]];
      case 3: power = power_step(power, c, (n >> 1) & 1u); [[fallthrough]];
      case 2: power = power_step(power, c, n & 1u); [[fallthrough]];
      default: break;
    }
    return power;
  }
  // Highway's Exp holds for arguments up to 88; past that the power overflows or nearly
  // does, as std::pow's does (a shininess of 109 on a normal of length 2 without
  // GL_NORMALIZE: n . h up to 8). The power is exp(t - 88) exp(88) there, and infinite once
  // t passes 89 (exp(89) is past the largest float): the reference's colour then clamps to 1
  // where a wrong finite value (or NaN) would make it black.
  const hn::Vec<D> t = hn::Mul(hn::Set(d, e), hn::Log(d, c));
  const auto high = hn::Gt(t, hn::Set(d, 88.0f));
  hn::Vec<D> power = hn::Exp(d, hn::IfThenElse(high, hn::Sub(t, hn::Set(d, 88.0f)), t));
  power = hn::IfThenElse(high, hn::Mul(power, hn::Set(d, 1.6516363e38f)), power);  // exp(88)
  return hn::IfThenElse(hn::Gt(t, hn::Set(d, 89.0f)), hn::Inf(d), power);
}

// lighting.cpp's spot_factor for a positional light with a cone.
template <class D>
HWY_INLINE hn::Vec<D> spot_lanes(D d, const LightParams& l, const V3<D>& to_light) {
  if (l.spot_dark) return hn::Zero(d);
  V3<D> neg{hn::Neg(to_light.x), hn::Neg(to_light.y), hn::Neg(to_light.z)};
  hn::Vec<D> c = dot3(neg, splat3(d, l.spot_dir));
  auto outside = hn::Lt(c, hn::Set(d, l.cos_cutoff));
  // pow(0, 0) is 1 in C, as the GL equation wants at exponent 0.
  if (l.spot_exponent == 0.0f) return hn::IfThenZeroElse(outside, hn::Set(d, 1.0f));
  hn::Vec<D> cc = hn::Max(c, hn::Zero(d));
  hn::Vec<D> p = hn::IfThenElseZero(hn::Gt(cc, hn::Zero(d)), pow_positive(d, cc, l.spot_exponent));
  return hn::IfThenZeroElse(outside, p);
}

// The specular cosine raised to the shininess (specular_factor in lighting.cpp).
template <Form kForm, class D>
HWY_INLINE hn::Vec<D> specular_lanes(D d, const LightParams& l, const MaterialParams& m,
                                     const V3<D>& n, const V3<D>& to_light, hn::Vec<D> n_dot_l,
                                     const V3<D>& v, bool infinite_viewer) {
  hn::Vec<D> c;
  if (m.phong_specular) {
    hn::Vec<D> two_ndl = hn::Mul(hn::Set(d, 2.0f), n_dot_l);
    V3<D> r{hn::Sub(hn::Mul(two_ndl, n.x), to_light.x), hn::Sub(hn::Mul(two_ndl, n.y), to_light.y),
            hn::Sub(hn::Mul(two_ndl, n.z), to_light.z)};
    c = dot3(r, v);
  } else if (l.const_half) {
    c = dot3(n, splat3(d, l.half));
  } else if (kForm == Form::kPerPixel && infinite_viewer) {
    // v = (0, 0, 1) and |L| = 1: n . (L + v) / |L + v| = (n.L + n.z) / sqrt(2 + 2 L.z), and
    // 0 where L + v vanishes, as the reference's normalize_or.
    const hn::Vec<D> h2 = hn::MulAdd(hn::Set(d, 2.0f), to_light.z, hn::Set(d, 2.0f));
    const hn::Vec<D> num = hn::Add(n_dot_l, n.z);
    const float half = 0.5f * m.shininess;
    if (half >= 1.0f && half <= 64.0f && half == float(int(half))) {
      // An even shininess: c^e = (c^2)^(e/2) with c^2 = num^2 / (2 + 2 L.z), for positive c:
      // no square root (the divider's slowest operation).
      const auto positive = hn::And(hn::Gt(num, hn::Zero(d)), hn::Gt(h2, hn::Zero(d)));
      return hn::IfThenElseZero(positive, pow_positive(d, hn::Div(hn::Mul(num, num), h2), half));
    }
    const hn::Vec<D> ndh = hn::Div(num, hn::Sqrt(h2));
    c = hn::IfThenElseZero(hn::Gt(h2, hn::Zero(d)), ndh);
  } else {
    V3<D> h{hn::Add(to_light.x, v.x), hn::Add(to_light.y, v.y), hn::Add(to_light.z, v.z)};
    V3<D> zero{hn::Zero(d), hn::Zero(d), hn::Zero(d)};
    c = dot3(n, normalize_or<kForm>(d, h, zero, nullptr));
  }
  auto positive = hn::Gt(c, hn::Zero(d));
  if (m.shininess == 0.0f) return hn::IfThenElseZero(positive, hn::Set(d, 1.0f));
  return hn::IfThenElseZero(positive, pow_positive(d, c, m.shininess));
}

// Direction to the light and attenuation * spot for one light (the reference form).
template <class D>
HWY_INLINE hn::Vec<D> light_direction(D d, const LightParams& l, const V3<D>& p, V3<D>& to_light) {
  if (!l.positional) {
    to_light = splat3(d, l.pos);
    return hn::Set(d, l.const_spot);  // attenuation 1
  }
  V3<D> delta{hn::Sub(hn::Set(d, l.pos[0]), p.x), hn::Sub(hn::Set(d, l.pos[1]), p.y),
              hn::Sub(hn::Set(d, l.pos[2]), p.z)};
  V3<D> zero{hn::Zero(d), hn::Zero(d), hn::Zero(d)};
  hn::Vec<D> dist;
  to_light = normalize_or<Form::kReference>(d, delta, zero, &dist);
  const hn::Vec<D> denom = hn::Add(hn::Add(hn::Set(d, l.kc), hn::Mul(hn::Set(d, l.kl), dist)),
                                   hn::Mul(hn::Mul(hn::Set(d, l.kq), dist), dist));
  hn::Vec<D> att = hn::IfThenElseZero(hn::Gt(denom, hn::Zero(d)), hn::Div(hn::Set(d, 1.0f), denom));
  if (!l.spot) return att;
  return hn::Mul(att, spot_lanes(d, l, to_light));
}

// (s * a[c]) * b[c] for the three channels, as glm evaluates scale * rgb(a) * rgb(b).
template <class D>
HWY_INLINE V3<D> scaled(D d, hn::Vec<D> s, const float a[3], const float b[3]) {
  return {hn::Mul(hn::Mul(s, hn::Set(d, a[0])), hn::Set(d, b[0])),
          hn::Mul(hn::Mul(s, hn::Set(d, a[1])), hn::Set(d, b[1])),
          hn::Mul(hn::Mul(s, hn::Set(d, a[2])), hn::Set(d, b[2]))};
}

// lighting.cpp's clamp01: x > 0 ? min(x, 1) : 0, so NaN and -0 become +0. On x86, Max is
// maxps(x, 0), which returns its second operand, +0, where x is NaN or either zero: two
// operations. Elsewhere Highway's Max may keep the NaN, so the comparisons.
template <class D>
HWY_INLINE hn::Vec<D> clamp01(D d, hn::Vec<D> x) {
#if HWY_ARCH_X86 && HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128
  return hn::Min(hn::Max(x, hn::Zero(d)), hn::Set(d, 1.0f));
#else
  hn::Vec<D> hi = hn::IfThenElse(hn::Lt(x, hn::Set(d, 1.0f)), x, hn::Set(d, 1.0f));
  return hn::IfThenElseZero(hn::Gt(x, hn::Zero(d)), hi);
#endif
}

// Per-pixel lighting (Form::kPerPixel), arranged for fewer vector operations: the kernel is
// bound by their number, not by the divider's latency (lighting two independent blocks per
// light took twice as long as one). For a positional light, n . L is (n . d) / |d| with
// d = position - p, without normalizing d (the other components of L only where a spot, the
// Phong specular or a local viewer needs them); each term is accumulated by fused
// multiply-adds of the light x material products, with the lit test folded into its scale;
// and a light whose ambient product is black adds no ambient term (the reference adds
// scale x 0, which differs only where the scale is infinite: a light at the lit point without
// constant attenuation).
template <class D>
HWY_INLINE LitOut<D> light_per_pixel(D d, const LightingSetup& s, const MaterialParams& m, const LitIn<D>& in) {
  using V = hn::Vec<D>;
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0f);
  V3<D> v{zero, zero, one};
  if (s.local_viewer) {
    V3<D> minus_p{hn::Neg(in.p.x), hn::Neg(in.p.y), hn::Neg(in.p.z)};
    v = normalize_or<Form::kPerPixel>(d, minus_p, v, nullptr);
  }
  V3<D> primary = splat3(d, m.base);
  V3<D> spec{zero, zero, zero};
  for (const LightParams& l : s.lights) {
    const float(&product)[3][3] = l.product[m.side];
    V scale, n_dot_l;
    V3<D> to_light;
    if (l.positional) {
      const V3<D> delta{hn::Sub(hn::Set(d, l.pos[0]), in.p.x), hn::Sub(hn::Set(d, l.pos[1]), in.p.y),
                        hn::Sub(hn::Set(d, l.pos[2]), in.p.z)};
      const V dist = hn::Sqrt(dot3_fused(delta, delta));
      const V inv = hn::IfThenElseZero(hn::Gt(dist, zero), hn::Div(one, dist));  // L = 0 at d = 0
      const V denom = hn::MulAdd(hn::MulAdd(hn::Set(d, l.kq), dist, hn::Set(d, l.kl)), dist, hn::Set(d, l.kc));
      scale = hn::IfThenElseZero(hn::Gt(denom, zero), hn::Div(one, denom));
      n_dot_l = hn::Mul(dot3_fused(in.n, delta), inv);
      if (l.spot || m.phong_specular || s.local_viewer) {
        to_light = {hn::Mul(delta.x, inv), hn::Mul(delta.y, inv), hn::Mul(delta.z, inv)};
        if (l.spot) scale = hn::Mul(scale, spot_lanes(d, l, to_light));
      } else {  // Blinn's infinite-viewer form reads L.z only
        to_light = {zero, zero, hn::Mul(delta.z, inv)};
      }
    } else {
      to_light = splat3(d, l.pos);
      scale = hn::Set(d, l.const_spot);
      n_dot_l = dot3_fused(in.n, to_light);
    }
    // lighting.cpp: diffuse and specular only where n.L > 0 and attenuation * spot > 0.
    const auto lit = hn::And(hn::Gt(n_dot_l, zero), hn::Gt(scale, zero));
    if (l.ambient_product[m.side]) {
      primary.x = hn::MulAdd(scale, hn::Set(d, product[0][0]), primary.x);
      primary.y = hn::MulAdd(scale, hn::Set(d, product[0][1]), primary.y);
      primary.z = hn::MulAdd(scale, hn::Set(d, product[0][2]), primary.z);
    }
    const V diffuse = hn::IfThenElseZero(lit, hn::Mul(scale, n_dot_l));
    primary.x = hn::MulAdd(diffuse, hn::Set(d, product[1][0]), primary.x);
    primary.y = hn::MulAdd(diffuse, hn::Set(d, product[1][1]), primary.y);
    primary.z = hn::MulAdd(diffuse, hn::Set(d, product[1][2]), primary.z);
    if (hn::AllFalse(d, lit)) continue;  // adding zeros changes nothing
    const V f = specular_lanes<Form::kPerPixel>(d, l, m, in.n, to_light, n_dot_l, v, !s.local_viewer);
    const V specular = hn::IfThenElseZero(lit, hn::Mul(scale, f));
    spec.x = hn::MulAdd(specular, hn::Set(d, product[2][0]), spec.x);
    spec.y = hn::MulAdd(specular, hn::Set(d, product[2][1]), spec.y);
    spec.z = hn::MulAdd(specular, hn::Set(d, product[2][2]), spec.z);
  }
  if (!s.separate_specular) {
    return {{clamp01(d, hn::Add(primary.x, spec.x)), clamp01(d, hn::Add(primary.y, spec.y)),
             clamp01(d, hn::Add(primary.z, spec.z))},
            {zero, zero, zero}};
  }
  return {{clamp01(d, primary.x), clamp01(d, primary.y), clamp01(d, primary.z)},
          {clamp01(d, spec.x), clamp01(d, spec.y), clamp01(d, spec.z)}};
}

// The reference form (Form::kReference): light_point's operations in light_point's order.
template <class D>
HWY_INLINE LitOut<D> light_reference(D d, const LightingSetup& s, const MaterialParams& m,
                                     const LitIn<D>& in) {
  V3<D> v{hn::Zero(d), hn::Zero(d), hn::Set(d, 1.0f)};
  if (s.local_viewer) {
    V3<D> minus_p{hn::Neg(in.p.x), hn::Neg(in.p.y), hn::Neg(in.p.z)};
    v = normalize_or<Form::kReference>(d, minus_p, v, nullptr);
  }
  V3<D> primary = splat3(d, m.base);
  V3<D> spec{hn::Zero(d), hn::Zero(d), hn::Zero(d)};
  for (const LightParams& l : s.lights) {
    V3<D> to_light;
    hn::Vec<D> scale = light_direction(d, l, in.p, to_light);
    hn::Vec<D> n_dot_l = dot3(in.n, to_light);
    // lighting.cpp: diffuse and specular only where n.L > 0 and attenuation * spot > 0.
    auto lit = hn::And(hn::Gt(n_dot_l, hn::Zero(d)), hn::Gt(scale, hn::Zero(d)));
    const V3<D> amb = scaled(d, scale, m.ambient, l.ambient);
    const V3<D> dif = scaled(d, hn::Mul(scale, n_dot_l), m.diffuse, l.diffuse);
    primary.x = hn::Add(primary.x, hn::Add(amb.x, hn::IfThenElseZero(lit, dif.x)));
    primary.y = hn::Add(primary.y, hn::Add(amb.y, hn::IfThenElseZero(lit, dif.y)));
    primary.z = hn::Add(primary.z, hn::Add(amb.z, hn::IfThenElseZero(lit, dif.z)));
    if (hn::AllFalse(d, lit)) continue;  // adding zeros changes nothing
    hn::Vec<D> f = specular_lanes<Form::kReference>(d, l, m, in.n, to_light, n_dot_l, v, !s.local_viewer);
    const hn::Vec<D> spec_scale = hn::Mul(scale, f);
    const V3<D> sp = scaled(d, spec_scale, m.specular, l.specular);
    spec.x = hn::Add(spec.x, hn::IfThenElseZero(lit, sp.x));
    spec.y = hn::Add(spec.y, hn::IfThenElseZero(lit, sp.y));
    spec.z = hn::Add(spec.z, hn::IfThenElseZero(lit, sp.z));
  }
  if (!s.separate_specular) {
    V3<D> sum{hn::Add(primary.x, spec.x), hn::Add(primary.y, spec.y), hn::Add(primary.z, spec.z)};
    return {{clamp01(d, sum.x), clamp01(d, sum.y), clamp01(d, sum.z)},
            {hn::Zero(d), hn::Zero(d), hn::Zero(d)}};
  }
  return {{clamp01(d, primary.x), clamp01(d, primary.y), clamp01(d, primary.z)},
          {clamp01(d, spec.x), clamp01(d, spec.y), clamp01(d, spec.z)}};
}

/// The whole equation for every lane: light_point(model, lights, material, {p, n}).
template <Form kForm, class D>
HWY_INLINE LitOut<D> light_lanes(D d, const LightingSetup& s, const MaterialParams& m,
                                 const LitIn<D>& in) {
  if constexpr (kForm == Form::kPerPixel) {
    return light_per_pixel(d, s, m, in);
  } else {
    return light_reference(d, s, m, in);
  }
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SHADELAB_FAST_LIGHTING_INL_H_
