// What the texture files share (GL 1.1 section 3.8): the object bound to a target, the
// texture the pipeline samples, and the image operations the copy and query commands reuse.
// No entry points here.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "gl/src/context.hpp"

namespace shadelab::gl {

/// The object bound to GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP or
/// GL_TEXTURE_RECTANGLE_ARB (the target's default object while name 0 is bound); nullptr for
/// any other target.
TextureObject* bound_texture(GlContext& c, GLenum target);
/// Whether glBindTexture, glEnable and glTexParameter take `target` (bound_texture's targets).
bool is_texture_target(GLenum target);
/// Gives a new object its target (at its first binding): its dimensions, a cube map's faces,
/// a rectangle texture's defaults (GL_LINEAR minification, GL_CLAMP_TO_EDGE).
void set_texture_target(TextureObject& t, GLenum target);

/// The texture texture unit `unit` applies (GL 1.5 section 3.8.15), or nullptr:
/// GL_TEXTURE_CUBE_MAP when enabled and complete, else GL_TEXTURE_RECTANGLE_ARB, else
/// GL_TEXTURE_3D, else GL_TEXTURE_2D, else GL_TEXTURE_1D (an incomplete texture is as if its
/// target were disabled, as in Mesa).
const Texture* unit_texture(GlContext& c, std::size_t unit);
/// What unit `unit`'s texture coordinates s and t are multiplied by before the pipeline sees
/// them: 1 / width and 1 / height when the unit applies a rectangle texture (addressed by texel
/// coordinates, sampled by the pipeline as a 2D texture), else 1.
glm::vec2 rectangle_scale(GlContext& c, std::size_t unit);

/// Where the images of an image target live: the bound object of GL_TEXTURE_1D, _2D or _3D,
/// or the face of the bound cube map for a face target (its base and maximum levels and
/// mipmap generation those of the cube map); nullptr for any other target.
TextureObject* image_texture(GlContext& c, GLenum target);

/// Call after level `level` of image target `target` (image_texture's `t`) was specified or
/// its texels changed: GL_GENERATE_MIPMAP's levels (level_changed), and a face's cube map
/// assembled again.
void image_changed(GlContext& c, GLenum target, TextureObject& t, int level);

/// A cube map's levels made from its faces (TextureObject::faces).
void assemble_cube(TextureObject& cube);

/// The bits of the texture units that apply a texture (unit_texture), GL_FEEDBACK's unit 0
/// too (feedback reports its coordinates whether or not a texture applies, as Mesa's): the
/// units whose texture coordinates a draw carries.
unsigned textured_units(GlContext& c);

/// Sets the texturing of a draw's `shade` (each unit's texture, its environment mode and
/// colour) and marks the textures kept (ShadeState::texture_kept): the objects stay alive
/// while draws that read them wait, and texture_changing finishes them before they change.
void texture_draw_state(GlContext& c, ShadeState& shade);

/// An enum-valued parameter given as a float: glTexParameterf rounds it, the vector forms
/// truncate (Mesa's texparam.c).
GLint enum_param(float v, bool rounded);

/// The core's form of a unit's GL_COMBINE environment (texenv.cpp).
TextureCombine core_combine(const TexEnvCombine& c);

/// Call before `t`'s texels or parameters change: the waiting draws that read it are drawn
/// first (GL's order), as Mesa flushes before it modifies a texture.
void texture_changing(GlContext& c, const TextureObject& t);

/// Pixels as RGBA floats, row by row from the first, ready to be stored into a texture:
/// `exact_bytes` when they were unsigned bytes passed through unchanged (then stored exactly
/// as Mesa stores bytes); `from_framebuffer` for glCopyTex*, whose 5-bit components llvmpipe
/// truncates (measured: its copy renders into the texture) where glTexImage rounds.
struct RgbaImage {
  int width = 0, height = 0;
  int depth = 1;  // images of `height` rows, one after the other
  std::vector<float> rgba;
  bool exact_bytes = false;
  bool from_framebuffer = false;
};

/// Stores `image` as texels (converted to `image_format`'s storage) at (x, y, z) of a level
/// whose storage is described by `level` and `core`, both already sized.
void store_texels(const RgbaImage& image, int x, int y, int z, TexImage& level, TextureLevel& core);

/// Makes level `level` of `t` a width x height image of `internal_format` (contents zero),
/// with the core's format and dimensions following level 0; false (nothing changed) when the
/// internal format is not one.
bool define_level(TextureObject& t, int level, GLint internal_format, int width, int height, int depth = 1);

/// GL_GENERATE_MIPMAP (GL 1.4, mipmap.cpp): call after level `level` of `t` was specified or
/// its texels changed; when it is the base level of a texture generating its mipmaps (and
/// below GL_TEXTURE_MAX_LEVEL), the levels after it are made again from it.
void level_changed(TextureObject& t, int level);

/// The number of levels a texture of `target` may have (GL_MAX_TEXTURE_SIZE's log2 + 1).
inline constexpr int max_texture_levels() { return kMaxTextureLevels; }

}  // namespace shadelab::gl
