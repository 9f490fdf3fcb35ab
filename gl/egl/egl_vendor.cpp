// The GLVND vendor interface of libEGL_shadelab (GLVND's glvnd/libeglabi.h): __egl_Main hands
// libEGL the vendor's imports; getPlatformDisplay answers the surfaceless platform and the
// default display; getProcAddress answers every EGL 1.5 function and every GL function of the
// GL front end by name. Also here: the thread's error, eglInitialize / eglTerminate,
// eglQueryString, the wait calls, and the calls for what this headless vendor has not (window
// and pixmap surfaces, texture binding, client buffers), which answer with the errors EGL 1.5
// gives for them.
#include <cstring>

#include "gl/egl/egl_vendor.hpp"
#include "gl/src/proc_table.hpp"

#include <glvnd/libeglabi.h>

namespace shadelab::gl::egl {
namespace {

thread_local EGLint t_error = EGL_SUCCESS;

constexpr const char* kVendor = "shadelab";
constexpr const char* kVersion = "1.5 shadelab";
constexpr const char* kClientApis = "OpenGL";
constexpr const char* kExtensions =
    "EGL_KHR_create_context EGL_KHR_get_all_proc_addresses EGL_KHR_no_config_context "
    "EGL_KHR_surfaceless_context";

// The configurations: depth/stencil 24/8, 24/0, 16/0, none, then 24/8 with a multisample
// buffer of 4 samples; each with a 16-bit accumulation buffer (EGL has no attribute for it; GL
// programs that accumulate get one), drawn to pbuffers or to nothing.
void make_configs(Display& d) {
  const int kinds[][3] = {{24, 8, 0}, {24, 0, 0}, {16, 0, 0}, {0, 0, 0}, {24, 8, 4}};
  for (auto [depth, stencil, samples] : kinds) {
    auto c = std::make_unique<Config>();
    c->id = EGLint(d.configs.size()) + 1;
    c->surface = {depth, stencil, 16, true, samples};
    d.configs.push_back(std::move(c));
  }
}

// EGL_PLATFORM_SURFACELESS_MESA with EGL_DEFAULT_DISPLAY, or the default display of
// eglGetDisplay (platform EGL_NONE): headless either way. Other platforms are left to other
// vendors (EGL_NO_DISPLAY with EGL_SUCCESS).
EGLDisplay get_platform_display(EGLenum platform, void* native, const EGLAttrib* attributes) {
  std::lock_guard lock(vendor_mutex());
  set_error(EGL_SUCCESS);
  if (platform != EGL_PLATFORM_SURFACELESS_MESA && platform != EGL_NONE) return EGL_NO_DISPLAY;
  if (native != EGL_DEFAULT_DISPLAY) {
    return platform == EGL_NONE ? EGL_NO_DISPLAY : fail(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
  }
  if (attributes && attributes[0] != EGL_NONE) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_DISPLAY);
  return the_display();
}

EGLBoolean supports_api(EGLenum api) { return api == EGL_OPENGL_API ? EGL_TRUE : EGL_FALSE; }

const char* vendor_string(int name) {
  return name == __EGL_VENDOR_STRING_PLATFORM_EXTENSIONS ? "EGL_MESA_platform_surfaceless" : nullptr;
}

EGLBoolean initialize(EGLDisplay dpy, EGLint* major, EGLint* minor) {
  std::lock_guard lock(vendor_mutex());
  Display* d = find_display(dpy);
  if (!d) return fail(EGL_BAD_DISPLAY, EGL_FALSE);
  if (d->configs.empty()) make_configs(*d);
  d->initialized = true;
  if (major) *major = 1;
  if (minor) *minor = 5;
  return EGL_TRUE;
}

EGLBoolean terminate_display(EGLDisplay dpy) {
  std::lock_guard lock(vendor_mutex());
  Display* d = find_display(dpy);
  if (!d) return fail(EGL_BAD_DISPLAY, EGL_FALSE);
  terminate(*d);
  return EGL_TRUE;
}

const char* query_string(EGLDisplay dpy, EGLint name) {
  std::lock_guard lock(vendor_mutex());
  Display* d = find_display(dpy);
  if (!d) return fail(EGL_BAD_DISPLAY, static_cast<const char*>(nullptr));
  if (!d->initialized) return fail(EGL_NOT_INITIALIZED, static_cast<const char*>(nullptr));
  switch (name) {
    case EGL_VENDOR: return kVendor;
    case EGL_VERSION: return kVersion;
    case EGL_CLIENT_APIS: return kClientApis;
    case EGL_EXTENSIONS: return kExtensions;
    default: return fail(EGL_BAD_PARAMETER, static_cast<const char*>(nullptr));
  }
}

EGLint get_error() { return take_error(); }

// EGL 1.5 section 3.8: client and native rendering are done before later native and client
// rendering; the GL's is done at a glFinish, and nothing here renders natively.
EGLBoolean wait_client() {
  glFinish();
  return EGL_TRUE;
}
EGLBoolean wait_gl() { return wait_client(); }
EGLBoolean wait_native(EGLint /*engine*/) { return EGL_TRUE; }

// No configuration has EGL_WINDOW_BIT or EGL_PIXMAP_BIT (EGL 1.5 section 3.5.1: EGL_BAD_MATCH).
EGLSurface no_native_surface(EGLDisplay dpy, EGLConfig config) {
  std::lock_guard lock(vendor_mutex());
  Display* d = find_display(dpy);
  if (!d) return fail(EGL_BAD_DISPLAY, EGL_NO_SURFACE);
  if (!d->initialized) return fail(EGL_NOT_INITIALIZED, EGL_NO_SURFACE);
  if (!find_config(*d, config)) return fail(EGL_BAD_CONFIG, EGL_NO_SURFACE);
  return fail(EGL_BAD_MATCH, EGL_NO_SURFACE);
}
EGLSurface create_window_surface(EGLDisplay dpy, EGLConfig config, EGLNativeWindowType, const EGLint*) {
  return no_native_surface(dpy, config);
}
EGLSurface create_pixmap_surface(EGLDisplay dpy, EGLConfig config, EGLNativePixmapType, const EGLint*) {
  return no_native_surface(dpy, config);
}
EGLSurface create_platform_window_surface(EGLDisplay dpy, EGLConfig config, void*, const EGLAttrib*) {
  return no_native_surface(dpy, config);
}
EGLSurface create_platform_pixmap_surface(EGLDisplay dpy, EGLConfig config, void*, const EGLAttrib*) {
  return no_native_surface(dpy, config);
}
// Only OpenVG client buffers exist (EGL 1.5 section 3.5.3): EGL_BAD_PARAMETER for any other.
EGLSurface create_pbuffer_from_client_buffer(EGLDisplay, EGLenum, EGLClientBuffer, EGLConfig, const EGLint*) {
  return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
}
// There is no native pixmap to copy to (EGL 1.5 section 3.10.2).
EGLBoolean copy_buffers(EGLDisplay, EGLSurface, EGLNativePixmapType) { return fail(EGL_BAD_NATIVE_PIXMAP, EGL_FALSE); }
// No surface has a texture format (EGL 1.5 section 3.6.1: EGL_BAD_MATCH).
EGLBoolean bind_tex_image(EGLDisplay, EGLSurface, EGLint) { return fail(EGL_BAD_MATCH, EGL_FALSE); }
EGLBoolean release_tex_image(EGLDisplay, EGLSurface, EGLint) { return fail(EGL_BAD_MATCH, EGL_FALSE); }

struct Proc {
  const char* name;
  void* address;
};

#define SHADELAB_EGL(name, f) {name, reinterpret_cast<void*>(&f)}
const Proc kEglProcs[] = {
    SHADELAB_EGL("eglBindTexImage", bind_tex_image),
    SHADELAB_EGL("eglChooseConfig", choose_config),
    SHADELAB_EGL("eglCopyBuffers", copy_buffers),
    SHADELAB_EGL("eglCreateContext", create_context),
    SHADELAB_EGL("eglCreatePbufferFromClientBuffer", create_pbuffer_from_client_buffer),
    SHADELAB_EGL("eglCreatePbufferSurface", create_pbuffer_surface),
    SHADELAB_EGL("eglCreatePixmapSurface", create_pixmap_surface),
    SHADELAB_EGL("eglCreatePlatformPixmapSurface", create_platform_pixmap_surface),
    SHADELAB_EGL("eglCreatePlatformWindowSurface", create_platform_window_surface),
    SHADELAB_EGL("eglCreateWindowSurface", create_window_surface),
    SHADELAB_EGL("eglDestroyContext", destroy_context),
    SHADELAB_EGL("eglDestroySurface", destroy_surface),
    SHADELAB_EGL("eglGetConfigAttrib", get_config_attrib),
    SHADELAB_EGL("eglGetConfigs", get_configs),
    SHADELAB_EGL("eglGetError", get_error),
    SHADELAB_EGL("eglInitialize", initialize),
    SHADELAB_EGL("eglMakeCurrent", make_current),
    SHADELAB_EGL("eglQueryContext", query_context),
    SHADELAB_EGL("eglQueryString", query_string),
    SHADELAB_EGL("eglQuerySurface", query_surface),
    SHADELAB_EGL("eglReleaseTexImage", release_tex_image),
    SHADELAB_EGL("eglReleaseThread", release_thread),
    SHADELAB_EGL("eglSurfaceAttrib", surface_attrib),
    SHADELAB_EGL("eglSwapBuffers", swap_buffers),
    SHADELAB_EGL("eglSwapInterval", swap_interval),
    SHADELAB_EGL("eglTerminate", terminate_display),
    SHADELAB_EGL("eglWaitClient", wait_client),
    SHADELAB_EGL("eglWaitGL", wait_gl),
    SHADELAB_EGL("eglWaitNative", wait_native),
};
#undef SHADELAB_EGL

void* get_proc_address(const char* name) {
  if (!name) return nullptr;
  for (const Proc& p : kEglProcs) {
    if (std::strcmp(p.name, name) == 0) return p.address;
  }
  // GL functions from the GL front end's table; OSMesa's own are not GL's.
  if (std::strncmp(name, "gl", 2) != 0) return nullptr;
  return reinterpret_cast<void*>(find_proc(name));
}

// No EGL extension function of this vendor needs a dispatch stub: the extensions offered add
// attributes only.
void* get_dispatch_address(const char* /*name*/) { return nullptr; }
void set_dispatch_index(const char* /*name*/, int /*index*/) {}

}  // namespace

std::recursive_mutex& vendor_mutex() {
  static auto* m = new std::recursive_mutex;
  return *m;
}

Display* the_display() {
  static auto* d = new Display;  // lives as long as the process: handles stay valid
  return d;
}

Display* find_display(EGLDisplay handle) { return handle == the_display() ? the_display() : nullptr; }

void set_error(EGLint error) { t_error = error; }

EGLint take_error() {
  EGLint e = t_error;
  t_error = EGL_SUCCESS;
  return e;
}

}  // namespace shadelab::gl::egl

using namespace shadelab::gl::egl;

extern "C" __attribute__((visibility("default"))) EGLBoolean __egl_Main(uint32_t version,
                                                                        const __EGLapiExports* /*exports*/,
                                                                        __EGLvendorInfo* /*vendor*/,
                                                                        __EGLapiImports* imports) {
  if (EGL_VENDOR_ABI_GET_MAJOR_VERSION(version) != EGL_VENDOR_ABI_MAJOR_VERSION || !imports) return EGL_FALSE;
  imports->getPlatformDisplay = get_platform_display;
  imports->getSupportsAPI = supports_api;
  imports->getVendorString = vendor_string;
  imports->getProcAddress = get_proc_address;
  imports->getDispatchAddress = get_dispatch_address;
  imports->setDispatchIndex = set_dispatch_index;
  // The entry-point patching callbacks and findNativeDisplayPlatform are optional: left null.
  return EGL_TRUE;
}
