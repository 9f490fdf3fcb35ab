// Texturing on the SIMD path, for one block of a triangle: the texture coordinates in the
// float arithmetic of raster/texcoord.hpp, llvmpipe's level of detail per 2x2 quad, texels
// gathered from the RGBA8 levels and filtered, and the texture environment. Each step is the
// reference's (texture.cpp's sample_texture_bytes, apply_texture_env) operation by operation,
// without fused multiply-adds, so that every target samples the texels the reference samples
// and gives its colours bit for bit. Per-target code (Highway).
#if defined(SHADELAB_FAST_TEXTURE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SHADELAB_FAST_TEXTURE_INL_H_
#undef SHADELAB_FAST_TEXTURE_INL_H_
#else
#define SHADELAB_FAST_TEXTURE_INL_H_
#endif

#include <algorithm>
#include <cstdint>

#include "fast/block-inl.h"
#include "fast/triangle.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

/// A triangle's texture coordinates s, t, q and r (r sampled by 3D textures only): value at
/// vertex 2 and the differences from it to vertices 0 and 1 (texcoord.hpp's texcoord_plane).
/// `unit_q`: q is 1 at every vertex, so its plane is 1 wherever the weights are finite.
struct TexcoordPlanes {
  float base[4], d0[4], d1[4];
  bool unit_q;
  bool with_r;  // a 3D texture: r is projected too
};

HWY_INLINE TexcoordPlanes texcoord_planes(const DrawJob& job, const TriSetup& t, int unit) {
  static constexpr int kSlot[4] = {0, 1, 3, 2};  // s, t, q, r
  const int first = job.plan.layout.texcoord[unit];
  TexcoordPlanes p;
  p.with_r = job.plan.texture[unit].three_d || job.plan.texture[unit].cube || job.plan.texture[unit].depth_texture;
  for (int i = 0; i < 4; ++i) {
    const int k = first + kSlot[i];
    const float a0 = t.var[0][k], a1 = t.var[1][k], a2 = t.var[2][k];
    p.base[i] = a2, p.d0[i] = a0 - a2, p.d1[i] = a1 - a2;
  }
  p.unit_q = p.base[2] == 1.0f && p.d0[2] == 0.0f && p.d1[2] == 0.0f;
  return p;
}

/// texcoord.hpp's float_weights for lanes of any width: the screen weights f0, f1 (rounded to
/// float) made perspective-correct (perspective_weights, for rows the block does not hold).
template <class D>
HWY_INLINE void float_weights(D d, const TriSetup& t, hn::Vec<D> f0, hn::Vec<D> f1, hn::Vec<D>& p0, hn::Vec<D>& p1) {
  if (t.affine) {
    p0 = f0, p1 = f1;
    return;
  }
  const auto f2 = hn::Sub(hn::Sub(hn::Set(d, 1.0f), f0), f1);
  const auto q0 = hn::Mul(f0, hn::Set(d, t.v[0]->inv_w));
  const auto q1 = hn::Mul(f1, hn::Set(d, t.v[1]->inv_w));
  const auto q2 = hn::Mul(f2, hn::Set(d, t.v[2]->inv_w));
  const auto inv = hn::Div(hn::Set(d, 1.0f), hn::Add(hn::Add(q0, q1), q2));
  p0 = hn::Mul(q0, inv), p1 = hn::Mul(q1, inv);
}

/// finite_texcoord: NaN to 0, magnitudes kept below 2^20.
template <class D>
HWY_INLINE hn::Vec<D> finite_coord(D d, hn::Vec<D> v) {
  const auto limit = hn::Set(d, 1048576.0f), minus = hn::Set(d, -1048576.0f);
  const auto below = hn::IfThenElse(hn::Lt(v, limit), v, limit);
  return hn::IfThenElse(hn::Gt(v, minus), below, hn::IfThenElseZero(hn::Eq(v, v), minus));
}

