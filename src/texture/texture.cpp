// Texture completeness, mipmap generation, filtered sampling with wrap modes, the border
// colour and llvmpipe's level-of-detail selection (with GL 1.2's base and maximum levels and
// LOD clamps and GL 1.4's bias), and cube maps' faces (GL 1.1 sections 3.8.1-3.8.8; GL 1.5
// sections 3.8.7-3.8.9). The environments that combine texels with a fragment are in texenv.cpp.
#include "shadelab/texture.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

namespace shadelab {

namespace {

bool uses_mipmaps(TextureFilter f) {
  return f != TextureFilter::kNearest && f != TextureFilter::kLinear;
}

// Texel coordinate i wrapped into [0, size) for repeat, or clamped (GL_CLAMP and
// GL_CLAMP_TO_BORDER may return -1 or size and beyond, meaning the border, which is the
// border colour). Mirrored repeat's indices are already mirrored: only clamped.
int wrap_index(int i, int size, TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::kRepeat: return ((i % size) + size) % size;
    case TextureWrap::kClampToEdge: case TextureWrap::kMirroredRepeat: return std::clamp(i, 0, size - 1);
    case TextureWrap::kClamp: return std::clamp(i, -1, size);
    case TextureWrap::kClampToBorder: return i;
  }
  return 0;
}

// llvmpipe's mirror (lp_build_coord_mirror): |2 (s/2 - round(s/2))|, rounded half to even;
// exact in float.
float mirror(float s) {
  const float h = s * 0.5f;
  const float f = h - std::nearbyint(h);
  return std::fabs(f + f);
}

// s (or t) before filtering: repeat keeps it (the index wraps), the clamps limit it, mirrored
// repeat mirrors it into [0, 1]. Clamp to border keeps it within [-1, 2]: beyond, every
// texel a filter reads is the border all the same, and indices stay small.
float wrap_coord(float s, int size, TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::kClamp: return std::clamp(s, 0.0f, 1.0f);
    case TextureWrap::kClampToEdge: {
      float half = 0.5f / float(size);
      return std::clamp(s, half, 1.0f - half);
    }
    case TextureWrap::kClampToBorder: return std::clamp(s, -1.0f, 2.0f);
    case TextureWrap::kMirroredRepeat: return mirror(s);
    case TextureWrap::kRepeat: break;
  }
  return s - std::floor(s);
}

// Nearest filtering's index from u (texels): repeat wraps it later; the clamps and mirrored
// repeat (u >= 0 there) keep it in the level (s = 1 picks the last texel); clamp to border
// keeps it, the border lying outside.
int nearest_index(float u, int size, TextureWrap wrap) {
  const int i = int(std::floor(u));
  if (wrap == TextureWrap::kRepeat || wrap == TextureWrap::kClampToBorder) return i;
  return std::clamp(i, 0, size - 1);
}

// The wrap modes sampled: llvmpipe clamps a cube map's faces to their edges whatever the wrap
// modes say (lp_build_sample_soa_code: gallium keeps no borders, and Direct3D ignores the
// modes), as Mesa 22 draws them.
TextureWrap wrap_s_of(const Texture& t) { return t.cube_map ? TextureWrap::kClampToEdge : t.wrap_s; }
TextureWrap wrap_t_of(const Texture& t) { return t.cube_map ? TextureWrap::kClampToEdge : t.wrap_t; }

// Texel (i, j, k) of a level in byte units (0 to 255; the border colour times 255); j is
// ignored by 1D textures, k by 1D and 2D ones.
// A depth texel d in byte units: d, or 1 where r OP d holds (compare), expanded by the depth
// texture mode.
glm::vec4 depth_texel(const Texture& t, float d, float ref) {
  const float v = t.compare ? (depth_compare(t.compare_func, ref, d) ? 255.0f : 0.0f) : d * 255.0f;
  switch (t.format) {
    case TextureFormat::kIntensity: return glm::vec4(v);
    case TextureFormat::kAlpha: return {0.0f, 0.0f, 0.0f, v};
    default: return {v, v, v, 255.0f};
  }
}

