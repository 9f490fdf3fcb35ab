// Texture objects and their parameters (GL 1.1 sections 3.8.3, 3.8.8; GL 1.5 sections 3.8.4,
// 3.8.8, 3.8.10): glGen/Bind/Delete/IsTexture, glPrioritizeTextures, glAreTexturesResident,
// glTexParameter* (with GL 1.2's LOD clamps and level range, GL 1.3's border clamp, GL 1.4's
// mirrored repeat, LOD bias and mipmap generation) and their queries, and which texture the
// pipeline samples. Images are teximage.cpp's, the environment texenv.cpp's; sampling is the
// core's (texture.hpp).
#include "gl/src/texture.hpp"

#include <algorithm>
#include <climits>

#include "gl/generated/exec.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/convert.hpp"

namespace shadelab::gl {
namespace {

bool is_min_filter(GLint f) {
  return f == GL_NEAREST || f == GL_LINEAR || (f >= GL_NEAREST_MIPMAP_NEAREST && f <= GL_LINEAR_MIPMAP_LINEAR);
}

TextureFilter filter_of(GLint f) {
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
  switch (w) {
    case TextureWrap::kRepeat: return GL_REPEAT;
    case TextureWrap::kClamp: return GL_CLAMP;
    case TextureWrap::kClampToEdge: return GL_CLAMP_TO_EDGE;
    case TextureWrap::kClampToBorder: return GL_CLAMP_TO_BORDER;
    case TextureWrap::kMirroredRepeat: return GL_MIRRORED_REPEAT;
  }
  return GL_REPEAT;
}

void set_wrap(GlContext& c, TextureWrap& wrap, GLint e) {
  switch (e) {
    case GL_REPEAT: wrap = TextureWrap::kRepeat; return;
    case GL_CLAMP: wrap = TextureWrap::kClamp; return;
    case GL_CLAMP_TO_EDGE: wrap = TextureWrap::kClampToEdge; return;
    case GL_CLAMP_TO_BORDER: wrap = TextureWrap::kClampToBorder; return;
    case GL_MIRRORED_REPEAT: wrap = TextureWrap::kMirroredRepeat; return;
    default: return c.set_error(GL_INVALID_ENUM);
  }
}

// GL_TEXTURE_BASE_LEVEL and GL_TEXTURE_MAX_LEVEL: any level >= 0 (Mesa's texparam.c).
void set_level(GlContext& c, int& level, GLint e) {
  if (e < 0) return c.set_error(GL_INVALID_VALUE);
  level = e;
}

// glTexParameter with its values as floats (4 for the border colour; `rounded`: see
// enum_param).
void tex_parameter(GlContext& c, GLenum target, GLenum pname, const float* v, bool vector, bool rounded) {
  TextureObject* t = bound_texture(c, target);
  if (!t) return c.set_error(GL_INVALID_ENUM);
  if (!v) return c.set_error(GL_INVALID_VALUE);
  const GLint e = enum_param(v[0], rounded);
  if (t->target == kTextureRectangle) {  // ARB_texture_rectangle: no repeat, no mipmaps
    const bool wrap = pname == GL_TEXTURE_WRAP_S || pname == GL_TEXTURE_WRAP_T || pname == GL_TEXTURE_WRAP_R;
    if (wrap && (e == GL_REPEAT || e == GL_MIRRORED_REPEAT)) return c.set_error(GL_INVALID_ENUM);
    if (pname == GL_TEXTURE_MIN_FILTER && e != GL_NEAREST && e != GL_LINEAR) return c.set_error(GL_INVALID_ENUM);
    if (pname == GL_TEXTURE_BASE_LEVEL && e != 0) return c.set_error(GL_INVALID_OPERATION);
  }
  texture_changing(c, *t);
  Texture& x = t->texture;
  switch (pname) {
    case GL_TEXTURE_WRAP_S: return set_wrap(c, x.wrap_s, e);
    case GL_TEXTURE_WRAP_T: return set_wrap(c, x.wrap_t, e);
    case GL_TEXTURE_WRAP_R: return set_wrap(c, x.wrap_r, e);
    case GL_TEXTURE_BASE_LEVEL: return set_level(c, x.base_level, e);
    case GL_TEXTURE_MAX_LEVEL: return set_level(c, x.max_level, e);
    // The LOD values are kept as given (Mesa's sampler takes max(min_lod, 0)); NaN as 0.
    case GL_TEXTURE_MIN_LOD: x.min_lod = finite_or_zero(v[0]); return;
    case GL_TEXTURE_MAX_LOD: x.max_lod = finite_or_zero(v[0]); return;
    case GL_TEXTURE_LOD_BIAS: x.lod_bias = finite_or_zero(v[0]); return;
    case GL_GENERATE_MIPMAP: t->generate_mipmap = e != 0; return;
    case GL_TEXTURE_MIN_FILTER:
      if (!is_min_filter(e)) return c.set_error(GL_INVALID_ENUM);
      x.min_filter = filter_of(e);
      return;
    case GL_TEXTURE_MAG_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR) return c.set_error(GL_INVALID_ENUM);
      x.mag_filter = filter_of(e);
      return;
    case GL_TEXTURE_BORDER_COLOR:  // clamped to [0, 1] (GL 1.1 section 3.8.3)
      if (!vector) return c.set_error(GL_INVALID_ENUM);
      for (int i = 0; i < 4; ++i) x.border_color[i] = std::clamp(finite_or_zero(v[i]), 0.0f, 1.0f);
      return;
    case GL_TEXTURE_PRIORITY: t->priority = std::clamp(finite_or_zero(v[0]), 0.0f, 1.0f); return;
    // GL 1.4's depth textures (ARB_depth_texture, ARB_shadow; EXT_shadow_funcs' functions).
    case GL_DEPTH_TEXTURE_MODE:
      if (e == GL_LUMINANCE) t->depth_mode = TextureFormat::kLuminance;
      else if (e == GL_INTENSITY) t->depth_mode = TextureFormat::kIntensity;
      else if (e == GL_ALPHA) t->depth_mode = TextureFormat::kAlpha;
      else return c.set_error(GL_INVALID_ENUM);
      return;
    case GL_TEXTURE_COMPARE_MODE:
      if (e != GL_NONE && e != GL_COMPARE_R_TO_TEXTURE) return c.set_error(GL_INVALID_ENUM);
      x.compare = e == GL_COMPARE_R_TO_TEXTURE;
      return;
    case GL_TEXTURE_COMPARE_FUNC:
      if (e < GLint(GL_NEVER) || e > GLint(GL_ALWAYS)) return c.set_error(GL_INVALID_ENUM);
      x.compare_func = TextureCompare(e - GL_NEVER);  // GL_NEVER .. GL_ALWAYS in TextureCompare's order
      return;
    default: return c.set_error(GL_INVALID_ENUM);
  }
}

// glGetTexParameter: count of values written into v (0: unknown pname).
int get_tex_parameter(const TextureObject& t, GLenum pname, float* v) {
  const Texture& x = t.texture;
  switch (pname) {
    case GL_TEXTURE_WRAP_S: v[0] = float(wrap_enum(x.wrap_s)); return 1;
    case GL_TEXTURE_WRAP_T: v[0] = float(wrap_enum(x.wrap_t)); return 1;
    case GL_TEXTURE_WRAP_R: v[0] = float(wrap_enum(x.wrap_r)); return 1;
    case GL_TEXTURE_BASE_LEVEL: v[0] = float(x.base_level); return 1;
    case GL_TEXTURE_MAX_LEVEL: v[0] = float(x.max_level); return 1;
    case GL_TEXTURE_MIN_LOD: v[0] = x.min_lod; return 1;
    case GL_TEXTURE_MAX_LOD: v[0] = x.max_lod; return 1;
    case GL_TEXTURE_LOD_BIAS: v[0] = x.lod_bias; return 1;
    case GL_GENERATE_MIPMAP: v[0] = t.generate_mipmap ? 1.0f : 0.0f; return 1;
    case GL_TEXTURE_MIN_FILTER: v[0] = float(filter_enum(x.min_filter)); return 1;
    case GL_TEXTURE_MAG_FILTER: v[0] = float(filter_enum(x.mag_filter)); return 1;
    case GL_TEXTURE_BORDER_COLOR: for (int i = 0; i < 4; ++i) v[i] = x.border_color[i]; return 4;
    case GL_TEXTURE_PRIORITY: v[0] = t.priority; return 1;
    case GL_TEXTURE_RESIDENT: v[0] = 1.0f; return 1;  // every texture is resident
    case GL_DEPTH_TEXTURE_MODE:
      v[0] = float(t.depth_mode == TextureFormat::kIntensity ? GL_INTENSITY
                   : t.depth_mode == TextureFormat::kAlpha   ? GL_ALPHA
                                                              : GL_LUMINANCE);
      return 1;
    case GL_TEXTURE_COMPARE_MODE: v[0] = float(x.compare ? GL_COMPARE_R_TO_TEXTURE : GL_NONE); return 1;
    case GL_TEXTURE_COMPARE_FUNC: v[0] = float(GL_NEVER + int(x.compare_func)); return 1;
    default: return 0;
  }
}

template <class T>
void get_tex_parameter_call(GlContext& c, GLenum target, GLenum pname, T* params) {
  const TextureObject* t = bound_texture(c, target);
  if (!t) return c.set_error(GL_INVALID_ENUM);
  float v[4];
  int n = get_tex_parameter(*t, pname, v);
  if (n == 0) return c.set_error(GL_INVALID_ENUM);
  if (!params) return c.set_error(GL_INVALID_VALUE);
  write_gl_values(v, n, pname == GL_TEXTURE_BORDER_COLOR, params);
}

// The texture of a target if it is complete (GL 1.5 section 3.8.10; every level of the
// mipmap chain with the base level's internal format as well, as Mesa requires).
const Texture* complete_texture(TextureObject& t) {
  if (!t.texture.complete()) return nullptr;
  const std::size_t base = std::size_t(t.texture.base_level);
  if (t.images.size() <= base) return nullptr;
  const bool mipmapped = t.texture.min_filter != TextureFilter::kNearest && t.texture.min_filter != TextureFilter::kLinear;
  const int last = mipmapped ? t.texture.last_level() : t.texture.base_level;
  for (int i = t.texture.base_level + 1; i <= last; ++i) {
    if (t.images[std::size_t(i)].internal_format != t.images[base].internal_format) return nullptr;
  }
  // The environment follows the base level's format; a depth texture's, its depth mode.
  t.texture.depth = t.images[base].format.depth;
  t.texture.wide = t.images[base].format.wide();  // filtered in float, as llvmpipe does
  t.texture.format = t.texture.depth ? t.depth_mode : t.images[base].format.base;
  return &t.texture;
}

}  // namespace

