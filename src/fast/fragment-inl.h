// SIMD fragment work for one block of pixels of one triangle: depth test,
// perspective-correct interpolation, Gouraud/flat colours or per-pixel Phong lighting, fog,
// the alpha test, blending or the logic op, and the colour write. A block is two rows of as many pixels as the SIMD target has
// double lanes (8 x 2 with AVX-512): coverage and the barycentric weights are computed row by
// row in double lanes, exactly as the reference; the rest on one float vector holding both
// rows. Depth (the reference's float plane), blending and the round-half-away conversion are
// the reference's arithmetic lane by lane; the perspective weights and the varyings are
// computed in floats (a few float roundings from the reference's doubles), and per-pixel
// lighting differs in its powers and divisions: the differential tests hold colours within
// 1/255. Per-target code (Highway).
//
// The small loops over a block's rows, colour channels and edges carry `#pragma GCC unroll`
// here and in raster-inl.h: left as loops, GCC kept their arrays of vectors (Rgba, the edge
// values, the weights) in memory, storing and reloading every vector on the way; unrolled,
// they stay in registers (the full-screen Gouraud fill took 38% less time).
#if defined(SHADELAB_FAST_FRAGMENT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SHADELAB_FAST_FRAGMENT_INL_H_
#undef SHADELAB_FAST_FRAGMENT_INL_H_
#else
#define SHADELAB_FAST_FRAGMENT_INL_H_
#endif

#include <algorithm>
#include <cstdint>

#include "fast/block-inl.h"
#include "fast/lighting-inl.h"
#include "fast/texture-inl.h"
#include "fast/triangle.hpp"
#include "hwy/contrib/math/math-inl.h"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

/// Varying `k` at every lane, as the reference computes it: the perspective weights and the
/// weighted sum in doubles.
HWY_INLINE VB exact_varying(const TriSetup& t, const Weights& w, int k) {
  const DD dd;
  const DF df;
  const double a0 = t.var[0][k], a1 = t.var[1][k], a2 = t.var[2][k];
  VF rows[kRows];
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) {
    VD q0 = w.b0[r], q1 = w.b1[r];
    VD q2 = hn::Sub(hn::Sub(hn::Set(dd, 1.0), q0), q1);
    if (!t.affine) {
      q0 = hn::Mul(q0, hn::Set(dd, double(t.v[0]->inv_w)));
      q1 = hn::Mul(q1, hn::Set(dd, double(t.v[1]->inv_w)));
      q2 = hn::Mul(q2, hn::Set(dd, double(t.v[2]->inv_w)));
      const VD inv = hn::Div(hn::Set(dd, 1.0), hn::Add(hn::Add(q0, q1), q2));
      q0 = hn::Mul(q0, inv), q1 = hn::Mul(q1, inv), q2 = hn::Mul(q2, inv);
    }
    VD s = hn::Add(hn::Add(hn::Mul(q0, hn::Set(dd, a0)), hn::Mul(q1, hn::Set(dd, a1))),
                   hn::Mul(q2, hn::Set(dd, a2)));
    rows[r] = hn::DemoteTo(df, s);
  }
  return join_rows(df, rows[0], rows[kRows - 1]);
}

/// One varying over one triangle, set up once per triangle and tile: a2 + q0 (a0 - a2) +
/// q1 (a1 - a2) in floats. The reference's double sum q0 a0 + q1 a1 + q2 a2 differs from it
/// by a few float roundings of the largest |a| (q0 + q1 + q2 = 1), far below the 1/255 of a
/// colour step. A value equal at the three vertices (and flat shading's provoking value) has
/// zero differences, so the sum is that value exactly (the weights of a covered pixel are
/// finite), as the reference's rounds back to it. A triangle with a non-finite value or
/// difference takes the reference's own arithmetic for all its varyings (exact_varying).
struct Plane {
  float base, d0, d1;
  int k;  // the varying
};

