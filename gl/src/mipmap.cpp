// Automatic mipmap generation (GL 1.4 section 3.8.8, GL_GENERATE_MIPMAP): when the base level
// of a texture whose GL_GENERATE_MIPMAP is on changes (glTexImage, glTexSubImage, glCopyTex*),
// the levels after it, down to q (GL 1.5 section 3.8.10), are made again from it, each from
// the one before. As Mesa's state tracker does it on llvmpipe (st_generate_mipmap, then
// util_gen_mipmap's blits): every level takes the base level's internal format and is the
// previous level sampled bilinearly at its texel centres, clamped to the edge; for formats of
// 8 bits a component or fewer, in llvmpipe's 8-bit arithmetic (8.8 fixed-point positions,
// lerps rounded as pmulhrsw rounds), otherwise in float. Halving sizes, that is the 2x2 box
// filter. State only: the texels are stored through store_texels.
#include <algorithm>

#include "gl/src/texture.hpp"

namespace shadelab::gl {
namespace {

// Where destination texel x samples a source of `src` texels (the blit's texture coordinate at
// the pixel centre, (x + 1/2) / dst, in 8.8 fixed point less half a texel, as
// lp_bld_sample_aos.c's linear filter takes it): the two texels, clamped to the edge, and the
// weight of the second in 256ths.
struct Tap {
  int i0, i1, w;
};

Tap tap(int x, int dst, int src) {
  const float s = (float(x) + 0.5f) / float(dst);
  const int fixed = int(s * float(src) * 256.0f) - 128;
  const int i = fixed >> 8;
  return {std::clamp(i, 0, src - 1), std::clamp(i + 1, 0, src - 1), fixed & 255};
}

// llvmpipe's 8-bit lerp with a weight in 256ths (lp_build_lerp_simple through pmulhrsw):
// a + round(w (b - a) / 256), halves rounded up.
int lerp8(int a, int b, int w) { return a + ((w * (b - a) + 128) >> 8); }

// Texel i of a level as RGBA in [0, 1], its base format expanded as the core's level is.
void texel_rgba(const TexImage& img, const TextureLevel& core, std::size_t i, float out[4]) {
  const StoredFormat& f = img.format;
  if (!f.wide()) {
    for (int k = 0; k < 4; ++k) out[k] = float(core.rgba[i * 4 + std::size_t(k)]) / 255.0f;
    return;
  }
  float c[4] = {0, 0, 0, 0};
  const std::size_t n = std::size_t(f.components);
  for (std::size_t k = 0; k < n; ++k) c[k] = stored_to_float(img.wide[i * n + k], f.bits[k]);
  switch (f.base) {
    case TextureFormat::kAlpha: out[0] = out[1] = out[2] = 0.0f, out[3] = c[0]; return;
    case TextureFormat::kLuminance: out[0] = out[1] = out[2] = c[0], out[3] = 1.0f; return;
    case TextureFormat::kLuminanceAlpha: out[0] = out[1] = out[2] = c[0], out[3] = c[1]; return;
    case TextureFormat::kIntensity: out[0] = out[1] = out[2] = out[3] = c[0]; return;
    case TextureFormat::kRgb: out[0] = c[0], out[1] = c[1], out[2] = c[2], out[3] = 1.0f; return;
    case TextureFormat::kRgba: std::copy(c, c + 4, out); return;
  }
}

// Level `to` (already defined, its sizes set) made from level `from`.
void filter_level(TextureObject& t, int from, int to) {
  const TexImage& src = t.images[std::size_t(from)];
  const TextureLevel& src_core = t.texture.levels[std::size_t(from)];
  TexImage& dst = t.images[std::size_t(to)];
  const bool bytes = !src.format.wide();
  RgbaImage image;
  image.width = dst.width, image.height = dst.height;
  image.exact_bytes = bytes;
  image.rgba.resize(std::size_t(dst.width) * std::size_t(dst.height) * 4);
  float* out = image.rgba.data();
  for (int y = 0; y < dst.height; ++y) {
    const Tap ty = tap(y, dst.height, src.height);
    for (int x = 0; x < dst.width; ++x, out += 4) {
      const Tap tx = tap(x, dst.width, src.width);
      const std::size_t row0 = std::size_t(ty.i0) * std::size_t(src.width), row1 = std::size_t(ty.i1) * std::size_t(src.width);
      const std::size_t corner[4] = {row0 + std::size_t(tx.i0), row0 + std::size_t(tx.i1), row1 + std::size_t(tx.i0),
                                     row1 + std::size_t(tx.i1)};
      if (bytes) {
        for (std::size_t k = 0; k < 4; ++k) {
          int v[4];
          for (int c = 0; c < 4; ++c) v[c] = src_core.rgba[corner[c] * 4 + k];
          const int top = lerp8(v[0], v[1], tx.w), bottom = lerp8(v[2], v[3], tx.w);
          out[k] = float(lerp8(top, bottom, ty.w)) / 255.0f;
        }
        continue;
      }
      float v[4][4];
      for (int c = 0; c < 4; ++c) texel_rgba(src, src_core, corner[c], v[c]);
      const float a = float(tx.w) / 256.0f, b = float(ty.w) / 256.0f;
      for (int k = 0; k < 4; ++k) {
        const float top = v[0][k] + a * (v[1][k] - v[0][k]), bottom = v[2][k] + a * (v[3][k] - v[2][k]);
        out[k] = top + b * (bottom - top);
      }
    }
  }
  store_texels(image, 0, 0, dst, t.texture.levels[std::size_t(to)]);
}

}  // namespace

void level_changed(TextureObject& t, int level) {
  const Texture& x = t.texture;
  if (!t.generate_mipmap || level != x.base_level || level >= x.max_level) return;
  if (t.images.size() <= std::size_t(level) || !t.images[std::size_t(level)].defined) return;
  const TexImage& base = t.images[std::size_t(level)];
  if (base.width <= 0 || base.height <= 0) return;
  int w = base.width, h = base.height, size = std::max(w, t.target == GL_TEXTURE_1D ? 1 : h), n = 0;
  while (size > 1) size /= 2, ++n;
  const int last = std::min({level + n, x.max_level, max_texture_levels() - 1});
  const GLint internal = base.internal_format;
  for (int l = level + 1; l <= last; ++l) {
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    define_level(t, l, internal, w, h);
    filter_level(t, l - 1, l);
  }
}

}  // namespace shadelab::gl