/// (s / q, t / q, r / q) at weights p0, p1, made finite (texcoord.hpp's project_texcoord); r
/// only for a 3D texture (else left as it is). Where q is 1 at every vertex its plane is
/// exactly 1 and the quotients the coordinates themselves, but where a weight is not finite
/// (outside the triangle, past the horizon): NaN there, as the plane's p * 0 and the quotient
/// give.
template <class D>
HWY_INLINE void project(D d, const TexcoordPlanes& tp, hn::Vec<D> p0, hn::Vec<D> p1, hn::Vec<D>& s, hn::Vec<D>& t,
                        hn::Vec<D>& r) {
  hn::Vec<D> c[4];
  auto plane = [&](int i) {
    return hn::Add(hn::Add(hn::Set(d, tp.base[i]), hn::Mul(p0, hn::Set(d, tp.d0[i]))), hn::Mul(p1, hn::Set(d, tp.d1[i])));
  };
  c[0] = plane(0), c[1] = plane(1);
  if (tp.with_r) c[3] = plane(3);
  if (tp.unit_q) {
    const auto finite = hn::And(hn::IsFinite(p0), hn::IsFinite(p1));
    const auto nan = hn::Set(d, __builtin_nanf(""));
    s = finite_coord(d, hn::IfThenElse(finite, c[0], nan));
    t = finite_coord(d, hn::IfThenElse(finite, c[1], nan));
    if (tp.with_r) r = finite_coord(d, hn::IfThenElse(finite, c[3], nan));
    return;
  }
  c[2] = plane(2);
  s = finite_coord(d, hn::Div(c[0], c[2]));
  t = finite_coord(d, hn::Div(c[1], c[2]));
  if (tp.with_r) r = finite_coord(d, hn::Div(c[3], c[2]));
}

/// The level-of-detail differences of each lane's quad (TextureDerivatives; r's for 3D
/// textures only).
struct QuadDerivatives {
  VB ds_dx, dt_dx, ds_dy, dt_dy, dr_dx, dr_dy;
  VB s, t, r;  // the quad's top-left (s, t, r), for cube maps (TextureDerivatives)
};

/// Where the block's two rows are one of llvmpipe's quads (an even framebuffer height: its
/// quads are GL rows 2k and 2k + 1, a block's rows): the differences come from the block's own
/// lanes, the top row (row 1) and its pairs of columns.
HWY_INLINE QuadDerivatives quad_derivatives_in_block(VB s, VB t, VB r, bool with_r) {
#if HWY_TARGET == HWY_SCALAR
  (void)s, (void)t, (void)r, (void)with_r;
  return {};
#else
  const DF df;
  auto across = [&](VB v) {  // the top-right lane less the top-left one
    const VF top = row_of(df, v, 1);
    const VF dx = hn::Sub(hn::DupOdd(top), hn::DupEven(top));
    return join_rows(df, dx, dx);
  };
  auto down = [&](VB v) {  // the bottom-left lane less the top-left one
    const VF dy = hn::Sub(hn::DupEven(row_of(df, v, 0)), hn::DupEven(row_of(df, v, 1)));
    return join_rows(df, dy, dy);
  };
  auto top_left = [&](VB v) {
    const VF tl = hn::DupEven(row_of(df, v, 1));
    return join_rows(df, tl, tl);
  };
  QuadDerivatives q{across(s), across(t), down(s), down(t), hn::Zero(DB()), hn::Zero(DB()),
                    top_left(s), top_left(t), hn::Zero(DB())};
  if (with_r) q.dr_dx = across(r), q.dr_dy = down(r), q.r = top_left(r);
  return q;
#endif
}

