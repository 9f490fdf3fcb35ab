// Texture sampling on the SIMD path, for one block of a triangle: texels gathered from the
// RGBA8 levels (or compared against the reference value of a depth texture), wrapped and
// filtered within and between the levels texcoord-inl.h chose. Each step is the reference's
// (texture.cpp's sample_texture_bytes) operation by operation, without fused multiply-adds, so
// that every target samples the texels the reference samples. The environments that combine
// the texels with the fragment's colour are in texenv-inl.h. Per-target code (Highway).
#if defined(SHADELAB_FAST_TEXTURE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SHADELAB_FAST_TEXTURE_INL_H_
#undef SHADELAB_FAST_TEXTURE_INL_H_
#else
#define SHADELAB_FAST_TEXTURE_INL_H_
#endif

#include <algorithm>
#include <cstdint>
#include <limits>

#include "fast/block-inl.h"
#include "fast/texcoord-inl.h"
#include "fast/triangle.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

/// texture.cpp's mirror: |2 (s/2 - round(s/2))|, rounded half to even.
HWY_INLINE VB mirror(VB s) {
  const DB db;
  const VB h = hn::Mul(s, hn::Set(db, 0.5f));
  const VB f = hn::Sub(h, hn::Round(h));
  return hn::Abs(hn::Add(f, f));
}

/// wrap_coord, times the level's size: where in the level, in texels, a coordinate falls.
HWY_INLINE VB texel_coord(VB s, int size, TextureWrap wrap) {
  const DB db;
  switch (wrap) {
    case TextureWrap::kRepeat: s = hn::Sub(s, hn::Floor(s)); break;
    case TextureWrap::kClamp: s = hn::Min(hn::Max(s, hn::Zero(db)), hn::Set(db, 1.0f)); break;
    case TextureWrap::kClampToEdge: {
      const float half = 0.5f / float(size);
      s = hn::Min(hn::Max(s, hn::Set(db, half)), hn::Set(db, 1.0f - half));
      break;
    }
    case TextureWrap::kClampToBorder: s = hn::Min(hn::Max(s, hn::Set(db, -1.0f)), hn::Set(db, 2.0f)); break;
    case TextureWrap::kMirroredRepeat: s = mirror(s); break;
  }
  return hn::Mul(s, hn::Set(db, float(size)));
}

/// wrap_index for indices in [-1, size] (clamp to border: [-size - 1, 2 size]): repeat wraps
/// them, clamp-to-edge and mirrored repeat clamp them, and GL_CLAMP and clamp to border keep
/// them, marking those outside [0, size) in `border` (the border colour).
HWY_INLINE hn::Vec<DIB> wrap_index(hn::Vec<DIB> i, int size, TextureWrap wrap, hn::Mask<DIB>& border) {
  const DIB di;
  const auto n = hn::Set(di, size);
  switch (wrap) {
    case TextureWrap::kRepeat:
      i = hn::IfThenElse(hn::Lt(i, hn::Zero(di)), hn::Add(i, n), i);
      return hn::IfThenElse(hn::Lt(i, n), i, hn::Sub(i, n));
    case TextureWrap::kClampToEdge: case TextureWrap::kMirroredRepeat:
      return hn::Min(hn::Max(i, hn::Zero(di)), hn::Sub(n, hn::Set(di, 1)));
    case TextureWrap::kClamp: case TextureWrap::kClampToBorder:
      border = hn::Or(border, hn::Or(hn::Lt(i, hn::Zero(di)), hn::Not(hn::Lt(i, n))));
  }
  return i;
}

/// texture.cpp's depth_texel: r OP d (or d) in byte units, expanded by the depth texture mode.
HWY_INLINE void depth_texels(const TexturePlan& tp, VB d, VB ref, VB out[4]) {
  const DB db;
  VB v = hn::Mul(d, hn::Set(db, 255.0f));
  if (tp.compare) {
    MB pass;
    switch (tp.compare_func) {
      case TextureCompare::kNever: pass = hn::FirstN(db, 0); break;
      case TextureCompare::kLess: pass = hn::Lt(ref, d); break;
      case TextureCompare::kEqual: pass = hn::Eq(ref, d); break;
      case TextureCompare::kLequal: pass = hn::Le(ref, d); break;
      case TextureCompare::kGreater: pass = hn::Gt(ref, d); break;
      case TextureCompare::kNotequal: pass = hn::Ne(ref, d); break;
      case TextureCompare::kGequal: pass = hn::Ge(ref, d); break;
      default: pass = hn::FirstN(db, hn::Lanes(db)); break;
    }
    v = hn::IfThenElseZero(pass, hn::Set(db, 255.0f));
  }
  const VB zero = hn::Zero(db);
  switch (tp.format) {
    case TextureFormat::kIntensity: out[0] = out[1] = out[2] = out[3] = v; return;
    case TextureFormat::kAlpha: out[0] = out[1] = out[2] = zero, out[3] = v; return;
    default: out[0] = out[1] = out[2] = v, out[3] = hn::Set(db, 255.0f); return;
  }
}