// Sets up planes[i] for varyings first + i; false where some value or difference is not
// finite. (x * 0 is 0 for finite x and NaN otherwise; a NaN makes the sum NaN.)
template <int N>
HWY_INLINE bool set_up(const TriSetup& t, int first, const float* flat, Plane (&planes)[N]) {
  if (flat) {
    for (int i = 0; i < N; ++i) planes[i] = {flat[first + i], 0.0f, 0.0f, first + i};
    return true;
  }
  float probe = 0.0f;
  for (int i = 0; i < N; ++i) {
    const float a0 = t.var[0][first + i], a1 = t.var[1][first + i], a2 = t.var[2][first + i];
    planes[i] = {a2, a0 - a2, a1 - a2, first + i};
    probe += (a2 * 0.0f + planes[i].d0 * 0.0f) + planes[i].d1 * 0.0f;
  }
  return probe == 0.0f;
}

// Fused where the target has FMA: within the same few roundings.
HWY_INLINE VB linear_varying(const Weights& w, const Plane& p) {
  const DB db;
  return hn::MulAdd(w.f1, hn::Set(db, p.d1), hn::MulAdd(w.f0, hn::Set(db, p.d0), hn::Set(db, p.base)));
}

/// The varyings a triangle's fragments read: its colours (primary, then secondary when
/// separate) or, for per-pixel Phong, its eye position and normal.
struct TrianglePlanes {
  Plane color[4], secondary[3];
  bool has_secondary;
  // One colour over the whole triangle (flat shading, a colour given once: glRect's layers),
  // clamped as write_colors clamps: what every lane's sum would be (zero differences).
  bool uniform;
  float uniform_color[4];
  Plane position[3], normal[3];
  Plane fog[1];  // the fog coordinate (never flat), when the draw is fogged
  TexcoordPlanes texcoord[kMaxTextureUnits];  // of each unit with a texture
  // The opaque kernels' colour planes, in bytes: 255 c + kJustBelowHalf, whose truncation
  // (clamped to [0, 255]) is the byte (to_unorm8). Equal to the colour planes' bytes for one
  // colour over the triangle; otherwise within the same few float roundings.
  Plane bytes[4];
  std::uint32_t uniform_bytes;  // with `uniform`, the opaque kernels' one packed colour (byte_plane_colors')
  bool exact;          // the reference's arithmetic for every varying (a non-finite one)
  bool ready = false;  // set up at the first fragment that passes its tests
};

HWY_INLINE VB varying(const TriSetup& t, const TrianglePlanes& planes, const Weights& w, const Plane& p) {
  return planes.exact ? exact_varying(t, w, p.k) : linear_varying(w, p);
}

HWY_INLINE void set_up_color_planes(const DrawJob& job, const TriSetup& t, TrianglePlanes& out) {
  const VaryingLayout& l = job.plan.layout;
  if (job.plan.phong) {
    const bool finite_position = set_up(t, l.eye_position, nullptr, out.position);
    const bool finite_normal = set_up(t, l.eye_normal, nullptr, out.normal);
    out.exact = !(finite_position && finite_normal);
    return;
  }
  const int color = t.front ? l.front_color : l.back_color;
  const int secondary = t.front ? l.front_secondary : l.back_secondary;
  out.exact = !set_up(t, color, t.flat, out.color);
  out.has_secondary = secondary >= 0;
  if (out.has_secondary && !set_up(t, secondary, t.flat, out.secondary)) out.exact = true;
  out.uniform = !out.exact && !out.has_secondary;
  for (int c = 0; c < 4; ++c) {
    const Plane& p = out.color[c];
    out.uniform = out.uniform && p.d0 == 0.0f && p.d1 == 0.0f;
    out.uniform_color[c] = p.base > 0.0f ? std::min(p.base, 1.0f) : 0.0f;  // clamp_unit
  }
  if (kernel_opaque(job.plan.kernel) || job.plan.kernel == BlockKernel::kStencil) {
    for (int c = 0; c < 4; ++c) {
      const Plane& p = out.color[c];
      out.bytes[c] = {p.base * 255.0f + kJustBelowHalf, p.d0 * 255.0f, p.d1 * 255.0f, p.k};
    }
    out.uniform_bytes = 0;
    for (int c = 0; c < 4; ++c) {
      out.uniform_bytes |= std::uint32_t(std::min(std::max(out.bytes[c].base, 0.0f), 255.0f)) << (8 * c);
    }
  }
}

