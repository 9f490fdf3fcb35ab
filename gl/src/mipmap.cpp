// Automatic mipmap generation (GL 1.4 section 3.8.8, GL_GENERATE_MIPMAP): when the base level
// of a texture whose GL_GENERATE_MIPMAP is on changes (glTexImage, glTexSubImage, glCopyTex*),
// the levels after it, down to q (GL 1.5 section 3.8.10), are made again from it, each from
// the one before. As Mesa's state tracker does it on llvmpipe (st_generate_mipmap, then
// util_gen_mipmap's blits): every level takes the base level's internal format and is the
// previous level sampled bilinearly at its texel centres, clamped to the edge; for formats of
// 8 bits a component or fewer, in llvmpipe's 8-bit arithmetic (8.8 fixed-point positions,
// lerps rounded as pmulhrsw rounds), otherwise in float. Halving sizes, that is the 2x2 box
// filter (2x2x2 for 3D levels). State only: the texels are stored through store_texels.
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

// Level `to` (already defined, its sizes set) made from level `from`: bilinear within an
// image, then between two images for a 3D level (llvmpipe's order of lerps).
void filter_level(TextureObject& t, int from, int to) {
  const TexImage& src = t.images[std::size_t(from)];
  const TextureLevel& src_core = t.texture.levels[std::size_t(from)];
  TexImage& dst = t.images[std::size_t(to)];
  const bool bytes = !src.format.wide(), three_d = t.texture.dimensions == 3;
  RgbaImage image;
  image.width = dst.width, image.height = dst.height, image.depth = dst.depth;
  image.exact_bytes = bytes;
  image.rgba.resize(std::size_t(dst.width) * std::size_t(dst.height) * std::size_t(dst.depth) * 4);
  float* out = image.rgba.data();
  for (int z = 0; z < dst.depth; ++z) {
    const Tap tz = three_d ? tap(z, dst.depth, src.depth) : Tap{0, 0, 0};
    for (int y = 0; y < dst.height; ++y) {
      const Tap ty = tap(y, dst.height, src.height);
      for (int x = 0; x < dst.width; ++x, out += 4) {
        const Tap tx = tap(x, dst.width, src.width);
        std::size_t corner[8];
        for (int c = 0; c < 8; ++c) {
          const int k = c & 4 ? tz.i1 : tz.i0, j = c & 2 ? ty.i1 : ty.i0, i = c & 1 ? tx.i1 : tx.i0;
          corner[c] = (std::size_t(k) * std::size_t(src.height) + std::size_t(j)) * std::size_t(src.width) + std::size_t(i);
        }
        const int slices = three_d ? 2 : 1;
        if (bytes) {
          for (std::size_t k = 0; k < 4; ++k) {
            int v[2];
            for (int sl = 0; sl < slices; ++sl) {
              int q[4];
              for (int c = 0; c < 4; ++c) q[c] = src_core.rgba[corner[sl * 4 + c] * 4 + k];
              v[sl] = lerp8(lerp8(q[0], q[1], tx.w), lerp8(q[2], q[3], tx.w), ty.w);
            }
            out[k] = float(three_d ? lerp8(v[0], v[1], tz.w) : v[0]) / 255.0f;
          }
          continue;
        }
        const float a = float(tx.w) / 256.0f, b = float(ty.w) / 256.0f, cz = float(tz.w) / 256.0f;
        float v[2][4];
        for (int sl = 0; sl < slices; ++sl) {
          float q[4][4];
          for (int c = 0; c < 4; ++c) texel_rgba(src, src_core, corner[sl * 4 + c], q[c]);
          for (int k = 0; k < 4; ++k) {
            const float top = q[0][k] + a * (q[1][k] - q[0][k]), bottom = q[2][k] + a * (q[3][k] - q[2][k]);
            v[sl][k] = top + b * (bottom - top);
          }
        }
        for (int k = 0; k < 4; ++k) out[k] = three_d ? v[0][k] + cz * (v[1][k] - v[0][k]) : v[0][k];
      }
    }
  }
  store_texels(image, 0, 0, 0, dst, t.texture.levels[std::size_t(to)]);
}

}  // namespace

void level_changed(TextureObject& t, int level) {
  const Texture& x = t.texture;
  if (!t.generate_mipmap || level != x.base_level || level >= x.max_level) return;
  if (t.target == kTextureRectangle) return;  // one level (ARB_texture_rectangle)
  if (t.images.size() <= std::size_t(level) || !t.images[std::size_t(level)].defined) return;
  const TexImage& base = t.images[std::size_t(level)];
  if (base.width <= 0 || base.height <= 0 || base.depth <= 0) return;
  if (base.format.depth) return;  // depth textures: no levels are generated (not implemented)
  int w = base.width, h = base.height, d = base.depth, n = 0;
  int size = std::max({w, x.dimensions == 1 ? 1 : h, x.dimensions == 3 ? d : 1});
  while (size > 1) size /= 2, ++n;
  const int levels = x.dimensions == 3 ? kMax3dTextureLevels : max_texture_levels();
  const int last = std::min({level + n, x.max_level, levels - 1});
  const GLint internal = base.internal_format;
  for (int l = level + 1; l <= last; ++l) {
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    d = x.dimensions == 3 ? std::max(1, d / 2) : 1;
    define_level(t, l, internal, w, h, d);
    filter_level(t, l - 1, l);
  }
}

}  // namespace shadelab::gl
