// Buffer objects in a context (GL 1.5 section 2.9): the objects, their names shared between
// contexts that share display lists, and the bindings. Plain data; gl/src/bufferobj.cpp
// implements the commands, gl/src/arrays.cpp reads vertex and index data from the objects in
// place. Nothing here draws.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

namespace shadelab::gl {

/// One buffer object's data store and parameters (GL 1.5 table 2.6).
struct BufferObject {
  std::vector<unsigned char> data;  // GL_BUFFER_SIZE bytes
  GLenum usage = GL_STATIC_DRAW;
  GLenum access = GL_READ_WRITE;  // of the current mapping
  bool mapped = false;            // GL_BUFFER_MAPPED: data.data() is GL_BUFFER_MAP_POINTER
};

/// Buffer names and their objects, shared between contexts as display lists are. A name
/// glGenBuffers returned has no object until it is first bound (glIsBuffer is false until then,
/// as in Mesa).
struct BufferNames {
  std::mutex mutex;  // contexts current in different threads may share them
  std::map<GLuint, std::shared_ptr<BufferObject>> buffers;  // null: generated, never bound
  GLuint max_name = 0;  // the largest name ever generated or bound
};

}  // namespace shadelab::gl
