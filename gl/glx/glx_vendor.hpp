// libGLX_shadelab: shadelab's GLX 1.4 as a GLVND vendor library (docs/platform.md). GLVND's
// libGLX.so.0 loads it (__GLX_VENDOR_LIBRARY_NAME=shadelab), asks it for every GLX and GL
// function by name (glx_vendor.cpp) and calls those through its dispatch. Rendering is the
// GL front end's (gl/src), on the client; X only receives finished images (XPutImage or
// MIT-SHM), so any X server with the GLX extension that GLVND queries works. This header holds
// what the vendor's files share: configurations, per-display state, X error helpers. The
// vendor exports __glx_Main only (glx.map): nothing in it interposes on libGL's gl* symbols.
#pragma once

#include <GL/gl.h>

#include <cstddef>

// glxext.h names GL 1.5's pointer-sized types, which an OpenGL 1.1 <GL/gl.h> lacks (the same
// types as Khronos' on LP64; repeating a typedef is allowed).
typedef std::ptrdiff_t GLintptr;
typedef std::ptrdiff_t GLsizeiptr;

#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "gl/src/platform/surface.hpp"

namespace shadelab::gl::glx {

/// One GLXFBConfig (GLX 1.4 section 3.3.3): an X visual whose pixels the XImage code can
/// write, with what the drawable holds. The GLXFBConfig handle points to it.
struct FbConfig {
  int id = 0;  ///< GLX_FBCONFIG_ID
  int screen = 0;
  XVisualInfo visual{};
  platform::ImageLayout layout = platform::ImageLayout::kBgra;
  platform::SurfaceConfig surface;
  int drawable_types = 0;  ///< GLX_DRAWABLE_TYPE bits
};

class XSurface;

/// What the vendor keeps per X display connection, until XCloseDisplay (glx_display.cpp).
struct DisplayState {
  Display* dpy = nullptr;
  std::vector<std::vector<std::unique_ptr<FbConfig>>> screens;  ///< configurations per screen
  std::map<XID, std::unique_ptr<XSurface>> surfaces;  ///< by GLX drawable (windows by their XID)
  std::map<VisualID, const FbConfig*> chosen;         ///< glXChooseVisual's answer per visual
  int glx_opcode = 0, glx_error_base = 0;             ///< from the server's GLX extension
  bool shm = false;                                   ///< MIT-SHM usable
};

/// The vendor's lock: every GLX entry point holds it while it reads or changes the tables.
std::recursive_mutex& vendor_mutex();
/// The state of `dpy`, made at first use (null if `dpy` is null).
DisplayState* display_state(Display* dpy);
/// The configurations of `screen` (empty for a bad screen or a screen without usable visuals).
const std::vector<std::unique_ptr<FbConfig>>& screen_configs(DisplayState& d, int screen);
/// Whether `config` is one of ours on `d` (a GLXFBConfig handle from the application).
const FbConfig* find_config(DisplayState& d, GLXFBConfig config);
/// The configuration a visual stands for: the one glXChooseVisual chose for it, else the
/// richest one on it (double-buffered, depth, stencil, accumulation); null if not ours.
const FbConfig* config_for_visual(DisplayState& d, const XVisualInfo* visual);
/// The layout of an XImage of `visual` in memory, if the presenting can write it (TrueColor,
/// 32 bits a pixel, 8-bit channels in an order a platform::ImageLayout names).
bool visual_layout(Display* dpy, const XVisualInfo& visual, platform::ImageLayout& layout);
/// glXGetFBConfigAttrib's answer (GLX 1.4 table 3.1); false for an unknown attribute.
bool config_attribute(const FbConfig& c, int attribute, int& value);

/// A new XID for a GLX drawable that has no server resource (pbuffers, GLX pixmaps, GLX
/// windows are the vendor's own). XAllocID refills its next ID only when a request follows: a
/// no-op request is queued after it, or the next XAllocID asserts.
XID new_xid(Display* dpy);
/// Generates an X error as the server would (GLX 1.4 section 3.3: errors are reported through
/// the application's X error handler): `glx_code` is relative to the GLX error base.
void send_x_error(Display* dpy, unsigned char code, XID resource, int minor_opcode);
void send_glx_error(Display* dpy, int glx_code, XID resource, int minor_opcode);

/// Catches the X errors of the requests made while it lives (the vendor's own requests, whose
/// failure is an answer, not the application's error).
class ErrorTrap {
 public:
  explicit ErrorTrap(Display* dpy);
  ~ErrorTrap();
  /// Waits for the replies and returns the first error code (0: none).
  int finish();

 private:
  Display* dpy_;
  int (*old_)(Display*, XErrorEvent*);
  std::unique_lock<std::mutex> lock_;
  bool finished_ = false;
};

/// The GLX entry points by name (glx_vendor.cpp's table), for GLVND's getProcAddress.
void* glx_proc(const char* name);

}  // namespace shadelab::gl::glx
