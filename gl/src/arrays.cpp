// Vertex arrays (GL 1.1 section 2.8): the array pointers (GL 1.4's secondary colour and fog
// coordinate arrays too), glArrayElement, glDrawArrays, glDrawElements, GL 1.2's
// glDrawRangeElements, GL 1.4's glMultiDrawArrays and glMultiDrawElements, and GL 1.5's arrays
// and indices in buffer objects (section 2.9, read in place). Each element becomes current
// attributes plus a vertex, exactly as the
// equivalent glBegin/glEnd sequence (which is how GL 1.1 defines them); draw.cpp does the rest,
// or array_mesh.cpp draws the whole array in one go where that gives the same result.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <mutex>
#include <type_traits>

#include "gl/generated/exec.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/convert.hpp"
#include "gl/src/dlist.hpp"
#include "gl/src/draw.hpp"
#include "gl/src/primitive.hpp"

namespace shadelab::gl {
namespace {

int type_size(GLenum type) {
  switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: return 2;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
  }
}

template <class T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);  // arrays need not be aligned
  return v;
}

// How integer components become floats. kDirect: as they are (positions, texture
// coordinates). kSpec: GL 1.1 table 2.6, as glArrayElement converts them (Mesa issues the
// immediate-mode calls, glColor3b and so on). kDraw: as llvmpipe's vertex fetch converts them
// for glDrawArrays / glDrawElements (Mesa hands the arrays over as normalized formats: signed
// c / (2^(b-1) - 1), at least -1; unsigned c / (2^b - 1)). The two differ by at most one
// step of the type.
enum class Norm { kDirect, kSpec, kDraw };

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

bool usable(const ClientArray& a) { return a.enabled && a.pointer; }

