// Texture objects and 2D texture images (GL 1.1 sections 3.8, 3.8.8): glGen/Bind/Delete/
// IsTexture, glTexImage2D, glTexParameter*, glTexEnv* and their queries. Builds the core's
// shadelab::Texture; sampling and the environment are the core's (texture.hpp).
#include <algorithm>
#include <cmath>

#include "gl/generated/exec.hpp"
#include "gl/generated/run.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/context.hpp"
#include "gl/src/convert.hpp"
#include "gl/src/pixels.hpp"

namespace shadelab::gl {
namespace {

// The base internal format of a glTexImage2D internalformat (GL 1.1 table 3.15), or false.
bool base_format(GLint internal, TextureFormat& out) {
  switch (internal) {
    case GL_ALPHA: case GL_ALPHA4: case GL_ALPHA8: case GL_ALPHA12: case GL_ALPHA16:
      out = TextureFormat::kAlpha; return true;
    case 1: case GL_LUMINANCE: case GL_LUMINANCE4: case GL_LUMINANCE8: case GL_LUMINANCE12:
    case GL_LUMINANCE16:
      out = TextureFormat::kLuminance; return true;
    case 2: case GL_LUMINANCE_ALPHA: case GL_LUMINANCE4_ALPHA4: case GL_LUMINANCE6_ALPHA2:
    case GL_LUMINANCE8_ALPHA8: case GL_LUMINANCE12_ALPHA4: case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16:
      out = TextureFormat::kLuminanceAlpha; return true;
    case GL_INTENSITY: case GL_INTENSITY4: case GL_INTENSITY8: case GL_INTENSITY12:
    case GL_INTENSITY16:
      out = TextureFormat::kIntensity; return true;
    case 3: case GL_RGB: case GL_R3_G3_B2: case GL_RGB4: case GL_RGB5: case GL_RGB8: case GL_RGB10:
    case GL_RGB12: case GL_RGB16:
      out = TextureFormat::kRgb; return true;
    case 4: case GL_RGBA: case GL_RGBA2: case GL_RGBA4: case GL_RGB5_A1: case GL_RGBA8:
    case GL_RGB10_A2: case GL_RGBA12: case GL_RGBA16:
      out = TextureFormat::kRgba; return true;
    default: return false;
  }
}

std::uint8_t to_byte(float v) { return std::uint8_t(std::lround(std::clamp(finite_or_zero(v), 0.0f, 1.0f) * 255.0f)); }

// Stores an RGBA pixel the way the core expects the base format (texture.hpp): L as
// (L, L, L, 1), LA as (L, L, L, A), I as (I, I, I, I), A as (0, 0, 0, A), RGB with alpha 1.
void store_texel(TextureFormat f, const float rgba[4], std::uint8_t* out) {
  float r = rgba[0], g = rgba[1], b = rgba[2], a = rgba[3];
  switch (f) {
    case TextureFormat::kAlpha: r = g = b = 0.0f; break;
    case TextureFormat::kLuminance: g = b = r, a = 1.0f; break;
    case TextureFormat::kLuminanceAlpha: g = b = r; break;
    case TextureFormat::kIntensity: g = b = a = r; break;
    case TextureFormat::kRgb: a = 1.0f; break;
    case TextureFormat::kRgba: break;
  }
  out[0] = to_byte(r), out[1] = to_byte(g), out[2] = to_byte(b), out[3] = to_byte(a);
}

// Reads the client image (without its border texels, which shadelab does not sample).
TextureLevel unpack_level(const GlContext& c, int width, int height, int border, GLenum format,
                          GLenum type, const void* pixels, TextureFormat base) {
  TextureLevel level;
  level.width = width - 2 * border;
  level.height = height - 2 * border;
  level.rgba.assign(std::size_t(level.width) * std::size_t(level.height) * 4, 0);
  if (!pixels) return level;  // contents undefined: zero
  PixelLayout layout = pixel_layout(c.unpack, color_format_components(format), pixel_type_size(type), width);
  const auto* in = static_cast<const unsigned char*>(pixels);
  for (int y = 0; y < level.height; ++y) {
    for (int x = 0; x < level.width; ++x) {
      float rgba[4];
      unpack_rgba(in + layout.offset(x + border, y + border), format, type, rgba);
      store_texel(base, rgba, &level.rgba[(std::size_t(y) * std::size_t(level.width) + std::size_t(x)) * 4]);
    }
  }
  return level;
}

int max_level() {
  int n = 0;
  while ((1 << n) < kMaxTextureSize) ++n;
  return n;
}

bool is_min_filter(GLenum f) {
  return f == GL_NEAREST || f == GL_LINEAR || (f >= GL_NEAREST_MIPMAP_NEAREST && f <= GL_LINEAR_MIPMAP_LINEAR);
}

TextureFilter filter_of(GLenum f) {
  switch (f) {
    case GL_NEAREST: return TextureFilter::kNearest;
    case GL_LINEAR: return TextureFilter::kLinear;
    case GL_NEAREST_MIPMAP_NEAREST: return TextureFilter::kNearestMipmapNearest;
    case GL_LINEAR_MIPMAP_NEAREST: return TextureFilter::kLinearMipmapNearest;
    case GL_NEAREST_MIPMAP_LINEAR: return TextureFilter::kNearestMipmapLinear;
    default: return TextureFilter::kLinearMipmapLinear;
  }
}

GLenum filter_enum(TextureFilter f) {
  switch (f) {
    case TextureFilter::kNearest: return GL_NEAREST;
    case TextureFilter::kLinear: return GL_LINEAR;
    case TextureFilter::kNearestMipmapNearest: return GL_NEAREST_MIPMAP_NEAREST;
    case TextureFilter::kLinearMipmapNearest: return GL_LINEAR_MIPMAP_NEAREST;
    case TextureFilter::kNearestMipmapLinear: return GL_NEAREST_MIPMAP_LINEAR;
    case TextureFilter::kLinearMipmapLinear: return GL_LINEAR_MIPMAP_LINEAR;
  }
  return GL_LINEAR;
}

GLenum wrap_enum(TextureWrap w) {
  return w == TextureWrap::kRepeat ? GL_REPEAT : w == TextureWrap::kClamp ? GL_CLAMP : GL_CLAMP_TO_EDGE;
}

// glTexParameter with its values as floats (n of them: 4 for the border colour).
void tex_parameter(GlContext& c, GLenum target, GLenum pname, const float* v, int n) {
  if (target != GL_TEXTURE_2D) return c.set_error(GL_INVALID_ENUM);
  if (!v) return c.set_error(GL_INVALID_VALUE);
  TextureObject& t = *c.textures.bound;
  GLenum e = v[0] >= 0.0f && v[0] < 4e9f ? GLenum(v[0]) : 0;
  switch (pname) {
    case GL_TEXTURE_WRAP_S: case GL_TEXTURE_WRAP_T: {
      if (e != GL_REPEAT && e != GL_CLAMP && e != GL_CLAMP_TO_EDGE) return c.set_error(GL_INVALID_ENUM);
      TextureWrap w = e == GL_REPEAT ? TextureWrap::kRepeat : e == GL_CLAMP ? TextureWrap::kClamp : TextureWrap::kClampToEdge;
      (pname == GL_TEXTURE_WRAP_S ? t.texture.wrap_s : t.texture.wrap_t) = w;
      return;
    }
    case GL_TEXTURE_MIN_FILTER:
      if (!is_min_filter(e)) return c.set_error(GL_INVALID_ENUM);
      t.texture.min_filter = filter_of(e);
      return;
    case GL_TEXTURE_MAG_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR) return c.set_error(GL_INVALID_ENUM);
      t.texture.mag_filter = filter_of(e);
      return;
    case GL_TEXTURE_BORDER_COLOR:
      if (n < 4) return c.set_error(GL_INVALID_ENUM);
      for (int i = 0; i < 4; ++i) t.border_color[i] = std::clamp(finite_or_zero(v[i]), 0.0f, 1.0f);
      return;
    case GL_TEXTURE_PRIORITY: t.priority = std::clamp(finite_or_zero(v[0]), 0.0f, 1.0f); return;
    default: return c.set_error(GL_INVALID_ENUM);
  }
}

// glGetTexParameter: count of values written into v (0: unknown pname).
int get_tex_parameter(const TextureObject& t, GLenum pname, float* v, bool& color) {
  color = pname == GL_TEXTURE_BORDER_COLOR;
  switch (pname) {
    case GL_TEXTURE_WRAP_S: v[0] = float(wrap_enum(t.texture.wrap_s)); return 1;
    case GL_TEXTURE_WRAP_T: v[0] = float(wrap_enum(t.texture.wrap_t)); return 1;
    case GL_TEXTURE_MIN_FILTER: v[0] = float(filter_enum(t.texture.min_filter)); return 1;
    case GL_TEXTURE_MAG_FILTER: v[0] = float(filter_enum(t.texture.mag_filter)); return 1;
    case GL_TEXTURE_BORDER_COLOR: for (int i = 0; i < 4; ++i) v[i] = t.border_color[i]; return 4;
    case GL_TEXTURE_PRIORITY: v[0] = t.priority; return 1;
    case GL_TEXTURE_RESIDENT: v[0] = 1.0f; return 1;
    default: return 0;
  }
}

// glTexEnv (GL 1.1 section 3.8.9).
void tex_env(GlContext& c, GLenum target, GLenum pname, const float* v, int n) {
  if (target != GL_TEXTURE_ENV) return c.set_error(GL_INVALID_ENUM);
  if (!v) return c.set_error(GL_INVALID_VALUE);
  if (pname == GL_TEXTURE_ENV_MODE) {
    GLenum m = v[0] >= 0.0f && v[0] < 4e9f ? GLenum(v[0]) : 0;
    if (m != GL_MODULATE && m != GL_DECAL && m != GL_BLEND && m != GL_REPLACE) return c.set_error(GL_INVALID_ENUM);
    c.textures.env_mode = m;
  } else if (pname == GL_TEXTURE_ENV_COLOR && n == 4) {
    for (int i = 0; i < 4; ++i) c.textures.env_color[i] = std::clamp(finite_or_zero(v[i]), 0.0f, 1.0f);
  } else {
    c.set_error(GL_INVALID_ENUM);
  }
}

template <class T>
void get_tex_env(GlContext& c, GLenum target, GLenum pname, T* params) {
  if (target != GL_TEXTURE_ENV) return c.set_error(GL_INVALID_ENUM);
  float v[4] = {float(c.textures.env_mode), 0, 0, 0};
  int n = 1;
  if (pname == GL_TEXTURE_ENV_COLOR) {
    for (int i = 0; i < 4; ++i) v[i] = c.textures.env_color[i];
    n = 4;
  } else if (pname != GL_TEXTURE_ENV_MODE) {
    return c.set_error(GL_INVALID_ENUM);
  }
  if (!params) return c.set_error(GL_INVALID_VALUE);
  write_gl_values(v, n, pname == GL_TEXTURE_ENV_COLOR, params);
}

template <class T>
void get_tex_parameter_call(GlContext& c, GLenum target, GLenum pname, T* params) {
  if (target != GL_TEXTURE_2D) return c.set_error(GL_INVALID_ENUM);
  float v[4];
  bool color = false;
  int n = get_tex_parameter(*c.textures.bound, pname, v, color);
  if (n == 0) return c.set_error(GL_INVALID_ENUM);
  if (!params) return c.set_error(GL_INVALID_VALUE);
  write_gl_values(v, n, color, params);
}

template <class T>
void to_floats(const T* in, int n, bool color, float* out) {
  for (int i = 0; i < n; ++i) {
    if constexpr (std::is_integral_v<T>) {
      out[i] = color ? int_to_color(in[i]) : float(in[i]);
    } else {
      out[i] = float(in[i]);
    }
  }
}

}  // namespace

