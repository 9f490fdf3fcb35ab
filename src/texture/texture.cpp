// Texture completeness, mipmap generation, filtered sampling with wrap modes and level of
// detail, and the texture environment (GL 1.1 sections 3.8.1-3.8.9, table 3.22).
#include "shadelab/texture.hpp"

#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

namespace shadelab {

namespace {

bool uses_mipmaps(TextureFilter f) {
  return f != TextureFilter::kNearest && f != TextureFilter::kLinear;
}

// Texel coordinate i wrapped into [0, size) for repeat, or clamped (GL_CLAMP may return -1 or
// size, meaning the border, which is black with alpha 0 by default).
int wrap_index(int i, int size, TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::kRepeat: return ((i % size) + size) % size;
    case TextureWrap::kClampToEdge: return std::clamp(i, 0, size - 1);
    case TextureWrap::kClamp: return std::clamp(i, -1, size);
  }
  return 0;
}

// s (or t) before filtering: repeat keeps it (the index wraps), the clamps limit it.
float wrap_coord(float s, int size, TextureWrap wrap) {
  if (wrap == TextureWrap::kClamp) return std::clamp(s, 0.0f, 1.0f);
  if (wrap == TextureWrap::kClampToEdge) {
    float half = 0.5f / float(size);
    return std::clamp(s, half, 1.0f - half);
  }
  return s - std::floor(s);
}

glm::vec4 texel(const TextureLevel& l, int i, int j, const Texture& t) {
  i = wrap_index(i, l.width, t.wrap_s);
  j = wrap_index(j, l.height, t.wrap_t);
  if (i < 0 || j < 0 || i >= l.width || j >= l.height) return glm::vec4(0.0f);  // border
  const std::uint8_t* p = &l.rgba[(std::size_t(j) * l.width + i) * 4];
  return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
}

glm::vec4 sample_level(const Texture& t, int level, glm::vec2 st, bool linear) {
  const TextureLevel& l = t.levels[std::size_t(level)];
  float u = wrap_coord(st.x, l.width, t.wrap_s) * l.width;
  float v = wrap_coord(st.y, l.height, t.wrap_t) * l.height;
  if (!linear) {  // nearest never reads the border: s = 1 picks the last texel
    int i = int(std::floor(u)), j = int(std::floor(v));
    if (t.wrap_s != TextureWrap::kRepeat) i = std::clamp(i, 0, l.width - 1);
    if (t.wrap_t != TextureWrap::kRepeat) j = std::clamp(j, 0, l.height - 1);
    return texel(l, i, j, t);
  }
  float uu = u - 0.5f, vv = v - 0.5f;
  int i0 = int(std::floor(uu)), j0 = int(std::floor(vv));
  float a = uu - std::floor(uu), b = vv - std::floor(vv);
  return (1 - a) * (1 - b) * texel(l, i0, j0, t) + a * (1 - b) * texel(l, i0 + 1, j0, t) +
         (1 - a) * b * texel(l, i0, j0 + 1, t) + a * b * texel(l, i0 + 1, j0 + 1, t);
}

}  // namespace

bool Texture::complete() const {
  if (levels.empty() || levels[0].width <= 0 || levels[0].height <= 0) return false;
  if (!uses_mipmaps(min_filter)) return true;
  int w = levels[0].width, h = levels[0].height;
  for (std::size_t i = 1;; ++i) {
    if (w == 1 && h == 1) return true;
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    if (i >= levels.size() || levels[i].width != w || levels[i].height != h) return false;
  }
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

glm::vec4 sample_texture(const Texture& t, glm::vec2 st, float lambda) {
  // GL 1.1 section 3.8.6: magnify when lambda <= c, c = 0.5 only for a linear mag filter with a
  // nearest-mipmap min filter.
  bool nearest_mip = t.min_filter == TextureFilter::kNearestMipmapNearest ||
                     t.min_filter == TextureFilter::kNearestMipmapLinear;
  float c = (t.mag_filter == TextureFilter::kLinear && nearest_mip) ? 0.5f : 0.0f;
  if (!(lambda > c)) return sample_level(t, 0, st, t.mag_filter == TextureFilter::kLinear);
  TextureFilter f = t.min_filter;
  if (!uses_mipmaps(f)) return sample_level(t, 0, st, f == TextureFilter::kLinear);
  int max_level = int(t.levels.size()) - 1;
  bool linear_in_level = f == TextureFilter::kLinearMipmapNearest || f == TextureFilter::kLinearMipmapLinear;
  if (f == TextureFilter::kNearestMipmapNearest || f == TextureFilter::kLinearMipmapNearest) {
    int d = lambda <= 0.5f ? 0 : int(std::ceil(lambda + 0.5f)) - 1;
    return sample_level(t, std::min(d, max_level), st, linear_in_level);
  }
  if (lambda >= float(max_level)) return sample_level(t, max_level, st, linear_in_level);
  int d1 = int(std::floor(lambda));
  float frac = lambda - float(d1);
  return (1.0f - frac) * sample_level(t, d1, st, linear_in_level) +
         frac * sample_level(t, d1 + 1, st, linear_in_level);
}

glm::vec4 apply_texture_env(TextureEnvMode mode, TextureFormat format, const glm::vec4& f,
                            const glm::vec4& t, const glm::vec4& env) {
  glm::vec3 cf(f), ct(t), cc(env);
  bool has_color = format != TextureFormat::kAlpha;
  bool has_alpha = format == TextureFormat::kAlpha || format == TextureFormat::kLuminanceAlpha ||
                   format == TextureFormat::kIntensity || format == TextureFormat::kRgba;
  float at = t.a;
  switch (mode) {
    case TextureEnvMode::kReplace:
      return glm::vec4(has_color ? ct : cf, has_alpha ? at : f.a);
    case TextureEnvMode::kModulate:
      return glm::vec4(has_color ? cf * ct : cf, has_alpha ? f.a * at : f.a);
    case TextureEnvMode::kDecal:  // defined for RGB and RGBA only; others keep the fragment
      if (format == TextureFormat::kRgb) return glm::vec4(ct, f.a);
      if (format == TextureFormat::kRgba) return glm::vec4(cf * (1.0f - at) + ct * at, f.a);
      return f;
    case TextureEnvMode::kBlend: {
      glm::vec3 c = has_color ? cf * (1.0f - ct) + cc * ct : cf;
      float a = format == TextureFormat::kIntensity ? f.a * (1.0f - at) + env.a * at
                                                    : (has_alpha ? f.a * at : f.a);
      return glm::vec4(c, a);
    }
  }
  return f;
}

}  // namespace shadelab
