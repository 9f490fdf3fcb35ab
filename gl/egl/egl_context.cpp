// EGL contexts and pbuffers (EGL 1.5 sections 3.5.2, 3.7, 3.10; EGL_KHR_create_context,
// EGL_KHR_surfaceless_context): creation with shared textures, make-current per thread (with
// or without a surface), deferred destruction of current objects, queries, swaps. The GL
// context is the front end's (gl/src); binding and presenting are the platform layer's.
#include <algorithm>
#include <cstdio>

#include "gl/generated/version.hpp"

#include "gl/egl/egl_vendor.hpp"

namespace shadelab::gl::egl {
namespace {

thread_local Context* t_current = nullptr;

// EGL_KHR_create_context's attributes for OpenGL (EGL 1.5 section 3.7.1.1).
struct Attributes {
  EGLint major = 1, minor = 0, flags = 0, profile = EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT;
  bool robust = false;
};

bool parse(const EGLint* list, Attributes& a) {
  for (int i = 0; list && list[i] != EGL_NONE; i += 2) {
    const EGLint v = list[i + 1];
    switch (list[i]) {
      case EGL_CONTEXT_MAJOR_VERSION: a.major = v; break;
      case EGL_CONTEXT_MINOR_VERSION: a.minor = v; break;
      case EGL_CONTEXT_FLAGS_KHR: a.flags = v; break;
      case EGL_CONTEXT_OPENGL_PROFILE_MASK: a.profile = v; break;
      case EGL_CONTEXT_OPENGL_DEBUG: a.flags |= v ? EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR : 0; break;
      case EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE: a.flags |= v ? EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR : 0; break;
      case EGL_CONTEXT_OPENGL_ROBUST_ACCESS: a.robust = v != EGL_FALSE; break;
      case EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY: break;
      default: return false;
    }
  }
  return true;
}

// The OpenGL version the GL front end reports: that of the newest version whose every command
// it implements (generated from gl/api/pending.txt).
void implemented_version(int& major, int& minor) {
  major = 1, minor = 0;
  std::sscanf(SHADELAB_GL_VERSION_NUMBER, "%d.%d", &major, &minor);
}

Display* initialized_display(EGLDisplay dpy) {
  Display* d = find_display(dpy);
  if (!d) return fail(EGL_BAD_DISPLAY, static_cast<Display*>(nullptr));
  if (!d->initialized) return fail(EGL_NOT_INITIALIZED, static_cast<Display*>(nullptr));
  return d;
}

Context* find_context(Display& d, EGLContext ctx) {
  auto* c = static_cast<Context*>(ctx);
  return d.contexts.count(c) && !c->destroyed ? c : nullptr;
}

Pbuffer* find_surface(Display& d, EGLSurface surface) {
  auto* s = static_cast<Pbuffer*>(surface);
  return d.surfaces.count(s) ? s : nullptr;
}

void free_context(Display& d, Context* c) {
  d.contexts.erase(c);
  delete c;
}

}  // namespace

Pbuffer::Pbuffer(const Config& config, int width, int height, bool largest)
    : platform::Surface(config.surface, platform::ImageLayout::kRgba),
      config_(&config), requested_width_(width), requested_height_(height), largest_(largest) {}

Pbuffer::~Pbuffer() { release_context(); }

std::uint8_t* Pbuffer::allocate_image(int width, int height, int& row_pixels) {
  pixels_.assign(std::size_t(width) * std::size_t(height) * 4, 0);
  row_pixels = width;
  return pixels_.data();
}

bool Pbuffer::query_size(int& width, int& height) {
  width = requested_width_, height = requested_height_;
  return true;
}

EGLContext create_context(EGLDisplay dpy, EGLConfig config, EGLContext share, const EGLint* attributes) {
  std::lock_guard lock(vendor_mutex());
  Display* d = initialized_display(dpy);
  if (!d) return EGL_NO_CONTEXT;
  // EGL_KHR_no_config_context: without a configuration the context has the richest one's
  // depth and stencil (its GL state is fixed at creation) and draws into any pbuffer.
  const bool no_config = config == EGL_NO_CONFIG_KHR;
  const Config* cfg = no_config ? d->configs.front().get() : find_config(*d, config);
  if (!cfg) return fail(EGL_BAD_CONFIG, EGL_NO_CONTEXT);
  Context* shared = nullptr;
  if (share != EGL_NO_CONTEXT && !(shared = find_context(*d, share))) return fail(EGL_BAD_CONTEXT, EGL_NO_CONTEXT);
  Attributes a;
  if (!parse(attributes, a)) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_CONTEXT);
  constexpr EGLint kFlags = EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR | EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR |
                            EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR;
  if ((a.flags & ~kFlags) != 0) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_CONTEXT);
  // Forward-compatible contexts exist from OpenGL 3.0 on; robust buffer access is not offered.
  if (((a.flags & EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR) && a.major < 3) || a.robust ||
      (a.flags & EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR)) {
    return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
  }
  auto c = std::make_unique<Context>();
  c->config = cfg;
  c->no_config = no_config;
  c->major = a.major;
  c->gl = std::make_unique<GlContext>(GLenum(GL_RGBA), cfg->surface.depth_bits, cfg->surface.stencil_bits,
                                      shared ? shared->gl.get() : nullptr);
  configure_buffers(*c->gl, cfg->surface.double_buffered, cfg->surface.accum_bits, cfg->surface.samples);
  int major = 1, minor = 0;
  implemented_version(major, minor);
  // EGL_KHR_create_context: a version the configuration cannot provide is EGL_BAD_MATCH.
  if (a.major > major || (a.major == major && a.minor > minor)) return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
  d->contexts.insert(c.get());
  return c.release();
}