/// Any framebuffer height and target: each lane's quad corners evaluated where they are
/// (texcoord.hpp's quad_derivatives): the edge functions moved there exactly, in doubles.
HWY_INLINE QuadDerivatives quad_derivatives_anywhere(const DrawJob& job, const TriSetup& t, const TexcoordPlanes& tp,
                                                     int x, int y, const VD e[kRows][3]) {
  const DD dd;
  const DF df;
  const int height = job.fb->height;
  const int lanes = int(hn::Lanes(dd));
  // -1 in the lanes of odd columns: the quad's left column is one step left of them.
  alignas(64) static constexpr double kOddColumns[8] = {0, -1, 0, -1, 0, -1, 0, -1};
  const VD parity = lanes == 1 ? hn::Set(dd, -double(x & 1)) : hn::Load(dd, kOddColumns);
  const VD inv_area = hn::Set(dd, t.inv_area);
  VF out[9][kRows];
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) {
    const int row = y + r, top = height - 1 - ((height - 1 - row) & ~1);
    VF s[3], tt[3], rr[3];  // the quad's top-left, top-right and bottom-left corners
    for (int corner = 0; corner < 3; ++corner) {
      const VD dcol = hn::Add(parity, hn::Set(dd, corner == 1 ? 1.0 : 0.0));
      const double drow = double(top - row - (corner == 2 ? 1 : 0));
      VF f[2];
      for (int k = 0; k < 2; ++k) {  // edge k at the corner: exact integers in doubles
        const VD ax = hn::Set(dd, double(-t.dy[k] * detail::kSubpixelOne));
        const VD ay = hn::Set(dd, double(t.dx[k] * detail::kSubpixelOne) * drow);
        const VD edge = hn::Add(hn::Add(e[r][k], hn::Mul(dcol, ax)), ay);
        f[k] = hn::DemoteTo(df, hn::Mul(edge, inv_area));
      }
      VF p0, p1;
      float_weights(df, t, f[0], f[1], p0, p1);
      rr[corner] = hn::Zero(df);
      project(df, tp, p0, p1, s[corner], tt[corner], rr[corner]);
    }
    out[0][r] = hn::Sub(s[1], s[0]);
    out[1][r] = hn::Sub(tt[1], tt[0]);
    out[2][r] = hn::Sub(s[2], s[0]);
    out[3][r] = hn::Sub(tt[2], tt[0]);
    out[4][r] = hn::Sub(rr[1], rr[0]);
    out[5][r] = hn::Sub(rr[2], rr[0]);
    out[6][r] = s[0], out[7][r] = tt[0], out[8][r] = rr[0];
  }
  return {join_rows(df, out[0][0], out[0][kRows - 1]), join_rows(df, out[1][0], out[1][kRows - 1]),
          join_rows(df, out[2][0], out[2][kRows - 1]), join_rows(df, out[3][0], out[3][kRows - 1]),
          join_rows(df, out[4][0], out[4][kRows - 1]), join_rows(df, out[5][0], out[5][kRows - 1]),
          join_rows(df, out[6][0], out[6][kRows - 1]), join_rows(df, out[7][0], out[7][kRows - 1]),
          join_rows(df, out[8][0], out[8][kRows - 1])};
}

/// The major axis of (s, t, r) as cube_face picks it: z where |r| >= max(|s|, |t|), else x
/// where |s| > |t|; `neg` where its sign bit is set.
struct CubeAxes {
  MB x_over_y, z_major, neg;
  VB ma;
};

HWY_INLINE CubeAxes cube_axes(VB s, VB t, VB r) {
  const DB db;
  const VB as = hn::Abs(s), at = hn::Abs(t), ar = hn::Abs(r);
  CubeAxes a;
  a.x_over_y = hn::Gt(as, at);
  a.z_major = hn::Ge(ar, hn::Max(as, at));
  a.ma = hn::IfThenElse(a.z_major, r, hn::IfThenElse(a.x_over_y, s, t));
  const DIB di;
  a.neg = hn::RebindMask(db, hn::Lt(hn::BitCast(di, a.ma), hn::Zero(di)));
  return a;
}

