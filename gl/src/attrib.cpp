// The attribute stacks (GL 1.1 section 6.1.14): glPushAttrib / glPopAttrib for every server
// attribute group of the state tables (chapter 6, the "Attribute" column), glPushClientAttrib /
// glPopClientAttrib for pixel storage and vertex arrays. A push copies the state structs
// (AttribRecord, context.hpp); a pop restores the groups of the pushed mask in the order Mesa's
// glPopAttrib does (which decides, for instance, that popped materials win over a colour
// material enabled by the enable group). State only; nothing is drawn here.
// New state joins its group here: see the comment on AttribRecord in context.hpp.
#include <iterator>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {
namespace {

// Every GL 1.1 capability (glEnable): the enable group saves those capability_flag accepts
// (a capability not implemented yet has no flag). GL_LIGHTi are saved too, but restored by
// the lighting group only: Mesa's enable group leaves them as they are (docs/gl.md).
constexpr GLenum kCapabilities[] = {
    GL_ALPHA_TEST, GL_AUTO_NORMAL, GL_BLEND, GL_CLIP_PLANE0, GL_CLIP_PLANE1, GL_CLIP_PLANE2,
    GL_CLIP_PLANE3, GL_CLIP_PLANE4, GL_CLIP_PLANE5, GL_COLOR_LOGIC_OP, GL_COLOR_MATERIAL,
    GL_COLOR_SUM,
    GL_CULL_FACE, GL_DEPTH_TEST, GL_DITHER, GL_FOG, GL_INDEX_LOGIC_OP, GL_LIGHTING,
    GL_LINE_SMOOTH, GL_LINE_STIPPLE, GL_MAP1_COLOR_4, GL_MAP1_INDEX, GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3,
    GL_MAP1_TEXTURE_COORD_4, GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP2_COLOR_4, GL_MAP2_INDEX,
    GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_1, GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3,
    GL_MAP2_TEXTURE_COORD_4, GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4, GL_NORMALIZE, GL_POINT_SMOOTH,
    GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH,
    GL_POLYGON_STIPPLE, GL_RESCALE_NORMAL, GL_SCISSOR_TEST, GL_STENCIL_TEST, GL_TEXTURE_1D,
    GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP, kTextureRectangle, kPointSprite, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q,
    // GL 1.3
    GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE,
};

// The parameters of a texture object that the texture group holds (GL 1.5 table 6.19),
// nineteen floats.
constexpr GLenum kTextureParameters[] = {
    GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER,  GL_TEXTURE_WRAP_S,     GL_TEXTURE_WRAP_T,
    GL_TEXTURE_WRAP_R,     GL_TEXTURE_PRIORITY,    GL_TEXTURE_BORDER_COLOR, GL_TEXTURE_MIN_LOD,
    GL_TEXTURE_MAX_LOD,    GL_TEXTURE_BASE_LEVEL,  GL_TEXTURE_MAX_LEVEL,  GL_TEXTURE_LOD_BIAS,
    GL_GENERATE_MIPMAP,    GL_DEPTH_TEXTURE_MODE,  GL_TEXTURE_COMPARE_MODE, GL_TEXTURE_COMPARE_FUNC};
constexpr std::size_t kTextureParameterFloats = 19;

// Runs a GL command for its effect on state the stack saves, leaving the error flag as it was:
// true if the command raised no error (a texture target not implemented raises one).
template <class F>
bool quietly(GlContext& c, F&& f) {
  const GLenum before = c.error;
  c.error = GL_NO_ERROR;
  f();
  const bool ok = c.error == GL_NO_ERROR;
  c.error = before;
  return ok;
}

void read_texture_parameters(GlContext& c, GLenum target, std::array<float, kTextureParameterFloats>& out) {
  std::size_t k = 0;
  for (GLenum pname : kTextureParameters) {
    exec::GetTexParameterfv(c, target, pname, &out[k]);
    k += pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1;
  }
}

void write_texture_parameters(GlContext& c, GLenum target, const std::array<float, kTextureParameterFloats>& in) {
  std::size_t k = 0;
  for (GLenum pname : kTextureParameters) {
    exec::TexParameterfv(c, target, pname, &in[k]);
    k += pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1;
  }
}

// A texture unit's capabilities (GL 1.3 section 2.7: glEnable addresses the active unit's).
bool texture_unit_capability(GLenum cap) {
  return cap == GL_TEXTURE_1D || cap == GL_TEXTURE_2D || cap == GL_TEXTURE_3D || cap == GL_TEXTURE_CUBE_MAP ||
         cap == kTextureRectangle ||
         (cap >= GL_TEXTURE_GEN_S && cap <= GL_TEXTURE_GEN_Q);
}

// Runs `f` with each texture unit active in turn, then the active unit as it was.
template <class F>
void for_each_unit(GlContext& c, F&& f) {
  const std::size_t active = c.textures.active;
  for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {
    c.textures.active = u;
    f(u);
  }
  c.textures.active = active;
}

void save_enables(GlContext& c, AttribRecord& r) {
  auto save = [&](GLenum cap) {
    if (texture_unit_capability(cap)) {
      for_each_unit(c, [&](std::size_t u) { r.enables.push_back({cap, u, *capability_flag(c, cap)}); });
    } else if (const bool* flag = capability_flag(c, cap)) {
      r.enables.push_back({cap, 0, *flag});
    }
  };
  for (GLenum cap : kCapabilities) save(cap);
  for (int i = 0; i < kMaxLights; ++i) save(GLenum(GL_LIGHT0 + i));
  for (int i = 6; i < kMaxClipPlanes; ++i) save(GLenum(GL_CLIP_PLANE0 + i));  // beyond GL 1.1's 6
}

// Through glEnable / glDisable, for what they do besides the flag (GL_COLOR_MATERIAL takes
// the current colour), and only where the value changes, as Mesa's pop; the capabilities
// `which` selects.
template <class Which>
void restore_enables(GlContext& c, const AttribRecord& r, const Which& which) {
  const std::size_t active = c.textures.active;
  for (const AttribRecord::Enable& e : r.enables) {
    if (!which(e.cap)) continue;
    c.textures.active = e.unit;
    if (*capability_flag(c, e.cap) != e.on) e.on ? exec::Enable(c, e.cap) : exec::Disable(c, e.cap);
  }
  c.textures.active = active;
}

// The texture group's bindings and object parameters (Mesa saves the default objects' too).
void save_textures(GlContext& c, AttribRecord& r) {
  static_assert(kTextureParameterFloats == std::tuple_size_v<decltype(AttribRecord::TextureTarget::bound)>);
  const std::pair<GLenum, GLenum> targets[] = {{GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D},
                                               {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D},
                                               {GL_TEXTURE_3D, GL_TEXTURE_BINDING_3D},
                                               {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP},
                                               {kTextureRectangle, kTextureBindingRectangle}};
  for_each_unit(c, [&](std::size_t unit) {
    for (const std::pair<GLenum, GLenum>& tb : targets) {
      // (Not a structured binding: clang 14, the fuzz build's compiler, cannot capture one.)
      const GLenum target = tb.first, binding = tb.second;
      AttribRecord::TextureTarget t;
      t.unit = unit;
      t.target = target;
      GLint name = 0;
      if (!quietly(c, [&] { exec::GetIntegerv(c, binding, &name); })) continue;
      t.name = GLuint(name);
      quietly(c, [&] {
        read_texture_parameters(c, target, t.bound);
        t.defaults = t.bound;
        if (t.name == 0) return;
        exec::BindTexture(c, target, 0);
        read_texture_parameters(c, target, t.defaults);
        exec::BindTexture(c, target, t.name);
      });
      r.texture_targets.push_back(t);
    }
  });
}

// Binds the pushed names again (a name deleted since comes back as a new object, as
// glBindTexture makes it) and gives the objects their pushed parameters.
void restore_textures(GlContext& c, const AttribRecord& r) {
  for (const AttribRecord::TextureTarget& t : r.texture_targets) {
    c.textures.active = t.unit;
    quietly(c, [&] {
      exec::BindTexture(c, t.target, 0);
      write_texture_parameters(c, t.target, t.defaults);
      if (t.name == 0) return;
      exec::BindTexture(c, t.target, t.name);
      write_texture_parameters(c, t.target, t.bound);
    });
  }
  // GL_ACTIVE_TEXTURE is in the texture group (GL 1.3 table 6.19).
  c.textures.active = r.textures.active;
  for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {
    TextureUnitState& d = c.textures.units[u];
    const TextureUnitState& s = r.textures.units[u];
    d.env_mode = s.env_mode;
    d.env_color = s.env_color;
    d.lod_bias = s.lod_bias;
    d.combine = s.combine;
    // Texture generation (table 6.16): the modes and both planes, the eye plane as stored (in
    // eye coordinates, not transformed again), as Mesa's pop copies it; the enables follow.
    for (std::size_t i = 0; i < d.gen.size(); ++i) {
      d.gen[i].mode = s.gen[i].mode;
      d.gen[i].object_plane = s.gen[i].object_plane;
      d.gen[i].eye_plane = s.gen[i].eye_plane;
    }
  }
  restore_enables(c, r, texture_unit_capability);
}

// GL_COLOR_BUFFER_BIT (table 6.19's "color-buffer" rows).
void restore_color_buffer(GlContext& c, const AttribRecord& r) {
  RasterState& d = c.raster;
  const RasterState& s = r.raster;
  d.clear_index = s.clear_index;
  d.clear_color = s.clear_color;
  d.index_mask = s.index_mask;
  d.color_mask = s.color_mask;
  d.blend = s.blend;
  d.blend_src = s.blend_src;
  d.blend_dst = s.blend_dst;
  d.blend_src_alpha = s.blend_src_alpha;
  d.blend_dst_alpha = s.blend_dst_alpha;
  d.blend_equation = s.blend_equation;
  d.blend_equation_alpha = s.blend_equation_alpha;
  d.blend_color = s.blend_color;
  d.dither = s.dither;
  d.alpha_test = s.alpha_test;
  d.alpha_func = s.alpha_func;
  d.alpha_ref = s.alpha_ref;
  d.color_logic_op = s.color_logic_op;
  d.index_logic_op = s.index_logic_op;
  d.logic_op = s.logic_op;
  c.buffers.draw_buffer = r.draw_buffer;
  select_draw_buffer(c);
}

// GL_FOG_BIT (table 6.9's fog rows): the enable, mode, density, start, end, index and colour.
void restore_fog(GlContext& c, const AttribRecord& r) { c.fog = r.fog; }

// GL_SCISSOR_BIT (table 6.17): the enable and the box.
void restore_scissor(GlContext& c, const AttribRecord& r) {
  RasterState& d = c.raster;
  const RasterState& s = r.raster;
  d.scissor_test = s.scissor_test;
  d.scissor_x = s.scissor_x;
  d.scissor_y = s.scissor_y;
  d.scissor_width = s.scissor_width;
  d.scissor_height = s.scissor_height;
}

// GL_CURRENT_BIT (table 6.5), the current raster position and its data included. The colour
// material does not follow the popped colour (as in Mesa: the next glColor updates it).
void restore_current(GlContext& c, const AttribRecord& r) {
  c.current = r.current;
  c.raster_pos = r.raster_pos;
}

// GL_PIXEL_MODE_BIT (table 6.17 and GL_READ_BUFFER): the transfer modes and the zoom; the
// pixel maps belong to no group (table 6.18).
void restore_pixel_mode(GlContext& c, const AttribRecord& r) {
  PixelTransfer& d = c.pixel;
  const PixelTransfer& s = r.pixel;
  d.scale = s.scale;
  d.bias = s.bias;
  d.depth_scale = s.depth_scale;
  d.depth_bias = s.depth_bias;
  d.index_shift = s.index_shift;
  d.index_offset = s.index_offset;
  d.map_color = s.map_color;
  d.map_stencil = s.map_stencil;
  d.zoom_x = s.zoom_x;
  d.zoom_y = s.zoom_y;
  c.buffers.read_buffer = r.read_buffer;
}

void restore_depth_buffer(GlContext& c, const AttribRecord& r) {
  c.raster.depth_func = r.raster.depth_func;
  c.raster.clear_depth = r.raster.clear_depth;
  c.raster.depth_test = r.raster.depth_test;
  c.raster.depth_mask = r.raster.depth_mask;
}

void restore_hints(GlContext& c, const AttribRecord& r) { c.hints = r.hints; }

// GL_LIGHTING_BIT (tables 6.9-6.11): all of LightingState but GL_NORMALIZE and
// GL_RESCALE_NORMAL (transform group). The materials are the pushed ones even if the colour
// material was switched on meanwhile.
void restore_lighting(GlContext& c, const AttribRecord& r) {
  const bool normalize = c.lighting.normalize, rescale = c.lighting.rescale_normal;
  c.lighting = r.lighting;  // GL_LIGHTi included
  c.lighting.normalize = normalize;
  c.lighting.rescale_normal = rescale;
}

void restore_line(GlContext& c, const AttribRecord& r) {
  PrimState& d = c.prims;
  const PrimState& s = r.prims;
  d.line_smooth = s.line_smooth;
  d.line_stipple = s.line_stipple;
  d.stipple_repeat = s.stipple_repeat;
  d.stipple_pattern = s.stipple_pattern;
  d.line_width = s.line_width;
}

void restore_point(GlContext& c, const AttribRecord& r) {
  c.prims.point_size = r.prims.point_size;
  c.prims.point_smooth = r.prims.point_smooth;
  c.prims.point_min = r.prims.point_min;  // GL 1.4's point parameters (table 6.11)
  c.prims.point_max = r.prims.point_max;
  c.prims.point_fade = r.prims.point_fade;
  c.prims.point_attenuation = r.prims.point_attenuation;
  c.prims.point_sprite = r.prims.point_sprite;  // ARB_point_sprite (GL 2.0 table 6.12)
  c.prims.coord_replace = r.prims.coord_replace;
}

void restore_polygon(GlContext& c, const AttribRecord& r) {
  c.raster.cull_mode = r.raster.cull_mode;
  c.raster.front_face = r.raster.front_face;
  c.raster.offset_factor = r.raster.offset_factor;
  c.raster.offset_units = r.raster.offset_units;
  c.prims.front_mode = r.prims.front_mode;
  c.prims.back_mode = r.prims.back_mode;
  c.prims.polygon_smooth = r.prims.polygon_smooth;
  c.raster.cull = r.raster.cull;
  c.prims.offset_point = r.prims.offset_point;
  c.prims.offset_line = r.prims.offset_line;
  c.raster.polygon_offset_fill = r.raster.polygon_offset_fill;
  c.raster.polygon_stipple = r.raster.polygon_stipple;  // the enable (table 6.12)
}

void restore_stencil(GlContext& c, const AttribRecord& r) {
  RasterState& d = c.raster;
  const RasterState& s = r.raster;
  d.stencil_test = s.stencil_test;
  d.clear_stencil = s.clear_stencil;
  d.stencil_func = s.stencil_func;
  d.stencil_ref = s.stencil_ref;
  d.stencil_value_mask = s.stencil_value_mask;
  d.stencil_write_mask = s.stencil_write_mask;
  d.stencil_fail = s.stencil_fail;
  d.stencil_zfail = s.stencil_zfail;
  d.stencil_zpass = s.stencil_zpass;
}

void restore_transform(GlContext& c, const AttribRecord& r) {
  c.matrix_mode = r.matrix_mode;
  c.prims.clip_planes = r.prims.clip_planes;  // in eye space, as they were pushed
  c.prims.clip_enabled = r.prims.clip_enabled;
  c.lighting.normalize = r.lighting.normalize;
  c.lighting.rescale_normal = r.lighting.rescale_normal;
}

void restore_viewport(GlContext& c, const AttribRecord& r) {
  const Viewport& v = r.raster.viewport;
  Viewport& d = c.raster.viewport;
  const bool moved = d.x != v.x || d.y != v.y || d.width != v.width || d.height != v.height;
  d = v;
  if (moved && c.surface) c.surface->viewport_set(c);
}

}  // namespace

