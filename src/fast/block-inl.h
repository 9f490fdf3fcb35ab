// The shape of the fast rasterizer's SIMD work: a block of two rows of pixels (as many per row
// as the target has double lanes) held in one float vector, masks to and from bits, rows
// loaded and stored, and the perspective-correct weights of a block's pixels. Shared by the
// fragment operations (fragment-inl.h) and the samplers (texture-inl.h). Per-target code
// (Highway).
#if defined(SHADELAB_FAST_BLOCK_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SHADELAB_FAST_BLOCK_INL_H_
#undef SHADELAB_FAST_BLOCK_INL_H_
#else
#define SHADELAB_FAST_BLOCK_INL_H_
#endif

#include <cstdint>

#include "fast/triangle.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DD = hn::ScalableTag<double>;
using DF = hn::Rebind<float, DD>;          // one float per double lane: one row of a block
using DU = hn::Rebind<std::uint32_t, DD>;  // one RGBA8 pixel per lane
using VD = hn::Vec<DD>;
using VF = hn::Vec<DF>;

// A block's rows side by side in one vector, row 0 in the lower lanes (one row on the scalar
// target, whose vectors have one lane).
#if HWY_TARGET == HWY_SCALAR
inline constexpr int kRows = 1;
template <class DH>
using Block = DH;
#else
inline constexpr int kRows = 2;
template <class DH>
using Block = hn::Twice<DH>;
#endif
using DB = Block<DF>;
using DUB = Block<DU>;
using DIB = hn::RebindToSigned<DUB>;
using VB = hn::Vec<DB>;
using MB = hn::Mask<DB>;

/// One row per half: row 0 low, row 1 high.
template <class DH>
HWY_INLINE hn::Vec<Block<DH>> join_rows(DH dh, hn::Vec<DH> row0, hn::Vec<DH> row1) {
  (void)dh;
#if HWY_TARGET == HWY_SCALAR
  (void)row1;
  return row0;
#else
  return hn::Combine(Block<DH>(), row1, row0);
#endif
}

template <class DH>
HWY_INLINE hn::Vec<DH> row_of(DH dh, hn::Vec<Block<DH>> v, int r) {
#if HWY_TARGET == HWY_SCALAR
  (void)dh, (void)r;
  return v;
#else
  return r == 0 ? hn::LowerHalf(dh, v) : hn::UpperHalf(dh, v);
#endif
}

/// Bit `r * Lanes(DD) + i` of a block's bits is lane i of row r.
HWY_INLINE unsigned row_bits(unsigned bits, int r) {
  const unsigned lanes = unsigned(hn::Lanes(DD()));
  return (bits >> (unsigned(r) * lanes)) & ((1u << lanes) - 1u);
}

// Masks from and to bits. AVX-512 masks are bit registers: taken as they are, without the
// round trip through bytes in memory that LoadMaskBits / StoreMaskBits take.
template <class D>
HWY_INLINE hn::Mask<D> mask_of_bits(D d, unsigned bits) {
#if HWY_TARGET <= HWY_AVX3
  (void)d;
  return hn::Mask<D>{static_cast<decltype(hn::Mask<D>().raw)>(bits)};
#else
  const std::uint8_t bytes[8] = {std::uint8_t(bits), std::uint8_t(bits >> 8)};
  return hn::LoadMaskBits(d, bytes);
#endif
}

HWY_INLINE MB block_mask(unsigned bits) { return mask_of_bits(DB(), bits); }

template <class D>
HWY_INLINE unsigned bits_of_mask(D d, hn::Mask<D> m) {
#if HWY_TARGET <= HWY_AVX3
  (void)d;
  return unsigned(m.raw);
#else
  std::uint8_t bytes[8] = {};
  hn::StoreMaskBits(d, m, bytes);
  return unsigned(bytes[0]) | unsigned(bytes[1]) << 8;
#endif
}

HWY_INLINE unsigned block_bits(MB m) { return bits_of_mask(DB(), m); }

/// The rows of a block from memory (each row's own address).
template <class DH, typename T>
HWY_INLINE hn::Vec<Block<DH>> load_rows(DH dh, T* const rows[kRows]) {
  return join_rows(dh, hn::LoadU(dh, rows[0]), hn::LoadU(dh, rows[kRows - 1]));
}

