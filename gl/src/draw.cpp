// Vertex processing and primitive submission: eye-space transformation, normal transformation
// (inverse transpose, GL_RESCALE_NORMAL, GL_NORMALIZE), per-vertex lighting through the core's
// light_point (GL 1.1 section 2.13), then triangles with pre-lit colours to draw_triangles.
// Fragment work (clipping, rasterization, texturing, blending) is the core pipeline's.
#include "gl/src/draw.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <span>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "gl/src/convert.hpp"
#include "gl/src/primitive.hpp"
#include "gl/src/texgen.hpp"
#include "gl/src/texture.hpp"
#include "shadelab/lighting.hpp"

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace shadelab::gl {
namespace {

glm::vec4 sanitize(glm::vec4 v) {
  for (int i = 0; i < 4; ++i) v[i] = finite_or_zero(v[i]);
  return v;
}
glm::vec3 sanitize(glm::vec3 v) {
  for (int i = 0; i < 3; ++i) v[i] = finite_or_zero(v[i]);
  return v;
}

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
    default: return BlendFactor::kOne;
  }
}

PolygonMode polygon_mode(GLenum mode) {
  return mode == GL_LINE    ? PolygonMode::kLine
         : mode == GL_POINT ? PolygonMode::kPoint
                            : PolygonMode::kFill;
}

// A width or size as Mesa's state tracker hands it to llvmpipe: clamped to [least, the
// maximum] (line widths from 1, point sizes from 0: glLineWidth and glPointSize keep any
// positive value, and a NaN, for glGet; a NaN draws as 1 here).
float raster_size(float v, float least, float max) {
  return v == v ? std::clamp(v, least, max) : 1.0f;
}

// The core's per-fragment state from GL's. Without a depth (stencil) buffer the depth
// (stencil) test behaves as if disabled (GL 1.1 sections 4.1.5, 4.1.6).
FragmentState fragment_state(const GlContext& c) {
  const RasterState& r = c.raster;
  FragmentState f;
  f.cull = !r.cull ? CullMode::kNone : r.cull_mode == GL_FRONT ? CullMode::kFront : CullMode::kBack;
  f.front_ccw = r.front_face == GL_CCW;
  f.depth_test = r.depth_test && c.depth_bits > 0;
  f.depth_func = compare_func(r.depth_func);
  f.depth_write = r.depth_mask;
  f.blend = {r.blend, blend_factor(r.blend_src), blend_factor(r.blend_dst)};
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
  f.point = {raster_size(p.point_size, 0.0f, kMaxPointSize), p.point_smooth};
  for (int i = 0; i < kMaxClipPlanes; ++i) {
    f.clip.eye[std::size_t(i)] = p.clip_planes[std::size_t(i)];
    if (p.clip_enabled[std::size_t(i)]) f.clip.enabled |= std::uint8_t(1u << i);
  }
  return f;
}

// The core's fog from GL's (GL 1.1 section 3.9).
shadelab::FogState fog_state(const GlContext& c) {
  const FogSettings& g = c.fog;
  shadelab::FogState f;
  f.enabled = g.enabled;
  f.mode = g.mode == GL_LINEAR ? FogMode::kLinear : g.mode == GL_EXP2 ? FogMode::kExp2 : FogMode::kExp;
  f.color = glm::vec3(g.color);
  f.start = g.start, f.end = g.end, f.density = g.density;
  return f;
}

// m * v with glm's operations in glm's order, (m0 x + m1 y) + (m2 z + m3 w), so the same
// floats; in one SSE register where the target has one. glm's operator*, called from the
// per-vertex loops, was not inlined: its result went through memory in two halves and was
// read back whole, a store-forwarding stall per vertex (most of draw_array_mesh's time on
// the 1M-triangle sphere).
[[gnu::always_inline]] inline glm::vec4 transform(const glm::mat4& m, const glm::vec4& v) {
#if defined(__SSE2__)
  const __m128 x = _mm_set1_ps(v.x), y = _mm_set1_ps(v.y), z = _mm_set1_ps(v.z), w = _mm_set1_ps(v.w);
  const __m128 a = _mm_add_ps(_mm_mul_ps(_mm_loadu_ps(&m[0][0]), x), _mm_mul_ps(_mm_loadu_ps(&m[1][0]), y));
  const __m128 b = _mm_add_ps(_mm_mul_ps(_mm_loadu_ps(&m[2][0]), z), _mm_mul_ps(_mm_loadu_ps(&m[3][0]), w));
  alignas(16) float out[4];
  _mm_store_ps(out, _mm_add_ps(a, b));
  return glm::vec4(out[0], out[1], out[2], out[3]);
#else
  return m * v;
#endif
}

