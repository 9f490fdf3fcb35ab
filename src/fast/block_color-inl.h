// A block's colours on the SIMD path: the interpolated primary and secondary colours (the
// reference's own where a last bit would matter), lit per pixel for Phong shading, textured by
// each enabled unit through its environment, fogged, and a smooth line's or point's coverage
// applied to alpha. Per-target code (Highway), called by raster-inl.h's simd_block; it computes
// colours only: the tests and the writes to the framebuffer are the caller's.
#if defined(SHADELAB_FAST_BLOCK_COLOR_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SHADELAB_FAST_BLOCK_COLOR_INL_H_
#undef SHADELAB_FAST_BLOCK_COLOR_INL_H_
#else
#define SHADELAB_FAST_BLOCK_COLOR_INL_H_
#endif

#include "fast/block-inl.h"
#include "fast/fragment-inl.h"
#include "fast/texenv-inl.h"
#include "fast/texture-inl.h"
#include "fast/triangle.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace shadelab::fast::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The interpolated colour channels [first, 4) of a block as the reference computes them
// (exact_varying): primary plus secondary, or primary alone.
HWY_INLINE void exact_color(const TriSetup& t, const TrianglePlanes& planes, const Weights& w, int first,
                            Rgba& color, bool with_secondary = true) {
  for (int c = first; c < 4; ++c) color.c[c] = exact_varying(t, w, planes.color[c].k);
  if (!planes.has_secondary || !with_secondary) return;
  for (int c = first; c < 3; ++c) color.c[c] = hn::Add(color.c[c], exact_varying(t, w, planes.secondary[c].k));
}

// What block_color needs of the block beyond its weights: where it is, its rows' edge values
// (the texture's level of detail evaluates quads at rows the block does not hold) and the
// lanes whose colours are used.
struct BlockPlace {
  int x, y;
  const VD (*e)[3];
  unsigned live;
};

// A textured block's colours (draw.cpp's shade_fragment): the primary colour, textured, then
// the secondary colour added.
HWY_INLINE Rgba textured_color(const DrawJob& job, const TriSetup& t, const TrianglePlanes& planes, const Weights& w,
                               const BlockPlace& at) {
  VB secondary[3] = {hn::Zero(DB()), hn::Zero(DB()), hn::Zero(DB())};
  Rgba color;
  // The environment may replace the fragment's alpha with the texel's: its own alpha is then
  // not needed as the reference computes it.
  // (Not with GL_COMBINE, which may read the primary colour again.)
  bool alpha_replaced = false;  // by some unit (the later ones combine the texel's alpha)
  for (const TexturePlan& tp : job.plan.texture) {
    alpha_replaced = alpha_replaced || (tp.texture && tp.env == TextureEnvMode::kReplace &&
                                        tp.format != TextureFormat::kLuminance && tp.format != TextureFormat::kRgb);
  }
  alpha_replaced = alpha_replaced && !job.plan.combine;
  const bool exact = job.plan.exact_colors && !planes.exact && !planes.uniform &&
                     (job.frag->logic_op.enabled || !alpha_replaced);
  // (GL_COMBINE's dot products make alpha from the colour: every channel exact then.)
  const bool exact_all = exact && (job.frag->logic_op.enabled || job.plan.combine);
  if (job.plan.phong) {
    color = phong_color(job, t, planes, w, secondary);
  } else {
    color = vertex_color(t, planes, w, false);
    if (exact && !t.flat) exact_color(t, planes, w, exact_all ? 0 : 3, color, false);
  }
  // Every unit's texels first (a GL_COMBINE environment may read another unit's; zero where a
  // unit has no texture), then the environments in order (draw.cpp's shade_fragment).
  VB texels[kMaxTextureUnits][4];
  const MB live = block_mask(at.live);
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    if (job.plan.texture[u].texture) {
      sample_block(job, u, t, planes.texcoord[u], w, at.x, at.y, at.e, live, texels[u]);
    } else if (job.plan.combine) {
      for (VB& v : texels[u]) v = hn::Zero(DB());
    }
  }
  VB primary[4];
  if (job.plan.combine) {
    for (int k = 0; k < 4; ++k) primary[k] = color.c[k];
  }
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    const TexturePlan& tp = job.plan.texture[u];
    if (!tp.texture) continue;
    if (tp.env == TextureEnvMode::kCombine) texture_combine(tp, u, color.c, texels, primary);
    else texture_env(tp, color.c, texels[u]);
  }
  color.clamped = false;
  if (!job.plan.phong && !planes.has_secondary) return color;
  #pragma GCC unroll 3
  for (int c = 0; c < 3; ++c) {
    if (!job.plan.phong) {
      const Plane& p = planes.secondary[c];
      secondary[c] = exact_all && !t.flat ? exact_varying(t, w, p.k) : varying(t, planes, w, p);
    }
    color.c[c] = hn::Add(color.c[c], secondary[c]);
  }
  return color;
}