// An enum-valued parameter given as a float: glTexParameterf rounds it, the vector forms
// truncate (Mesa's texparam.c).
GLint enum_param(float v, bool rounded) {
  if (!(v == v)) return 0;
  if (rounded) v = v > 0.0f ? v + 0.5f : v - 0.5f;
  return v >= float(INT_MAX) ? INT_MAX : v <= float(INT_MIN) ? INT_MIN : GLint(v);
}

TextureObject* bound_texture(GlContext& c, GLenum target) {
  if (!is_texture_target(target)) return nullptr;
  return c.textures.binding(target).object.get();
}

bool is_texture_target(GLenum target) {
  return target == GL_TEXTURE_1D || target == GL_TEXTURE_2D || target == GL_TEXTURE_3D ||
         target == GL_TEXTURE_CUBE_MAP || target == kTextureRectangle;
}

void set_texture_target(TextureObject& t, GLenum target) {
  t.target = target;
  t.texture.dimensions = texture_dimensions(target);
  t.texture.cube_map = target == GL_TEXTURE_CUBE_MAP;
  if (t.texture.cube_map) t.faces.resize(6);
  if (target == kTextureRectangle) {  // ARB_texture_rectangle's defaults: no mipmaps, clamped
    t.texture.min_filter = TextureFilter::kLinear;
    t.texture.wrap_s = t.texture.wrap_t = t.texture.wrap_r = TextureWrap::kClampToEdge;
  }
}