// `ref`: a depth texture's r (the value compared).
glm::vec4 texel(const TextureLevel& l, int i, int j, int k, const Texture& t, float ref = 0.0f) {
  i = wrap_index(i, l.width, wrap_s_of(t));
  j = t.dimensions == 1 ? 0 : wrap_index(j, l.height, wrap_t_of(t));
  k = t.cube_map ? k : t.dimensions < 3 ? 0 : wrap_index(k, l.depth, t.wrap_r);  // a cube map's k: the face
  const bool outside = i < 0 || j < 0 || k < 0 || i >= l.width || j >= l.height || k >= l.depth;
  if (t.depth) {  // the border's depth is the border colour's red
    const std::size_t at = (std::size_t(k) * std::size_t(l.height) + std::size_t(j)) * std::size_t(l.width) + std::size_t(i);
    return depth_texel(t, outside ? t.border_color.r : l.depth_values[at], ref);
  }
  if (outside) return border_texel(t) * 255.0f;
  const std::size_t row = std::size_t(k) * std::size_t(l.height) + std::size_t(j);
  const std::uint8_t* p = &l.rgba[(row * std::size_t(l.width) + std::size_t(i)) * 4];
  return glm::vec4(p[0], p[1], p[2], p[3]);
}

glm::vec4 lerp(const glm::vec4& a, const glm::vec4& b, float w) { return a + w * (b - a); }

// cvtps2dq: round to nearest even; outside the int range (and NaN) the integer indefinite.
std::int32_t round_to_int(float x) {
  if (!(x >= -2147483648.0f && x < 2147483648.0f)) return std::numeric_limits<std::int32_t>::min();
  return std::int32_t(std::nearbyint(x));
}

// A linear filter's two texels along an axis of a level `size` texels long and the weight of
// the second in 256ths (lp_build_sample_image_linear and lp_build_sample_wrap_linear_int):
// the position in texels times 256, rounded, less half a texel; repeat wraps the indices by
// masking (a power of two) or from the coordinate's fraction (lp_build_coord_repeat_npot_
// linear_int), clamp to edge clamps them.
struct FixedTaps {
  int i0, i1, weight;
};

FixedTaps fixed_taps(float s, int size, TextureWrap wrap, bool pot) {
  const bool npot_repeat = wrap == TextureWrap::kRepeat && !pot;
  const float scaled = npot_repeat ? (s - std::floor(s)) * float(size) : s * float(size);
  const std::int32_t fixed = std::int32_t(std::uint32_t(round_to_int(scaled * 256.0f)) - 128u);
  const int i = fixed >> 8, weight = fixed & 255;
  if (wrap == TextureWrap::kClampToEdge) return {std::clamp(i, 0, size - 1), std::clamp(i + 1, 0, size - 1), weight};
  if (pot) return {i & (size - 1), (i + 1) & (size - 1), weight};
  const int i0 = std::min(i < 0 ? size - 1 : i, size - 1);
  return {i0, i0 == size - 1 ? 0 : i0 + 1, weight};
}

// llvmpipe's 8-bit lerp (lp_build_lerp with prescaled weights, through pmulhrsw): a +
// round(w (b - a) / 256), halves rounded up, for each of a texel's four bytes.
int lerp8(int a, int b, int w) { return a + ((w * (b - a) + 128) >> 8); }

glm::vec4 lerp8(const glm::vec4& a, const glm::vec4& b, int w) {
  glm::vec4 r;
  for (int c = 0; c < 4; ++c) r[c] = float(lerp8(int(a[c]), int(b[c]), w));
  return r;
}

