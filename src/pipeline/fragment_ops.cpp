// Fog (GL 1.1 section 3.9), alpha test, stencil, depth, blending, logic op and colour mask for
// one fragment (GL 1.1 sections 4.1.3-4.1.7, GL 1.5's 4.1.8 for the colour sum's place).
#include "pipeline/fragment_ops.hpp"

#include <algorithm>
#include <cmath>

namespace shadelab::detail {

FogParams fog_params(const FogState& fog) {
  FogParams p;
  p.mode = fog.mode;
  p.color = fog.color;
  p.scale = fog.end == fog.start ? 1.0f : -1.0f / (fog.end - fog.start);
  p.bias = fog.end * -p.scale;
  constexpr double kLog2e = 1.4426950408889634, kInvSqrtLn2 = 1.2011224087864498;
  p.k = float(double(fog.density) * (fog.mode == FogMode::kExp2 ? kInvSqrtLn2 : kLog2e));
  return p;
}

float fog_factor(const FogParams& p, float c) {
  float f;
  switch (p.mode) {
    case FogMode::kLinear: f = c * p.scale + p.bias; break;
    case FogMode::kExp: f = std::exp2(-(c * p.k)); break;
    case FogMode::kExp2: {
      const float t = c * p.k;
      f = std::exp2(-(t * t));
      break;
    }
    default: f = 1.0f;
  }
  return f > 0.0f ? (f < 1.0f ? f : 1.0f) : 0.0f;
}

glm::vec4 apply_fog(const FogParams& p, float c, glm::vec4 color) {
  const float f = fog_factor(p, c);
  for (int i = 0; i < 3; ++i) color[i] = f * (color[i] - p.color[i]) + p.color[i];
  return color;
}

std::uint8_t unorm8(float c) {
  c = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
  return static_cast<std::uint8_t>(std::lround(c * 255.0f));
}

bool alpha_test(const AlphaTestState& a, float alpha) {
  const float byte = float(unorm8(alpha));
  return compare(a.func, byte, float(unorm8(a.ref))) && (a.floor < 0.0f || byte > float(unorm8(a.floor)));
}

std::uint32_t logic_op(LogicOp op, std::uint32_t s, std::uint32_t d) {
  switch (op) {
    case LogicOp::kClear: return 0;
    case LogicOp::kAnd: return s & d;
    case LogicOp::kAndReverse: return s & ~d;
    case LogicOp::kCopy: return s;
    case LogicOp::kAndInverted: return ~s & d;
    case LogicOp::kNoop: return d;
    case LogicOp::kXor: return s ^ d;
    case LogicOp::kOr: return s | d;
    case LogicOp::kNor: return ~(s | d);
    case LogicOp::kEquiv: return ~(s ^ d);
    case LogicOp::kInvert: return ~d;
    case LogicOp::kOrReverse: return s | ~d;
    case LogicOp::kCopyInverted: return ~s;
    case LogicOp::kOrInverted: return ~s | d;
    case LogicOp::kNand: return ~(s & d);
    case LogicOp::kSet: return ~0u;
  }
  return s;
}

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
    case StencilOp::kIncrWrap: return static_cast<std::uint8_t>(value + 1);  // modulo 256 (GL 1.4)
    case StencilOp::kDecrWrap: return static_cast<std::uint8_t>(value - 1);
  }
  return value;
}

void update_stencil(Framebuffer& fb, std::size_t i, StencilOp op, const StencilState& s) {
  std::uint8_t old = fb.stencil[i];
  std::uint8_t next = apply_stencil_op(op, old, s.ref);
  fb.stencil[i] = static_cast<std::uint8_t>((old & ~s.write_mask) | (next & s.write_mask));
}

// Factor `f` for channel `channel` (3: alpha); `constant` is the blend colour in the colour
// buffer's precision (blend_constant).
float blend_factor(BlendFactor f, int channel, const glm::vec4& src, const glm::vec4& dst,
                   const glm::vec4& constant) {
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
    case BlendFactor::kConstantColor: return constant[channel];
    case BlendFactor::kOneMinusConstantColor: return 1.0f - constant[channel];
    case BlendFactor::kConstantAlpha: return constant.a;
    case BlendFactor::kOneMinusConstantAlpha: return 1.0f - constant.a;
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

glm::vec4 blend_constant(const BlendState& b) {
  glm::vec4 k;
  for (int c = 0; c < 4; ++c) k[c] = float(unorm8(b.color[c])) / 255.0f;
  return k;
}

glm::vec4 blend(const BlendState& b, const glm::vec4& constant, const glm::vec4& src, const glm::vec4& dst) {
  glm::vec4 out;
  for (int c = 0; c < 4; ++c) {
    const BlendEquation e = c == 3 ? b.alpha_equation() : b.equation;
    if (e == BlendEquation::kMin) {
      out[c] = std::min(src[c], dst[c]);
      continue;
    }
    if (e == BlendEquation::kMax) {
      out[c] = std::max(src[c], dst[c]);
      continue;
    }
    const float s = src[c] * blend_factor(c == 3 ? b.src_alpha : b.src, c, src, dst, constant);
    const float d = dst[c] * blend_factor(c == 3 ? b.dst_alpha : b.dst, c, src, dst, constant);
    out[c] = e == BlendEquation::kAdd ? s + d : e == BlendEquation::kSubtract ? s - d : d - s;
  }
  return out;
}

void write_color(Framebuffer& fb, std::size_t i, glm::vec4 src, const FragmentState& state) {
  if (state.alpha_one) src.a = 1.0f;
  for (int c = 0; c < 4; ++c) src[c] = unit(src[c]);
  std::uint8_t* px = &fb.color[i * 4];
  if (state.logic_op.enabled) {  // on the 8-bit values, instead of blending (GL 1.1 4.1.7)
    std::uint32_t s = 0, d = 0;
    for (int c = 0; c < 4; ++c) {
      s |= std::uint32_t(unorm8(src[c])) << (8 * c);
      d |= std::uint32_t(px[c]) << (8 * c);
    }
    const std::uint32_t out = logic_op(state.logic_op.op, s, d);
    for (int c = 0; c < 4; ++c) {
      if (state.color_mask[c]) px[c] = std::uint8_t(out >> (8 * c));
    }
    return;
  }
  glm::vec4 out = src;
  if (state.blend.enabled) {
    glm::vec4 dst(px[0] / 255.0f, px[1] / 255.0f, px[2] / 255.0f, px[3] / 255.0f);
    out = blend(state.blend, blend_constant(state.blend), src, dst);
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
