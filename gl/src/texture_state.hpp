// The texture state of a context (GL 1.1 section 3.8, tables 6.15-6.16): texture objects by
// name, shared between contexts that share them, each with its levels as glTexImage specified
// them and in the core's form; per texture unit (GL 1.3), the bindings of the 1D, 2D and 3D
// targets, the texture environment and glTexGen's planes. Plain data; the commands are texture.cpp's, teximage.cpp's and their
// neighbours', and the pipeline samples the core's Texture.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include <glm/vec4.hpp>

#include "gl/src/texformat.hpp"
#include "shadelab/texture.hpp"

namespace shadelab::gl {

/// One level of a texture as glTexImage specified it (GL 1.1 section 3.8, table 6.16): what
/// glGetTexLevelParameter reports and, for formats of more than 8 bits a component, the stored
/// components (the core's RGBA8 level holds the rest: gl/src/texformat.hpp).
struct TexImage {
  bool defined = false;  // specified by glTexImage or glCopyTexImage (a proxy: accepted)
  int width = 0, height = 0, border = 0;
  int depth = 1;  // images of a 3D level
  GLint internal_format = GL_RGBA;  // as given; Mesa reports GL_RGBA for an undefined image
  StoredFormat format;
  std::vector<std::uint16_t> wide;  // format.components per texel when format.wide()
  std::vector<std::uint8_t> stencil;  // a texel's stencil index when format.stencil_bits
};

/// A texture object (GL 1.1 section 3.8.8): its target, fixed at its first binding, its
/// levels and parameters in the core's form (what the pipeline samples), and what GL reports.
struct TextureObject {
  GLenum target = 0;  // GL_TEXTURE_1D, _2D, _3D or _CUBE_MAP once bound; 0 before
  Texture texture;
  std::vector<TexImage> images;  // per level
  float priority = 1.0f;
  bool generate_mipmap = false;  // GL_GENERATE_MIPMAP (GL 1.4): mipmap.cpp
  /// GL_DEPTH_TEXTURE_MODE (GL 1.4): a depth texture's texels as luminance, intensity or alpha
  /// (the core's Texture::format while the base level is a depth image).
  TextureFormat depth_mode = TextureFormat::kLuminance;
  /// A cube map's six faces (GL 1.3 section 3.8.1; +X, -X, +Y, -Y, +Z, -Z), each holding its
  /// own images and 2D levels as glTexImage2D of its face target made them; `images` and
  /// `texture.levels` are then their assembly (assemble_cube): a level where the six faces
  /// are square, of one size and one internal format, else undefined (cube completeness).
  std::vector<TextureObject> faces;
};

/// Texture objects by name; shared between contexts created with a sharelist. glGenTextures
/// makes the objects (as Mesa does), without a target until their first binding.
struct TextureNames {
  std::unordered_map<GLuint, std::shared_ptr<TextureObject>> objects;
  GLuint next_name = 1;
};

/// A texture target's binding: the named object bound, or the target's default object (name 0).
struct TextureBinding {
  GLuint name = 0;
  std::shared_ptr<TextureObject> object;
  std::shared_ptr<TextureObject> default_object;
};

/// glTexGen state of one coordinate (GL 1.1 section 2.10.4). The eye plane is stored as given
/// times the inverse of the modelview matrix at the call.
struct TexGenCoord {
  bool enabled = false;  // GL_TEXTURE_GEN_S .. Q
  GLenum mode = GL_EYE_LINEAR;
  glm::vec4 object_plane{0.0f}, eye_plane{0.0f};
};

/// ARB_texture_rectangle (core in GL 3.1; GL 1.5's headers do not name it): 2D textures of one
/// level addressed by texel coordinates, s in [0, width] and t in [0, height].
inline constexpr GLenum kTextureRectangle = 0x84F5;         // GL_TEXTURE_RECTANGLE_ARB
inline constexpr GLenum kTextureBindingRectangle = 0x84F6;  // GL_TEXTURE_BINDING_RECTANGLE_ARB
inline constexpr GLenum kProxyTextureRectangle = 0x84F7;    // GL_PROXY_TEXTURE_RECTANGLE_ARB
inline constexpr GLenum kMaxRectangleTextureSize = 0x84F8;  // GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB

/// ARB_point_sprite (core in GL 2.0): the enable (also glTexEnv's target) and glTexEnv's
/// GL_COORD_REPLACE_ARB.
inline constexpr GLenum kPointSprite = 0x8861;   // GL_POINT_SPRITE_ARB
inline constexpr GLenum kCoordReplace = 0x8862;  // GL_COORD_REPLACE_ARB

/// The core's dimensions of a texture target: 1, 2 or 3 (a cube map's faces and a rectangle: 2).
inline int texture_dimensions(GLenum target) {
  return target == GL_TEXTURE_1D ? 1 : target == GL_TEXTURE_3D ? 3 : 2;
}

/// GL_TEXTURE_CUBE_MAP_POSITIVE_X .. GL_TEXTURE_CUBE_MAP_NEGATIVE_Z (GL 1.3): the targets of a
/// cube map's images.
inline bool is_cube_face(GLenum target) {
  return target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z;
}

/// A unit's GL_COMBINE environment as glTexEnv gave it (GL 1.3 section 3.8.13, table 6.20):
/// the functions, sources and operands of the colour and of alpha, and the scales.
struct TexEnvCombine {
  GLenum rgb = GL_MODULATE, alpha = GL_MODULATE;
  std::array<GLenum, 3> source_rgb{GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  std::array<GLenum, 3> source_alpha{GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  std::array<GLenum, 3> operand_rgb{GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
  std::array<GLenum, 3> operand_alpha{GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA};
  float rgb_scale = 1.0f, alpha_scale = 1.0f;
};

/// One texture unit (GL 1.3 section 2.7; table 6.19 ff.): its target enables and bindings,
/// its environment and its coordinate generation. Its texture matrix stack and current
/// texture coordinates are the context's (per unit there too).
struct TextureUnitState {
  bool enabled_1d = false, enabled_2d = false, enabled_3d = false;  // GL_TEXTURE_1D, _2D, _3D
  bool enabled_cube = false;                                        // GL_TEXTURE_CUBE_MAP (GL 1.3)
  bool enabled_rect = false;                                        // GL_TEXTURE_RECTANGLE_ARB
  TextureBinding binding_1d, binding_2d, binding_3d, binding_cube, binding_rect;
  GLenum env_mode = GL_MODULATE;
  glm::vec4 env_color{0.0f};
  float lod_bias = 0.0f;  // GL_TEXTURE_FILTER_CONTROL's GL_TEXTURE_LOD_BIAS (GL 1.4)
  TexEnvCombine combine;
  std::array<TexGenCoord, 4> gen;  // s, t, r, q

  TextureBinding& binding(GLenum target) {
    return target == GL_TEXTURE_1D     ? binding_1d
           : target == GL_TEXTURE_3D   ? binding_3d
           : target == GL_TEXTURE_CUBE_MAP ? binding_cube
           : target == kTextureRectangle ? binding_rect
                                       : binding_2d;
  }
  const TextureBinding& binding(GLenum target) const { return const_cast<TextureUnitState*>(this)->binding(target); }
  bool any_texgen() const { return gen[0].enabled || gen[1].enabled || gen[2].enabled || gen[3].enabled; }
};

struct TextureState {
  std::array<TextureUnitState, kMaxTextureUnits> units;
  std::size_t active = 0;  // glActiveTexture's unit (GL_ACTIVE_TEXTURE - GL_TEXTURE0)
  // The proxy targets' levels (GL 1.1 section 3.8.1): state only, no texels.
  std::vector<TexImage> proxy_1d, proxy_2d, proxy_3d, proxy_cube, proxy_rect;
  std::shared_ptr<TextureNames> names;

  /// The active unit, which glBindTexture, glTexEnv, glTexGen, glEnable of a texture target and
  /// the texture queries address.
  TextureUnitState& unit() { return units[active]; }
  const TextureUnitState& unit() const { return units[active]; }
  TextureBinding& binding(GLenum target) { return unit().binding(target); }
  const TextureBinding& binding(GLenum target) const { return unit().binding(target); }
};

}  // namespace shadelab::gl