// The eye-space normal GL lights with: inverse transpose of the modelview, then rescaled
// (GL 1.2 equation 2.1) or normalized when enabled; otherwise left as it is.
[[gnu::always_inline]] inline glm::vec3 eye_normal(const GlContext& c, const glm::vec3& normal) {
  const Primitive& p = c.prim;
  glm::vec3 n = p.normal_matrix * normal;
  if (c.lighting.normalize) {
    float len = glm::length(n);
    return len > 0.0f ? n / len : n;
  }
  return c.lighting.rescale_normal ? n * p.rescale : n;
}

void light_vertex(const GlContext& c, const PrimitiveVertex& v, VertexColors& out) {
  const LightingState& l = c.lighting;
  if (!l.enabled) {
    // Colours are clamped to [0, 1] per vertex (GL 1.1 section 2.13.6), before interpolation.
    glm::vec4 col = glm::clamp(sanitize(c.current.color), glm::vec4(0.0f), glm::vec4(1.0f));
    out.front = out.back = col;
    out.front_secondary = out.back_secondary = glm::vec3(0.0f);
    return;
  }
  glm::vec3 pos = v.eye.w != 0.0f ? glm::vec3(v.eye) / v.eye.w : glm::vec3(v.eye);
  const glm::vec3& n = v.normal;
  LitColor f = light_point(l.model, c.prim.lights, l.front, {pos, n, nullptr});
  LitColor b = l.model.two_side ? light_point(l.model, c.prim.lights, l.back, {pos, -n, nullptr}) : f;
  out.front = sanitize(f.primary);
  out.back = sanitize(b.primary);
  out.front_secondary = sanitize(f.secondary);
  out.back_secondary = sanitize(b.secondary);
}

// (s, t, r, q) after the texture matrix; the pipeline divides by q per fragment.
glm::vec4 texcoord(const GlContext& c, glm::vec4 tc) {
  if (!c.prim.identity_texture_matrix) tc = c.prim.texture_matrix * tc;
  return tc;
}

// A vertex's texture coordinates before the texture matrix: `given`, or generated where
// glTexGen is enabled (GL 1.1 section 2.10.4) from its object and eye positions and its
// object-space `normal` (transformed here when a sphere map reads it).
glm::vec4 source_texcoord(const GlContext& c, const glm::vec4& given, const glm::vec4& object, const glm::vec4& eye,
                          const glm::vec3& normal) {
  const TextureState& t = c.textures;
  if (!t.any_texgen()) return given;
  const glm::vec3 n = texgen_needs_normal(t) ? eye_normal(c, normal) : glm::vec3(0.0f);
  return generate_texcoords(t, given, object, eye, n);
}

// Arrays for one draw_triangles call, in the context's reused buffers: one entry per vertex
// of the primitive (set), then any vertex a flat quad adds (add).
struct Batch {
  ImmediateScratch& s;

  Batch(ImmediateScratch& scratch, std::size_t vertices) : s(scratch) {
    for (auto* v : {&s.positions, &s.colors, &s.back_colors}) v->resize(vertices);
    for (auto* v : {&s.normals, &s.secondary, &s.back_secondary}) v->resize(vertices);
    s.texcoords.resize(vertices);
    s.triangles.clear();
  }

  // Only what the draw reads: normals when the pipeline lights, colours when lit here (or
  // unlit), texture coordinates when textured.
  void set(std::size_t i, const PrimitiveVertex& v, bool normals, const VertexColors* colors,
           const glm::vec4* texcoord) {
    s.positions[i] = v.eye;
    if (normals) s.normals[i] = v.normal;
    if (colors) {
      s.colors[i] = colors->front;
      s.back_colors[i] = colors->back;
      s.secondary[i] = colors->front_secondary;
      s.back_secondary[i] = colors->back_secondary;
    }
    if (texcoord) s.texcoords[i] = *texcoord;
  }

