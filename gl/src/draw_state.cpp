// The core pipeline's per-draw state from GL's (GL 1.1 chapter 4, sections 3.3-3.5 and 3.9;
// GL 1.4's blending and stencil operations, section 4.1): depth, stencil, blending, logic op,
// scissor, alpha test, colour mask, polygon offset and stipple, polygon modes, lines, points
// and clip planes into FragmentState; glFog into FogState. Translation only: no GL state
// changes and no drawing here.
#include "gl/src/draw_state.hpp"

#include <algorithm>
#include <cstdint>

#include "gl/src/texture.hpp"

namespace shadelab::gl {
namespace {

CompareFunc compare_func(GLenum f) {
  switch (f) {
    case GL_NEVER: return CompareFunc::kNever;
    case GL_LESS: return CompareFunc::kLess;
    case GL_EQUAL: return CompareFunc::kEqual;
    case GL_LEQUAL: return CompareFunc::kLequal;
    case GL_GREATER: return CompareFunc::kGreater;
    case GL_NOTEQUAL: return CompareFunc::kNotequal;
    case GL_GEQUAL: return CompareFunc::kGequal;
    default: return CompareFunc::kAlways;
  }
}

StencilOp stencil_op(GLenum op) {
  switch (op) {
    case GL_ZERO: return StencilOp::kZero;
    case GL_REPLACE: return StencilOp::kReplace;
    case GL_INCR: return StencilOp::kIncr;
    case GL_DECR: return StencilOp::kDecr;
    case GL_INVERT: return StencilOp::kInvert;
    case GL_INCR_WRAP: return StencilOp::kIncrWrap;
    case GL_DECR_WRAP: return StencilOp::kDecrWrap;
    default: return StencilOp::kKeep;
  }
}

BlendFactor blend_factor(GLenum f) {
  switch (f) {
    case GL_ZERO: return BlendFactor::kZero;
    case GL_SRC_COLOR: return BlendFactor::kSrcColor;
    case GL_ONE_MINUS_SRC_COLOR: return BlendFactor::kOneMinusSrcColor;
    case GL_DST_COLOR: return BlendFactor::kDstColor;
    case GL_ONE_MINUS_DST_COLOR: return BlendFactor::kOneMinusDstColor;
    case GL_SRC_ALPHA: return BlendFactor::kSrcAlpha;
    case GL_ONE_MINUS_SRC_ALPHA: return BlendFactor::kOneMinusSrcAlpha;
    case GL_DST_ALPHA: return BlendFactor::kDstAlpha;
    case GL_ONE_MINUS_DST_ALPHA: return BlendFactor::kOneMinusDstAlpha;
    case GL_SRC_ALPHA_SATURATE: return BlendFactor::kSrcAlphaSaturate;
    case GL_CONSTANT_COLOR: return BlendFactor::kConstantColor;
    case GL_ONE_MINUS_CONSTANT_COLOR: return BlendFactor::kOneMinusConstantColor;
    case GL_CONSTANT_ALPHA: return BlendFactor::kConstantAlpha;
    case GL_ONE_MINUS_CONSTANT_ALPHA: return BlendFactor::kOneMinusConstantAlpha;
    default: return BlendFactor::kOne;
  }
}

BlendEquation blend_equation(GLenum mode) {
  switch (mode) {
    case GL_FUNC_SUBTRACT: return BlendEquation::kSubtract;
    case GL_FUNC_REVERSE_SUBTRACT: return BlendEquation::kReverseSubtract;
    case GL_MIN: return BlendEquation::kMin;
    case GL_MAX: return BlendEquation::kMax;
    default: return BlendEquation::kAdd;
  }
}

BlendState blend_state(const RasterState& r) {
  BlendState b{r.blend, blend_factor(r.blend_src), blend_factor(r.blend_dst)};
  b.src_alpha = blend_factor(r.blend_src_alpha);
  b.dst_alpha = blend_factor(r.blend_dst_alpha);
  b.equation = blend_equation(r.blend_equation);
  b.separate_equations = r.blend_equation_alpha != r.blend_equation;
  b.equation_alpha = blend_equation(r.blend_equation_alpha);
  b.color = r.blend_color;
  return b;
}

PolygonMode polygon_mode(GLenum mode) {
  return mode == GL_LINE    ? PolygonMode::kLine
         : mode == GL_POINT ? PolygonMode::kPoint
                            : PolygonMode::kFill;
}

}  // namespace

float raster_size(float v, float least, float max) {
  return v == v ? std::clamp(v, least, max) : 1.0f;
}

FragmentState fragment_state(const GlContext& c) {
  const RasterState& r = c.raster;
  FragmentState f;
  f.cull = !r.cull ? CullMode::kNone : r.cull_mode == GL_FRONT ? CullMode::kFront : CullMode::kBack;
  f.front_ccw = r.front_face == GL_CCW;
  f.depth_test = r.depth_test && c.depth_bits > 0;
  f.depth_func = compare_func(r.depth_func);
  f.depth_write = r.depth_mask;
  f.blend = blend_state(r);
  // glDrawBuffer(GL_NONE) writes no colour (GL 1.1 section 4.2.1).
  for (int i = 0; i < 4; ++i) f.color_mask[i] = r.color_mask[std::size_t(i)] && draws_color(c);
  StencilState& s = f.stencil;
  s.enabled = r.stencil_test && c.stencil_bits > 0;
  s.func = compare_func(r.stencil_func);
  s.ref = std::uint8_t(std::clamp(r.stencil_ref, 0, 255));
  s.value_mask = std::uint8_t(r.stencil_value_mask & 0xffu);
  s.write_mask = std::uint8_t(r.stencil_write_mask & 0xffu);
  s.fail = stencil_op(r.stencil_fail);
  s.depth_fail = stencil_op(r.stencil_zfail);
  s.pass = stencil_op(r.stencil_zpass);
  f.polygon_offset = r.polygon_offset_fill;
  f.offset_factor = r.offset_factor;
  f.offset_units = r.offset_units;
  f.scissor = {r.scissor_test, r.scissor_x, r.scissor_y, r.scissor_width, r.scissor_height};
  f.alpha_test = {r.alpha_test, compare_func(r.alpha_func), r.alpha_ref};
  f.logic_op = {r.color_logic_op, LogicOp(r.logic_op - GL_CLEAR)};
  f.stipple.enabled = r.polygon_stipple;
  if (r.polygon_stipple) f.stipple.rows = r.stipple;
  const PrimState& p = c.prims;
  f.offset_line = p.offset_line;
  f.offset_point = p.offset_point;
  f.front_mode = polygon_mode(p.front_mode);
  f.back_mode = polygon_mode(p.back_mode);
  f.line = {raster_size(p.line_width, 1.0f, kMaxLineWidth), p.line_smooth,
            p.line_stipple && p.stipple_pattern != 0xffff, p.stipple_pattern,
            GLushort(p.stipple_repeat)};
  // GL 1.4 section 3.3: the derived size clamped to [GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX]. As
  // in Mesa, glPointSize's size is clamped so when nothing attenuates it; else the core derives
  // each point's size and clamps it (never below kMinPointSize). The fade threshold applies to
  // multisampled points only (multisample.cpp).
  f.point = {raster_size(p.point_size, 0.0f, kMaxPointSize), p.point_smooth};
  f.point.sprite = p.point_sprite;
  f.point.coord_replace = p.point_sprite ? p.coord_replace : 0;
  f.point.attenuation = p.point_attenuation;
  f.point.min_size = std::max(p.point_min, kMinPointSize);
  f.point.max_size = std::min(p.point_max, kMaxPointSize);
  if (!f.point.attenuated()) {
    const float s = p.point_size < p.point_min ? p.point_min : p.point_size > p.point_max ? p.point_max : p.point_size;
    f.point.size = raster_size(s, 0.0f, kMaxPointSize);
  }
  for (int i = 0; i < kMaxClipPlanes; ++i) {
    f.clip.eye[std::size_t(i)] = p.clip_planes[std::size_t(i)];
    if (p.clip_enabled[std::size_t(i)]) f.clip.enabled |= std::uint8_t(1u << i);
  }
  if (c.ms.active >= 0 && c.multisample.enabled) sample_fragment_state(c, f);
  return f;
}

shadelab::FogState fog_state(const GlContext& c) {
  const FogSettings& g = c.fog;
  shadelab::FogState f;
  f.enabled = g.enabled;
  f.mode = g.mode == GL_LINEAR ? FogMode::kLinear : g.mode == GL_EXP2 ? FogMode::kExp2 : FogMode::kExp;
  f.color = glm::vec3(g.color);
  f.start = g.start, f.end = g.end, f.density = g.density;
  return f;
}

FragmentState rectangle_fragment_state(const GlContext& c) { return fragment_state(c); }

ShadeState rectangle_shade_state(GlContext& c) {
  ShadeState shade;
  shade.lighting = false;
  texture_draw_state(c, shade);
  return shade;
}

void draw_rectangle(GlContext& c, const FragmentRect& given) {
  FragmentRect rect = given;
  for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {  // a rectangle texture's texel coordinates
    const glm::vec2 scale = rectangle_scale(c, u);
    rect.texcoords[u].x *= scale.x, rect.texcoords[u].y *= scale.y;
  }
  make_pipeline(c);
  for_each_draw_buffer(c, [&](bool first) {
    draw_fragments(c.fb, rectangle_fragment_state(c), rectangle_shade_state(c), rect, pass_counts(c, first),
                   c.pipeline.get());
    mark_dirty(c, rect.x, rect.y, rect.x + rect.width, rect.y + rect.height);
  });
}

}  // namespace shadelab::gl
