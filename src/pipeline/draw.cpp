// draw_triangles: the vertex stage (transform, per-vertex lighting, fog coordinate),
// clipping, facing and culling, then the reference rasterizer with per-pixel shading, fog
// and the fragment operations in GL's order (GL 1.1 chapters 3.5-4.1); lines, points and
// unfilled polygons: draw_prims.cpp.
#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>

#include "fast/draw_fast.hpp"
#include "pipeline/fragment_ops.hpp"
#include "pipeline/reference_draw.hpp"
#include "pipeline/stages.hpp"
#include "raster/prims.hpp"
#include "shadelab/lighting.hpp"

namespace shadelab {

using namespace detail;

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

void put(Attribs& a, int slot, const glm::vec4& v) {
  for (int i = 0; i < 4; ++i) a[slot + i] = v[i];
}
void put(Attribs& a, int slot, const glm::vec3& v) {
  for (int i = 0; i < 3; ++i) a[slot + i] = v[i];
}
glm::vec4 get4(const Attribs& a, int slot) {
  return {a[slot], a[slot + 1], a[slot + 2], a[slot + 3]};
}
glm::vec3 get3(const Attribs& a, int slot) { return {a[slot], a[slot + 1], a[slot + 2]}; }

// How much of each light reaches eye-space point p (empty when no light has a shadow map).
std::vector<float> shadow_visibility(const ShadeState& shade, const glm::vec3& p, const glm::vec3& n) {
  std::vector<float> v;
  if (shade.shadow_maps.empty()) return v;
  v.resize(shade.lights.size(), 1.0f);
  for (std::size_t i = 0; i < v.size() && i < shade.shadow_maps.size(); ++i) {
    v[i] = shade.shadow_maps[i].visibility(p, n);
  }
  return v;
}

// Colours of one vertex: lit (flat and Gouraud) or given (lighting off). Back slots hold the
// back-face colours, equal to the front ones when there are none.
void vertex_colors(const ShadeState& shade, const VertexInput& in, std::size_t i,
                   Attribs& a, RenderStats& stats) {
  glm::vec3 pos(in.positions[i]);
  glm::vec3 n = in.normals.empty() ? glm::vec3(0, 0, 1) : in.normals[i];
  if (shade.lighting && shade.shading != ShadingMode::kPhong) {
    std::vector<float> visible = shadow_visibility(shade, pos, n);
    const float* vis = visible.empty() ? nullptr : visible.data();
    LitColor f = light_point(shade.model, shade.lights, shade.front, {pos, n, vis});
    LitColor b = shade.model.two_side ? light_point(shade.model, shade.lights, shade.back, {pos, -n, vis}) : f;
    put(a, kFrontColor, f.primary);
    put(a, kFrontSecondary, f.secondary);
    put(a, kBackColor, b.primary);
    put(a, kBackSecondary, b.secondary);
    stats.vertices_lit += shade.model.two_side ? 2 : 1;
    return;
  }
  glm::vec4 c = in.colors.empty() ? in.constant_color : in.colors[i];
  put(a, kFrontColor, c);
  put(a, kBackColor, in.back_colors.empty() ? c : in.back_colors[i]);
  glm::vec3 s = in.secondary_colors.empty() ? glm::vec3(0.0f) : in.secondary_colors[i];
  put(a, kFrontSecondary, s);
  put(a, kBackSecondary, in.back_secondary_colors.empty() ? s : in.back_secondary_colors[i]);
}

std::vector<ClipVertex> vertex_stage(const glm::mat4& projection, const ShadeState& shade,
                                     const VertexInput& in, RenderStats& stats) {
  std::vector<ClipVertex> out(in.positions.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    ClipVertex& v = out[i];
    v.attr.fill(0.0f);
    v.clip = projection * in.positions[i];
    vertex_colors(shade, in, i, v.attr, stats);
    // Eye-space position for lighting is the dehomogenized point (GL uses x/w, y/w, z/w).
    glm::vec4 p = in.positions[i];
    put(v.attr, kEyePosition, p.w != 0.0f ? glm::vec3(p) / p.w : glm::vec3(p));
    if (!in.normals.empty()) put(v.attr, kEyeNormal, in.normals[i]);
    for (int u = 0; u < kMaxTextureUnits; ++u) {
      const std::span<const glm::vec4> t = in.texcoords[std::size_t(u)];
      put(v.attr, kTexCoord + 4 * u, t.empty() ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : t[i]);
    }
    v.attr[kFogCoord] = fog_coordinate(in, i);
  }
  return out;
}


// Twice the signed window-space area of a polygon (positive: counter-clockwise).
double signed_area(const std::vector<WindowVertex>& w) {
  double a = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const WindowVertex& p = w[i];
    const WindowVertex& q = w[(i + 1) % w.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return a;
}

}  // namespace

// Viewport mapping (GL 1.1 section 2.10.1) of a clipped vertex, in double for x and y.
WindowVertex detail::to_window(const ClipVertex& v, const Viewport& vp) {
  float inv_w = 1.0f / v.clip.w;
  double nx = double(v.clip.x) * inv_w, ny = double(v.clip.y) * inv_w;
  float nz = v.clip.z * inv_w;
  WindowVertex w;
  w.x = (nx + 1.0) * 0.5 * vp.width + vp.x;
  w.y = (ny + 1.0) * 0.5 * vp.height + vp.y;
  w.z = nz * 0.5f * (vp.far_depth - vp.near_depth) + 0.5f * (vp.far_depth + vp.near_depth);
  w.inv_w = inv_w;
  w.attr = &v.attr;
  return w;
}

// glPolygonOffset: factor * max depth slope + units * r (GL 1.5 section 3.5.5), r two steps of
// a 24-bit depth buffer as llvmpipe takes it (2 / (2^24 - 1), its draw module's and its
// triangle setup's: piglit's gl-1.4-polygon-offset measures it), in float as they round it.
float detail::polygon_offset(const WindowVertex& a, const WindowVertex& b,
                             const WindowVertex& c, const FragmentState& f) {
  double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  double m = 0.0;
  if (det != 0.0) {
    double dzdx = ((b.z - a.z) * (c.y - a.y) - (c.z - a.z) * (b.y - a.y)) / det;
    double dzdy = ((c.z - a.z) * (b.x - a.x) - (b.z - a.z) * (c.x - a.x)) / det;
    m = std::max(std::abs(dzdx), std::abs(dzdy));
  }
  const float units = float(double(f.offset_units) * (1.0 / double((1 << 24) - 1)) * 2.0);
  return static_cast<float>(f.offset_factor * m + double(units));
}

float detail::fog_coordinate(const VertexInput& in, std::size_t i) {
  return in.fog_coords.empty() ? std::fabs(in.positions[i].z) : in.fog_coords[i];
}

// The colour of one fragment, lit per pixel for Phong, else interpolated or flat; then
// textured, then the secondary colour added, then fogged.
glm::vec4 detail::shade_fragment(const ShadeState& shade, const Fragment& f, bool front) {
  const Attribs& a = f.attr;
  LitColor lit;
  if (shade.lighting && shade.shading == ShadingMode::kPhong) {
    glm::vec3 n = get3(a, kEyeNormal);
    float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0, 0, 1);
    bool back = !front && shade.model.two_side;
    glm::vec3 p = get3(a, kEyePosition), side_n = back ? -n : n;
    std::vector<float> visible = shadow_visibility(shade, p, front ? n : -n);
    lit = light_point(shade.model, shade.lights, back ? shade.back : shade.front,
                      {p, side_n, visible.empty() ? nullptr : visible.data()});
  } else {
    lit.primary = get4(a, front ? kFrontColor : kBackColor);
    lit.secondary = get3(a, front ? kFrontSecondary : kBackSecondary);
  }
  glm::vec4 color = lit.primary;
  // Every unit's texel first (a GL_COMBINE environment may read another unit's: GL 1.4's
  // crossbar; zero where a unit has no texture).
  std::array<glm::vec4, kMaxTextureUnits> texels{};
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    const TextureUnit& unit = shade.textures[std::size_t(u)];
    if (!unit.texture) continue;
    const Texture& t = *unit.texture;
    // GL 1.1 section 3.8: s / q, t / q (and r / q) per fragment (projective texture
    // coordinates).
    const int k = kTexCoord + 4 * u;
    const float q = a[std::size_t(k + 3)];
    const glm::vec3 str(finite_texcoord(a[std::size_t(k)] / q), finite_texcoord(a[std::size_t(k + 1)] / q),
                        finite_texcoord(a[std::size_t(k + 2)] / q));
    texels[std::size_t(u)] = sample_texture(t, str, texture_rho2(t, f.texture_derivatives[std::size_t(u)]), unit.lod_bias);
  }
  // GL 1.3 section 3.8.13: the units in order, each combining its texel with the colour the
  // unit before it gave (a unit without a texture passes it on).
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    const TextureUnit& unit = shade.textures[std::size_t(u)];
    if (!unit.texture) continue;
    if (unit.env == TextureEnvMode::kCombine) {
      color = apply_texture_combine(unit.combine, {texels.data(), u, unit.env_color, lit.primary, color});
    } else {
      color = apply_texture_env(unit.env, unit.texture->format, color, texels[std::size_t(u)], unit.env_color);
    }
  }
  // Colour sum (GL 1.4 section 3.9): the secondary colour is added after texturing, unclamped
  // (Mesa's fixed-function fragment program adds it without saturating).
  color = glm::vec4(glm::vec3(color) + lit.secondary, color.a);
  if (shade.fog.enabled) color = apply_fog(fog_params(shade.fog), a[kFogCoord], color);
  return color;
}

