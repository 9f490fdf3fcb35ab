// The GLVND vendor interface of libGLX_shadelab (GLVND's glvnd/libglxabi.h): __glx_Main
// hands libGLX the vendor's imports; getProcAddress answers every GLX 1.4 function and every
// GL function of the GL front end by name (libGLdispatch builds its per-thread dispatch table
// from the GL ones); the strings of glXQueryServerString, glXGetClientString and
// glXQueryExtensionsString. The extensions offered need no dispatch stubs of the vendor's own:
// libGLX dispatches glXCreateContextAttribsARB itself.
#include <cstring>

#include "gl/glx/glx_context.hpp"
#include "gl/glx/glx_protocol.hpp"
#include "gl/src/proc_table.hpp"

#include <glvnd/libglxabi.h>

namespace shadelab::gl::glx {
namespace {

constexpr const char* kVendor = "shadelab";
constexpr const char* kVersion = "1.4";
constexpr const char* kExtensions =
    "GLX_ARB_create_context GLX_ARB_create_context_profile GLX_ARB_get_proc_address "
    "GLX_EXT_visual_info GLX_EXT_visual_rating";

const char* query_server_string(Display* /*dpy*/, int /*screen*/, int name) {
  switch (name) {
    case GLX_VENDOR: return kVendor;
    case GLX_VERSION: return kVersion;
    case GLX_EXTENSIONS: return kExtensions;
    default: return nullptr;
  }
}

const char* get_client_string(Display* dpy, int name) { return query_server_string(dpy, 0, name); }
const char* query_extensions_string(Display* /*dpy*/, int /*screen*/) { return kExtensions; }

GLXContext create_context_from_visual(Display* dpy, XVisualInfo* visual, GLXContext share, Bool /*direct*/) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  const FbConfig* config = d ? config_for_visual(*d, visual) : nullptr;
  if (d && !config) {  // Mesa: BadValue for a visual without a GL configuration
    send_x_error(dpy, BadValue, visual ? visual->visualid : 0, X_GLXCreateContext);
    return nullptr;
  }
  return create_context(dpy, config, share, nullptr, X_GLXCreateContext);
}

GLXContext create_new_context(Display* dpy, GLXFBConfig config, int render_type, GLXContext share, Bool /*direct*/) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  if (render_type != GLX_RGBA_TYPE) {  // no colour-index configurations
    send_x_error(dpy, BadValue, 0, X_GLXCreateNewContext);
    return nullptr;
  }
  return create_context(dpy, d ? find_config(*d, config) : nullptr, share, nullptr, X_GLXCreateNewContext);
}

GLXContext create_context_attribs(Display* dpy, GLXFBConfig config, GLXContext share, Bool /*direct*/,
                                  const int* attributes) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  return create_context(dpy, d ? find_config(*d, config) : nullptr, share, attributes,
                        X_GLXCreateContextAttribsARB);
}

__GLXextFuncPtr get_proc_address_glx(const GLubyte* name);

struct Proc {
  const char* name;
  void* address;
};