HWY_INLINE void set_up_planes(const DrawJob& job, const TriSetup& t, TrianglePlanes& out) {
  out.ready = true;
  set_up_color_planes(job, t, out);
  if (job.plan.textured) {
    for (int u = 0; u < kMaxTextureUnits; ++u) {
      if (job.plan.texture[u].texture) out.texcoord[u] = texcoord_planes(job, t, u);
    }
    out.uniform = false;  // the environment combines the unclamped colour
  }
  if (!job.plan.fog) return;
  // Fog blends the unclamped colour (draw.cpp's shade_fragment): no clamped uniform colour.
  out.uniform = false;
  if (!set_up(t, job.plan.layout.fog, nullptr, out.fog)) out.exact = true;
}

struct Rgba {
  VB c[4];
  bool clamped = false;  // already in [0, 1] as clamp_unit leaves it
};

// Gouraud, flat or unlit colour: primary plus secondary (the colour sum, draw.cpp), or without
// the secondary (a textured draw adds it after the texture environment).
HWY_INLINE Rgba vertex_color(const TriSetup& t, const TrianglePlanes& planes, const Weights& w,
                             bool with_secondary = true) {
  Rgba out;
  if (planes.uniform) {
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) out.c[c] = hn::Set(DB(), planes.uniform_color[c]);
    out.clamped = true;
    return out;
  }
  if (!planes.exact && !planes.has_secondary) {  // the usual case, without branches
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) out.c[c] = linear_varying(w, planes.color[c]);
    return out;
  }
  #pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) out.c[c] = varying(t, planes, w, planes.color[c]);
  if (!planes.has_secondary || !with_secondary) return out;
  #pragma GCC unroll 4
  for (int c = 0; c < 3; ++c) out.c[c] = hn::Add(out.c[c], varying(t, planes, w, planes.secondary[c]));
  return out;
}

/// Per-pixel Phong for lanes of any width: the interpolated eye position `p` and normal `n`,
/// re-normalized, lit; out[0..3] = red, green, blue (secondary added when separate, or stored
/// in `secondary` when given: zero when not separate) and alpha.
template <class D>
HWY_INLINE void phong_lanes(const DrawJob& job, const TriSetup& t, D d, const V3<D>& p, V3<D> n,
                            hn::Vec<D> out[4], hn::Vec<D>* secondary = nullptr) {
  V3<D> up{hn::Zero(d), hn::Zero(d), hn::Set(d, 1.0f)};
  n = normalize_or<Form::kPerPixel>(d, n, up, nullptr);
  bool back = !t.front && job.plan.two_side;
  LitIn<D> in;
  in.p = p;
  in.n = back ? V3<D>{hn::Neg(n.x), hn::Neg(n.y), hn::Neg(n.z)} : n;
  const MaterialParams& m = back ? job.plan.lighting.back : job.plan.lighting.front;
  LitOut<D> lit = light_lanes<Form::kPerPixel>(d, job.plan.lighting, m, in);
  out[0] = lit.primary.x;
  out[1] = lit.primary.y;
  out[2] = lit.primary.z;
  out[3] = hn::Set(d, m.alpha);
  if (secondary) {
    const bool separate = job.plan.lighting.separate_specular;
    secondary[0] = separate ? lit.secondary.x : hn::Zero(d);
    secondary[1] = separate ? lit.secondary.y : hn::Zero(d);
    secondary[2] = separate ? lit.secondary.z : hn::Zero(d);
    return;
  }
  if (!job.plan.lighting.separate_specular) return;
  out[0] = hn::Add(out[0], lit.secondary.x);
  out[1] = hn::Add(out[1], lit.secondary.y);
  out[2] = hn::Add(out[2], lit.secondary.z);
}

