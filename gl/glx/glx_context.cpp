// GLX contexts (GLX 1.4 sections 3.3.7 and 3.5, GLX_ARB_create_context): creation with
// sharing of textures, make-current per thread, destruction deferred while current,
// glXQueryContext, glXIsDirect. A GLX context is a GL front-end context (gl/src) plus what GLX
// knows of it; rendering and presenting are the platform layer's (gl/src/platform).
#include "gl/glx/glx_protocol.hpp"
#include "gl/glx/glx_context.hpp"


#include <cstdio>

#include "gl/generated/version.hpp"
#include <set>

#include "gl/glx/glx_surface.hpp"

namespace shadelab::gl::glx {
namespace {

std::set<GlxContext*>& contexts() {
  static auto* set = new std::set<GlxContext*>;
  return *set;
}

thread_local GlxContext* t_current = nullptr;

// The OpenGL version the GL front end reports: that of the newest version whose every command
// it implements (generated from gl/api/pending.txt).
void implemented_version(int& major, int& minor) {
  major = 1, minor = 0;
  std::sscanf(SHADELAB_GL_VERSION_NUMBER, "%d.%d", &major, &minor);
}

// GLX_ARB_create_context's attributes. False with the X error to raise.
struct Attributes {
  int major = 1, minor = 0, flags = 0, profile = GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB;
  int render_type = GLX_RGBA_TYPE;
};

bool parse_attributes(const int* list, Attributes& a, int& error, bool& glx_error) {
  glx_error = false;
  for (int i = 0; list && list[i] != None; i += 2) {
    const int value = list[i + 1];
    switch (list[i]) {
      case GLX_CONTEXT_MAJOR_VERSION_ARB: a.major = value; break;
      case GLX_CONTEXT_MINOR_VERSION_ARB: a.minor = value; break;
      case GLX_CONTEXT_FLAGS_ARB: a.flags = value; break;
      case GLX_CONTEXT_PROFILE_MASK_ARB: a.profile = value; break;
      case GLX_RENDER_TYPE: a.render_type = value; break;
      case GLX_SCREEN: break;
      default: error = BadValue; return false;
    }
  }
  constexpr int kKnownFlags = GLX_CONTEXT_DEBUG_BIT_ARB | GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB;
  if ((a.flags & ~kKnownFlags) != 0 || a.render_type != GLX_RGBA_TYPE) {
    error = BadValue;
    return false;
  }
  if (a.profile != GLX_CONTEXT_CORE_PROFILE_BIT_ARB && a.profile != GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB) {
    error = GLXBadProfileARB, glx_error = true;
    return false;
  }
  // Forward-compatible contexts exist from OpenGL 3.0 on (GLX_ARB_create_context).
  if ((a.flags & GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB) && a.major < 3) {
    error = BadMatch;
    return false;
  }
  return true;
}

GLXContext handle(GlxContext* c) { return reinterpret_cast<GLXContext>(c); }

void free_context(GlxContext* c) {
  contexts().erase(c);
  delete c;
}

// Window surfaces whose X window is gone and that no context draws into are dropped (the X
// server never says when a window dies; GLUT programs make and destroy windows).
void prune_windows(DisplayState& d) {
  for (auto it = d.surfaces.begin(); it != d.surfaces.end();) {
    int w = 0, h = 0;
    XSurface& s = *it->second;
    bool gone = s.kind() == XSurface::Kind::kWindow && !s.is_bound() && !s.drawable_size(w, h);
    it = gone ? d.surfaces.erase(it) : std::next(it);
  }
}

}  // namespace

GlxContext* find_context(GLXContext handle) {
  auto* c = reinterpret_cast<GlxContext*>(handle);
  return contexts().count(c) && !c->destroyed ? c : nullptr;
}

GlxContext* current_glx_context() { return t_current; }

GLXContext create_context(Display* dpy, const FbConfig* config, GLXContext share, const int* attributes,
                          int minor_opcode) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  if (!d) return nullptr;
  if (!config) {
    send_glx_error(dpy, GLXBadFBConfig, 0, minor_opcode);
    return nullptr;
  }
  GlxContext* shared = nullptr;
  if (share && !(shared = find_context(share))) {
    send_glx_error(dpy, GLXBadContext, 0, minor_opcode);
    return nullptr;
  }
  Attributes a;
  int error = 0;
  bool glx_error = false;
  if (!parse_attributes(attributes, a, error, glx_error)) {
    if (glx_error) send_glx_error(dpy, error, 0, minor_opcode);
    else send_x_error(dpy, static_cast<unsigned char>(error), 0, minor_opcode);
    return nullptr;
  }
  auto c = std::make_unique<GlxContext>();
  c->dpy = dpy;
  c->config = config;
  const platform::SurfaceConfig& s = config->surface;
  c->gl = std::make_unique<GlContext>(GLenum(GL_RGBA), s.depth_bits, s.stencil_bits,
                                      shared ? shared->gl.get() : nullptr);
  configure_buffers(*c->gl, s.double_buffered, s.accum_bits, s.samples);
  int major = 1, minor = 0;
  implemented_version(major, minor);
  if (a.major > major || (a.major == major && a.minor > minor)) {
    // A version shadelab does not implement: what Mesa's GLX raises for a version its driver
    // lacks (GLX_ARB_create_context: "does not support ... the requested API major and minor
    // version").
    send_glx_error(dpy, GLXBadFBConfig, 0, minor_opcode);
    return nullptr;
  }
  contexts().insert(c.get());
  return handle(c.release());
}