void detail::reference_fragment(const ReferenceDraw& ctx, const Fragment& f, bool front, float offset,
                                const Coverage* coverage, bool polygon) {
  Framebuffer& fb = *ctx.fb;
  const FragmentState& fs = *ctx.fragment;
  if (!pixel_kept(fs, f.x, f.y, polygon)) return;  // polygon stipple, scissor
  float factor = 1.0f;
  if (coverage) {  // smooth lines and points: a discarded fragment touches nothing
    factor = coverage_at(*coverage, f.x + 0.5, f.y + 0.5);
    if (factor < 0.0f) return;
  }
  std::size_t px = std::size_t(f.y) * fb.width + f.x;
  ++ctx.stats->fragments;
  float z = f.z + offset;
  z = z > 0.0f ? (z < 1.0f ? z : 1.0f) : 0.0f;  // clamped, NaN to 0 (as the fast path)
  // The alpha test needs the colour before the depth and stencil tests (GL 1.1 4.1.3);
  // without it, fragments failing those are not shaded (the same pixels either way). A
  // smooth line's or point's coverage is part of the colour's alpha (Mesa multiplies it in
  // at the end of the fragment program).
  glm::vec4 color;
  if (fs.alpha_test.enabled) {
    color = shade_fragment(*ctx.shade, f, front);
    color.a *= factor;
    if (!alpha_test(fs.alpha_test, color.a)) return;
  }
  if (!depth_stencil_test(fb, px, z, fs)) return;
  if (!fs.alpha_test.enabled) {
    color = shade_fragment(*ctx.shade, f, front);
    color.a *= factor;
  }
  if (FragmentCapture* cap = fs.capture) {
    if (cap->count >= cap->limit) {
      ++cap->dropped;
      return;
    }
    cap->pixels[px].push_back({z, color, fs.blend});
    ++cap->count;
    ++ctx.stats->pixels_shaded;
    return;
  }
  write_color(fb, px, color, fs);
  ++ctx.stats->pixels_shaded;
}