// Per-pixel Phong for one block: the interpolated eye position and normal, lit (the
// secondary colour into `secondary` when given, as phong_lanes).
HWY_INLINE Rgba phong_color(const DrawJob& job, const TriSetup& t, const TrianglePlanes& planes,
                            const Weights& w, VB* secondary = nullptr) {
  const DB db;
  VB v[6];
  #pragma GCC unroll 4
  for (int k = 0; k < 3; ++k) {
    v[k] = varying(t, planes, w, planes.position[k]);
    v[3 + k] = varying(t, planes, w, planes.normal[k]);
  }
  Rgba out;
  phong_lanes(job, t, db, V3<DB>{v[0], v[1], v[2]}, V3<DB>{v[3], v[4], v[5]}, out.c, secondary);
  return out;
}

/// fragment_ops.cpp's apply_fog on a block's colours: the fog factor from the interpolated
/// fog coordinate (2^y as e^(y ln 2), within an ulp or two of the reference's exp2), clamped,
/// then f (C - C_fog) + C_fog for red, green and blue.
HWY_INLINE void apply_fog(const detail::FogParams& p, const TriSetup& t, const TrianglePlanes& planes,
                          const Weights& w, Rgba& color) {
  const DB db;
  const VB c = varying(t, planes, w, planes.fog[0]);
  VB f;
  if (p.mode == FogMode::kLinear) {
    f = hn::MulAdd(c, hn::Set(db, p.scale), hn::Set(db, p.bias));
  } else {
    VB y = hn::Mul(c, hn::Set(db, p.k));
    if (p.mode == FogMode::kExp2) y = hn::Mul(y, y);
    const VB x = hn::Neg(hn::Mul(y, hn::Set(db, 0.693147180559945309f)));
    // Exp is valid up to 104: a positive exponent (a negative coordinate) gives a factor
    // clamped to 1 anyway; NaN gives 0, as the reference's clamp.
    f = hn::IfThenZeroElse(hn::IsNaN(x), hn::Exp(db, hn::Min(x, hn::Zero(db))));
  }
  f = clamp01(db, f);
  #pragma GCC unroll 4
  for (int k = 0; k < 3; ++k) {
    const VB fog = hn::Set(db, p.color[k]);
    color.c[k] = hn::MulAdd(f, hn::Sub(color.c[k], fog), fog);
  }
  color.clamped = false;
}

/// fragment_ops.cpp's compare(func, incoming, stored).
HWY_INLINE MB depth_compare(CompareFunc func, VB z, VB stored) {
  const DB db;
  switch (func) {
    case CompareFunc::kNever: return hn::FirstN(db, 0);
    case CompareFunc::kLess: return hn::Lt(z, stored);
    case CompareFunc::kEqual: return hn::Eq(z, stored);
    case CompareFunc::kLequal: return hn::Le(z, stored);
    case CompareFunc::kGreater: return hn::Gt(z, stored);
    case CompareFunc::kNotequal: return hn::Ne(z, stored);
    case CompareFunc::kGequal: return hn::Ge(z, stored);
    case CompareFunc::kAlways: break;
  }
  return hn::FirstN(db, hn::Lanes(db));
}

HWY_INLINE VB one_minus(VB v) { return hn::Sub(hn::Set(DB(), 1.0f), v); }

