// Display lists (GL 1.1 section 5.4): glNewList, glEndList, glCallList, glCallLists,
// glListBase, glGenLists, glDeleteLists, glIsList, and the execution of a list. Names and
// errors follow Mesa's dlist.c where the specification leaves room (glCallList(0), the names
// glGenLists picks, nesting). Commands are recorded and replayed by the generated code
// (gl/generated/dlist_commands.cpp); nothing here knows a command's arguments.
#include "gl/src/dlist.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gl/generated/exec.hpp"
#include "gl/src/dlist_geometry.hpp"

namespace shadelab::gl {
namespace {

std::shared_ptr<const DisplayList> find_list(ListNames& names, GLuint name) {
  std::lock_guard lock(names.mutex);
  auto it = names.lists.find(name);
  return it != names.lists.end() ? it->second : nullptr;
}

bool is_reserved(const ListNames& names, GLuint name) {
  auto it = names.reserved.upper_bound(name);
  return it != names.reserved.begin() && std::prev(it)->second >= name;
}

// Takes names [first, last] out of the reserved ranges.
void unreserve(ListNames& names, GLuint first, GLuint last) {
  auto begin = names.reserved.upper_bound(first);
  if (begin != names.reserved.begin() && std::prev(begin)->second >= first) --begin;
  auto end = names.reserved.upper_bound(last);
  if (begin == end) return;
  const GLuint a = begin->first, b = std::prev(end)->second;  // the overlapping ranges' extent
  names.reserved.erase(begin, end);
  if (a < first) names.reserved.emplace(a, first - 1);
  if (b > last) names.reserved.emplace(last + 1, b);
}

bool name_used(const ListNames& names, GLuint name) {
  // A list being compiled is not a list until glEndList (as in Mesa).
  return names.lists.count(name) || is_reserved(names, name);
}

// The first of `range` consecutive unused names: above every name used so far when there is
// room (Mesa's quick answer), else the lowest free block (found by jumping past the last used
// name of each window tried); 0 when there is none.
GLuint free_block(const ListNames& names, GLuint range) {
  const std::uint64_t top = std::numeric_limits<GLuint>::max() - 1;
  if (top - range > names.max_name) return names.max_name + 1;
  std::uint64_t first = 1;
  while (first + range - 1 <= top) {
    const GLuint last = GLuint(first + range - 1);
    std::uint64_t past_used = 0;
    auto l = names.lists.upper_bound(last);
    if (l != names.lists.begin() && std::prev(l)->first >= first) past_used = std::prev(l)->first + std::uint64_t(1);
    auto r = names.reserved.upper_bound(last);
    if (r != names.reserved.begin() && std::prev(r)->second >= first) {
      past_used = std::max(past_used, std::prev(r)->second + std::uint64_t(1));
    }
    if (past_used == 0) return GLuint(first);
    first = past_used;
  }
  return 0;
}

// The list number element `i` of glCallLists' array names before glListBase is added.
GLuint list_offset(GLenum type, const void* lists, std::size_t i) {
  const auto* b = static_cast<const unsigned char*>(lists);
  auto load = [&](auto zero) {
    decltype(zero) v;
    std::memcpy(&v, b + i * sizeof v, sizeof v);
    return v;
  };
  switch (type) {
    case GL_BYTE: return GLuint(GLint(load(GLbyte{})));
    case GL_UNSIGNED_BYTE: return load(GLubyte{});
    case GL_SHORT: return GLuint(GLint(load(GLshort{})));
    case GL_UNSIGNED_SHORT: return load(GLushort{});
    case GL_INT: return GLuint(load(GLint{}));
    case GL_UNSIGNED_INT: return load(GLuint{});
    case GL_FLOAT: {  // converted to an integer as C converts it (out of range: clamped)
      const double f = load(GLfloat{});
      return f == f ? GLuint(GLint(std::clamp(f, -2147483648.0, 2147483647.0))) : 0;
    }
    case GL_2_BYTES: return GLuint(b[2 * i]) << 8 | b[2 * i + 1];
    case GL_3_BYTES: return GLuint(b[3 * i]) << 16 | GLuint(b[3 * i + 1]) << 8 | b[3 * i + 2];
    default: return GLuint(b[4 * i]) << 24 | GLuint(b[4 * i + 1]) << 16 | GLuint(b[4 * i + 2]) << 8 | b[4 * i + 3];
  }
}

std::size_t list_type_size(GLenum type) {
  switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: case GL_2_BYTES: return 2;
    case GL_3_BYTES: return 3;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: case GL_4_BYTES: return 4;
    default: return 0;
  }
}

}  // namespace