  std::uint32_t add(const PrimitiveVertex& v, const VertexColors& colors, const glm::vec4& texcoord) {
    s.positions.push_back(v.eye);
    s.normals.push_back(v.normal);
    s.colors.push_back(colors.front);
    s.back_colors.push_back(colors.back);
    s.secondary.push_back(colors.front_secondary);
    s.back_secondary.push_back(colors.back_secondary);
    s.texcoords.push_back(texcoord);
    return std::uint32_t(s.positions.size() - 1);
  }
};

// A triangle whose last vertex provokes it: rotated when the provoking vertex is one of its
// three (rotation keeps the winding), else its last vertex is repeated with the provoking
// vertex's colours (a quad's first triangle; the primitive's colours, none while lighting is
// deferred).
Triangle flat_triangle(const PrimitiveTriangle& t, const Primitive& prim, Batch& batch) {
  const std::uint32_t* v = t.v;
  if (v[0] == t.provoking) return {v[1], v[2], v[0]};
  if (v[1] == t.provoking) return {v[2], v[0], v[1]};
  if (v[2] == t.provoking) return {v[0], v[1], v[2]};
  const VertexColors colors = prim.colors.empty() ? VertexColors{} : prim.colors[t.provoking];
  const glm::vec4 texcoord = prim.texcoords.empty() ? glm::vec4(0, 0, 0, 1) : prim.texcoords[v[2]];
  return {v[0], v[1], batch.add(prim.vertices[v[2]], colors, texcoord)};
}

// Marks the window-space bounds of the batch's vertices, widened by `margin` pixels (the whole
// viewport when a vertex is behind the eye, as clipping may then reach any part of it).
void mark_batch(GlContext& c, const glm::mat4& projection, std::span<const glm::vec4> eye,
                int margin) {
  const Viewport& vp = c.raster.viewport;
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const glm::vec4& e : eye) {
    glm::vec4 clip = projection * e;
    if (!(clip.w > 0.0f)) {
      x0 = y0 = -1e300, x1 = y1 = 1e300;
      break;
    }
    double wx = (double(clip.x) / clip.w + 1.0) * 0.5 * vp.width + vp.x;
    double wy = (double(clip.y) / clip.w + 1.0) * 0.5 * vp.height + vp.y;
    x0 = std::min(x0, wx), x1 = std::max(x1, wx), y0 = std::min(y0, wy), y1 = std::max(y1, wy);
  }
  x0 = std::max(x0, double(vp.x)), y0 = std::max(y0, double(vp.y));
  x1 = std::min(x1, double(vp.x) + vp.width), y1 = std::min(y1, double(vp.y) + vp.height);
  if (!(x0 <= x1 && y0 <= y1)) return;  // nothing inside, or a NaN: nothing marked
  mark_dirty(c, int(std::floor(x0)) - margin, int(std::floor(y0)) - margin,
             int(std::ceil(x1)) + margin, int(std::ceil(y1)) + margin);
}

// How far beyond its vertices a primitive may draw, in pixels: half a wide line or point
// (a smooth one's rim besides), and one for rounding.
int prim_margin(const GlContext& c) {
  const PrimState& p = c.prims;  // sizes as drawn: clamped, a NaN as 1 (never cast unbounded)
  const float widest = std::max(raster_size(p.point_size, 0.0f, kMaxPointSize),
                                raster_size(p.line_width, 1.0f, kMaxLineWidth));
  return 2 + int(std::ceil(widest / 2.0f));
}

// Whether every entry is finite and at most 1e18 in magnitude: products of two such numbers,
// and sums of four products, stay below 4e36, finite.
bool bounded(const float* v, int n) {
  bool ok = true;
  for (int i = 0; i < n; ++i) ok &= std::fabs(v[i]) <= 1e18f;  // false for NaN
  return ok;
}

// Whether projection * eye is finite; `small_projection`: bounded(projection), checked once.
[[gnu::always_inline]] inline bool finite_clip(const glm::mat4& projection, bool small_projection,
                                               const glm::vec4& eye) {
#if defined(__SSE2__)  // bounded(&eye[0], 4) in one comparison of the four (false for NaN)
  const __m128 magnitude = _mm_andnot_ps(_mm_set1_ps(-0.0f), _mm_loadu_ps(&eye[0]));
  const bool small_eye = _mm_movemask_ps(_mm_cmple_ps(magnitude, _mm_set1_ps(1e18f))) == 0xf;
#else
  const bool small_eye = bounded(&eye[0], 4);
#endif
  if (small_projection && small_eye) return true;  // no overflow possible
  glm::vec4 clip = transform(projection, eye);
  return std::isfinite(clip.x) && std::isfinite(clip.y) && std::isfinite(clip.z) &&
         std::isfinite(clip.w);
}