void exec::GenTextures(GlContext& c, GLsizei n, GLuint* textures) {
  if (n < 0) return c.set_error(GL_INVALID_VALUE);
  if (n > 0 && !textures) return c.set_error(GL_INVALID_VALUE);
  TextureNames& names = *c.textures.names;
  for (GLsizei i = 0; i < n; ++i) {
    while (names.next_name == 0 || names.objects.count(names.next_name)) ++names.next_name;
    GLuint name = names.next_name++;
    names.objects[name] = nullptr;  // reserved; the object appears at its first bind
    textures[i] = name;
  }
}

// Deleting a bound texture binds 0 in this context (GL 1.1 section 3.8.8).
void exec::DeleteTextures(GlContext& c, GLsizei n, const GLuint* textures) {
  if (n < 0) return c.set_error(GL_INVALID_VALUE);
  if (n > 0 && !textures) return c.set_error(GL_INVALID_VALUE);
  for (GLsizei i = 0; i < n; ++i) {
    if (textures[i] == 0) continue;
    c.textures.names->objects.erase(textures[i]);
    if (c.textures.bound_name == textures[i]) {
      c.textures.bound_name = 0;
      c.textures.bound = c.textures.default_texture;
    }
  }
}

void exec::BindTexture(GlContext& c, GLenum target, GLuint texture) {
  if (target != GL_TEXTURE_2D) return c.set_error(GL_INVALID_ENUM);
  TextureState& t = c.textures;
  if (texture == 0) {
    t.bound = t.default_texture;
  } else {
    std::shared_ptr<TextureObject>& obj = t.names->objects[texture];
    if (!obj) obj = std::make_shared<TextureObject>();
    t.bound = obj;
  }
  t.bound_name = texture;
}

