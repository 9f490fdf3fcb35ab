// glInterleavedArrays (GL 1.1 section 2.8, table 2.5): the fourteen interleaved layouts, each
// set up as the equivalent gl*Pointer and glEnable/DisableClientState calls. Array state
// only; the draws are arrays.cpp's.
#include <cstddef>
#include <cstdint>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {
namespace {

// One row of table 2.5: which arrays the format enables, their sizes, the colour type, and
// the offsets in bytes of the colour, normal and vertex in an element of `stride` bytes.
struct Layout {
  int texcoords = 0, colors = 0, vertices = 0;  // components, 0 for an array left disabled
  bool normals = false;
  GLenum color_type = GL_FLOAT;
  int color_offset = 0, normal_offset = 0, vertex_offset = 0, stride = 0;
};

constexpr int kF = int(sizeof(GLfloat));
// Four unsigned bytes, rounded up to a whole number of floats (the table's c).
constexpr int kC = (4 * int(sizeof(GLubyte)) + kF - 1) / kF * kF;

bool layout_of(GLenum format, Layout& l) {
  switch (format) {
    case GL_V2F: l = {0, 0, 2, false, GL_FLOAT, 0, 0, 0, 2 * kF}; return true;
    case GL_V3F: l = {0, 0, 3, false, GL_FLOAT, 0, 0, 0, 3 * kF}; return true;
    case GL_C4UB_V2F: l = {0, 4, 2, false, GL_UNSIGNED_BYTE, 0, 0, kC, kC + 2 * kF}; return true;
    case GL_C4UB_V3F: l = {0, 4, 3, false, GL_UNSIGNED_BYTE, 0, 0, kC, kC + 3 * kF}; return true;
    case GL_C3F_V3F: l = {0, 3, 3, false, GL_FLOAT, 0, 0, 3 * kF, 6 * kF}; return true;
    case GL_N3F_V3F: l = {0, 0, 3, true, GL_FLOAT, 0, 0, 3 * kF, 6 * kF}; return true;
    case GL_C4F_N3F_V3F: l = {0, 4, 3, true, GL_FLOAT, 0, 4 * kF, 7 * kF, 10 * kF}; return true;
    case GL_T2F_V3F: l = {2, 0, 3, false, GL_FLOAT, 0, 0, 2 * kF, 5 * kF}; return true;
    case GL_T4F_V4F: l = {4, 0, 4, false, GL_FLOAT, 0, 0, 4 * kF, 8 * kF}; return true;
    case GL_T2F_C4UB_V3F: l = {2, 4, 3, false, GL_UNSIGNED_BYTE, 2 * kF, 0, kC + 2 * kF, kC + 5 * kF}; return true;
    case GL_T2F_C3F_V3F: l = {2, 3, 3, false, GL_FLOAT, 2 * kF, 0, 5 * kF, 8 * kF}; return true;
    case GL_T2F_N3F_V3F: l = {2, 0, 3, true, GL_FLOAT, 0, 2 * kF, 5 * kF, 8 * kF}; return true;
    case GL_T2F_C4F_N3F_V3F: l = {2, 4, 3, true, GL_FLOAT, 2 * kF, 6 * kF, 9 * kF, 12 * kF}; return true;
    case GL_T4F_C4F_N3F_V4F: l = {4, 4, 4, true, GL_FLOAT, 4 * kF, 8 * kF, 11 * kF, 15 * kF}; return true;
    default: return false;
  }
}

// `pointer` + `offset` bytes, as an address: with a buffer bound (GL 1.5) the pointer is an
// offset into it, often 0, which pointer arithmetic may not move.
const void* at(const void* pointer, int offset) {
  return reinterpret_cast<const void*>(reinterpret_cast<std::uintptr_t>(pointer) + std::uintptr_t(offset));
}

}  // namespace

// Errors in Mesa's order: a negative stride, then an unknown format. The edge-flag and index
// arrays are disabled, as the specification's equivalent sequence does.
void exec::InterleavedArrays(GlContext& c, GLenum format, GLsizei stride, const void* pointer) {
  if (stride < 0) return c.set_error(GL_INVALID_VALUE);
  Layout l;
  if (!layout_of(format, l)) return c.set_error(GL_INVALID_ENUM);
  if (stride == 0) stride = l.stride;
  ClientArrays& a = c.arrays;
  // GL 1.5: the arrays take the buffer bound to GL_ARRAY_BUFFER, `pointer` an offset into it.
  const std::shared_ptr<BufferObject> buffer = a.array_buffer;
  const GLuint name = a.array_buffer_name;
  a.edge_flag.enabled = false;
  a.index.enabled = false;
  a.secondary_color.enabled = false;  // GL 1.4 section 2.8
  a.fog_coord.enabled = false;
  // The client active texture unit's array (GL 1.3 section 2.8).
  a.texcoord().enabled = l.texcoords > 0;
  if (l.texcoords > 0) a.texcoord() = {true, l.texcoords, GL_FLOAT, stride, pointer, buffer, name};
  a.color.enabled = l.colors > 0;
  if (l.colors > 0) a.color = {true, l.colors, l.color_type, stride, at(pointer, l.color_offset), buffer, name};
  a.normal.enabled = l.normals;
  if (l.normals) a.normal = {true, 3, GL_FLOAT, stride, at(pointer, l.normal_offset), buffer, name};
  a.vertex = {true, l.vertices, GL_FLOAT, stride, at(pointer, l.vertex_offset), buffer, name};
}

}  // namespace shadelab::gl
