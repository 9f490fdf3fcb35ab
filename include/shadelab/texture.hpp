// 2D textures as OpenGL 1.1 samples them: RGBA8 mipmap levels, wrap modes, nearest/linear
// filtering with mipmaps, and the texture environment (modulate, replace, decal).
// Sampling only: no file reading (image.hpp) and no rasterization here.
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
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  ///< row 0 is t = 0 (the first row given to glTexImage2D)
};

struct Texture {
  std::vector<TextureLevel> levels;  ///< level 0 first
  TextureFormat format = TextureFormat::kRgba;
  TextureWrap wrap_s = TextureWrap::kRepeat, wrap_t = TextureWrap::kRepeat;
  TextureFilter min_filter = TextureFilter::kNearestMipmapLinear;  ///< GL's default
  TextureFilter mag_filter = TextureFilter::kLinear;
  glm::vec4 env_color{0.0f};  ///< GL_TEXTURE_ENV_COLOR, for kBlend

  /// Complete when level 0 exists and, if the min filter uses mipmaps, every level down to
  /// 1x1 is present with halved sizes (GL 1.1 section 3.8.9). Incomplete textures are ignored.
  bool complete() const;
};

/// Builds every mipmap level below level 0 by 2x2 box filtering.
void generate_mipmaps(Texture& texture);

/// The filtered texel colour at (s, t) for a level of detail `lambda` (log2 of texels per
/// pixel; <= 0 magnifies).
glm::vec4 sample_texture(const Texture& texture, glm::vec2 st, float lambda);

/// Combines the fragment colour with a texel as the environment mode says.
glm::vec4 apply_texture_env(TextureEnvMode mode, TextureFormat format, const glm::vec4& fragment,
                            const glm::vec4& texel, const glm::vec4& env_color);

}  // namespace shadelab