GLboolean exec::IsTexture(GlContext& c, GLuint texture) {
  auto it = c.textures.names->objects.find(texture);
  return it != c.textures.names->objects.end() && it->second ? GL_TRUE : GL_FALSE;
}

// Any size up to GL_MAX_TEXTURE_SIZE is accepted (non-power-of-two too, as Mesa does);
// border texels are skipped.
void exec::TexImage2D(GlContext& c, GLenum target, GLint level, GLint internal_format, GLsizei width,
                      GLsizei height, GLint border, GLenum format, GLenum type, const void* pixels) {
  if (target == GL_PROXY_TEXTURE_2D) return;  // proxies: nothing stored
  if (target != GL_TEXTURE_2D) return c.set_error(GL_INVALID_ENUM);
  shadelab::TextureFormat base;
  if (color_format_components(format) == 0 || pixel_type_size(type) == 0) return c.set_error(GL_INVALID_ENUM);
  if (!base_format(internal_format, base)) return c.set_error(GL_INVALID_VALUE);
  if (level < 0 || level > max_level() || (border != 0 && border != 1)) return c.set_error(GL_INVALID_VALUE);
  if (width < 2 * border || height < 2 * border || width - 2 * border > kMaxTextureSize ||
      height - 2 * border > kMaxTextureSize) {
    return c.set_error(GL_INVALID_VALUE);
  }
  shadelab::TextureLevel image = unpack_level(c, width, height, border, format, type, pixels, base);
  TextureObject& t = *c.textures.bound;
  if (t.texture.levels.size() <= std::size_t(level)) {
    t.texture.levels.resize(std::size_t(level) + 1);
    t.internal_formats.resize(std::size_t(level) + 1, 0);
  }
  t.texture.levels[std::size_t(level)] = std::move(image);
  t.internal_formats[std::size_t(level)] = internal_format;
  if (level == 0) t.texture.format = base;
}