TextureObject* image_texture(GlContext& c, GLenum target) {
  if (!is_cube_face(target)) return target == GL_TEXTURE_CUBE_MAP ? nullptr : bound_texture(c, target);
  TextureObject& cube = *c.textures.unit().binding_cube.object;
  if (cube.faces.size() != 6) cube.faces.resize(6);
  TextureObject& face = cube.faces[target - GL_TEXTURE_CUBE_MAP_POSITIVE_X];
  face.generate_mipmap = cube.generate_mipmap;
  face.texture.base_level = cube.texture.base_level;
  face.texture.max_level = cube.texture.max_level;
  return &face;
}

void image_changed(GlContext& c, GLenum target, TextureObject& t, int level) {
  level_changed(t, level);
  if (is_cube_face(target)) assemble_cube(*c.textures.unit().binding_cube.object);
}

// GL 1.3 section 3.8.10's cube completeness, level by level: the six faces defined, square,
// of one size and one internal format (Mesa's _mesa_test_texobj_completeness).
void assemble_cube(TextureObject& cube) {
  std::size_t n = 0;
  for (const TextureObject& f : cube.faces) n = std::max(n, f.images.size());
  cube.images.assign(n, TexImage{});
  cube.texture.levels.assign(n, TextureLevel{});
  for (std::size_t l = 0; l < n; ++l) {
    const TexImage* first = nullptr;
    bool ok = cube.faces.size() == 6;
    for (const TextureObject& f : cube.faces) {
      if (f.images.size() <= l || !f.images[l].defined) { ok = false; break; }
      const TexImage& im = f.images[l];
      if (!first) first = &im;
      if (im.width != im.height || im.width != first->width || im.internal_format != first->internal_format) ok = false;
    }
    if (!ok || first->width <= 0) continue;
    TexImage& img = cube.images[l];
    img.defined = true;
    img.width = img.height = first->width, img.border = first->border;
    img.internal_format = first->internal_format;
    img.format = first->format;
    TextureLevel& core = cube.texture.levels[l];
    core.width = core.height = first->width, core.depth = 6;
    core.rgba.reserve(std::size_t(first->width) * std::size_t(first->width) * 24);
    for (const TextureObject& f : cube.faces) {
      const std::vector<std::uint8_t>& face = f.texture.levels[l].rgba;
      core.rgba.insert(core.rgba.end(), face.begin(), face.end());
      const std::vector<float>& depth = f.texture.levels[l].depth_values;
      core.depth_values.insert(core.depth_values.end(), depth.begin(), depth.end());
    }
  }
  if (!cube.images.empty() && cube.images[0].defined) cube.texture.format = cube.images[0].format.base;
}

