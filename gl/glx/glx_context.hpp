// The GLX vendor's contexts and drawables as the entry-point table sees them (glx_context.cpp,
// glx_drawable.cpp): each function is the vendor's implementation of the GLX 1.4 function of
// the same name, called by GLVND's libGLX after it found this vendor for the display.
#pragma once

#include <memory>

#include "gl/glx/glx_vendor.hpp"

namespace shadelab::gl::glx {

/// A GLXContext handle points to one.
struct GlxContext {
  std::unique_ptr<GlContext> gl;
  Display* dpy = nullptr;
  const FbConfig* config = nullptr;
  bool current = false;    ///< current in some thread
  bool destroyed = false;  ///< glXDestroyContext called while current: freed when released
  GLXDrawable draw = None, read = None;
};

/// The live context behind a handle, or null.
GlxContext* find_context(GLXContext handle);
GlxContext* current_glx_context();
class XSurface;
/// The surface of a GLX drawable, made for an X window at its first binding (with `config`);
/// null with the GLX error code in `error` when `drawable` is none of these.
XSurface* surface_for(DisplayState& d, GLXDrawable drawable, const FbConfig& config, int& error);

/// Contexts (glx_context.cpp). `attributes` are GLX_ARB_create_context's (may be null).
GLXContext create_context(Display* dpy, const FbConfig* config, GLXContext share, const int* attributes,
                          int minor_opcode);
bool bind_context(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx, int minor_opcode);
Bool make_current(Display* dpy, GLXDrawable drawable, GLXContext ctx);
Bool make_context_current(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx);
void destroy_context(Display* dpy, GLXContext ctx);
Bool is_direct(Display* dpy, GLXContext ctx);
int query_context(Display* dpy, GLXContext ctx, int attribute, int* value);
void copy_context(Display* dpy, GLXContext source, GLXContext dest, unsigned long mask);

/// Configurations (glx_config.cpp).
XVisualInfo* choose_visual(Display* dpy, int screen, int* attributes);
int get_config(Display* dpy, XVisualInfo* visual, int attribute, int* value);
GLXFBConfig* choose_fbconfig(Display* dpy, int screen, const int* attributes, int* count);
GLXFBConfig* get_fbconfigs(Display* dpy, int screen, int* count);
int get_fbconfig_attrib(Display* dpy, GLXFBConfig config, int attribute, int* value);
XVisualInfo* get_visual_from_fbconfig(Display* dpy, GLXFBConfig config);

/// Drawables (glx_drawable.cpp).
void swap_buffers(Display* dpy, GLXDrawable drawable);
GLXPixmap create_glx_pixmap(Display* dpy, XVisualInfo* visual, Pixmap pixmap);
GLXPixmap create_pixmap(Display* dpy, GLXFBConfig config, Pixmap pixmap, const int* attributes);
GLXPbuffer create_pbuffer(Display* dpy, GLXFBConfig config, const int* attributes);
GLXWindow create_window(Display* dpy, GLXFBConfig config, Window window, const int* attributes);
void destroy_glx_pixmap(Display* dpy, GLXPixmap pixmap);
void destroy_pixmap(Display* dpy, GLXPixmap pixmap);
void destroy_pbuffer(Display* dpy, GLXPbuffer pbuffer);
void destroy_window(Display* dpy, GLXWindow window);
void query_drawable(Display* dpy, GLXDrawable drawable, int attribute, unsigned int* value);
void select_event(Display* dpy, GLXDrawable drawable, unsigned long mask);
void get_selected_event(Display* dpy, GLXDrawable drawable, unsigned long* mask);
void wait_gl();
void wait_x();
void use_x_font(Font font, int first, int count, int list_base);

}  // namespace shadelab::gl::glx