EGLBoolean destroy_context(EGLDisplay dpy, EGLContext ctx) {
  std::lock_guard lock(vendor_mutex());
  Display* d = initialized_display(dpy);
  if (!d) return EGL_FALSE;
  Context* c = find_context(*d, ctx);
  if (!c) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
  c->destroyed = true;  // a current context lives on until released (EGL 1.5 section 3.7.2)
  if (!c->current) free_context(*d, c);
  return EGL_TRUE;
}

EGLBoolean make_current(EGLDisplay dpy, EGLSurface draw, EGLSurface read, EGLContext ctx) {
  std::lock_guard lock(vendor_mutex());
  Display* d = find_display(dpy);
  const bool release = ctx == EGL_NO_CONTEXT;
  if (!d) return fail(EGL_BAD_DISPLAY, EGL_FALSE);
  if (!d->initialized && !release) return fail(EGL_NOT_INITIALIZED, EGL_FALSE);
  if (release && (draw != EGL_NO_SURFACE || read != EGL_NO_SURFACE)) return fail(EGL_BAD_MATCH, EGL_FALSE);
  Context* c = release ? nullptr : find_context(*d, ctx);
  if (!release && !c) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
  if ((draw == EGL_NO_SURFACE) != (read == EGL_NO_SURFACE)) return fail(EGL_BAD_MATCH, EGL_FALSE);
  Pbuffer* surface = nullptr;
  if (draw != EGL_NO_SURFACE) {
    surface = find_surface(*d, draw);
    if (!surface || !find_surface(*d, read)) return fail(EGL_BAD_SURFACE, EGL_FALSE);
    // Reading from another surface than the one drawn to is not implemented (the GL front end
    // reads its own framebuffer).
    if (read != draw) return fail(EGL_BAD_MATCH, EGL_FALSE);
  }
  Context* old = t_current;
  if (c && c->current && c != old) return fail(EGL_BAD_ACCESS, EGL_FALSE);  // current in another thread
  if (!platform::make_current(c ? c->gl.get() : nullptr, surface)) {
    c = nullptr;
    set_error(EGL_BAD_ALLOC);
  }
  if (old && old != c) {
    old->current = false;
    old->draw = nullptr;
    if (old->destroyed) free_context(*d, old);
  }
  t_current = c;
  if (c) c->current = true, c->draw = surface;
  return c || release ? EGL_TRUE : EGL_FALSE;
}

