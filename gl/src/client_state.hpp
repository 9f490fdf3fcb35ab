// The client state of a context (GL 1.1 section 6.1.14's client attribute groups): the pixel
// store parameters of each direction and the vertex arrays (with GL 1.3's per-unit texture
// coordinate arrays, GL 1.4's secondary colour and fog coordinate arrays and GL 1.5's buffer
// bindings), and the glPushClientAttrib record that saves them. Plain data: the commands that
// set them are arrays.cpp's, pixels.cpp's and attrib.cpp's; array_fetch.cpp reads the arrays.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstddef>
#include <memory>

#include "gl/src/buffer_state.hpp"
#include "shadelab/texture.hpp"

namespace shadelab::gl {

/// glPixelStore parameters for one direction (pack: glReadPixels, unpack: glTexImage2D).
struct PixelStore {
  GLint alignment = 4, row_length = 0, skip_pixels = 0, skip_rows = 0;
  GLint image_height = 0, skip_images = 0;  // GL 1.2: 3D images (section 3.6.4)
  bool swap_bytes = false, lsb_first = false;
};

struct ClientArray {
  bool enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLsizei stride = 0;
  const void* pointer = nullptr;  // an offset into `buffer` when there is one
  // GL 1.5 section 2.9: the buffer bound to GL_ARRAY_BUFFER when the pointer was given
  // (GL_*_ARRAY_BUFFER_BINDING), null for client memory.
  std::shared_ptr<BufferObject> buffer;
  GLuint buffer_name = 0;
};

struct ClientArrays {
  static ClientArray initial(GLint size, GLenum type = GL_FLOAT) {
    ClientArray a;
    a.size = size, a.type = type;
    return a;
  }
  ClientArray vertex, normal = initial(3), color;
  // Per texture unit (GL 1.3 section 2.8): glTexCoordPointer and GL_TEXTURE_COORD_ARRAY address
  // the client active unit's (glClientActiveTexture).
  std::array<ClientArray, kMaxTextureUnits> texcoords;
  std::size_t client_active = 0;
  ClientArray& texcoord() { return texcoords[client_active]; }
  const ClientArray& texcoord() const { return texcoords[client_active]; }
  ClientArray secondary_color = initial(3), fog_coord = initial(1);  // GL 1.4 section 2.8
  ClientArray index = initial(1);                        // colour indices: current index only
  ClientArray edge_flag = initial(1, GL_UNSIGNED_BYTE);  // GLboolean elements
  // GL 1.5: GL_ARRAY_BUFFER and GL_ELEMENT_ARRAY_BUFFER (vertex-array client state).
  std::shared_ptr<BufferObject> array_buffer, element_buffer;
  GLuint array_buffer_name = 0, element_buffer_name = 0;
  /// Every array, for what applies to all of them (buffers read in place, deleted buffers).
  std::array<ClientArray*, 7 + kMaxTextureUnits> all() {
    static_assert(kMaxTextureUnits == 4);
    return {&vertex,       &normal,       &color,           &texcoords[0], &texcoords[1], &texcoords[2],
            &texcoords[3], &secondary_color, &fog_coord, &index,        &edge_flag};
  }
};

/// One glPushClientAttrib entry (GL 1.1 section 6.1.14).
struct ClientAttribRecord {
  GLbitfield mask = 0;
  PixelStore pack, unpack;
  ClientArrays arrays;
};

}  // namespace shadelab::gl
