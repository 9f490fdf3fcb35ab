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

namespace shadelab::gl {

/// GL_MAX_LIST_NESTING: how many lists may be executing at once, one calling the next (Mesa's).
inline constexpr int kMaxListNesting = 64;

/// One compiled list: its commands, each a header word (opcode, and the command's length in
/// words) followed by its arguments (dlist.hpp's ListWriter). Never changed once installed.
struct DisplayList {
  std::vector<std::uint64_t> code;
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
  std::shared_ptr<DisplayList> building;  // the list being compiled
  std::shared_ptr<ListNames> names;
};

}  // namespace shadelab::gl
