// Per-display state of the GLX vendor: the configurations of each screen (GLX 1.4 section
// 3.3.3), the drawables, X errors raised on the client side (section 3.3: GLX errors are X
// errors) and their trapping, and the clean-up at XCloseDisplay. No rendering here.
#include <X11/Xlib.h>
#include <X11/extensions/XShm.h>


#include <algorithm>
#include <tuple>
#include <utility>

#include "gl/glx/glx_protocol.hpp"
#include "gl/glx/glx_surface.hpp"
#include "gl/glx/glx_vendor.hpp"

// Xlib's internals, for raising an X error on the client side (_XError); last, as it defines
// min and max macros.
#include <X11/Xlibint.h>
#undef min
#undef max

namespace shadelab::gl::glx {
namespace {

std::map<Display*, std::unique_ptr<DisplayState>>& displays() {
  static auto* map = new std::map<Display*, std::unique_ptr<DisplayState>>;  // outlives exit handlers
  return *map;
}

// XCloseDisplay: the display's drawables go (no requests: the connection is closing; the
// server frees its own resources). Its configurations are kept: contexts that outlive the
// connection still point to theirs.
int close_display(Display* dpy, XExtCodes* /*codes*/) {
  static auto* kept = new std::vector<std::vector<std::unique_ptr<FbConfig>>>;
  std::lock_guard lock(vendor_mutex());
  auto it = displays().find(dpy);
  if (it == displays().end()) return 0;
  for (auto& [id, surface] : it->second->surfaces) surface->forget_display();
  for (auto& configs : it->second->screens) kept->push_back(std::move(configs));
  displays().erase(it);
  return 0;
}

// Byte of a pixel that holds the channel of `mask` in a 32-bit pixel of the server's order.
int byte_of(unsigned long mask, bool msb_first) {
  int shift = 0;
  while (shift < 32 && !((mask >> shift) & 1u)) ++shift;
  if (shift % 8 != 0 || ((mask >> shift) != 0xffu)) return -1;
  return msb_first ? 3 - shift / 8 : shift / 8;
}

}  // namespace

bool visual_layout(Display* dpy, const XVisualInfo& v, platform::ImageLayout& layout) {
  if (v.c_class != TrueColor || (v.depth != 24 && v.depth != 32)) return false;
  int formats = 0;
  XPixmapFormatValues* list = XListPixmapFormats(dpy, &formats);
  int bpp = 0;
  for (int i = 0; i < formats; ++i) {
    if (list[i].depth == v.depth) bpp = list[i].bits_per_pixel;
  }
  if (list) XFree(list);
  if (bpp != 32) return false;
  const bool msb = ImageByteOrder(dpy) == MSBFirst;
  const int r = byte_of(v.red_mask, msb), g = byte_of(v.green_mask, msb), b = byte_of(v.blue_mask, msb);
  if (r == 0 && g == 1 && b == 2) layout = platform::ImageLayout::kRgba;
  else if (r == 2 && g == 1 && b == 0) layout = platform::ImageLayout::kBgra;
  else if (r == 1 && g == 2 && b == 3) layout = platform::ImageLayout::kArgb;
  else return false;
  return true;
}

namespace {

// The screen's TrueColor visuals of depth 24 whose pixels the presenting can write, the
// default visual first.
std::vector<std::pair<XVisualInfo, platform::ImageLayout>> usable_visuals(Display* dpy, int screen) {
  XVisualInfo templ{};
  templ.screen = screen;
  int n = 0;
  XVisualInfo* visuals = XGetVisualInfo(dpy, VisualScreenMask, &templ, &n);
  const VisualID preferred = XVisualIDFromVisual(DefaultVisual(dpy, screen));
  std::vector<std::pair<XVisualInfo, platform::ImageLayout>> usable;
  for (int i = 0; i < n; ++i) {
    platform::ImageLayout layout;
    if (visuals[i].depth == 24 && visual_layout(dpy, visuals[i], layout)) usable.emplace_back(visuals[i], layout);
  }
  if (visuals) XFree(visuals);
  std::stable_partition(usable.begin(), usable.end(), [&](const auto& v) { return v.first.visualid == preferred; });
  return usable;
}

// The configurations of a screen: double- and single-buffered; 24 bits of depth with 8 of
// stencil, 24, 16 or no depth; with and without a 16-bit accumulation buffer (the variety
// llvmpipe offers, so that glXChooseFBConfig picks alike), the richest first; then the
// double- and single-buffered ones with 24 bits of depth and 8 of stencil again, with a
// multisample buffer of 4 samples (llvmpipe's count), without and with accumulation. Each takes a
// visual of its own when the server has enough (Xvfb's GLX extension makes hundreds), so that
// glXGetConfig on a window's visual is unambiguous; otherwise they share the first (then the
// visual stands for glXChooseVisual's last choice, as in Mesa's Xlib driver).
std::vector<std::unique_ptr<FbConfig>> make_configs(Display* dpy, int screen) {
  std::vector<std::unique_ptr<FbConfig>> out;
  std::vector<std::pair<XVisualInfo, platform::ImageLayout>> visuals = usable_visuals(dpy, screen);
  if (visuals.empty()) return out;
  auto add = [&](const platform::SurfaceConfig& surface) {
    auto c = std::make_unique<FbConfig>();
    const std::size_t k = out.size();
    c->id = int(k) + 1 + screen * 1000;
    c->screen = screen;
    std::tie(c->visual, c->layout) = visuals[k < visuals.size() ? k : 0];
    c->surface = surface;
    // GLX pixmaps are single-buffered (GLX 1.4 section 3.3.5).
    c->drawable_types = GLX_WINDOW_BIT | GLX_PBUFFER_BIT | (surface.double_buffered ? 0 : GLX_PIXMAP_BIT);
    out.push_back(std::move(c));
  };
  const int depth_stencil[][2] = {{24, 8}, {24, 0}, {16, 0}, {0, 0}};
  for (bool doubled : {true, false}) {
    for (auto [depth, stencil] : depth_stencil) {
      for (int accum : {16, 0}) add({depth, stencil, accum, doubled});
    }
  }
  for (bool doubled : {true, false}) {
    for (int accum : {0, 16}) add({24, 8, accum, doubled, 4});
  }
  if (visuals.size() < out.size()) {
    for (auto& c : out) std::tie(c->visual, c->layout) = visuals[0];
  }
  return out;
}

std::mutex& trap_mutex() {
  static std::mutex m;
  return m;
}
int trapped_error = 0;

int trap_handler(Display* /*dpy*/, XErrorEvent* e) {
  if (trapped_error == 0) trapped_error = e->error_code;
  return 0;
}

}  // namespace

std::recursive_mutex& vendor_mutex() {
  static auto* m = new std::recursive_mutex;
  return *m;
}

DisplayState* display_state(Display* dpy) {
  if (!dpy) return nullptr;
  std::lock_guard lock(vendor_mutex());
  auto& slot = displays()[dpy];
  if (slot) return slot.get();
  auto d = std::make_unique<DisplayState>();
  d->dpy = dpy;
  d->screens.resize(std::size_t(std::max(ScreenCount(dpy), 0)));
  int event = 0, error = 0;
  if (XQueryExtension(dpy, "GLX", &d->glx_opcode, &event, &error)) d->glx_error_base = error;
  int major = 0, minor = 0;
  Bool pixmaps = False;
  d->shm = XShmQueryVersion(dpy, &major, &minor, &pixmaps) == True;
  if (XExtCodes* codes = XAddExtension(dpy)) XESetCloseDisplay(dpy, codes->extension, close_display);
  slot = std::move(d);
  return slot.get();
}

const std::vector<std::unique_ptr<FbConfig>>& screen_configs(DisplayState& d, int screen) {
  static const std::vector<std::unique_ptr<FbConfig>> kNone;
  if (screen < 0 || std::size_t(screen) >= d.screens.size()) return kNone;
  auto& configs = d.screens[std::size_t(screen)];
  if (configs.empty()) configs = make_configs(d.dpy, screen);
  return configs;
}

const FbConfig* find_config(DisplayState& d, GLXFBConfig config) {
  for (std::size_t s = 0; s < d.screens.size(); ++s) {
    for (const auto& c : screen_configs(d, int(s))) {
      if (reinterpret_cast<GLXFBConfig>(c.get()) == config) return c.get();
    }
  }
  return nullptr;
}

const FbConfig* config_for_visual(DisplayState& d, const XVisualInfo* visual) {
  if (!visual) return nullptr;
  auto chosen = d.chosen.find(visual->visualid);
  if (chosen != d.chosen.end()) return chosen->second;  // only kept when configs share a visual
  const FbConfig* best = nullptr;
  for (const auto& c : screen_configs(d, visual->screen)) {
    if (c->visual.visualid != visual->visualid) continue;
    const platform::SurfaceConfig& s = c->surface;
    // The richest: double-buffered, then the most depth, stencil and accumulation bits; a
    // multisample buffer last (a visual of its own is never shared with one without).
    auto rank = [](const platform::SurfaceConfig& x) {
      return (x.double_buffered ? 1 << 20 : 0) + x.depth_bits * 1024 + x.stencil_bits * 32 + x.accum_bits -
             (x.samples > 0 ? 1 << 21 : 0);
    };
    if (!best || rank(s) > rank(best->surface)) best = c.get();
  }
  return best;
}

bool config_attribute(const FbConfig& c, int attribute, int& value) {
  const platform::SurfaceConfig& s = c.surface;
  switch (attribute) {
    case GLX_FBCONFIG_ID: value = c.id; return true;
    case GLX_BUFFER_SIZE: value = 32; return true;
    case GLX_LEVEL: case GLX_STEREO: case GLX_AUX_BUFFERS: value = 0; return true;
    case GLX_DOUBLEBUFFER: value = s.double_buffered ? True : False; return true;
    case GLX_RED_SIZE: case GLX_GREEN_SIZE: case GLX_BLUE_SIZE: case GLX_ALPHA_SIZE: value = 8; return true;
    case GLX_DEPTH_SIZE: value = s.depth_bits; return true;
    case GLX_STENCIL_SIZE: value = s.stencil_bits; return true;
    case GLX_ACCUM_RED_SIZE: case GLX_ACCUM_GREEN_SIZE: case GLX_ACCUM_BLUE_SIZE: case GLX_ACCUM_ALPHA_SIZE:
      value = s.accum_bits; return true;
    case GLX_RENDER_TYPE: value = GLX_RGBA_BIT; return true;
    case GLX_DRAWABLE_TYPE: value = c.drawable_types; return true;
    case GLX_X_RENDERABLE: case GLX_USE_GL: case GLX_RGBA: value = True; return true;
    case GLX_VISUAL_ID: value = int(c.visual.visualid); return true;
    case GLX_X_VISUAL_TYPE: value = GLX_TRUE_COLOR; return true;
    case GLX_CONFIG_CAVEAT: case GLX_TRANSPARENT_TYPE: value = GLX_NONE; return true;
    case GLX_TRANSPARENT_INDEX_VALUE: case GLX_TRANSPARENT_RED_VALUE: case GLX_TRANSPARENT_GREEN_VALUE:
    case GLX_TRANSPARENT_BLUE_VALUE: case GLX_TRANSPARENT_ALPHA_VALUE: value = 0; return true;
    case GLX_MAX_PBUFFER_WIDTH: case GLX_MAX_PBUFFER_HEIGHT: value = kMaxBufferDim; return true;
    case GLX_MAX_PBUFFER_PIXELS: value = kMaxBufferDim * kMaxBufferDim; return true;
    case GLX_SAMPLE_BUFFERS: value = s.samples > 0 ? 1 : 0; return true;
    case GLX_SAMPLES: value = s.samples; return true;
    case GLX_SCREEN: value = c.screen; return true;
    default: return false;
  }
}

XID new_xid(Display* dpy) {
  XID id = XAllocID(dpy);
  XNoOp(dpy);
  return id;
}

void send_x_error(Display* dpy, unsigned char code, XID resource, int minor_opcode) {
  DisplayState* d = display_state(dpy);
  if (!d) return;
  xError error{};
  LockDisplay(dpy);
  error.type = X_Error;
  error.errorCode = code;
  error.sequenceNumber = CARD16(dpy->request);
  error.resourceID = CARD32(resource);
  error.minorCode = CARD16(minor_opcode);
  error.majorCode = CARD8(d->glx_opcode);
  _XError(dpy, &error);
  UnlockDisplay(dpy);
}

void send_glx_error(Display* dpy, int glx_code, XID resource, int minor_opcode) {
  DisplayState* d = display_state(dpy);
  if (!d || d->glx_error_base == 0) return;  // no GLX extension: no GLX error codes either
  send_x_error(dpy, static_cast<unsigned char>(d->glx_error_base + glx_code), resource, minor_opcode);
}

ErrorTrap::ErrorTrap(Display* dpy) : dpy_(dpy), lock_(trap_mutex()) {
  XSync(dpy_, False);  // earlier errors belong to the application
  trapped_error = 0;
  old_ = XSetErrorHandler(trap_handler);
}

int ErrorTrap::finish() {
  if (!finished_) {
    XSync(dpy_, False);
    XSetErrorHandler(old_);
    finished_ = true;
  }
  return trapped_error;
}

ErrorTrap::~ErrorTrap() { finish(); }

}  // namespace shadelab::gl::glx
