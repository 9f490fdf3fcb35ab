// Display lists (GL 1.1 section 5.4): how a command is written into the list being compiled
// and read back at execution, and the few helpers savers share. The generated code
// (gl/generated/save.hpp, dlist_commands.cpp) records and replays each command with these;
// gl/src/dlist.cpp implements glNewList ... glCallLists. Nothing here draws.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <type_traits>

#include "gl/generated/save.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {

/// Appends one command to the list being compiled: a header word, then one word per scalar
/// argument and, per array argument, its element count (kNull for a null pointer) and the
/// elements packed into whole words (so that every array starts 8-byte aligned). If an
/// exception leaves the command unfinished, the list is cut back to where it began.
class ListWriter {
 public:
  static constexpr std::uint64_t kNull = ~std::uint64_t(0);

  ListWriter(GlContext& c, Opcode op) : ListWriter(c.lists.building->code, op) {}
  ListWriter(std::vector<std::uint64_t>& code, Opcode op) : code_(code), start_(code.size()) {
    code_.push_back(std::uint64_t(op));
  }
  ~ListWriter() {
    if (std::uncaught_exceptions() > exceptions_) {
      code_.resize(start_);
      return;
    }
    code_[start_] |= std::uint64_t(code_.size() - start_) << 16;
  }
  ListWriter(const ListWriter&) = delete;
  ListWriter& operator=(const ListWriter&) = delete;

  template <class T>
  void scalar(T value) {
    static_assert(std::is_trivially_copyable_v<T> && sizeof(T) <= 8);
    std::uint64_t word = 0;
    std::memcpy(&word, &value, sizeof value);
    code_.push_back(word);
  }

  template <class T>
  void array(const T* values, std::size_t count) {
    if (!values) return code_.push_back(kNull);
    code_.push_back(count);
    const std::size_t bytes = count * sizeof(T), at = code_.size();
    code_.resize(at + (bytes + 7) / 8, 0);
    if (bytes) std::memcpy(&code_[at], values, bytes);
  }

 private:
  std::vector<std::uint64_t>& code_;
  std::size_t start_;
  int exceptions_ = std::uncaught_exceptions();
};

/// Reads commands back in the order ListWriter wrote them.
class ListReader {
 public:
  explicit ListReader(const DisplayList& list)
      : list_(list), at_(list.code.data()), end_(list.code.data() + list.code.size()) {}

  const DisplayList& list() const { return list_; }
  bool done() const { return at_ == end_; }
  /// Where the reader is, in words from the list's start; seek goes back there.
  std::size_t offset() const { return std::size_t(at_ - list_.code.data()); }
  void seek(std::size_t offset) { at_ = list_.code.data() + offset; }
  /// The next command's opcode; its arguments follow.
  Opcode next() {
    next_ = at_ + (*at_ >> 16);
    return Opcode(*at_++ & 0xffff);
  }
  /// Where the command `next` returned ends (after its arguments).
  const std::uint64_t* command_end() const { return next_; }
  void skip_command() { at_ = next_; }

  template <class T>
  T scalar() {
    T value;
    std::memcpy(&value, at_++, sizeof value);
    return value;
  }

  /// The elements of an array argument in place (nullptr for a null pointer). An empty array
  /// reads as zeros: a command given a parameter name it rejects reads nothing from it, but
  /// its pointer must not point past the list.
  template <class T>
  const T* array() {
    const std::uint64_t count = *at_++;
    if (count == ListWriter::kNull) return nullptr;
    if (count == 0) return reinterpret_cast<const T*>(kZeros);
    const T* values = reinterpret_cast<const T*>(at_);
    at_ += (count * sizeof(T) + 7) / 8;
    return values;
  }
  std::uint64_t array_count() const { return *at_; }

 private:
  static constexpr std::uint64_t kZeros[16] = {};
  const DisplayList& list_;
  const std::uint64_t* at_;
  const std::uint64_t* end_;
  const std::uint64_t* next_ = nullptr;
};

/// The elements of a dereferenced vertex-array command (ArrayElements, ArrayDraw: gl/src/
/// arrays.cpp writes them): per element, 3 floats of normal, 4 of colour, 4 of texture
/// coordinates, 4 of position and 1 of edge flag, each array null when its client array was
/// disabled.
struct RecordedElements {
  std::uint64_t count;
  const float *normals, *colors, *texcoords, *positions, *edges;
  const float* secondary;  // GL 1.4: red, green and blue per element
  const float* fog;        // GL 1.4: the fog coordinate per element
  // GL 1.3: per texture unit, 4 floats per element (unit 0's are `texcoords`).
  std::array<const float*, kMaxTextureUnits> unit_texcoords{};
  explicit RecordedElements(ListReader& r)
      : count(r.scalar<std::uint64_t>()),
        normals(r.array<float>()),
        colors(r.array<float>()),
        texcoords(r.array<float>()),
        positions(r.array<float>()),
        edges(r.array<float>()),
        secondary(r.array<float>()),
        fog(r.array<float>()) {
    unit_texcoords[0] = texcoords;
    for (std::size_t u = 1; u < kMaxTextureUnits; ++u) unit_texcoords[u] = r.array<float>();
  }
  /// Whether a texture unit other than 0 has coordinates (a compiled mesh keeps unit 0's only).
  bool other_units() const {
    for (std::size_t u = 1; u < kMaxTextureUnits; ++u) {
      if (unit_texcoords[u]) return true;
    }
    return false;
  }
};

/// While a command is compiled: runs its saver (out of memory becomes GL_OUT_OF_MEMORY) and
/// says whether the command is also to be executed now (GL_COMPILE_AND_EXECUTE).
template <class Save>
bool compile_command(GlContext& c, Save&& save) noexcept {
  try {
    save();
  } catch (...) {
    c.set_error(GL_OUT_OF_MEMORY);
  }
  return c.lists.mode == GL_COMPILE_AND_EXECUTE;
}

/// Records an error a saver detected, raised when the list executes (as Mesa's
/// _mesa_compile_error does; in GL_COMPILE_AND_EXECUTE the execution raises it now as well).
void record_error(GlContext& c, GLenum error);

/// The unpack state while a command replays an image its saver unpacked: the default one,
/// tightly packed (alignment 1), as Mesa replays it; restored afterwards.
class DefaultUnpack {
 public:
  explicit DefaultUnpack(GlContext& c) : c_(c), saved_(c.unpack) { c.unpack = tight(); }
  ~DefaultUnpack() { c_.unpack = saved_; }
  DefaultUnpack(const DefaultUnpack&) = delete;
  DefaultUnpack& operator=(const DefaultUnpack&) = delete;
  static PixelStore tight() {
    PixelStore s;
    s.alignment = 1;
    return s;
  }

 private:
  GlContext& c_;
  PixelStore saved_;
};

/// Executes list `name` (none: nothing), unless kMaxListNesting lists are executing already.
void execute_list(GlContext& c, GLuint name);

}  // namespace shadelab::gl
