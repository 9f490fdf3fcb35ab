// Framebuffer storage: RGBA8 colour, float depth, 8-bit stencil, in GL window space (row 0 at
// the bottom), and conversion to a top-down Image.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "shadelab/pipeline.hpp"

namespace shadelab {

void Framebuffer::resize(int w, int h) {
  width = std::max(w, 0);
  height = std::max(h, 0);
  std::size_t n = std::size_t(width) * std::size_t(height);
  color.assign(n * 4, 0);
  depth.assign(n, 1.0f);
  stencil.assign(n, 0);
}

namespace {
std::uint8_t to_unorm8(float c) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}
}  // namespace

std::array<std::uint8_t, 4> Framebuffer::color_bytes(glm::vec4 rgba) {
  return {to_unorm8(rgba.r), to_unorm8(rgba.g), to_unorm8(rgba.b), to_unorm8(rgba.a)};
}

void Framebuffer::clear_color(glm::vec4 rgba) {
  const std::array<std::uint8_t, 4> px = color_bytes(rgba);
  for (std::size_t i = 0; i < color.size(); i += 4) std::memcpy(&color[i], px.data(), 4);
}

void Framebuffer::clear_depth(float d) { std::fill(depth.begin(), depth.end(), std::clamp(d, 0.0f, 1.0f)); }

void Framebuffer::clear_stencil(std::uint8_t s) { std::fill(stencil.begin(), stencil.end(), s); }

Image Framebuffer::to_image() const {
  Image img;
  img.width = width;
  img.height = height;
  img.rgba.resize(color.size());
  std::size_t row = std::size_t(width) * 4;
  for (int y = 0; y < height; ++y) {
    std::memcpy(&img.rgba[std::size_t(height - 1 - y) * row], &color[std::size_t(y) * row], row);
  }
  return img;
}

}  // namespace shadelab