// The colours of a block's lanes: Gouraud, flat or Phong, textured, then fogged. Where a
// difference in the last bit would change more than that bit of the result (the 8-bit alpha
// the alpha test compares, the bytes a logic op combines), the interpolated colours are the
// reference's own (flat and uniform colours and the exact planes already are).
HWY_INLINE Rgba block_color(const DrawJob& job, const TriSetup& t, TrianglePlanes& planes, const VD b0[kRows],
                            const VD b1[kRows], VB f0, VB f1, const VB* coverage, const BlockPlace& at) {
  if (!planes.ready) set_up_planes(job, t, planes);
  const Weights w = perspective_weights(t, b0, b1, f0, f1);
  Rgba color;
  if (job.plan.textured) {
    color = textured_color(job, t, planes, w, at);
  } else {
    color = job.plan.phong ? phong_color(job, t, planes, w) : vertex_color(t, planes, w);
    if (job.plan.exact_colors && !job.plan.phong && !t.flat && !planes.exact && !planes.uniform) {
      exact_color(t, planes, w, job.frag->logic_op.enabled ? 0 : 3, color);
    }
  }
  if (job.plan.fog) apply_fog(job.plan.fog_params, t, planes, w, color);
  if (coverage) {  // a smooth line's or point's (Mesa multiplies it in at the very end)
    color.c[3] = hn::Mul(color.c[3], *coverage);
    color.clamped = false;
  }
  return color;
}

// A smooth line's or point's coverage at the block's pixel centres (raster/prims.cpp's
// coverage_at, lane by lane: the affine functions in double, the rest in float): the alpha
// factor, and the lanes a point discards cleared from `bits`.
HWY_INLINE VB block_coverage(const detail::Coverage& c, int x, int y, unsigned& bits) {
  const DD dd;
  const DF df;
  const DB db;
  const VD xs = hn::Iota(dd, double(x) + 0.5);
  VF u[kRows], v[kRows];
  #pragma GCC unroll 4
  for (int r = 0; r < kRows; ++r) {
    const VD ys = hn::Set(dd, double(y + r) + 0.5);
    u[r] = hn::DemoteTo(df, hn::Add(hn::Add(hn::Set(dd, double(c.u0)), hn::Mul(hn::Set(dd, double(c.ux)), xs)),
                                    hn::Mul(hn::Set(dd, double(c.uy)), ys)));
    v[r] = hn::DemoteTo(df, hn::Add(hn::Add(hn::Set(dd, double(c.v0)), hn::Mul(hn::Set(dd, double(c.vx)), xs)),
                                    hn::Mul(hn::Set(dd, double(c.vy)), ys)));
  }
  const VB ub = join_rows(df, u[0], u[kRows - 1]), vb = join_rows(df, v[0], v[kRows - 1]);
  const VB one = hn::Set(db, 1.0f), a = hn::Set(db, c.a);
  if (c.kind == detail::Coverage::Kind::kLine) {
    return hn::Mul(clamp_unit(hn::Sub(a, hn::Abs(ub))), clamp_unit(hn::Sub(hn::Set(db, c.b), hn::Abs(vb))));
  }
  const VB d = hn::Add(hn::Mul(ub, ub), hn::Mul(vb, vb));
  bits &= ~block_bits(hn::Lt(one, d));
  const VB rim = hn::Mul(hn::Set(db, 1.0f / (1.0f - c.a)), hn::Sub(one, d));
  return hn::IfThenElse(hn::Ge(a, d), rim, one);
}

}  // namespace shadelab::fast::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // SHADELAB_FAST_BLOCK_COLOR_INL_H_