// One level's filtered texel in byte units. The arithmetic, operation by operation, is what
// the fast pipeline's samplers do on every SIMD target (fast/texcoord-inl.h for coordinates
// and levels, fast/texture-inl.h for texels): keep them equal.
// A cube map's str is (s', t', face) on the face (cube_face).
glm::vec4 sample_level(const Texture& t, int level, glm::vec3 str, bool linear) {
  const TextureLevel& l = t.levels[std::size_t(level)];
  const bool one_d = t.dimensions == 1, three_d = t.dimensions == 3;
  const int face = t.cube_map ? int(str.z) : 0;
  // A depth texture's r, clamped to [0, 1] as llvmpipe clamps it for unorm depth formats
  // (lp_build_sample_compare).
  const float ref = std::clamp(str.z, 0.0f, 1.0f);
  float u = wrap_coord(str.x, l.width, wrap_s_of(t)) * float(l.width);
  float v = one_d ? 0.0f : wrap_coord(str.y, l.height, wrap_t_of(t)) * float(l.height);
  float w = three_d ? wrap_coord(str.z, l.depth, t.wrap_r) * float(l.depth) : 0.0f;
  if (!linear) {  // nearest reads the border only with clamp to border
    const int i = nearest_index(u, l.width, wrap_s_of(t));
    const int j = one_d ? 0 : nearest_index(v, l.height, wrap_t_of(t));
    const int k = three_d ? nearest_index(w, l.depth, t.wrap_r) : face;
    return texel(l, i, j, k, t, ref);
  }
  if (eight_bit_filtering(t)) {
    // Repeat wraps a side that is a power of two by a mask: llvmpipe decides it once for the
    // texture (pot_width and the others, from its resource's first level), here from the base
    // level; every level below a power-of-two base is one too.
    const TextureLevel& base = t.levels[std::size_t(t.base_level)];
    auto power_of_two = [](int side) { return std::has_single_bit(unsigned(side)); };
    const FixedTaps x = fixed_taps(str.x, l.width, wrap_s_of(t), power_of_two(base.width));
    if (one_d) return lerp8(texel(l, x.i0, 0, 0, t), texel(l, x.i1, 0, 0, t), x.weight);
    const FixedTaps y = fixed_taps(str.y, l.height, wrap_t_of(t), power_of_two(base.height));
    auto slice = [&](int k) {
      return lerp8(lerp8(texel(l, x.i0, y.i0, k, t), texel(l, x.i1, y.i0, k, t), x.weight),
                   lerp8(texel(l, x.i0, y.i1, k, t), texel(l, x.i1, y.i1, k, t), x.weight), y.weight);
    };
    if (!three_d) return slice(face);
    const FixedTaps z = fixed_taps(str.z, l.depth, t.wrap_r, power_of_two(base.depth));
    return lerp8(slice(z.i0), slice(z.i1), z.weight);
  }
  float uu = u - 0.5f;
  int i0 = int(std::floor(uu));
  float a = uu - std::floor(uu);
  if (one_d) return lerp(texel(l, i0, 0, 0, t, ref), texel(l, i0 + 1, 0, 0, t, ref), a);
  float vv = v - 0.5f;
  int j0 = int(std::floor(vv));
  float b = vv - std::floor(vv);
  auto slice = [&](int k) {
    const glm::vec4 top = lerp(texel(l, i0, j0, k, t, ref), texel(l, i0 + 1, j0, k, t, ref), a);
    const glm::vec4 bottom = lerp(texel(l, i0, j0 + 1, k, t, ref), texel(l, i0 + 1, j0 + 1, k, t, ref), a);
    return lerp(top, bottom, b);
  };
  if (!three_d) return slice(face);
  float ww = w - 0.5f;
  int k0 = int(std::floor(ww));
  float c = ww - std::floor(ww);
  return lerp(slice(k0), slice(k0 + 1), c);
}

// x = m 2^e with m in [0.5, 1) (frexp); 0, infinities and NaN count as 0 (llvmpipe replaces
// an infinite or NaN rho by 0 as well).
int exponent_of(float x, float& mantissa) {
  int e = 0;
  mantissa = std::isfinite(x) ? std::frexp(x, &e) : 0.0f;
  return e;
}

// lp_build_fast_log2: floor(log2 x) - 1 + the mantissa in [1, 2); piecewise linear between
// powers of two, where it is exact.
float fast_log2(float x) {
  float m;
  int e = exponent_of(x, m);
  if (m == 0.0f) return -128.0f;  // llvmpipe: exponent -127, mantissa 1
  return float(e - 2) + 2.0f * m;
}

// lp_build_ilog2_sqrt: round(log2(sqrt(x))) from the exponent, (floor(log2 x) + 1) >> 1.
int rounded_half_log2(float x) {
  float m;
  int e = exponent_of(x, m);
  if (m == 0.0f) return -63;
  return (e - 1 + 1) >> 1;  // arithmetic shift: floor for negative values too
}

}  // namespace