/// Whether every lane of `index` holds `first`, its first lane's.
HWY_INLINE bool uniform(hn::Vec<DIB> index, std::int32_t first) {
  return hn::AllTrue(DIB(), hn::Eq(index, hn::Set(DIB(), first)));
}

/// The RGBA8 words at `index`: one load where every lane reads the same texel (most blocks of
/// a magnified texture do, and every block wholly in a border, whose lanes read texel 0), a
/// gather otherwise.
HWY_INLINE hn::Vec<DUB> gather_words(const std::uint32_t* words, hn::Vec<DIB> index) {
  const std::int32_t first = hn::GetLane(index);
  return uniform(index, first) ? hn::Set(DUB(), words[first]) : hn::GatherIndex(DUB(), words, index);
}

/// Texels (i, j, k) of a level in byte units (texture.cpp's texel), gathered from its RGBA8
/// words; j is ignored by 1D textures, k by 1D and 2D ones.
template <bool k2D = false>
HWY_INLINE void fetch(const TexturePlan& tp, const TextureLevel& l, hn::Vec<DIB> i, hn::Vec<DIB> j, hn::Vec<DIB> k,
                      VB out[4], VB ref) {
  const DIB di;
  hn::Mask<DIB> border = hn::FirstN(di, 0);
  i = wrap_index(i, l.width, tp.wrap_s, border);
  if (!is_1d<k2D>(tp)) j = wrap_index(j, l.height, tp.wrap_t, border);
  if (is_3d<k2D>(tp)) {
    k = wrap_index(k, l.depth, tp.wrap_r, border);
    j = hn::Add(hn::Mul(k, hn::Set(di, l.height)), j);
  } else if (is_cube<k2D>(tp)) {  // k: the face's image
    j = hn::Add(hn::Mul(k, hn::Set(di, l.height)), j);
  }
  const auto index = hn::IfThenZeroElse(border, hn::Add(hn::Mul(j, hn::Set(di, l.width)), i));
  if (is_depth<k2D>(tp)) {  // the border's depth: the border colour's red
    const DB db;
    VB d = hn::GatherIndex(db, l.depth_values.data(), index);
    d = hn::IfThenElse(hn::RebindMask(db, border), hn::Set(db, tp.border_depth), d);
    return depth_texels(tp, d, ref, out);
  }
  const bool any_border = !hn::AllFalse(di, border);
  const auto words = gather_words(reinterpret_cast<const std::uint32_t*>(l.rgba.data()), index);
  #pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) {
    out[c] = channel(words, c);
    if (any_border) out[c] = hn::IfThenElse(hn::RebindMask(DB(), border), hn::Set(DB(), tp.border[c]), out[c]);
  }
}

/// a + w (b - a), the reference's lerp.
HWY_INLINE VB lerp(VB a, VB b, VB w) { return hn::Add(a, hn::Mul(w, hn::Sub(b, a))); }

/// The RGBA8 words at wrapped indices i0 and i1 of each lane's row (whose first texel is
/// `row`); lanes marked in `border0` or `border1` read the level's first texel there (the
/// caller puts the border in). Where every lane reads the same two texels (most blocks of a
/// magnified texture, and blocks wholly in a border) they are two loads; where every lane's two
/// texels are neighbours in memory (inside the level, not wrapped: all but the lanes within
/// half a texel of a wrapped or clamped edge), each lane's pair is read as one 64-bit word,
/// half the loads of two gathers.
HWY_INLINE void texel_words(const TextureLevel& l, hn::Vec<DIB> row, hn::Vec<DIB> i0, hn::Mask<DIB> border0,
                            hn::Vec<DIB> i1, hn::Mask<DIB> border1, hn::Vec<DUB>& w0, hn::Vec<DUB>& w1) {
  const DUB du;
  const auto* words = reinterpret_cast<const std::uint32_t*>(l.rgba.data());
  const auto index0 = hn::IfThenZeroElse(border0, hn::Add(row, i0));
  const auto index1 = hn::IfThenZeroElse(border1, hn::Add(row, i1));
  const std::int32_t first0 = hn::GetLane(index0), first1 = hn::GetLane(index1);
  if (uniform(index0, first0) && uniform(index1, first1)) {
    w0 = hn::Set(du, words[first0]), w1 = hn::Set(du, words[first1]);
    return;
  }
#if HWY_TARGET != HWY_SCALAR
  const DIB di;
  const auto pairs = hn::AndNot(hn::Or(border0, border1), hn::Eq(i1, hn::Add(i0, hn::Set(di, 1))));
  if (hn::AllTrue(di, pairs)) {
    const hn::Half<DIB> dh;
    const hn::Repartition<std::uint64_t, DUB> dq;
    const hn::Repartition<std::int64_t, DUB> dqi;
    const auto* quads = reinterpret_cast<const std::uint64_t*>(words);
    // GatherOffset's byte offsets: four a texel (a shift: 64-bit products take three
    // multiplications with AVX2).
    const auto lo = hn::GatherOffset(dq, quads, hn::ShiftLeft<2>(hn::PromoteTo(dqi, hn::LowerHalf(dh, index0))));
    const auto hi = hn::GatherOffset(dq, quads, hn::ShiftLeft<2>(hn::PromoteTo(dqi, hn::UpperHalf(dh, index0))));
    w0 = hn::ConcatEven(du, hn::BitCast(du, hi), hn::BitCast(du, lo));
    w1 = hn::ConcatOdd(du, hn::BitCast(du, hi), hn::BitCast(du, lo));
    return;
  }
#endif
  w0 = gather_words(words, index0);
  w1 = gather_words(words, index1);
}