// GL 1.5 section 3.8.15: the cube map when enabled, else the 3D texture, else the 2D one, else
// the 1D one. Like
// Mesa, an enabled target whose texture is incomplete gives way to the next enabled one.
namespace {

TextureEnvMode env_mode(GLenum mode) {
  switch (mode) {
    case GL_REPLACE: return TextureEnvMode::kReplace;
    case GL_DECAL: return TextureEnvMode::kDecal;
    case GL_BLEND: return TextureEnvMode::kBlend;
    case GL_ADD: return TextureEnvMode::kAdd;
    case GL_COMBINE: return TextureEnvMode::kCombine;
    default: return TextureEnvMode::kModulate;
  }
}

const Texture* unit_texture(GlContext& c, std::size_t unit, std::shared_ptr<const TextureObject>* object) {
  TextureUnitState& s = c.textures.units[unit];
  const Texture* t = nullptr;
  if (s.enabled_cube && s.binding_cube.object && (t = complete_texture(*s.binding_cube.object))) {
    if (object) *object = s.binding_cube.object;
    return t;
  }
  if (s.enabled_rect && s.binding_rect.object && (t = complete_texture(*s.binding_rect.object))) {
    if (object) *object = s.binding_rect.object;
    return t;
  }
  if (s.enabled_3d && s.binding_3d.object && (t = complete_texture(*s.binding_3d.object))) {
    if (object) *object = s.binding_3d.object;
    return t;
  }
  if (s.enabled_2d && s.binding_2d.object && (t = complete_texture(*s.binding_2d.object))) {
    if (object) *object = s.binding_2d.object;
    return t;
  }
  if (s.enabled_1d && s.binding_1d.object && (t = complete_texture(*s.binding_1d.object))) {
    if (object) *object = s.binding_1d.object;
  }
  return t;
}

}  // namespace

