// Texture images (GL 1.1 sections 3.8.1, 3.8.2; GL 1.2's 3D images): glTexImage1D/2D/3D with
// every GL 1.1 internal format, the proxy targets, glTexSubImage1D/2D/3D, and the storage shared with the copies
// (texcopy.cpp). Errors and their order are Mesa's (teximage.c's texture_error_check and
// texsubimage_error_check). As in Mesa's gallium drivers, a border is stripped from the
// image when it is stored (GL_CLAMP blends in GL_TEXTURE_BORDER_COLOR instead); proxies keep
// the sizes as given.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "gl/generated/exec.hpp"
#include "gl/generated/run.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/pixel_transfer.hpp"
#include "gl/src/pixels.hpp"
#include "gl/src/texture.hpp"

namespace shadelab::gl {
namespace {

bool is_pixel_type(GLenum type) {
  return type == GL_BITMAP || pixel_type_size(type) != 0;
}

bool is_pixel_format(GLenum format) {
  return color_format_components(format) != 0 || format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX ||
         format == GL_DEPTH_COMPONENT || format == kDepthStencil;
}

// Mesa's _mesa_error_check_format_and_type and texture_formats_agree for a colour texture:
// unknown enums and GL_BITMAP with other than an index format are GL_INVALID_ENUM, a packed
// type with a format it does not pack, depth and stencil images GL_INVALID_OPERATION.
GLenum check_format_and_type(GLenum format, GLenum type) {
  if (!is_pixel_format(format) || !is_pixel_type(type)) return GL_INVALID_ENUM;
  if (type == GL_BITMAP && format != GL_COLOR_INDEX && format != GL_STENCIL_INDEX) return GL_INVALID_ENUM;
  return format_type_error(format, type);
}

// Mesa's texture_formats_agree: depth (and depth-stencil) images for depth internal formats
// only (GL 1.4), and the other way round; no stencil images.
bool formats_agree(GLenum format, bool depth_internal) {
  return format != GL_STENCIL_INDEX && (format == GL_DEPTH_COMPONENT || format == kDepthStencil) == depth_internal;
}

// A GL_DEPTH_COMPONENT client image's values (converted, scaled and biased as glDrawPixels'
// depth, section 3.6.4), clamped to [0, 1], stored at (x, y) of a depth level; a
// GL_DEPTH_STENCIL image's stencil indices too, when the level keeps them.
void store_depths(const GlContext& c, int x0, int y0, int width, int height, GLenum format, GLenum type,
                  const void* pixels, TexImage& img, TextureLevel& core) {
  if (!pixels || width <= 0 || height <= 0) return;
  std::vector<float> depths;
  std::vector<std::uint8_t> stencil;
  if (format == kDepthStencil) unpack_depth_stencil_image(c, pixels, width, height, depths, stencil);
  else unpack_depth_image(c, pixels, width, height, type, depths);
  const bool keeps_stencil = !stencil.empty() && !img.stencil.empty();
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t from = std::size_t(y) * std::size_t(width) + std::size_t(x);
      const std::size_t to = std::size_t(y0 + y) * std::size_t(core.width) + std::size_t(x0 + x);
      core.depth_values[to] = stored_depth_value(depths[from], img.format.bits[0]);
      if (keeps_stencil) img.stencil[to] = stencil[from];
    }
  }
}

// Mesa's _mesa_legal_texture_dimensions: each side from 2 border to 2 border + the largest
// size at that level (any size in between: non-power-of-two sizes are accepted). 3D
// textures have their own limit (GL_MAX_3D_TEXTURE_SIZE).
bool legal_size(int size, int border, int level, int dims) {
  const long max = long(dims == 3 ? kMax3dTextureSize : kMaxTextureSize) >> level;
  return size >= 2 * border && long(size) <= 2 * border + max;
}

// llvmpipe makes no texture of more than 1 GiB (LP_MAX_TEXTURE_SIZE): a 3D image past it, or
// a cube map's face whose six faces would be, is GL_OUT_OF_MEMORY (a proxy: not made).
bool fits_in_memory(int width, int height, int depth) {
  return double(width) * double(height) * double(depth) * 4.0 <= double(1u << 30);
}