bool bind_context(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx, int minor_opcode) {
  std::lock_guard lock(vendor_mutex());
  GlxContext* old = t_current;
  GlxContext* c = nullptr;
  if (ctx && !(c = find_context(ctx))) {
    send_glx_error(dpy, GLXBadContext, 0, minor_opcode);
    return false;
  }
  if (c && c->current && c != old) {  // current in another thread (GLX 1.4 section 3.3.7)
    send_x_error(dpy, BadAccess, 0, minor_opcode);
    return false;
  }
  XSurface* surface = nullptr;
  if (c && (draw != None || read != None)) {
    // No drawable at all is accepted, as Mesa accepts it (GLX_ARB_create_context lets a context
    // be current without a default framebuffer): the context then draws into nothing shown.
    if (read != draw) {
      // Reading from another drawable than the one drawn to is not implemented: the GL front
      // end reads its own framebuffer.
      send_x_error(dpy, BadMatch, read, minor_opcode);
      return false;
    }
    int error = 0;
    surface = surface_for(*display_state(dpy), draw, *c->config, error);
    if (!surface) {
      send_glx_error(dpy, error, draw, minor_opcode);
      return false;
    }
  }
  if (!platform::make_current(c ? c->gl.get() : nullptr, surface)) {
    send_x_error(dpy, BadAlloc, draw, minor_opcode);
    c = nullptr;
  }
  if (old && old != c) {
    old->current = false;
    old->draw = old->read = None;
    if (old->destroyed) free_context(old);
  }
  t_current = c;
  if (c) c->current = true, c->draw = draw, c->read = read, c->dpy = dpy;
  return c != nullptr || ctx == nullptr;
}

Bool make_current(Display* dpy, GLXDrawable drawable, GLXContext ctx) {
  return bind_context(dpy, drawable, drawable, ctx, X_GLXMakeCurrent) ? True : False;
}

Bool make_context_current(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx) {
  return bind_context(dpy, draw, read, ctx, X_GLXMakeContextCurrent) ? True : False;
}

void destroy_context(Display* dpy, GLXContext ctx) {
  std::lock_guard lock(vendor_mutex());
  GlxContext* c = find_context(ctx);
  if (!c) {
    send_glx_error(dpy, GLXBadContext, 0, X_GLXDestroyContext);
    return;
  }
  // A current context lives on until it is no longer current (GLX 1.4 section 3.3.7).
  c->destroyed = true;
  if (!c->current) free_context(c);
  if (DisplayState* d = display_state(dpy)) prune_windows(*d);
}

Bool is_direct(Display* dpy, GLXContext ctx) {
  std::lock_guard lock(vendor_mutex());
  if (!find_context(ctx)) {
    send_glx_error(dpy, GLXBadContext, 0, X_GLXIsDirect);
    return False;
  }
  return True;  // rendering never goes through the X server
}

int query_context(Display* dpy, GLXContext ctx, int attribute, int* value) {
  std::lock_guard lock(vendor_mutex());
  GlxContext* c = find_context(ctx);
  if (!c) {
    send_glx_error(dpy, GLXBadContext, 0, X_GLXQueryContext);
    return GLXBadContext;
  }
  int v = 0;
  switch (attribute) {
    case GLX_FBCONFIG_ID: v = c->config->id; break;
    case GLX_RENDER_TYPE: v = GLX_RGBA_TYPE; break;
    case GLX_SCREEN: v = c->config->screen; break;
    default: return GLX_BAD_ATTRIBUTE;
  }
  if (value) *value = v;
  return Success;
}

}  // namespace shadelab::gl::glx
