// Stencil, depth, blending and colour mask for one fragment (GL 1.5 sections 4.1.5-4.1.8).
#include "pipeline/fragment_ops.hpp"

#include <algorithm>
#include <cmath>

namespace shadelab::detail {

bool compare(CompareFunc func, float incoming, float stored) {
  switch (func) {
    case CompareFunc::kNever: return false;
    case CompareFunc::kLess: return incoming < stored;
    case CompareFunc::kEqual: return incoming == stored;
    case CompareFunc::kLequal: return incoming <= stored;
    case CompareFunc::kGreater: return incoming > stored;
    case CompareFunc::kNotequal: return incoming != stored;
    case CompareFunc::kGequal: return incoming >= stored;
    case CompareFunc::kAlways: return true;
  }
  return true;
}

bool compare_stencil(CompareFunc func, unsigned ref, unsigned stored) {
  return compare(func, static_cast<float>(ref), static_cast<float>(stored));
}

namespace {

std::uint8_t apply_stencil_op(StencilOp op, std::uint8_t value, std::uint8_t ref) {
  switch (op) {
    case StencilOp::kKeep: return value;
    case StencilOp::kZero: return 0;
    case StencilOp::kReplace: return ref;
    case StencilOp::kIncr: return value == 0xff ? value : value + 1;  // clamped (GL 1.1)
    case StencilOp::kDecr: return value == 0 ? value : value - 1;
    case StencilOp::kInvert: return static_cast<std::uint8_t>(~value);
  }
  return value;
}

void update_stencil(Framebuffer& fb, std::size_t i, StencilOp op, const StencilState& s) {
  std::uint8_t old = fb.stencil[i];
  std::uint8_t next = apply_stencil_op(op, old, s.ref);
  fb.stencil[i] = static_cast<std::uint8_t>((old & ~s.write_mask) | (next & s.write_mask));
}

float blend_factor(BlendFactor f, int channel, const glm::vec4& src, const glm::vec4& dst) {
  switch (f) {
    case BlendFactor::kZero: return 0.0f;
    case BlendFactor::kOne: return 1.0f;
    case BlendFactor::kSrcColor: return src[channel];
    case BlendFactor::kOneMinusSrcColor: return 1.0f - src[channel];
    case BlendFactor::kDstColor: return dst[channel];
    case BlendFactor::kOneMinusDstColor: return 1.0f - dst[channel];
    case BlendFactor::kSrcAlpha: return src.a;
    case BlendFactor::kOneMinusSrcAlpha: return 1.0f - src.a;
    case BlendFactor::kDstAlpha: return dst.a;
    case BlendFactor::kOneMinusDstAlpha: return 1.0f - dst.a;
    case BlendFactor::kSrcAlphaSaturate: return channel == 3 ? 1.0f : std::min(src.a, 1.0f - dst.a);
  }
  return 1.0f;
}

}  // namespace

bool depth_stencil_test(Framebuffer& fb, std::size_t i, float z, const FragmentState& state) {
  const StencilState& s = state.stencil;
  if (s.enabled && !compare_stencil(s.func, s.ref & s.value_mask, fb.stencil[i] & s.value_mask)) {
    update_stencil(fb, i, s.fail, s);
    return false;
  }
  if (state.depth_test) {
    if (!compare(state.depth_func, z, fb.depth[i])) {
      if (s.enabled) update_stencil(fb, i, s.depth_fail, s);
      return false;
    }
    if (state.depth_write) fb.depth[i] = z;
  }
  if (s.enabled) update_stencil(fb, i, s.pass, s);
  return true;
}

namespace {
// Clamps to [0, 1] with NaN to 0 (the fast pipeline's clamp_unit makes the same choice).
float unit(float x) { return x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0f; }
}  // namespace

void write_color(Framebuffer& fb, std::size_t i, glm::vec4 src, const FragmentState& state) {
  for (int c = 0; c < 4; ++c) src[c] = unit(src[c]);
  std::uint8_t* px = &fb.color[i * 4];
  glm::vec4 out = src;
  if (state.blend.enabled) {
    glm::vec4 dst(px[0] / 255.0f, px[1] / 255.0f, px[2] / 255.0f, px[3] / 255.0f);
    for (int c = 0; c < 4; ++c) {
      out[c] = src[c] * blend_factor(state.blend.src, c, src, dst) +
               dst[c] * blend_factor(state.blend.dst, c, src, dst);
    }
  }
  for (int c = 0; c < 4; ++c) {
    if (!state.color_mask[c]) continue;
    px[c] = static_cast<std::uint8_t>(std::lround(unit(out[c]) * 255.0f));
  }
}

}  // namespace shadelab::detail

namespace shadelab {

void resolve_fragments(Framebuffer& fb, FragmentCapture& capture) {
  FragmentState state;
  for (std::size_t i = 0; i < capture.pixels.size(); ++i) {
    auto& list = capture.pixels[i];
    // Far to near; equal depths keep their drawing order.
    std::stable_sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.depth > b.depth; });
    for (const FragmentCapture::Entry& e : list) {
      state.blend = e.blend;
      detail::write_color(fb, i, e.color, state);
    }
    list.clear();
  }
  capture.count = 0;
}

}  // namespace shadelab
