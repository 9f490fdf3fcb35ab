// 1D and 2D textures as OpenGL 1.1 samples them (with llvmpipe's choices where GL leaves one):
// RGBA8 mipmap levels, wrap modes with the border colour, nearest/linear filtering with
// mipmaps, the level of detail of a 2x2 pixel quad, and the texture environment (modulate,
// replace, decal, blend). Sampling only: no file reading (image.hpp), no rasterization here.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace shadelab {

enum class TextureWrap { kRepeat, kClamp, kClampToEdge };
enum class TextureFilter {
  kNearest, kLinear,
  kNearestMipmapNearest, kLinearMipmapNearest, kNearestMipmapLinear, kLinearMipmapLinear,
};
/// glTexEnv GL_TEXTURE_ENV_MODE (GL 1.1 table 3.22).
enum class TextureEnvMode { kModulate, kReplace, kDecal, kBlend };
/// The base internal format, which decides how the environment combines (table 3.22).
/// Texels are stored expanded to RGBA: luminance L as (L, L, L, 1), luminance-alpha as
/// (L, L, L, A), intensity I as (I, I, I, I), alpha A as (0, 0, 0, A), RGB with alpha 1.
enum class TextureFormat { kAlpha, kLuminance, kLuminanceAlpha, kIntensity, kRgb, kRgba };

struct TextureLevel {
  int width = 0, height = 0;       ///< texels, without a border (1D levels: height 1)
  std::vector<std::uint8_t> rgba;  ///< row 0 is t = 0 (the first row given to glTexImage2D)
};

struct Texture {
  std::vector<TextureLevel> levels;  ///< level 0 first
  TextureFormat format = TextureFormat::kRgba;
  /// 1: a 1D texture (GL 1.1 section 3.8.1): only s is used, each level is one row and
  /// wrap_t is ignored. 2: a 2D texture.
  int dimensions = 2;
  TextureWrap wrap_s = TextureWrap::kRepeat, wrap_t = TextureWrap::kRepeat;
  TextureFilter min_filter = TextureFilter::kNearestMipmapLinear;  ///< GL's default
  TextureFilter mag_filter = TextureFilter::kLinear;
  /// GL_TEXTURE_BORDER_COLOR, in [0, 1]: what GL_CLAMP's linear filter blends in beyond the
  /// edge (border texels themselves are not kept, as in Mesa's gallium drivers).
  glm::vec4 border_color{0.0f};

  /// Complete when level 0 exists and, if the min filter uses mipmaps, every level down to
  /// 1x1 is present with halved sizes (GL 1.1 section 3.8.9). Incomplete textures are ignored.
  bool complete() const;
  /// The last level the mipmap filters use: log2 of level 0's larger side (GL 1.1 section
  /// 3.8.7), or fewer when fewer levels are present.
  int last_level() const;
};

/// Builds every mipmap level below level 0 by 2x2 box filtering.
void generate_mipmaps(Texture& texture);

/// The differences of a 2x2 pixel quad's texture coordinates (s and t after the division by
/// q), from its top-left pixel to the pixel beside it (x) and to the one below it (y), as
/// llvmpipe derives them for every pixel of the quad (lp_build_packed_ddx_ddy_twocoord).
struct TextureDerivatives {
  float ds_dx = 0.0f, dt_dx = 0.0f, ds_dy = 0.0f, dt_dy = 0.0f;
};

/// The squared scale factor rho^2 of GL 1.1 section 3.8.5 as llvmpipe computes it (exactly,
/// in float): the larger of the squared lengths of the x and y differences measured in level
/// 0's texels. A texture is minified where rho^2 > 1.
float texture_rho2(const Texture& texture, const TextureDerivatives& d);

/// The filtered texel colour at (s, t) for a quad whose scale factor is sqrt(rho2): level
/// selection as llvmpipe's (log2 computed as lp_build_fast_log2 for *_MIPMAP_LINEAR, rounded
/// exactly for *_MIPMAP_NEAREST; magnification wherever rho2 <= 1, that is c = 0 for every
/// filter pair). `st` must be finite (see finite_texcoord).
glm::vec4 sample_texture(const Texture& texture, glm::vec2 st, float rho2);
/// sample_texture's texel in byte units (0 to 255), before its one scaling by 1/255: texels
/// are read as their bytes, filtered by linear interpolations a + w (b - a) (along s, then
/// t, then between two levels), the border colour taken times 255.
glm::vec4 sample_texture_bytes(const Texture& texture, glm::vec2 st, float rho2);

/// A texture coordinate the samplers can index with: NaN becomes 0 and magnitudes are kept
/// below 2^20, so that texel indices never overflow (such coordinates only repeat or clamp).
float finite_texcoord(float v);

/// Combines the fragment colour with a texel as the environment mode says.
glm::vec4 apply_texture_env(TextureEnvMode mode, TextureFormat format, const glm::vec4& fragment,
                            const glm::vec4& texel, const glm::vec4& env_color);

}  // namespace shadelab