std::vector<TexImage>& proxy_images(GlContext& c, GLenum target) {
  if (target == GL_PROXY_TEXTURE_CUBE_MAP) return c.textures.proxy_cube;
  if (target == kProxyTextureRectangle) return c.textures.proxy_rect;
  return target == GL_PROXY_TEXTURE_1D ? c.textures.proxy_1d
                                       : target == GL_PROXY_TEXTURE_3D ? c.textures.proxy_3d : c.textures.proxy_2d;
}

// glTexImage2D's and glCopyTexImage2D's targets besides GL_TEXTURE_2D: a cube map's faces
// (GL 1.3), whose images are square (Mesa's _mesa_legal_texture_dimensions).
bool is_cube_target(GLenum target) { return is_cube_face(target) || target == GL_PROXY_TEXTURE_CUBE_MAP; }

// A proxy's level as glTexImage would have made it (sizes as given, border kept), or cleared
// when the image could not be made.
void set_proxy(GlContext& c, GLenum target, int level, GLint internal, int width, int height, int depth, int border,
               bool ok) {
  std::vector<TexImage>& images = proxy_images(c, target);
  if (images.size() <= std::size_t(level)) images.resize(std::size_t(level) + 1);
  TexImage& img = images[std::size_t(level)];
  img = TexImage{};
  if (!ok) return;
  img.defined = true;
  img.width = width, img.height = height, img.depth = depth, img.border = border;
  img.internal_format = internal;
  stored_format(internal, img.format);
}

// The client image's pixels as RGBA, its border skipped (`skip` pixels on each side it has;
// skip_z whole images of a 3D image), image by image (GL_UNPACK_IMAGE_HEIGHT and
// GL_UNPACK_SKIP_IMAGES lay the images out).
RgbaImage unpack(const GlContext& c, int row_pixels, int rows, int skip_x, int skip_y, int skip_z, int width, int height,
                 int depth, bool three_d, GLenum format, GLenum type, const void* pixels) {
  RgbaImage image;
  image.width = width, image.height = height, image.depth = depth;
  const std::size_t slice = std::size_t(width) * std::size_t(height) * 4;
  image.rgba.assign(slice * std::size_t(depth), 0.0f);
  image.exact_bytes = type == GL_UNSIGNED_BYTE && format != GL_COLOR_INDEX;
  if (!pixels || width <= 0 || height <= 0) return image;
  const std::size_t stride = three_d ? image_stride(c.unpack, format, type, row_pixels, rows) : 0;
  for (int z = 0; z < depth; ++z) {
    const std::size_t first = three_d ? std::size_t(c.unpack.skip_images + skip_z + z) * stride : 0;
    const void* images = static_cast<const unsigned char*>(pixels) + first;
    unpack_rgba_image(c, c.unpack, row_pixels, skip_x, skip_y, width, height, format, type, images,
                      image.rgba.data() + slice * std::size_t(z));
  }
  return image;
}

// unpack, then store_texels at (x0, y0, z0): a 1D or 2D image band by band (64 rows at a time,
// on the pipeline's threads when there are several bands), so that a large image is never held
// whole as floats (a 16384 x 16384 one would take 4 GiB).
void store_client_image(GlContext& c, int row_pixels, int rows, int skip_x, int skip_y, int skip_z, int width,
                        int height, int depth, bool three_d, GLenum format, GLenum type, const void* pixels, int x0,
                        int y0, int z0, TexImage& img, TextureLevel& core) {
  if (three_d) {
    const RgbaImage image = unpack(c, row_pixels, rows, skip_x, skip_y, skip_z, width, height, depth, true, format, type,
                                   pixels);
    return store_texels(image, x0, y0, z0, img, core);
  }
  constexpr int kBand = 64;
  const std::size_t bands = std::size_t((height + kBand - 1) / kBand);
  auto store = [&](std::size_t first, std::size_t end) {  // bands [first, end): disjoint rows
    for (std::size_t b = first; b < end; ++b) {
      const int r = int(b) * kBand, h = std::min(kBand, height - r);
      const RgbaImage image = unpack(c, row_pixels, rows, skip_x, skip_y + r, skip_z, width, h, 1, false, format, type,
                                     pixels);
      store_texels(image, x0, y0 + r, z0, img, core);
    }
  };
  if (bands < 4) return store(0, bands);
  make_pipeline(c);
  if (c.pipeline) c.pipeline->parallel_for(bands, 1, store);
  else store(0, bands);
}