void record_error(GlContext& c, GLenum error) {
  ListWriter w(c, Opcode::kError);
  w.scalar(error);
}

void replay_internal::Error(GlContext& c, ListReader& r) { c.set_error(r.scalar<GLenum>()); }

void execute_list(GlContext& c, GLuint name) {
  if (c.lists.depth >= kMaxListNesting) return;  // deeper calls are ignored, as in Mesa
  std::shared_ptr<const DisplayList> list = find_list(*c.lists.names, name);
  if (!list) return;
  struct Depth {
    int& d;
    explicit Depth(int& depth) : d(depth) { ++d; }
    ~Depth() { --d; }
  } depth(c.lists.depth);
  ListReader r(*list);
  while (!r.done()) replay_command(c, r);
}

void exec::NewList(GlContext& c, GLuint list, GLenum mode) {
  if (list == 0) return c.set_error(GL_INVALID_VALUE);
  if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) return c.set_error(GL_INVALID_ENUM);
  if (c.lists.mode != 0) return c.set_error(GL_INVALID_OPERATION);
  c.lists.building = std::make_shared<DisplayList>();
  c.lists.mode = mode;
  c.lists.index = list;
}

// The list replaces any list of that name only now (GL 1.1 section 5.4): until glEndList the
// old one can still be called.
void exec::EndList(GlContext& c) {
  if (c.lists.mode == GL_COMPILE_AND_EXECUTE && c.prim.active) c.set_error(GL_INVALID_OPERATION);
  if (c.lists.mode == 0) return c.set_error(GL_INVALID_OPERATION);
  compile_geometry(*c.lists.building);
  std::shared_ptr<const DisplayList> list = std::move(c.lists.building);
  c.lists.mode = 0;
  ListNames& names = *c.lists.names;
  std::lock_guard lock(names.mutex);
  unreserve(names, c.lists.index, c.lists.index);
  names.lists[c.lists.index] = std::move(list);
  names.max_name = std::max(names.max_name, c.lists.index);
  c.lists.index = 0;
}

// Mesa: glCallList(0) is GL_INVALID_VALUE when called, ignored inside a list.
void exec::CallList(GlContext& c, GLuint list) {
  if (list == 0) {
    if (c.lists.depth == 0) c.set_error(GL_INVALID_VALUE);
    return;
  }
  execute_list(c, list);
}

void exec::CallLists(GlContext& c, GLsizei n, GLenum type, const void* lists) {
  if (list_type_size(type) == 0) return c.set_error(GL_INVALID_ENUM);
  if (n < 0) return c.set_error(GL_INVALID_VALUE);
  if (n == 0 || !lists) return;
  for (std::size_t i = 0; i < std::size_t(n); ++i) {
    // glListBase may change between the lists (a list may call it).
    execute_list(c, c.lists.base + list_offset(type, lists, i));
  }
}

std::size_t save_count::CallLists(GLsizei n, GLenum type) {
  return n > 0 ? std::size_t(n) * list_type_size(type) : 0;
}

void exec::ListBase(GlContext& c, GLuint base) { c.lists.base = base; }

GLuint exec::GenLists(GlContext& c, GLsizei range) {
  if (range < 0) {
    c.set_error(GL_INVALID_VALUE);
    return 0;
  }
  if (range == 0) return 0;
  ListNames& names = *c.lists.names;
  std::lock_guard lock(names.mutex);
  const GLuint first = free_block(names, GLuint(range));
  if (first == 0) return 0;
  const GLuint last = first + GLuint(range) - 1;
  names.reserved.emplace(first, last);
  names.max_name = std::max(names.max_name, last);
  return first;
}

// Names [list, list + range) wrap around as Mesa's unsigned loop does (nothing is deleted
// when list + range overflows).
void exec::DeleteLists(GlContext& c, GLuint list, GLsizei range) {
  if (range < 0) return c.set_error(GL_INVALID_VALUE);
  const GLuint end = list + GLuint(range);
  if (range == 0 || end <= list) return;
  ListNames& names = *c.lists.names;
  std::lock_guard lock(names.mutex);
  names.lists.erase(names.lists.lower_bound(list), names.lists.lower_bound(end));
  unreserve(names, list, end - 1);
}

GLboolean exec::IsList(GlContext& c, GLuint list) {
  ListNames& names = *c.lists.names;
  std::lock_guard lock(names.mutex);
  return name_used(names, list) ? GL_TRUE : GL_FALSE;
}

}  // namespace shadelab::gl
