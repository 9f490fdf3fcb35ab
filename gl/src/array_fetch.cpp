// Reading vertex arrays' elements: components converted as each command converts them,
// arrays in buffer objects resolved for a draw, index data (array_fetch.hpp).
#include "gl/src/array_fetch.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <type_traits>

#include "gl/src/convert.hpp"

namespace shadelab::gl {
namespace {

template <class T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);  // arrays need not be aligned
  return v;
}

template <class T>
float convert_component(T v, Norm norm) {
  if (norm == Norm::kDirect) return float(v);
  if (norm == Norm::kSpec) return color_component(v);
  if constexpr (std::is_signed_v<T>) {
    return std::max(-1.0f, float(double(v) / double(std::numeric_limits<T>::max())));
  } else {
    return float(double(v) / double(std::numeric_limits<T>::max()));
  }
}

}  // namespace

int type_size(GLenum type) {
  switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: return 2;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
  }
}

// Component k of element i.
float component(const ClientArray& a, std::size_t i, int k, Norm norm) {
  std::size_t size = std::size_t(type_size(a.type));
  std::size_t stride = a.stride ? std::size_t(a.stride) : size * std::size_t(a.size);
  const unsigned char* p = static_cast<const unsigned char*>(a.pointer) + i * stride + std::size_t(k) * size;
  switch (a.type) {
    case GL_BYTE: return convert_component(load<GLbyte>(p), norm);
    case GL_UNSIGNED_BYTE: return convert_component(load<GLubyte>(p), norm);
    case GL_SHORT: return convert_component(load<GLshort>(p), norm);
    case GL_UNSIGNED_SHORT: return convert_component(load<GLushort>(p), norm);
    case GL_INT: return convert_component(load<GLint>(p), norm);
    case GL_UNSIGNED_INT: return convert_component(load<GLuint>(p), norm);
    case GL_FLOAT: return load<GLfloat>(p);
    case GL_DOUBLE: return float(load<GLdouble>(p));
    default: return 0.0f;
  }
}

ResolvedArrays::ResolvedArrays(GlContext& c) : c_(c) {
  ClientArrays& a = c.arrays;
  bool any = false;
  for (ClientArray* array : a.all()) {
    if (!array->enabled || !array->buffer) continue;
    any = true;
  }
  if (!any) return;
  saved_ = a;
  swapped_ = true;
  for (ClientArray* array : a.all()) {
    if (!array->enabled || !array->buffer) continue;
    const std::vector<unsigned char>& data = array->buffer->data;
    const std::size_t offset = reinterpret_cast<std::uintptr_t>(array->pointer);
    const std::size_t size = std::size_t(type_size(array->type)) * std::size_t(array->size);
    const std::size_t stride = array->stride ? std::size_t(array->stride) : size;
    const std::size_t elements =
        offset > data.size() || data.size() - offset < size ? 0 : (data.size() - offset - size) / std::max<std::size_t>(stride, 1) + 1;
    limit_ = std::min(limit_, elements);
    array->pointer = elements ? data.data() + offset : nullptr;
  }
}

// Up to four components of element i, the missing ones taken from `fill`.
glm::vec4 fetch(const ClientArray& a, std::size_t i, glm::vec4 fill, Norm norm) {
  if (a.type == GL_FLOAT) {  // the common case, read directly
    std::size_t stride = a.stride ? std::size_t(a.stride) : sizeof(float) * std::size_t(a.size);
    const unsigned char* p = static_cast<const unsigned char*>(a.pointer) + i * stride;
    for (int k = 0; k < a.size && k < 4; ++k) std::memcpy(&fill[k], p + sizeof(float) * std::size_t(k), sizeof(float));
    return fill;
  }
  for (int k = 0; k < a.size && k < 4; ++k) fill[k] = component(a, i, k, norm);
  return fill;
}

// Element i of the secondary colour array (GL 1.4 section 2.8): red, green and blue (a fourth
// component is read by no one), alpha 1 as glSecondaryColor3 leaves it.
glm::vec4 secondary_element(const ClientArray& a, std::size_t i, Norm norm) {
  glm::vec4 v = fetch(a, i, glm::vec4(0, 0, 0, 1), norm);
  v.a = 1.0f;
  return v;
}

bool index_type(GLenum type) {
  return type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_SHORT || type == GL_UNSIGNED_INT;
}

// Index k of an index array of `type` (one of index_type's).
std::size_t read_index(const unsigned char* bytes, GLenum type, std::size_t k) {
  if (type == GL_UNSIGNED_BYTE) return bytes[k];
  if (type == GL_UNSIGNED_SHORT) return load<GLushort>(bytes + 2 * k);
  return load<GLuint>(bytes + 4 * k);
}

// The index data of an indexed draw: `indices` itself, or the offset it is into the buffer
// bound to GL_ELEMENT_ARRAY_BUFFER (null when `count` indices of `type` run past its end:
// nothing is read outside it). `error`: GL_INVALID_VALUE for null client indices.
const unsigned char* index_data(const GlContext& c, GLsizei count, GLenum type, const void* indices, bool& error) {
  error = false;
  if (const BufferObject* b = c.arrays.element_buffer.get()) {
    const std::size_t offset = reinterpret_cast<std::uintptr_t>(indices);
    const std::size_t bytes = std::size_t(count) * (type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2 : 4);
    if (offset > b->data.size() || b->data.size() - offset < bytes || b->data.empty()) return nullptr;
    return b->data.data() + offset;
  }
  error = !indices && count != 0;
  return static_cast<const unsigned char*>(indices);
}

}  // namespace shadelab::gl
