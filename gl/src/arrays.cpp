// Vertex arrays (GL 1.1 section 2.8): the array pointers (GL 1.4's secondary colour and fog
// coordinate arrays too), glArrayElement, glDrawArrays and
// glDrawElements. Each element becomes current attributes plus a vertex, exactly as the
// equivalent glBegin/glEnd sequence (which is how GL 1.1 defines them); draw.cpp does the rest,
// or array_mesh.cpp draws the whole array in one go where that gives the same result.
#include <algorithm>
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
  if (usable(a.texcoord)) c.current.texcoord = fetch(a.texcoord, i, glm::vec4(0, 0, 0, 1), Norm::kDirect);
  if (usable(a.secondary_color)) c.current.secondary = secondary_element(a.secondary_color, i, norm);
  if (usable(a.fog_coord)) c.current.fog_coord = component(a.fog_coord, i, 0, Norm::kDirect);
  if (usable(a.vertex) && c.prim.active) emit_vertex(c, fetch(a.vertex, i, glm::vec4(0, 0, 0, 1), Norm::kDirect));
}

// A whole primitive from array elements. The current attributes and material are restored
// afterwards: GL leaves them indeterminate, and Mesa leaves them unchanged.
template <class IndexOf>
void draw_elements(GlContext& c, GLenum mode, std::size_t count, IndexOf index_of, bool from_elements,
                   const std::uint32_t* direct = nullptr) {
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
      texcoords[v] = usable(a.texcoord) ? fetch(a.texcoord, first + v, glm::vec4(0, 0, 0, 1), Norm::kDirect) : now.texcoord;
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

// The gl*Pointer rule, checked in Mesa's order: the stride, then the type, then the size.
void set_pointer(GlContext& c, ClientArray& a, GLint size, GLenum type, GLsizei stride, const void* ptr,
                 int min_size, int max_size, std::initializer_list<GLenum> types) {
  if (stride < 0) return c.set_error(GL_INVALID_VALUE);
  if (!valid_type(type, types)) return c.set_error(GL_INVALID_ENUM);
  if (size < min_size || size > max_size) return c.set_error(GL_INVALID_VALUE);
  a = {a.enabled, size, type, stride, ptr};
}

// Array elements dereferenced for a display list: per element, the attributes
// glArrayElement would set (GL 1.1 section 2.8), each array null when it is disabled; colours
// and normals converted as `norm` says (as the command being recorded converts them).
void write_elements(GlContext& c, ListWriter& w, std::size_t count, Norm norm, const auto& index_of) {
  const ClientArrays& a = c.arrays;
  std::vector<float> normals, colors, texcoords, positions, edges, secondary, fog;
  auto put = [](std::vector<float>& out, const glm::vec4& v, int n) {
    for (int k = 0; k < n; ++k) out.push_back(v[k]);
  };
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = index_of(k);
    if (usable(a.normal)) put(normals, fetch(a.normal, i, glm::vec4(0.0f), norm), 3);
    if (usable(a.color)) put(colors, fetch(a.color, i, glm::vec4(0, 0, 0, 1), norm), 4);
    if (usable(a.texcoord)) put(texcoords, fetch(a.texcoord, i, glm::vec4(0, 0, 0, 1), Norm::kDirect), 4);
    if (usable(a.vertex)) put(positions, fetch(a.vertex, i, glm::vec4(0, 0, 0, 1), Norm::kDirect), 4);
    if (usable(a.edge_flag)) edges.push_back(component(a.edge_flag, i, 0, Norm::kDirect));
    if (usable(a.secondary_color)) put(secondary, secondary_element(a.secondary_color, i, norm), 3);
    if (usable(a.fog_coord)) fog.push_back(component(a.fog_coord, i, 0, Norm::kDirect));
  }
  w.scalar(std::uint64_t(count));
  w.array(usable(a.normal) ? normals.data() : nullptr, normals.size());
  w.array(usable(a.color) ? colors.data() : nullptr, colors.size());
  w.array(usable(a.texcoord) ? texcoords.data() : nullptr, texcoords.size());
  w.array(usable(a.vertex) ? positions.data() : nullptr, positions.size());
  w.array(usable(a.edge_flag) ? edges.data() : nullptr, edges.size());
  w.array(usable(a.secondary_color) ? secondary.data() : nullptr, secondary.size());
  w.array(usable(a.fog_coord) ? fog.data() : nullptr, fog.size());
}

