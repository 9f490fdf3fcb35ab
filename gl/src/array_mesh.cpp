// The vertex-array path (GL 1.1 section 2.8): a glDrawArrays or glDrawElements, or a display
// list's compiled mesh, drawn in one go when the material is the same at every vertex. Each
// element of the draw's index range is loaded and transformed once (on the pipeline's threads
// for large draws) and the pipeline lights it with the core's light_point or its batched form;
// the triangles go to draw_triangles. A draw that must go vertex by vertex is left to draw.cpp's
// glBegin/glEnd path (draw_array_mesh returns false); nothing here lights, rasterizes or shades.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <span>
#include <vector>

#include "gl/src/capture.hpp"
#include "gl/src/draw.hpp"
#include "gl/src/draw_state.hpp"
#include "gl/src/primitive.hpp"
#include "gl/src/texture.hpp"
#include "gl/src/vertex_ops.hpp"

namespace shadelab::gl {

bool draw_array_mesh(GlContext& c, GLenum mode, bool per_vertex_color, bool from_elements, std::size_t count,
                     const std::uint32_t* direct, std::uint32_t lo, std::uint32_t hi,
                     const ElementLoader& load, const ExtraLoader* extra) {
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
  // The texture units that apply a texture (GL 1.3): their coordinates are loaded.
  const unsigned textured = p.textured;
  auto has = [&](std::size_t u) { return (textured >> u & 1u) != 0; };
  // Object-space attributes of the range, then eye space in place.
  m.positions.resize(n);
  m.normals.resize(n);
  m.colors.resize(l.enabled ? 0 : n);  // lit: colours come from the lighting
  for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {
    m.texcoords[u].resize(has(u) ? n : 0);
    m.raw_texcoords[u].resize(has(u) ? n : 0);
  }
  bool other_units = false;  // units past 0 (the ExtraLoader's)
  for (std::size_t u = 1; u < kMaxTextureUnits; ++u) other_units = other_units || has(u);
  m.finite.resize(n);
  // GL 1.4: the secondary colours the colour sum adds to unlit colours (GL_COLOR_SUM).
  const bool sum = !l.enabled && c.fog.color_sum;
  m.secondary.resize(sum ? n : 0);
  // ... and the fog coordinates fog uses instead of the eye distance (GL_FOG_COORDINATE).
  const bool fog_coords = c.fog.by_coordinates();
  m.fog.resize(fog_coords ? n : 0);
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
         has(0) ? &m.raw_texcoords[0][begin] : nullptr);
    if (sum || fog_coords || other_units) {
      ExtraOutputs out{sum ? &m.secondary[begin] : nullptr, fog_coords ? &m.fog[begin] : nullptr};
      for (std::size_t u = 1; u < kMaxTextureUnits; ++u) out.texcoords[u] = has(u) ? &m.raw_texcoords[u][begin] : nullptr;
      if (extra) (*extra)(lo + begin, end - begin, out);
      if (!extra && sum) std::fill_n(out.secondary, end - begin, glm::vec3(c.current.secondary));
      if (!extra && fog_coords) std::fill_n(out.fog, end - begin, c.current.fog_coord);
      for (std::size_t u = 1; !extra && u < kMaxTextureUnits; ++u) {
        if (out.texcoords[u]) std::fill_n(out.texcoords[u], end - begin, c.current.texcoords[u]);
      }
    }
    for (std::size_t v = begin; v < end; ++v) {
      glm::vec4 eye = transform(p.modelview, m.positions[v]);
      if (eye.w != 1.0f) homogeneous = true;
      for (std::size_t u = 0; textured >> u; ++u) {
        if (has(u)) m.raw_texcoords[u][v] = source_texcoord(c, u, m.raw_texcoords[u][v], m.positions[v], eye, m.normals[v]);
      }
      m.positions[v] = eye;
      m.finite[v] = finite_clip(projection, small_projection, eye);
      if (!m.finite[v]) nonfinite = true;
      if (l.enabled) m.normals[v] = eye_normal(c, m.normals[v]);
      else m.colors[v] = glm::clamp(sanitize(m.colors[v]), glm::vec4(0.0f), glm::vec4(1.0f));
      if (sum) m.secondary[v] = glm::clamp(sanitize(m.secondary[v]), glm::vec3(0.0f), glm::vec3(1.0f));
      // Mesa's fixed-function vertex program passes the coordinate's absolute value on.
      if (fog_coords) m.fog[v] = std::fabs(m.fog[v]);
      for (std::size_t u = 0; textured >> u; ++u) {
        if (has(u)) m.texcoords[u][v] = texcoord(c, u, m.raw_texcoords[u][v]);
      }
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
  for (std::size_t u = 0; u < kMaxTextureUnits; ++u) in.texcoords[u] = m.texcoords[u];
  in.secondary_colors = m.secondary;
  in.fog_coords = m.fog;
  in.triangles = triangles;
  capture_draw(c, shade, in, l.enabled, {});
  for_each_draw_buffer(c, [&](bool first) {
    draw_triangles(c.fb, sample_projection(c, projection), c.raster.viewport, fragment_state(c), shade, in,
                   pass_counts(c, first), c.pipeline.get());
    // Without the pipeline's tiles, the whole viewport is marked, not the bounds of every vertex.
    const Viewport& vp = c.raster.viewport;
    if (c.pipeline) mark_drawn(c);
    else mark_dirty(c, vp.x, vp.y, vp.x + vp.width, vp.y + vp.height);
  });
  return true;
}

}  // namespace shadelab::gl
