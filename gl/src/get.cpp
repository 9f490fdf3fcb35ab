// glGetBooleanv/Integerv/Floatv/Doublev and glGetString (GL 1.1 sections 6.1.1-6.1.2,
// 6.1.11): every query answers from one table of values with a kind, converted per the
// spec's rules. Reads state only.
#include <climits>

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "gl/generated/exec.hpp"
#include "gl/generated/version.hpp"
#include "gl/src/context.hpp"
#include "gl/src/convert.hpp"

#ifndef SHADELAB_VERSION
#define SHADELAB_VERSION "0"
#endif

namespace shadelab::gl {
namespace {

// How a value converts to the other query types (GL 1.1 section 6.1.2).
enum class Kind {
  kBool,
  kInt,     // integers and enums
  kUint,    // unsigned integers (masks): glGetIntegerv clamps to INT_MAX, as Mesa's TYPE_UINT
  kFloat,   // rounded to the nearest integer by glGetIntegerv
  kColor,   // colours, normals, depths: [-1, 1] maps to the whole integer range
};

struct Values {
  double v[16] = {};
  int n = 0;
  Kind kind = Kind::kInt;

  Values& add(double x) {
    v[n++] = x;
    return *this;
  }
};

Values make(Kind k, std::initializer_list<double> xs) {
  Values r;
  r.kind = k;
  for (double x : xs) r.add(x);
  return r;
}

Values vec(Kind k, const float* p, int n) {
  Values r;
  r.kind = k;
  for (int i = 0; i < n; ++i) r.add(p[i]);
  return r;
}

Values transposed(const glm::mat4& m) {
  const glm::mat4 t = glm::transpose(m);
  return vec(Kind::kFloat, glm::value_ptr(t), 16);
}

Values ints(std::initializer_list<double> xs) { return make(Kind::kInt, xs); }

// GL_CURRENT_RASTER_SECONDARY_COLOR: the raster position's secondary colour, which Mesa
// answers (the enum came with GL 3.0's compatibility tables, not in a GL 1.x feature).
constexpr GLenum kCurrentRasterSecondaryColor = 0x845F;
// EXT_blend_equation_separate's GL_BLEND_EQUATION_ALPHA_EXT (GL_BLEND_EQUATION_RGB_EXT is
// GL_BLEND_EQUATION).
constexpr GLenum kBlendEquationAlpha = 0x883D;

Values array_state(const ClientArray& a, bool with_size) {
  return with_size ? ints({double(a.size)}) : ints({});
}

// Client arrays and pixel storage.
bool query_client(const GlContext& c, GLenum pname, Values& out) {
  const ClientArrays& a = c.arrays;
  switch (pname) {
    case GL_VERTEX_ARRAY_SIZE: out = array_state(a.vertex, true); return true;
    case GL_VERTEX_ARRAY_TYPE: out = ints({double(a.vertex.type)}); return true;
    case GL_VERTEX_ARRAY_STRIDE: out = ints({double(a.vertex.stride)}); return true;
    case GL_NORMAL_ARRAY_TYPE: out = ints({double(a.normal.type)}); return true;
    case GL_NORMAL_ARRAY_STRIDE: out = ints({double(a.normal.stride)}); return true;
    case GL_COLOR_ARRAY_SIZE: out = array_state(a.color, true); return true;
    case GL_COLOR_ARRAY_TYPE: out = ints({double(a.color.type)}); return true;
    case GL_COLOR_ARRAY_STRIDE: out = ints({double(a.color.stride)}); return true;
    case GL_TEXTURE_COORD_ARRAY_SIZE: out = array_state(a.texcoord(), true); return true;
    case GL_TEXTURE_COORD_ARRAY_TYPE: out = ints({double(a.texcoord().type)}); return true;
    case GL_TEXTURE_COORD_ARRAY_STRIDE: out = ints({double(a.texcoord().stride)}); return true;
    case GL_INDEX_ARRAY_TYPE: out = ints({double(a.index.type)}); return true;
    case GL_INDEX_ARRAY_STRIDE: out = ints({double(a.index.stride)}); return true;
    case GL_EDGE_FLAG_ARRAY_STRIDE: out = ints({double(a.edge_flag.stride)}); return true;
    case GL_SECONDARY_COLOR_ARRAY_SIZE: out = array_state(a.secondary_color, true); return true;
    case GL_SECONDARY_COLOR_ARRAY_TYPE: out = ints({double(a.secondary_color.type)}); return true;
    case GL_SECONDARY_COLOR_ARRAY_STRIDE: out = ints({double(a.secondary_color.stride)}); return true;
    case GL_FOG_COORD_ARRAY_TYPE: out = ints({double(a.fog_coord.type)}); return true;
    case GL_FOG_COORD_ARRAY_STRIDE: out = ints({double(a.fog_coord.stride)}); return true;
    default: break;
  }
  switch (pname) {  // GL 1.2's 3D image layout, GL 1.5's buffer bindings (section 2.9)
    case GL_PACK_IMAGE_HEIGHT: out = ints({double(c.pack.image_height)}); return true;
    case GL_PACK_SKIP_IMAGES: out = ints({double(c.pack.skip_images)}); return true;
    case GL_UNPACK_IMAGE_HEIGHT: out = ints({double(c.unpack.image_height)}); return true;
    case GL_UNPACK_SKIP_IMAGES: out = ints({double(c.unpack.skip_images)}); return true;
    case GL_ARRAY_BUFFER_BINDING: out = ints({double(a.array_buffer_name)}); return true;
    case GL_ELEMENT_ARRAY_BUFFER_BINDING: out = ints({double(a.element_buffer_name)}); return true;
    case GL_VERTEX_ARRAY_BUFFER_BINDING: out = ints({double(a.vertex.buffer_name)}); return true;
    case GL_NORMAL_ARRAY_BUFFER_BINDING: out = ints({double(a.normal.buffer_name)}); return true;
    case GL_COLOR_ARRAY_BUFFER_BINDING: out = ints({double(a.color.buffer_name)}); return true;
    case GL_INDEX_ARRAY_BUFFER_BINDING: out = ints({double(a.index.buffer_name)}); return true;
    case GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING: out = ints({double(a.texcoord().buffer_name)}); return true;
    case GL_EDGE_FLAG_ARRAY_BUFFER_BINDING: out = ints({double(a.edge_flag.buffer_name)}); return true;
    case GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING: out = ints({double(a.secondary_color.buffer_name)}); return true;
    case GL_FOG_COORD_ARRAY_BUFFER_BINDING: out = ints({double(a.fog_coord.buffer_name)}); return true;
    default: break;
  }
  bool pack = pname >= GL_PACK_SWAP_BYTES && pname <= GL_PACK_ALIGNMENT;
  bool unpack = pname >= GL_UNPACK_SWAP_BYTES && pname <= GL_UNPACK_ALIGNMENT;
  if (!pack && !unpack) return false;
  const PixelStore& s = pack ? c.pack : c.unpack;
  GLenum which = pname - (pack ? GL_PACK_SWAP_BYTES : GL_UNPACK_SWAP_BYTES);
  const double values[6] = {double(s.swap_bytes), double(s.lsb_first), double(s.row_length),
                            double(s.skip_rows), double(s.skip_pixels), double(s.alignment)};
  out = make(which <= 1 ? Kind::kBool : Kind::kInt, {values[which]});
  return true;
}

// Transformation, current attributes and lighting state.
bool query_transform_lighting(const GlContext& c, GLenum pname, Values& out) {
  const LightingState& l = c.lighting;
  const Viewport& vp = c.raster.viewport;
  switch (pname) {
    case GL_CURRENT_COLOR: out = vec(Kind::kColor, glm::value_ptr(c.current.color), 4); return true;
    case GL_CURRENT_NORMAL: out = vec(Kind::kColor, glm::value_ptr(c.current.normal), 3); return true;
    case GL_CURRENT_TEXTURE_COORDS: out = vec(Kind::kFloat, glm::value_ptr(c.current.texcoords[c.textures.active]), 4); return true;
    case GL_CURRENT_INDEX: out = make(Kind::kFloat, {c.current.index}); return true;
    case GL_CURRENT_SECONDARY_COLOR: out = vec(Kind::kColor, glm::value_ptr(c.current.secondary), 4); return true;
    case GL_CURRENT_FOG_COORD: out = make(Kind::kFloat, {c.current.fog_coord}); return true;
    case GL_EDGE_FLAG: out = make(Kind::kBool, {double(c.current.edge_flag == 1.0f)}); return true;
    case GL_MODELVIEW_MATRIX: out = vec(Kind::kFloat, glm::value_ptr(c.modelview.top()), 16); return true;
    case GL_PROJECTION_MATRIX: out = vec(Kind::kFloat, glm::value_ptr(c.projection.top()), 16); return true;
    case GL_TEXTURE_MATRIX: out = vec(Kind::kFloat, glm::value_ptr(c.texture_matrix().top()), 16); return true;
    // GL 1.3: the same matrices row by row.
    case GL_TRANSPOSE_MODELVIEW_MATRIX: out = transposed(c.modelview.top()); return true;
    case GL_TRANSPOSE_PROJECTION_MATRIX: out = transposed(c.projection.top()); return true;
    case GL_TRANSPOSE_TEXTURE_MATRIX: out = transposed(c.texture_matrix().top()); return true;
    case GL_MODELVIEW_STACK_DEPTH: out = ints({double(c.modelview.entries.size())}); return true;
    case GL_PROJECTION_STACK_DEPTH: out = ints({double(c.projection.entries.size())}); return true;
    case GL_TEXTURE_STACK_DEPTH: out = ints({double(c.texture_matrix().entries.size())}); return true;
    case GL_ATTRIB_STACK_DEPTH: out = ints({double(c.attrib_stack.size())}); return true;
    case GL_CLIENT_ATTRIB_STACK_DEPTH: out = ints({double(c.client_attrib_stack.size())}); return true;
    case GL_MATRIX_MODE: out = ints({double(c.matrix_mode)}); return true;
    case GL_VIEWPORT: out = ints({double(vp.x), double(vp.y), double(vp.width), double(vp.height)}); return true;
    case GL_DEPTH_RANGE: out = make(Kind::kColor, {vp.near_depth, vp.far_depth}); return true;
    case GL_LIGHT_MODEL_AMBIENT: out = vec(Kind::kColor, glm::value_ptr(l.model.ambient), 4); return true;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: out = make(Kind::kBool, {double(l.model.local_viewer)}); return true;
    case GL_LIGHT_MODEL_TWO_SIDE: out = make(Kind::kBool, {double(l.model.two_side)}); return true;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      out = ints({double(l.model.separate_specular ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR)});
      return true;
    case GL_SHADE_MODEL: out = ints({double(l.shade_model)}); return true;
    case GL_COLOR_MATERIAL_FACE: out = ints({double(l.color_material_face)}); return true;
    case GL_COLOR_MATERIAL_PARAMETER: out = ints({double(l.color_material_mode)}); return true;
    default: return false;
  }
}

// Fragment operations, framebuffer and textures.
bool query_raster(const GlContext& c, GLenum pname, Values& out) {
  const RasterState& r = c.raster;
  const auto& m = r.color_mask;
  switch (pname) {
    case GL_DEPTH_FUNC: out = ints({double(r.depth_func)}); return true;
    case GL_DEPTH_WRITEMASK: out = make(Kind::kBool, {double(r.depth_mask)}); return true;
    case GL_DEPTH_CLEAR_VALUE: out = make(Kind::kColor, {r.clear_depth}); return true;
    case GL_COLOR_CLEAR_VALUE: out = vec(Kind::kColor, glm::value_ptr(r.clear_color), 4); return true;
    case GL_COLOR_WRITEMASK: out = make(Kind::kBool, {double(m[0]), double(m[1]), double(m[2]), double(m[3])}); return true;
    case GL_BLEND_SRC: out = ints({double(r.blend_src)}); return true;  // the colour's (GL 1.4)
    case GL_BLEND_DST: out = ints({double(r.blend_dst)}); return true;
    case GL_BLEND_SRC_RGB: out = ints({double(r.blend_src)}); return true;
    case GL_BLEND_DST_RGB: out = ints({double(r.blend_dst)}); return true;
    case GL_BLEND_SRC_ALPHA: out = ints({double(r.blend_src_alpha)}); return true;
    case GL_BLEND_DST_ALPHA: out = ints({double(r.blend_dst_alpha)}); return true;
    case GL_BLEND_EQUATION: out = ints({double(r.blend_equation)}); return true;  // also _RGB_EXT
    case kBlendEquationAlpha: out = ints({double(r.blend_equation_alpha)}); return true;
    case GL_BLEND_COLOR: out = vec(Kind::kColor, glm::value_ptr(r.blend_color), 4); return true;
    case GL_CULL_FACE_MODE: out = ints({double(r.cull_mode)}); return true;
    case GL_FRONT_FACE: out = ints({double(r.front_face)}); return true;
    case GL_STENCIL_FUNC: out = ints({double(r.stencil_func)}); return true;
    case GL_STENCIL_REF: out = ints({double(r.stencil_ref)}); return true;
    case GL_STENCIL_VALUE_MASK: out = make(Kind::kUint, {double(r.stencil_value_mask)}); return true;
    case GL_STENCIL_WRITEMASK: out = make(Kind::kUint, {double(r.stencil_write_mask)}); return true;
    case GL_STENCIL_FAIL: out = ints({double(r.stencil_fail)}); return true;
    case GL_STENCIL_PASS_DEPTH_FAIL: out = ints({double(r.stencil_zfail)}); return true;
    case GL_STENCIL_PASS_DEPTH_PASS: out = ints({double(r.stencil_zpass)}); return true;
    case GL_STENCIL_CLEAR_VALUE: out = ints({double(r.clear_stencil)}); return true;
    case GL_POLYGON_OFFSET_FACTOR: out = make(Kind::kFloat, {r.offset_factor}); return true;
    case GL_POLYGON_OFFSET_UNITS: out = make(Kind::kFloat, {r.offset_units}); return true;
    case GL_SCISSOR_BOX:
      out = ints({double(r.scissor_x), double(r.scissor_y), double(r.scissor_width), double(r.scissor_height)});
      return true;
    case GL_ALPHA_TEST_FUNC: out = ints({double(r.alpha_func)}); return true;
    case GL_ALPHA_TEST_REF: out = make(Kind::kColor, {r.alpha_ref}); return true;
    case GL_LOGIC_OP_MODE: out = ints({double(r.logic_op)}); return true;
    case GL_FOG_MODE: out = ints({double(c.fog.mode)}); return true;
    case GL_FOG_DENSITY: out = make(Kind::kFloat, {c.fog.density}); return true;
    case GL_FOG_START: out = make(Kind::kFloat, {c.fog.start}); return true;
    case GL_FOG_END: out = make(Kind::kFloat, {c.fog.end}); return true;
    case GL_FOG_INDEX: out = make(Kind::kFloat, {c.fog.index}); return true;
    case GL_FOG_COLOR: out = vec(Kind::kColor, glm::value_ptr(c.fog.color), 4); return true;
    case GL_FOG_COORD_SRC: out = ints({double(c.fog.coord_source)}); return true;
    case GL_TEXTURE_BINDING_1D: out = ints({double(c.textures.unit().binding_1d.name)}); return true;
    case GL_TEXTURE_BINDING_2D: out = ints({double(c.textures.unit().binding_2d.name)}); return true;
    case GL_TEXTURE_BINDING_3D: out = ints({double(c.textures.unit().binding_3d.name)}); return true;
    case GL_TEXTURE_BINDING_CUBE_MAP: out = ints({double(c.textures.unit().binding_cube.name)}); return true;
    case kTextureBindingRectangle: out = ints({double(c.textures.unit().binding_rect.name)}); return true;
    // GL 1.3 section 2.7 (table 6.19, 6.7): the active and client active units.
    case GL_ACTIVE_TEXTURE: out = ints({double(GL_TEXTURE0 + c.textures.active)}); return true;
    case GL_CLIENT_ACTIVE_TEXTURE: out = ints({double(GL_TEXTURE0 + c.arrays.client_active)}); return true;
    case GL_RED_BITS: case GL_GREEN_BITS: case GL_BLUE_BITS: case GL_ALPHA_BITS: out = ints({8}); return true;
    case GL_DEPTH_BITS: out = ints({double(c.depth_bits)}); return true;
    case GL_STENCIL_BITS: out = ints({double(c.stencil_bits)}); return true;
    case GL_INDEX_BITS: case GL_AUX_BUFFERS: out = ints({0}); return true;
    case GL_RGBA_MODE: out = make(Kind::kBool, {1}); return true;
    case GL_INDEX_MODE: case GL_STEREO: out = make(Kind::kBool, {0}); return true;
    case GL_DOUBLEBUFFER: out = make(Kind::kBool, {double(c.double_buffered)}); return true;
    case GL_RENDER_MODE: out = ints({double(c.render_mode)}); return true;
    // Multisampling (GL 1.3): the visual's multisample buffer, if it has one.
    case GL_SAMPLE_COVERAGE_VALUE: out = make(Kind::kFloat, {c.multisample.coverage_value}); return true;
    case GL_SAMPLE_COVERAGE_INVERT: out = make(Kind::kBool, {double(c.multisample.coverage_invert)}); return true;
    case GL_SAMPLE_BUFFERS: out = ints({c.ms.count > 0 ? 1.0 : 0.0}); return true;
    case GL_SAMPLES: out = ints({double(c.ms.count)}); return true;
    // Selection and feedback (GL 1.1 table 6.31).
    case GL_FEEDBACK_BUFFER_SIZE: out = ints({double(c.feedback.size)}); return true;
    case GL_FEEDBACK_BUFFER_TYPE: out = ints({double(c.feedback.type)}); return true;
    case GL_SELECTION_BUFFER_SIZE: out = ints({double(c.selection.size)}); return true;
    case GL_NAME_STACK_DEPTH: out = ints({double(c.selection.depth)}); return true;
    case GL_MAX_NAME_STACK_DEPTH: out = ints({double(kMaxNameStackDepth)}); return true;
    // Colour-index state, kept in an RGBA context as Mesa keeps it.
    case GL_INDEX_CLEAR_VALUE: out = ints({double(r.clear_index)}); return true;
    case GL_INDEX_WRITEMASK: out = ints({double(GLint(r.index_mask))}); return true;
    case GL_CURRENT_RASTER_INDEX: out = ints({1}); return true;
    default: return false;
  }
}

// The raster position, pixel transfer and zoom, the colour buffers and the accumulation
// buffer (GL 1.1 tables 6.6, 6.17, 6.18, 6.11, 6.26).
bool query_pixels(const GlContext& c, GLenum pname, Values& out) {
  const RasterPosition& r = c.raster_pos;
  const PixelTransfer& p = c.pixel;
  if (pname >= GL_PIXEL_MAP_I_TO_I_SIZE && pname <= GL_PIXEL_MAP_A_TO_A_SIZE) {
    out = ints({double(p.maps.maps[pname - GL_PIXEL_MAP_I_TO_I_SIZE].size())});
    return true;
  }
  switch (pname) {
    case GL_CURRENT_RASTER_POSITION: out = vec(Kind::kFloat, glm::value_ptr(r.window), 4); return true;
    case GL_CURRENT_RASTER_POSITION_VALID: out = make(Kind::kBool, {double(r.valid)}); return true;
    case GL_CURRENT_RASTER_COLOR: out = vec(Kind::kColor, glm::value_ptr(r.color), 4); return true;
    case kCurrentRasterSecondaryColor: out = vec(Kind::kColor, glm::value_ptr(r.secondary), 4); return true;
    case GL_CURRENT_RASTER_TEXTURE_COORDS: out = vec(Kind::kFloat, glm::value_ptr(r.texcoords[c.textures.active]), 4); return true;
    case GL_CURRENT_RASTER_DISTANCE: out = make(Kind::kFloat, {r.distance}); return true;
    case GL_CURRENT_RASTER_INDEX: out = make(Kind::kFloat, {r.index}); return true;
    case GL_RED_SCALE: case GL_GREEN_SCALE: case GL_BLUE_SCALE: case GL_ALPHA_SCALE:
      out = make(Kind::kFloat, {p.scale[pname == GL_RED_SCALE ? 0 : pname == GL_GREEN_SCALE ? 1 : pname == GL_BLUE_SCALE ? 2 : 3]});
      return true;
    case GL_RED_BIAS: case GL_GREEN_BIAS: case GL_BLUE_BIAS: case GL_ALPHA_BIAS:
      out = make(Kind::kFloat, {p.bias[pname == GL_RED_BIAS ? 0 : pname == GL_GREEN_BIAS ? 1 : pname == GL_BLUE_BIAS ? 2 : 3]});
      return true;
    case GL_DEPTH_SCALE: out = make(Kind::kFloat, {p.depth_scale}); return true;
    case GL_DEPTH_BIAS: out = make(Kind::kFloat, {p.depth_bias}); return true;
    case GL_INDEX_SHIFT: out = ints({double(p.index_shift)}); return true;
    case GL_INDEX_OFFSET: out = ints({double(p.index_offset)}); return true;
    case GL_MAP_COLOR: out = make(Kind::kBool, {double(p.map_color)}); return true;
    case GL_MAP_STENCIL: out = make(Kind::kBool, {double(p.map_stencil)}); return true;
    case GL_ZOOM_X: out = make(Kind::kFloat, {p.zoom_x}); return true;
    case GL_ZOOM_Y: out = make(Kind::kFloat, {p.zoom_y}); return true;
    case GL_MAX_PIXEL_MAP_TABLE: out = ints({kMaxPixelMapTable}); return true;
    case GL_DRAW_BUFFER: out = ints({double(c.buffers.draw_buffer)}); return true;
    case GL_READ_BUFFER: out = ints({double(c.buffers.read_buffer)}); return true;
    case GL_ACCUM_RED_BITS: case GL_ACCUM_GREEN_BITS: case GL_ACCUM_BLUE_BITS: case GL_ACCUM_ALPHA_BITS:
      out = ints({double(c.buffers.accum_bits)});
      return true;
    case GL_ACCUM_CLEAR_VALUE: out = vec(Kind::kColor, glm::value_ptr(c.buffers.accum_clear), 4); return true;
    default: return false;
  }
}

bool query_limits(const GlContext& c, GLenum pname, Values& out) {
  switch (pname) {
    case GL_MAX_LIGHTS: out = ints({kMaxLights}); return true;
    case GL_MAX_MODELVIEW_STACK_DEPTH: out = ints({kMaxModelviewDepth}); return true;
    case GL_MAX_PROJECTION_STACK_DEPTH: out = ints({kMaxProjectionDepth}); return true;
    case GL_MAX_TEXTURE_STACK_DEPTH: out = ints({kMaxTextureStackDepth}); return true;
    case GL_MAX_ATTRIB_STACK_DEPTH: out = ints({kMaxAttribStackDepth}); return true;
    case GL_MAX_CLIENT_ATTRIB_STACK_DEPTH: out = ints({kMaxClientAttribStackDepth}); return true;
    case GL_MAX_TEXTURE_SIZE: out = ints({kMaxTextureSize}); return true;
    case GL_MAX_TEXTURE_UNITS: out = ints({kMaxTextureUnits}); return true;
    // GL 1.3: no specific compressed texture format (texcompress.cpp).
    case GL_NUM_COMPRESSED_TEXTURE_FORMATS: out = ints({0}); return true;
    case GL_COMPRESSED_TEXTURE_FORMATS: out = ints({}); return true;
    case GL_MAX_3D_TEXTURE_SIZE: out = ints({kMax3dTextureSize}); return true;
    case GL_MAX_CUBE_MAP_TEXTURE_SIZE: out = ints({kMaxTextureSize}); return true;  // llvmpipe's: 16384
    case kMaxRectangleTextureSize: out = ints({kMaxTextureSize}); return true;
    case GL_MAX_VIEWPORT_DIMS: out = ints({kMaxViewportDim, kMaxViewportDim}); return true;
    case GL_SUBPIXEL_BITS: out = ints({8}); return true;
    case GL_PERSPECTIVE_CORRECTION_HINT: out = ints({double(c.hints[0])}); return true;
    case GL_POINT_SMOOTH_HINT: out = ints({double(c.hints[1])}); return true;
    case GL_LINE_SMOOTH_HINT: out = ints({double(c.hints[2])}); return true;
    case GL_POLYGON_SMOOTH_HINT: out = ints({double(c.hints[3])}); return true;
    case GL_FOG_HINT: out = ints({double(c.hints[4])}); return true;
    case GL_TEXTURE_COMPRESSION_HINT: out = ints({double(c.hints[6])}); return true;
    case GL_GENERATE_MIPMAP_HINT: out = ints({double(c.hints[5])}); return true;
    case GL_MAX_TEXTURE_LOD_BIAS: out = make(Kind::kFloat, {kMaxTextureLodBias}); return true;
    case GL_MAX_LIST_NESTING: out = ints({kMaxListNesting}); return true;
    case GL_MAX_EVAL_ORDER: out = ints({kMaxEvalOrder}); return true;
    case GL_MAP1_GRID_DOMAIN: out = make(Kind::kFloat, {c.eval.attribs.grid1_u1, c.eval.attribs.grid1_u2}); return true;
    case GL_MAP1_GRID_SEGMENTS: out = ints({double(c.eval.attribs.grid1_un)}); return true;
    case GL_MAP2_GRID_DOMAIN: {
      const EvalAttribs& e = c.eval.attribs;
      out = make(Kind::kFloat, {e.grid2_u1, e.grid2_u2, e.grid2_v1, e.grid2_v2});
      return true;
    }
    case GL_MAP2_GRID_SEGMENTS: out = ints({double(c.eval.attribs.grid2_un), double(c.eval.attribs.grid2_vn)}); return true;
    case GL_LIST_BASE: out = ints({double(c.lists.base)}); return true;
    case GL_LIST_INDEX: out = ints({double(c.lists.index)}); return true;
    case GL_LIST_MODE: out = ints({double(c.lists.mode)}); return true;
    default: return false;
  }
}

// Points, lines, polygon modes, edge flags and clip planes (GL 1.1 tables 6.10-6.12), with
// Mesa's limits.
bool query_prims(const GlContext& c, GLenum pname, Values& out) {
  const PrimState& p = c.prims;
  switch (pname) {
    case GL_POINT_SIZE:
      out = make(Kind::kFloat, {p.point_size});
      return true;
    case GL_POINT_SIZE_RANGE:
      out = make(Kind::kFloat, {1.0, kMaxPointSize});
      return true;
    case GL_POINT_SIZE_GRANULARITY:
      out = make(Kind::kFloat, {kSizeGranularity});
      return true;
    case GL_POINT_SIZE_MIN: out = make(Kind::kFloat, {p.point_min}); return true;
    case GL_POINT_SIZE_MAX: out = make(Kind::kFloat, {p.point_max}); return true;
    case GL_POINT_FADE_THRESHOLD_SIZE: out = make(Kind::kFloat, {p.point_fade}); return true;
    case GL_POINT_DISTANCE_ATTENUATION:
      out = make(Kind::kFloat, {p.point_attenuation.x, p.point_attenuation.y, p.point_attenuation.z});
      return true;
    case GL_LINE_WIDTH:
      out = make(Kind::kFloat, {p.line_width});
      return true;
    case GL_LINE_WIDTH_RANGE:
      out = make(Kind::kFloat, {1.0, kMaxLineWidth});
      return true;
    case GL_LINE_WIDTH_GRANULARITY:
      out = make(Kind::kFloat, {kSizeGranularity});
      return true;
    case 0x846D:  // GL_ALIASED_POINT_SIZE_RANGE (GL 1.2)
      out = make(Kind::kFloat, {1.0, kMaxPointSize});
      return true;
    case 0x846E:  // GL_ALIASED_LINE_WIDTH_RANGE (GL 1.2)
      out = make(Kind::kFloat, {1.0, kMaxLineWidth});
      return true;
    case GL_LINE_STIPPLE_PATTERN:
      out = ints({double(p.stipple_pattern)});
      return true;
    case GL_LINE_STIPPLE_REPEAT:
      out = ints({double(p.stipple_repeat)});
      return true;
    case GL_POLYGON_MODE:
      out = ints({double(p.front_mode), double(p.back_mode)});
      return true;
    case GL_MAX_CLIP_PLANES:
      out = ints({kMaxClipPlanes});
      return true;
    default:
      return false;
  }
}

bool query(GlContext& c, GLenum pname, Values& out) {
  if (bool* f = capability_flag(c, pname)) return out = make(Kind::kBool, {double(*f)}), true;
  if (bool* f = client_capability_flag(c, pname)) return out = make(Kind::kBool, {double(*f)}), true;
  return query_transform_lighting(c, pname, out) || query_raster(c, pname, out) ||
         query_prims(c, pname, out) || query_limits(c, pname, out) || query_client(c, pname, out) ||
         query_pixels(c, pname, out);
}

// Integers held as GLuint (names) read back as Mesa's TYPE_INT of a GLuint field: wrapped to
// GLint first, whatever the query's type.
GLint wrap_int(double v) { return GLint(std::uint32_t(std::int64_t(std::clamp(v, -9.0e18, 9.0e18)))); }

template <class T>
T convert(double v, Kind kind) {
  if constexpr (std::is_same_v<T, GLboolean>) {
    return v != 0.0 ? GL_TRUE : GL_FALSE;
  } else if constexpr (std::is_same_v<T, GLint>) {
    if (kind == Kind::kColor) return color_to_int(v);
    if (kind == Kind::kFloat) return lround_to_int(v);
    if (kind == Kind::kUint) return GLint(std::min(v, double(INT_MAX)));
    return wrap_int(v);
  } else {
    return kind == Kind::kInt ? T(wrap_int(v)) : T(v);
  }
}

template <class T>
void get(GlContext& c, GLenum pname, T* params) {
  Values v;
  if (!query(c, pname, v)) return c.set_error(GL_INVALID_ENUM);
  if (!params) return c.set_error(GL_INVALID_VALUE);
  for (int i = 0; i < v.n; ++i) params[i] = convert<T>(v.v[i], v.kind);
}

}  // namespace

void exec::GetBooleanv(GlContext& c, GLenum pname, GLboolean* params) { get(c, pname, params); }
void exec::GetIntegerv(GlContext& c, GLenum pname, GLint* params) { get(c, pname, params); }
void exec::GetFloatv(GlContext& c, GLenum pname, GLfloat* params) { get(c, pname, params); }
void exec::GetDoublev(GlContext& c, GLenum pname, GLdouble* params) { get(c, pname, params); }

// glGetPointerv (GL 1.1 section 6.1.11): a null `params` is ignored, as Mesa does.
void exec::GetPointerv(GlContext& c, GLenum pname, void** params) {
  const ClientArrays& a = c.arrays;
  const void* p = nullptr;
  switch (pname) {
    case GL_VERTEX_ARRAY_POINTER: p = a.vertex.pointer; break;
    case GL_NORMAL_ARRAY_POINTER: p = a.normal.pointer; break;
    case GL_COLOR_ARRAY_POINTER: p = a.color.pointer; break;
    case GL_INDEX_ARRAY_POINTER: p = a.index.pointer; break;
    case GL_TEXTURE_COORD_ARRAY_POINTER: p = a.texcoord().pointer; break;
    case GL_EDGE_FLAG_ARRAY_POINTER: p = a.edge_flag.pointer; break;
    case GL_SECONDARY_COLOR_ARRAY_POINTER: p = a.secondary_color.pointer; break;
    case GL_FOG_COORD_ARRAY_POINTER: p = a.fog_coord.pointer; break;
    case GL_FEEDBACK_BUFFER_POINTER: p = c.feedback.buffer; break;
    case GL_SELECTION_BUFFER_POINTER: p = c.selection.buffer; break;
    default: return c.set_error(GL_INVALID_ENUM);
  }
  if (params) *params = const_cast<void*>(p);
}

// GL_VERSION is that of the newest OpenGL version whose every command is implemented
// (gl/api/pending.txt; SHADELAB_GL_VERSION_NUMBER is generated from it); GL_EXTENSIONS lists
// gl/api/config.toml's extensions.
const GLubyte* exec::GetString(GlContext& c, GLenum name) {
  static const char* const kVendor = "shadelab";
  static const char* const kRenderer = "shadelab software rasterizer (OpenGL " SHADELAB_GL_VERSION_NUMBER " fixed function)";
  static const char* const kVersion = SHADELAB_GL_VERSION_NUMBER " shadelab " SHADELAB_VERSION;
  static const char* const kExtensions = SHADELAB_GL_EXTENSIONS;  // gl/api/config.toml
  const char* result = nullptr;
  switch (name) {
    case GL_VENDOR: result = kVendor; break;
    case GL_RENDERER: result = kRenderer; break;
    case GL_VERSION: result = kVersion; break;
    case GL_EXTENSIONS: result = kExtensions; break;
    default: c.set_error(GL_INVALID_ENUM);
  }
  return reinterpret_cast<const GLubyte*>(result);
}

}  // namespace shadelab::gl