namespace {

// log2 of a level's largest side (the sides a texture of `dimensions` uses).
int size_log2(const TextureLevel& l, int dimensions) {
  int size = std::max({l.width, dimensions == 1 ? 1 : l.height, dimensions == 3 ? l.depth : 1}), n = 0;
  while (size > 1) size /= 2, ++n;
  return n;
}

}  // namespace

int Texture::last_level() const {
  if (base_level < 0 || std::size_t(base_level) >= levels.size()) return base_level;
  const int n = size_log2(levels[std::size_t(base_level)], dimensions);
  return std::min({base_level + n, max_level, int(levels.size()) - 1});
}

bool Texture::complete() const {
  if (base_level < 0 || std::size_t(base_level) >= levels.size()) return false;
  const TextureLevel& b = levels[std::size_t(base_level)];
  if (b.width <= 0 || b.height <= 0 || b.depth <= 0) return false;
  if (!uses_mipmaps(min_filter)) return true;
  if (max_level < base_level) return false;
  const int q = std::min(base_level + size_log2(b, dimensions), max_level);
  int w = b.width, h = b.height, d = b.depth;
  for (int i = base_level + 1; i <= q; ++i) {
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    d = std::max(1, d / 2);
    if (std::size_t(i) >= levels.size()) return false;
    const TextureLevel& l = levels[std::size_t(i)];
    if (l.width != w || l.height != h || (dimensions == 3 && l.depth != d)) return false;
  }
  return true;
}

bool eight_bit_filtering(const Texture& t) {
  auto simple = [](TextureWrap w) { return w == TextureWrap::kRepeat || w == TextureWrap::kClampToEdge; };
  if (t.depth || t.wide || !simple(wrap_s_of(t))) return false;
  if ((t.dimensions >= 2 || t.cube_map) && !simple(wrap_t_of(t))) return false;
  return t.dimensions < 3 || simple(t.wrap_r);
}

glm::vec4 border_texel(const Texture& t) {
  const glm::vec4& b = t.border_color;
  switch (t.format) {
    case TextureFormat::kAlpha: return {0.0f, 0.0f, 0.0f, b.a};
    case TextureFormat::kLuminance: return {b.r, b.r, b.r, 1.0f};
    case TextureFormat::kLuminanceAlpha: return {b.r, b.r, b.r, b.a};
    case TextureFormat::kIntensity: return glm::vec4(b.r);
    case TextureFormat::kRgb: return {b.r, b.g, b.b, 1.0f};
    case TextureFormat::kRgba: break;
  }
  return b;
}

namespace {

// Mesa's util_quantize_lod_bias: within [-16, 16], rounded to 1/256 (half away from zero).
float quantize_bias(float b) {
  if (!(b == b)) return 0.0f;
  return std::round(std::clamp(b, -16.0f, 16.0f) * 256.0f) / 256.0f;
}

}  // namespace

// llvmpipe's static sampler state (lp_sampler_static_sampler_state): the bias applies when it
// is not 0, the min clamp when above 0 (Mesa's sampler keeps min_lod >= 0), the max clamp
// below 15 (PIPE_MAX_TEXTURE_LEVELS - 1); equal clamps force their level, which the two
// clamps give too.
TextureLod texture_lod(const Texture& t, float unit_bias) {
  TextureLod l;
  l.bias = std::clamp(quantize_bias(t.lod_bias) + quantize_bias(unit_bias), -kMaxTextureLodBias, kMaxTextureLodBias);
  l.min_lod = t.min_lod > 0.0f ? t.min_lod : 0.0f;  // NaN too
  l.max_lod = t.max_lod == t.max_lod ? t.max_lod : 0.0f;
  l.apply_min = l.min_lod > 0.0f;
  l.apply_max = l.max_lod < 15.0f;
  l.adjusted = l.bias != 0.0f || l.apply_min || l.apply_max;
  return l;
}

float adjusted_lod(float rho2, const TextureLod& l) {
  float lod = 0.5f * fast_log2(rho2);
  lod = lod + l.bias;
  if (l.apply_max) lod = std::min(lod, l.max_lod);
  if (l.apply_min) lod = std::max(lod, l.min_lod);
  return std::clamp(lod, -128.0f, 64.0f);
}