// Mesa's llvmpipe sends a draw through its draw pipeline, which splits quads along the other
// diagonal, when some vertex of it lies outside the view volume (it needs clipping); measured
// through OSMesa (tests/gl-conformance/programs/quad_split.c). Mesa merges consecutive
// glBegin(GL_QUADS)/glEnd pairs into one draw; here each pair decides for itself.
bool inside_view_volume(const glm::mat4& projection, const glm::vec4& eye) {
  glm::vec4 v = transform(projection, eye);
  return -v.w <= v.x && v.x <= v.w && -v.w <= v.y && v.y <= v.w && -v.w <= v.z && v.z <= v.w;
}

// The fewest vertices of `mode` that draw something.
std::uint32_t min_vertices(GLenum mode) {
  return mode == GL_POINTS ? 1 : is_line_mode(mode) ? 2 : 3;
}

// The polygon primitive's triangles with their TriangleFlag bits, as Mesa's draw pipeline
// decomposes it when some face is drawn as lines or points: each polygon edge flagged unless
// the edge flag of its first vertex is off (GL 1.1 section 2.6.2: strips, fans and quad strips
// ignore edge flags).
void unfilled_triangles(GlContext& c, std::uint32_t count,
                        const std::vector<std::uint8_t>& finite) {
  Primitive& p = c.prim;
  ImmediateScratch& s = c.immediate_scratch;
  s.unfilled.clear();
  s.triangle_flags.clear();
  decompose_unfilled(p.mode, count, p.odd_strip_start, s.unfilled);
  const bool flagged = p.mode == GL_TRIANGLES || p.mode == GL_QUADS || p.mode == GL_POLYGON;
  for (const UnfilledTriangle& t : s.unfilled) {
    if (!finite[t.v[0]] || !finite[t.v[1]] || !finite[t.v[2]]) continue;  // NaN or infinite
    std::uint8_t flags = t.flags;
    for (int k = 0; k < 3 && flagged && !p.edges.empty(); ++k) {
      if (!p.edges[t.v[k]]) flags &= std::uint8_t(~(1u << k));  // kTriangleEdge01, 12, 20
    }
    s.triangles.push_back({t.v[0], t.v[1], t.v[2]});
    s.triangle_flags.push_back(flags);
  }
}

void line_segments(GlContext& c, std::uint32_t count, bool last_part,
                   const std::vector<std::uint8_t>& finite) {
  Primitive& p = c.prim;
  ImmediateScratch& s = c.immediate_scratch;
  s.line_pieces.clear();
  s.lines.clear();
  decompose_lines(p.mode, count, p.continued, last_part, s.line_pieces);
  for (const PrimitiveLine& l : s.line_pieces) {
    if (!finite[l.v[0]] || !finite[l.v[1]]) continue;
    s.lines.push_back({{l.v[0], l.v[1]}, l.restart ? LineSegment::kRestartStipple : 0u});
  }
}

