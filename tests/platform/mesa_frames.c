/* A preload library that captures the frames a GL program shows on Mesa as `shadelab run
 * --capture` captures them on shadelab, for compare_with_mesa.sh (docs/gl-conformance.md,
 * "Programs written by others"):
 *   MESA_FRAMES_OUT=DIR/m%04d.png  (frame numbers from 1)
 *   MESA_FRAMES_COUNT=N            (the program ends, status 0, after frame N)
 *   MESA_FRAMES_SIZE=WxH           (top-level windows resized when first made current)
 * A frame is a glXSwapBuffers (the back buffer read before the swap), or a glFlush / glFinish
 * while the current drawable is single-buffered (the front buffer read). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <png.h>
#include <X11/Xlib.h>
#include <GL/gl.h>
#include <GL/glx.h>

static int frame_no = 0;
static int capturing = 0;

static void *real(const char *name) {
  void *p = dlsym(RTLD_NEXT, name);
  if (!p) { fprintf(stderr, "mesa_frames: no %s\n", name); _exit(3); }
  return p;
}

static void write_png(const char *path, int w, int h, const unsigned char *rgba) {
  FILE *f = fopen(path, "wb");
  if (!f) { perror(path); return; }
  png_structp p = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
  png_infop info = png_create_info_struct(p);
  if (setjmp(png_jmpbuf(p))) { fclose(f); return; }
  png_init_io(p, f);
  png_set_IHDR(p, info, w, h, 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(p, info);
  for (int y = h - 1; y >= 0; --y) png_write_row(p, (png_bytep)(rgba + (size_t)y * w * 4));
  png_write_end(p, info);
  png_destroy_write_struct(&p, &info);
  fclose(f);
}

static void capture(Display *dpy, GLXDrawable d, GLenum buffer) {
  if (capturing) return;
  capturing = 1;
  Window root; int x, y; unsigned w = 0, h = 0, bw, depth;
  if (!dpy) dpy = glXGetCurrentDisplay();
  if (!dpy || !d || !XGetGeometry(dpy, d, &root, &x, &y, &w, &h, &bw, &depth) || !w || !h) {
    GLint vp[4]; glGetIntegerv(GL_VIEWPORT, vp); w = vp[2]; h = vp[3];
  }
  ++frame_no;
  const char *pattern = getenv("MESA_FRAMES_OUT");
  if (pattern && *pattern) {
    unsigned char *px = calloc((size_t)w * h, 4);
    glPushAttrib(GL_PIXEL_MODE_BIT);
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glPixelStorei(GL_PACK_ALIGNMENT, 1); glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0); glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_PACK_SWAP_BYTES, 0); glPixelStorei(GL_PACK_LSB_FIRST, 0);
    glPixelTransferi(GL_MAP_COLOR, 0);
    glPixelTransferf(GL_RED_SCALE, 1); glPixelTransferf(GL_GREEN_SCALE, 1);
    glPixelTransferf(GL_BLUE_SCALE, 1); glPixelTransferf(GL_ALPHA_SCALE, 1);
    glPixelTransferf(GL_RED_BIAS, 0); glPixelTransferf(GL_GREEN_BIAS, 0);
    glPixelTransferf(GL_BLUE_BIAS, 0); glPixelTransferf(GL_ALPHA_BIAS, 0);
    glReadBuffer(buffer);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px);
    glPopClientAttrib();
    glPopAttrib();
    char path[4096];
    snprintf(path, sizeof path, pattern, frame_no);
    write_png(path, w, h, px);
    free(px);
  }
  const char *n = getenv("MESA_FRAMES_COUNT");
  if (n && frame_no >= atoi(n)) { fflush(NULL); _exit(0); }
  capturing = 0;
}

static Window resized[64];
static int nresized = 0;

static void maybe_resize(Display *dpy, GLXDrawable d) {
  const char *s = getenv("MESA_FRAMES_SIZE");
  int w, h;
  if (!dpy || !d || !s || sscanf(s, "%dx%d", &w, &h) != 2) return;
  for (int i = 0; i < nresized; ++i) if (resized[i] == d) return;
  if (nresized < 64) resized[nresized++] = d;
  Window root, parent, *children = NULL; unsigned count;
  if (!XQueryTree(dpy, d, &root, &parent, &children, &count)) return;  /* not a window: ignored */
  if (children) XFree(children);
  if (parent == root) XResizeWindow(dpy, d, w, h);
}

Bool glXMakeCurrent(Display *dpy, GLXDrawable d, GLXContext c) {
  static Bool (*f)(Display *, GLXDrawable, GLXContext);
  if (!f) f = real("glXMakeCurrent");
  maybe_resize(dpy, d);
  return f(dpy, d, c);
}

Bool glXMakeContextCurrent(Display *dpy, GLXDrawable d, GLXDrawable r, GLXContext c) {
  static Bool (*f)(Display *, GLXDrawable, GLXDrawable, GLXContext);
  if (!f) f = real("glXMakeContextCurrent");
  maybe_resize(dpy, d);
  return f(dpy, d, r, c);
}

void glXSwapBuffers(Display *dpy, GLXDrawable d) {
  static void (*f)(Display *, GLXDrawable);
  if (!f) f = real("glXSwapBuffers");
  if (d == glXGetCurrentDrawable()) capture(dpy, d, GL_BACK);
  f(dpy, d);
}

static int single_buffered(void) {
  if (!glXGetCurrentContext()) return 0;
  GLboolean db = GL_TRUE;
  glGetBooleanv(GL_DOUBLEBUFFER, &db);
  return !db;
}

void glFlush(void) {
  static void (*f)(void);
  if (!f) f = real("glFlush");
  f();
  if (!capturing && single_buffered()) capture(glXGetCurrentDisplay(), glXGetCurrentDrawable(), GL_FRONT);
}

void glFinish(void) {
  static void (*f)(void);
  if (!f) f = real("glFinish");
  f();
  if (!capturing && single_buffered()) capture(glXGetCurrentDisplay(), glXGetCurrentDrawable(), GL_FRONT);
}