const Texture* unit_texture(GlContext& c, std::size_t unit) { return unit_texture(c, unit, nullptr); }

glm::vec2 rectangle_scale(GlContext& c, std::size_t unit) {
  if (!c.textures.units[unit].enabled_rect) return glm::vec2(1.0f);  // most draws: no lookup
  std::shared_ptr<const TextureObject> object;
  if (!unit_texture(c, unit, &object) || object->target != kTextureRectangle || object->images.empty()) {
    return glm::vec2(1.0f);
  }
  const TexImage& img = object->images[0];
  return glm::vec2(1.0f / float(std::max(img.width, 1)), 1.0f / float(std::max(img.height, 1)));
}

unsigned textured_units(GlContext& c) {
  unsigned bits = c.render_mode == GL_FEEDBACK ? 1u : 0u;
  for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {
    if (unit_texture(c, u)) bits |= 1u << u;
  }
  return bits;
}

void texture_draw_state(GlContext& c, ShadeState& shade) {
  std::vector<GlContext::KeptTexture>& kept = c.textures_of_waiting_draws;
  bool counted = false;
  for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {
    const TextureUnitState& s = c.textures.units[u];
    TextureUnit& unit = shade.textures[u];
    std::shared_ptr<const TextureObject> object;
    unit.texture = unit_texture(c, u, &object);
    unit.env = env_mode(s.env_mode);
    unit.env_color = s.env_color;
    unit.lod_bias = s.lod_bias;
    if (unit.env == TextureEnvMode::kCombine) unit.combine = core_combine(s.combine);
    if (!unit.texture) continue;
    shade.texture_kept = true;
    if (!counted) {
      // The waiting draws are always the last ones made: a texture whose last draw is drawn by
      // now (deleted or redefined since, perhaps) need not be kept. A program that draws with a
      // new texture each time, without glFinish, keeps a queue's worth, not all of them.
      counted = true;
      if (!c.pipeline) {
        kept.clear();
      } else {
        const std::uint64_t drawn = c.pipeline->draws_made() - c.pipeline->deferred_draws();
        std::erase_if(kept, [&](const GlContext::KeptTexture& k) { return k.draw <= drawn; });
      }
    }
    // This draw's number, if it reaches the pipeline (if not, the next draw's: kept longer).
    const std::uint64_t draw = c.pipeline ? c.pipeline->draws_made() + 1 : 0;
    auto same = [&](const GlContext::KeptTexture& k) { return k.object == object; };
    if (auto it = std::find_if(kept.begin(), kept.end(), same); it != kept.end()) it->draw = draw;
    else kept.push_back({std::move(object), draw});
  }
}

void texture_changing(GlContext& c, const TextureObject& t) {
  if (!c.pipeline || c.pipeline->deferred_draws() == 0) return;
  for (const GlContext::KeptTexture& k : c.textures_of_waiting_draws) {
    if (k.object.get() == &t) return c.pipeline->finish_draws();
    for (const TextureObject& face : k.object->faces) {  // a cube map's face
      if (&face == &t) return c.pipeline->finish_draws();
    }
  }
}

void exec::GenTextures(GlContext& c, GLsizei n, GLuint* textures) {
  if (n < 0) return c.set_error(GL_INVALID_VALUE);
  if (n > 0 && !textures) return c.set_error(GL_INVALID_VALUE);
  TextureNames& names = *c.textures.names;
  for (GLsizei i = 0; i < n; ++i) {
    while (names.next_name == 0 || names.objects.count(names.next_name)) ++names.next_name;
    GLuint name = names.next_name++;
    names.objects[name] = std::make_shared<TextureObject>();  // its target comes at its first bind
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
    for (TextureUnitState& u : c.textures.units) {
      for (TextureBinding* b : {&u.binding_1d, &u.binding_2d, &u.binding_3d, &u.binding_cube}) {
        if (b->name == textures[i]) *b = {0, b->default_object, b->default_object};
      }
    }
  }
}