// Draws the first `count` vertices of the primitive (`last_part`: the rest of it, at glEnd).
void draw_vertices(GlContext& c, std::uint32_t count, bool last_part) {
  Primitive& p = c.prim;
  const bool polygons = is_polygon_mode(p.mode);
  if (polygons && c.raster.cull && c.raster.cull_mode == GL_FRONT_AND_BACK)
    return;  // every polygon culled
  if (count < min_vertices(p.mode)) return;
  const glm::mat4& projection = c.projection.top();
  make_pipeline(c);
  // Per vertex: the draw's arrays, whether its clip coordinates are finite and, for quads,
  // whether it lies in the view volume. On the calling thread only: a vertex record another
  // core read here has to be taken back from that core's cache when the next glVertex call
  // writes it (the records are reused from primitive to primitive), and that cost the
  // recording more than sharing this loop saved (the teapot's 19,200 glVertex calls took
  // 0.4-0.65 ms on two threads against 0.26-0.30 ms on one; with this loop on the caller,
  // the same on both).
  Batch batch(c.immediate_scratch, count);
  std::vector<std::uint8_t>& finite = c.immediate_scratch.finite;
  finite.resize(count);
  const bool small_projection = bounded(&projection[0][0], 16);
  // GL_SELECT and GL_FEEDBACK: the pipeline reports the primitives (feedback.cpp) as Mesa's
  // draw module decomposes them, the polygons' path in line and point mode.
  const bool observe = c.render_mode != GL_RENDER;
  const bool unfilled = polygons && (c.prims.unfilled() || observe);
  const bool quads = p.mode == GL_QUADS && !unfilled;
  const bool normals = p.deferred_lighting && !p.object_normals, colors = !p.deferred_lighting;
  bool outside = false;
  for (std::uint32_t i = 0; i < count; ++i) {
    const PrimitiveVertex& v = p.vertices[i];
    batch.set(i, v, normals, colors ? &p.colors[i] : nullptr, p.textured ? &p.texcoords[i] : nullptr);
    if (p.object_normals) batch.s.normals[i] = eye_normal(c, v.normal);
    finite[i] = finite_clip(projection, small_projection, v.eye);
    if (quads && !outside) outside = !inside_view_volume(projection, v.eye);
  }
  bool flat = c.lighting.shade_model == GL_FLAT;
  VertexInput in;
  ImmediateScratch& s = c.immediate_scratch;
  if (p.mode == GL_POINTS) {
    s.points.clear();
    for (std::uint32_t i = 0; i < count; ++i) {
      if (finite[i]) s.points.push_back(i);
    }
    in.points = s.points;
  } else if (!polygons) {
    line_segments(c, count, last_part, finite);
    in.lines = s.lines;
  } else if (unfilled) {
    unfilled_triangles(c, count, finite);
    in.triangles = s.triangles;
    in.triangle_flags = s.triangle_flags;
  } else {
    std::vector<PrimitiveTriangle>& tris = s.pieces;
    tris.clear();
    const bool second = outside || p.in_list || p.from_elements;
    decompose(p.mode, count, p.odd_strip_start,
              second ? QuadSplit::kFromSecond : QuadSplit::kFromFirst, tris);
    for (const PrimitiveTriangle& t : tris) {
      if (!finite[t.v[0]] || !finite[t.v[1]] || !finite[t.v[2]]) continue;  // NaN or infinite
      batch.s.triangles.push_back(flat ? flat_triangle(t, p, batch)
                                       : Triangle{t.v[0], t.v[1], t.v[2]});
    }
    in.triangles = batch.s.triangles;
  }
  if (in.triangles.empty() && in.lines.empty() && in.points.empty()) return;

  ShadeState shade;
  shade.lighting = false;  // colours lit per vertex above, unless deferred below
  shade.shading = flat ? ShadingMode::kFlat : ShadingMode::kGouraud;
  texture_draw_state(c, shade);
  shade.fog = fog_state(c);
  const LightingState& l = c.lighting;
  bool lit = l.enabled && !p.deferred_lighting;  // colours lit per vertex above
  in.positions = batch.s.positions;
  if (p.deferred_lighting) {  // lit by the pipeline with the primitive's one material
    shade.lighting = true;
    shade.model = l.model;
    shade.lights = p.lights;
    shade.front = l.front;
    shade.back = l.back;
    in.normals = batch.s.normals;
  } else {
    in.colors = batch.s.colors;
  }
  if (lit && c.lighting.model.two_side) in.back_colors = batch.s.back_colors;
  if (lit && c.lighting.model.separate_specular) {
    in.secondary_colors = batch.s.secondary;
    if (c.lighting.model.two_side) in.back_secondary_colors = batch.s.back_secondary;
  }
  if (shade.texture || p.textured) in.texcoords = batch.s.texcoords;
  in.stipple_counter = &p.stipple_counter;
  if (observe) {
    FragmentState f = fragment_state(c);
    f.observer = &c.render_mode_observer;
    draw_triangles(c.fb, projection, c.raster.viewport, f, shade, in);
    return;
  }
  make_pipeline(c);
  draw_triangles(c.fb, projection, c.raster.viewport, fragment_state(c), shade, in, nullptr,
                 c.pipeline.get());
  if (c.pipeline) mark_drawn(c);
  else
    mark_batch(c, projection, batch.s.positions, prim_margin(c));
}

// Keeps the first element (with `first`) and the `last` last ones, in place.
template <class T>
void keep_ends(std::vector<T>& v, bool first, std::uint32_t last) {
  const std::size_t kept = (first ? 1 : 0) + std::size_t(last);
  if (v.size() <= kept) return;
  std::copy(v.end() - last, v.end(), v.begin() + (first ? 1 : 0));  // to the front, from behind it
  v.resize(kept);
}