/// The reference's bilinear slice of a 2D, cube or 3D colour level at texels (i, j) to
/// (i + 1, j + 1) of image k, weighted by a across and b down: fetch's texels, each index
/// wrapped once (a depth texture's compared with `ref` by fetch).
template <bool k2D = false>
HWY_INLINE void bilinear_slice(const TexturePlan& tp, const TextureLevel& l, hn::Vec<DIB> i, hn::Vec<DIB> j,
                               hn::Vec<DIB> k, VB a, VB b, VB ref, VB out[4]) {
  const DIB di;
  const auto one = hn::Set(di, 1);
  if (is_depth<k2D>(tp)) {  // depth comparisons per texel: fetch's
    VB t00[4], t10[4], t01[4], t11[4];
    fetch<k2D>(tp, l, i, j, k, t00, ref);
    fetch<k2D>(tp, l, hn::Add(i, one), j, k, t10, ref);
    fetch<k2D>(tp, l, i, hn::Add(j, one), k, t01, ref);
    fetch<k2D>(tp, l, hn::Add(i, one), hn::Add(j, one), k, t11, ref);
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) out[c] = lerp(lerp(t00[c], t10[c], a), lerp(t01[c], t11[c], a), b);
    return;
  }
  const hn::Mask<DIB> none = hn::FirstN(di, 0);
  hn::Mask<DIB> bi0 = none, bi1 = none, bj0 = none, bj1 = none, bk = none;
  const auto i0 = wrap_index(i, l.width, tp.wrap_s, bi0), i1 = wrap_index(hn::Add(i, one), l.width, tp.wrap_s, bi1);
  auto j0 = wrap_index(j, l.height, tp.wrap_t, bj0), j1 = wrap_index(hn::Add(j, one), l.height, tp.wrap_t, bj1);
  if (is_3d<k2D>(tp) || is_cube<k2D>(tp)) {  // k: a 3D level's image (wrapped), a cube map's face
    const auto image = hn::Mul(is_3d<k2D>(tp) ? wrap_index(k, l.depth, tp.wrap_r, bk) : k, hn::Set(di, l.height));
    j0 = hn::Add(image, j0), j1 = hn::Add(image, j1);
  }
  // The four texels' words, then one channel at a time (converted, the border put in, lerped):
  // few vectors live at once, which keeps AVX2's sixteen registers from spilling.
  const auto width = hn::Set(di, l.width);
  const auto b00 = hn::Or(hn::Or(bi0, bj0), bk), b10 = hn::Or(hn::Or(bi1, bj0), bk);
  const auto b01 = hn::Or(hn::Or(bi0, bj1), bk), b11 = hn::Or(hn::Or(bi1, bj1), bk);
  const DB db;
  if (hn::AllTrue(di, hn::And(hn::And(b00, b10), hn::And(b01, b11)))) {
    // Every lane's four texels are the border (GL_CLAMP_TO_BORDER's outside; GL_CLAMP's always
    // takes an edge texel too): the same lerps of the border colour, nothing read.
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) {
      const VB border = hn::Set(db, tp.border[c]);
      out[c] = lerp(lerp(border, border, a), lerp(border, border, a), b);
    }
    return;
  }
  hn::Vec<DUB> w00, w10, w01, w11;
  texel_words(l, hn::Mul(j0, width), i0, b00, i1, b10, w00, w10);
  texel_words(l, hn::Mul(j1, width), i0, b01, i1, b11, w01, w11);
  const bool any_border = !hn::AllFalse(di, hn::Or(hn::Or(b00, b10), hn::Or(b01, b11)));
  #pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) {
    VB t00 = channel(w00, c), t10 = channel(w10, c), t01 = channel(w01, c), t11 = channel(w11, c);
    if (any_border) {
      const VB border = hn::Set(db, tp.border[c]);
      t00 = hn::IfThenElse(hn::RebindMask(db, b00), border, t00);
      t10 = hn::IfThenElse(hn::RebindMask(db, b10), border, t10);
      t01 = hn::IfThenElse(hn::RebindMask(db, b01), border, t01);
      t11 = hn::IfThenElse(hn::RebindMask(db, b11), border, t11);
    }
    out[c] = lerp(lerp(t00, t10, a), lerp(t01, t11, a), b);
  }
}

