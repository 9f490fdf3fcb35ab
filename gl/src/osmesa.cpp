// The OSMesa interface: contexts that render into a GL_UNSIGNED_BYTE buffer owned by the
// caller, made current per thread. Buffer sizes and depth/stencil formats follow Mesa 22's
// OSMesa (checked against libOSMesa). It owns the contexts and never touches GL state
// beyond the initial viewport.
#include <GL/osmesa.h>

#include <new>

#include "gl/src/osmesa_context.hpp"
#include "gl/src/proc_table.hpp"

using namespace shadelab::gl;

namespace {

bool supported_format(GLenum format) {
  return format == OSMESA_RGBA || format == OSMESA_BGRA || format == OSMESA_ARGB ||
         format == OSMESA_RGB || format == OSMESA_BGR;
}

// Mesa's choice of depth/stencil buffer: any stencil gives 8 stencil bits packed with a
// 24-bit depth (when depth is asked for); otherwise 24 bits from 24 up, 16 from 16 up.
void choose_bits(GLint depth, GLint stencil, int& depth_bits, int& stencil_bits) {
  stencil_bits = stencil > 0 ? 8 : 0;
  if (depth > 0 && stencil_bits > 0) depth_bits = 24;
  else if (depth >= 24) depth_bits = 24;
  else if (depth >= 16) depth_bits = 16;
  else depth_bits = 0;
}

OSMesaContext create(GLenum format, GLint depth, GLint stencil, GLint accum, OSMesaContext share, int samples = 0) {
  if (!supported_format(format)) return nullptr;
  int depth_bits = 0, stencil_bits = 0;
  choose_bits(depth, stencil, depth_bits, stencil_bits);
  try {
    auto* c = new osmesa_context(format, depth_bits, stencil_bits, share);
    configure_buffers(*c, false, accum, samples);  // an OSMesa buffer is single-buffered
    return c;
  } catch (...) {
    return nullptr;
  }
}

// Binds the caller's buffer: the framebuffer takes its size (keeping depth and stencil when
// the size is unchanged) and its pixels.
void bind_buffer(GlContext& c, void* buffer, int width, int height) {
  settle_clears(c);  // depth is kept
  c.user.data = buffer;
  c.user.width = width;
  c.user.height = height;
  c.user.format = c.buffer_format;
  if (c.fb.width != width || c.fb.height != height) c.fb.resize(width, height);
  import_user_buffer(c);
  reset_tiles(c);
  if (!c.ever_current) set_initial_window_state(c, width, height);
}

}  // namespace