// GL 1.5 section 2.9: while a draw reads the arrays, those given as offsets into buffer
// objects point into the buffers' data stores (read in place, never copied); the arrays are
// as they were afterwards. A mapped buffer is read all the same (GL 1.5 leaves such draws
// undefined; Mesa 22.3 draws them without an error; the mapping is the store itself). `limit`: the number of elements every
// enabled array in a buffer holds (SIZE_MAX with none).
class ResolvedArrays {
 public:
  explicit ResolvedArrays(GlContext& c) : c_(c) {
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
  ~ResolvedArrays() {
    if (swapped_) c_.arrays = std::move(saved_);
  }
  ResolvedArrays(const ResolvedArrays&) = delete;
  ResolvedArrays& operator=(const ResolvedArrays&) = delete;
  std::size_t limit() const { return limit_; }

 private:
  GlContext& c_;
  ClientArrays saved_;
  bool swapped_ = false;
  std::size_t limit_ = SIZE_MAX;
};

// A GL_FLOAT array as floats: element i's first component, and the step between elements
// in floats (a stride that is not a whole number of floats takes the general path).
std::size_t float_stride(const ClientArray& a) {
  return a.stride ? std::size_t(a.stride) / sizeof(float) : std::size_t(a.size);
}
bool aligned_floats(const ClientArray& a) {
  return a.stride % sizeof(float) == 0 && reinterpret_cast<std::uintptr_t>(a.pointer) % alignof(float) == 0;
}
const float* floats3(const ClientArray& a, std::size_t i) {
  return static_cast<const float*>(a.pointer) + i * float_stride(a);
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

// GL 1.4's attributes of a draw's elements (draw_array_mesh's ExtraLoader): from their arrays
// as a draw converts them, or the current values.
void load_extra(const GlContext& c, std::size_t first, std::size_t n, const ExtraOutputs& out) {
  const ClientArrays& a = c.arrays;
  for (std::size_t v = 0; out.secondary && v < n; ++v) {
    out.secondary[v] = glm::vec3(usable(a.secondary_color) ? secondary_element(a.secondary_color, first + v, Norm::kDraw)
                                                           : c.current.secondary);
  }
  for (std::size_t v = 0; out.fog && v < n; ++v) {
    out.fog[v] = usable(a.fog_coord) ? component(a.fog_coord, first + v, 0, Norm::kDirect) : c.current.fog_coord;
  }
  for (std::size_t u = 1; u < kMaxTextureUnits; ++u) {
    const ClientArray& t = a.texcoords[u];
    for (std::size_t v = 0; out.texcoords[u] && v < n; ++v) {
      out.texcoords[u][v] = usable(t) ? fetch(t, first + v, glm::vec4(0, 0, 0, 1), Norm::kDirect) : c.current.texcoords[u];
    }
  }
}

// glArrayElement's effect (GL 1.1 section 2.8): attributes first, the vertex last. `norm`:
// how colours and normals convert (kSpec for glArrayElement itself, kDraw within a draw).
void array_element(GlContext& c, std::size_t i, Norm norm) {
  const ClientArrays& a = c.arrays;
  if (usable(a.edge_flag)) c.current.edge_flag = component(a.edge_flag, i, 0, Norm::kDirect);
  if (usable(a.index)) c.current.index = component(a.index, i, 0, Norm::kDirect);
  if (usable(a.normal)) c.current.normal = glm::vec3(fetch(a.normal, i, glm::vec4(0.0f), norm));
  if (usable(a.color)) {
    c.current.color = fetch(a.color, i, glm::vec4(0, 0, 0, 1), norm);
    apply_color_material(c);
  }
  for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {  // every unit's array (GL 1.3 section 2.8)
    if (usable(a.texcoords[u])) c.current.texcoords[u] = fetch(a.texcoords[u], i, glm::vec4(0, 0, 0, 1), Norm::kDirect);
  }
  if (usable(a.secondary_color)) c.current.secondary = secondary_element(a.secondary_color, i, norm);
  if (usable(a.fog_coord)) c.current.fog_coord = component(a.fog_coord, i, 0, Norm::kDirect);
  if (usable(a.vertex) && c.prim.active) emit_vertex(c, fetch(a.vertex, i, glm::vec4(0, 0, 0, 1), Norm::kDirect));
}

// A whole primitive from array elements. The current attributes and material are restored
// afterwards: GL leaves them indeterminate, and Mesa leaves them unchanged.
template <class IndexOf>
void draw_elements(GlContext& c, GLenum mode, std::size_t count, IndexOf index_of, bool from_elements,
                   const std::uint32_t* direct = nullptr, std::size_t limit = SIZE_MAX) {
  if (!usable(c.arrays.vertex)) return;
  const ClientArrays& a = c.arrays;
  const CurrentAttribs& now = c.current;
  // glArrayElement's attributes for a range of elements, array by array.
  auto load = [&](std::size_t first, std::size_t n, glm::vec4* positions, glm::vec3* normals,
                  glm::vec4* colors, glm::vec4* texcoords) {
    if (a.vertex.type == GL_FLOAT && a.vertex.size == 3 && aligned_floats(a.vertex)) {  // the common layout, read directly
      const float* f = floats3(a.vertex, first);
      std::size_t step = float_stride(a.vertex);
      for (std::size_t v = 0; v < n; ++v, f += step) positions[v] = glm::vec4(f[0], f[1], f[2], 1.0f);
    } else {
      for (std::size_t v = 0; v < n; ++v) positions[v] = fetch(a.vertex, first + v, glm::vec4(0, 0, 0, 1), Norm::kDirect);
    }
    if (usable(a.normal) && a.normal.type == GL_FLOAT && aligned_floats(a.normal)) {
      const float* f = floats3(a.normal, first);
      std::size_t step = float_stride(a.normal);
      for (std::size_t v = 0; v < n; ++v, f += step) normals[v] = glm::vec3(f[0], f[1], f[2]);
    } else {
      for (std::size_t v = 0; v < n; ++v) {
        normals[v] = usable(a.normal) ? glm::vec3(fetch(a.normal, first + v, glm::vec4(0.0f), Norm::kDraw)) : now.normal;
      }
    }
    for (std::size_t v = 0; colors && v < n; ++v) {
      colors[v] = usable(a.color) ? fetch(a.color, first + v, glm::vec4(0, 0, 0, 1), Norm::kDraw) : now.color;
    }
    if (!texcoords) return;
    for (std::size_t v = 0; v < n; ++v) {
      texcoords[v] =
          usable(a.texcoords[0]) ? fetch(a.texcoords[0], first + v, glm::vec4(0, 0, 0, 1), Norm::kDirect) : now.texcoords[0];
    }
  };
  auto& sequence = c.array_scratch.sequence;
  // 32-bit triangle indices are read where they are; others are gathered into `sequence`.
  const bool read_direct = direct && mode == GL_TRIANGLES;
  sequence.resize(read_direct ? 0 : count);
  std::uint32_t lo = UINT32_MAX, hi = 0;
  std::mutex bounds;
  auto gather = [&](std::size_t begin, std::size_t end) {  // indices and their range
    std::uint32_t l = UINT32_MAX, h = 0;
    if (read_direct) {  // the range only
      for (std::size_t k = begin; k < end; ++k) l = std::min(l, direct[k]), h = std::max(h, direct[k]);
    } else {
      for (std::size_t k = begin; k < end; ++k) {
        std::uint32_t i = std::uint32_t(std::min<std::size_t>(index_of(k), UINT32_MAX));
        sequence[k] = i;
        l = std::min(l, i), h = std::max(h, i);
      }
    }
    std::lock_guard<std::mutex> lock(bounds);
    lo = std::min(lo, l), hi = std::max(hi, h);
  };
  make_pipeline(c);
  if (c.pipeline && count >= (1u << 16)) c.pipeline->parallel_for(count, 1u << 15, gather);
  else gather(0, count);
  // An element past the end of a buffer the arrays read: nothing is drawn (nothing is read
  // outside a buffer).
  if (count > 0 && hi >= limit) return;
  const ExtraLoader extra = [&](std::size_t first, std::size_t n, const ExtraOutputs& out) {
    load_extra(c, first, n, out);
  };
  if (draw_array_mesh(c, mode, usable(a.color), from_elements, count, read_direct ? direct : nullptr, lo, hi, load,
                      &extra)) {
    return;
  }
  CurrentAttribs saved = c.current;
  Material front = c.lighting.front, back = c.lighting.back;
  begin_primitive(c, mode);
  c.prim.from_elements = from_elements;
  for (std::size_t k = 0; k < count; ++k) array_element(c, index_of(k), Norm::kDraw);
  end_primitive(c);
  c.current = saved;
  c.lighting.front = front, c.lighting.back = back;
}

bool valid_type(GLenum type, std::initializer_list<GLenum> allowed) {
  for (GLenum t : allowed) {
    if (t == type) return true;
  }
  return false;
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

// glDrawElements' drawing once its arguments are checked: `count` indices of `type` at
// `indices` (client memory, or an offset into the element array buffer).
void draw_indexed(GlContext& c, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  ResolvedArrays arrays(c);
  bool error = false;
  const unsigned char* bytes = index_data(c, count, type, indices, error);
  if (error) return c.set_error(GL_INVALID_VALUE);
  if (!bytes) return;
  // Aligned 32-bit indices can be read in place (as triangles, draw_array_mesh).
  const bool aligned = type == GL_UNSIGNED_INT && reinterpret_cast<std::uintptr_t>(bytes) % alignof(shadelab::Triangle) == 0;
  draw_elements(
      c, mode, std::size_t(count), [&](std::size_t k) { return read_index(bytes, type, k); }, true,
      aligned ? reinterpret_cast<const std::uint32_t*>(bytes) : nullptr, arrays.limit());
}

// glDrawArrays' drawing once its arguments are checked.
void draw_range(GlContext& c, GLenum mode, GLint first, GLsizei count) {
  ResolvedArrays arrays(c);
  draw_elements(c, mode, std::size_t(count), [&](std::size_t k) { return std::size_t(first) + k; }, false, nullptr,
                arrays.limit());
}

// The gl*Pointer rule, checked in Mesa's order: the stride, then the type, then the size.
void set_pointer(GlContext& c, ClientArray& a, GLint size, GLenum type, GLsizei stride, const void* ptr,
                 int min_size, int max_size, std::initializer_list<GLenum> types) {
  if (stride < 0) return c.set_error(GL_INVALID_VALUE);
  if (!valid_type(type, types)) return c.set_error(GL_INVALID_ENUM);
  if (size < min_size || size > max_size) return c.set_error(GL_INVALID_VALUE);
  // GL 1.5 section 2.9: the array takes the buffer bound to GL_ARRAY_BUFFER now; the pointer
  // is then an offset into it.
  a = {a.enabled, size, type, stride, ptr, c.arrays.array_buffer, c.arrays.array_buffer_name};
}

// Array elements dereferenced for a display list: per element, the attributes
// glArrayElement would set (GL 1.1 section 2.8), each array null when it is disabled; colours
// and normals converted as `norm` says (as the command being recorded converts them).
void write_elements(GlContext& c, ListWriter& w, std::size_t count, Norm norm, const auto& index_of) {
  const ClientArrays& a = c.arrays;
  std::vector<float> normals, colors, positions, edges, secondary, fog;
  std::array<std::vector<float>, kMaxTextureUnits> texcoords;
  auto put = [](std::vector<float>& out, const glm::vec4& v, int n) {
    for (int k = 0; k < n; ++k) out.push_back(v[k]);
  };
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = index_of(k);
    if (usable(a.normal)) put(normals, fetch(a.normal, i, glm::vec4(0.0f), norm), 3);
    if (usable(a.color)) put(colors, fetch(a.color, i, glm::vec4(0, 0, 0, 1), norm), 4);
    for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {
      if (usable(a.texcoords[u])) put(texcoords[u], fetch(a.texcoords[u], i, glm::vec4(0, 0, 0, 1), Norm::kDirect), 4);
    }
    if (usable(a.vertex)) put(positions, fetch(a.vertex, i, glm::vec4(0, 0, 0, 1), Norm::kDirect), 4);
    if (usable(a.edge_flag)) edges.push_back(component(a.edge_flag, i, 0, Norm::kDirect));
    if (usable(a.secondary_color)) put(secondary, secondary_element(a.secondary_color, i, norm), 3);
    if (usable(a.fog_coord)) fog.push_back(component(a.fog_coord, i, 0, Norm::kDirect));
  }
  w.scalar(std::uint64_t(count));
  w.array(usable(a.normal) ? normals.data() : nullptr, normals.size());
  w.array(usable(a.color) ? colors.data() : nullptr, colors.size());
  w.array(usable(a.texcoords[0]) ? texcoords[0].data() : nullptr, texcoords[0].size());
  w.array(usable(a.vertex) ? positions.data() : nullptr, positions.size());
  w.array(usable(a.edge_flag) ? edges.data() : nullptr, edges.size());
  w.array(usable(a.secondary_color) ? secondary.data() : nullptr, secondary.size());
  w.array(usable(a.fog_coord) ? fog.data() : nullptr, fog.size());
  for (std::size_t u = 1; u < kMaxTextureUnits; ++u) {  // GL 1.3: the other units', after the rest
    w.array(usable(a.texcoords[u]) ? texcoords[u].data() : nullptr, texcoords[u].size());
  }
}

// A draw in a display list: its mode and elements. Drawn only if the vertex array is enabled,
// as the command itself draws.
void record_draw(GlContext& c, GLenum mode, std::size_t count, const auto& index_of) {
  // Without the vertex array the draw specifies nothing, but it is still recorded (with no
  // elements): run inside glBegin/glEnd it is GL_INVALID_OPERATION, as Mesa's.
  // Arrays in buffers are dereferenced now too (GL 1.5 section 5.4); an element past a
  // buffer's end leaves the draw empty.
  ResolvedArrays arrays(c);
  if (!usable(c.arrays.vertex)) count = 0;
  for (std::size_t k = 0; arrays.limit() != SIZE_MAX && k < count; ++k) {
    if (index_of(k) >= arrays.limit()) count = 0;
  }
  ListWriter w(c, Opcode::kArrayDraw);
  w.scalar(mode);
  write_elements(c, w, count, Norm::kDraw, index_of);
}

// Element k's attributes become current, then its vertex is specified (outside glBegin/glEnd
// it specifies none).
void specify(GlContext& c, const RecordedElements& e, std::uint64_t k) {
  if (e.normals) c.current.normal = glm::vec3(e.normals[3 * k], e.normals[3 * k + 1], e.normals[3 * k + 2]);
  if (e.colors) {
    c.current.color = glm::vec4(e.colors[4 * k], e.colors[4 * k + 1], e.colors[4 * k + 2], e.colors[4 * k + 3]);
    apply_color_material(c);
  }
  for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {
    if (!e.unit_texcoords[u]) continue;
    const float* t = &e.unit_texcoords[u][4 * k];
    c.current.texcoords[u] = glm::vec4(t[0], t[1], t[2], t[3]);
  }
  if (e.edges) c.current.edge_flag = e.edges[k];
  if (e.secondary) c.current.secondary = glm::vec4(e.secondary[3 * k], e.secondary[3 * k + 1], e.secondary[3 * k + 2], 1.0f);
  if (e.fog) c.current.fog_coord = e.fog[k];
  if (e.positions && c.prim.active) {
    const float* p = &e.positions[4 * k];
    emit_vertex(c, glm::vec4(p[0], p[1], p[2], p[3]));
  }
}

}  // namespace

void replay_internal::ArrayElements(GlContext& c, ListReader& r) {
  const RecordedElements e(r);
  for (std::uint64_t k = 0; k < e.count; ++k) specify(c, e, k);
}

// A recorded glDrawArrays / glDrawElements: as the command draws them (glDrawArrays' rule
// between glBegin and glEnd included), leaving the current attributes and material as they
// were, as Mesa does.
void replay_internal::ArrayDraw(GlContext& c, ListReader& r) {
  const GLenum mode = r.scalar<GLenum>();
  const RecordedElements e(r);
  if (c.prim.active) return c.set_error(GL_INVALID_OPERATION);
  const CurrentAttribs saved = c.current;
  const Material front = c.lighting.front, back = c.lighting.back;
  begin_primitive(c, mode);
  for (std::uint64_t k = 0; k < e.count; ++k) specify(c, e, k);
  end_primitive(c);
  c.current = saved;
  c.lighting.front = front, c.lighting.back = back;
}

// Vertex-array commands in a display list take the arrays' contents of the moment (GL 1.1
// section 5.4). Argument errors are recorded (as Mesa's compile errors) and nothing else.
void save::ArrayElement(GlContext& c, GLint i) {
  if (i < 0) return;  // no error, as Mesa (which reads before the arrays); nothing recorded
  ResolvedArrays arrays(c);
  if (std::size_t(i) >= arrays.limit()) return;
  ListWriter w(c, Opcode::kArrayElements);
  write_elements(c, w, 1, Norm::kSpec, [&](std::size_t) { return std::size_t(i); });
}

void save::DrawArrays(GlContext& c, GLenum mode, GLint first, GLsizei count) {
  if (mode > GL_POLYGON) return record_error(c, GL_INVALID_ENUM);
  if (first < 0 || count < 0) return record_error(c, GL_INVALID_VALUE);
  record_draw(c, mode, std::size_t(count), [&](std::size_t k) { return std::size_t(first) + k; });
}

namespace {

// A glDrawElements-like saver's checks, in Mesa's order (its compile errors); false when
// the draw is not recorded. `type_error`: Mesa's compile error for a wrong type, which is
// GL_INVALID_VALUE in the savers of GL 1.2-1.4's draws (they share one path in Mesa 22.3).
bool save_elements_checks(GlContext& c, GLenum mode, GLsizei count, GLenum type, GLenum type_error = GL_INVALID_ENUM) {
  if (mode > GL_POLYGON) return record_error(c, GL_INVALID_ENUM), false;
  if (count < 0) return record_error(c, GL_INVALID_VALUE), false;
  if (!index_type(type)) return record_error(c, type_error), false;
  return true;
}

void save_elements(GlContext& c, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  bool error = false;
  const unsigned char* bytes = index_data(c, count, type, indices, error);
  if (error) return record_error(c, GL_INVALID_VALUE);
  if (!bytes) return;
  record_draw(c, mode, std::size_t(count), [&](std::size_t k) { return read_index(bytes, type, k); });
}

}  // namespace

void save::DrawElements(GlContext& c, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  if (save_elements_checks(c, mode, count, type)) save_elements(c, mode, count, type, indices);
}

// GL 1.2: as glDrawElements, the range checked first (Mesa's compile error).
void save::DrawRangeElements(GlContext& c, GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                             const void* indices) {
  if (end < start) return record_error(c, GL_INVALID_VALUE);
  if (save_elements_checks(c, mode, count, type, GL_INVALID_VALUE)) save_elements(c, mode, count, type, indices);
}

// GL 1.4: each primitive recorded as the glDrawArrays / glDrawElements it stands for, with
// Mesa's compile errors (glMultiDrawArrays: the mode, the primitive count, every count, then
// each primitive's; glMultiDrawElements: those of each primitive of a positive count, in turn).
void save::MultiDrawArrays(GlContext& c, GLenum mode, const GLint* first, const GLsizei* count, GLsizei drawcount) {
  if (mode > GL_POLYGON) return record_error(c, GL_INVALID_ENUM);
  if (drawcount < 0) return record_error(c, GL_INVALID_VALUE);
  for (GLsizei i = 0; i < drawcount; ++i) {
    if (count[i] < 0) return record_error(c, GL_INVALID_VALUE);
  }
  for (GLsizei i = 0; i < drawcount; ++i) {
    if (count[i] > 0) save::DrawArrays(c, mode, first[i], count[i]);
  }
}

void save::MultiDrawElements(GlContext& c, GLenum mode, const GLsizei* count, GLenum type,
                             const void* const* indices, GLsizei drawcount) {
  if (!c.arrays.element_buffer && std::find(indices, indices + std::max(drawcount, 0), nullptr) != indices + std::max(drawcount, 0)) {
    return;
  }
  for (GLsizei i = 0; i < drawcount; ++i) {
    if (count[i] <= 0) continue;
    if (!save_elements_checks(c, mode, count[i], type, GL_INVALID_VALUE)) return;
    save_elements(c, mode, count[i], type, indices[i]);
  }
}

void exec::VertexPointer(GlContext& c, GLint size, GLenum type, GLsizei stride, const void* ptr) {
  set_pointer(c, c.arrays.vertex, size, type, stride, ptr, 2, 4, {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
}

void exec::NormalPointer(GlContext& c, GLenum type, GLsizei stride, const void* ptr) {
  set_pointer(c, c.arrays.normal, 3, type, stride, ptr, 3, 3, {GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
}

void exec::ColorPointer(GlContext& c, GLint size, GLenum type, GLsizei stride, const void* ptr) {
  set_pointer(c, c.arrays.color, size, type, stride, ptr, 3, 4,
              {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT,
               GL_FLOAT, GL_DOUBLE});
}

void exec::TexCoordPointer(GlContext& c, GLint size, GLenum type, GLsizei stride, const void* ptr) {
  set_pointer(c, c.arrays.texcoord(), size, type, stride, ptr, 1, 4, {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
}

void exec::IndexPointer(GlContext& c, GLenum type, GLsizei stride, const void* ptr) {
  set_pointer(c, c.arrays.index, 1, type, stride, ptr, 1, 1, {GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
}

// GL 1.4 section 2.8. Sizes 3 and 4, as Mesa accepts them (GL 1.4 allows 3 only).
void exec::SecondaryColorPointer(GlContext& c, GLint size, GLenum type, GLsizei stride, const void* ptr) {
  set_pointer(c, c.arrays.secondary_color, size, type, stride, ptr, 3, 4,
              {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT,
               GL_FLOAT, GL_DOUBLE});
}

// GL 1.4 section 2.8: one float or double per element.
void exec::FogCoordPointer(GlContext& c, GLenum type, GLsizei stride, const void* ptr) {
  set_pointer(c, c.arrays.fog_coord, 1, type, stride, ptr, 1, 1, {GL_FLOAT, GL_DOUBLE});
}

void exec::EdgeFlagPointer(GlContext& c, GLsizei stride, const void* ptr) {
  set_pointer(c, c.arrays.edge_flag, 1, GL_UNSIGNED_BYTE, stride, ptr, 1, 1, {GL_UNSIGNED_BYTE});
}

// Legal between glBegin and glEnd; outside them it only sets the current attributes. A
// negative index is no error in Mesa (which reads before the arrays): here it does nothing.
void exec::ArrayElement(GlContext& c, GLint i) {
  if (i < 0) return;
  ResolvedArrays arrays(c);  // arrays in buffers are read in place
  if (std::size_t(i) >= arrays.limit()) return;
  array_element(c, std::size_t(i), Norm::kSpec);
}

void exec::DrawArrays(GlContext& c, GLenum mode, GLint first, GLsizei count) {
  if (mode > GL_POLYGON) return c.set_error(GL_INVALID_ENUM);
  if (first < 0 || count < 0) return c.set_error(GL_INVALID_VALUE);
  draw_range(c, mode, first, count);
}

// Indices are used as given: like GL, shadelab cannot know how long the caller's arrays are.
void exec::DrawElements(GlContext& c, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  if (mode > GL_POLYGON) return c.set_error(GL_INVALID_ENUM);
  if (count < 0) return c.set_error(GL_INVALID_VALUE);
  if (!index_type(type)) return c.set_error(GL_INVALID_ENUM);
  draw_indexed(c, mode, count, type, indices);
}

// GL 1.2 section 2.8: glDrawElements with the promise that every index is in [start, end].
// Checked as Mesa checks it (the range, then the count, the mode and the type); indices outside
// the range are drawn all the same, as Mesa draws them.
void exec::DrawRangeElements(GlContext& c, GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                             const void* indices) {
  if (end < start || count < 0) return c.set_error(GL_INVALID_VALUE);
  if (mode > GL_POLYGON || !index_type(type)) return c.set_error(GL_INVALID_ENUM);
  draw_indexed(c, mode, count, type, indices);
}

// GL 1.4 section 2.8: glDrawArrays for each of `drawcount` primitives. Mesa checks the
// primitive count, the mode, then every count before drawing anything.
void exec::MultiDrawArrays(GlContext& c, GLenum mode, const GLint* first, const GLsizei* count, GLsizei drawcount) {
  if (drawcount < 0) return c.set_error(GL_INVALID_VALUE);
  if (mode > GL_POLYGON) return c.set_error(GL_INVALID_ENUM);
  for (GLsizei i = 0; i < drawcount; ++i) {
    if (count[i] < 0) return c.set_error(GL_INVALID_VALUE);
  }
  for (GLsizei i = 0; i < drawcount; ++i) {
    // A negative first is no error in Mesa (which reads before the arrays): nothing drawn.
    if (count[i] > 0 && first[i] >= 0) draw_range(c, mode, first[i], count[i]);
  }
}

// GL 1.4: glDrawElements for each primitive; checked as Mesa checks it (the primitive count,
// the mode, the type, every count). Without an element array buffer, a null index pointer
// among them makes the whole call draw nothing, with no error (Mesa's rule).
void exec::MultiDrawElements(GlContext& c, GLenum mode, const GLsizei* count, GLenum type,
                             const void* const* indices, GLsizei drawcount) {
  if (drawcount < 0) return c.set_error(GL_INVALID_VALUE);
  if (mode > GL_POLYGON || !index_type(type)) return c.set_error(GL_INVALID_ENUM);
  for (GLsizei i = 0; i < drawcount; ++i) {
    if (count[i] < 0) return c.set_error(GL_INVALID_VALUE);
  }
  if (!c.arrays.element_buffer && std::find(indices, indices + drawcount, nullptr) != indices + drawcount) return;
  for (GLsizei i = 0; i < drawcount; ++i) {
    if (count[i] > 0) draw_indexed(c, mode, count[i], type, indices[i]);
  }
}

}  // namespace shadelab::gl
