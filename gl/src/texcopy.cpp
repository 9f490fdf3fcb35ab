// Texture images copied from the framebuffer (GL 1.1 section 3.8.2): glCopyTexImage1D/2D and
// glCopyTexSubImage1D/2D/3D (GL 1.2: a rectangle into one image of a 3D level). The colour buffer is read after every draw made before the call
// and its RGBA converted as glTexImage converts unsigned bytes (luminance and intensity take
// R). Errors and their order are Mesa's (teximage.c's copytexture_error_check and
// copytexsubimage_error_check).
#include <algorithm>
#include <cmath>

#include "gl/generated/exec.hpp"
#include "gl/src/texture.hpp"

namespace shadelab::gl {
namespace {

// The framebuffer's rectangle [x, x + width) x [y, y + height) (window coordinates, y up)
// as RGBA; pixels outside the framebuffer are not read and `inside` says which are.
RgbaImage read_framebuffer(GlContext& c, int x, int y, int width, int height, std::vector<std::uint8_t>& inside) {
  const ColorBuffer& color = read_color_buffer(c);
  RgbaImage image;
  image.width = width, image.height = height;
  image.exact_bytes = image.from_framebuffer = true;
  image.rgba.assign(std::size_t(width) * std::size_t(height) * 4, 0.0f);
  inside.assign(std::size_t(width) * std::size_t(height), 0);
  for (int j = 0; j < height; ++j) {
    const long fy = long(y) + j;
    for (int i = 0; i < width; ++i) {
      const long fx = long(x) + i;
      if (fx < 0 || fy < 0 || fx >= c.fb.width || fy >= c.fb.height) continue;
      const std::uint8_t* px = &color[(std::size_t(fy) * std::size_t(c.fb.width) + std::size_t(fx)) * 4];
      float* out = &image.rgba[(std::size_t(j) * std::size_t(width) + std::size_t(i)) * 4];
      for (int k = 0; k < 4; ++k) out[k] = px[k] / 255.0f;
      inside[std::size_t(j) * std::size_t(width) + std::size_t(i)] = 1;
    }
  }
  return image;
}

// GL 1.4: a depth texture's rectangle copied from the depth buffer (pixels outside the
// framebuffer not read), into (x0, y0) of a depth level; a depth-stencil level's stencil
// indices from the stencil buffer.
// The depth buffer's values are its stored 24 (or 16) bits, as Mesa's Z24 buffer holds them,
// then kept as the texture's bits keep them.
void copy_depths(GlContext& c, int x, int y, int width, int height, int x0, int y0, TexImage& img, TextureLevel& core) {
  const double max = c.depth_bits == 16 ? 65535.0 : 16777215.0;
  const int bits = img.format.bits[0];
  const bool stencil = !img.stencil.empty() && c.stencil_bits > 0;
  settle_clears(c);
  for (int j = 0; j < height; ++j) {
    const long fy = long(y) + j;
    for (int i = 0; i < width; ++i) {
      const long fx = long(x) + i;
      if (fx < 0 || fy < 0 || fx >= c.fb.width || fy >= c.fb.height || c.fb.depth.empty()) continue;
      const std::size_t from = std::size_t(fy) * std::size_t(c.fb.width) + std::size_t(fx);
      const std::size_t to = std::size_t(y0 + j) * std::size_t(core.width) + std::size_t(x0 + i);
      const double d = std::clamp(double(c.fb.depth[from]), 0.0, 1.0);
      const float buffer = float(std::round(d * max) / max);
      core.depth_values[to] = bits == int(c.depth_bits) ? buffer : stored_depth_value(buffer, bits);
      if (stencil) img.stencil[to] = c.fb.stencil[from];
    }
  }
}

// Stores only the pixels that came from inside the framebuffer (the others keep the
// texture's texels: what Mesa does, and within what GL allows, as they are undefined).
void store_inside(const RgbaImage& image, const std::vector<std::uint8_t>& inside, int x0, int y0, int z0,
                  TexImage& level, TextureLevel& core) {
  if (std::all_of(inside.begin(), inside.end(), [](std::uint8_t in) { return in != 0; })) {
    return store_texels(image, x0, y0, z0, level, core);
  }
  RgbaImage one;
  one.width = one.height = 1;
  one.exact_bytes = one.from_framebuffer = true;
  one.rgba.resize(4);
  for (int j = 0; j < image.height; ++j) {
    for (int i = 0; i < image.width; ++i) {
      const std::size_t k = std::size_t(j) * std::size_t(image.width) + std::size_t(i);
      if (!inside[k]) continue;
      std::copy(&image.rgba[k * 4], &image.rgba[k * 4] + 4, one.rgba.begin());
      store_texels(one, x0 + i, y0 + j, z0, level, core);
    }
  }
}

// glCopyTexImage1D (dims 1, height 1) and glCopyTexImage2D.
void copy_tex_image(GlContext& c, int dims, GLenum target, GLint level, GLenum internal, GLint x, GLint y,
                    GLsizei width, GLsizei height, GLint border) {
  const bool cube = dims == 2 && is_cube_face(target);  // GL 1.3: a cube map's face, square
  const bool rect = dims == 2 && target == kTextureRectangle;  // one level, no border
  if (target != (dims == 1 ? GL_TEXTURE_1D : GL_TEXTURE_2D) && !cube && !rect) return c.set_error(GL_INVALID_ENUM);
  if (level < 0 || level >= (rect ? 1 : kMaxTextureLevels)) return c.set_error(GL_INVALID_VALUE);
  if (border < 0 || border > (rect ? 0 : 1)) return c.set_error(GL_INVALID_VALUE);
  StoredFormat stored;  // the unsized 1 .. 4 are not accepted here (GL 1.1 section 3.8.2)
  if (internal <= 4 || !stored_format(GLint(internal), stored)) return c.set_error(GL_INVALID_ENUM);
  const long max = long(kMaxTextureSize) >> level;
  auto legal = [&](int size) { return size >= 2 * border && long(size) <= 2 * border + max; };
  if (!legal(width) || (dims == 2 && !legal(height)) || (cube && width != height)) return c.set_error(GL_INVALID_VALUE);
  // The border is stripped, as glTexImage strips it.
  const bool strip_rows = dims == 2 && border && height >= 3;
  const int inner_w = width - 2 * border, inner_h = strip_rows ? height - 2 : height;
  // No depth buffer (or, for a depth-stencil format, no stencil buffer): Mesa's error.
  if (stored.depth && (c.depth_bits == 0 || (stored.stencil_bits && c.stencil_bits == 0))) {
    return c.set_error(GL_INVALID_OPERATION);
  }
  TextureObject& t = *image_texture(c, target);
  if (stored.depth) {
    texture_changing(c, t);
    define_level(t, level, GLint(internal), inner_w, inner_h);
    copy_depths(c, x + border, y + (strip_rows ? 1 : 0), inner_w, inner_h, 0, 0, t.images[std::size_t(level)],
                t.texture.levels[std::size_t(level)]);
    return image_changed(c, target, t, level);
  }
  std::vector<std::uint8_t> inside;
  RgbaImage image = read_framebuffer(c, x + border, y + (strip_rows ? 1 : 0), inner_w, inner_h, inside);
  texture_changing(c, t);
  define_level(t, level, GLint(internal), inner_w, inner_h);
  store_inside(image, inside, 0, 0, 0, t.images[std::size_t(level)], t.texture.levels[std::size_t(level)]);
  image_changed(c, target, t, level);
}

// glCopyTexSubImage1D (dims 1), glCopyTexSubImage2D and glCopyTexSubImage3D (into image
// zoffset).
void copy_tex_sub_image(GlContext& c, int dims, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                        GLint zoffset, GLint x, GLint y, GLsizei width, GLsizei height) {
  const bool rect = dims == 2 && target == kTextureRectangle;
  if (target != (dims == 1 ? GL_TEXTURE_1D : dims == 3 ? GL_TEXTURE_3D : GL_TEXTURE_2D) &&
      !(dims == 2 && is_cube_face(target)) && !rect) {
    return c.set_error(GL_INVALID_ENUM);
  }
  const int levels = rect ? 1 : dims == 3 ? kMax3dTextureLevels : kMaxTextureLevels;
  if (level < 0 || level >= levels) return c.set_error(GL_INVALID_VALUE);
  TextureObject& t = *image_texture(c, target);
  if (t.images.size() <= std::size_t(level) || !t.images[std::size_t(level)].defined) {
    return c.set_error(GL_INVALID_OPERATION);
  }
  TexImage& img = t.images[std::size_t(level)];
  if (width < 0 || height < 0) return c.set_error(GL_INVALID_VALUE);
  if (xoffset < 0 || yoffset < 0 || long(xoffset) + width > img.width || long(yoffset) + height > img.height ||
      zoffset < 0 || zoffset >= img.depth) {
    return c.set_error(GL_INVALID_VALUE);
  }
  if (width == 0 || height == 0) return;
  if (img.format.depth) {
    texture_changing(c, t);
    copy_depths(c, x, y, width, height, xoffset, yoffset, img, t.texture.levels[std::size_t(level)]);
    return image_changed(c, target, t, level);
  }
  std::vector<std::uint8_t> inside;
  RgbaImage image = read_framebuffer(c, x, y, width, height, inside);
  texture_changing(c, t);
  store_inside(image, inside, xoffset, yoffset, zoffset, img, t.texture.levels[std::size_t(level)]);
  image_changed(c, target, t, level);
}

}  // namespace

void exec::CopyTexImage1D(GlContext& c, GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                          GLsizei width, GLint border) {
  copy_tex_image(c, 1, target, level, internalformat, x, y, width, 1, border);
}

void exec::CopyTexImage2D(GlContext& c, GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                          GLsizei width, GLsizei height, GLint border) {
  copy_tex_image(c, 2, target, level, internalformat, x, y, width, height, border);
}

void exec::CopyTexSubImage1D(GlContext& c, GLenum target, GLint level, GLint xoffset, GLint x, GLint y, GLsizei width) {
  copy_tex_sub_image(c, 1, target, level, xoffset, 0, 0, x, y, width, 1);
}

void exec::CopyTexSubImage2D(GlContext& c, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x, GLint y,
                             GLsizei width, GLsizei height) {
  copy_tex_sub_image(c, 2, target, level, xoffset, yoffset, 0, x, y, width, height);
}

void exec::CopyTexSubImage3D(GlContext& c, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                             GLint x, GLint y, GLsizei width, GLsizei height) {
  copy_tex_sub_image(c, 3, target, level, xoffset, yoffset, zoffset, x, y, width, height);
}

}  // namespace shadelab::gl
