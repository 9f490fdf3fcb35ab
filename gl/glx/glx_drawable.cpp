// GLX drawables (GLX 1.4 sections 3.3.4 to 3.3.6, 3.3.9 to 3.3.11): windows (made into
// surfaces at their first binding, or by glXCreateWindow), GLX pixmaps, pbuffers, their
// queries and events, glXSwapBuffers, glXWaitGL and glXWaitX. The pixels are the platform
// layer's; this file only finds, makes and destroys surfaces.

#include "gl/glx/glx_protocol.hpp"
#include "gl/glx/glx_context.hpp"
#include "gl/glx/glx_surface.hpp"

namespace shadelab::gl::glx {
namespace {

// The visual and size of an X window, or false (not a window, or a visual the presenting
// cannot write).
bool window_visual(Display* dpy, Window window, XVisualInfo& visual, platform::ImageLayout& layout) {
  XWindowAttributes attributes{};
  {
    ErrorTrap trap(dpy);
    Status ok = XGetWindowAttributes(dpy, window, &attributes);
    if (trap.finish() != 0 || !ok) return false;
  }
  XVisualInfo templ{};
  templ.visualid = XVisualIDFromVisual(attributes.visual);
  int n = 0;
  XVisualInfo* found = XGetVisualInfo(dpy, VisualIDMask, &templ, &n);
  if (!found) return false;
  visual = found[0];
  XFree(found);
  return visual_layout(dpy, visual, layout);
}

XSurface* find_surface(Display* dpy, GLXDrawable drawable) {
  DisplayState* d = display_state(dpy);
  if (!d) return nullptr;
  auto it = d->surfaces.find(drawable);
  return it == d->surfaces.end() ? nullptr : it->second.get();
}

XID add_surface(DisplayState& d, XID id, std::unique_ptr<XSurface> surface) {
  d.surfaces[id] = std::move(surface);
  return id;
}

// A GLX pixmap over `pixmap`, whose depth must be the configuration's (GLX 1.4 section 3.3.5).
GLXPixmap make_pixmap(Display* dpy, const FbConfig* config, Pixmap pixmap, int minor_opcode) {
  DisplayState* d = display_state(dpy);
  if (!d) return None;
  if (!config || !(config->drawable_types & GLX_PIXMAP_BIT)) {
    send_x_error(dpy, BadMatch, pixmap, minor_opcode);
    return None;
  }
  Window root = 0;
  int x = 0, y = 0;
  unsigned w = 0, h = 0, border = 0, depth = 0;
  {
    ErrorTrap trap(dpy);
    Status ok = XGetGeometry(dpy, pixmap, &root, &x, &y, &w, &h, &border, &depth);
    if (trap.finish() != 0 || !ok) {
      send_x_error(dpy, BadPixmap, pixmap, minor_opcode);
      return None;
    }
  }
  if (int(depth) != config->visual.depth) {
    send_x_error(dpy, BadMatch, pixmap, minor_opcode);
    return None;
  }
  return add_surface(*d, new_xid(dpy),
                     std::make_unique<XSurface>(dpy, pixmap, XSurface::Kind::kPixmap, *config, config->visual,
                                                config->layout));
}

// Destroys the surface of `id` if it is of `kind`; else raises `glx_error`.
void destroy_surface(Display* dpy, XID id, XSurface::Kind kind, int glx_error, int minor_opcode) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  XSurface* s = find_surface(dpy, id);
  if (!d || !s || s->kind() != kind) {
    send_glx_error(dpy, glx_error, id, minor_opcode);
    return;
  }
  d->surfaces.erase(id);  // a context current on it draws into nothing from now on
}

}  // namespace

XSurface* surface_for(DisplayState& d, GLXDrawable drawable, const FbConfig& config, int& error) {
  if (XSurface* s = find_surface(d.dpy, drawable)) return s;
  XVisualInfo visual{};
  platform::ImageLayout layout{};
  if (!window_visual(d.dpy, drawable, visual, layout)) {
    error = GLXBadDrawable;
    return nullptr;
  }
  auto s = std::make_unique<XSurface>(d.dpy, drawable, XSurface::Kind::kWindow, config, visual, layout);
  XSurface* made = s.get();
  add_surface(d, drawable, std::move(s));
  return made;
}

