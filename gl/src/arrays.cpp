// Vertex arrays (GL 1.1 section 2.8): the array pointers (GL 1.4's secondary colour and fog
// coordinate arrays too), glArrayElement, glDrawArrays, glDrawElements, GL 1.2's
// glDrawRangeElements, GL 1.4's glMultiDrawArrays and glMultiDrawElements, and GL 1.5's arrays
// and indices in buffer objects (section 2.9, read in place). Each element becomes current
// attributes plus a vertex, exactly as the equivalent glBegin/glEnd sequence (which is how GL
// 1.1 defines them); draw.cpp does the rest, or array_mesh.cpp draws the whole array in one go
// where that gives the same result. Elements are read by array_fetch.cpp; the commands'
// display-list forms are array_list.cpp's.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <mutex>
#include <type_traits>

#include "gl/generated/exec.hpp"
#include "gl/src/array_fetch.hpp"
#include "gl/src/convert.hpp"
#include "gl/src/dlist.hpp"
#include "gl/src/draw.hpp"
#include "gl/src/primitive.hpp"

namespace shadelab::gl {
namespace {

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

}  // namespace

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
