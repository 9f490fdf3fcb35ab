// libEGL_shadelab: shadelab's EGL 1.5 as a GLVND vendor library (docs/platform.md), headless:
// the surfaceless platform (EGL_MESA_platform_surfaceless) and the default display, pbuffer
// surfaces, surfaceless contexts (EGL_KHR_surfaceless_context), EGL_KHR_create_context,
// EGL_KHR_no_config_context. GLVND's
// libEGL loads it through its JSON file (__EGL_VENDOR_LIBRARY_FILENAMES) and asks it for every
// EGL and GL function by name (egl_vendor.cpp). Rendering and surfaces are the platform
// layer's (gl/src/platform); this header holds what the vendor's files share. The vendor
// exports __egl_Main only (egl.map).
#pragma once

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <memory>
#include <mutex>
#include <set>
#include <vector>

#include "gl/src/platform/surface.hpp"

namespace shadelab::gl::egl {

/// One EGLConfig (EGL 1.5 section 3.4): what a pbuffer holds. The EGLConfig handle points to it.
struct Config {
  EGLint id = 0;  ///< EGL_CONFIG_ID
  platform::SurfaceConfig surface;
};

/// A pbuffer (EGL 1.5 section 3.5.2): its image is plain memory, never shown.
class Pbuffer final : public platform::Surface {
 public:
  Pbuffer(const Config& config, int width, int height, bool largest);
  ~Pbuffer() override;
  const Config& egl_config() const { return *config_; }
  bool largest() const { return largest_; }
  int requested_width() const { return requested_width_; }
  int requested_height() const { return requested_height_; }

 protected:
  std::uint8_t* allocate_image(int width, int height, int& row_pixels) override;
  bool query_size(int& width, int& height) override;

 private:
  const Config* config_;
  int requested_width_, requested_height_;
  bool largest_;
  std::vector<std::uint8_t> pixels_;
};

struct Context {
  std::unique_ptr<GlContext> gl;
  const Config* config = nullptr;
  bool no_config = false;  ///< made with EGL_NO_CONFIG_KHR
  int major = 1;
  bool current = false;    ///< current in some thread
  bool destroyed = false;  ///< eglDestroyContext while current: freed when released
  Pbuffer* draw = nullptr;
};

/// An EGLDisplay: the surfaceless platform's one display (the default display is the same).
struct Display {
  bool initialized = false;
  std::vector<std::unique_ptr<Config>> configs;
  std::set<Context*> contexts;
  std::set<Pbuffer*> surfaces;
};

/// The vendor's lock: every EGL entry point holds it while it reads or changes the tables.
std::recursive_mutex& vendor_mutex();
/// The one display (made at first use), or null when `handle` is not it.
Display* the_display();
Display* find_display(EGLDisplay handle);
/// Records `error` for eglGetError (EGL 1.5 section 3.1: the thread's last error).
void set_error(EGLint error);
/// eglGetError: the thread's last error, then EGL_SUCCESS.
EGLint take_error();
/// Records `error` and returns `result`.
template <class T>
T fail(EGLint error, T result) {
  set_error(error);
  return result;
}

/// Configurations (egl_config.cpp).
const Config* find_config(Display& d, EGLConfig config);
bool config_attribute(const Config& c, EGLint attribute, EGLint& value);
EGLBoolean get_configs(EGLDisplay dpy, EGLConfig* configs, EGLint size, EGLint* count);
EGLBoolean choose_config(EGLDisplay dpy, const EGLint* attributes, EGLConfig* configs, EGLint size, EGLint* count);
EGLBoolean get_config_attrib(EGLDisplay dpy, EGLConfig config, EGLint attribute, EGLint* value);

/// Contexts and surfaces (egl_context.cpp).
EGLContext create_context(EGLDisplay dpy, EGLConfig config, EGLContext share, const EGLint* attributes);
EGLBoolean destroy_context(EGLDisplay dpy, EGLContext ctx);
EGLBoolean make_current(EGLDisplay dpy, EGLSurface draw, EGLSurface read, EGLContext ctx);
EGLBoolean query_context(EGLDisplay dpy, EGLContext ctx, EGLint attribute, EGLint* value);
EGLSurface create_pbuffer_surface(EGLDisplay dpy, EGLConfig config, const EGLint* attributes);
EGLBoolean destroy_surface(EGLDisplay dpy, EGLSurface surface);
EGLBoolean query_surface(EGLDisplay dpy, EGLSurface surface, EGLint attribute, EGLint* value);
EGLBoolean surface_attrib(EGLDisplay dpy, EGLSurface surface, EGLint attribute, EGLint value);
EGLBoolean swap_buffers(EGLDisplay dpy, EGLSurface surface);
EGLBoolean swap_interval(EGLDisplay dpy, EGLint interval);
EGLBoolean release_thread();
/// eglTerminate's work: every context and surface not current is freed now, the others when
/// released (EGL 1.5 section 3.2).
void terminate(Display& d);

}  // namespace shadelab::gl::egl