// In a display list, the image is kept as the unpack state of the moment reads it (GL 1.1
// section 5.4), tightly packed; proxy textures are queries, executed at once and not
// compiled (as in Mesa). An image the command will reject is not read.
void save::TexImage2D(GlContext& c, GLenum target, GLint level, GLint internal_format, GLsizei width,
                      GLsizei height, GLint border, GLenum format, GLenum type, const void* pixels) {
  if (target == GL_PROXY_TEXTURE_2D) {
    if (c.lists.mode == GL_COMPILE) run::TexImage2D(c, target, level, internal_format, width, height, border, format, type, pixels);
    return;
  }
  const int components = color_format_components(format), size = pixel_type_size(type);
  const bool readable = pixels && components > 0 && size > 0 && width >= 0 && height >= 0 &&
                        width <= kMaxTextureSize + 2 && height <= kMaxTextureSize + 2;
  std::vector<unsigned char> image;
  if (readable) image = copy_image(c.unpack, width, height, components, size, pixels);
  record::TexImage2D(c, target, level, internal_format, width, height, border, format, type,
                     readable ? image.data() : nullptr, image.size());
}

void exec::TexParameterf(GlContext& c, GLenum target, GLenum pname, GLfloat param) {
  tex_parameter(c, target, pname, &param, 1);
}
void exec::TexParameteri(GlContext& c, GLenum target, GLenum pname, GLint param) {
  float v = float(param);
  tex_parameter(c, target, pname, &v, 1);
}
void exec::TexParameterfv(GlContext& c, GLenum target, GLenum pname, const GLfloat* params) {
  tex_parameter(c, target, pname, params, pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1);
}
void exec::TexParameteriv(GlContext& c, GLenum target, GLenum pname, const GLint* params) {
  float v[4] = {0, 0, 0, 0};
  int n = pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1;
  if (params) to_floats(params, n, pname == GL_TEXTURE_BORDER_COLOR, v);
  tex_parameter(c, target, pname, params ? v : nullptr, n);
}
void exec::GetTexParameterfv(GlContext& c, GLenum target, GLenum pname, GLfloat* params) {
  get_tex_parameter_call(c, target, pname, params);
}
void exec::GetTexParameteriv(GlContext& c, GLenum target, GLenum pname, GLint* params) {
  get_tex_parameter_call(c, target, pname, params);
}