// A draw in a display list: its mode and elements. Drawn only if the vertex array is enabled,
// as the command itself draws.
void record_draw(GlContext& c, GLenum mode, std::size_t count, const auto& index_of) {
  // Without the vertex array the draw specifies nothing, but it is still recorded (with no
  // elements): run inside glBegin/glEnd it is GL_INVALID_OPERATION, as Mesa's.
  if (!usable(c.arrays.vertex)) count = 0;
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
  if (e.texcoords) {
    const float* t = &e.texcoords[4 * k];
    c.current.texcoord = glm::vec4(t[0], t[1], t[2], t[3]);
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
  ListWriter w(c, Opcode::kArrayElements);
  write_elements(c, w, 1, Norm::kSpec, [&](std::size_t) { return std::size_t(i); });
}

void save::DrawArrays(GlContext& c, GLenum mode, GLint first, GLsizei count) {
  if (mode > GL_POLYGON) return record_error(c, GL_INVALID_ENUM);
  if (first < 0 || count < 0) return record_error(c, GL_INVALID_VALUE);
  record_draw(c, mode, std::size_t(count), [&](std::size_t k) { return std::size_t(first) + k; });
}

void save::DrawElements(GlContext& c, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  if (mode > GL_POLYGON) return record_error(c, GL_INVALID_ENUM);
  if (count < 0) return record_error(c, GL_INVALID_VALUE);
  if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT) {
    return record_error(c, GL_INVALID_ENUM);
  }
  if (!indices) return count == 0 ? void() : record_error(c, GL_INVALID_VALUE);
  const auto* bytes = static_cast<const unsigned char*>(indices);
  record_draw(c, mode, std::size_t(count), [&](std::size_t k) -> std::size_t {
    if (type == GL_UNSIGNED_BYTE) return bytes[k];
    if (type == GL_UNSIGNED_SHORT) return load<GLushort>(bytes + 2 * k);
    return load<GLuint>(bytes + 4 * k);
  });
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
  set_pointer(c, c.arrays.texcoord, size, type, stride, ptr, 1, 4, {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
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
  array_element(c, std::size_t(i), Norm::kSpec);
}

void exec::DrawArrays(GlContext& c, GLenum mode, GLint first, GLsizei count) {
  if (mode > GL_POLYGON) return c.set_error(GL_INVALID_ENUM);
  if (first < 0 || count < 0) return c.set_error(GL_INVALID_VALUE);
  draw_elements(c, mode, std::size_t(count), [&](std::size_t k) { return std::size_t(first) + k; }, false);
}

// Indices are used as given: like GL, shadelab cannot know how long the caller's arrays are.
void exec::DrawElements(GlContext& c, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  if (mode > GL_POLYGON) return c.set_error(GL_INVALID_ENUM);
  if (count < 0) return c.set_error(GL_INVALID_VALUE);
  if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT) {
    return c.set_error(GL_INVALID_ENUM);
  }
  if (!indices) return count == 0 ? void() : c.set_error(GL_INVALID_VALUE);
  const auto* bytes = static_cast<const unsigned char*>(indices);
  // Aligned 32-bit indices can be read in place (as triangles, draw_array_mesh).
  const bool aligned = type == GL_UNSIGNED_INT && reinterpret_cast<std::uintptr_t>(indices) % alignof(shadelab::Triangle) == 0;
  draw_elements(
      c, mode, std::size_t(count),
      [&](std::size_t k) -> std::size_t {
        if (type == GL_UNSIGNED_BYTE) return bytes[k];
        if (type == GL_UNSIGNED_SHORT) return load<GLushort>(bytes + 2 * k);
        return load<GLuint>(bytes + 4 * k);
      },
      true, aligned ? static_cast<const std::uint32_t*>(indices) : nullptr);
}

}  // namespace shadelab::gl
