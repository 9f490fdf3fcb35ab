// Texture coordinates on the SIMD path, for one block of a triangle: the coordinates' planes
// and their perspective projection in the float arithmetic of raster/texcoord.hpp, the
// derivatives per 2x2 quad, the cube map's face, and llvmpipe's level of detail with the levels
// it chooses (texture.cpp's sample_texture_bytes), operation by operation without fused
// multiply-adds so that every target picks the reference's levels. It computes coordinates
// only; texels are fetched and filtered in texture-inl.h. Per-target code (Highway).
#if defined(SHADELAB_FAST_TEXCOORD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SHADELAB_FAST_TEXCOORD_INL_H_
#undef SHADELAB_FAST_TEXCOORD_INL_H_
#else
#define SHADELAB_FAST_TEXCOORD_INL_H_
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "fast/block-inl.h"
#include "fast/triangle.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// A sampler compiled for one shape of texture: with k2D a 2D colour texture (not 1D, 3D, a
// cube map or a depth texture; the shape nearly every program samples), the other shapes'
// branches compiled out; without, the shape read from the plan.
template <bool k2D>
HWY_INLINE bool is_1d(const TexturePlan& tp) { return !k2D && tp.one_d; }
template <bool k2D>
HWY_INLINE bool is_3d(const TexturePlan& tp) { return !k2D && tp.three_d; }
template <bool k2D>
HWY_INLINE bool is_cube(const TexturePlan& tp) { return !k2D && tp.cube; }
template <bool k2D>
HWY_INLINE bool is_depth(const TexturePlan& tp) { return !k2D && tp.depth_texture; }

/// A triangle's texture coordinates s, t, q and r (r sampled by 3D textures only): value at
/// vertex 2 and the differences from it to vertices 0 and 1 (texcoord.hpp's texcoord_plane).
/// `unit_q`: q is 1 at every vertex, so its plane is 1 wherever the weights are finite.
struct TexcoordPlanes {
  float base[4], d0[4], d1[4];
  bool unit_q;
  bool with_r;      // a 3D texture: r is projected too
  bool magnified;   // every quad the triangle's blocks hold is magnified (magnified_everywhere)
};

/// Whether the level of detail is at most 0 at every 2x2 quad the triangle's blocks in the
/// tile hold, for a texture whose plan computes one (TexturePlan::lod) without bias or limits:
/// then every lane samples the base level with the magnification filter, as choose_levels
/// would choose, and the block needs no derivatives. Decided for affine triangles with q 1
/// (their coordinate planes in the screen weights, constant differences from pixel to pixel)
/// of 1D and 2D textures: the planes' gradient, widened by what the float roundings of the
/// lanes' coordinates can add to a difference, is below one base-level texel a pixel along x
/// and along y, with a margin for the roundings of texture_rho2 itself.
HWY_INLINE bool magnified_everywhere(const DrawJob& job, const TriSetup& t, const TexcoordPlanes& p, int unit) {
  const TexturePlan& tp = job.plan.texture[unit];
  if (!tp.lod || tp.adjust.adjusted || tp.cube || tp.three_d || p.with_r || !t.affine || !p.unit_q) return false;
  // Screen weights f_k = edge_k * inv_area: their change one pixel right and one row up.
  double fx[2], fy[2];
  for (int k = 0; k < 2; ++k) {
    fx[k] = double(-t.dy[k] * detail::kSubpixelOne) * t.inv_area;
    fy[k] = double(t.dx[k] * detail::kSubpixelOne) * t.inv_area;
  }
  // The largest |base| + |f0 d0| + |f1 d1| of s and t over the pixels the blocks and the quads'
  // corners reach (the box widened by a block and two pixels; the weights are linear, so at its
  // corners): a lane's coordinate is within a few float roundings of that sum, 2^-22 of it,
  // and a difference of two within 2^-21; the bound below allows 2^-19.
  const int xs[2] = {t.x0 - 18, t.x1 + 18}, ys[2] = {t.y0 - 3, t.y1 + 3};
  double largest = 0.0;
  for (int x : xs) {
    for (int y : ys) {
      const double f0 = double(edge_at(t, 0, x, y)) * t.inv_area, f1 = double(edge_at(t, 1, x, y)) * t.inv_area;
      for (int c = 0; c < 2; ++c) {
        const double sum = std::fabs(p.base[c]) + std::fabs(f0 * p.d0[c]) + std::fabs(f1 * p.d1[c]);
        largest = std::max(largest, sum);
      }
    }
  }
  const double slack = largest * 0x1p-19;
  const double width = tp.width, height = tp.one_d ? 0.0 : tp.height;
  auto below_one = [&](const double (&f)[2]) {
    const double ds = std::fabs(p.d0[0] * f[0] + p.d1[0] * f[1]) + slack;
    const double dt = std::fabs(p.d0[1] * f[0] + p.d1[1] * f[1]) + slack;
    const double rho2 = ds * width * ds * width + dt * height * dt * height;
    return rho2 <= 0.99;  // false for NaN
  };
  return below_one(fx) && below_one(fy);
}

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
  p.magnified = magnified_everywhere(job, t, p, unit);
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
template <bool k2D = false>
HWY_INLINE VB rho2(const TexturePlan& tp, const QuadDerivatives& d) {
  const DB db;
  if (is_cube<k2D>(tp)) return cube_rho2(tp, d);
  const VB w = hn::Set(db, tp.width), h = hn::Set(db, tp.height);
  const VB sx = hn::Mul(d.ds_dx, w), sy = hn::Mul(d.ds_dy, w);
  if (is_1d<k2D>(tp)) {
    const VB a = hn::Mul(sx, sx), b = hn::Mul(sy, sy);
    return hn::IfThenElse(hn::Lt(a, b), b, a);
  }
  const VB tx = hn::Mul(d.dt_dx, h), ty = hn::Mul(d.dt_dy, h);
  VB a = hn::Add(hn::Mul(sx, sx), hn::Mul(tx, tx)), b = hn::Add(hn::Mul(sy, sy), hn::Mul(ty, ty));
  if (is_3d<k2D>(tp)) {  // the r terms added last, as lp_build_rho
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

template <bool k2D = false>
HWY_INLINE LevelChoice choose_levels(const TexturePlan& tp, const QuadDerivatives& d) {
  const DB db;
  const DIB di;
  const VB r2 = rho2<k2D>(tp, d);
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
  const auto level = hn::Add(base, truncate_in_range(floor));
  const auto below_last = hn::And(minified_i, hn::Lt(level, last));
  c.lo = hn::IfThenElse(below_last, level, hn::IfThenElse(minified_i, last, base));
  c.hi = hn::IfThenElse(below_last, hn::Add(level, hn::Set(di, 1)), c.lo);
  c.frac = hn::IfThenElseZero(hn::RebindMask(db, below_last), hn::Sub(lod, floor));
  c.two_levels = !hn::AllFalse(di, below_last);
  return c;
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SHADELAB_FAST_TEXCOORD_INL_H_