/// texture.cpp's nearest_index: the clamps and mirrored repeat (u >= 0 there) keep a nearest
/// index in the level; repeat wraps it and clamp to border takes the border outside.
HWY_INLINE bool keeps_nearest_in_level(TextureWrap w) {
  return w != TextureWrap::kRepeat && w != TextureWrap::kClampToBorder;
}

/// One level's filtered texels in byte units (texture.cpp's sample_level): `linear` lanes
/// blend four texels (two for 1D textures), the others take the nearest; the nearest reads
/// the border only with clamp to border.
template <bool k2D = false>
HWY_INLINE void sample_level(const TexturePlan& tp, int level, VB s, VB t, VB r, MB linear, VB out[4]) {
  if (is_depth<k2D>(tp)) r = hn::Min(hn::Max(r, hn::Zero(DB())), hn::Set(DB(), 1.0f));  // texture.cpp's ref
  const DB db;
  const DIB di;
  const TextureLevel& l = tp.texture->levels[std::size_t(level)];
  const VB u = texel_coord(s, l.width, tp.wrap_s);
  const VB v = is_1d<k2D>(tp) ? hn::Zero(db) : texel_coord(t, l.height, tp.wrap_t);
  const VB w = is_3d<k2D>(tp) ? texel_coord(r, l.depth, tp.wrap_r) : hn::Zero(db);
  const bool any_linear = !hn::AllFalse(db, linear), all_linear = hn::AllTrue(db, linear);
  hn::Vec<DIB> i, j, k = is_cube<k2D>(tp) ? truncate_in_range(r) : hn::Zero(di);  // a cube map's r: the face
  if (!all_linear) {  // nearest: floor, clamped by the clamps (repeat's size wraps to 0)
    i = truncate_in_range(hn::Floor(u));
    j = is_1d<k2D>(tp) ? hn::Zero(di) : truncate_in_range(hn::Floor(v));
    if (keeps_nearest_in_level(tp.wrap_s)) i = hn::Min(i, hn::Set(di, l.width - 1));
    if (keeps_nearest_in_level(tp.wrap_t)) j = hn::Min(j, hn::Set(di, l.height - 1));
    if (is_3d<k2D>(tp)) {
      k = truncate_in_range(hn::Floor(w));
      if (keeps_nearest_in_level(tp.wrap_r)) k = hn::Min(k, hn::Set(di, l.depth - 1));
    }
  }
  if (!any_linear) return fetch<k2D>(tp, l, i, j, k, out, r);
  const VB uu = hn::Sub(u, hn::Set(db, 0.5f)), vv = hn::Sub(v, hn::Set(db, 0.5f));
  const VB fu = hn::Floor(uu), fv = hn::Floor(vv);
  const auto li = hn::RebindMask(di, linear);
  i = all_linear ? truncate_in_range(fu) : hn::IfThenElse(li, truncate_in_range(fu), i);
  if (is_1d<k2D>(tp)) j = hn::Zero(di);  // 1D: one row, whatever the filter
  else j = all_linear ? truncate_in_range(fv) : hn::IfThenElse(li, truncate_in_range(fv), j);
  const VB a = hn::IfThenElseZero(linear, hn::Sub(uu, fu)), b = hn::IfThenElseZero(linear, hn::Sub(vv, fv));
  const auto one = hn::Set(di, 1);
  if (is_1d<k2D>(tp)) {
    VB c00[4], c10[4];
    fetch<k2D>(tp, l, i, j, k, c00, r);
    fetch<k2D>(tp, l, hn::Add(i, one), j, k, c10, r);
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) out[c] = lerp(c00[c], c10[c], a);
    return;
  }
  if (!is_3d<k2D>(tp)) return bilinear_slice<k2D>(tp, l, i, j, k, a, b, r, out);
  const VB ww = hn::Sub(w, hn::Set(db, 0.5f)), fw = hn::Floor(ww);
  k = all_linear ? truncate_in_range(fw) : hn::IfThenElse(li, truncate_in_range(fw), k);
  const VB cw = hn::IfThenElseZero(linear, hn::Sub(ww, fw));
  VB near[4], far[4];
  bilinear_slice<k2D>(tp, l, i, j, k, a, b, r, near);
  bilinear_slice<k2D>(tp, l, i, j, hn::Add(k, one), a, b, r, far);
  #pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) out[c] = lerp(near[c], far[c], cw);
}

/// The levels the `live` lanes sample, from `first` to `last` (a lane's lower and upper ones).
HWY_INLINE void level_range(const LevelChoice& c, hn::Mask<DIB> live, int& first, int& last) {
  const DIB di;
  first = hn::GetLane(hn::MinOfLanes(di, hn::IfThenElse(live, c.lo, hn::Set(di, 1 << 20))));
  last = hn::GetLane(hn::MaxOfLanes(di, hn::IfThenElse(live, c.hi, hn::Set(di, -1))));
}

