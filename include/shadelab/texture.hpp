// 1D, 2D and 3D textures as OpenGL 1.4 samples them (with llvmpipe's choices where GL leaves one):
// RGBA8 mipmap levels, wrap modes with the border colour, nearest/linear filtering with
// mipmaps, the level of detail of a 2x2 pixel quad with its bias and clamps and the base and
// maximum levels, and the texture environment (modulate, replace, decal, blend). Sampling
// only: no file reading (image.hpp), no rasterization here.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace shadelab {

/// GL_TEXTURE_WRAP_S/T (GL 1.4 section 3.8.7): GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE (1.2),
/// GL_CLAMP_TO_BORDER (1.3), GL_MIRRORED_REPEAT (1.4).
enum class TextureWrap { kRepeat, kClamp, kClampToEdge, kClampToBorder, kMirroredRepeat };
enum class TextureFilter {
  kNearest, kLinear,
  kNearestMipmapNearest, kLinearMipmapNearest, kNearestMipmapLinear, kLinearMipmapLinear,
};
/// glTexEnv GL_TEXTURE_ENV_MODE (GL 1.1 table 3.22; GL_ADD and GL_COMBINE: GL 1.3 tables 3.23,
/// 3.24).
enum class TextureEnvMode { kModulate, kReplace, kDecal, kBlend, kAdd, kCombine };

/// GL_COMBINE_RGB / GL_COMBINE_ALPHA (GL 1.3 table 3.24; the dot products for RGB only).
enum class CombineFunction : std::uint8_t {
  kReplace, kModulate, kAdd, kAddSigned, kInterpolate, kSubtract, kDot3Rgb, kDot3Rgba,
};
/// GL_SOURCEn_RGB / _ALPHA (table 3.25): the unit's texel, another unit's (GL 1.4's crossbar:
/// kTexture0 + i), the environment colour, the fragment's primary colour, the previous unit's.
enum class CombineSource : std::uint8_t {
  kTexture, kTexture0, kTexture1, kTexture2, kTexture3, kConstant, kPrimaryColor, kPrevious,
};
/// GL_OPERANDn_RGB / _ALPHA (tables 3.25, 3.26).
enum class CombineOperand : std::uint8_t { kSrcColor, kOneMinusSrcColor, kSrcAlpha, kOneMinusSrcAlpha };

/// A texture unit's GL_COMBINE environment (GL 1.3 section 3.8.13).
struct TextureCombine {
  CombineFunction rgb = CombineFunction::kModulate, alpha = CombineFunction::kModulate;
  CombineSource rgb_source[3] = {CombineSource::kTexture, CombineSource::kPrevious, CombineSource::kConstant};
  CombineSource alpha_source[3] = {CombineSource::kTexture, CombineSource::kPrevious, CombineSource::kConstant};
  CombineOperand rgb_operand[3] = {CombineOperand::kSrcColor, CombineOperand::kSrcColor, CombineOperand::kSrcAlpha};
  CombineOperand alpha_operand[3] = {CombineOperand::kSrcAlpha, CombineOperand::kSrcAlpha, CombineOperand::kSrcAlpha};
  float rgb_scale = 1.0f, alpha_scale = 1.0f;  ///< 1, 2 or 4
};

/// Texture units (GL 1.3 section 2.7): each has its own texture coordinates, texture and
/// environment; the units apply in order, each to the previous unit's colour. llvmpipe's
/// GL_MAX_TEXTURE_UNITS is 8; shadelab has 4 (GL 1.3's minimum is 2).
inline constexpr int kMaxTextureUnits = 4;
/// GL_TEXTURE_COMPARE_FUNC (GL 1.4's GL_LEQUAL and GL_GEQUAL, EXT_shadow_funcs' others): the
/// comparison of r with a depth texel, r OP D.
enum class TextureCompare { kNever, kLess, kEqual, kLequal, kGreater, kNotequal, kGequal, kAlways };
/// The base internal format, which decides how the environment combines (table 3.22).
/// Texels are stored expanded to RGBA: luminance L as (L, L, L, 1), luminance-alpha as
/// (L, L, L, A), intensity I as (I, I, I, I), alpha A as (0, 0, 0, A), RGB with alpha 1.
enum class TextureFormat { kAlpha, kLuminance, kLuminanceAlpha, kIntensity, kRgb, kRgba };