extern "C" {

OSMesaContext GLAPIENTRY OSMesaCreateContext(GLenum format, OSMesaContext sharelist) {
  return create(format, 24, 8, 0, sharelist);
}

OSMesaContext GLAPIENTRY OSMesaCreateContextExt(GLenum format, GLint depthBits, GLint stencilBits,
                                                GLint accumBits, OSMesaContext sharelist) {
  return create(format, depthBits, stencilBits, accumBits, sharelist);
}

// Attributes as Mesa reads them; only OpenGL 1.x compatibility contexts can be had.
OSMesaContext GLAPIENTRY OSMesaCreateContextAttribs(const int* attribList, OSMesaContext sharelist) {
  GLenum format = OSMESA_RGBA;
  GLint depth = 24, stencil = 8, accum = 0, samples = 0;
  for (int i = 0; attribList && i < 64 && attribList[i] != 0; i += 2) {
    int value = attribList[i + 1];
    switch (attribList[i]) {
      case OSMESA_FORMAT: format = GLenum(value); break;
      case OSMESA_DEPTH_BITS: depth = value; break;
      case OSMESA_STENCIL_BITS: stencil = value; break;
      case OSMESA_ACCUM_BITS: accum = value; break;
      case OSMESA_PROFILE: if (value != OSMESA_COMPAT_PROFILE) return nullptr; break;
      case OSMESA_CONTEXT_MAJOR_VERSION: if (value > 1) return nullptr; break;
      case OSMESA_CONTEXT_MINOR_VERSION: break;
      case OSMESA_SAMPLES_SHADELAB:  // as GLX and EGL choose: at least as many, here 4
        if (value < 0 || value > 4) return nullptr;
        samples = value > 0 ? 4 : 0;
        break;
      default: return nullptr;
    }
  }
  return create(format, depth, stencil, accum, sharelist, samples);
}

void GLAPIENTRY OSMesaDestroyContext(OSMesaContext ctx) {
  if (!ctx) return;
  present(*ctx);  // what was drawn reaches the caller's buffer, as a flush would do
  if (current_context() == ctx) current_context() = nullptr;
  delete ctx;
}

// OSMesaMakeCurrent(NULL, NULL, ...) releases the current context, as in Mesa.
GLboolean GLAPIENTRY OSMesaMakeCurrent(OSMesaContext ctx, void* buffer, GLenum type,
                                       GLsizei width, GLsizei height) {
  // Drawing reaches the caller's buffer at a flush; changing or rebinding the current
  // context is one (and rebinding reads the buffer back).
  if (GlContext* old = current_context()) present(*old);
  if (!ctx && !buffer) {
    current_context() = nullptr;
    return GL_TRUE;
  }
  if (ctx) present(*ctx);
  if (!ctx || !buffer || type != GL_UNSIGNED_BYTE || width < 1 || height < 1 ||
      width > kMaxBufferDim || height > kMaxBufferDim) {
    return GL_FALSE;
  }
  try {
    bind_buffer(*ctx, buffer, width, height);
  } catch (...) {
    return GL_FALSE;
  }
  current_context() = ctx;
  return GL_TRUE;
}

OSMesaContext GLAPIENTRY OSMesaGetCurrentContext(void) {
  return static_cast<osmesa_context*>(current_context());
}

// A new layout rewrites the whole buffer in it at once.
void GLAPIENTRY OSMesaPixelStore(GLint pname, GLint value) {
  with_context([&](GlContext& c) {
    if (pname == OSMESA_ROW_LENGTH) {
      if (value < 0) return c.set_error(GL_INVALID_VALUE);
      c.user.row_length = value;
    } else if (pname == OSMESA_Y_UP) {
      c.user.y_up = value != 0;
    } else {
      return c.set_error(GL_INVALID_ENUM);
    }
    // The colour is copied out in the new layout, and the buffer used as the colour buffer
    // again only if that layout is the framebuffer's.
    if (c.pipeline) c.pipeline->finish_draws();
    c.fb.color.detach();
    mark_all_changed(c);
    present(c);
    if (lends_color(c)) import_user_buffer(c);
  });
}

void GLAPIENTRY OSMesaGetIntegerv(GLint pname, GLint* value) {
  with_context([&](GlContext& c) {
    if (!value) return;
    switch (pname) {
      case OSMESA_WIDTH: *value = c.user.width; break;
      case OSMESA_HEIGHT: *value = c.user.height; break;
      case OSMESA_FORMAT: *value = GLint(c.user.format); break;
      case OSMESA_TYPE: *value = GL_UNSIGNED_BYTE; break;
      case OSMESA_ROW_LENGTH: *value = c.user.row_length; break;
      case OSMESA_Y_UP: *value = c.user.y_up ? 1 : 0; break;
      case OSMESA_MAX_WIDTH: case OSMESA_MAX_HEIGHT: *value = kMaxBufferDim; break;
      default: c.set_error(GL_INVALID_ENUM);
    }
  });
}

// Depth values as Mesa exposes them: GLushort for a 16-bit buffer, else GLuint with the
// 24-bit depth in the low bits and the stencil value in the high byte. The copy is refreshed
// here and at every glFinish/glFlush.
GLboolean GLAPIENTRY OSMesaGetDepthBuffer(OSMesaContext c, GLint* width, GLint* height,
                                          GLint* bytesPerValue, void** buffer) {
  bool ok = c && c->depth_bits > 0 && c->fb.width > 0;
  if (ok) {
    try {
      export_depth(*c);
      c->depth_exported = true;
    } catch (...) {
      ok = false;
    }
  }
  if (width) *width = ok ? c->fb.width : 0;
  if (height) *height = ok ? c->fb.height : 0;
  if (bytesPerValue) *bytesPerValue = ok ? (c->depth_bits == 16 ? 2 : 4) : 0;
  if (buffer) *buffer = ok ? c->depth_export.data() : nullptr;
  return ok ? GL_TRUE : GL_FALSE;
}

GLboolean GLAPIENTRY OSMesaGetColorBuffer(OSMesaContext c, GLint* width, GLint* height,
                                          GLint* format, void** buffer) {
  bool ok = c && c->user.data;
  if (ok) present(*c);
  if (width) *width = ok ? c->user.width : 0;
  if (height) *height = ok ? c->user.height : 0;
  if (format) *format = ok ? GLint(c->user.format) : 0;
  if (buffer) *buffer = ok ? c->user.data : nullptr;
  return ok ? GL_TRUE : GL_FALSE;
}

// Colours are always clamped to [0, 1]: there is nothing to switch.
void GLAPIENTRY OSMesaColorClamp(GLboolean /*enable*/) {}

// Every gl* and OSMesa* function of the library (the generated table, proc_table.hpp).
OSMESAproc GLAPIENTRY OSMesaGetProcAddress(const char* funcName) {
  return reinterpret_cast<OSMESAproc>(find_proc(funcName));
}

}  // extern "C"
