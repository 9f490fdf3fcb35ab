// The glBegin/glEnd path (GL 1.1 sections 2.6-2.7, 2.13): each vertex transformed to eye space
// with its normal (inverse transpose, GL_RESCALE_NORMAL, GL_NORMALIZE) and lit as it arrives by
// the core's light_point (or, while the material stays what it was at glBegin, by the pipeline
// at the draw), then the primitive's triangles, lines or points with their colours to
// draw_triangles, in parts for long primitives. Fragment work (clipping, rasterization,
// texturing, blending) is the core pipeline's.
#include "gl/src/draw.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "gl/src/capture.hpp"
#include "gl/src/convert.hpp"
#include "gl/src/draw_state.hpp"
#include "gl/src/primitive.hpp"
#include "gl/src/texture.hpp"
#include "gl/src/vertex_ops.hpp"
#include "shadelab/lighting.hpp"

namespace shadelab::gl {
namespace {

// A vertex's colours: lit by the core's light_point (src/lighting, the one lighting function;
// this file keeps no copy of the equation) with the front material and, for two-sided
// lighting, the back one at the negated normal; unlit, the current colour clamped.
void light_vertex(const GlContext& c, const PrimitiveVertex& v, VertexColors& out) {
  const LightingState& l = c.lighting;
  if (!l.enabled) {
    // Colours are clamped to [0, 1] per vertex (GL 1.1 section 2.13.6), before interpolation.
    glm::vec4 col = glm::clamp(sanitize(c.current.color), glm::vec4(0.0f), glm::vec4(1.0f));
    out.front = out.back = col;
    // The secondary colour (GL 1.4 section 2.7), clamped alike; added when GL_COLOR_SUM is on.
    const glm::vec3 sec = glm::clamp(sanitize(glm::vec3(c.current.secondary)), glm::vec3(0.0f), glm::vec3(1.0f));
    out.front_secondary = out.back_secondary = sec;
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

// Arrays for one draw_triangles call, in the context's reused buffers: one entry per vertex
// of the primitive (set), then any vertex a flat quad adds (add).
struct Batch {
  ImmediateScratch& s;

  Batch(ImmediateScratch& scratch, std::size_t vertices) : s(scratch) {
    for (auto* v : {&s.positions, &s.colors, &s.back_colors}) v->resize(vertices);
    for (auto* v : {&s.normals, &s.secondary, &s.back_secondary}) v->resize(vertices);
    for (auto& t : s.texcoords) t.resize(vertices);
    s.fog.resize(vertices);
    s.triangles.clear();
  }

  // Only what the draw reads: normals when the pipeline lights, colours when lit here (or
  // unlit), the texture coordinates of the units in `textured`.
  void set(std::size_t i, const PrimitiveVertex& v, bool normals, const VertexColors* colors, const Primitive& p,
           const float* fog) {
    s.positions[i] = v.eye;
    if (normals) s.normals[i] = v.normal;
    if (colors) {
      s.colors[i] = colors->front;
      s.back_colors[i] = colors->back;
      s.secondary[i] = colors->front_secondary;
      s.back_secondary[i] = colors->back_secondary;
    }
    for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {
      if (p.textured >> u & 1u) s.texcoords[u][i] = p.texcoords[u][i];
    }
    if (fog) s.fog[i] = *fog;
  }

  // Vertex `i` of `p` again, with `colors`.
  std::uint32_t add(const Primitive& p, std::uint32_t i, const VertexColors& colors, float fog) {
    const PrimitiveVertex& v = p.vertices[i];
    s.positions.push_back(v.eye);
    s.normals.push_back(v.normal);
    s.colors.push_back(colors.front);
    s.back_colors.push_back(colors.back);
    s.secondary.push_back(colors.front_secondary);
    s.back_secondary.push_back(colors.back_secondary);
    for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {
      s.texcoords[u].push_back(p.texcoords[u].empty() ? glm::vec4(0, 0, 0, 1) : p.texcoords[u][i]);
    }
    s.fog.push_back(fog);
    return std::uint32_t(s.positions.size() - 1);
  }
};

// A triangle whose last vertex provokes it: rotated when the provoking vertex is one of its
// three (rotation keeps the winding), else its last vertex is repeated with the provoking
// vertex's colours (a quad's first triangle; the primitive's colours, none while lighting is
// deferred).
Triangle flat_triangle(const PrimitiveTriangle& t, const Primitive& prim, Batch& batch) {
  Triangle rotated;
  if (provoking_last(t, rotated)) return rotated;
  const std::uint32_t* v = t.v;
  const VertexColors colors = prim.colors.empty() ? VertexColors{} : prim.colors[t.provoking];
  const float fog = prim.fog_coords.empty() ? 0.0f : prim.fog_coords[v[2]];  // never flat
  if (!batch.s.capture_materials.empty()) batch.s.capture_materials.push_back(prim.capture_materials[t.provoking]);
  return {v[0], v[1], batch.add(prim, v[2], colors, fog)};
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
  // An attenuated point may be as large as GL_POINT_SIZE_MAX allows (GL 1.4 section 3.3).
  const bool attenuated = p.point_attenuation != glm::vec3(1.0f, 0.0f, 0.0f);
  const float point = attenuated ? std::max(p.point_size, p.point_max) : p.point_size;
  const float widest = std::max(raster_size(point, 0.0f, kMaxPointSize),
                                raster_size(p.line_width, 1.0f, kMaxLineWidth));
  return 2 + int(std::ceil(widest / 2.0f));
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
  // A captured frame keeps the normals and materials of vertices lit here (capture.hpp).
  const bool capture_lit = p.capture_lit && !p.deferred_lighting && !observe;
  std::vector<VertexMaterials>& capture_materials = c.immediate_scratch.capture_materials;
  capture_materials.clear();
  if (capture_lit) capture_materials.assign(p.capture_materials.begin(), p.capture_materials.begin() + count);
  bool outside = false;
  for (std::uint32_t i = 0; i < count; ++i) {
    const PrimitiveVertex& v = p.vertices[i];
    batch.set(i, v, normals || capture_lit, colors ? &p.colors[i] : nullptr, p, p.fog_coordinates ? &p.fog_coords[i] : nullptr);
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
  // GL 1.4 section 3.9: unlit, the colour sum adds the vertices' secondary colours.
  if (!l.enabled && c.fog.color_sum) in.secondary_colors = batch.s.secondary;
  for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {
    if (p.textured >> u & 1u) in.texcoords[u] = batch.s.texcoords[u];
  }
  if (p.fog_coordinates) in.fog_coords = batch.s.fog;
  in.stipple_counter = &p.stipple_counter;
  if (observe) {
    FragmentState f = fragment_state(c);
    f.observer = &c.render_mode_observer;
    draw_triangles(c.fb, projection, c.raster.viewport, f, shade, in);
    return;
  }
  if (c.capture) {
    VertexInput captured = in;
    if (capture_lit) captured.normals = batch.s.normals;
    capture_draw(c, shade, captured, l.enabled, capture_materials);
  }
  make_pipeline(c);
  const auto stipple_counter = p.stipple_counter;  // each buffer's lines start the pattern alike
  for_each_draw_buffer(c, [&](bool first) {
    if (!first) p.stipple_counter = stipple_counter;
    draw_triangles(c.fb, sample_projection(c, projection), c.raster.viewport, fragment_state(c), shade, in,
                   pass_counts(c, first), c.pipeline.get());
    if (c.pipeline) mark_drawn(c);
    else mark_batch(c, projection, batch.s.positions, prim_margin(c));
  });
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
  for (std::vector<glm::vec4>& t : p.texcoords) keep_ends(t, f.keep_first, f.keep_last);
  keep_ends(p.fog_coords, f.keep_first, f.keep_last);
  keep_ends(p.edges, f.keep_first, f.keep_last);
  keep_ends(p.capture_materials, f.keep_first, f.keep_last);
}

}  // namespace

void begin_primitive(GlContext& c, GLenum mode) {
  Primitive& p = c.prim;
  p.active = true;
  p.mode = mode;
  p.vertices.clear();
  p.colors.clear();
  for (std::vector<glm::vec4>& t : p.texcoords) t.clear();
  p.fog_coords.clear();
  p.fog_coordinates = c.fog.by_coordinates();
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
  for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {
    p.texture_matrix[u] = c.texture_matrices[u].top();
    // A rectangle texture's texel coordinates, normalized for the pipeline (feedback reports
    // them as they are).
    const glm::vec2 scale = c.render_mode == GL_RENDER ? rectangle_scale(c, u) : glm::vec2(1.0f);
    if (scale != glm::vec2(1.0f)) p.texture_matrix[u] = glm::mat4(glm::vec4(scale.x, 0, 0, 0), glm::vec4(0, scale.y, 0, 0),
                                                                  glm::vec4(0, 0, 1, 0), glm::vec4(0, 0, 0, 1)) * p.texture_matrix[u];
    p.identity_texture_matrix[u] = p.texture_matrix[u] == glm::mat4(1.0f);
  }
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
  p.textured = textured_units(c);
  p.capture_lit = c.lighting.enabled && capture_recording(c);
  p.capture_materials.clear();
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
  for (std::size_t u = 0; p.textured >> u; ++u) {
    if (!(p.textured >> u & 1u)) continue;
    p.texcoords[u].push_back(
        texcoord(c, u, source_texcoord(c, u, c.current.texcoords[u], object_position, eye, c.current.normal)));
  }
  // Mesa's fixed-function vertex program passes the fog coordinate's absolute value on.
  if (p.fog_coordinates) p.fog_coords.push_back(std::fabs(c.current.fog_coord));
  if (c.lighting.enabled) v.normal = p.object_normals ? c.current.normal : eye_normal(c, c.current.normal);
  if (!p.deferred_lighting) light_vertex(c, v, p.colors.emplace_back());
  if (p.capture_lit) p.capture_materials.push_back({c.lighting.front, c.lighting.back});
  if (p.edge_flags) p.edges.push_back(c.current.edge_flag != 0.0f);
  if (p.vertices.size() >= kFlushVertices) flush_part(c);
}

void end_primitive(GlContext& c) {
  Primitive& p = c.prim;
  if (p.vertices.size() >= min_vertices(p.mode))
    draw_vertices(c, std::uint32_t(p.vertices.size()), true);
  p.vertices.clear();
  p.colors.clear();
  for (std::vector<glm::vec4>& t : p.texcoords) t.clear();
  p.fog_coords.clear();
  p.capture_materials.clear();
  p.active = false;
}

}  // namespace shadelab::gl