void generate_mipmaps(Texture& texture) {
  if (texture.levels.empty()) return;
  texture.levels.resize(1);
  while (texture.levels.back().width > 1 || texture.levels.back().height > 1) {
    const TextureLevel& src = texture.levels.back();
    TextureLevel dst;
    dst.width = std::max(1, src.width / 2);
    dst.height = std::max(1, src.height / 2);
    dst.rgba.resize(std::size_t(dst.width) * dst.height * 4);
    for (int y = 0; y < dst.height; ++y) {
      for (int x = 0; x < dst.width; ++x) {
        for (int c = 0; c < 4; ++c) {
          int sum = 0;
          for (int dy = 0; dy < 2; ++dy) {
            for (int dx = 0; dx < 2; ++dx) {
              int sx = std::min(src.width - 1, x * 2 + dx), sy = std::min(src.height - 1, y * 2 + dy);
              sum += src.rgba[(std::size_t(sy) * src.width + sx) * 4 + c];
            }
          }
          dst.rgba[(std::size_t(y) * dst.width + x) * 4 + c] = std::uint8_t((sum + 2) / 4);
        }
      }
    }
    texture.levels.push_back(std::move(dst));
  }
}

CubeCoord cube_face(glm::vec3 v) {
  const float as = std::fabs(v.x), at = std::fabs(v.y), ar = std::fabs(v.z);
  const bool x_over_y = as > at, z_major = ar >= std::max(as, at);
  const float ma = z_major ? v.z : x_over_y ? v.x : v.y;
  const bool neg = std::signbit(ma);
  CubeCoord c;
  float sc, tc;
  if (z_major) {
    c.face = 4, sc = neg ? -v.x : v.x, tc = -v.y;
  } else if (x_over_y) {
    c.face = 0, sc = neg ? v.z : -v.z, tc = -v.y;
  } else {
    c.face = 2, sc = v.x, tc = neg ? -v.z : v.z;
  }
  c.face += neg ? 1 : 0;
  const float abs_ma = std::fabs(ma), ima = abs_ma > 0.0f ? 0.5f / abs_ma : 0.0f;
  c.s = sc * ima + 0.5f;
  c.t = tc * ima + 0.5f;
  return c;
}

namespace {

// lp_build_cube_lookup's derivatives of the face coordinates at the top-left pixel (the
// differences of sc, tc and ma picked and mirrored as the coordinates are), then lp_build_rho
// of a 2D texture of side `size`.
float cube_rho2(float size, const TextureDerivatives& d) {
  const float as = std::fabs(d.s), at = std::fabs(d.t), ar = std::fabs(d.r);
  const bool x_over_y = as > at, z_major = ar >= std::max(as, at);
  auto pick = [&](float x, float y, float z) { return z_major ? z : x_over_y ? x : y; };
  const float ma = pick(d.s, d.t, d.r);
  const bool neg = std::signbit(ma);
  const float ima = 1.0f / ma, imahalf = 0.5f * ima;
  // Minor axes as cube_face mirrors them: (sc, tc) of a vector (x, y, z).
  auto minor = [&](float x, float y, float z, float& sc, float& tc) {
    if (z_major) sc = neg ? -x : x, tc = -y;
    else if (x_over_y) sc = neg ? z : -z, tc = -y;
    else sc = x, tc = neg ? -z : z;
  };
  float sc, tc, sdx, tdx, sdy, tdy;
  minor(d.s, d.t, d.r, sc, tc);
  minor(d.ds_dx, d.dt_dx, d.dr_dx, sdx, tdx);
  minor(d.ds_dy, d.dt_dy, d.dr_dy, sdy, tdy);
  const float madx = pick(d.ds_dx, d.dt_dx, d.dr_dx) * ima, mady = pick(d.ds_dy, d.dt_dy, d.dr_dy) * ima;
  const float dsx = (sdx - madx * sc) * imahalf, dtx = (tdx - madx * tc) * imahalf;
  const float dsy = (sdy - mady * sc) * imahalf, dty = (tdy - mady * tc) * imahalf;
  const float sx = size * dsx, tx = size * dtx, sy = size * dsy, ty = size * dty;
  const float x2 = sx * sx + tx * tx, y2 = sy * sy + ty * ty;
  const float rho2 = std::max(x2, y2);
  return std::isfinite(rho2) ? rho2 : 0.0f;  // lp_build_rho: infinite or NaN rho is 0
}

}  // namespace

