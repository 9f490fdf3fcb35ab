// Vertex-array commands in display lists (GL 1.1 section 5.4): glArrayElement, glDrawArrays,
// glDrawElements, GL 1.2's glDrawRangeElements and GL 1.4's glMultiDraw* record the arrays'
// contents of the moment (buffer objects' too, GL 1.5), dereferenced element by element, with
// Mesa's compile errors; a replayed record specifies the same attributes and vertices the
// command would have. The commands themselves are arrays.cpp's.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "gl/generated/exec.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/array_fetch.hpp"
#include "gl/src/dlist.hpp"
#include "gl/src/draw.hpp"
#include "gl/src/primitive.hpp"

namespace shadelab::gl {
namespace {

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

}  // namespace shadelab::gl