/// fragment_ops.cpp's blend_factor for channel c; `constant` is the blend colour as the
/// reference's blend_constant gives it (DrawPlan::blend_constant).
HWY_INLINE VB blend_factor(BlendFactor f, int c, const Rgba& src, const Rgba& dst, const float* constant) {
  const DB db;
  switch (f) {
    case BlendFactor::kZero: return hn::Zero(db);
    case BlendFactor::kOne: return hn::Set(db, 1.0f);
    case BlendFactor::kSrcColor: return src.c[c];
    case BlendFactor::kOneMinusSrcColor: return one_minus(src.c[c]);
    case BlendFactor::kDstColor: return dst.c[c];
    case BlendFactor::kOneMinusDstColor: return one_minus(dst.c[c]);
    case BlendFactor::kSrcAlpha: return src.c[3];
    case BlendFactor::kOneMinusSrcAlpha: return one_minus(src.c[3]);
    case BlendFactor::kDstAlpha: return dst.c[3];
    case BlendFactor::kOneMinusDstAlpha: return one_minus(dst.c[3]);
    case BlendFactor::kSrcAlphaSaturate: {
      if (c == 3) return hn::Set(db, 1.0f);
      VB b = one_minus(dst.c[3]);  // std::min(a, b) = (b < a) ? b : a
      return hn::IfThenElse(hn::Lt(b, src.c[3]), b, src.c[3]);
    }
    case BlendFactor::kConstantColor: return hn::Set(db, constant[c]);
    case BlendFactor::kOneMinusConstantColor: return one_minus(hn::Set(db, constant[c]));
    case BlendFactor::kConstantAlpha: return hn::Set(db, constant[3]);
    case BlendFactor::kOneMinusConstantAlpha: return one_minus(hn::Set(db, constant[3]));
  }
  return hn::Set(db, 1.0f);
}

// fragment_ops.cpp's unit(): v > 0 ? min(v, 1) : 0, so NaN becomes 0.
HWY_INLINE VB clamp_unit(VB v) { return clamp01(DB(), v); }

/// trunc(t) for t in [0, 256) as an integer lane.
HWY_INLINE hn::Vec<DUB> truncate_byte(VB t) { return hn::BitCast(DUB(), truncate_in_range(t)); }

// lround(v * 255) for v in [0, 1] (clamped by the caller) as an integer lane: s = v * 255,
// then trunc(s + kJustBelowHalf) (draw_job.hpp), which is lround(s) for every float s in
// [0, 255].
HWY_INLINE hn::Vec<DUB> to_unorm8(VB v) {
  const DB db;
  return truncate_byte(hn::Add(hn::Mul(v, hn::Set(db, 255.0f)), hn::Set(db, kJustBelowHalf)));
}


/// x / 255 for integers x in [0, 255], correctly rounded as the reference's division. With
/// fused multiply-adds: q = x * (1/255) is within an ulp; its residual x - 255 q is exact in
/// one FMA, and q + residual / 255 rounds to the quotient (checked for all 256 values in
/// tests/fast/unorm8_test.cpp). Without them, the division.
HWY_INLINE VB byte_to_unit(VB x) {
  const DB db;
#if HWY_NATIVE_FMA
  const VB r = hn::Set(db, kInv255);
  const VB q = hn::Mul(x, r);
  return hn::MulAdd(hn::NegMulAdd(q, hn::Set(db, 255.0f), x), r, q);
#else
  return hn::Div(x, hn::Set(db, 255.0f));
#endif
}

/// Colours clamped to [0, 1] as fragment_ops.cpp's unit().
HWY_INLINE Rgba clamped(const Rgba& color) {
  if (color.clamped) return color;
  Rgba out;
  #pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) out.c[c] = clamp_unit(color.c[c]);
  out.clamped = true;
  return out;
}

/// The colours of a block's pixels (RGBA8 words) in [0, 1], as blending reads them.
HWY_INLINE Rgba unit_colors(hn::Vec<DUB> px) {
  Rgba dst;
  #pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) dst.c[c] = byte_to_unit(channel(px, c));
  return dst;
}