HWY_INLINE VB cube_pick(const CubeAxes& a, VB x, VB y, VB z) {
  return hn::IfThenElse(a.z_major, z, hn::IfThenElse(a.x_over_y, x, y));
}

/// The minor axes of a vector (x, y, z) mirrored as cube_face mirrors them.
HWY_INLINE void cube_minor(const CubeAxes& a, VB x, VB y, VB z, VB& sc, VB& tc) {
  const VB nx = hn::Neg(x), ny = hn::Neg(y), nz = hn::Neg(z);
  const VB sz = hn::IfThenElse(a.neg, nx, x), sx = hn::IfThenElse(a.neg, z, nz);
  sc = hn::IfThenElse(a.z_major, sz, hn::IfThenElse(a.x_over_y, sx, x));
  tc = hn::IfThenElse(a.z_major, ny, hn::IfThenElse(a.x_over_y, ny, hn::IfThenElse(a.neg, nz, z)));
}

/// cube_face: (s', t') on the face, and the face (0 to 5) as a float.
HWY_INLINE void cube_face(VB& s, VB& t, VB& r) {
  const DB db;
  const CubeAxes a = cube_axes(s, t, r);
  VB sc, tc;
  cube_minor(a, s, t, r, sc, tc);
  const VB abs_ma = hn::Abs(a.ma), half = hn::Set(db, 0.5f);
  const VB ima = hn::IfThenElseZero(hn::Gt(abs_ma, hn::Zero(db)), hn::Div(half, abs_ma));
  VB face = hn::IfThenElse(a.z_major, hn::Set(db, 4.0f), hn::IfThenElse(a.x_over_y, hn::Zero(db), hn::Set(db, 2.0f)));
  face = hn::Add(face, hn::IfThenElseZero(a.neg, hn::Set(db, 1.0f)));
  s = hn::Add(hn::Mul(sc, ima), half);
  t = hn::Add(hn::Mul(tc, ima), half);
  r = face;
}

/// texture.cpp's cube_rho2: the face coordinates' differences at the quad's top-left pixel.
HWY_INLINE VB cube_rho2(const TexturePlan& tp, const QuadDerivatives& d) {
  const DB db;
  const CubeAxes a = cube_axes(d.s, d.t, d.r);
  const VB ima = hn::Div(hn::Set(db, 1.0f), a.ma), imahalf = hn::Mul(hn::Set(db, 0.5f), ima);
  VB sc, tc, sdx, tdx, sdy, tdy;
  cube_minor(a, d.s, d.t, d.r, sc, tc);
  cube_minor(a, d.ds_dx, d.dt_dx, d.dr_dx, sdx, tdx);
  cube_minor(a, d.ds_dy, d.dt_dy, d.dr_dy, sdy, tdy);
  const VB madx = hn::Mul(cube_pick(a, d.ds_dx, d.dt_dx, d.dr_dx), ima);
  const VB mady = hn::Mul(cube_pick(a, d.ds_dy, d.dt_dy, d.dr_dy), ima);
  const VB dsx = hn::Mul(hn::Sub(sdx, hn::Mul(madx, sc)), imahalf), dtx = hn::Mul(hn::Sub(tdx, hn::Mul(madx, tc)), imahalf);
  const VB dsy = hn::Mul(hn::Sub(sdy, hn::Mul(mady, sc)), imahalf), dty = hn::Mul(hn::Sub(tdy, hn::Mul(mady, tc)), imahalf);
  const VB size = hn::Set(db, tp.width);
  const VB sx = hn::Mul(size, dsx), tx = hn::Mul(size, dtx), sy = hn::Mul(size, dsy), ty = hn::Mul(size, dty);
  const VB x2 = hn::Add(hn::Mul(sx, sx), hn::Mul(tx, tx)), y2 = hn::Add(hn::Mul(sy, sy), hn::Mul(ty, ty));
  const VB r2 = hn::IfThenElse(hn::Lt(x2, y2), y2, x2);
  return hn::IfThenElseZero(hn::IsFinite(r2), r2);
}