/// texture.cpp's round_to_int (cvtps2dq): nearest, ties to even; outside the int range and NaN
/// the integer indefinite (x86's conversion itself; elsewhere its result made).
HWY_INLINE hn::Vec<DIB> round_to_int(VB x) {
#if HWY_TARGET <= HWY_AVX3
  return hn::Vec<DIB>{_mm512_cvtps_epi32(x.raw)};
#elif HWY_TARGET == HWY_AVX2
  return hn::Vec<DIB>{_mm256_cvtps_epi32(x.raw)};
#elif HWY_TARGET == HWY_SSE4 || HWY_TARGET == HWY_SSSE3
  return hn::Vec<DIB>{_mm_cvtps_epi32(x.raw)};
#else
  const DB db;
  const DIB di;
  const MB inside = hn::And(hn::Ge(x, hn::Set(db, -2147483648.0f)), hn::Lt(x, hn::Set(db, 2147483648.0f)));
  const auto indefinite = hn::Set(di, std::numeric_limits<std::int32_t>::min());
  return hn::IfThenElse(hn::RebindMask(di, inside), hn::NearestInt(hn::IfThenElseZero(inside, x)), indefinite);
#endif
}

/// texture.cpp's fixed_taps: the 8-bit filter's two texels along an axis of `size` texels and
/// the second's weight in 256ths.
HWY_INLINE void fixed_taps(VB s, int size, TextureWrap wrap, bool pot, hn::Vec<DIB>& i0, hn::Vec<DIB>& i1,
                           hn::Vec<DIB>& weight) {
  const DB db;
  const DIB di;
  const bool npot_repeat = wrap == TextureWrap::kRepeat && !pot;
  const VB scaled = hn::Mul(npot_repeat ? hn::Sub(s, hn::Floor(s)) : s, hn::Set(db, float(size)));
  const auto fixed = hn::Sub(round_to_int(hn::Mul(scaled, hn::Set(db, 256.0f))), hn::Set(di, 128));
  const auto i = hn::ShiftRight<8>(fixed), last = hn::Set(di, size - 1);
  weight = hn::And(fixed, hn::Set(di, 255));
  if (wrap == TextureWrap::kClampToEdge) {
    i0 = hn::Min(hn::Max(i, hn::Zero(di)), last);
    i1 = hn::Min(hn::Max(hn::Add(i, hn::Set(di, 1)), hn::Zero(di)), last);
  } else if (pot) {
    i0 = hn::And(i, last), i1 = hn::And(hn::Add(i, hn::Set(di, 1)), last);
  } else {
    i0 = hn::Min(hn::IfThenElse(hn::Lt(i, hn::Zero(di)), last, i), last);
    i1 = hn::IfThenZeroElse(hn::Eq(i0, last), hn::Add(i0, hn::Set(di, 1)));
  }
}

