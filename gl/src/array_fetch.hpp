// Reading vertex arrays' elements (GL 1.1 section 2.8, GL 1.5 section 2.9), shared by the
// array commands (arrays.cpp) and their display-list forms (array_list.cpp): a component of an
// element converted as the command converts it, arrays in buffer objects resolved to their
// data stores for the length of a draw, and index data. It reads the arrays only: what an
// element does (current attributes, a vertex) is the commands'.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

#include <glm/vec4.hpp>

#include "gl/src/context.hpp"

namespace shadelab::gl {

/// The size in bytes of one component of `type` (0 for a type arrays do not take).
int type_size(GLenum type);

/// How integer components become floats. kDirect: as they are (positions, texture
/// coordinates). kSpec: GL 1.1 table 2.6, as glArrayElement converts them (Mesa issues the
/// immediate-mode calls, glColor3b and so on). kDraw: as llvmpipe's vertex fetch converts them
/// for glDrawArrays / glDrawElements (Mesa hands the arrays over as normalized formats: signed
/// c / (2^(b-1) - 1), at least -1; unsigned c / (2^b - 1)). The two differ by at most one
/// step of the type.
enum class Norm { kDirect, kSpec, kDraw };

/// Component k of element i.
float component(const ClientArray& a, std::size_t i, int k, Norm norm);

/// An array a draw reads: enabled, with a pointer.
inline bool usable(const ClientArray& a) { return a.enabled && a.pointer; }

/// Up to four components of element i, the missing ones taken from `fill`.
glm::vec4 fetch(const ClientArray& a, std::size_t i, glm::vec4 fill, Norm norm);

/// Element i of the secondary colour array (GL 1.4 section 2.8): red, green and blue (a fourth
/// component is read by no one), alpha 1 as glSecondaryColor3 leaves it.
glm::vec4 secondary_element(const ClientArray& a, std::size_t i, Norm norm);

/// GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT or GL_UNSIGNED_INT.
bool index_type(GLenum type);

/// Index k of an index array of `type` (one of index_type's).
std::size_t read_index(const unsigned char* bytes, GLenum type, std::size_t k);

/// The index data of an indexed draw: `indices` itself, or the offset it is into the buffer
/// bound to GL_ELEMENT_ARRAY_BUFFER (null when `count` indices of `type` run past its end:
/// nothing is read outside it). `error`: GL_INVALID_VALUE for null client indices.
const unsigned char* index_data(const GlContext& c, GLsizei count, GLenum type, const void* indices, bool& error);

/// GL 1.5 section 2.9: while a draw reads the arrays, those given as offsets into buffer
/// objects point into the buffers' data stores (read in place, never copied); the arrays are
/// as they were afterwards. A mapped buffer is read all the same (GL 1.5 leaves such draws
/// undefined; Mesa 22.3 draws them without an error; the mapping is the store itself).
/// `limit`: the number of elements every enabled array in a buffer holds (SIZE_MAX with none).
class ResolvedArrays {
 public:
  explicit ResolvedArrays(GlContext& c);
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

}  // namespace shadelab::gl