void exec::TexEnvf(GlContext& c, GLenum target, GLenum pname, GLfloat param) { tex_env(c, target, pname, &param, 1); }
void exec::TexEnvi(GlContext& c, GLenum target, GLenum pname, GLint param) {
  float v = float(param);
  tex_env(c, target, pname, &v, 1);
}
void exec::TexEnvfv(GlContext& c, GLenum target, GLenum pname, const GLfloat* params) {
  tex_env(c, target, pname, params, pname == GL_TEXTURE_ENV_COLOR ? 4 : 1);
}
void exec::TexEnviv(GlContext& c, GLenum target, GLenum pname, const GLint* params) {
  float v[4] = {0, 0, 0, 0};
  int n = pname == GL_TEXTURE_ENV_COLOR ? 4 : 1;
  if (params) to_floats(params, n, pname == GL_TEXTURE_ENV_COLOR, v);
  tex_env(c, target, pname, params ? v : nullptr, n);
}
// How many values the vector forms read, for their display-list savers: the first value
// even for a pname they reject (tex_parameter reads it before it looks at the pname).
std::size_t save_count::TexParameterfv(GLenum pname) { return pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1; }
std::size_t save_count::TexParameteriv(GLenum pname) { return pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1; }
std::size_t save_count::TexEnvfv(GLenum pname) { return pname == GL_TEXTURE_ENV_COLOR ? 4 : 1; }
std::size_t save_count::TexEnviv(GLenum pname) { return pname == GL_TEXTURE_ENV_COLOR ? 4 : 1; }

void exec::GetTexEnvfv(GlContext& c, GLenum target, GLenum pname, GLfloat* params) { get_tex_env(c, target, pname, params); }
void exec::GetTexEnviv(GlContext& c, GLenum target, GLenum pname, GLint* params) { get_tex_env(c, target, pname, params); }

}  // namespace shadelab::gl