/// texture_rho2: the larger squared length of the x and y differences in the base level's texels.
HWY_INLINE VB rho2(const TexturePlan& tp, const QuadDerivatives& d) {
  const DB db;
  if (tp.cube) return cube_rho2(tp, d);
  const VB w = hn::Set(db, tp.width), h = hn::Set(db, tp.height);
  const VB sx = hn::Mul(d.ds_dx, w), sy = hn::Mul(d.ds_dy, w);
  if (tp.one_d) {
    const VB a = hn::Mul(sx, sx), b = hn::Mul(sy, sy);
    return hn::IfThenElse(hn::Lt(a, b), b, a);
  }
  const VB tx = hn::Mul(d.dt_dx, h), ty = hn::Mul(d.dt_dy, h);
  VB a = hn::Add(hn::Mul(sx, sx), hn::Mul(tx, tx)), b = hn::Add(hn::Mul(sy, sy), hn::Mul(ty, ty));
  if (tp.three_d) {  // the r terms added last, as lp_build_rho
    const VB depth = hn::Set(db, tp.depth), rx = hn::Mul(d.dr_dx, depth), ry = hn::Mul(d.dr_dy, depth);
    a = hn::Add(a, hn::Mul(rx, rx));
    b = hn::Add(b, hn::Mul(ry, ry));
  }
  return hn::IfThenElse(hn::Lt(a, b), b, a);
}

/// texture.cpp's fast_log2 (lp_build_fast_log2) for x >= 0: the exponent less one plus the
/// mantissa in [1, 2); -128 for 0, infinities and NaN. (Subnormal x give another value below
/// -126 than frexp's: every such level of detail is magnification all the same.)
HWY_INLINE VB fast_log2(VB x) {
  const DB db;
  const DIB di;
  const auto bits = hn::BitCast(di, x);
  const auto exponent = hn::And(hn::ShiftRight<23>(bits), hn::Set(di, 0xff));
  const VB mantissa = hn::BitCast(db, hn::Or(hn::And(bits, hn::Set(di, 0x7fffff)), hn::Set(di, 0x3f800000)));
  const VB r = hn::Add(hn::ConvertTo(db, hn::Sub(exponent, hn::Set(di, 128))), mantissa);
  const MB special = hn::Or(hn::Eq(x, hn::Zero(db)), hn::RebindMask(db, hn::Eq(exponent, hn::Set(di, 0xff))));
  return hn::IfThenElse(special, hn::Set(db, -128.0f), r);
}

/// Each lane's levels and filter (texture.cpp's sample_texture_bytes): the lower level `lo`,
/// the upper `hi` (equal to lo where one level is sampled) and the weight of the upper `frac`;
/// `linear` lanes are filtered linearly within a level.
struct LevelChoice {
  hn::Vec<DIB> lo, hi;
  VB frac;
  MB linear;
  bool two_levels;  // some lane blends two levels
};

HWY_INLINE MB filter_mask(bool linear) { return linear ? hn::FirstN(DB(), hn::Lanes(DB())) : hn::FirstN(DB(), 0); }