struct TextureLevel {
  int width = 0, height = 0;       ///< texels, without a border (1D levels: height 1)
  /// Row 0 is t = 0 (the first row given to glTexImage2D); a 3D level holds `depth` images
  /// of `height` rows one after the other, image 0 at r = 0.
  std::vector<std::uint8_t> rgba;
  int depth = 1;  ///< images (3D levels; 1 otherwise)
  /// A depth texture's texels (GL 1.4, ARB_depth_texture), in [0, 1], laid out as `rgba`.
  std::vector<float> depth_values;
};

struct Texture {
  std::vector<TextureLevel> levels;  ///< level 0 first
  TextureFormat format = TextureFormat::kRgba;
  /// 1: a 1D texture (GL 1.1 section 3.8.1): only s is used, each level is one row and
  /// wrap_t is ignored. 2: a 2D texture. 3: a 3D texture (GL 1.2): s, t and r.
  int dimensions = 2;
  TextureWrap wrap_s = TextureWrap::kRepeat, wrap_t = TextureWrap::kRepeat;
  /// GL_TEXTURE_WRAP_R (GL 1.2): sampled by 3D textures only.
  TextureWrap wrap_r = TextureWrap::kRepeat;
  /// A cube map (GL 1.3 section 3.8.6; dimensions 2): each level holds the six square faces as
  /// `depth` 6 images, in the order +X, -X, +Y, -Y, +Z, -Z; (s, t, r) is a direction whose
  /// major axis picks the face (cube_face), which is then sampled as a 2D image, with wrap_s
  /// and wrap_t on the face (no seamless filtering, as GL 1.x and Mesa's default).
  bool cube_map = false;
  /// A depth texture (GL 1.4, 1D or 2D): its levels' depth_values are sampled; each texel is
  /// D, or with `compare` (GL_COMPARE_R_TO_TEXTURE, ARB_shadow) 1 where r OP D holds and 0
  /// elsewhere, compared texel by texel before filtering as llvmpipe does (percentage-closer
  /// filtering); then expanded as `format` says (GL_DEPTH_TEXTURE_MODE: luminance (v, v, v,
  /// 1), intensity (v, v, v, v), alpha (0, 0, 0, v)). r is s, t, r's r after the division by q,
  /// clamped to [0, 1] (llvmpipe's for unorm depth formats).
  bool depth = false;
  /// Some component is kept with more than 8 bits (GL_RGBA16 and the like; the levels hold it
  /// rounded to 8): llvmpipe filters such a texture in float, not in 8 bits.
  bool wide = false;
  bool compare = false;
  TextureCompare compare_func = TextureCompare::kLequal;
  TextureFilter min_filter = TextureFilter::kNearestMipmapLinear;  ///< GL's default
  TextureFilter mag_filter = TextureFilter::kLinear;
  /// GL_TEXTURE_BORDER_COLOR, in [0, 1]: what GL_CLAMP's linear filter and GL_CLAMP_TO_BORDER
  /// take beyond the edge (border texels themselves are not kept, as in Mesa's gallium drivers).
  glm::vec4 border_color{0.0f};
  /// GL_TEXTURE_BASE_LEVEL and GL_TEXTURE_MAX_LEVEL (GL 1.2, section 3.8.8 of GL 1.4): the
  /// levels sampled are base_level to last_level(); the level of detail is measured in
  /// base_level's texels. Levels below base_level need not exist.
  int base_level = 0, max_level = 1000;
  /// GL_TEXTURE_MIN_LOD / GL_TEXTURE_MAX_LOD (GL 1.2) and the object's GL_TEXTURE_LOD_BIAS
  /// (GL 1.4); the texture unit's bias is added when sampling (texture_lod).
  float min_lod = -1000.0f, max_lod = 1000.0f, lod_bias = 0.0f;