// Draws what can be drawn of a long primitive and keeps the vertices it still needs.
void flush_part(GlContext& c) {
  Primitive& p = c.prim;
  PartialFlush f = partial_flush(p.mode, std::uint32_t(p.vertices.size()));
  if (f.drawable < min_vertices(p.mode)) return;
  draw_vertices(c, f.drawable, false);
  if (p.mode == GL_TRIANGLE_STRIP && ((f.drawable - 2) & 1u)) p.odd_strip_start = !p.odd_strip_start;
  p.continued = true;
  keep_ends(p.vertices, f.keep_first, f.keep_last);
  keep_ends(p.colors, f.keep_first, f.keep_last);
  keep_ends(p.texcoords, f.keep_first, f.keep_last);
  keep_ends(p.edges, f.keep_first, f.keep_last);
}

// Rotates a triangle so that its provoking vertex comes last (the core's flat convention);
// false when the provoking vertex is not one of its three.
bool provoking_last(const PrimitiveTriangle& t, Triangle& out) {
  const std::uint32_t* v = t.v;
  if (v[0] == t.provoking) out = {v[1], v[2], v[0]};
  else if (v[1] == t.provoking) out = {v[2], v[0], v[1]};
  else if (v[2] == t.provoking) out = {v[0], v[1], v[2]};
  else return false;
  return true;
}

}  // namespace

FragmentState rectangle_fragment_state(const GlContext& c) { return fragment_state(c); }

ShadeState rectangle_shade_state(GlContext& c) {
  ShadeState shade;
  shade.lighting = false;
  texture_draw_state(c, shade);
  return shade;
}