#define SHADELAB_GLX(name, f) {name, reinterpret_cast<void*>(&f)}
const Proc kGlxProcs[] = {
    SHADELAB_GLX("glXChooseFBConfig", choose_fbconfig),
    SHADELAB_GLX("glXChooseVisual", choose_visual),
    SHADELAB_GLX("glXCopyContext", copy_context),
    SHADELAB_GLX("glXCreateContext", create_context_from_visual),
    SHADELAB_GLX("glXCreateContextAttribsARB", create_context_attribs),
    SHADELAB_GLX("glXCreateGLXPixmap", create_glx_pixmap),
    SHADELAB_GLX("glXCreateNewContext", create_new_context),
    SHADELAB_GLX("glXCreatePbuffer", create_pbuffer),
    SHADELAB_GLX("glXCreatePixmap", create_pixmap),
    SHADELAB_GLX("glXCreateWindow", create_window),
    SHADELAB_GLX("glXDestroyContext", destroy_context),
    SHADELAB_GLX("glXDestroyGLXPixmap", destroy_glx_pixmap),
    SHADELAB_GLX("glXDestroyPbuffer", destroy_pbuffer),
    SHADELAB_GLX("glXDestroyPixmap", destroy_pixmap),
    SHADELAB_GLX("glXDestroyWindow", destroy_window),
    SHADELAB_GLX("glXGetClientString", get_client_string),
    SHADELAB_GLX("glXGetConfig", get_config),
    SHADELAB_GLX("glXGetFBConfigAttrib", get_fbconfig_attrib),
    SHADELAB_GLX("glXGetFBConfigs", get_fbconfigs),
    SHADELAB_GLX("glXGetProcAddress", get_proc_address_glx),
    SHADELAB_GLX("glXGetProcAddressARB", get_proc_address_glx),
    SHADELAB_GLX("glXGetSelectedEvent", get_selected_event),
    SHADELAB_GLX("glXGetVisualFromFBConfig", get_visual_from_fbconfig),
    SHADELAB_GLX("glXIsDirect", is_direct),
    SHADELAB_GLX("glXMakeContextCurrent", make_context_current),
    SHADELAB_GLX("glXMakeCurrent", make_current),
    SHADELAB_GLX("glXQueryContext", query_context),
    SHADELAB_GLX("glXQueryDrawable", query_drawable),
    SHADELAB_GLX("glXQueryExtensionsString", query_extensions_string),
    SHADELAB_GLX("glXQueryServerString", query_server_string),
    SHADELAB_GLX("glXSelectEvent", select_event),
    SHADELAB_GLX("glXSwapBuffers", swap_buffers),
    SHADELAB_GLX("glXUseXFont", use_x_font),
    SHADELAB_GLX("glXWaitGL", wait_gl),
    SHADELAB_GLX("glXWaitX", wait_x),
};
#undef SHADELAB_GLX

// GL functions come from the GL front end's table; OSMesa's own functions are not GL's.
void* gl_proc(const char* name) {
  if (std::strncmp(name, "gl", 2) != 0 || std::strncmp(name, "glX", 3) == 0) return nullptr;
  return reinterpret_cast<void*>(find_proc(name));
}

void* get_proc_address(const GLubyte* name) {
  const char* n = reinterpret_cast<const char*>(name);
  if (!n) return nullptr;
  if (void* glx = glx_proc(n)) return glx;
  return gl_proc(n);
}

// Only called by programs that reach the vendor's own glXGetProcAddress (libGLX answers
// glXGetProcAddress itself); answers as getProcAddress does.
__GLXextFuncPtr get_proc_address_glx(const GLubyte* name) {
  return reinterpret_cast<__GLXextFuncPtr>(get_proc_address(name));
}

Bool is_screen_supported(Display* dpy, int screen) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  return d && !screen_configs(*d, screen).empty() ? True : False;
}

// No GLX extension function of this vendor needs a dispatch stub (see the file's opening).
void* get_dispatch_address(const GLubyte* /*name*/) { return nullptr; }
void set_dispatch_index(const GLubyte* /*name*/, int /*index*/) {}

}  // namespace

void* glx_proc(const char* name) {
  for (const Proc& p : kGlxProcs) {
    if (std::strcmp(p.name, name) == 0) return p.address;
  }
  return nullptr;
}

}  // namespace shadelab::gl::glx

using namespace shadelab::gl::glx;

extern "C" __attribute__((visibility("default"))) Bool __glx_Main(uint32_t version, const __GLXapiExports* /*exports*/,
                                                                  __GLXvendorInfo* /*vendor*/,
                                                                  __GLXapiImports* imports) {
  if (GLX_VENDOR_ABI_GET_MAJOR_VERSION(version) != GLX_VENDOR_ABI_MAJOR_VERSION || !imports) return False;
  imports->isScreenSupported = is_screen_supported;
  imports->getProcAddress = get_proc_address;
  imports->getDispatchAddress = get_dispatch_address;
  imports->setDispatchIndex = set_dispatch_index;
  // notifyError and the entry-point patching callbacks are optional and left null: libGLX
  // then reports errors itself and calls through its dispatch table.
  return True;
}
