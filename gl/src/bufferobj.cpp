// Buffer objects (GL 1.5 section 2.9): glGenBuffers, glDeleteBuffers, glIsBuffer,
// glBindBuffer, glBufferData, glBufferSubData, glGetBufferSubData, glMapBuffer,
// glUnmapBuffer, glGetBufferParameteriv, glGetBufferPointerv (section 6.1.13), for the
// GL_ARRAY_BUFFER and GL_ELEMENT_ARRAY_BUFFER targets. Object and binding state only, with
// the errors in Mesa's order; arrays.cpp reads the vertex and index data out of the objects.
#include <algorithm>
#include <cstring>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {
namespace {

// The binding a target names (nullptr: not a buffer target, GL_INVALID_ENUM).
std::shared_ptr<BufferObject>* binding(GlContext& c, GLenum target, GLuint** name = nullptr) {
  switch (target) {
    case GL_ARRAY_BUFFER:
      if (name) *name = &c.arrays.array_buffer_name;
      return &c.arrays.array_buffer;
    case GL_ELEMENT_ARRAY_BUFFER:
      if (name) *name = &c.arrays.element_buffer_name;
      return &c.arrays.element_buffer;
    default: return nullptr;
  }
}

// The object bound to `target`, or null after recording the error: GL_INVALID_ENUM for a
// target that is none, GL_INVALID_OPERATION when buffer 0 is bound.
BufferObject* bound(GlContext& c, GLenum target) {
  std::shared_ptr<BufferObject>* b = binding(c, target);
  if (!b) return c.set_error(GL_INVALID_ENUM), nullptr;
  if (!*b) return c.set_error(GL_INVALID_OPERATION), nullptr;
  return b->get();
}

bool valid_usage(GLenum usage) {
  switch (usage) {
    case GL_STREAM_DRAW: case GL_STREAM_READ: case GL_STREAM_COPY:
    case GL_STATIC_DRAW: case GL_STATIC_READ: case GL_STATIC_COPY:
    case GL_DYNAMIC_DRAW: case GL_DYNAMIC_READ: case GL_DYNAMIC_COPY:
      return true;
    default: return false;
  }
}

// Every binding of the current context to `object` becomes 0 (section 2.9: other contexts
// keep theirs).
void unbind_everywhere(GlContext& c, const BufferObject* object) {
  ClientArrays& a = c.arrays;
  auto drop = [&](std::shared_ptr<BufferObject>& b, GLuint& name) {
    if (b.get() == object) b.reset(), name = 0;
  };
  drop(a.array_buffer, a.array_buffer_name);
  drop(a.element_buffer, a.element_buffer_name);
  // An array's binding reads 0 from now on; it keeps the object, so that a draw from it reads
  // the orphaned store rather than the offset as an address (the specification leaves that
  // draw undefined).
  for (ClientArray* array : a.all()) {
    if (array->buffer.get() == object) array->buffer_name = 0;
  }
}

// Section 2.9's range rule for glBufferSubData and glGetBufferSubData.
bool in_range(const BufferObject& b, GLintptr offset, GLsizeiptr size) {
  return offset >= 0 && size >= 0 && std::size_t(offset) + std::size_t(size) <= b.data.size();
}

}  // namespace

void exec::GenBuffers(GlContext& c, GLsizei n, GLuint* buffers) {
  if (n < 0) return c.set_error(GL_INVALID_VALUE);
  if (!buffers) return;
  BufferNames& names = *c.buffer_names;
  std::lock_guard<std::mutex> lock(names.mutex);
  // After the largest name ever used, as Mesa's names come.
  for (GLsizei i = 0; i < n; ++i) {
    buffers[i] = ++names.max_name;
    names.buffers.emplace(buffers[i], nullptr);
  }
}

// Deleting a bound buffer unbinds it (section 2.9); unknown names and 0 are ignored.
void exec::DeleteBuffers(GlContext& c, GLsizei n, const GLuint* buffers) {
  if (n < 0) return c.set_error(GL_INVALID_VALUE);
  if (!buffers) return;
  BufferNames& names = *c.buffer_names;
  for (GLsizei i = 0; i < n; ++i) {
    std::shared_ptr<BufferObject> object;
    {
      std::lock_guard<std::mutex> lock(names.mutex);
      auto it = names.buffers.find(buffers[i]);
      if (buffers[i] == 0 || it == names.buffers.end()) continue;
      object = std::move(it->second);
      names.buffers.erase(it);
    }
    if (!object) continue;
    object->mapped = false;  // a deleted buffer is unmapped
    unbind_everywhere(c, object.get());
  }
}

GLboolean exec::IsBuffer(GlContext& c, GLuint buffer) {
  BufferNames& names = *c.buffer_names;
  std::lock_guard<std::mutex> lock(names.mutex);
  auto it = names.buffers.find(buffer);
  return it != names.buffers.end() && it->second ? GL_TRUE : GL_FALSE;
}

