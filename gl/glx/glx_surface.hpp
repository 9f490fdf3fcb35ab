// XSurface: a GLX drawable (GLX 1.4 section 2.2: a window, a GLX pixmap or a pbuffer) as a
// platform Surface whose image is an XImage, put on the X drawable with MIT-SHM when the
// server shares memory with us and with XPutImage otherwise. Pbuffers keep their image.
#pragma once

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>

#include <cstdint>
#include <vector>

#include "gl/glx/glx_vendor.hpp"
#include "gl/src/platform/surface.hpp"

namespace shadelab::gl::glx {

class XSurface final : public platform::Surface {
 public:
  enum class Kind { kWindow, kPixmap, kPbuffer };
  /// `x_drawable` is the window or pixmap (None for a pbuffer); `visual` its visual (a
  /// pixmap's: the configuration's). A pbuffer is `width` x `height`; the others are sized
  /// from the X drawable when first bound.
  XSurface(Display* dpy, Drawable x_drawable, Kind kind, const FbConfig& config,
           const XVisualInfo& visual, platform::ImageLayout layout, int width = 0, int height = 0);
  ~XSurface() override;

  Kind kind() const { return kind_; }
  const FbConfig& fbconfig() const { return *config_; }
  Drawable x_drawable() const { return x_drawable_; }
  unsigned long event_mask = 0;  ///< glXSelectEvent's (no event is ever generated)
  bool preserved = false;        ///< GLX_PRESERVED_CONTENTS of a pbuffer
  bool largest = false;          ///< GLX_LARGEST_PBUFFER of a pbuffer
  /// Swaps (double-buffered) or shows (single-buffered) the image: glXSwapBuffers.
  void swap_buffers() { swap(); }
  /// Called at XCloseDisplay: the connection is going, no request may be made any more.
  void forget_display();
  /// The X drawable's size now (a window's may change at any time).
  bool drawable_size(int& width, int& height);

 protected:
  std::uint8_t* allocate_image(int width, int height, int& row_pixels) override;
  void show() override;
  bool query_size(int& width, int& height) override;
  bool counts_frames() const override { return kind_ == Kind::kWindow; }

 private:
  void free_image();
  bool attach_shm(int width, int height);

  Display* dpy_;
  Drawable x_drawable_;
  Kind kind_;
  const FbConfig* config_;
  XVisualInfo visual_;
  GC gc_ = nullptr;
  XImage* image_ = nullptr;
  XShmSegmentInfo shm_{};
  bool shm_attached_ = false;
  int pbuffer_width_, pbuffer_height_;
  std::vector<std::uint8_t> pixels_;  // a pbuffer's image
};

}  // namespace shadelab::gl::glx