bool draw_array_mesh(GlContext& c, GLenum mode, bool per_vertex_color, bool from_elements, std::size_t count,
                     const std::uint32_t* direct, std::uint32_t lo, std::uint32_t hi,
                     const ElementLoader& load) {
  const LightingState& l = c.lighting;
  bool flat = l.shade_model == GL_FLAT;
  // Flat quads and polygons may be provoked by a vertex outside a triangle, and colour
  // material changes the material per vertex: those go vertex by vertex, as do the draws of
  // the selection and feedback modes.
  bool flat_ok = mode == GL_TRIANGLES || mode == GL_TRIANGLE_STRIP || mode == GL_TRIANGLE_FAN;
  if (!is_polygon_mode(mode) || c.prims.unfilled() || (flat && !flat_ok) || c.render_mode != GL_RENDER ||
      (l.enabled && l.color_material && per_vertex_color)) {
    return false;
  }
  ArrayScratch& m = c.array_scratch;
  begin_primitive(c, mode);  // fixes the transforms and lights as glBegin does
  Primitive& p = c.prim;
  p.active = false;
  // Every element from the smallest index used to the largest is a vertex (shared
  // vertices are transformed and lit once; unused ones in between cost a little).
  if (count == 0 || hi >= UINT32_MAX || hi - lo > 4 * count + 1024) return false;  // sparse: vertex by vertex
  std::size_t n = std::size_t(hi - lo) + 1;
  const Texture* texture = active_texture(c);
  // Object-space attributes of the range, then eye space in place.
  m.positions.resize(n);
  m.normals.resize(n);
  m.colors.resize(l.enabled ? 0 : n);  // lit: colours come from the lighting
  m.texcoords.resize(texture ? n : 0);
  m.raw_texcoords.resize(texture ? n : 0);
  m.finite.resize(n);
  const glm::mat4& projection = c.projection.top();
  make_pipeline(c);
  // Ranges of vertices on the pipeline's threads (the loader only reads the arrays).
  auto in_parallel = [&](std::size_t items, const auto& fn) {
    if (c.pipeline && items >= 8192) c.pipeline->parallel_for(items, 4096, fn);
    else fn(0, items);
  };
  std::atomic<bool> homogeneous{false}, nonfinite{false};
  const bool small_projection = bounded(&projection[0][0], 16);
  in_parallel(n, [&](std::size_t begin, std::size_t end) {
    load(lo + begin, end - begin, &m.positions[begin], &m.normals[begin], l.enabled ? nullptr : &m.colors[begin],
         texture ? &m.raw_texcoords[begin] : nullptr);
    for (std::size_t v = begin; v < end; ++v) {
      glm::vec4 eye = transform(p.modelview, m.positions[v]);
      if (eye.w != 1.0f) homogeneous = true;
      if (texture) m.raw_texcoords[v] = source_texcoord(c, m.raw_texcoords[v], m.positions[v], eye, m.normals[v]);
      m.positions[v] = eye;
      m.finite[v] = finite_clip(projection, small_projection, eye);
      if (!m.finite[v]) nonfinite = true;
      if (l.enabled) m.normals[v] = eye_normal(c, m.normals[v]);
      else m.colors[v] = glm::clamp(sanitize(m.colors[v]), glm::vec4(0.0f), glm::vec4(1.0f));
      if (texture) m.texcoords[v] = texcoord(c, m.raw_texcoords[v]);
    }
  });
  // The pipeline lights at xyz, glBegin/glEnd's path at xyz / w: vertices with w != 1 go
  // vertex by vertex (nothing is drawn yet).
  if (homogeneous && l.enabled) return false;
  if (!l.enabled) m.normals.clear();
  // Quads of a glDrawElements, or begun by a display list: along b-d, as llvmpipe
  // (docs/gl-conformance.md).
  QuadSplit split = from_elements || c.lists.depth > 0 ? QuadSplit::kFromSecond : QuadSplit::kFromFirst;
  if (mode == GL_QUADS) {
    for (std::size_t k = 0; k < count && split == QuadSplit::kFromFirst; ++k) {
      glm::vec4 v = projection * m.positions[m.sequence[k] - lo];
      bool inside = -v.w <= v.x && v.x <= v.w && -v.w <= v.y && v.y <= v.w && -v.w <= v.z && v.z <= v.w;
      if (!inside) split = QuadSplit::kFromSecond;
    }
  }
  m.triangles.clear();
  auto add = [&](Triangle tri) {  // NaN or infinite vertices drop their triangles
    if (m.finite[tri[0]] && m.finite[tri[1]] && m.finite[tri[2]]) m.triangles.push_back(tri);
  };
  const std::size_t tris = count / 3;
  // The caller's 32-bit indices are the triangles, read in place (all in the loaded range).
  const bool in_place = mode == GL_TRIANGLES && direct && lo == 0 && !nonfinite;
  if (mode == GL_TRIANGLES && !in_place) {  // no decomposition, the last vertex provokes
    // In parallel; triangles with a non-finite vertex are removed afterwards (rare).
    m.triangles.resize(tris);
    std::atomic<bool> dropped{false};
    auto index = [&](std::size_t k) { return direct ? direct[k] : m.sequence[k]; };
    in_parallel(tris, [&](std::size_t begin, std::size_t end) {
      bool drop = false;
      for (std::size_t t = begin; t < end; ++t) {
        Triangle tri{index(3 * t) - lo, index(3 * t + 1) - lo, index(3 * t + 2) - lo};
        m.triangles[t] = tri;
        drop = drop || !(m.finite[tri[0]] && m.finite[tri[1]] && m.finite[tri[2]]);
      }
      if (drop) dropped = true;
    });
    if (dropped) {
      std::erase_if(m.triangles, [&](const Triangle& tri) {
        return !(m.finite[tri[0]] && m.finite[tri[1]] && m.finite[tri[2]]);
      });
    }
  } else if (mode != GL_TRIANGLES) {
    m.pieces.clear();
    decompose(mode, std::uint32_t(count), false, split, m.pieces);
    for (const PrimitiveTriangle& t : m.pieces) {
      PrimitiveTriangle u = t;
      for (std::uint32_t& v : u.v) v = m.sequence[v] - lo;
      u.provoking = m.sequence[t.provoking] - lo;
      Triangle tri{u.v[0], u.v[1], u.v[2]};
      if (flat && !provoking_last(u, tri)) continue;  // not reached: flat_ok above
      add(tri);
    }
  }
  const std::span<const Triangle> triangles =
      in_place ? std::span<const Triangle>(reinterpret_cast<const Triangle*>(direct), tris) : std::span<const Triangle>(m.triangles);
  if (triangles.empty() || (c.raster.cull && c.raster.cull_mode == GL_FRONT_AND_BACK)) return true;

  ShadeState shade;
  shade.lighting = l.enabled;  // lit by the pipeline, once per distinct vertex
  shade.shading = flat ? ShadingMode::kFlat : ShadingMode::kGouraud;
  shade.model = l.model;
  shade.lights = p.lights;
  shade.front = l.front;
  shade.back = l.back;
  texture_draw_state(c, shade);
  shade.fog = fog_state(c);
  VertexInput in;
  in.positions = m.positions;
  in.normals = m.normals;
  in.colors = m.colors;
  in.texcoords = m.texcoords;
  in.triangles = triangles;
  draw_triangles(c.fb, projection, c.raster.viewport, fragment_state(c), shade, in, nullptr,
                 c.pipeline.get());
  // Without the pipeline's tiles, the whole viewport is marked, not the bounds of every vertex.
  const Viewport& vp = c.raster.viewport;
  if (c.pipeline) mark_drawn(c);
  else mark_dirty(c, vp.x, vp.y, vp.x + vp.width, vp.y + vp.height);
  return true;
}