HWY_INLINE LevelChoice choose_levels(const TexturePlan& tp, const QuadDerivatives& d) {
  const DB db;
  const DIB di;
  const VB r2 = rho2(tp, d);
  LevelChoice c;
  c.lo = c.hi = hn::Set(di, tp.base_level);
  c.frac = hn::Zero(db);
  c.two_levels = false;
  VB lod = hn::Zero(db);
  MB minified;
  if (tp.adjust.adjusted) {  // texture.cpp's adjusted_lod
    lod = hn::Add(hn::Mul(hn::Set(db, 0.5f), fast_log2(r2)), hn::Set(db, tp.adjust.bias));
    if (tp.adjust.apply_max) lod = hn::Min(lod, hn::Set(db, tp.adjust.max_lod));
    if (tp.adjust.apply_min) lod = hn::Max(lod, hn::Set(db, tp.adjust.min_lod));
    lod = hn::Min(hn::Max(lod, hn::Set(db, -128.0f)), hn::Set(db, 64.0f));
    minified = hn::Gt(lod, hn::Zero(db));
  } else {
    if (tp.linear_mip) lod = hn::Mul(hn::Set(db, 0.5f), fast_log2(r2));
    minified = tp.linear_mip ? hn::Gt(lod, hn::Zero(db)) : hn::Gt(r2, hn::Set(db, 1.0f));
  }
  c.linear = tp.min_linear == tp.mag_linear ? filter_mask(tp.mag_linear)
                                            : (tp.min_linear ? minified : hn::Not(minified));
  if (!tp.mipmaps) return c;
  const auto base = hn::Set(di, tp.base_level), last = hn::Set(di, tp.last_level);
  const auto minified_i = hn::RebindMask(di, minified);
  if (!tp.linear_mip) {
    hn::Vec<DIB> i;
    if (tp.adjust.adjusted) {  // lp_build_iround: half to even
      i = hn::NearestInt(lod);
    } else {  // rounded_half_log2: the frexp exponent (biased exponent - 126), halved
      const auto exponent = hn::And(hn::ShiftRight<23>(hn::BitCast(di, r2)), hn::Set(di, 0xff));
      i = hn::ShiftRight<1>(hn::Sub(exponent, hn::Set(di, 126)));
    }
    const auto level = hn::Min(hn::Max(hn::Add(base, i), base), last);
    c.lo = c.hi = hn::IfThenElse(minified_i, level, base);
    return c;
  }
  const VB floor = hn::Floor(lod);
  const auto level = hn::Add(base, hn::ConvertTo(di, floor));
  const auto below_last = hn::And(minified_i, hn::Lt(level, last));
  c.lo = hn::IfThenElse(below_last, level, hn::IfThenElse(minified_i, last, base));
  c.hi = hn::IfThenElse(below_last, hn::Add(level, hn::Set(di, 1)), c.lo);
  c.frac = hn::IfThenElseZero(hn::RebindMask(db, below_last), hn::Sub(lod, floor));
  c.two_levels = !hn::AllFalse(di, below_last);
  return c;
}

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

/// Texels (i, j, k) of a level in byte units (texture.cpp's texel), gathered from its RGBA8
/// words; j is ignored by 1D textures, k by 1D and 2D ones.
HWY_INLINE void fetch(const TexturePlan& tp, const TextureLevel& l, hn::Vec<DIB> i, hn::Vec<DIB> j, hn::Vec<DIB> k,
                      VB out[4], VB ref) {
  const DIB di;
  const DUB du;
  hn::Mask<DIB> border = hn::FirstN(di, 0);
  i = wrap_index(i, l.width, tp.wrap_s, border);
  if (!tp.one_d) j = wrap_index(j, l.height, tp.wrap_t, border);
  if (tp.three_d) {
    k = wrap_index(k, l.depth, tp.wrap_r, border);
    j = hn::Add(hn::Mul(k, hn::Set(di, l.height)), j);
  } else if (tp.cube) {  // k: the face's image
    j = hn::Add(hn::Mul(k, hn::Set(di, l.height)), j);
  }
  const auto index = hn::IfThenZeroElse(border, hn::Add(hn::Mul(j, hn::Set(di, l.width)), i));
  if (tp.depth_texture) {  // the border's depth: the border colour's red
    const DB db;
    VB d = hn::GatherIndex(db, l.depth_values.data(), index);
    d = hn::IfThenElse(hn::RebindMask(db, border), hn::Set(db, tp.border_depth), d);
    return depth_texels(tp, d, ref, out);
  }
  const auto words = hn::GatherIndex(du, reinterpret_cast<const std::uint32_t*>(l.rgba.data()), index);
  const bool any_border = !hn::AllFalse(di, border);
  #pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) {
    out[c] = channel(words, c);
    if (any_border) out[c] = hn::IfThenElse(hn::RebindMask(DB(), border), hn::Set(DB(), tp.border[c]), out[c]);
  }
}

