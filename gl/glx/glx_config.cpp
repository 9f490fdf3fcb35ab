// Choosing configurations: glXChooseVisual and glXGetConfig (GLX 1.4 section 3.4: the GLX 1.2
// calls), glXChooseFBConfig, glXGetFBConfigs, glXGetFBConfigAttrib and
// glXGetVisualFromFBConfig (section 3.3.3). Matching follows the specification's table 3.4;
// sorting follows Mesa's reading of it (src/glx/glxcmds.c), so that a program gets the
// configuration it would get on llvmpipe. No drawing, no contexts here.
#include <algorithm>
#include <cstdlib>
#include <vector>

#include "gl/glx/glx_vendor.hpp"

namespace shadelab::gl::glx {
namespace {

constexpr int kDontCare = int(GLX_DONT_CARE);  // an unsigned all-ones in the header

// What an attribute list asks for (GLX_DONT_CARE where it leaves a choice).
struct Request {
  int fbconfig_id = kDontCare;
  int double_buffer = kDontCare;
  int stereo = False, level = 0, aux = 0, buffer = 0;
  int color[4] = {0, 0, 0, 0};  // red, green, blue, alpha minimums
  int depth = 0, stencil = 0;
  int accum[4] = {0, 0, 0, 0};
  int render_type = GLX_RGBA_BIT, drawable_type = GLX_WINDOW_BIT;
  int x_renderable = kDontCare, visual_type = kDontCare, caveat = kDontCare;
  int transparent = GLX_NONE, sample_buffers = 0, samples = 0;
  int visual_id = kDontCare;
};

// One attribute of a list; `value` is unused for glXChooseVisual's booleans. False for an
// attribute that no list may hold.
bool read_attribute(Request& r, int name, int value) {
  switch (name) {
    case GLX_FBCONFIG_ID: r.fbconfig_id = value; return true;
    case GLX_BUFFER_SIZE: r.buffer = value; return true;
    case GLX_LEVEL: r.level = value; return true;
    case GLX_DOUBLEBUFFER: r.double_buffer = value; return true;
    case GLX_STEREO: r.stereo = value; return true;
    case GLX_AUX_BUFFERS: r.aux = value; return true;
    case GLX_RED_SIZE: r.color[0] = value; return true;
    case GLX_GREEN_SIZE: r.color[1] = value; return true;
    case GLX_BLUE_SIZE: r.color[2] = value; return true;
    case GLX_ALPHA_SIZE: r.color[3] = value; return true;
    case GLX_DEPTH_SIZE: r.depth = value; return true;
    case GLX_STENCIL_SIZE: r.stencil = value; return true;
    case GLX_ACCUM_RED_SIZE: r.accum[0] = value; return true;
    case GLX_ACCUM_GREEN_SIZE: r.accum[1] = value; return true;
    case GLX_ACCUM_BLUE_SIZE: r.accum[2] = value; return true;
    case GLX_ACCUM_ALPHA_SIZE: r.accum[3] = value; return true;
    case GLX_RENDER_TYPE: r.render_type = value; return true;
    case GLX_DRAWABLE_TYPE: r.drawable_type = value; return true;
    case GLX_X_RENDERABLE: r.x_renderable = value; return true;
    case GLX_X_VISUAL_TYPE: r.visual_type = value; return true;
    case GLX_CONFIG_CAVEAT: r.caveat = value; return true;
    case GLX_TRANSPARENT_TYPE: r.transparent = value; return true;
    case GLX_TRANSPARENT_INDEX_VALUE: case GLX_TRANSPARENT_RED_VALUE: case GLX_TRANSPARENT_GREEN_VALUE:
    case GLX_TRANSPARENT_BLUE_VALUE: case GLX_TRANSPARENT_ALPHA_VALUE: return true;
    case GLX_SAMPLE_BUFFERS: r.sample_buffers = value; return true;
    case GLX_SAMPLES: r.samples = value; return true;
    case GLX_VISUAL_ID: r.visual_id = value; return true;
    case GLX_MAX_PBUFFER_WIDTH: case GLX_MAX_PBUFFER_HEIGHT: case GLX_MAX_PBUFFER_PIXELS: return true;
    default: return false;
  }
}

// glXChooseFBConfig's list: every attribute has a value; attributes of extensions shadelab
// does not offer are passed over, as they constrain nothing it has.
void parse_fbconfig_list(const int* list, Request& r) {
  for (int i = 0; list && list[i] != None; i += 2) read_attribute(r, list[i], list[i + 1]);
}

// glXChooseVisual's list (GLX 1.4 section 3.4, table 3.8): GLX_USE_GL, GLX_RGBA,
// GLX_DOUBLEBUFFER and GLX_STEREO stand alone; single-buffered unless GLX_DOUBLEBUFFER is named.
// Without GLX_RGBA the specification asks for a colour-index visual; Mesa, which has none,
// answers with an RGBA one, and so does shadelab (programs that forget GLX_RGBA run on Mesa).
bool parse_visual_list(const int* list, Request& r) {
  r.render_type = GLX_RGBA_BIT;
  r.double_buffer = False;
  for (int i = 0; list && list[i] != None;) {
    switch (list[i]) {
      case GLX_USE_GL: ++i; break;
      case GLX_RGBA: r.render_type = GLX_RGBA_BIT, ++i; break;
      case GLX_DOUBLEBUFFER: r.double_buffer = True, ++i; break;
      case GLX_STEREO: r.stereo = True, ++i; break;
      default:
        if (!read_attribute(r, list[i], list[i + 1])) return false;
        i += 2;
    }
  }
  return true;
}

int value_of(const FbConfig& c, int attribute) {
  int v = 0;
  config_attribute(c, attribute, v);
  return v;
}

bool at_least(int wanted, int have) { return wanted == kDontCare || have >= wanted; }
bool exactly(int wanted, int have) { return wanted == kDontCare || have == wanted; }

// GLX 1.4 table 3.4's selection criteria.
bool matches(const Request& r, const FbConfig& c) {
  if (r.fbconfig_id != kDontCare) return r.fbconfig_id == c.id;  // every other attribute ignored
  if (!exactly(r.double_buffer, value_of(c, GLX_DOUBLEBUFFER) ? True : False)) return false;
  if (!exactly(r.stereo, False) || !exactly(r.level, 0) || !at_least(r.aux, 0)) return false;
  if (!at_least(r.buffer, value_of(c, GLX_BUFFER_SIZE))) return false;
  for (int i = 0; i < 4; ++i) {
    if (!at_least(r.color[i], 8) || !at_least(r.accum[i], c.surface.accum_bits)) return false;
  }
  if (!at_least(r.depth, c.surface.depth_bits) || !at_least(r.stencil, c.surface.stencil_bits)) return false;
  if (r.render_type != kDontCare && (r.render_type & ~GLX_RGBA_BIT) != 0) return false;
  if (r.drawable_type != kDontCare && (r.drawable_type & ~c.drawable_types) != 0) return false;
  if (!exactly(r.x_renderable, True) || !exactly(r.visual_type, GLX_TRUE_COLOR)) return false;
  if (!exactly(r.caveat, GLX_NONE) || !exactly(r.visual_id, int(c.visual.visualid))) return false;
  if (r.transparent != kDontCare && r.transparent != GLX_NONE) return false;
  // Minimums, as Mesa matches them (src/glx/glxcmds.c fbconfigs_compatible).
  return at_least(r.sample_buffers, c.surface.samples > 0 ? 1 : 0) && at_least(r.samples, c.surface.samples);
}

// Mesa's order (src/glx/glxcmds.c fbconfig_compare): single-buffered first; fewer samples;
// for depth and accumulation "larger, but none first"; stencil smaller; then the list's own
// order.
bool better(const FbConfig* a, const FbConfig* b) {
  const platform::SurfaceConfig &x = a->surface, &y = b->surface;
  if (x.double_buffered != y.double_buffered) return !x.double_buffered;
  if (x.samples != y.samples) return x.samples < y.samples;
  auto larger_or_zero = [](int p, int q, bool& decided) {
    decided = p != q;
    return p == 0 || (q != 0 && p > q);
  };
  bool decided = false;
  bool r = larger_or_zero(x.depth_bits, y.depth_bits, decided);
  if (decided) return r;
  if (x.stencil_bits != y.stencil_bits) return x.stencil_bits < y.stencil_bits;
  r = larger_or_zero(x.accum_bits, y.accum_bits, decided);
  if (decided) return r;
  return false;
}

std::vector<const FbConfig*> choose(DisplayState& d, int screen, const Request& r) {
  std::vector<const FbConfig*> out;
  for (const auto& c : screen_configs(d, screen)) {
    if (matches(r, *c)) out.push_back(c.get());
  }
  std::stable_sort(out.begin(), out.end(), better);
  return out;
}

// A list of GLXFBConfig handles the application frees with XFree (Xlib's allocator).
GLXFBConfig* handles(const std::vector<const FbConfig*>& configs, int* count) {
  if (count) *count = int(configs.size());
  if (configs.empty()) return nullptr;
  auto* list = static_cast<GLXFBConfig*>(std::malloc(configs.size() * sizeof(GLXFBConfig)));
  if (!list) {
    if (count) *count = 0;
    return nullptr;
  }
  for (std::size_t i = 0; i < configs.size(); ++i) list[i] = reinterpret_cast<GLXFBConfig>(const_cast<FbConfig*>(configs[i]));
  return list;
}

XVisualInfo* visual_info(Display* dpy, const FbConfig& c) {
  XVisualInfo templ{};
  templ.visualid = c.visual.visualid;
  templ.screen = c.screen;
  int n = 0;
  return XGetVisualInfo(dpy, VisualIDMask | VisualScreenMask, &templ, &n);
}

bool shares_visuals(DisplayState& d, int screen) {
  const auto& configs = screen_configs(d, screen);
  return configs.size() > 1 && configs[0]->visual.visualid == configs[1]->visual.visualid;
}

}  // namespace

XVisualInfo* choose_visual(Display* dpy, int screen, int* attributes) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  Request r;
  if (!d || !parse_visual_list(attributes, r)) return nullptr;
  std::vector<const FbConfig*> found = choose(*d, screen, r);
  if (found.empty()) return nullptr;
  if (shares_visuals(*d, screen)) d->chosen[found[0]->visual.visualid] = found[0];
  return visual_info(dpy, *found[0]);
}