// The usual upload, an 8-bit RGB(A) or BGR(A) image into a level of 8-bit components with no
// pixel transfer, copied byte for byte (rows of RGBA into RGBA at memcpy speed) instead of
// through floats: the texels the general path stores (an unsigned byte reads back exactly;
// the level keeps red as luminance and intensity, alpha as alpha, as base_components does).
// Images `skip_z` .., rows `skip_y` .. and pixels `skip_x` .. of the client image (rows of
// `row_pixels`, images of `rows` rows when `three_d`) go to texels (x0, y0, z0) ...; false,
// with nothing stored, when the image or the level is another kind.
struct ByteCopy {
  int row_pixels = 0, rows = 0, skip_x = 0, skip_y = 0, skip_z = 0;
  int width = 0, height = 0, depth = 1;
  int x0 = 0, y0 = 0, z0 = 0;
  bool three_d = false;
};

bool store_bytes(const GlContext& c, const ByteCopy& b, GLenum format, GLenum type, const void* pixels,
                 const TexImage& img, TextureLevel& core) {
  const StoredFormat& f = img.format;
  if (type != GL_UNSIGNED_BYTE || !pixels || f.depth) return false;
  for (int i = 0; i < f.components; ++i) {
    if (f.bits[i] != 8) return false;
  }
  const PixelTransfer& t = c.pixel;
  if (t.map_color) return false;
  for (std::size_t i = 0; i < 4; ++i) {
    if (t.scale[i] != 1.0f || t.bias[i] != 0.0f) return false;
  }
  ByteOrder order;
  if (!byte_order(format, order)) return false;
  const int n = order.components, r = order.red, bl = order.blue;
  const PixelLayout layout = pixel_layout(c.unpack, n, 1, b.row_pixels);
  const std::size_t stride = b.three_d ? image_stride(c.unpack, format, type, b.row_pixels, b.rows) : 0;
  const auto* in = static_cast<const unsigned char*>(pixels);
  const bool copy_rows = f.base == TextureFormat::kRgba && order.rgba();
  for (int z = 0; z < b.depth; ++z) {
    const unsigned char* image = in + (b.three_d ? std::size_t(c.unpack.skip_images + b.skip_z + z) * stride : 0);
    for (int y = 0; y < b.height; ++y) {
      const unsigned char* src = image + layout.offset(b.skip_x, b.skip_y + y);
      const std::size_t row = std::size_t(b.z0 + z) * std::size_t(core.height) + std::size_t(b.y0 + y);
      std::uint8_t* dst = &core.rgba[(row * std::size_t(core.width) + std::size_t(b.x0)) * 4];
      if (copy_rows) {
        std::memcpy(dst, src, std::size_t(b.width) * 4);
        continue;
      }
      for (int x = 0; x < b.width; ++x, src += n, dst += 4) {
        const std::uint8_t red = src[r], alpha = n == 4 ? src[3] : 255;
        switch (f.base) {
          case TextureFormat::kRgba: dst[0] = red, dst[1] = src[1], dst[2] = src[bl], dst[3] = alpha; break;
          case TextureFormat::kRgb: dst[0] = red, dst[1] = src[1], dst[2] = src[bl], dst[3] = 255; break;
          case TextureFormat::kLuminance: dst[0] = dst[1] = dst[2] = red, dst[3] = 255; break;
          case TextureFormat::kIntensity: dst[0] = dst[1] = dst[2] = dst[3] = red; break;
          case TextureFormat::kLuminanceAlpha: dst[0] = dst[1] = dst[2] = red, dst[3] = alpha; break;
          case TextureFormat::kAlpha: dst[0] = dst[1] = dst[2] = 0, dst[3] = alpha; break;
        }
      }
    }
  }
  return true;
}