// RGBA8 texels between the 8-bit filter's lerps: each byte kept in a 16-bit lane, red and blue
// in the halves of one 32-bit lane, green and alpha in another's, so that one operation serves
// two channels (the scalar target: a 32-bit lane a channel). Weights in 256ths, per lane.
#if HWY_TARGET == HWY_SCALAR
struct Bytes8 {
  hn::Vec<DIB> c[4];
};
using Weight8 = hn::Vec<DIB>;
HWY_INLINE Weight8 weight8(hn::Vec<DIB> w) { return w; }
HWY_INLINE Bytes8 unpack8(hn::Vec<DUB> words) {
  Bytes8 b;
  for (int c = 0; c < 4; ++c) b.c[c] = hn::BitCast(DIB(), hn::And(hn::ShiftRightSame(words, 8 * c), hn::Set(DUB(), 0xffu)));
  return b;
}
HWY_INLINE Bytes8 lerp8(const Bytes8& a, const Bytes8& b, Weight8 w) {
  const DIB di;
  Bytes8 r;
  for (int c = 0; c < 4; ++c) {
    r.c[c] = hn::Add(a.c[c], hn::ShiftRight<8>(hn::Add(hn::Mul(w, hn::Sub(b.c[c], a.c[c])), hn::Set(di, 128))));
  }
  return r;
}
HWY_INLINE Bytes8 select8(hn::Mask<DUB> m, const Bytes8& a, const Bytes8& b) {
  Bytes8 r;
  for (int c = 0; c < 4; ++c) r.c[c] = hn::IfThenElse(hn::RebindMask(DIB(), m), a.c[c], b.c[c]);
  return r;
}
HWY_INLINE void bytes_to_float(const Bytes8& v, VB out[4]) {
  for (int c = 0; c < 4; ++c) out[c] = hn::ConvertTo(DB(), v.c[c]);
}
HWY_INLINE hn::Vec<DUB> bytes_to_words(const Bytes8& v) {
  hn::Vec<DUB> word = hn::Zero(DUB());
  for (int c = 0; c < 4; ++c) word = hn::Or(word, hn::ShiftLeftSame(hn::BitCast(DUB(), v.c[c]), 8 * c));
  return word;
}
#else
using DW = hn::Repartition<std::uint16_t, DUB>;
struct Bytes8 {
  hn::Vec<DW> rb, ga;
};
using Weight8 = hn::Vec<DW>;
HWY_INLINE Weight8 weight8(hn::Vec<DIB> w) {
  const auto u = hn::BitCast(DUB(), w);
  return hn::BitCast(DW(), hn::Or(u, hn::ShiftLeft<16>(u)));
}
HWY_INLINE Bytes8 unpack8(hn::Vec<DUB> words) {
  const auto bytes = hn::Set(DUB(), 0x00ff00ffu);
  return {hn::BitCast(DW(), hn::And(words, bytes)), hn::BitCast(DW(), hn::And(hn::ShiftRight<8>(words), bytes))};
}
/// texture.cpp's lerp8 in 16-bit lanes: the products wrap at 16 bits, and the bits they keep
/// hold the byte the rounded quotient adds, modulo 256; the result is a byte.
HWY_INLINE Bytes8 lerp8(const Bytes8& a, const Bytes8& b, Weight8 w) {
  const DW dw;
  auto lerp = [&](hn::Vec<DW> x, hn::Vec<DW> y) {
    const auto p = hn::Add(hn::Mul(hn::Sub(y, x), w), hn::Set(dw, 128));
    return hn::And(hn::Add(x, hn::ShiftRight<8>(p)), hn::Set(dw, 0xff));
  };
  return {lerp(a.rb, b.rb), lerp(a.ga, b.ga)};
}
HWY_INLINE Bytes8 select8(hn::Mask<DUB> m, const Bytes8& a, const Bytes8& b) {
  const DUB du;
  auto pick = [&](hn::Vec<DW> x, hn::Vec<DW> y) {
    return hn::BitCast(DW(), hn::IfThenElse(m, hn::BitCast(du, x), hn::BitCast(du, y)));
  };
  return {pick(a.rb, b.rb), pick(a.ga, b.ga)};
}
HWY_INLINE void bytes_to_float(const Bytes8& v, VB out[4]) {
  const DUB du;
  const DIB di;
  const auto low = hn::Set(du, 0xffffu);
  const auto rb = hn::BitCast(du, v.rb), ga = hn::BitCast(du, v.ga);
  out[0] = hn::ConvertTo(DB(), hn::BitCast(di, hn::And(rb, low)));
  out[1] = hn::ConvertTo(DB(), hn::BitCast(di, hn::And(ga, low)));
  out[2] = hn::ConvertTo(DB(), hn::BitCast(di, hn::ShiftRight<16>(rb)));
  out[3] = hn::ConvertTo(DB(), hn::BitCast(di, hn::ShiftRight<16>(ga)));
}
/// The RGBA8 words of bytes (unpack8's inverse).
HWY_INLINE hn::Vec<DUB> bytes_to_words(const Bytes8& v) {
  const DUB du;
  return hn::Or(hn::BitCast(du, v.rb), hn::ShiftLeft<8>(hn::BitCast(du, v.ga)));
}
#endif

/// One image of a level (a 2D level, a 3D level's image, a cube map's face) filtered by the
/// 8-bit sampler at taps (i0, i1) across and (j0, j1) down: a function, not a lambda, so that
/// it is inlined (a lambda called twice is a call, its vectors spilled around it).
template <bool k2D = false>
HWY_INLINE Bytes8 bilinear_bytes(const TexturePlan& tp, const TextureLevel& l, hn::Vec<DIB> image, hn::Vec<DIB> i0,
                                 hn::Vec<DIB> i1, hn::Vec<DIB> j0, hn::Vec<DIB> j1, Weight8 across, Weight8 down) {
  const DIB di;
  const hn::Mask<DIB> none = hn::FirstN(di, 0);
  const auto width = hn::Set(di, l.width);
  const auto base = hn::Mul(image, hn::Set(di, l.height));
  hn::Vec<DUB> t00, t10, t01, t11;
  texel_words(l, hn::Mul(hn::Add(base, j0), width), i0, none, i1, none, t00, t10);
  const Bytes8 top = lerp8(unpack8(t00), unpack8(t10), across);
  if (is_1d<k2D>(tp)) return top;
  texel_words(l, hn::Mul(hn::Add(base, j1), width), i0, none, i1, none, t01, t11);
  return lerp8(top, lerp8(unpack8(t01), unpack8(t11), across), down);
}