/// Stores the lanes set in `bits` of each row.
template <class DH, typename T>
HWY_INLINE void store_rows(DH dh, hn::Vec<Block<DH>> v, unsigned bits, T* const rows[kRows]) {
#if HWY_TARGET <= HWY_AVX3
  // Masks are registers here: both rows stored under theirs, without branches on the bits
  // (which a partly covered block's pattern makes hard to predict).
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) hn::BlendedStore(row_of(dh, v, r), mask_of_bits(dh, row_bits(bits, r)), dh, rows[r]);
#else
  // Masks are built from bytes in memory here: whole rows (the interior of a triangle) are
  // stored plainly, and empty rows not at all.
  constexpr unsigned kAll = (1u << (kRows * hn::MaxLanes(DD()))) - 1u;
  if (bits == kAll && hn::Lanes(DD()) == hn::MaxLanes(DD())) {
    #pragma GCC unroll 4
    for (int r = 0; r < kRows; ++r) hn::StoreU(row_of(dh, v, r), dh, rows[r]);
    return;
  }
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) {
    std::uint8_t b = std::uint8_t(row_bits(bits, r));
    if (b) hn::BlendedStore(row_of(dh, v, r), mask_of_bits(dh, b), dh, rows[r]);
  }
#endif
}

/// A block's barycentric weights: b0, b1 of each row in doubles (exact_varying reads them),
/// and the normalized perspective weights q0, q1 of the whole block in floats
/// (reference_raster.inl's q0, q1: q_i = b_i / w_i, divided by their sum).
struct Weights {
  VD b0[kRows], b1[kRows];
  VB f0, f1;
};

/// The float weights: b0, b1 rounded to float (f0, f1, which depth also reads), then (affine
/// triangles aside) the perspective division in floats over the whole block: one float
/// division where the reference's double arithmetic takes one per row. They differ from the
/// reference's by a few float roundings, as the varyings computed from them already do
/// (Plane).
HWY_INLINE Weights perspective_weights(const TriSetup& t, const VD b0[kRows], const VD b1[kRows], VB f0,
                                       VB f1) {
  const DB db;
  Weights w;
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) w.b0[r] = b0[r], w.b1[r] = b1[r];
  if (t.affine) {
    w.f0 = f0, w.f1 = f1;
    return w;
  }
  const VB f2 = hn::Sub(hn::Sub(hn::Set(db, 1.0f), f0), f1);
  const VB q0 = hn::Mul(f0, hn::Set(db, t.v[0]->inv_w));
  const VB q1 = hn::Mul(f1, hn::Set(db, t.v[1]->inv_w));
  const VB q2 = hn::Mul(f2, hn::Set(db, t.v[2]->inv_w));
  const VB inv = hn::Div(hn::Set(db, 1.0f), hn::Add(hn::Add(q0, q1), q2));
  w.f0 = hn::Mul(q0, inv), w.f1 = hn::Mul(q1, inv);
  return w;
}

/// trunc(x) as an integer lane for x known to be within the int32 range (texel coordinates,
/// levels, weights): x86's truncating conversion itself, without the four operations that
/// ConvertTo adds for values that overflow.
HWY_INLINE hn::Vec<DIB> truncate_in_range(VB x) {
#if HWY_TARGET <= HWY_AVX3
  return hn::Vec<DIB>{_mm512_cvttps_epi32(x.raw)};
#elif HWY_TARGET == HWY_AVX2
  return hn::Vec<DIB>{_mm256_cvttps_epi32(x.raw)};
#elif HWY_TARGET == HWY_SSE4 || HWY_TARGET == HWY_SSSE3
  return hn::Vec<DIB>{_mm_cvttps_epi32(x.raw)};
#else
  return hn::ConvertTo(DIB(), x);
#endif
}

/// Byte `c` of each RGBA8 word as a float (0 to 255).
HWY_INLINE VB channel(hn::Vec<DUB> px, int c) {
  const DUB dub;
  hn::Vec<DUB> v = hn::And(hn::ShiftRightSame(px, 8 * c), hn::Set(dub, 0xffu));
  return hn::ConvertTo(DB(), hn::BitCast(DIB(), v));
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SHADELAB_FAST_BLOCK_INL_H_