  /// Complete (GL 1.5 section 3.8.10) when level base_level exists and, if the min filter
  /// uses mipmaps, base_level <= max_level and every level from base_level to last_level()
  /// is present with halved sizes (depth too). Incomplete textures are ignored.
  bool complete() const;
  /// The last level the mipmap filters use: q = min(base_level + log2 of the base level's
  /// largest side, max_level) (GL 1.5 section 3.8.10), or fewer when fewer levels are present.
  int last_level() const;
};

/// The border colour as a texel of the texture's base format (GL 1.5 section 3.8.8: converted
/// as table 3.15 converts a colour, then expanded as the levels are: luminance and intensity
/// take red, alpha is 1 where the format has none), in [0, 1]. What Mesa's state tracker
/// hands llvmpipe (st_translate_color).
glm::vec4 border_texel(const Texture& texture);

/// GL_MAX_TEXTURE_LOD_BIAS: llvmpipe's (PIPE_CAPF_MAX_TEXTURE_LOD_BIAS).
inline constexpr float kMaxTextureLodBias = 16.0f;

/// The level-of-detail adjustments of a texture sampled through a texture unit (GL 1.4
/// section 3.8.8): lambda' = lambda + bias, then clamped to [min_lod, max_lod], as llvmpipe
/// applies them (lp_build_lod_selector): `adjusted` when a bias or a clamp can matter (its
/// general path), else the level is chosen straight from rho^2 as before GL 1.2.
struct TextureLod {
  bool adjusted = false;
  float bias = 0.0f;  ///< the texture's and the unit's, each quantized to 1/256 as Mesa does
  bool apply_min = false, apply_max = false;
  float min_lod = 0.0f, max_lod = 0.0f;  ///< min_lod at least 0, as Mesa's sampler state
};

/// The adjustments of `texture` sampled with the texture unit's GL_TEXTURE_LOD_BIAS
/// `unit_bias` (glTexEnv GL_TEXTURE_FILTER_CONTROL): Mesa quantizes each bias to 1/256 within
/// [-16, 16]; their sum is clamped to GL_MAX_TEXTURE_LOD_BIAS (the specification).
TextureLod texture_lod(const Texture& texture, float unit_bias);

/// lambda of an adjusted level of detail (TextureLod::adjusted): 0.5 fast_log2(rho2) plus the
/// bias, clamped to max_lod then to min_lod, then kept within [-128, 64] (no level lies
/// beyond; the sign, magnification or not, is kept).
float adjusted_lod(float rho2, const TextureLod& lod);

/// Builds every mipmap level below level 0 by 2x2 box filtering (scene textures).
void generate_mipmaps(Texture& texture);

/// The differences of a 2x2 pixel quad's texture coordinates (s, t and r after the division
/// by q), from its top-left pixel to the pixel beside it (x) and to the one below it (y), as
/// llvmpipe derives them for every pixel of the quad (lp_build_packed_ddx_ddy_twocoord; r's
/// only matter to 3D textures).
struct TextureDerivatives {
  float ds_dx = 0.0f, dt_dx = 0.0f, ds_dy = 0.0f, dt_dy = 0.0f;
  float dr_dx = 0.0f, dr_dy = 0.0f;
  /// (s, t, r) at the quad's top-left pixel: cube maps turn the differences into the face's
  /// there (cube_rho2).
  float s = 0.0f, t = 0.0f, r = 0.0f;
};

/// A cube map's face and the coordinates on it (GL 1.3 section 3.8.6, table 3.19) as
/// llvmpipe computes them (lp_build_cube_lookup): the major axis is z where |r| >= max(|s|,
/// |t|), else x where |s| > |t|, else y; its sign (the sign bit) picks the positive or negative
/// face (0 +X, 1 -X, 2 +Y, 3 -Y, 4 +Z, 5 -Z); s' = sc * (0.5 / |ma|) + 0.5, the same for t'
/// (0.5 where ma is 0).
struct CubeCoord {
  int face = 0;
  float s = 0.0f, t = 0.0f;
};
CubeCoord cube_face(glm::vec3 str);