/// a + w (b - a), the reference's lerp.
HWY_INLINE VB lerp(VB a, VB b, VB w) { return hn::Add(a, hn::Mul(w, hn::Sub(b, a))); }

/// texture.cpp's nearest_index: the clamps and mirrored repeat (u >= 0 there) keep a nearest
/// index in the level; repeat wraps it and clamp to border takes the border outside.
HWY_INLINE bool keeps_nearest_in_level(TextureWrap w) {
  return w != TextureWrap::kRepeat && w != TextureWrap::kClampToBorder;
}

/// One level's filtered texels in byte units (texture.cpp's sample_level): `linear` lanes
/// blend four texels (two for 1D textures), the others take the nearest; the nearest reads
/// the border only with clamp to border.
HWY_INLINE void sample_level(const TexturePlan& tp, int level, VB s, VB t, VB r, MB linear, VB out[4]) {
  if (tp.depth_texture) r = hn::Min(hn::Max(r, hn::Zero(DB())), hn::Set(DB(), 1.0f));  // texture.cpp's ref
  const DB db;
  const DIB di;
  const TextureLevel& l = tp.texture->levels[std::size_t(level)];
  const VB u = texel_coord(s, l.width, tp.wrap_s);
  const VB v = tp.one_d ? hn::Zero(db) : texel_coord(t, l.height, tp.wrap_t);
  const VB w = tp.three_d ? texel_coord(r, l.depth, tp.wrap_r) : hn::Zero(db);
  const bool any_linear = !hn::AllFalse(db, linear), all_linear = hn::AllTrue(db, linear);
  hn::Vec<DIB> i, j, k = tp.cube ? hn::ConvertTo(di, r) : hn::Zero(di);  // a cube map's r: the face
  if (!all_linear) {  // nearest: floor, clamped by the clamps (repeat's size wraps to 0)
    i = hn::ConvertTo(di, hn::Floor(u));
    j = tp.one_d ? hn::Zero(di) : hn::ConvertTo(di, hn::Floor(v));
    if (keeps_nearest_in_level(tp.wrap_s)) i = hn::Min(i, hn::Set(di, l.width - 1));
    if (keeps_nearest_in_level(tp.wrap_t)) j = hn::Min(j, hn::Set(di, l.height - 1));
    if (tp.three_d) {
      k = hn::ConvertTo(di, hn::Floor(w));
      if (keeps_nearest_in_level(tp.wrap_r)) k = hn::Min(k, hn::Set(di, l.depth - 1));
    }
  }
  if (!any_linear) return fetch(tp, l, i, j, k, out, r);
  const VB uu = hn::Sub(u, hn::Set(db, 0.5f)), vv = hn::Sub(v, hn::Set(db, 0.5f));
  const VB fu = hn::Floor(uu), fv = hn::Floor(vv);
  const auto li = hn::RebindMask(di, linear);
  i = all_linear ? hn::ConvertTo(di, fu) : hn::IfThenElse(li, hn::ConvertTo(di, fu), i);
  if (tp.one_d) j = hn::Zero(di);  // 1D: one row, whatever the filter
  else j = all_linear ? hn::ConvertTo(di, fv) : hn::IfThenElse(li, hn::ConvertTo(di, fv), j);
  const VB a = hn::IfThenElseZero(linear, hn::Sub(uu, fu)), b = hn::IfThenElseZero(linear, hn::Sub(vv, fv));
  const auto one = hn::Set(di, 1);
  if (tp.one_d) {
    VB c00[4], c10[4];
    fetch(tp, l, i, j, k, c00, r);
    fetch(tp, l, hn::Add(i, one), j, k, c10, r);
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) out[c] = lerp(c00[c], c10[c], a);
    return;
  }
  auto slice = [&](hn::Vec<DIB> kk, VB res[4]) {  // the reference's bilinear slice
    VB t00[4], t10[4], t01[4], t11[4];
    fetch(tp, l, i, j, kk, t00, r);
    fetch(tp, l, hn::Add(i, one), j, kk, t10, r);
    fetch(tp, l, i, hn::Add(j, one), kk, t01, r);
    fetch(tp, l, hn::Add(i, one), hn::Add(j, one), kk, t11, r);
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) res[c] = lerp(lerp(t00[c], t10[c], a), lerp(t01[c], t11[c], a), b);
  };
  if (!tp.three_d) return slice(k, out);
  const VB ww = hn::Sub(w, hn::Set(db, 0.5f)), fw = hn::Floor(ww);
  k = all_linear ? hn::ConvertTo(di, fw) : hn::IfThenElse(li, hn::ConvertTo(di, fw), k);
  const VB cw = hn::IfThenElseZero(linear, hn::Sub(ww, fw));
  VB near[4], far[4];
  slice(k, near);
  slice(hn::Add(k, one), far);
  #pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) out[c] = lerp(near[c], far[c], cw);
}