EGLBoolean release_thread() {
  std::lock_guard lock(vendor_mutex());
  if (Context* c = t_current) {
    Display* d = the_display();
    platform::make_current(nullptr, nullptr);
    c->current = false;
    c->draw = nullptr;
    if (c->destroyed) free_context(*d, c);
    t_current = nullptr;
  }
  set_error(EGL_SUCCESS);
  return EGL_TRUE;
}

EGLBoolean query_context(EGLDisplay dpy, EGLContext ctx, EGLint attribute, EGLint* value) {
  std::lock_guard lock(vendor_mutex());
  Display* d = initialized_display(dpy);
  if (!d) return EGL_FALSE;
  Context* c = find_context(*d, ctx);
  if (!c) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
  EGLint v = 0;
  switch (attribute) {
    case EGL_CONFIG_ID: v = c->no_config ? 0 : c->config->id; break;
    case EGL_CONTEXT_CLIENT_TYPE: v = EGL_OPENGL_API; break;
    case EGL_CONTEXT_CLIENT_VERSION: v = c->major; break;
    case EGL_RENDER_BUFFER: v = c->draw ? EGL_BACK_BUFFER : EGL_NONE; break;
    default: return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  }
  if (value) *value = v;
  return EGL_TRUE;
}

// EGL 1.5 section 3.5.2: width and height default to 0; EGL_LARGEST_PBUFFER to false; no
// texture binding (EGL_TEXTURE_FORMAT must stay EGL_NO_TEXTURE: no configuration binds).
EGLSurface create_pbuffer_surface(EGLDisplay dpy, EGLConfig config, const EGLint* attributes) {
  std::lock_guard lock(vendor_mutex());
  Display* d = initialized_display(dpy);
  if (!d) return EGL_NO_SURFACE;
  const Config* cfg = find_config(*d, config);
  if (!cfg) return fail(EGL_BAD_CONFIG, EGL_NO_SURFACE);
  EGLint width = 0, height = 0, largest = EGL_FALSE;
  for (int i = 0; attributes && attributes[i] != EGL_NONE; i += 2) {
    const EGLint v = attributes[i + 1];
    switch (attributes[i]) {
      case EGL_WIDTH: width = v; break;
      case EGL_HEIGHT: height = v; break;
      case EGL_LARGEST_PBUFFER: largest = v; break;
      case EGL_TEXTURE_FORMAT: case EGL_TEXTURE_TARGET:
        if (v != EGL_NO_TEXTURE) return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
        break;
      case EGL_MIPMAP_TEXTURE: case EGL_GL_COLORSPACE: case EGL_VG_ALPHA_FORMAT: case EGL_VG_COLORSPACE: break;
      default: return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SURFACE);
    }
  }
  if (width < 0 || height < 0) return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
  if (width > kMaxBufferDim || height > kMaxBufferDim) {
    if (!largest) return fail(EGL_BAD_ALLOC, EGL_NO_SURFACE);
    width = std::min(width, kMaxBufferDim), height = std::min(height, kMaxBufferDim);
  }
  auto s = std::make_unique<Pbuffer>(*cfg, width, height, largest != EGL_FALSE);
  d->surfaces.insert(s.get());
  return s.release();
}

EGLBoolean destroy_surface(EGLDisplay dpy, EGLSurface surface) {
  std::lock_guard lock(vendor_mutex());
  Display* d = initialized_display(dpy);
  if (!d) return EGL_FALSE;
  Pbuffer* s = find_surface(*d, surface);
  if (!s) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  d->surfaces.erase(s);
  delete s;  // a context current on it draws into nothing from now on
  return EGL_TRUE;
}