GLenum plain_target(int dims) { return dims == 1 ? GL_TEXTURE_1D : dims == 3 ? GL_TEXTURE_3D : GL_TEXTURE_2D; }
int max_levels(int dims) { return dims == 3 ? kMax3dTextureLevels : kMaxTextureLevels; }

// glTexImage1D (dims 1, height 1), glTexImage2D and glTexImage3D.
void tex_image(GlContext& c, int dims, GLenum target, GLint level, GLint internal, GLsizei width, GLsizei height,
               GLsizei depth, GLint border, GLenum format, GLenum type, const void* pixels) {
  const GLenum plain = plain_target(dims);
  GLenum proxy = dims == 1 ? GL_PROXY_TEXTURE_1D : dims == 3 ? GL_PROXY_TEXTURE_3D : GL_PROXY_TEXTURE_2D;
  const bool cube = dims == 2 && is_cube_target(target);
  if (cube) proxy = GL_PROXY_TEXTURE_CUBE_MAP;
  // ARB_texture_rectangle: one level, no border.
  const bool rect = dims == 2 && (target == kTextureRectangle || target == kProxyTextureRectangle);
  if (rect) proxy = kProxyTextureRectangle;
  if (target != plain && target != proxy && !cube && !rect) return c.set_error(GL_INVALID_ENUM);
  if (level < 0 || level >= (rect ? 1 : max_levels(dims))) return c.set_error(GL_INVALID_VALUE);
  if (border < 0 || border > (rect ? 0 : 1)) return c.set_error(GL_INVALID_VALUE);
  if (width < 0 || height < 0 || depth < 0) return c.set_error(GL_INVALID_VALUE);
  if (GLenum e = check_format_and_type(format, type)) return c.set_error(e);
  StoredFormat stored;
  if (!stored_format(internal, stored)) return c.set_error(GL_INVALID_VALUE);
  if (!formats_agree(format, stored.depth)) return c.set_error(GL_INVALID_OPERATION);
  if (stored.depth && dims == 3) return c.set_error(GL_INVALID_OPERATION);  // 1D and 2D depth textures (Mesa)
  const bool legal = legal_size(width, border, level, dims) && (dims == 1 || legal_size(height, border, level, dims)) &&
                     (dims < 3 || legal_size(depth, border, level, dims)) && (!cube || width == height);
  const bool fits = cube ? fits_in_memory(width, height, 6) : dims < 3 || fits_in_memory(width, height, depth);
  if (target == proxy) return set_proxy(c, target, level, internal, width, height, depth, border, legal && fits);
  if (!legal) return c.set_error(GL_INVALID_VALUE);
  if (!fits) return c.set_error(GL_OUT_OF_MEMORY);
  // Mesa's strip_texture_border: the border's pixels are skipped, the sides lose two.
  const int inner_w = width - 2 * border;
  const bool strip_rows = dims >= 2 && border && height >= 3, strip_images = dims == 3 && border && depth >= 3;
  const int inner_h = strip_rows ? height - 2 : height, inner_d = strip_images ? depth - 2 : depth;
  TextureObject& t = *image_texture(c, target);
  if (stored.depth) {  // GL 1.4: a depth image (its border, if any, left out of the client image's rows)
    texture_changing(c, t);
    define_level(t, level, internal, inner_w, inner_h, 1);
    store_depths(c, 0, 0, inner_w, inner_h, format, type, pixels, t.images[std::size_t(level)],
                 t.texture.levels[std::size_t(level)]);
    return image_changed(c, target, t, level);
  }
  texture_changing(c, t);
  define_level(t, level, internal, inner_w, inner_h, inner_d);
  TexImage& img = t.images[std::size_t(level)];
  TextureLevel& core = t.texture.levels[std::size_t(level)];
  // No image (pixels null): the level as define_level made it (GL leaves it undefined).
  ByteCopy copy;
  copy.row_pixels = width, copy.rows = height, copy.skip_x = border, copy.skip_y = strip_rows ? 1 : 0;
  copy.skip_z = strip_images ? 1 : 0, copy.width = inner_w, copy.height = inner_h, copy.depth = inner_d;
  copy.three_d = dims == 3;
  if (pixels && !store_bytes(c, copy, format, type, pixels, img, core)) {
    store_client_image(c, width, height, border, strip_rows ? 1 : 0, strip_images ? 1 : 0, inner_w, inner_h, inner_d,
                       dims == 3, format, type, pixels, 0, 0, 0, img, core);
  }
  image_changed(c, target, t, level);
}

