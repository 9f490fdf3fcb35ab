// Compressed texture images (GL 1.3; GL 1.5 section 3.8.3): glCompressedTexImage1D/2D/3D,
// glCompressedTexSubImage1D/2D/3D and glGetCompressedTexImage. shadelab has no specific
// compressed format (GL_NUM_COMPRESSED_TEXTURE_FORMATS is 0), so every such call is an error:
// the one Mesa gives a target or format it cannot compress, in Mesa's order. The generic
// compressed internal formats of glTexImage (GL_COMPRESSED_RGB ...) are texformat.cpp's, stored
// uncompressed. Errors only; no state changes.
#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {
namespace {

bool generic_compressed(GLenum format) {
  switch (format) {
    case GL_COMPRESSED_ALPHA: case GL_COMPRESSED_LUMINANCE: case GL_COMPRESSED_LUMINANCE_ALPHA:
    case GL_COMPRESSED_INTENSITY: case GL_COMPRESSED_RGB: case GL_COMPRESSED_RGBA:
      return true;
    default: return false;
  }
}

// glCompressedTexImage: whatever the target (1D and 3D ones cannot hold compressed images,
// other enums are no target) and whatever the format (no specific compressed format exists),
// GL_INVALID_ENUM, before any other argument is looked at (Mesa's first two checks).
void compressed_image(GlContext& c) { c.set_error(GL_INVALID_ENUM); }

// glCompressedTexSubImage: a target that can hold no compressed image (every 1D target, and
// anything but GL_TEXTURE_2D / GL_TEXTURE_3D) is GL_INVALID_ENUM; then, in 2D, a generic
// compressed format GL_INVALID_ENUM and any other format GL_INVALID_OPERATION (it cannot match
// the image's format, which is never compressed); in 3D any format GL_INVALID_OPERATION (Mesa's
// codes, measured).
void compressed_sub_image(GlContext& c, int dims, GLenum target, GLenum format) {
  const bool target_ok = (dims == 2 && target == GL_TEXTURE_2D) || (dims == 3 && target == GL_TEXTURE_3D);
  if (!target_ok || (dims == 2 && generic_compressed(format))) return c.set_error(GL_INVALID_ENUM);
  c.set_error(GL_INVALID_OPERATION);
}

}  // namespace

void exec::CompressedTexImage1D(GlContext& c, GLenum, GLint, GLenum, GLsizei, GLint, GLsizei, const void*) {
  compressed_image(c);
}
void exec::CompressedTexImage2D(GlContext& c, GLenum, GLint, GLenum, GLsizei, GLsizei, GLint, GLsizei, const void*) {
  compressed_image(c);
}
void exec::CompressedTexImage3D(GlContext& c, GLenum, GLint, GLenum, GLsizei, GLsizei, GLsizei, GLint, GLsizei,
                                const void*) {
  compressed_image(c);
}
void exec::CompressedTexSubImage1D(GlContext& c, GLenum target, GLint, GLint, GLsizei, GLenum format, GLsizei,
                                   const void*) {
  compressed_sub_image(c, 1, target, format);
}
void exec::CompressedTexSubImage2D(GlContext& c, GLenum target, GLint, GLint, GLint, GLsizei, GLsizei, GLenum format,
                                   GLsizei, const void*) {
  compressed_sub_image(c, 2, target, format);
}
void exec::CompressedTexSubImage3D(GlContext& c, GLenum target, GLint, GLint, GLint, GLint, GLsizei, GLsizei, GLsizei,
                                   GLenum format, GLsizei, const void*) {
  compressed_sub_image(c, 3, target, format);
}

// No image is compressed: a target that is none is GL_INVALID_ENUM, a level out of range or
// with no image GL_INVALID_VALUE, an image GL_INVALID_OPERATION (Mesa's codes).
void exec::GetCompressedTexImage(GlContext& c, GLenum target, GLint level, void*) {
  if (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D && target != GL_TEXTURE_3D) return c.set_error(GL_INVALID_ENUM);
  if (level < 0 || level >= kMaxTextureLevels || target == GL_TEXTURE_3D) return c.set_error(GL_INVALID_VALUE);
  const std::vector<TexImage>& images = c.textures.binding(target).object->images;
  if (std::size_t(level) >= images.size() || !images[std::size_t(level)].defined) return c.set_error(GL_INVALID_VALUE);
  c.set_error(GL_INVALID_OPERATION);
}

}  // namespace shadelab::gl