/// The usual transparency, glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), of clamped
/// colours. Its result needs no clamp: with s, d, a in [0, 1], the rounded s a is at most a
/// and d (1 - a) at most the rounded 1 - a, whose sum with a rounds to at most 1 (it exceeds 1
/// by under half an ulp of 1); nothing is negative or NaN.
HWY_INLINE Rgba blend_src_alpha(const Rgba& src, const Rgba& dst) {
  Rgba out;
  const VB a = src.c[3], one_minus_a = one_minus(src.c[3]);
  #pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) out.c[c] = hn::Add(hn::Mul(src.c[c], a), hn::Mul(dst.c[c], one_minus_a));
  return out;
}

/// fragment_ops.cpp's blend, then clamped: any equation and factors (GL 1.4 section 4.1.7),
/// alpha with its own factors and equation. kMin and kMax read no factor.
HWY_INLINE Rgba blend_colors(const BlendState& b, const float* constant, const Rgba& src, const Rgba& dst) {
  Rgba out;
  #pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) {
    VB v;
    const BlendEquation e = c == 3 ? b.alpha_equation() : b.equation;
    if (e == BlendEquation::kMin) {
      v = hn::Min(src.c[c], dst.c[c]);
    } else if (e == BlendEquation::kMax) {
      v = hn::Max(src.c[c], dst.c[c]);
    } else {
      const VB s = hn::Mul(src.c[c], blend_factor(c == 3 ? b.src_alpha : b.src, c, src, dst, constant));
      const VB d = hn::Mul(dst.c[c], blend_factor(c == 3 ? b.dst_alpha : b.dst, c, src, dst, constant));
      v = e == BlendEquation::kAdd ? hn::Add(s, d) : e == BlendEquation::kSubtract ? hn::Sub(s, d) : hn::Sub(d, s);
    }
    out.c[c] = clamp_unit(v);
  }
  out.clamped = true;
  return out;
}

/// RGBA8 words of colours in [0, 1].
HWY_INLINE hn::Vec<DUB> pack_unorm8(const Rgba& out) {
  return hn::Or(hn::Or(to_unorm8(out.c[0]), hn::ShiftLeft<8>(to_unorm8(out.c[1]))),
                hn::Or(hn::ShiftLeft<16>(to_unorm8(out.c[2])), hn::ShiftLeft<24>(to_unorm8(out.c[3]))));
}

/// The opaque kernels' RGBA8 words from the byte planes (TrianglePlanes::bytes): each
/// channel's plane clamped to [0, 255] and truncated (a plane's value lies 255 c +
/// kJustBelowHalf: to_unorm8 of the clamped colour).
HWY_INLINE hn::Vec<DUB> byte_plane_colors(const TrianglePlanes& planes, const Weights& w) {
  const DB db;
  const VB lo = hn::Zero(db), hi = hn::Set(db, 255.0f);
  hn::Vec<DUB> b[4];
  #pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) b[c] = truncate_byte(hn::Min(hn::Max(linear_varying(w, planes.bytes[c]), lo), hi));
  return hn::Or(hn::Or(b[0], hn::ShiftLeft<8>(b[1])), hn::Or(hn::ShiftLeft<16>(b[2]), hn::ShiftLeft<24>(b[3])));
}

/// The lanes whose alpha, as its 8-bit value `byte` in a float, passes the alpha test
/// (fragment_ops.cpp's alpha_test): against the reference's (and above the floor's).
HWY_INLINE unsigned alpha_byte_bits(const AlphaTestState& a, float ref_byte, VB byte) {
  const DB db;
  const unsigned bits = block_bits(depth_compare(a.func, byte, hn::Set(db, ref_byte)));
  if (a.floor < 0.0f) return bits;
  return bits & block_bits(hn::Gt(byte, hn::Set(db, float(detail::unorm8(a.floor)))));
}

/// alpha_byte_bits for the alpha in [0, 1] (clamped first).
HWY_INLINE unsigned alpha_bits(const AlphaTestState& a, float ref_byte, VB alpha) {
  const DB db;
  return alpha_byte_bits(
      a, ref_byte, hn::Trunc(hn::Add(hn::Mul(clamp_unit(alpha), hn::Set(db, 255.0f)), hn::Set(db, kJustBelowHalf))));
}