// glTexSubImage1D (dims 1), glTexSubImage2D and glTexSubImage3D.
void tex_sub_image(GlContext& c, int dims, GLenum target, GLint level, GLint x, GLint y, GLint z, GLsizei width,
                   GLsizei height, GLsizei depth, GLenum format, GLenum type, const void* pixels) {
  const bool rect = dims == 2 && target == kTextureRectangle;
  if (target != plain_target(dims) && !(dims == 2 && is_cube_face(target)) && !rect) return c.set_error(GL_INVALID_ENUM);
  if (level < 0 || level >= (rect ? 1 : max_levels(dims))) return c.set_error(GL_INVALID_VALUE);
  if (GLenum e = check_format_and_type(format, type)) return c.set_error(e);
  TextureObject& t = *image_texture(c, target);
  if (t.images.size() <= std::size_t(level) || !t.images[std::size_t(level)].defined) {
    return c.set_error(GL_INVALID_OPERATION);
  }
  TexImage& img = t.images[std::size_t(level)];
  if (width < 0 || height < 0 || depth < 0) return c.set_error(GL_INVALID_VALUE);
  if (x < 0 || y < 0 || z < 0 || long(x) + width > img.width || long(y) + height > img.height ||
      long(z) + depth > img.depth) {
    return c.set_error(GL_INVALID_VALUE);
  }
  if (!formats_agree(format, img.format.depth)) return c.set_error(GL_INVALID_OPERATION);
  if (width == 0 || height == 0 || depth == 0 || !pixels) return;
  if (img.format.depth) {
    texture_changing(c, t);
    store_depths(c, x, y, width, height, format, type, pixels, img, t.texture.levels[std::size_t(level)]);
    return image_changed(c, target, t, level);
  }
  texture_changing(c, t);
  TextureLevel& core = t.texture.levels[std::size_t(level)];
  ByteCopy copy;
  copy.row_pixels = width, copy.rows = height, copy.width = width, copy.height = height, copy.depth = depth;
  copy.x0 = x, copy.y0 = y, copy.z0 = z, copy.three_d = dims == 3;
  if (!store_bytes(c, copy, format, type, pixels, img, core)) {
    store_client_image(c, width, height, 0, 0, 0, width, height, depth, dims == 3, format, type, pixels, x, y, z, img,
                       core);
  }
  image_changed(c, target, t, level);
}

// What a display list keeps of a client image (GL 1.1 section 5.4): its pixels as the unpack
// state of the moment reads them, tightly packed (the list replays the command with the
// default unpack state); empty when the command will not read them (it is then recorded
// without pixels and fails, or makes an image of undefined contents, when the list runs).
std::vector<unsigned char> list_image(const GlContext& c, int width, int height, GLenum format, GLenum type,
                                      const void* pixels, int depth = 0) {
  const int limit = kMaxTextureSize + 2;
  // depth 0: a 1D or 2D image (GL_UNPACK_SKIP_IMAGES does not apply).
  if (!pixels || width <= 0 || height <= 0 || depth < 0 || width > limit || height > limit || depth > limit) return {};
  if (type == GL_BITMAP) {
    if (format != GL_COLOR_INDEX || depth > 0) return {};
    return copy_bitmap(c.unpack, width, height, pixels);
  }
  const int components = format == GL_COLOR_INDEX || format == GL_DEPTH_COMPONENT ? 1
                         : color_format_components(format)                      ? elements_per_pixel(format, type)
                                                                                : 0;
  const int size = pixel_type_size(type);
  if (components == 0 || size == 0) return {};
  if (depth == 0) return copy_image(c.unpack, width, height, components, size, pixels);
  // A 3D image: each image as copy_image reads a 2D one, after the skipped images.
  const std::size_t stride = image_stride(c.unpack, format, type, width, height);
  std::vector<unsigned char> out;
  for (int z = 0; z < depth; ++z) {
    const auto* image = static_cast<const unsigned char*>(pixels) + std::size_t(c.unpack.skip_images + z) * stride;
    const std::vector<unsigned char> one = copy_image(c.unpack, width, height, components, size, image);
    out.insert(out.end(), one.begin(), one.end());
  }
  return out;
}

