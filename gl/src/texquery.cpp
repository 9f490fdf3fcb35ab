// Texture image queries (GL 1.1 section 6.1.4; 3D images of GL 1.2): glGetTexLevelParameter{iv,fv}
// for the texture and proxy targets, and glGetTexImage, which packs a level's texels as glReadPixels
// packs pixels (every format and type, the pack state). Values, errors and the conversions
// are Mesa's (texparam.c, texgetimage.c), measured on Debian's Mesa 22: an undefined level
// reports GL_RGBA and zero sizes, luminance is read back as R alone, integers are converted
// from the stored precision as Mesa's unorm conversions do. Reads state only.
#include <cmath>
#include <cstring>

#include "gl/generated/exec.hpp"
#include "gl/src/convert.hpp"
#include "gl/src/pixels.hpp"
#include "gl/src/texture.hpp"

namespace shadelab::gl {
namespace {

constexpr GLenum kTextureDepth = GL_TEXTURE_DEPTH;  // GL 1.2

const std::vector<TexImage>* level_images(GlContext& c, GLenum target) {
  switch (target) {
    case GL_TEXTURE_1D: case GL_TEXTURE_2D: case GL_TEXTURE_3D: case kTextureRectangle:
      return &bound_texture(c, target)->images;
    case kProxyTextureRectangle: return &c.textures.proxy_rect;
    case GL_PROXY_TEXTURE_1D: return &c.textures.proxy_1d;
    case GL_PROXY_TEXTURE_CUBE_MAP: return &c.textures.proxy_cube;
    case GL_PROXY_TEXTURE_2D: return &c.textures.proxy_2d;
    case GL_PROXY_TEXTURE_3D: return &c.textures.proxy_3d;
    default: return is_cube_face(target) ? &image_texture(c, target)->images : nullptr;  // GL 1.3
  }
}

int target_levels(GLenum target) {
  if (target == kTextureRectangle || target == kProxyTextureRectangle) return 1;
  return target == GL_TEXTURE_3D || target == GL_PROXY_TEXTURE_3D ? kMax3dTextureLevels : kMaxTextureLevels;
}

bool is_level_pname(GLenum pname) {
  switch (pname) {
    case GL_TEXTURE_WIDTH: case GL_TEXTURE_HEIGHT: case kTextureDepth: case GL_TEXTURE_BORDER:
    case GL_TEXTURE_INTERNAL_FORMAT: case GL_TEXTURE_RED_SIZE: case GL_TEXTURE_GREEN_SIZE:
    case GL_TEXTURE_BLUE_SIZE: case GL_TEXTURE_ALPHA_SIZE: case GL_TEXTURE_LUMINANCE_SIZE:
    case GL_TEXTURE_INTENSITY_SIZE: case GL_TEXTURE_COMPRESSED: case GL_TEXTURE_DEPTH_SIZE: case kTextureStencilSize:
      return true;
    default: return false;
  }
}

// GL 1.3 section 3.8.1: a generic compressed internal format with no specific compressed
// format to choose is replaced by its base internal format, which is what is reported (as
// Mesa reports it for an image it did not compress).
GLint reported_internal_format(GLint internal) {
  switch (internal) {
    case GL_COMPRESSED_ALPHA: return GL_ALPHA;
    case GL_COMPRESSED_LUMINANCE: return GL_LUMINANCE;
    case GL_COMPRESSED_LUMINANCE_ALPHA: return GL_LUMINANCE_ALPHA;
    case GL_COMPRESSED_INTENSITY: return GL_INTENSITY;
    case GL_COMPRESSED_RGB: return GL_RGB;
    case GL_COMPRESSED_RGBA: return GL_RGBA;
    default: return internal;
  }
}

// GL_TEXTURE_DEPTH (GL 1.2): a 3D image's depth, 1 for a defined 1D or 2D image (as Mesa).
GLint level_parameter(const TexImage& img, GLenum pname) {
  if (!img.defined) return pname == GL_TEXTURE_INTERNAL_FORMAT ? GL_RGBA : 0;
  switch (pname) {
    case GL_TEXTURE_WIDTH: return img.width;
    case GL_TEXTURE_HEIGHT: return img.height;
    case kTextureDepth: return img.depth;
    case GL_TEXTURE_BORDER: return img.border;
    case GL_TEXTURE_INTERNAL_FORMAT: return reported_internal_format(img.internal_format);
    case GL_TEXTURE_COMPRESSED: return GL_FALSE;  // GL 1.3: no image is ever compressed
    default: return component_size(img.format, pname);
  }
}

template <class T>
void get_level_parameter(GlContext& c, GLenum target, GLint level, GLenum pname, T* params) {
  const std::vector<TexImage>* images = level_images(c, target);
  if (!images) return c.set_error(GL_INVALID_ENUM);
  if (level < 0 || level >= target_levels(target)) return c.set_error(GL_INVALID_VALUE);
  // GL 1.3: no image is compressed, so none has a compressed size (Mesa's code).
  if (pname == GL_TEXTURE_COMPRESSED_IMAGE_SIZE) return c.set_error(GL_INVALID_OPERATION);
  if (!is_level_pname(pname)) return c.set_error(GL_INVALID_ENUM);
  if (!params) return;
  const TexImage none;
  const TexImage& img = std::size_t(level) < images->size() ? (*images)[std::size_t(level)] : none;
  *params = T(level_parameter(img, pname));
}

// A component as Mesa keeps it: an n-bit value (constants 0 and 1 as one-bit values).
struct Stored {
  std::uint16_t k;
  int bits;
  double unit() const { return double(k) / double((1u << bits) - 1u); }
};

// Texel i of a level as RGBA stored values (GL 1.1 table 6.1: L and I read back in R).
void texel_rgba(const TexImage& img, const TextureLevel& core, std::size_t i, Stored out[4]) {
  const StoredFormat& f = img.format;
  Stored comps[4];
  for (int k = 0; k < f.components; ++k) {
    const int bits = f.bits[k];
    std::uint16_t v;
    if (f.wide()) {
      v = img.wide[i * std::size_t(f.components) + std::size_t(k)];
    } else {  // the byte of the core's expansion that holds component k
      const int channel = f.base == TextureFormat::kAlpha || (f.base == TextureFormat::kLuminanceAlpha && k == 1) ? 3 : k;
      v = byte_to_stored(core.rgba[i * 4 + std::size_t(channel)], bits);
    }
    comps[k] = {v, bits};
  }
  out[0] = out[1] = out[2] = {0, 1};
  out[3] = {1, 1};
  switch (f.base) {
    case TextureFormat::kAlpha: out[3] = comps[0]; break;
    case TextureFormat::kLuminance: case TextureFormat::kIntensity: out[0] = comps[0]; break;
    case TextureFormat::kLuminanceAlpha: out[0] = comps[0], out[3] = comps[1]; break;
    case TextureFormat::kRgb: for (int k = 0; k < 3; ++k) out[k] = comps[k]; break;
    case TextureFormat::kRgba: for (int k = 0; k < 4; ++k) out[k] = comps[k]; break;
  }
}

// The components of `format` taken from RGBA (luminance is R, as Mesa's glGetTexImage).
int select_components(GLenum format, const Stored rgba[4], Stored out[4]) {
  const int order[][4] = {{0}, {1}, {2}, {3}, {0}, {0, 3}, {0, 1, 2}, {2, 1, 0}, {0, 1, 2, 3}, {2, 1, 0, 3}};
  int which;
  switch (format) {
    case GL_RED: which = 0; break;
    case GL_GREEN: which = 1; break;
    case GL_BLUE: which = 2; break;
    case GL_ALPHA: which = 3; break;
    case GL_LUMINANCE: which = 4; break;
    case GL_LUMINANCE_ALPHA: which = 5; break;
    case GL_RGB: which = 6; break;
    case GL_BGR: which = 7; break;
    case GL_RGBA: which = 8; break;
    case GL_BGRA: which = 9; break;
    default: return 0;
  }
  const int n = color_format_components(format);
  for (int k = 0; k < n; ++k) out[k] = rgba[order[which][k]];
  return n;
}

template <class T>
void put(unsigned char* p, T v, bool swap) {
  unsigned char b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  for (std::size_t k = 0; k < sizeof v; ++k) p[k] = b[swap ? sizeof v - 1 - k : k];
}

// One component as `type`: unsigned bytes and shorts by Mesa's unorm conversions of the
// stored value, the other types rounded from its value in [0, 1].
void pack_component(const Stored& s, GLenum type, bool swap, unsigned char* p) {
  const double v = s.unit();
  switch (type) {
    case GL_UNSIGNED_BYTE: *p = stored_to_byte(s.k, s.bits); return;
    case GL_UNSIGNED_SHORT: return put(p, GLushort(stored_to_ushort(s.k, s.bits)), swap);
    case GL_UNSIGNED_INT: return put(p, GLuint(std::llround(v * 4294967295.0)), swap);
    case GL_BYTE: *p = static_cast<unsigned char>(GLbyte(std::lround(v * 127.0))); return;
    case GL_SHORT: return put(p, GLshort(std::lround(v * 32767.0)), swap);
    case GL_INT: return put(p, GLint(std::llround(v * 2147483647.0)), swap);
    case GL_FLOAT: return put(p, stored_to_float(s.k, s.bits), swap);
    default: return;
  }
}

// A depth level as GL_DEPTH_COMPONENT values of `type` (the floats kept, converted as
// glReadPixels converts depths; byte swapping as the pack state says).
// A depth-stencil level as GL_DEPTH_STENCIL reads it: GL_UNSIGNED_INT_24_8 pixels.
void get_depth_image(GlContext& c, const TextureObject& t, int level, GLenum type, void* pixels) {
  if (!pixels) return;
  const TexImage& img = t.images[std::size_t(level)];
  const TextureLevel& core = t.texture.levels[std::size_t(level)];
  const int size = pixel_type_size(type);
  if (packed_type(type)) return c.set_error(GL_INVALID_OPERATION);
  const PixelLayout layout = pixel_layout(c.pack, 1, size, img.width);
  const bool swap = c.pack.swap_bytes;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(img.width) + std::size_t(x);
      const float d = core.depth_values[i];
      unsigned char* p = static_cast<unsigned char*>(pixels) + layout.offset(x, y);
      switch (type) {
        case kUnsignedInt24_8:
          put(p, GLuint(std::lround(double(d) * 16777215.0)) << 8 | (img.stencil.empty() ? 0u : img.stencil[i]), swap);
          break;
        case GL_UNSIGNED_BYTE: *p = GLubyte(std::lround(d * 255.0f)); break;
        case GL_BYTE: *p = static_cast<unsigned char>(GLbyte(std::lround(d * 127.0f))); break;
        case GL_UNSIGNED_SHORT: put(p, GLushort(std::lround(d * 65535.0f)), swap); break;
        case GL_SHORT: put(p, GLshort(std::lround(d * 32767.0f)), swap); break;
        case GL_UNSIGNED_INT: put(p, GLuint(std::llround(double(d) * 4294967295.0)), swap); break;
        case GL_INT: put(p, GLint(std::llround(double(d) * 2147483647.0)), swap); break;
        default: put(p, GLfloat(d), swap); break;
      }
    }
  }
}