void swap_buffers(Display* dpy, GLXDrawable drawable) {
  std::lock_guard lock(vendor_mutex());
  XSurface* s = find_surface(dpy, drawable);
  if (!s) {
    send_glx_error(dpy, GLXBadDrawable, drawable, X_GLXSwapBuffers);
    return;
  }
  s->swap_buffers();
}

GLXPixmap create_glx_pixmap(Display* dpy, XVisualInfo* visual, Pixmap pixmap) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  const FbConfig* config = d ? config_for_visual(*d, visual) : nullptr;
  // A visual's richest configuration is double-buffered: its single-buffered twin draws pixmaps.
  if (config && config->surface.double_buffered) {
    for (const auto& c : screen_configs(*d, config->screen)) {
      platform::SurfaceConfig a = c->surface, b = config->surface;
      if (!a.double_buffered && a.depth_bits == b.depth_bits && a.stencil_bits == b.stencil_bits &&
          a.accum_bits == b.accum_bits && a.samples == b.samples) {
        config = c.get();
        break;
      }
    }
  }
  if (!config) {
    send_x_error(dpy, BadValue, visual ? visual->visualid : 0, X_GLXCreateGLXPixmap);
    return None;
  }
  return make_pixmap(dpy, config, pixmap, X_GLXCreateGLXPixmap);
}

GLXPixmap create_pixmap(Display* dpy, GLXFBConfig config, Pixmap pixmap, const int* /*attributes*/) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  const FbConfig* c = d ? find_config(*d, config) : nullptr;
  if (d && !c) {
    send_glx_error(dpy, GLXBadFBConfig, 0, X_GLXCreatePixmap);
    return None;
  }
  return make_pixmap(dpy, c, pixmap, X_GLXCreatePixmap);
}

// GLX 1.4 section 3.3.6: width and height default to 0, GLX_LARGEST_PBUFFER to False,
// GLX_PRESERVED_CONTENTS to True.
GLXPbuffer create_pbuffer(Display* dpy, GLXFBConfig config, const int* attributes) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  const FbConfig* c = d ? find_config(*d, config) : nullptr;
  if (!c) {
    send_glx_error(dpy, GLXBadFBConfig, 0, X_GLXCreatePbuffer);
    return None;
  }
  int width = 0, height = 0, largest = False, preserved = True;
  for (int i = 0; attributes && attributes[i] != None; i += 2) {
    const int v = attributes[i + 1];
    switch (attributes[i]) {
      case GLX_PBUFFER_WIDTH: width = v; break;
      case GLX_PBUFFER_HEIGHT: height = v; break;
      case GLX_LARGEST_PBUFFER: largest = v; break;
      case GLX_PRESERVED_CONTENTS: preserved = v; break;
      default: send_x_error(dpy, BadValue, 0, X_GLXCreatePbuffer); return None;
    }
  }
  if (width < 0 || height < 0) {
    send_x_error(dpy, BadValue, 0, X_GLXCreatePbuffer);
    return None;
  }
  if (width > kMaxBufferDim || height > kMaxBufferDim) {
    if (!largest) {
      send_x_error(dpy, BadAlloc, 0, X_GLXCreatePbuffer);
      return None;
    }
    width = std::min(width, kMaxBufferDim), height = std::min(height, kMaxBufferDim);
  }
  auto s = std::make_unique<XSurface>(dpy, None, XSurface::Kind::kPbuffer, *c, c->visual, c->layout, width, height);
  s->preserved = preserved != False;
  s->largest = largest != False;
  return add_surface(*d, new_xid(dpy), std::move(s));
}

GLXWindow create_window(Display* dpy, GLXFBConfig config, Window window, const int* /*attributes*/) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  const FbConfig* c = d ? find_config(*d, config) : nullptr;
  if (!c) {
    send_glx_error(dpy, GLXBadFBConfig, 0, X_GLXCreateWindow);
    return None;
  }
  XVisualInfo visual{};
  platform::ImageLayout layout{};
  if (!window_visual(dpy, window, visual, layout)) {
    send_x_error(dpy, BadWindow, window, X_GLXCreateWindow);
    return None;
  }
  if (visual.depth != c->visual.depth) {  // the window must be of the configuration's visual
    send_x_error(dpy, BadMatch, window, X_GLXCreateWindow);
    return None;
  }
  return add_surface(*d, new_xid(dpy),
                     std::make_unique<XSurface>(dpy, window, XSurface::Kind::kWindow, *c, visual, layout));
}