int get_config(Display* dpy, XVisualInfo* visual, int attribute, int* value) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  if (!d || d->glx_opcode == 0) return GLX_NO_EXTENSION;
  const FbConfig* c = config_for_visual(*d, visual);
  if (!c) {
    // A visual the GL cannot draw to: GLX_USE_GL is False, anything else is an error.
    if (attribute == GLX_USE_GL && value) *value = False;
    return attribute == GLX_USE_GL ? Success : GLX_BAD_VISUAL;
  }
  int v = 0;
  if (!config_attribute(*c, attribute, v)) return GLX_BAD_ATTRIBUTE;
  if (value) *value = v;
  return Success;
}

GLXFBConfig* choose_fbconfig(Display* dpy, int screen, const int* attributes, int* count) {
  if (count) *count = 0;
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  Request r;
  if (!d) return nullptr;
  parse_fbconfig_list(attributes, r);
  return handles(choose(*d, screen, r), count);
}

GLXFBConfig* get_fbconfigs(Display* dpy, int screen, int* count) {
  if (count) *count = 0;
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  if (!d) return nullptr;
  std::vector<const FbConfig*> all;
  for (const auto& c : screen_configs(*d, screen)) all.push_back(c.get());
  return handles(all, count);
}

int get_fbconfig_attrib(Display* dpy, GLXFBConfig config, int attribute, int* value) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  const FbConfig* c = d ? find_config(*d, config) : nullptr;
  if (!c) return GLX_BAD_ATTRIBUTE;  // GLX 1.4 section 3.3.3: not a configuration
  int v = 0;
  if (!config_attribute(*c, attribute, v)) return GLX_BAD_ATTRIBUTE;
  if (value) *value = v;
  return Success;
}

XVisualInfo* get_visual_from_fbconfig(Display* dpy, GLXFBConfig config) {
  std::lock_guard lock(vendor_mutex());
  DisplayState* d = display_state(dpy);
  const FbConfig* c = d ? find_config(*d, config) : nullptr;
  if (!c) return nullptr;
  if (shares_visuals(*d, c->screen)) d->chosen[c->visual.visualid] = c;
  return visual_info(dpy, *c);
}

}  // namespace shadelab::gl::glx