// Binding a name makes its object (zero-sized) if it has none; 0 binds no buffer.
void exec::BindBuffer(GlContext& c, GLenum target, GLuint buffer) {
  GLuint* name = nullptr;
  std::shared_ptr<BufferObject>* b = binding(c, target, &name);
  if (!b) return c.set_error(GL_INVALID_ENUM);
  std::shared_ptr<BufferObject> object;
  if (buffer != 0) {
    BufferNames& names = *c.buffer_names;
    std::lock_guard<std::mutex> lock(names.mutex);
    std::shared_ptr<BufferObject>& slot = names.buffers[buffer];
    names.max_name = std::max(names.max_name, buffer);
    if (!slot) slot = std::make_shared<BufferObject>();
    object = slot;
  }
  *b = std::move(object);
  *name = buffer;
}

// A new data store of `size` bytes (a mapping of the old one ends), from `data` or undefined
// (zeros here).
void exec::BufferData(GlContext& c, GLenum target, GLsizeiptr size, const void* data, GLenum usage) {
  BufferObject* b = bound(c, target);
  if (!b) return;
  if (size < 0) return c.set_error(GL_INVALID_VALUE);
  if (!valid_usage(usage)) return c.set_error(GL_INVALID_ENUM);
  std::vector<unsigned char> store(static_cast<std::size_t>(size));
  if (data && size > 0) std::memcpy(store.data(), data, std::size_t(size));
  b->data = std::move(store);
  b->usage = usage;
  b->mapped = false;
  b->access = GL_READ_WRITE;
}

void exec::BufferSubData(GlContext& c, GLenum target, GLintptr offset, GLsizeiptr size, const void* data) {
  BufferObject* b = bound(c, target);
  if (!b) return;
  if (!in_range(*b, offset, size)) return c.set_error(GL_INVALID_VALUE);
  if (b->mapped) return c.set_error(GL_INVALID_OPERATION);
  if (data && size > 0) std::memcpy(b->data.data() + offset, data, std::size_t(size));
}

void exec::GetBufferSubData(GlContext& c, GLenum target, GLintptr offset, GLsizeiptr size, void* data) {
  BufferObject* b = bound(c, target);
  if (!b) return;
  if (!in_range(*b, offset, size)) return c.set_error(GL_INVALID_VALUE);
  if (b->mapped) return c.set_error(GL_INVALID_OPERATION);
  if (data && size > 0) std::memcpy(data, b->data.data() + offset, std::size_t(size));
}

// The data store itself is the mapping, so draws may read a mapped buffer: GL 1.5 leaves
// them undefined and Mesa 22.3 raises no error and draws.
void* exec::MapBuffer(GlContext& c, GLenum target, GLenum access) {
  if (access != GL_READ_ONLY && access != GL_WRITE_ONLY && access != GL_READ_WRITE) {
    return c.set_error(GL_INVALID_ENUM), nullptr;
  }
  BufferObject* b = bound(c, target);
  if (!b) return nullptr;
  if (b->mapped) return c.set_error(GL_INVALID_OPERATION), nullptr;
  if (b->data.empty()) return c.set_error(GL_INVALID_OPERATION), nullptr;  // Mesa's code
  b->mapped = true;
  b->access = access;
  return b->data.data();
}

// The contents are never lost here: GL_TRUE.
GLboolean exec::UnmapBuffer(GlContext& c, GLenum target) {
  BufferObject* b = bound(c, target);
  if (!b) return GL_FALSE;
  if (!b->mapped) return c.set_error(GL_INVALID_OPERATION), GL_FALSE;
  b->mapped = false;
  b->access = GL_READ_WRITE;
  return GL_TRUE;
}

void exec::GetBufferParameteriv(GlContext& c, GLenum target, GLenum pname, GLint* params) {
  BufferObject* b = bound(c, target);
  if (!b) return;
  GLint value = 0;
  switch (pname) {
    case GL_BUFFER_SIZE: value = GLint(std::min<std::size_t>(b->data.size(), 0x7fffffff)); break;
    case GL_BUFFER_USAGE: value = GLint(b->usage); break;
    case GL_BUFFER_ACCESS: value = GLint(b->access); break;
    case GL_BUFFER_MAPPED: value = b->mapped; break;
    default: return c.set_error(GL_INVALID_ENUM);
  }
  if (params) *params = value;
}

void exec::GetBufferPointerv(GlContext& c, GLenum target, GLenum pname, void** params) {
  if (pname != GL_BUFFER_MAP_POINTER) return c.set_error(GL_INVALID_ENUM);
  BufferObject* b = bound(c, target);
  if (!b) return;
  if (params) *params = b->mapped ? b->data.data() : nullptr;
}

}  // namespace shadelab::gl