namespace {

void draw_polygon(const ReferenceDraw& ctx, std::vector<ClipVertex>& poly,
                  const ClipVertex* provoking, std::vector<WindowVertex>& win) {
  win.clear();
  for (const ClipVertex& v : poly) win.push_back(to_window(v, *ctx.viewport));
  double area = signed_area(win);
  if (area == 0.0 || !std::isfinite(area)) {
    ++ctx.stats->triangles_culled;
    return;
  }
  bool front = (area > 0.0) == ctx.fragment->front_ccw;
  CullMode cull = ctx.fragment->cull;
  if ((cull == CullMode::kBack && !front) || (cull == CullMode::kFront && front)) {
    ++ctx.stats->triangles_culled;
    return;
  }
  // Flat shading: every fragment takes the provoking vertex's colours (GL 1.5 section 2.14.7).
  if (provoking) {
    for (ClipVertex& v : poly) {
      for (int i = kFrontColor; i < kEyePosition; ++i) v.attr[i] = provoking->attr[i];
    }
  }
  ++ctx.stats->triangles_rasterized;
  Framebuffer& fb = *ctx.fb;
  for (std::size_t i = 1; i + 1 < win.size(); ++i) {
    const WindowVertex &a = win[0], &b = win[i], &c = win[i + 1];
    float offset = ctx.fragment->polygon_offset ? polygon_offset(a, b, c, *ctx.fragment) : 0.0f;
    rasterize_triangle(a, b, c, fb.width, fb.height, textured_units(*ctx.shade),
                       [&](const Fragment& f) { reference_fragment(ctx, f, front, offset, nullptr, true); });
  }
}

}  // namespace