void destroy_glx_pixmap(Display* dpy, GLXPixmap pixmap) {
  destroy_surface(dpy, pixmap, XSurface::Kind::kPixmap, GLXBadPixmap, X_GLXDestroyGLXPixmap);
}
void destroy_pixmap(Display* dpy, GLXPixmap pixmap) {
  destroy_surface(dpy, pixmap, XSurface::Kind::kPixmap, GLXBadPixmap, X_GLXDestroyPixmap);
}
void destroy_pbuffer(Display* dpy, GLXPbuffer pbuffer) {
  destroy_surface(dpy, pbuffer, XSurface::Kind::kPbuffer, GLXBadPbuffer, X_GLXDestroyPbuffer);
}
void destroy_window(Display* dpy, GLXWindow window) {
  destroy_surface(dpy, window, XSurface::Kind::kWindow, GLXBadWindow, X_GLXDestroyWindow);
}

void query_drawable(Display* dpy, GLXDrawable drawable, int attribute, unsigned int* value) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  XSurface* s = find_surface(dpy, drawable);
  int width = 0, height = 0;
  if (!s && d) {  // a window not yet drawn to
    XVisualInfo visual{};
    platform::ImageLayout layout{};
    int error = 0;
    if (window_visual(dpy, drawable, visual, layout) && !screen_configs(*d, visual.screen).empty()) {
      s = surface_for(*d, drawable, *screen_configs(*d, visual.screen)[0], error);
    }
  }
  if (!s) {
    send_glx_error(dpy, GLXBadDrawable, drawable, X_GLXGetDrawableAttributes);
    return;
  }
  if (!s->is_bound()) s->follow_size();
  width = s->width(), height = s->height();
  if (width == 0 && !s->drawable_size(width, height)) width = height = 0;
  unsigned v = 0;
  switch (attribute) {
    case GLX_WIDTH: v = unsigned(width); break;
    case GLX_HEIGHT: v = unsigned(height); break;
    case GLX_PRESERVED_CONTENTS: v = s->preserved ? True : False; break;
    case GLX_LARGEST_PBUFFER: v = s->largest ? True : False; break;
    case GLX_FBCONFIG_ID: v = unsigned(s->fbconfig().id); break;
    case GLX_EVENT_MASK: v = unsigned(s->event_mask); break;
    default: send_x_error(dpy, BadValue, drawable, X_GLXGetDrawableAttributes); return;
  }
  if (value) *value = v;
}

// GLX_PBUFFER_CLOBBER_MASK is kept and reported; shadelab's pbuffers are never clobbered, so
// no event is ever sent.
void select_event(Display* dpy, GLXDrawable drawable, unsigned long mask) {
  std::lock_guard lock(vendor_mutex());
  if (XSurface* s = find_surface(dpy, drawable)) s->event_mask = mask;
  else send_glx_error(dpy, GLXBadDrawable, drawable, X_GLXChangeDrawableAttributes);
}

void get_selected_event(Display* dpy, GLXDrawable drawable, unsigned long* mask) {
  std::lock_guard lock(vendor_mutex());
  XSurface* s = find_surface(dpy, drawable);
  if (!s) {
    send_glx_error(dpy, GLXBadDrawable, drawable, X_GLXGetDrawableAttributes);
    return;
  }
  if (mask) *mask = s->event_mask;
}

// GLX 1.4 section 3.3.11: GL rendering is done before later X rendering: the current
// context's drawing reaches its drawable (as glFinish).
void wait_gl() { glFinish(); }

// X rendering requested before is done before later GL rendering: the server has handled
// every request.
void wait_x() {
  std::lock_guard lock(vendor_mutex());
  GlxContext* c = current_glx_context();
  if (c && c->dpy) XSync(c->dpy, False);
}

}  // namespace shadelab::gl::glx