void exec::PushAttrib(GlContext& c, GLbitfield mask) {
  if (c.attrib_stack.size() >= std::size_t(kMaxAttribStackDepth)) return c.set_error(GL_STACK_OVERFLOW);
  AttribRecord r;
  r.mask = mask;
  r.current = c.current;
  r.lighting = c.lighting;
  r.raster = c.raster;
  r.prims = c.prims;
  r.textures = c.textures;
  r.fog = c.fog;
  save_enables(c, r);
  if (mask & GL_TEXTURE_BIT) save_textures(c, r);
  r.hints = c.hints;
  r.matrix_mode = c.matrix_mode;
  r.list_base = c.lists.base;
  r.raster_pos = c.raster_pos;
  r.pixel = c.pixel;
  r.pixel.maps = {};  // restored by no group: not kept
  r.draw_buffer = c.buffers.draw_buffer;
  r.read_buffer = c.buffers.read_buffer;
  r.accum_clear = c.buffers.accum_clear;
  r.eval = c.eval.attribs;
  r.multisample = c.multisample;
  c.attrib_stack.push_back(std::move(r));
}

// In the order of Mesa's glPopAttrib.
void exec::PopAttrib(GlContext& c) {
  if (c.attrib_stack.empty()) return c.set_error(GL_STACK_UNDERFLOW);
  const AttribRecord r = std::move(c.attrib_stack.back());
  c.attrib_stack.pop_back();
  const GLbitfield m = r.mask;
  if (m & GL_ACCUM_BUFFER_BIT) c.buffers.accum_clear = r.accum_clear;
  if (m & GL_COLOR_BUFFER_BIT) restore_color_buffer(c, r);
  if (m & GL_CURRENT_BIT) restore_current(c, r);
  if (m & GL_DEPTH_BUFFER_BIT) restore_depth_buffer(c, r);
  if (m & GL_ENABLE_BIT) {
    restore_enables(c, r, [](GLenum cap) { return cap < GL_LIGHT0 || cap >= GLenum(GL_LIGHT0 + kMaxLights); });
  }
  if (m & GL_FOG_BIT) restore_fog(c, r);
  // GL_EVAL_BIT (table 6.20): the map enables, GL_AUTO_NORMAL and the grids.
  if (m & GL_EVAL_BIT) c.eval.attribs = r.eval;
  if (m & GL_HINT_BIT) restore_hints(c, r);
  if (m & GL_LIGHTING_BIT) restore_lighting(c, r);
  if (m & GL_LINE_BIT) restore_line(c, r);
  if (m & GL_LIST_BIT) c.lists.base = r.list_base;
  if (m & GL_PIXEL_MODE_BIT) restore_pixel_mode(c, r);
  if (m & GL_POINT_BIT) restore_point(c, r);
  if (m & GL_POLYGON_BIT) restore_polygon(c, r);
  if (m & GL_POLYGON_STIPPLE_BIT) c.raster.stipple = r.raster.stipple;
  if (m & GL_SCISSOR_BIT) restore_scissor(c, r);
  if (m & GL_STENCIL_BUFFER_BIT) restore_stencil(c, r);
  if (m & GL_TRANSFORM_BIT) restore_transform(c, r);
  if (m & GL_TEXTURE_BIT) restore_textures(c, r);
  if (m & GL_VIEWPORT_BIT) restore_viewport(c, r);
  // GL 1.3's multisample group (table 6.16 of GL 1.5): the enables and the coverage values.
  if (m & GL_MULTISAMPLE_BIT) c.multisample = r.multisample;
}

void exec::PushClientAttrib(GlContext& c, GLbitfield mask) {
  if (c.client_attrib_stack.size() >= std::size_t(kMaxClientAttribStackDepth)) {
    return c.set_error(GL_STACK_OVERFLOW);
  }
  c.client_attrib_stack.push_back({mask, c.pack, c.unpack, c.arrays});
}

void exec::PopClientAttrib(GlContext& c) {
  if (c.client_attrib_stack.empty()) return c.set_error(GL_STACK_UNDERFLOW);
  const ClientAttribRecord r = c.client_attrib_stack.back();
  c.client_attrib_stack.pop_back();
  if (r.mask & GL_CLIENT_PIXEL_STORE_BIT) {
    c.pack = r.pack;
    c.unpack = r.unpack;
  }
  if (r.mask & GL_CLIENT_VERTEX_ARRAY_BIT) c.arrays = r.arrays;
}

}  // namespace shadelab::gl
