// The per-draw plan: which attribute slots vertices carry (only those the draw reads), where
// lighting happens, which fragments take the per-fragment reference path, and which of the
// per-fragment operations (fog, scissor, stipple, alpha test) the SIMD path must do.
#include "fast/plan.hpp"

#include <algorithm>
#include <bit>

namespace shadelab::fast {

namespace {

int take(VaryingLayout& l, int floats) {
  int offset = l.count;
  l.count += floats;
  return offset;
}

// Colour slots, as draw.cpp's vertex_colors fills them: lit colours, or the given ones.
void color_layout(const DrawJob& job, VaryingLayout& l) {
  const DrawPlan& p = job.plan;
  const VertexInput& in = *job.in;
  l.front_color = take(l, 4);
  if (p.vertex_lighting) {
    bool separate = job.shade->model.separate_specular;
    l.back_color = p.two_side ? take(l, 4) : l.front_color;
    l.front_secondary = separate ? take(l, 3) : -1;
    l.back_secondary = separate && p.two_side ? take(l, 3) : l.front_secondary;
    return;
  }
  l.back_color = in.back_colors.empty() ? l.front_color : take(l, 4);
  l.front_secondary = in.secondary_colors.empty() ? -1 : take(l, 3);
  l.back_secondary = in.back_secondary_colors.empty() ? l.front_secondary : take(l, 3);
}

bool writes_color(const FragmentState& f) {
  return f.capture || f.color_mask[0] || f.color_mask[1] || f.color_mask[2] || f.color_mask[3];
}

void copy_slot(const float* from, float* to, int n) { std::copy(from, from + n, to); }

// The kTextured kernel's draws: one unit textured, its environment not GL_COMBINE, every
// channel written, nothing but fog, the depth and alpha tests and the blend on.
bool single_unit_textured(const DrawPlan& p, const FragmentState& f) {
  int units = 0;
  for (const TexturePlan& tp : p.texture) units += tp.texture ? 1 : 0;
  return units == 1 && !p.combine && !p.phong && !p.scalar_fragments && !p.lane_masks &&
         !f.logic_op.enabled && !f.stencil.enabled && !f.alpha_one && f.color_mask[0] && f.color_mask[1] &&
         f.color_mask[2] && f.color_mask[3];
}

BlockKernel kernel_for(const DrawPlan& p, const FragmentState& f) {
  const bool less = f.depth_func == CompareFunc::kLess, lequal = f.depth_func == CompareFunc::kLequal;
  if (p.textured) {
    if (!single_unit_textured(p, f)) return BlockKernel::kGeneral;
    const TexturePlan& tp = *std::find_if(p.texture, p.texture + kMaxTextureUnits,
                                          [](const TexturePlan& u) { return u.texture != nullptr; });
    return tp.one_d || tp.three_d || tp.cube || tp.depth_texture ? BlockKernel::kTextured : BlockKernel::kTextured2D;
  }
  if (p.alpha_test || p.lane_masks || f.logic_op.enabled || f.alpha_one || p.scalar_fragments || p.phong) {
    return BlockKernel::kGeneral;
  }
  if (f.stencil.enabled && !p.writes_color) return BlockKernel::kStencil;  // a mask drawn into the stencil buffer
  const bool every_channel = f.color_mask[0] && f.color_mask[1] && f.color_mask[2] && f.color_mask[3];
  if (!every_channel || (f.blend.enabled && !f.blend.source_over())) return BlockKernel::kGeneral;
  if (f.stencil.enabled) return BlockKernel::kStencil;
  if (!f.depth_test) return f.blend.enabled ? BlockKernel::kBlend : BlockKernel::kOpaque;  // 2D drawing
  if (!f.depth_write || !(less || lequal)) return BlockKernel::kGeneral;
  if (!f.blend.enabled) return less ? BlockKernel::kOpaqueLess : BlockKernel::kOpaqueLequal;
  return less ? BlockKernel::kBlendLess : BlockKernel::kBlendLequal;
}

bool uses_mipmaps(TextureFilter f) { return f != TextureFilter::kNearest && f != TextureFilter::kLinear; }

TexturePlan texture_plan(const TextureUnit& unit) {
  TexturePlan tp;
  const Texture* t = unit.texture;  // draw_fast.cpp leaves only complete textures
  if (!t) return tp;
  tp.texture = t;
  tp.one_d = t->dimensions == 1;
  tp.three_d = t->dimensions == 3;
  tp.cube = t->cube_map;
  tp.depth_texture = t->depth, tp.compare = t->compare, tp.compare_func = t->compare_func;
  tp.border_depth = t->border_color.r;
  tp.mipmaps = uses_mipmaps(t->min_filter);
  tp.linear_mip = t->min_filter == TextureFilter::kNearestMipmapLinear || t->min_filter == TextureFilter::kLinearMipmapLinear;
  tp.mag_linear = t->mag_filter == TextureFilter::kLinear;
  tp.min_linear = t->min_filter == TextureFilter::kLinear || t->min_filter == TextureFilter::kLinearMipmapNearest ||
                  t->min_filter == TextureFilter::kLinearMipmapLinear;
  tp.lod = tp.mipmaps || tp.min_linear != tp.mag_linear;
  tp.wrap_s = t->wrap_s, tp.wrap_t = t->wrap_t, tp.wrap_r = t->wrap_r;
  if (t->cube_map) tp.wrap_s = tp.wrap_t = TextureWrap::kClampToEdge;  // texture.cpp's wrap_s_of
  const TextureLevel& base = t->levels[std::size_t(t->base_level)];
  tp.width = float(base.width), tp.height = float(base.height), tp.depth = float(base.depth);
  tp.base_level = t->base_level;
  tp.last_level = t->last_level();
  tp.adjust = texture_lod(*t, unit.lod_bias);
  const glm::vec4 border = border_texel(*t);
  for (int c = 0; c < 4; ++c) tp.border[c] = border[c] * 255.0f, tp.env_color[c] = unit.env_color[c];
  tp.env = unit.env;
  tp.combine = unit.combine;
  tp.format = t->format;
  tp.eight_bit = eight_bit_filtering(*t);
  tp.pot_s = std::has_single_bit(unsigned(base.width)), tp.pot_t = std::has_single_bit(unsigned(base.height));
  tp.pot_r = std::has_single_bit(unsigned(base.depth));
  return tp;
}

// The framebuffer cut by the scissor box, and whether blocks need lane masks: a scissor box
// that leaves some pixel of the framebuffer out, or the polygon stipple.
void pixel_box(const Framebuffer& fb, const FragmentState& f, DrawPlan& p) {
  p.box_x0 = 0, p.box_y0 = 0, p.box_x1 = fb.width - 1, p.box_y1 = fb.height - 1;
  const ScissorState& s = f.scissor;
  bool cut = false;
  if (s.enabled) {
    const long x1 = long(s.x) + s.width - 1, y1 = long(s.y) + s.height - 1;
    cut = s.x > 0 || s.y > 0 || x1 < p.box_x1 || y1 < p.box_y1;
    p.box_x0 = std::max(p.box_x0, s.x), p.box_y0 = std::max(p.box_y0, s.y);
    p.box_x1 = int(std::min<long>(p.box_x1, x1)), p.box_y1 = int(std::min<long>(p.box_y1, y1));
  }
  p.lane_masks = cut || f.stipple.enabled;
}

}  // namespace

bool has_shadow_maps(const ShadeState& shade) {
  std::size_t n = std::min(shade.lights.size(), shade.shadow_maps.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (shade.shadow_maps[i].size > 0 && !shade.shadow_maps[i].faces.empty()) return true;
  }
  return false;
}

const float* shadow_visibility(const ShadeState& shade, const glm::vec3& p, const glm::vec3& n,
                               std::vector<float>& buffer) {
  if (shade.shadow_maps.empty()) return nullptr;
  buffer.assign(shade.lights.size(), 1.0f);
  for (std::size_t i = 0; i < buffer.size() && i < shade.shadow_maps.size(); ++i) {
    buffer[i] = shade.shadow_maps[i].visibility(p, n);
  }
  return buffer.data();
}

void make_plan(DrawJob& job) {
  const ShadeState& shade = *job.shade;
  const FragmentState& frag = *job.frag;
  DrawPlan& p = job.plan;
  bool shadows = has_shadow_maps(shade);
  p.two_side = shade.model.two_side;
  p.phong = shade.lighting && shade.shading == ShadingMode::kPhong;
  p.vertex_lighting = shade.lighting && !p.phong;
  p.flat = shade.shading == ShadingMode::kFlat;
  bool simd_materials = simd_supports(shade.front) && (!p.two_side || simd_supports(shade.back));
  p.simd_vertex_lighting = p.vertex_lighting && !shadows && simd_materials;
  p.writes_color = writes_color(frag);
  p.scalar_fragments = frag.capture || (p.phong && (shadows || !simd_materials));
  p.textured = false;
  p.combine = false;
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    p.texture[u] = texture_plan(shade.textures[std::size_t(u)]);
    p.textured = p.textured || p.texture[u].texture;
    p.combine = p.combine || (p.texture[u].texture && p.texture[u].env == TextureEnvMode::kCombine);
  }
  p.fog = shade.fog.enabled;
  if (p.fog) p.fog_params = detail::fog_params(shade.fog);
  p.alpha_test = frag.alpha_test.enabled;
  p.alpha_ref = float(detail::unorm8(frag.alpha_test.ref));
  p.exact_colors = p.alpha_test || frag.logic_op.enabled;
  const glm::vec4 constant = detail::blend_constant(frag.blend);
  for (int c = 0; c < 4; ++c) p.blend_constant[c] = constant[c];
  pixel_box(*job.fb, frag, p);
  const VertexInput& in = *job.in;
  const bool unfilled = detail::PrimAssembler::unfilled(frag);
  p.prims = unfilled || !in.lines.empty() || !in.points.empty();
  const bool line_edges = frag.front_mode == PolygonMode::kLine || frag.back_mode == PolygonMode::kLine;
  const bool point_edges = frag.front_mode == PolygonMode::kPoint || frag.back_mode == PolygonMode::kPoint;
  p.coverage = (frag.line.smooth && (!in.lines.empty() || (line_edges && !in.triangles.empty()))) ||
               ((frag.point.smooth || (frag.point.multisample && !frag.point.sprite)) &&
                (!in.points.empty() || (point_edges && !in.triangles.empty())));
  p.kernel = p.coverage ? BlockKernel::kGeneral : kernel_for(p, frag);
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    if (p.texture[u].texture) p.texture_unit = u;
  }
  const TexturePlan& unit = p.texture[p.texture_unit];
  p.texel_bytes = kernel_textured(p.kernel) && unit.eight_bit && unit.env == TextureEnvMode::kReplace &&
                  unit.format == TextureFormat::kRgba && !frag.blend.enabled && !p.fog;
  p.user_plane_count = detail::clip_space_planes(frag.clip, job.projection, p.user_planes);
  VaryingLayout l;
  if (!p.phong) color_layout(job, l);
  if (p.phong) {
    l.eye_position = take(l, 3);
    l.eye_normal = take(l, 3);
  }
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    if (shade.textures[std::size_t(u)].texture) l.texcoord[u] = take(l, 4);
  }
  if (p.fog) l.fog = take(l, 1);
  p.layout = l;
  if (shade.lighting) {
    make_lighting_setup(shade.model, shade.lights, shade.front, shade.back, p.lighting);
  }
}