const void* data_or_null(const std::vector<unsigned char>& image) { return image.empty() ? nullptr : image.data(); }

}  // namespace

bool define_level(TextureObject& t, int level, GLint internal_format, int width, int height, int depth) {
  StoredFormat format;
  if (!stored_format(internal_format, format)) return false;
  const std::size_t l = std::size_t(level);
  if (t.images.size() <= l) t.images.resize(l + 1);
  if (t.texture.levels.size() <= l) t.texture.levels.resize(l + 1);
  const std::size_t texels = std::size_t(width) * std::size_t(height) * std::size_t(depth);
  TexImage& img = t.images[l];
  img = TexImage{};
  img.defined = true;
  img.width = width, img.height = height, img.depth = depth;
  img.internal_format = internal_format;
  img.format = format;
  if (format.wide()) img.wide.assign(texels * std::size_t(format.components), 0);
  if (format.stencil_bits) img.stencil.assign(texels, 0);
  TextureLevel& core = t.texture.levels[l];
  core.width = width, core.height = height, core.depth = depth;
  core.rgba.assign(texels * 4, 0);
  if (format.depth) core.depth_values.assign(texels, 0.0f);
  else core.depth_values.clear();
  if (level == 0) t.texture.format = format.base;
  return true;
}

namespace {

// A component in [0, 1] as `bits` bits, as Mesa stores it (see RgbaImage).
std::uint16_t stored_value(const RgbaImage& image, float v, int bits) {
  if (!image.exact_bytes) return quantize(v, bits);
  const auto byte = std::uint8_t(std::lround(v * 255.0f));
  return image.from_framebuffer && bits == 5 ? std::uint16_t(byte >> 3) : quantize_byte(byte, bits);
}

}  // namespace

void store_texels(const RgbaImage& image, int x0, int y0, int z0, TexImage& level, TextureLevel& core) {
  const StoredFormat& f = level.format;
  const std::size_t n = std::size_t(f.components);
  const float* in = image.rgba.data();
  for (int yz = 0; yz < image.height * image.depth; ++yz) {  // rows of every image in turn
    const int y = yz % image.height, z = yz / image.height;
    const std::size_t row = std::size_t(z0 + z) * std::size_t(level.height) + std::size_t(y0 + y);
    for (int x = 0; x < image.width; ++x, in += 4) {
      const std::size_t texel = row * std::size_t(level.width) + std::size_t(x0 + x);
      float comps[4];
      base_components(f.base, in, comps);
      std::uint8_t bytes[4];
      for (std::size_t i = 0; i < n; ++i) {
        const int bits = f.bits[i];
        const std::uint16_t k = stored_value(image, comps[i], bits);
        if (!level.wide.empty()) level.wide[texel * n + i] = k;
        bytes[i] = stored_to_byte(k, bits);
      }
      expand_texel(f.base, bytes, &core.rgba[texel * 4]);
    }
  }
}

void exec::TexImage1D(GlContext& c, GLenum target, GLint level, GLint internalformat, GLsizei width, GLint border,
                      GLenum format, GLenum type, const void* pixels) {
  tex_image(c, 1, target, level, internalformat, width, 1, 1, border, format, type, pixels);
}