void begin_primitive(GlContext& c, GLenum mode) {
  Primitive& p = c.prim;
  p.active = true;
  p.mode = mode;
  p.vertices.clear();
  p.colors.clear();
  p.texcoords.clear();
  p.odd_strip_start = false;
  p.in_list = c.lists.depth > 0;
  p.from_elements = false;
  p.continued = false;
  p.stipple_counter = 0;
  p.edge_flags = is_polygon_mode(mode) && c.prims.unfilled();
  p.edges.clear();
  p.modelview = c.modelview.top();
  glm::mat3 inv = glm::inverse(glm::mat3(p.modelview));
  p.normal_matrix = glm::transpose(inv);
  p.rescale = 1.0f / std::sqrt(inv[0][2] * inv[0][2] + inv[1][2] * inv[1][2] + inv[2][2] * inv[2][2]);
  p.texture_matrix = c.texture_matrix.top();
  p.identity_texture_matrix = p.texture_matrix == glm::mat4(1.0f);
  p.lights.clear();
  if (c.lighting.enabled) {
    for (const Light& l : c.lighting.lights) {
      if (l.enabled) p.lights.push_back(l);
    }
  }
  // Flat quads take a colour from outside their first triangle: those are lit here.
  p.deferred_lighting = c.lighting.enabled && !(c.lighting.shade_model == GL_FLAT && mode == GL_QUADS);
  // (Flat shading may copy a vertex while drawing: its normals are transformed here.)
  p.object_normals = p.deferred_lighting && c.lighting.shade_model != GL_FLAT;
  // Feedback reports texture coordinates whether or not a texture applies (as Mesa's).
  p.textured = active_texture(c) != nullptr || c.render_mode == GL_FEEDBACK;
}

void settle_lighting(GlContext& c) {
  Primitive& p = c.prim;
  if (!p.deferred_lighting) return;
  p.colors.resize(p.vertices.size());
  for (std::size_t i = 0; i < p.vertices.size(); ++i) {
    PrimitiveVertex& v = p.vertices[i];
    if (p.object_normals) v.normal = eye_normal(c, v.normal);
    light_vertex(c, v, p.colors[i]);
  }
  p.deferred_lighting = false;
  p.object_normals = false;
}

void emit_vertex(GlContext& c, const glm::vec4& object_position) {
  Primitive& p = c.prim;
  const glm::vec4 eye = transform(p.modelview, object_position);
  // The pipeline lights at xyz, this path at xyz / w: a vertex with w != 1 ends the deferral.
  if (p.deferred_lighting && eye.w != 1.0f) settle_lighting(c);
  // Made in place: a vertex built on the stack and copied in was read back in wider pieces
  // than it was written, a store-forwarding stall per vertex (half of this function's time).
  PrimitiveVertex& v = p.vertices.emplace_back();
  v.eye = eye;
  if (p.textured) {
    p.texcoords.push_back(texcoord(c, source_texcoord(c, c.current.texcoord, object_position, eye, c.current.normal)));
  }
  if (c.lighting.enabled) v.normal = p.object_normals ? c.current.normal : eye_normal(c, c.current.normal);
  if (!p.deferred_lighting) light_vertex(c, v, p.colors.emplace_back());
  if (p.edge_flags) p.edges.push_back(c.current.edge_flag != 0.0f);
  if (p.vertices.size() >= kFlushVertices) flush_part(c);
}

void end_primitive(GlContext& c) {
  Primitive& p = c.prim;
  if (p.vertices.size() >= min_vertices(p.mode))
    draw_vertices(c, std::uint32_t(p.vertices.size()), true);
  p.vertices.clear();
  p.colors.clear();
  p.texcoords.clear();
  p.active = false;
}

}  // namespace shadelab::gl