/// sample_level's nearest index along an axis of `size` texels, wrapped as fetch wraps it (the
/// 8-bit sampler's wrap modes never take the border).
HWY_INLINE hn::Vec<DIB> nearest_index(VB c, int size, TextureWrap wrap) {
  const DIB di;
  hn::Mask<DIB> unused = hn::FirstN(di, 0);
  const auto i = truncate_in_range(hn::Floor(texel_coord(c, size, wrap)));
  return wrap_index(keeps_nearest_in_level(wrap) ? hn::Min(i, hn::Set(di, size - 1)) : i, size, wrap, unused);
}

/// One level's texels filtered by the 8-bit sampler (texture.cpp's sample_level where
/// eight_bit_filtering holds): `linear` lanes by fixed_taps and lerp8 along s, t and r, the
/// others the nearest texel (sample_level's index, wrapped by repeat or clamp to edge).
template <bool k2D = false>
HWY_INLINE Bytes8 sample_level_bytes(const TexturePlan& tp, int level, VB s, VB t, VB r, MB linear) {
  const DB db;
  const DIB di;
  const DUB du;
  const TextureLevel& l = tp.texture->levels[std::size_t(level)];
  const bool any_linear = !hn::AllFalse(db, linear), all_linear = hn::AllTrue(db, linear);
  const auto face = is_cube<k2D>(tp) ? truncate_in_range(r) : hn::Zero(di);  // a cube map's r: the face
  Bytes8 nearest;
  if (!all_linear) {  // sample_level's nearest index, wrapped as fetch wraps it
    const auto i = nearest_index(s, l.width, tp.wrap_s);
    auto row = is_1d<k2D>(tp) ? hn::Zero(di) : nearest_index(t, l.height, tp.wrap_t);
    if (is_3d<k2D>(tp)) row = hn::Add(hn::Mul(nearest_index(r, l.depth, tp.wrap_r), hn::Set(di, l.height)), row);
    else if (is_cube<k2D>(tp)) row = hn::Add(hn::Mul(face, hn::Set(di, l.height)), row);
    const auto* words = reinterpret_cast<const std::uint32_t*>(l.rgba.data());
    nearest = unpack8(gather_words(words, hn::Add(hn::Mul(row, hn::Set(di, l.width)), i)));
    if (!any_linear) return nearest;
  }
  hn::Vec<DIB> i0, i1, wi, j0 = hn::Zero(di), j1 = j0, wj = j0;
  fixed_taps(s, l.width, tp.wrap_s, tp.pot_s, i0, i1, wi);
  if (!is_1d<k2D>(tp)) fixed_taps(t, l.height, tp.wrap_t, tp.pot_t, j0, j1, wj);
  const Weight8 across = weight8(wi), down = weight8(wj);
  Bytes8 out;
  if (is_3d<k2D>(tp)) {
    hn::Vec<DIB> k0, k1, wk;
    fixed_taps(r, l.depth, tp.wrap_r, tp.pot_r, k0, k1, wk);
    out = lerp8(bilinear_bytes<k2D>(tp, l, k0, i0, i1, j0, j1, across, down),
                bilinear_bytes<k2D>(tp, l, k1, i0, i1, j0, j1, across, down), weight8(wk));
  } else {
    out = bilinear_bytes<k2D>(tp, l, face, i0, i1, j0, j1, across, down);
  }
  return all_linear ? out : select8(hn::RebindMask(du, linear), out, nearest);
}

/// sample_texture's levels for the 8-bit sampler, blended between two levels in 256ths (the
/// fraction truncated, texture.cpp's sample_texture_bytes).
template <bool k2D = false>
HWY_INLINE Bytes8 sample_bytes(const TexturePlan& tp, VB s, VB t, VB r, const QuadDerivatives* d, MB live) {
  const DB db;
  const DIB di;
  const DUB du;
  if (!d) return sample_level_bytes<k2D>(tp, tp.base_level, s, t, r, filter_mask(tp.mag_linear));
  const LevelChoice c = choose_levels<k2D>(tp, *d);
  const auto live_i = hn::RebindMask(di, live);
  int first, last;
  level_range(c, live_i, first, last);
  Bytes8 lo = unpack8(hn::Zero(du)), hi = lo;
  for (int level = first; level <= last; ++level) {
    const auto is_lo = hn::Eq(c.lo, hn::Set(di, level)), is_hi = hn::Eq(c.hi, hn::Set(di, level));
    if (hn::AllFalse(di, hn::And(live_i, hn::Or(is_lo, is_hi)))) continue;
    const Bytes8 texel = sample_level_bytes<k2D>(tp, level, s, t, r, c.linear);
    lo = level == first ? texel : select8(hn::RebindMask(du, is_lo), texel, lo);
    hi = level == first ? texel : select8(hn::RebindMask(du, is_hi), texel, hi);
  }
  if (!c.two_levels) return lo;
  return lerp8(lo, hi, weight8(truncate_in_range(hn::Mul(c.frac, hn::Set(db, 256.0f)))));
}