// lp_build_rho (exact, "no_rho_approx", llvmpipe's default since Mesa 20): each difference
// scaled by level 0's size and squared, in float.
float texture_rho2(const Texture& t, const TextureDerivatives& d) {
  const TextureLevel& base = t.levels[std::size_t(t.base_level)];
  if (t.cube_map) return cube_rho2(float(base.width), d);
  const float w = float(base.width), h = float(base.height);
  const float sx = d.ds_dx * w, sy = d.ds_dy * w;
  if (t.dimensions == 1) return std::max(sx * sx, sy * sy);
  const float tx = d.dt_dx * h, ty = d.dt_dy * h;
  float x2 = sx * sx + tx * tx, y2 = sy * sy + ty * ty;
  if (t.dimensions == 3) {  // lp_build_rho: the r terms added last
    const float depth = float(base.depth), rx = d.dr_dx * depth, ry = d.dr_dy * depth;
    x2 = x2 + rx * rx;
    y2 = y2 + ry * ry;
  }
  return std::max(x2, y2);
}

float finite_texcoord(float v) {
  constexpr float kLimit = 1048576.0f;
  return v > -kLimit ? (v < kLimit ? v : kLimit) : (v == v ? -kLimit : 0.0f);
}

// lp_build_lod_selector and lp_build_sample_soa's level choice (GL 1.1 section 3.8.6 with the
// later specifications' c = 0): minified where rho2 > 1 (for *_MIPMAP_LINEAR, or with
// adjustments, where lambda is above 0); levels from the base level on, past the last one
// clamped.
glm::vec4 sample_texture(const Texture& t, glm::vec3 st, float rho2, float unit_bias) {
  return sample_texture_bytes(t, st, rho2, unit_bias) * (1.0f / 255.0f);
}

// In byte units; sample_texture scales them by 1/255 (a float product: one rounding of the
// reciprocal away from the quotient) once at the end.
glm::vec4 sample_texture_bytes(const Texture& t, glm::vec3 st, float rho2, float unit_bias) {
  const TextureFilter f = t.min_filter;
  const bool linear_mip = f == TextureFilter::kNearestMipmapLinear || f == TextureFilter::kLinearMipmapLinear;
  const TextureLod adjust = texture_lod(t, unit_bias);
  float lod = 0.0f;
  bool minified;
  if (adjust.adjusted) {
    lod = adjusted_lod(rho2, adjust);
    minified = lod > 0.0f;
  } else {
    if (linear_mip) lod = 0.5f * fast_log2(rho2);
    minified = linear_mip ? lod > 0.0f : rho2 > 1.0f;
  }
  const int base = t.base_level;
  if (t.cube_map) {  // the face and the coordinates on it, then 2D sampling of that face
    const CubeCoord c = cube_face(st);
    st = glm::vec3(c.s, c.t, float(c.face));
  }
  if (!minified) return sample_level(t, base, st, t.mag_filter == TextureFilter::kLinear);
  if (!uses_mipmaps(f)) return sample_level(t, base, st, f == TextureFilter::kLinear);
  const int last = t.last_level();
  const bool linear_in_level = f == TextureFilter::kLinearMipmapNearest || f == TextureFilter::kLinearMipmapLinear;
  if (!linear_mip) {  // adjusted: lp_build_iround, half to even
    const int i = adjust.adjusted ? int(std::nearbyint(lod)) : rounded_half_log2(rho2);
    return sample_level(t, std::clamp(base + i, base, last), st, linear_in_level);
  }
  const float floor = std::floor(lod);
  const int level = base + int(floor);
  const float frac = lod - floor;
  if (level >= last) return sample_level(t, last, st, linear_in_level);
  const glm::vec4 lo = sample_level(t, level, st, linear_in_level), hi = sample_level(t, level + 1, st, linear_in_level);
  // The 8-bit sampler blends the levels in 256ths too, the fraction truncated.
  if (eight_bit_filtering(t)) return lerp8(lo, hi, int(frac * 256.0f));
  return lerp(lo, hi, frac);
}

}  // namespace shadelab