/// The filtered texel of every `live` lane in [0, 1] (sample_texture): the levels each lane
/// needs sampled one level at a time, then blended.
HWY_INLINE void sample_texture(const TexturePlan& tp, VB s, VB t, VB r, const QuadDerivatives* d, MB live, VB out[4]) {
  const DB db;
  const DIB di;
  if (!d) {  // one level, one filter for every lane
    sample_level(tp, tp.base_level, s, t, r, filter_mask(tp.mag_linear), out);
  } else {
    const LevelChoice c = choose_levels(tp, *d);
    const auto live_i = hn::RebindMask(di, live);
    const int first = hn::GetLane(hn::MinOfLanes(di, hn::IfThenElse(live_i, c.lo, hn::Set(di, 1 << 20))));
    const int last = hn::GetLane(hn::MaxOfLanes(di, hn::IfThenElse(live_i, c.hi, hn::Set(di, -1))));
    VB lo[4] = {hn::Zero(db), hn::Zero(db), hn::Zero(db), hn::Zero(db)}, hi[4] = {lo[0], lo[1], lo[2], lo[3]};
    for (int level = first; level <= last; ++level) {
      const auto is_lo = hn::Eq(c.lo, hn::Set(di, level)), is_hi = hn::Eq(c.hi, hn::Set(di, level));
      if (hn::AllFalse(di, hn::And(live_i, hn::Or(is_lo, is_hi)))) continue;
      VB texel[4];
      sample_level(tp, level, s, t, r, c.linear, texel);
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

/// The filtered texels of texture unit `unit` for the block's fragments, at each lane's
/// coordinates. `e` are the rows' edge values, `w` their perspective weights; `live` the lanes
/// whose colour is used.
HWY_INLINE void sample_block(const DrawJob& job, int unit, const TriSetup& t, const TexcoordPlanes& planes,
                             const Weights& w, int x, int y, const VD e[kRows][3], MB live, VB texel[4]) {
  const DB db;
  const TexturePlan& tp = job.plan.texture[unit];
  VB s, tc, r = hn::Zero(db);
  project(db, planes, w.f0, w.f1, s, tc, r);
  QuadDerivatives d;
  if (tp.lod) {
    d = kRows == 2 && job.fb->height % 2 == 0 ? quad_derivatives_in_block(s, tc, r, planes.with_r)
                                              : quad_derivatives_anywhere(job, t, planes, x, y, e);
  }
  if (tp.cube) cube_face(s, tc, r);
  sample_texture(tp, s, tc, r, tp.lod ? &d : nullptr, live, texel);
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SHADELAB_FAST_TEXTURE_INL_H_
