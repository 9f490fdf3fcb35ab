// glEnable/glDisable/glIsEnabled, client state, glGetError, glHint, glPixelStore, glFinish and
// glFlush (GL 1.1 sections 2.5, 2.8, 5.6, 5.5, 3.6.1). State only; nothing is drawn here.
#include <cmath>

#include "gl/generated/exec.hpp"
#include "gl/src/capture.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {

// The flag behind an enable capability, or nullptr for one shadelab does not accept.
// Capabilities shadelab does not know are rejected with GL_INVALID_ENUM.
bool* capability_flag(GlContext& c, GLenum cap) {
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + kMaxLights) return &c.lighting.lights[cap - GL_LIGHT0].enabled;
  if (cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + kMaxClipPlanes)
    return &c.prims.clip_enabled[cap - GL_CLIP_PLANE0];
  switch (cap) {
    case GL_LIGHTING: return &c.lighting.enabled;
    case GL_NORMALIZE: return &c.lighting.normalize;
    case GL_RESCALE_NORMAL: return &c.lighting.rescale_normal;
    case GL_COLOR_MATERIAL: return &c.lighting.color_material;
    case GL_DEPTH_TEST: return &c.raster.depth_test;
    case GL_BLEND: return &c.raster.blend;
    case GL_CULL_FACE: return &c.raster.cull;
    case GL_STENCIL_TEST: return &c.raster.stencil_test;
    case GL_POLYGON_OFFSET_FILL: return &c.raster.polygon_offset_fill;
    case GL_DITHER: return &c.raster.dither;
    case GL_SCISSOR_TEST: return &c.raster.scissor_test;
    case GL_ALPHA_TEST: return &c.raster.alpha_test;
    case GL_COLOR_LOGIC_OP: return &c.raster.color_logic_op;
    case GL_INDEX_LOGIC_OP: return &c.raster.index_logic_op;  // = GL 1.0's GL_LOGIC_OP
    case GL_POLYGON_STIPPLE: return &c.raster.polygon_stipple;
    case GL_FOG: return &c.fog.enabled;
    case GL_COLOR_SUM: return &c.fog.color_sum;
    case GL_TEXTURE_1D: return &c.textures.unit().enabled_1d;
    case GL_TEXTURE_2D: return &c.textures.unit().enabled_2d;
    case GL_TEXTURE_3D: return &c.textures.unit().enabled_3d;
    case GL_TEXTURE_CUBE_MAP: return &c.textures.unit().enabled_cube;
    case kTextureRectangle: return &c.textures.unit().enabled_rect;
    case kPointSprite: return &c.prims.point_sprite;
    case GL_TEXTURE_GEN_S: return &c.textures.unit().gen[0].enabled;
    case GL_TEXTURE_GEN_T: return &c.textures.unit().gen[1].enabled;
    case GL_TEXTURE_GEN_R: return &c.textures.unit().gen[2].enabled;
    case GL_TEXTURE_GEN_Q: return &c.textures.unit().gen[3].enabled;
    case GL_POINT_SMOOTH: return &c.prims.point_smooth;
    case GL_LINE_SMOOTH: return &c.prims.line_smooth;
    case GL_LINE_STIPPLE: return &c.prims.line_stipple;
    case GL_POLYGON_OFFSET_POINT: return &c.prims.offset_point;
    case GL_POLYGON_OFFSET_LINE: return &c.prims.offset_line;
    case GL_POLYGON_SMOOTH: return &c.prims.polygon_smooth;
    case GL_MULTISAMPLE: return &c.multisample.enabled;
    case GL_SAMPLE_ALPHA_TO_COVERAGE: return &c.multisample.alpha_to_coverage;
    case GL_SAMPLE_ALPHA_TO_ONE: return &c.multisample.alpha_to_one;
    case GL_SAMPLE_COVERAGE: return &c.multisample.coverage;
    default: return eval_capability_flag(c, cap);
  }
}

bool* client_capability_flag(GlContext& c, GLenum cap) {
  switch (cap) {
    case GL_VERTEX_ARRAY: return &c.arrays.vertex.enabled;
    case GL_NORMAL_ARRAY: return &c.arrays.normal.enabled;
    case GL_COLOR_ARRAY: return &c.arrays.color.enabled;
    case GL_TEXTURE_COORD_ARRAY: return &c.arrays.texcoord().enabled;
    case GL_INDEX_ARRAY: return &c.arrays.index.enabled;
    case GL_EDGE_FLAG_ARRAY: return &c.arrays.edge_flag.enabled;
    case GL_SECONDARY_COLOR_ARRAY: return &c.arrays.secondary_color.enabled;
    case GL_FOG_COORD_ARRAY: return &c.arrays.fog_coord.enabled;
    default: return nullptr;
  }
}