/// fragment_ops.cpp's logic_op on RGBA8 words.
HWY_INLINE hn::Vec<DUB> logic_op(LogicOp op, hn::Vec<DUB> s, hn::Vec<DUB> d) {
  const DUB dub;
  switch (op) {
    case LogicOp::kClear: return hn::Zero(dub);
    case LogicOp::kAnd: return hn::And(s, d);
    case LogicOp::kAndReverse: return hn::AndNot(d, s);
    case LogicOp::kCopy: return s;
    case LogicOp::kAndInverted: return hn::AndNot(s, d);
    case LogicOp::kNoop: return d;
    case LogicOp::kXor: return hn::Xor(s, d);
    case LogicOp::kOr: return hn::Or(s, d);
    case LogicOp::kNor: return hn::Not(hn::Or(s, d));
    case LogicOp::kEquiv: return hn::Not(hn::Xor(s, d));
    case LogicOp::kInvert: return hn::Not(d);
    case LogicOp::kOrReverse: return hn::Or(s, hn::Not(d));
    case LogicOp::kCopyInverted: return hn::Not(s);
    case LogicOp::kOrInverted: return hn::Or(hn::Not(s), d);
    case LogicOp::kNand: return hn::Not(hn::And(s, d));
    case LogicOp::kSet: return hn::Set(dub, ~0u);
  }
  return s;
}

/// The colour mask as a word: the bytes of the channels written.
HWY_INLINE std::uint32_t mask_word(const FragmentState& fs) {
  std::uint32_t m = 0;
  for (int c = 0; c < 4; ++c) m |= fs.color_mask[c] ? 0xffu << (8 * c) : 0u;
  return m;
}

/// fragment_ops.cpp's write_color for the lanes of a block set in `live`, at `rows`.
HWY_INLINE void write_colors(const DrawJob& job, const Rgba& color, unsigned live, std::uint32_t* const rows[kRows]) {
  const DUB dub;
  const FragmentState& fs = *job.frag;
  Rgba out = clamped(color);
  if (fs.alpha_one) out.c[3] = hn::Set(DB(), 1.0f);
  if (fs.logic_op.enabled) {  // instead of blending, on the 8-bit values
    const hn::Vec<DUB> old = load_rows(DU(), rows);
    const hn::Vec<DUB> keep = hn::Set(dub, mask_word(fs));
    const hn::Vec<DUB> result = logic_op(fs.logic_op.op, pack_unorm8(out), old);
    return store_rows(DU(), hn::Or(hn::And(result, keep), hn::AndNot(keep, old)), live, rows);
  }
  bool masked = !(fs.color_mask[0] && fs.color_mask[1] && fs.color_mask[2] && fs.color_mask[3]);
  hn::Vec<DUB> old = (fs.blend.enabled || masked) ? load_rows(DU(), rows) : hn::Zero(dub);
  if (fs.blend.enabled) {
    const Rgba src = out;
    const Rgba dst = unit_colors(old);
    out = fs.blend.source_over() ? blend_src_alpha(src, dst) : blend_colors(fs.blend, job.plan.blend_constant, src, dst);
  }
  hn::Vec<DUB> packed;
  if (!masked) {
    packed = pack_unorm8(out);
  } else {
    packed = hn::Zero(dub);
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) {
      hn::Vec<DUB> v = fs.color_mask[c] ? to_unorm8(out.c[c])
                                        : hn::And(hn::ShiftRightSame(old, 8 * c), hn::Set(dub, 0xffu));
      packed = hn::Or(packed, hn::ShiftLeftSame(v, 8 * c));
    }
  }
  store_rows(DU(), packed, live, rows);
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SHADELAB_FAST_FRAGMENT_INL_H_