/// The filtered texel of every `live` lane in [0, 1] (sample_texture): the levels each lane
/// needs sampled one level at a time, then blended.
template <bool k2D = false>
HWY_INLINE void sample_texture(const TexturePlan& tp, VB s, VB t, VB r, const QuadDerivatives* d, MB live, VB out[4]) {
  const DB db;
  const DIB di;
  if (tp.eight_bit) {
    bytes_to_float(sample_bytes<k2D>(tp, s, t, r, d, live), out);
  } else if (!d) {  // one level, one filter for every lane
    sample_level<k2D>(tp, tp.base_level, s, t, r, filter_mask(tp.mag_linear), out);
  } else {
    const LevelChoice c = choose_levels<k2D>(tp, *d);
    const auto live_i = hn::RebindMask(di, live);
    int first, last;
    level_range(c, live_i, first, last);
    VB lo[4] = {hn::Zero(db), hn::Zero(db), hn::Zero(db), hn::Zero(db)}, hi[4] = {lo[0], lo[1], lo[2], lo[3]};
    for (int level = first; level <= last; ++level) {
      const auto is_lo = hn::Eq(c.lo, hn::Set(di, level)), is_hi = hn::Eq(c.hi, hn::Set(di, level));
      if (hn::AllFalse(di, hn::And(live_i, hn::Or(is_lo, is_hi)))) continue;
      VB texel[4];
      sample_level<k2D>(tp, level, s, t, r, c.linear, texel);
      const MB lo_mask = hn::RebindMask(db, is_lo), hi_mask = hn::RebindMask(db, is_hi);
      #pragma GCC unroll 4
      for (int k = 0; k < 4; ++k) {
        lo[k] = level == first ? texel[k] : hn::IfThenElse(lo_mask, texel[k], lo[k]);
        hi[k] = level == first ? texel[k] : hn::IfThenElse(hi_mask, texel[k], hi[k]);
      }
    }
    #pragma GCC unroll 4
    for (int k = 0; k < 4; ++k) out[k] = c.two_levels ? lerp(lo[k], hi[k], c.frac) : lo[k];
  }
  #pragma GCC unroll 4
  for (int k = 0; k < 4; ++k) out[k] = hn::Mul(out[k], hn::Set(db, 1.0f / 255.0f));
}

/// A block's texture coordinates (s, t, r) as the samplers take them.
struct BlockCoords {
  VB s, t, r;
  QuadDerivatives d;  // where the texture needs a level of detail: `lod`
  bool lod;           // TexturePlan::lod, unless the triangle is magnified everywhere
};

/// The block's coordinates on texture unit `unit` (on a cube map's face), as sample_block
/// samples them.
template <bool k2D = false>
HWY_INLINE BlockCoords block_coords(const DrawJob& job, int unit, const TriSetup& t, const TexcoordPlanes& planes,
                                    const Weights& w, int x, int y, const VD e[kRows][3]) {
  const DB db;
  const TexturePlan& tp = job.plan.texture[unit];
  BlockCoords c;
  c.r = hn::Zero(db);
  project(db, planes, w.f0, w.f1, c.s, c.t, c.r);
  c.lod = tp.lod && !planes.magnified;
  if (c.lod) {
    c.d = kRows == 2 && job.fb->height % 2 == 0 ? quad_derivatives_in_block(c.s, c.t, c.r, planes.with_r)
                                                : quad_derivatives_anywhere(job, t, planes, x, y, e);
  }
  if (is_cube<k2D>(tp)) cube_face(c.s, c.t, c.r);
  return c;
}

/// The filtered texels of texture unit `unit` for the block's fragments, at each lane's
/// coordinates. `e` are the rows' edge values, `w` their perspective weights; `live` the lanes
/// whose colour is used.
template <bool k2D = false>
HWY_INLINE void sample_block(const DrawJob& job, int unit, const TriSetup& t, const TexcoordPlanes& planes,
                             const Weights& w, int x, int y, const VD e[kRows][3], MB live, VB texel[4]) {
  const TexturePlan& tp = job.plan.texture[unit];
  const BlockCoords c = block_coords<k2D>(job, unit, t, planes, w, x, y, e);
  sample_texture<k2D>(tp, c.s, c.t, c.r, c.lod ? &c.d : nullptr, live, texel);
}

/// sample_block's texels as RGBA8 words, for a texture the 8-bit sampler filters
/// (TexturePlan::eight_bit): its bytes, before they are made floats.
template <bool k2D = false>
HWY_INLINE hn::Vec<DUB> sample_block_words(const DrawJob& job, int unit, const TriSetup& t, const TexcoordPlanes& planes,
                                           const Weights& w, int x, int y, const VD e[kRows][3], MB live) {
  const TexturePlan& tp = job.plan.texture[unit];
  const BlockCoords c = block_coords<k2D>(job, unit, t, planes, w, x, y, e);
  return bytes_to_words(sample_bytes<k2D>(tp, c.s, c.t, c.r, c.lod ? &c.d : nullptr, live));
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SHADELAB_FAST_TEXTURE_INL_H_