/// The squared scale factor rho^2 of GL 1.1 section 3.8.5 as llvmpipe computes it (exactly,
/// in float): the larger of the squared lengths of the x and y differences measured in the
/// base level's texels ((s^2 + t^2) + r^2 for a 3D texture). A texture is minified where
/// rho^2 > 1 (without LOD adjustments). For a cube map the differences are first those of the
/// face coordinates of the top-left pixel's face, d(sc / |ma|) / 2 by the quotient rule, as
/// lp_build_cube_lookup derives them: 0.5 (dsc - sc dma / ma) / ma.
float texture_rho2(const Texture& texture, const TextureDerivatives& d);

/// The filtered texel colour at (s, t, r) (r for 3D textures and cube maps only) for a quad whose scale factor is sqrt(rho2), sampled
/// through a texture unit whose GL_TEXTURE_LOD_BIAS is `unit_bias`: level selection as
/// llvmpipe's (without adjustments, log2 computed as lp_build_fast_log2 for *_MIPMAP_LINEAR,
/// rounded exactly for *_MIPMAP_NEAREST, magnification wherever rho2 <= 1, that is c = 0 for
/// every filter pair; with them, lambda from adjusted_lod, rounded half to even for
/// *_MIPMAP_NEAREST, magnification where lambda <= 0). `str` must be finite (finite_texcoord).
glm::vec4 sample_texture(const Texture& texture, glm::vec3 str, float rho2, float unit_bias = 0.0f);
/// sample_texture's texel in byte units (0 to 255), before its one scaling by 1/255: texels
/// are read as their bytes, filtered by linear interpolations (along s, then t, then r, then
/// between two levels), the border colour taken times 255. Where eight_bit_filtering holds,
/// as llvmpipe's 8-bit sampler: positions in 8.8 fixed point, each interpolation in 256ths
/// rounded to a byte; otherwise in float, a + w (b - a).
glm::vec4 sample_texture_bytes(const Texture& texture, glm::vec3 str, float rho2, float unit_bias = 0.0f);

/// Whether a texture is filtered as llvmpipe's 8-bit sampler filters it (lp_bld_sample_aos.c,
/// chosen by lp_build_sample_soa_code): a colour texture whose texels fit 8-bit unorm (not
/// `wide`) and whose wrap modes on every axis sampled are GL_REPEAT or GL_CLAMP_TO_EDGE.
bool eight_bit_filtering(const Texture& texture);

/// r OP d of a depth comparison.
inline bool depth_compare(TextureCompare op, float r, float d) {
  switch (op) {
    case TextureCompare::kNever: return false;
    case TextureCompare::kLess: return r < d;
    case TextureCompare::kEqual: return r == d;
    case TextureCompare::kLequal: return r <= d;
    case TextureCompare::kGreater: return r > d;
    case TextureCompare::kNotequal: return r != d;
    case TextureCompare::kGequal: return r >= d;
    case TextureCompare::kAlways: return true;
  }
  return false;
}

/// A texture coordinate the samplers can index with: NaN becomes 0 and magnitudes are kept
/// below 2^20, so that texel indices never overflow (such coordinates only repeat or clamp).
float finite_texcoord(float v);

/// Combines the fragment colour with a texel as the environment mode says (not kCombine).
glm::vec4 apply_texture_env(TextureEnvMode mode, TextureFormat format, const glm::vec4& fragment,
                            const glm::vec4& texel, const glm::vec4& env_color);

/// What a GL_COMBINE environment reads: each unit's texel (zero for a unit without a texture,
/// as llvmpipe's fixed-function program reads one), the unit's own index, the environment
/// colour, the fragment's primary colour and the previous unit's colour.
struct CombineInputs {
  const glm::vec4* texels;  ///< kMaxTextureUnits of them
  int unit;
  glm::vec4 constant, primary, previous;
};

/// The GL_COMBINE environment (GL 1.3 section 3.8.13) as Mesa's fixed-function fragment
/// program computes it: the function of the operands in float, then, with a scale, the scaled
/// result clamped to [0, 1]; without one, clamped only after the functions that can leave
/// [0, 1] (add, add signed, subtract, the dot products). The dot products' result is every
/// colour component, and alpha too for kDot3Rgba (scaled there by the alpha scale).
glm::vec4 apply_texture_combine(const TextureCombine& combine, const CombineInputs& in);

}  // namespace shadelab