void exec::TexImage2D(GlContext& c, GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height,
                      GLint border, GLenum format, GLenum type, const void* pixels) {
  tex_image(c, 2, target, level, internalformat, width, height, 1, border, format, type, pixels);
}

void exec::TexSubImage1D(GlContext& c, GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format,
                         GLenum type, const void* pixels) {
  tex_sub_image(c, 1, target, level, xoffset, 0, 0, width, 1, 1, format, type, pixels);
}

void exec::TexSubImage2D(GlContext& c, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width,
                         GLsizei height, GLenum format, GLenum type, const void* pixels) {
  tex_sub_image(c, 2, target, level, xoffset, yoffset, 0, width, height, 1, format, type, pixels);
}

void exec::TexImage3D(GlContext& c, GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height,
                      GLsizei depth, GLint border, GLenum format, GLenum type, const void* pixels) {
  tex_image(c, 3, target, level, internalformat, width, height, depth, border, format, type, pixels);
}

void exec::TexSubImage3D(GlContext& c, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                         GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type, const void* pixels) {
  tex_sub_image(c, 3, target, level, xoffset, yoffset, zoffset, width, height, depth, format, type, pixels);
}

// Display-list savers (gl/generated/save.hpp). Proxies are queries: executed at once and
// not compiled, as in Mesa.
void save::TexImage1D(GlContext& c, GLenum target, GLint level, GLint internalformat, GLsizei width, GLint border,
                      GLenum format, GLenum type, const void* pixels) {
  if (target == GL_PROXY_TEXTURE_1D) {
    if (c.lists.mode == GL_COMPILE) run::TexImage1D(c, target, level, internalformat, width, border, format, type, pixels);
    return;
  }
  const std::vector<unsigned char> image = list_image(c, width, 1, format, type, pixels);
  record::TexImage1D(c, target, level, internalformat, width, border, format, type, data_or_null(image), image.size());
}

void save::TexImage2D(GlContext& c, GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height,
                      GLint border, GLenum format, GLenum type, const void* pixels) {
  if (target == GL_PROXY_TEXTURE_2D || target == GL_PROXY_TEXTURE_CUBE_MAP) {
    if (c.lists.mode == GL_COMPILE) {
      run::TexImage2D(c, target, level, internalformat, width, height, border, format, type, pixels);
    }
    return;
  }
  const std::vector<unsigned char> image = list_image(c, width, height, format, type, pixels);
  record::TexImage2D(c, target, level, internalformat, width, height, border, format, type, data_or_null(image),
                     image.size());
}

void save::TexImage3D(GlContext& c, GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height,
                      GLsizei depth, GLint border, GLenum format, GLenum type, const void* pixels) {
  if (target == GL_PROXY_TEXTURE_3D) {
    if (c.lists.mode == GL_COMPILE) {
      run::TexImage3D(c, target, level, internalformat, width, height, depth, border, format, type, pixels);
    }
    return;
  }
  const std::vector<unsigned char> image = list_image(c, width, height, format, type, pixels, depth);
  record::TexImage3D(c, target, level, internalformat, width, height, depth, border, format, type,
                     data_or_null(image), image.size());
}

void save::TexSubImage3D(GlContext& c, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                         GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type, const void* pixels) {
  const std::vector<unsigned char> image = list_image(c, width, height, format, type, pixels, depth);
  record::TexSubImage3D(c, target, level, xoffset, yoffset, zoffset, width, height, depth, format, type,
                        data_or_null(image), image.size());
}

void save::TexSubImage1D(GlContext& c, GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format,
                         GLenum type, const void* pixels) {
  const std::vector<unsigned char> image = list_image(c, width, 1, format, type, pixels);
  record::TexSubImage1D(c, target, level, xoffset, width, format, type, data_or_null(image), image.size());
}

void save::TexSubImage2D(GlContext& c, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width,
                         GLsizei height, GLenum format, GLenum type, const void* pixels) {
  const std::vector<unsigned char> image = list_image(c, width, height, format, type, pixels);
  record::TexSubImage2D(c, target, level, xoffset, yoffset, width, height, format, type, data_or_null(image),
                        image.size());
}

}  // namespace shadelab::gl
