// EGL configurations (EGL 1.5 section 3.4): eglGetConfigs, eglChooseConfig (the matching
// criteria and sort order of table 3.4), eglGetConfigAttrib. shadelab's configurations draw
// pbuffers with OpenGL: RGBA 8/8/8/8; depth/stencil 24/8, 24/0, 16/0 or none, and 24/8 with 4
// samples. No surfaces here.
#include <algorithm>

#include "gl/egl/egl_vendor.hpp"

namespace shadelab::gl::egl {
namespace {

constexpr EGLint kDontCare = EGL_DONT_CARE;

// What an attribute list asks for; EGL 1.5 table 3.4's defaults.
struct Request {
  EGLint config_id = kDontCare;
  EGLint color[4] = {0, 0, 0, 0};  // red, green, blue, alpha minimums
  EGLint buffer = 0, depth = 0, stencil = 0, samples = 0, sample_buffers = 0, luminance = 0, alpha_mask = 0;
  EGLint level = 0;
  EGLint surface_type = EGL_WINDOW_BIT, renderable = EGL_OPENGL_ES_BIT, conformant = 0;
  EGLint color_buffer_type = EGL_RGB_BUFFER, caveat = kDontCare, transparent = EGL_NONE;
  EGLint bind_rgb = kDontCare, bind_rgba = kDontCare, native_renderable = kDontCare;
  EGLint native_visual_type = kDontCare, min_swap = kDontCare, max_swap = kDontCare;
};

bool read_attribute(Request& r, EGLint name, EGLint value) {
  switch (name) {
    case EGL_CONFIG_ID: r.config_id = value; return true;
    case EGL_RED_SIZE: r.color[0] = value; return true;
    case EGL_GREEN_SIZE: r.color[1] = value; return true;
    case EGL_BLUE_SIZE: r.color[2] = value; return true;
    case EGL_ALPHA_SIZE: r.color[3] = value; return true;
    case EGL_BUFFER_SIZE: r.buffer = value; return true;
    case EGL_DEPTH_SIZE: r.depth = value; return true;
    case EGL_STENCIL_SIZE: r.stencil = value; return true;
    case EGL_SAMPLES: r.samples = value; return true;
    case EGL_SAMPLE_BUFFERS: r.sample_buffers = value; return true;
    case EGL_LUMINANCE_SIZE: r.luminance = value; return true;
    case EGL_ALPHA_MASK_SIZE: r.alpha_mask = value; return true;
    case EGL_LEVEL: r.level = value; return true;
    case EGL_SURFACE_TYPE: r.surface_type = value; return true;
    case EGL_RENDERABLE_TYPE: r.renderable = value; return true;
    case EGL_CONFORMANT: r.conformant = value; return true;
    case EGL_COLOR_BUFFER_TYPE: r.color_buffer_type = value; return true;
    case EGL_CONFIG_CAVEAT: r.caveat = value; return true;
    case EGL_TRANSPARENT_TYPE: r.transparent = value; return true;
    case EGL_BIND_TO_TEXTURE_RGB: r.bind_rgb = value; return true;
    case EGL_BIND_TO_TEXTURE_RGBA: r.bind_rgba = value; return true;
    case EGL_NATIVE_RENDERABLE: r.native_renderable = value; return true;
    case EGL_NATIVE_VISUAL_TYPE: r.native_visual_type = value; return true;
    case EGL_MIN_SWAP_INTERVAL: r.min_swap = value; return true;
    case EGL_MAX_SWAP_INTERVAL: r.max_swap = value; return true;
    case EGL_TRANSPARENT_RED_VALUE: case EGL_TRANSPARENT_GREEN_VALUE: case EGL_TRANSPARENT_BLUE_VALUE:
    case EGL_MATCH_NATIVE_PIXMAP: case EGL_MAX_PBUFFER_WIDTH: case EGL_MAX_PBUFFER_HEIGHT:
    case EGL_MAX_PBUFFER_PIXELS: case EGL_NATIVE_VISUAL_ID:
      return true;  // ignored by eglChooseConfig (table 3.4)
    default: return false;
  }
}

EGLint value_of(const Config& c, EGLint attribute) {
  EGLint v = 0;
  config_attribute(c, attribute, v);
  return v;
}

bool at_least(EGLint wanted, EGLint have) { return wanted == kDontCare || have >= wanted; }
bool exactly(EGLint wanted, EGLint have) { return wanted == kDontCare || have == wanted; }
bool has_bits(EGLint wanted, EGLint have) { return wanted == kDontCare || (wanted & ~have) == 0; }

bool matches(const Request& r, const Config& c) {
  if (r.config_id != kDontCare) return r.config_id == c.id;  // every other attribute ignored
  for (int i = 0; i < 4; ++i) {
    if (!at_least(r.color[i], 8)) return false;
  }
  if (!at_least(r.buffer, 32) || !at_least(r.depth, c.surface.depth_bits) ||
      !at_least(r.stencil, c.surface.stencil_bits) || !at_least(r.samples, c.surface.samples) ||
      !at_least(r.sample_buffers, c.surface.samples > 0 ? 1 : 0) ||
      !at_least(r.luminance, 0) || !at_least(r.alpha_mask, 0) || !exactly(r.level, 0)) {
    return false;
  }
  if (!has_bits(r.surface_type, value_of(c, EGL_SURFACE_TYPE)) || !has_bits(r.renderable, EGL_OPENGL_BIT) ||
      !has_bits(r.conformant, EGL_OPENGL_BIT)) {
    return false;
  }
  return exactly(r.color_buffer_type, EGL_RGB_BUFFER) && exactly(r.caveat, EGL_NONE) &&
         exactly(r.transparent, EGL_NONE) && exactly(r.bind_rgb, EGL_FALSE) && exactly(r.bind_rgba, EGL_FALSE) &&
         exactly(r.native_renderable, EGL_FALSE) && exactly(r.native_visual_type, EGL_NONE) &&
         exactly(r.min_swap, 0) && exactly(r.max_swap, 1);
}

// Table 3.4's sort: the colour sizes are all equal here; then fewer samples (EGL_SAMPLE_BUFFERS
// and EGL_SAMPLES), smaller depth, smaller stencil, and smaller EGL_CONFIG_ID.
bool better(const Config* a, const Config* b) {
  if (a->surface.samples != b->surface.samples) return a->surface.samples < b->surface.samples;
  if (a->surface.depth_bits != b->surface.depth_bits) return a->surface.depth_bits < b->surface.depth_bits;
  if (a->surface.stencil_bits != b->surface.stencil_bits) return a->surface.stencil_bits < b->surface.stencil_bits;
  return a->id < b->id;
}

EGLBoolean list(const std::vector<const Config*>& found, EGLConfig* configs, EGLint size, EGLint* count) {
  if (!count) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  if (!configs) {
    *count = EGLint(found.size());
    return EGL_TRUE;
  }
  EGLint n = std::min<EGLint>(std::max<EGLint>(size, 0), EGLint(found.size()));
  for (EGLint i = 0; i < n; ++i) configs[i] = reinterpret_cast<EGLConfig>(const_cast<Config*>(found[std::size_t(i)]));
  *count = n;
  return EGL_TRUE;
}

Display* initialized_display(EGLDisplay dpy) {
  Display* d = find_display(dpy);
  if (!d) return fail(EGL_BAD_DISPLAY, static_cast<Display*>(nullptr));
  if (!d->initialized) return fail(EGL_NOT_INITIALIZED, static_cast<Display*>(nullptr));
  return d;
}

}  // namespace

const Config* find_config(Display& d, EGLConfig config) {
  for (const auto& c : d.configs) {
    if (reinterpret_cast<EGLConfig>(c.get()) == config) return c.get();
  }
  return nullptr;
}

bool config_attribute(const Config& c, EGLint attribute, EGLint& value) {
  switch (attribute) {
    case EGL_CONFIG_ID: value = c.id; return true;
    case EGL_RED_SIZE: case EGL_GREEN_SIZE: case EGL_BLUE_SIZE: case EGL_ALPHA_SIZE: value = 8; return true;
    case EGL_BUFFER_SIZE: value = 32; return true;
    case EGL_DEPTH_SIZE: value = c.surface.depth_bits; return true;
    case EGL_STENCIL_SIZE: value = c.surface.stencil_bits; return true;
    case EGL_SAMPLES: value = c.surface.samples; return true;
    case EGL_SAMPLE_BUFFERS: value = c.surface.samples > 0 ? 1 : 0; return true;
    case EGL_LUMINANCE_SIZE: case EGL_ALPHA_MASK_SIZE: case EGL_LEVEL: case EGL_NATIVE_VISUAL_ID: case EGL_TRANSPARENT_RED_VALUE:
    case EGL_TRANSPARENT_GREEN_VALUE: case EGL_TRANSPARENT_BLUE_VALUE: case EGL_MIN_SWAP_INTERVAL:
      value = 0; return true;
    case EGL_MAX_SWAP_INTERVAL: value = 1; return true;
    case EGL_BIND_TO_TEXTURE_RGB: case EGL_BIND_TO_TEXTURE_RGBA: case EGL_NATIVE_RENDERABLE: value = EGL_FALSE; return true;
    case EGL_COLOR_BUFFER_TYPE: value = EGL_RGB_BUFFER; return true;
    case EGL_CONFIG_CAVEAT: case EGL_NATIVE_VISUAL_TYPE: case EGL_TRANSPARENT_TYPE: value = EGL_NONE; return true;
    case EGL_MAX_PBUFFER_WIDTH: case EGL_MAX_PBUFFER_HEIGHT: value = kMaxBufferDim; return true;
    case EGL_MAX_PBUFFER_PIXELS: value = kMaxBufferDim * kMaxBufferDim; return true;
    case EGL_SURFACE_TYPE: value = EGL_PBUFFER_BIT; return true;
    case EGL_RENDERABLE_TYPE: case EGL_CONFORMANT: value = EGL_OPENGL_BIT; return true;
    default: return false;
  }
}

EGLBoolean get_configs(EGLDisplay dpy, EGLConfig* configs, EGLint size, EGLint* count) {
  std::lock_guard lock(vendor_mutex());
  Display* d = initialized_display(dpy);
  if (!d) return EGL_FALSE;
  std::vector<const Config*> all;
  for (const auto& c : d->configs) all.push_back(c.get());
  return list(all, configs, size, count);
}

EGLBoolean choose_config(EGLDisplay dpy, const EGLint* attributes, EGLConfig* configs, EGLint size, EGLint* count) {
  std::lock_guard lock(vendor_mutex());
  Display* d = initialized_display(dpy);
  if (!d) return EGL_FALSE;
  Request r;
  for (int i = 0; attributes && attributes[i] != EGL_NONE; i += 2) {
    if (!read_attribute(r, attributes[i], attributes[i + 1])) return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  }
  std::vector<const Config*> found;
  for (const auto& c : d->configs) {
    if (matches(r, *c)) found.push_back(c.get());
  }
  std::stable_sort(found.begin(), found.end(), better);
  return list(found, configs, size, count);
}

EGLBoolean get_config_attrib(EGLDisplay dpy, EGLConfig config, EGLint attribute, EGLint* value) {
  std::lock_guard lock(vendor_mutex());
  Display* d = initialized_display(dpy);
  if (!d) return EGL_FALSE;
  const Config* c = find_config(*d, config);
  if (!c) return fail(EGL_BAD_CONFIG, EGL_FALSE);
  EGLint v = 0;
  if (!config_attribute(*c, attribute, v)) return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  if (value) *value = v;
  return EGL_TRUE;
}

}  // namespace shadelab::gl::egl