namespace {

// The client arrays are accepted too and set the array's flag, as Mesa's glEnable does.
void set_cap(GlContext& c, GLenum cap, bool on) {
  bool* flag = capability_flag(c, cap);
  if (!flag) flag = client_capability_flag(c, cap);
  if (!flag) return c.set_error(GL_INVALID_ENUM);
  *flag = on;
  if (cap == GL_COLOR_MATERIAL && on) apply_color_material(c);
}

void set_client_cap(GlContext& c, GLenum cap, bool on) {
  bool* flag = client_capability_flag(c, cap);
  if (!flag) return c.set_error(GL_INVALID_ENUM);
  *flag = on;
}

int hint_slot(GLenum target) {
  switch (target) {
    case GL_PERSPECTIVE_CORRECTION_HINT: return 0;
    case GL_POINT_SMOOTH_HINT: return 1;
    case GL_LINE_SMOOTH_HINT: return 2;
    case GL_POLYGON_SMOOTH_HINT: return 3;
    case GL_FOG_HINT: return 4;
    case GL_GENERATE_MIPMAP_HINT: return 5;  // GL 1.4: accepted, changes nothing (as Mesa)
    case GL_TEXTURE_COMPRESSION_HINT: return 6;
    default: return -1;
  }
}

// glPixelStore (GL 1.1 section 3.6.1): alignment 1, 2, 4 or 8; lengths and skips >= 0.
void pixel_store(GlContext& c, GLenum pname, double value) {
  bool pack = pname >= GL_PACK_SWAP_BYTES && pname <= GL_PACK_ALIGNMENT;
  bool unpack = pname >= GL_UNPACK_SWAP_BYTES && pname <= GL_UNPACK_ALIGNMENT;
  GLint* images = nullptr;  // GL 1.2's image height and skip images (3D images)
  switch (pname) {
    case GL_PACK_IMAGE_HEIGHT: images = &c.pack.image_height; break;
    case GL_PACK_SKIP_IMAGES: images = &c.pack.skip_images; break;
    case GL_UNPACK_IMAGE_HEIGHT: images = &c.unpack.image_height; break;
    case GL_UNPACK_SKIP_IMAGES: images = &c.unpack.skip_images; break;
    default: break;
  }
  if (images) {
    const double rounded = value < 0.0 ? std::ceil(value - 0.5) : std::floor(value + 0.5);
    if (!(rounded >= 0.0 && rounded <= 1e9)) return c.set_error(GL_INVALID_VALUE);
    *images = GLint(rounded);
    return;
  }
  if (!pack && !unpack) return c.set_error(GL_INVALID_ENUM);
  PixelStore& s = pack ? c.pack : c.unpack;
  GLenum base = pack ? GL_PACK_SWAP_BYTES : GL_UNPACK_SWAP_BYTES;
  GLenum which = pname - base;  // 0 swap, 1 lsb, 2 row length, 3 skip rows, 4 skip pixels, 5 align
  if (which <= 1) {  // glPixelStoref rounds its value first, as Mesa does
    (which == 0 ? s.swap_bytes : s.lsb_first) = std::fabs(value) >= 0.5;
    return;
  }
  // Rounded to the nearest integer, halves away from zero (Mesa's IROUND), then checked: -0.1
  // is 0, -0.9 is -1 and an error.
  const double rounded = value < 0.0 ? std::ceil(value - 0.5) : std::floor(value + 0.5);
  if (!(rounded >= 0.0 && rounded <= 1e9)) return c.set_error(GL_INVALID_VALUE);
  GLint v = GLint(rounded);
  if (which == 5) {
    if (v != 1 && v != 2 && v != 4 && v != 8) return c.set_error(GL_INVALID_VALUE);
    s.alignment = v;
  } else {
    (which == 2 ? s.row_length : which == 3 ? s.skip_rows : s.skip_pixels) = v;
  }
}

void finish_drawing(GlContext& c) {
  if (c.surface) {
    // The draws are rasterized (a double-buffered drawable's back buffer is presented at the
    // swap, with the clears left to it); the drawable presents what it shows.
    if (c.pipeline) c.pipeline->finish_draws();
    return c.surface->flushed(c);
  }
  present(c);
  if (c.depth_exported) export_depth(c);
  capture_frame_end(c);  // an OSMesa buffer's frame
}

}  // namespace

void exec::Enable(GlContext& c, GLenum cap) { set_cap(c, cap, true); }
void exec::Disable(GlContext& c, GLenum cap) { set_cap(c, cap, false); }
void exec::EnableClientState(GlContext& c, GLenum cap) { set_client_cap(c, cap, true); }
void exec::DisableClientState(GlContext& c, GLenum cap) { set_client_cap(c, cap, false); }

GLboolean exec::IsEnabled(GlContext& c, GLenum cap) {
  bool* flag = capability_flag(c, cap);
  if (!flag) flag = client_capability_flag(c, cap);
  if (!flag) {
    c.set_error(GL_INVALID_ENUM);
    return GL_FALSE;
  }
  return *flag ? GL_TRUE : GL_FALSE;
}

// Returns and clears the recorded error. Between glBegin and glEnd it is itself an error and
// returns 0, as Mesa does (the entry point's rule).
GLenum exec::GetError(GlContext& c) {
  GLenum result = c.error;
  c.error = GL_NO_ERROR;
  return result;
}

void exec::Hint(GlContext& c, GLenum target, GLenum mode) {
  int slot = hint_slot(target);
  if (slot < 0 || (mode != GL_DONT_CARE && mode != GL_FASTEST && mode != GL_NICEST)) {
    return c.set_error(GL_INVALID_ENUM);
  }
  c.hints[std::size_t(slot)] = mode;
}

void exec::PixelStorei(GlContext& c, GLenum pname, GLint param) { pixel_store(c, pname, param); }
void exec::PixelStoref(GlContext& c, GLenum pname, GLfloat param) { pixel_store(c, pname, param); }

// Drawing reaches the caller's buffer here (and when the current context changes), as with
// Mesa's llvmpipe, which renders at a flush; these two also refresh the depth values handed
// out by OSMesaGetDepthBuffer.
void exec::Finish(GlContext& c) { finish_drawing(c); }
void exec::Flush(GlContext& c) { finish_drawing(c); }

}  // namespace shadelab::gl
