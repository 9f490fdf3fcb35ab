// XSurface (glx_surface.hpp): the image of a GLX drawable in an XImage, shared with the X
// server through MIT-SHM when it can be (one copy less per frame) and sent by XPutImage
// otherwise; the X drawable's size queried with errors trapped (a window may be gone).
#include "gl/glx/glx_surface.hpp"

#include <sys/ipc.h>
#include <sys/shm.h>

#include <cstdlib>
#include <new>

#include "gl/src/platform/run_link.hpp"

namespace shadelab::gl::glx {
namespace {

// `shadelab run --size WxH`: a top-level window is resized before its first frame (GLUT
// programs then get a reshape to that size from the X server, as if the user resized it).
void apply_requested_size(Display* dpy, Window window) {
  int width = 0, height = 0;
  if (!platform::run_link::requested_size(width, height)) return;
  ErrorTrap trap(dpy);
  Window root = 0, parent = 0, *children = nullptr;
  unsigned count = 0;
  if (!XQueryTree(dpy, window, &root, &parent, &children, &count)) return;
  if (children) XFree(children);
  if (parent == root) XResizeWindow(dpy, window, unsigned(width), unsigned(height));
}

}  // namespace

XSurface::XSurface(Display* dpy, Drawable x_drawable, Kind kind, const FbConfig& config,
                   const XVisualInfo& visual, platform::ImageLayout layout, int width, int height)
    : platform::Surface(config.surface, layout),
      dpy_(dpy), x_drawable_(x_drawable), kind_(kind), config_(&config), visual_(visual),
      pbuffer_width_(width), pbuffer_height_(height) {
  if (kind_ == Kind::kWindow) apply_requested_size(dpy_, x_drawable_);
}

XSurface::~XSurface() {
  release_context();
  free_image();
  if (gc_ && dpy_) XFreeGC(dpy_, gc_);
}

void XSurface::forget_display() {
  dpy_ = nullptr;  // nothing is shown any more
  release_context();
  if (image_) {
    if (shm_attached_) image_->data = nullptr;  // the segment is detached below, not freed by Xlib
    XDestroyImage(image_);  // client memory only
    image_ = nullptr;
  }
  if (shm_attached_) shmdt(shm_.shmaddr);
  shm_attached_ = false;
  if (gc_) XFree(gc_);  // the GC's client-side record (its server side goes with the connection)
  gc_ = nullptr;
}

void XSurface::free_image() {
  if (!image_) return;
  if (shm_attached_) {
    if (dpy_) XShmDetach(dpy_, &shm_);
    if (dpy_) XSync(dpy_, False);  // the server lets go before the memory does
    image_->data = nullptr;
    shmdt(shm_.shmaddr);
    shm_attached_ = false;
  }
  XDestroyImage(image_);
  image_ = nullptr;
}

bool XSurface::attach_shm(int width, int height) {
  DisplayState* d = display_state(dpy_);
  if (!d || !d->shm) return false;
  image_ = XShmCreateImage(dpy_, visual_.visual, unsigned(visual_.depth), ZPixmap, nullptr, &shm_,
                           unsigned(width), unsigned(height));
  if (!image_) return false;
  const std::size_t bytes = std::size_t(image_->bytes_per_line) * std::size_t(height);
  shm_.shmid = shmget(IPC_PRIVATE, bytes, IPC_CREAT | 0600);
  void* memory = shm_.shmid >= 0 ? shmat(shm_.shmid, nullptr, 0) : reinterpret_cast<void*>(-1);
  bool ok = memory != reinterpret_cast<void*>(-1);
  if (ok) {
    shm_.shmaddr = image_->data = static_cast<char*>(memory);
    shm_.readOnly = False;
    ErrorTrap trap(dpy_);
    XShmAttach(dpy_, &shm_);
    ok = trap.finish() == 0;  // a remote server cannot attach our memory
    if (!ok) shmdt(memory);
  }
  if (shm_.shmid >= 0) shmctl(shm_.shmid, IPC_RMID, nullptr);  // freed once both let go
  if (!ok) {
    image_->data = nullptr;
    XDestroyImage(image_);
    image_ = nullptr;
    d->shm = false;  // do not try again on this display
    return false;
  }
  shm_attached_ = true;
  return true;
}

std::uint8_t* XSurface::allocate_image(int width, int height, int& row_pixels) {
  free_image();
  if (kind_ == Kind::kPbuffer || !dpy_) {
    pixels_.assign(std::size_t(width) * std::size_t(height) * 4, 0);
    row_pixels = width;
    return pixels_.data();
  }
  if (!attach_shm(width, height)) {
    auto* data = static_cast<char*>(std::calloc(std::size_t(width) * std::size_t(height), 4));
    if (!data) throw std::bad_alloc();
    image_ = XCreateImage(dpy_, visual_.visual, unsigned(visual_.depth), ZPixmap, 0, data, unsigned(width),
                          unsigned(height), 32, width * 4);
    if (!image_) {
      std::free(data);
      throw std::bad_alloc();
    }
  }
  row_pixels = image_->bytes_per_line / 4;
  return reinterpret_cast<std::uint8_t*>(image_->data);
}

void XSurface::show() {
  if (!image_ || !dpy_ || kind_ == Kind::kPbuffer) return;
  if (!gc_) gc_ = XCreateGC(dpy_, x_drawable_, 0, nullptr);
  const unsigned w = unsigned(width()), h = unsigned(height());
  if (shm_attached_) {
    XShmPutImage(dpy_, x_drawable_, gc_, image_, 0, 0, 0, 0, w, h, False);
    XSync(dpy_, False);  // the server has read the image before the next frame is written into it
  } else {
    XPutImage(dpy_, x_drawable_, gc_, image_, 0, 0, 0, 0, w, h);
    XFlush(dpy_);
  }
}

bool XSurface::drawable_size(int& width, int& height) {
  if (!dpy_ || kind_ == Kind::kPbuffer) return false;
  ErrorTrap trap(dpy_);
  Window root = 0;
  int x = 0, y = 0;
  unsigned w = 0, h = 0, border = 0, depth = 0;
  Status ok = XGetGeometry(dpy_, x_drawable_, &root, &x, &y, &w, &h, &border, &depth);
  if (trap.finish() != 0 || !ok) return false;
  width = int(w), height = int(h);
  return true;
}

bool XSurface::query_size(int& width, int& height) {
  if (kind_ == Kind::kPbuffer) {
    width = pbuffer_width_, height = pbuffer_height_;
    return true;
  }
  return drawable_size(width, height);
}

}  // namespace shadelab::gl::glx