EGLBoolean query_surface(EGLDisplay dpy, EGLSurface surface, EGLint attribute, EGLint* value) {
  std::lock_guard lock(vendor_mutex());
  Display* d = initialized_display(dpy);
  if (!d) return EGL_FALSE;
  Pbuffer* s = find_surface(*d, surface);
  if (!s) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  EGLint v = 0;
  switch (attribute) {
    case EGL_WIDTH: v = s->requested_width(); break;
    case EGL_HEIGHT: v = s->requested_height(); break;
    case EGL_CONFIG_ID: v = s->egl_config().id; break;
    case EGL_LARGEST_PBUFFER: v = s->largest() ? EGL_TRUE : EGL_FALSE; break;
    case EGL_TEXTURE_FORMAT: case EGL_TEXTURE_TARGET: v = EGL_NO_TEXTURE; break;
    case EGL_MIPMAP_TEXTURE: case EGL_MIPMAP_LEVEL: v = 0; break;
    case EGL_RENDER_BUFFER: v = EGL_BACK_BUFFER; break;
    case EGL_SWAP_BEHAVIOR: v = EGL_BUFFER_PRESERVED; break;
    case EGL_MULTISAMPLE_RESOLVE: v = EGL_MULTISAMPLE_RESOLVE_DEFAULT; break;
    case EGL_HORIZONTAL_RESOLUTION: case EGL_VERTICAL_RESOLUTION: case EGL_PIXEL_ASPECT_RATIO: v = EGL_UNKNOWN; break;
    case EGL_GL_COLORSPACE: v = EGL_GL_COLORSPACE_LINEAR; break;
    default: return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  }
  if (value) *value = v;
  return EGL_TRUE;
}

EGLBoolean surface_attrib(EGLDisplay dpy, EGLSurface surface, EGLint attribute, EGLint value) {
  std::lock_guard lock(vendor_mutex());
  Display* d = initialized_display(dpy);
  if (!d) return EGL_FALSE;
  if (!find_surface(*d, surface)) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  switch (attribute) {
    case EGL_MIPMAP_LEVEL: return EGL_TRUE;  // no texture binding: nothing it applies to
    case EGL_SWAP_BEHAVIOR:  // pbuffers keep their contents either way
      return value == EGL_BUFFER_PRESERVED || value == EGL_BUFFER_DESTROYED ? EGL_TRUE : fail(EGL_BAD_PARAMETER, EGL_FALSE);
    case EGL_MULTISAMPLE_RESOLVE:
      return value == EGL_MULTISAMPLE_RESOLVE_DEFAULT ? EGL_TRUE : fail(EGL_BAD_MATCH, EGL_FALSE);
    default: return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  }
}

// EGL 1.5 section 3.10.1: swapping a pbuffer has no effect (but the implicit flush).
EGLBoolean swap_buffers(EGLDisplay dpy, EGLSurface surface) {
  std::lock_guard lock(vendor_mutex());
  Display* d = initialized_display(dpy);
  if (!d) return EGL_FALSE;
  Pbuffer* s = find_surface(*d, surface);
  if (!s) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  if (!t_current || t_current->draw != s) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  glFlush();
  return EGL_TRUE;
}

// Nothing is shown on a display, so there is no vertical retrace to wait for.
EGLBoolean swap_interval(EGLDisplay dpy, EGLint /*interval*/) {
  std::lock_guard lock(vendor_mutex());
  if (!initialized_display(dpy)) return EGL_FALSE;
  if (!t_current) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
  return t_current->draw ? EGL_TRUE : fail(EGL_BAD_SURFACE, EGL_FALSE);
}

void terminate(Display& d) {
  for (auto it = d.contexts.begin(); it != d.contexts.end();) {
    Context* c = *it;
    if (c->current) {
      c->destroyed = true;
      ++it;
    } else {
      it = d.contexts.erase(it);
      delete c;
    }
  }
  // A surface current to a context stays until it is destroyed after its release.
  for (auto it = d.surfaces.begin(); it != d.surfaces.end();) {
    Pbuffer* s = *it;
    if (s->is_bound()) {
      ++it;
    } else {
      it = d.surfaces.erase(it);
      delete s;
    }
  }
  d.initialized = false;
}

}  // namespace shadelab::gl::egl