// A name bound to one target cannot be bound to the other: GL_INVALID_OPERATION.
void exec::BindTexture(GlContext& c, GLenum target, GLuint texture) {
  if (!is_texture_target(target)) return c.set_error(GL_INVALID_ENUM);
  TextureBinding& b = c.textures.binding(target);
  if (texture == 0) {
    b.name = 0;
    b.object = b.default_object;
    return;
  }
  std::shared_ptr<TextureObject>& obj = c.textures.names->objects[texture];
  if (!obj) obj = std::make_shared<TextureObject>();
  if (obj->target != 0 && obj->target != target) return c.set_error(GL_INVALID_OPERATION);
  if (obj->target == 0) set_texture_target(*obj, target);
  b.name = texture;
  b.object = obj;
}

// True once the name's object has been bound (Mesa's rule).
GLboolean exec::IsTexture(GlContext& c, GLuint texture) {
  auto it = c.textures.names->objects.find(texture);
  return it != c.textures.names->objects.end() && it->second && it->second->target != 0 ? GL_TRUE : GL_FALSE;
}

// Priorities clamped to [0, 1]; unknown names and 0 are skipped (Mesa's texobj.c).
void exec::PrioritizeTextures(GlContext& c, GLsizei n, const GLuint* textures, const GLclampf* priorities) {
  if (n < 0) return c.set_error(GL_INVALID_VALUE);
  if (!textures || !priorities) return;
  for (GLsizei i = 0; i < n; ++i) {
    auto it = c.textures.names->objects.find(textures[i]);
    if (textures[i] == 0 || it == c.textures.names->objects.end() || !it->second) continue;
    it->second->priority = std::clamp(finite_or_zero(priorities[i]), 0.0f, 1.0f);
  }
}

// Every texture is resident: GL_TRUE, `residences` untouched (GL 1.1 section 3.8.8 lets the
// answer stop there); 0 or an unknown name is GL_INVALID_VALUE.
GLboolean exec::AreTexturesResident(GlContext& c, GLsizei n, const GLuint* textures, GLboolean* residences) {
  if (n < 0) return c.set_error(GL_INVALID_VALUE), GL_FALSE;
  if (!textures || !residences) return GL_FALSE;
  for (GLsizei i = 0; i < n; ++i) {
    auto it = c.textures.names->objects.find(textures[i]);
    if (textures[i] == 0 || it == c.textures.names->objects.end() || !it->second) {
      return c.set_error(GL_INVALID_VALUE), GL_FALSE;
    }
  }
  return GL_TRUE;
}

void exec::TexParameterf(GlContext& c, GLenum target, GLenum pname, GLfloat param) {
  tex_parameter(c, target, pname, &param, false, true);
}
void exec::TexParameteri(GlContext& c, GLenum target, GLenum pname, GLint param) {
  float v = float(param);
  tex_parameter(c, target, pname, &v, false, false);
}
void exec::TexParameterfv(GlContext& c, GLenum target, GLenum pname, const GLfloat* params) {
  tex_parameter(c, target, pname, params, true, false);
}
void exec::TexParameteriv(GlContext& c, GLenum target, GLenum pname, const GLint* params) {
  float v[4] = {0, 0, 0, 0};
  int n = pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1;
  if (params) to_floats(params, n, pname == GL_TEXTURE_BORDER_COLOR, v);
  tex_parameter(c, target, pname, params ? v : nullptr, true, false);
}
void exec::GetTexParameterfv(GlContext& c, GLenum target, GLenum pname, GLfloat* params) {
  get_tex_parameter_call(c, target, pname, params);
}
void exec::GetTexParameteriv(GlContext& c, GLenum target, GLenum pname, GLint* params) {
  get_tex_parameter_call(c, target, pname, params);
}

// How many values the vector forms read, for their display-list savers: the first value
// decides, as in the commands themselves.
std::size_t save_count::TexParameterfv(GLenum pname) { return pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1; }
std::size_t save_count::TexParameteriv(GLenum pname) { return pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1; }

}  // namespace shadelab::gl
