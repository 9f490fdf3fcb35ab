// The pixels the pipeline draws into (part of pipeline.hpp): colour, depth and stencil in
// OpenGL window space, and the viewport that maps onto them. Storage and clears only: nothing
// here rasterizes, shades or keeps drawing state.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec4.hpp>

#include "shadelab/image.hpp"

namespace shadelab {

class PipelineContext;

/// A framebuffer's RGBA8 bytes: its own storage, or memory its owner lends it (attach), as
/// an OSMesa caller's buffer of the same layout is the GL library's colour buffer itself.
/// Copies always own their bytes.
class ColorBuffer {
 public:
  ColorBuffer() = default;
  ColorBuffer(const ColorBuffer& other) : owned_(other.begin(), other.end()) { point_at_owned(); }
  ColorBuffer& operator=(const ColorBuffer& other) {
    if (this != &other) {
      owned_.assign(other.begin(), other.end());
      point_at_owned();
    }
    return *this;
  }
  ColorBuffer(ColorBuffer&& other) noexcept { take(other); }
  ColorBuffer& operator=(ColorBuffer&& other) noexcept {
    if (this != &other) take(other);
    return *this;
  }

  std::uint8_t* data() { return data_; }
  const std::uint8_t* data() const { return data_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::uint8_t& operator[](std::size_t i) { return data_[i]; }
  const std::uint8_t& operator[](std::size_t i) const { return data_[i]; }
  std::uint8_t* begin() { return data_; }
  std::uint8_t* end() { return data_ + size_; }
  const std::uint8_t* begin() const { return data_; }
  const std::uint8_t* end() const { return data_ + size_; }
  friend bool operator==(const ColorBuffer& a, const ColorBuffer& b) {
    return a.size_ == b.size_ && (a.size_ == 0 || std::equal(a.begin(), a.end(), b.begin()));
  }

  /// Own storage of n bytes, all `value` (lent memory is let go, untouched).
  void assign(std::size_t n, std::uint8_t value) {
    owned_.assign(n, value);
    point_at_owned();
  }
  /// Uses the n bytes at `bytes` from now on, as they are, until assign, detach or the next
  /// attach; they must outlive that use. Nothing is copied.
  void attach(std::uint8_t* bytes, std::size_t n) {
    owned_ = {};
    data_ = bytes;
    size_ = n;
    lent_ = true;
  }
  /// Copies lent memory into own storage and lets it go.
  void detach() {
    if (!lent_) return;
    std::vector<std::uint8_t> copy(begin(), end());
    owned_.swap(copy);
    point_at_owned();
  }
  bool attached() const { return lent_; }

 private:
  void take(ColorBuffer& other) {
    owned_ = std::move(other.owned_);
    data_ = other.lent_ ? other.data_ : owned_.data();
    size_ = other.size_;
    lent_ = other.lent_;
    other.owned_ = {};
    other.point_at_owned();
  }
  void point_at_owned() {
    data_ = owned_.data();
    size_ = owned_.size();
    lent_ = false;
  }
  std::vector<std::uint8_t> owned_;
  std::uint8_t* data_ = nullptr;
  std::size_t size_ = 0;
  bool lent_ = false;
};

/// Colour, depth and stencil in OpenGL window space: row 0 is the BOTTOM row.
struct Framebuffer {
  int width = 0;
  int height = 0;
  ColorBuffer color;  ///< RGBA8, width * height * 4
  std::vector<float> depth;         ///< window-space depth in [0, 1]
  std::vector<std::uint8_t> stencil;

  void resize(int w, int h);
  /// Clears are split over `threads`' threads when given (a full-HD frame is 16 MB of colour
  /// and depth).
  void clear_color(glm::vec4 rgba, PipelineContext* threads = nullptr);
  /// The RGBA8 bytes clear_color writes for `rgba`.
  static std::array<std::uint8_t, 4> color_bytes(glm::vec4 rgba);
  void clear_depth(float d, PipelineContext* threads = nullptr);
  void clear_stencil(std::uint8_t s);
  /// The colour buffer as an image, top row first.
  Image to_image() const;
};

/// glViewport / glDepthRange.
struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;
  float near_depth = 0.0f, far_depth = 1.0f;
};

}  // namespace shadelab