void get_tex_image(GlContext& c, GLenum target, GLint level, GLenum format, GLenum type, void* pixels) {
  if (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D && target != GL_TEXTURE_3D && target != kTextureRectangle &&
      !is_cube_face(target)) {
    return c.set_error(GL_INVALID_ENUM);
  }
  if (level < 0 || level >= target_levels(target)) return c.set_error(GL_INVALID_VALUE);
  const bool known_format = color_format_components(format) != 0 || format == GL_COLOR_INDEX ||
                            format == GL_STENCIL_INDEX || format == GL_DEPTH_COMPONENT || format == kDepthStencil;
  if (!known_format || pixel_type_size(type) == 0) return c.set_error(GL_INVALID_ENUM);
  if (const GLenum e = format_type_error(format, type); e != GL_NO_ERROR) return c.set_error(e);
  TextureObject& t = *image_texture(c, target);
  // A depth texture reads back as GL_DEPTH_COMPONENT only, and only it does (GL 1.4); a
  // depth-stencil one as GL_DEPTH_STENCIL too, and only it does.
  const TexImage* level_image = std::size_t(level) < t.images.size() ? &t.images[std::size_t(level)] : nullptr;
  const bool depth_texture = level_image && level_image->format.depth;
  const bool depth_format = format == GL_DEPTH_COMPONENT || format == kDepthStencil;
  if (format == GL_STENCIL_INDEX || depth_format != depth_texture ||
      (format == kDepthStencil && level_image->format.stencil_bits == 0)) {
    return c.set_error(GL_INVALID_OPERATION);
  }
  if (depth_texture) return get_depth_image(c, t, level, type, pixels);
  if (std::size_t(level) >= t.images.size() || !t.images[std::size_t(level)].defined || !pixels) return;
  if (format == GL_COLOR_INDEX) return;  // no index textures in an RGBA context: nothing is written
  const TexImage& img = t.images[std::size_t(level)];
  const TextureLevel& core = t.texture.levels[std::size_t(level)];
  const int n = color_format_components(format), size = pixel_type_size(type);
  const PackedType* packed = packed_type(type);
  const PixelLayout layout = pixel_layout(c.pack, elements_per_pixel(format, type), size, img.width);
  // 3D images one after the other, GL_PACK_IMAGE_HEIGHT rows apart, after GL_PACK_SKIP_IMAGES.
  const bool three_d = target == GL_TEXTURE_3D;
  const std::size_t stride = three_d ? image_stride(c.pack, format, type, img.width, img.height) : 0;
  for (int z = 0; z < img.depth; ++z) {
    auto* out = static_cast<unsigned char*>(pixels) + (three_d ? std::size_t(c.pack.skip_images + z) * stride : 0);
    for (int y = 0; y < img.height; ++y) {
      for (int x = 0; x < img.width; ++x) {
        Stored rgba[4], comps[4];
        const std::size_t row = std::size_t(z) * std::size_t(img.height) + std::size_t(y);
        texel_rgba(img, core, row * std::size_t(img.width) + std::size_t(x), rgba);
        select_components(format, rgba, comps);
        unsigned char* p = out + layout.offset(x, y);
        if (packed) {  // one element: the components' fields, from their bytes as Mesa converts them
          std::uint32_t e = 0;
          for (int k = 0; k < n; ++k) e |= packed->field_from_byte(stored_to_byte(comps[k].k, comps[k].bits), k) << packed->shift(k);
          if (size == 1) *p = static_cast<unsigned char>(e);
          else if (size == 2) put(p, GLushort(e), c.pack.swap_bytes);
          else put(p, GLuint(e), c.pack.swap_bytes);
          continue;
        }
        for (int k = 0; k < n; ++k) pack_component(comps[k], type, c.pack.swap_bytes, p + k * size);
      }
    }
  }
}

}  // namespace

void exec::GetTexLevelParameteriv(GlContext& c, GLenum target, GLint level, GLenum pname, GLint* params) {
  get_level_parameter(c, target, level, pname, params);
}

void exec::GetTexLevelParameterfv(GlContext& c, GLenum target, GLint level, GLenum pname, GLfloat* params) {
  get_level_parameter(c, target, level, pname, params);
}

void exec::GetTexImage(GlContext& c, GLenum target, GLint level, GLenum format, GLenum type, void* pixels) {
  get_tex_image(c, target, level, format, type, pixels);
}

}  // namespace shadelab::gl