void draw_triangles(Framebuffer& fb, const glm::mat4& projection, const Viewport& viewport,
                    const FragmentState& fragment, const ShadeState& shade,
                    const VertexInput& in, RenderStats* stats_out, PipelineContext* fast) {
  if (fast && !fragment.observer) return detail::draw_triangles_fast(*fast, fb, projection, viewport, fragment, shade, in, stats_out);
  RenderStats local;
  RenderStats& stats = stats_out ? *stats_out : local;
  auto t0 = Clock::now();
  std::vector<ClipVertex> verts = vertex_stage(projection, shade, in, stats);
  stats.ms_vertex += ms_since(t0);

  auto t1 = Clock::now();
  // An incomplete texture is as if texturing were off (GL 1.1 section 3.8.9).
  ShadeState effective = shade;
  effective.drop_incomplete_textures();
  ReferenceDraw ctx{&fb, &fragment, &effective, &viewport, &stats};
  bool flat = shade.shading == ShadingMode::kFlat;
  std::array<glm::vec4, ClipPlanes::kCount> planes;
  const std::span<const glm::vec4> user(planes.data(), std::size_t(clip_space_planes(fragment.clip, projection, planes)));
  std::vector<ClipVertex> poly, scratch;
  std::vector<WindowVertex> win;
  // Observed draws take Mesa's draw module's path for every polygon (prims.cpp).
  const bool filled = !PrimAssembler::unfilled(fragment) && !fragment.observer;
  for (const Triangle& t : filled ? in.triangles : std::span<const Triangle>{}) {
    ++stats.triangles_in;
    if (t[0] >= verts.size() || t[1] >= verts.size() || t[2] >= verts.size()) continue;
    poly.assign({verts[t[0]], verts[t[1]], verts[t[2]]});
    if (clip_polygon(poly, scratch, user)) ++stats.triangles_clipped;
    if (poly.empty()) continue;
    draw_polygon(ctx, poly, flat ? &verts[t[2]] : nullptr, win);
  }
  draw_prims_reference(ctx, projection, in, verts);
  stats.ms_raster += ms_since(t1);
}

}  // namespace shadelab
