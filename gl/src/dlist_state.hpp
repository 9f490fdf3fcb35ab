// The display-list state of a context (GL 1.1 section 5.4, table 6.26): the lists by name,
// shared between contexts created to share them, and what glNewList, glListBase and the
// execution of lists leave behind. Plain data; gl/src/dlist.cpp gives it its meaning.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace shadelab::gl {

/// GL_MAX_LIST_NESTING: how many lists may be executing at once, one calling the next (Mesa's).
inline constexpr int kMaxListNesting = 64;

/// Geometry of a list compiled once (dlist_geometry.cpp): a glBegin ... glEnd of vertices and
/// attributes, or a dereferenced glDrawArrays / glDrawElements, as distinct vertices (object
/// space; an attribute array is empty when the commands never set that attribute, which then
/// keeps its current value) and the primitive's vertices as indices into them.
struct ListMesh {
  GLenum mode = GL_TRIANGLES;
  // A vertex-array draw: the current attributes and material are left as they were (Mesa);
  // else the attributes set last stay current (GL 1.1 section 2.7).
  bool array_draw = false;
  std::vector<glm::vec4> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec4> colors, texcoords;
  std::vector<std::uint32_t> indices;
  // glBegin ... glEnd: the values it left current, for the attributes it set.
  glm::vec3 last_normal{0.0f};
  glm::vec4 last_color{0.0f}, last_texcoord{0.0f};
  bool sets_normal = false, sets_color = false, sets_texcoord = false;
};

/// One compiled list: its commands, each a header word (opcode, and the command's length in
/// words) followed by its arguments (dlist.hpp's ListWriter), and the meshes its Mesh
/// commands draw. Never changed once installed.
struct DisplayList {
  std::vector<std::uint64_t> code;
  std::vector<ListMesh> meshes;
};

/// Display-list names and their lists, shared between contexts as texture names are. Names
/// glGenLists reserved but no list defined yet are kept as ranges (a reserved name is a list,
/// an empty one), so that reserving a huge range costs nothing.
struct ListNames {
  std::mutex mutex;  // lists may be shared by contexts current in different threads
  std::map<GLuint, std::shared_ptr<const DisplayList>> lists;
  std::map<GLuint, GLuint> reserved;  // first name -> last name, ranges that do not overlap
  GLuint max_name = 0;  // the largest name ever used: glGenLists looks above it first (as Mesa)
};

struct ListState {
  GLenum mode = 0;   // GL_LIST_MODE: 0, or GL_COMPILE / GL_COMPILE_AND_EXECUTE while compiling
  GLuint index = 0;  // GL_LIST_INDEX: the name of the list being compiled
  GLuint base = 0;   // GL_LIST_BASE
  int depth = 0;     // lists being executed, each called by the one before
  // Meshes drawn through the vertex-array path, and vertex by vertex (dlist_geometry.cpp):
  // what tests and benchmarks read to know which path a list took.
  std::uint64_t meshes_fast = 0, meshes_by_vertex = 0;
  std::shared_ptr<DisplayList> building;  // the list being compiled
  std::shared_ptr<ListNames> names;
};

}  // namespace shadelab::gl
