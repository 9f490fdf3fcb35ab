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

namespace {

// fill(begin, end) over [0, count), on the context's threads for large buffers.
template <class Fill>
void in_ranges(std::size_t count, PipelineContext* threads, const Fill& fill) {
  if (threads && count >= (1u << 16)) threads->parallel_for(count, 1u << 15, fill);
  else fill(0, count);
}

}  // namespace

void Framebuffer::clear_color(glm::vec4 rgba, PipelineContext* threads) {
  const std::array<std::uint8_t, 4> px = color_bytes(rgba);
  std::uint32_t value;
  std::memcpy(&value, px.data(), 4);
  std::uint32_t* pixels = reinterpret_cast<std::uint32_t*>(color.data());
  in_ranges(color.size() / 4, threads, [&](std::size_t b, std::size_t e) { std::fill(pixels + b, pixels + e, value); });
}

void Framebuffer::clear_depth(float d, PipelineContext* threads) {
  const float value = std::clamp(d, 0.0f, 1.0f);
  in_ranges(depth.size(), threads, [&](std::size_t b, std::size_t e) { std::fill(&depth[b], &depth[b] + (e - b), value); });
}

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
