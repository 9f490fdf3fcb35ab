// Surfaces and make-current for the window-system front ends (surface.hpp): a context renders
// into its own framebuffer and presents into the surface's image as OSMesa presents into the
// caller's buffer (present.cpp); swaps and single-buffered flushes show the image and are
// frames for `shadelab run` (run_link.hpp). Nothing here knows X11 or EGL.
#include "gl/src/platform/surface.hpp"

#include <GL/osmesa.h>

#include <algorithm>

#include "gl/src/capture.hpp"
#include "gl/src/platform/run_link.hpp"

namespace shadelab::gl::platform {
namespace {

GLenum osmesa_format(ImageLayout layout) {
  switch (layout) {
    case ImageLayout::kBgra: return OSMESA_BGRA;
    case ImageLayout::kArgb: return OSMESA_ARGB;
    default: return OSMESA_RGBA;
  }
}

// The drawing of `c` reaches its surface's image (and its depth export, as at glFlush).
void present_context(GlContext& c) {
  present(c);
  if (c.depth_exported) export_depth(c);
}

}  // namespace

Surface::~Surface() = default;

void Surface::release_context() {
  // A context current on a destroyed drawable draws into nothing until made current again.
  while (!bound_.empty()) unbind(*bound_.back());
}

void Surface::set_size(int width, int height) {
  width = std::clamp(width, 1, kMaxBufferDim);
  height = std::clamp(height, 1, kMaxBufferDim);
  for (GlContext* c : bound_) settle_clears(*c);  // nothing may still write into the old image
  image_ = allocate_image(width, height, row_pixels_);
  width_ = width;
  height_ = height;
  for (GlContext* c : bound_) point_at_image(*c);
}

// The context's framebuffer follows the surface's size; every pixel is presented again.
void Surface::point_at_image(GlContext& c) const {
  settle_clears(c);
  c.user.data = image_;
  c.user.width = width_;
  c.user.height = height_;
  c.user.row_length = row_pixels_;
  c.user.y_up = false;
  c.user.format = osmesa_format(layout_);
  if (c.fb.width != width_ || c.fb.height != height_) {
    leave_drawable(c);  // a front buffer of the old size: read again from the image
    c.fb.resize(width_, height_);
  }
  c.fb.color.detach();
  reset_tiles(c);
  mark_all_changed(c);
  if (c.surface == this) select_draw_buffer(c);
}

void Surface::bind(GlContext& c) {
  if (width_ == 0) {
    int w = 0, h = 0;
    if (!query_size(w, h)) w = h = 1;
    set_size(w, h);
  }
  leave_drawable(c);
  point_at_image(c);
  c.surface = this;
  c.double_buffered = config_.double_buffered;
  bound_.push_back(&c);
  select_draw_buffer(c);
  // GLX 1.4 section 3.3.7 (EGL 1.5 section 3.7.3): the first binding sets the viewport and
  // the scissor box to the drawable's size.
  if (!c.ever_current) set_initial_window_state(c, width_, height_);
}

void Surface::unbind(GlContext& c) {
  present_context(c);
  if (!config_.double_buffered) show();
  c.surface = nullptr;
  c.user.data = nullptr;  // the image belongs to the surface; unbound, nothing is presented
  bound_.erase(std::remove(bound_.begin(), bound_.end(), &c), bound_.end());
}

void Surface::swap() {
  GlContext* c = current_context();
  if (c && c->surface == this) {
    if (c->front_in_fb) exchange_color_buffers(*c);  // the back buffer is shown
    present_context(*c);
    capture_frame_end(*c);  // before the runner hears of the frame (it may end the program)
  }
  show();
  frame_shown();
  follow_size();
  if (c && c->surface == this) swapped_color_buffers(*c);
}

void Surface::follow_size() {
  int w = 0, h = 0;
  if (query_size(w, h) && (w != width_ || h != height_)) set_size(w, h);
}

void Surface::flushed(GlContext& c) {
  if (config_.double_buffered) {
    // The back buffer is shown at the swap; what was drawn into the front one, now.
    if (c.front_in_fb) present_context(c);
    if (c.front_in_fb || !c.other_color.empty()) show();
    return;
  }
  present_context(c);
  capture_frame_end(c);
  show();
  frame_shown();
}

void Surface::viewport_set(GlContext& /*c*/) { follow_size(); }

void Surface::frame_shown() {
  if (!counts_frames() || !run_link::active()) return;
  run_link::frame(*this);
}

void Surface::copy_rgba(std::vector<std::uint8_t>& out) const {
  out.resize(std::size_t(width_) * std::size_t(height_) * 4);
  int r = 0, g = 1, b = 2;
  if (layout_ == ImageLayout::kBgra) r = 2, b = 0;
  if (layout_ == ImageLayout::kArgb) r = 1, g = 2, b = 3;
  std::uint8_t* dst = out.data();
  for (int y = 0; y < height_; ++y) {
    const std::uint8_t* src = image_ + std::size_t(y) * std::size_t(row_pixels_) * 4;
    for (int x = 0; x < width_; ++x, src += 4, dst += 4) {
      dst[0] = src[r], dst[1] = src[g], dst[2] = src[b], dst[3] = 255;  // a window shows no alpha
    }
  }
}

bool make_current(GlContext* c, Surface* draw) {
  GlContext* old = current_context();
  if (old && old->surface) static_cast<Surface*>(old->surface)->unbind(*old);
  else if (old) present_context(*old);
  current_context() = nullptr;
  if (!c) return true;
  try {
    if (draw) draw->bind(*c);
  } catch (...) {
    return false;  // the image or the framebuffer could not be allocated
  }
  current_context() = c;
  return true;
}

Surface* current_surface() {
  GlContext* c = current_context();
  return c ? static_cast<Surface*>(c->surface) : nullptr;
}

}  // namespace shadelab::gl::platform