void expand_varyings(const VaryingLayout& l, const float* v, detail::Attribs& a) {
  a.fill(0.0f);
  if (l.front_color >= 0) copy_slot(v + l.front_color, &a[detail::kFrontColor], 4);
  if (l.back_color >= 0) copy_slot(v + l.back_color, &a[detail::kBackColor], 4);
  if (l.front_secondary >= 0) copy_slot(v + l.front_secondary, &a[detail::kFrontSecondary], 3);
  if (l.back_secondary >= 0) copy_slot(v + l.back_secondary, &a[detail::kBackSecondary], 3);
  if (l.eye_position >= 0) copy_slot(v + l.eye_position, &a[detail::kEyePosition], 3);
  if (l.eye_normal >= 0) copy_slot(v + l.eye_normal, &a[detail::kEyeNormal], 3);
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    if (l.texcoord[u] >= 0) copy_slot(v + l.texcoord[u], &a[std::size_t(detail::kTexCoord + 4 * u)], 4);
  }
  if (l.fog >= 0) a[detail::kFogCoord] = v[l.fog];
}

void compact_varyings(const VaryingLayout& l, const detail::Attribs& a, float* v) {
  // Aliased back slots hold the same values as the front ones; the front copy wins.
  if (l.back_color >= 0) copy_slot(&a[detail::kBackColor], v + l.back_color, 4);
  if (l.front_color >= 0) copy_slot(&a[detail::kFrontColor], v + l.front_color, 4);
  if (l.back_secondary >= 0) copy_slot(&a[detail::kBackSecondary], v + l.back_secondary, 3);
  if (l.front_secondary >= 0) copy_slot(&a[detail::kFrontSecondary], v + l.front_secondary, 3);
  if (l.eye_position >= 0) copy_slot(&a[detail::kEyePosition], v + l.eye_position, 3);
  if (l.eye_normal >= 0) copy_slot(&a[detail::kEyeNormal], v + l.eye_normal, 3);
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    if (l.texcoord[u] >= 0) copy_slot(&a[std::size_t(detail::kTexCoord + 4 * u)], v + l.texcoord[u], 4);
  }
  if (l.fog >= 0) v[l.fog] = a[detail::kFogCoord];
}

std::uint64_t attribute_slots(const VaryingLayout& l) {
  std::uint64_t slots = 0;
  auto take_slots = [&](int present, int first, int n) {
    if (present >= 0) slots |= ((std::uint64_t(1) << n) - 1) << first;
  };
  take_slots(l.front_color, detail::kFrontColor, 4);
  take_slots(l.back_color, detail::kBackColor, 4);
  take_slots(l.front_secondary, detail::kFrontSecondary, 3);
  take_slots(l.back_secondary, detail::kBackSecondary, 3);
  take_slots(l.eye_position, detail::kEyePosition, 3);
  take_slots(l.eye_normal, detail::kEyeNormal, 3);
  for (int u = 0; u < kMaxTextureUnits; ++u) take_slots(l.texcoord[u], detail::kTexCoord + 4 * u, 4);
  take_slots(l.fog, detail::kFogCoord, 1);
  return slots;
}

}  // namespace shadelab::fast
