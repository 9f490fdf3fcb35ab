// The platform layer shared by the window-system front ends (GLX now, EGL next): a Surface is
// a drawable as GL draws into it (GLX 1.4 section 2.2: windows, pixmaps, pbuffers): its
// configuration, its size and its image, the pixels in the layout its window system takes
// them (an XImage's memory for X). A context made current on a surface renders into its own
// framebuffer and presents the changed pixels into the surface's image at a flush or a swap,
// as OSMesa presents into the caller's buffer; the surface then shows the image. No X11 here,
// and nothing here creates contexts or picks configurations: gl/glx and gl/egl do.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "gl/src/context.hpp"

namespace shadelab::gl::platform {

/// What a drawable holds (GLX 1.4 section 3.3.3, EGL 1.5 section 3.4). Colour is always eight
/// bits per channel with alpha (the framebuffer's RGBA8); the window system shows RGB.
struct SurfaceConfig {
  int depth_bits = 24;
  int stencil_bits = 8;
  int accum_bits = 0;  ///< per channel
  bool double_buffered = true;
  int samples = 0;  ///< per pixel in the multisample buffer; 0: none
};

/// Where the pixels of a surface's image go: byte positions of R, G, B (and A, or -1) in a
/// 4-byte pixel, rows from the top.
enum class ImageLayout { kRgba, kBgra, kArgb };

class Surface : public SurfaceHooks {
 public:
  Surface(const SurfaceConfig& config, ImageLayout layout) : config_(config), layout_(layout) {}
  virtual ~Surface();
  Surface(const Surface&) = delete;
  Surface& operator=(const Surface&) = delete;

  const SurfaceConfig& config() const { return config_; }
  int width() const { return width_; }
  int height() const { return height_; }
  /// Whether a context draws into this surface (is current on it, in any thread).
  bool is_bound() const { return !bound_.empty(); }

  /// Presents what the bound context drew (as glFlush does), shows it and counts a frame: a
  /// double-buffered surface's swap (GLX 1.4 section 3.3.10: an implicit glFlush first), or the
  /// flush of a single-buffered one. Then checks the drawable's size, as llvmpipe does after a
  /// swap.
  void swap();
  /// Follows the drawable's size now (a resized window): the image and the bound context's
  /// framebuffer are resized, their pixels undefined, as a window system's are.
  void follow_size();
  /// Writes the image as the window shows it into `out`: RGBA rows from the top, alpha 255
  /// (width * height * 4 bytes).
  void copy_rgba(std::vector<std::uint8_t>& out) const;

  void flushed(GlContext& c) override;
  void viewport_set(GlContext& c) override;

 protected:
  /// Sizes the image for the drawable: (re)allocates it through allocate_image.
  void set_size(int width, int height);
  /// Makes an image of width x height pixels and returns its memory (4 bytes a pixel, rows of
  /// row_pixels, from the top); freed by the next call or by the destructor of the subclass.
  virtual std::uint8_t* allocate_image(int width, int height, int& row_pixels) = 0;
  /// Shows the image in the window system (XPutImage); nothing for off-screen surfaces.
  virtual void show() {}
  /// Queries the drawable's size from the window system; false when it has none (pbuffers)
  /// or the query failed, and then the size stays.
  virtual bool query_size(int& width, int& height) = 0;
  /// Whether swaps and flushes of this surface are frames (`shadelab run --capture`).
  virtual bool counts_frames() const { return false; }
  /// Unbinds the context before the subclass frees the image (its destructor calls this).
  void release_context();

 private:
  friend bool make_current(GlContext* c, Surface* draw);
  void bind(GlContext& c);
  void unbind(GlContext& c);
  void point_at_image(GlContext& c) const;
  void frame_shown();

  SurfaceConfig config_;
  ImageLayout layout_;
  int width_ = 0, height_ = 0;
  std::uint8_t* image_ = nullptr;
  int row_pixels_ = 0;
  // The contexts current on it: one, but GLX lets a drawable be current to contexts in
  // several threads (what they draw then is undefined, not a crash).
  std::vector<GlContext*> bound_;
};

/// Makes `c` this thread's current context drawing into `draw`, or releases the thread's
/// context when `c` is null. The old context's drawing is presented into its surface first (a
/// single-buffered window shows it). The first time a context is made current, its viewport
/// is set to the surface's size (GLX 1.4 section 3.3.7). Returns false, releasing the thread's
/// context, when the surface's image cannot be allocated.
bool make_current(GlContext* c, Surface* draw);

/// The surface the thread's current context draws into, or null.
Surface* current_surface();

}  // namespace shadelab::gl::platform
