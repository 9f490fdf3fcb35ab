/* GLX through GLVND, for shadelab's platform tests (tests/platform): plain Xlib + GLX 1.4,
   linked with -lGL -lX11 and nothing of shadelab's, so that it runs on any vendor.

     glx_contexts            functional checks; prints "ok NAME" or "FAIL NAME: ..." per check and
                             exits 1 if any failed
     glx_contexts --errors   prints what each wrong call returns and the X error it raises, one
                             line each (compared between Mesa and shadelab by the test)

   Checks: configurations, a double-buffered window (its swap reaches the X window), a
   single-buffered one (its glFlush does), texture sharing between contexts, two threads drawing
   with two contexts at once, release, destroying a current context, glXCopyContext, a pbuffer,
   a GLX pixmap, glXGetProcAddress, following a window's resize. */
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static Display* dpy;
static int failures = 0, glx_error_base = 0, last_error = 0;

static int on_error(Display* d, XErrorEvent* e) {
  (void)d;
  last_error = e->error_code;
  return 0;
}

static void check(int ok, const char* name, const char* detail) {
  if (ok) printf("ok %s\n", name);
  else printf("FAIL %s: %s\n", name, detail), ++failures;
}

static GLXFBConfig choose(int doubled) {
  int attributes[] = {GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, GLX_RED_SIZE, 8,
                      GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_DEPTH_SIZE, 16, GLX_DOUBLEBUFFER, doubled, None};
  int n = 0;
  GLXFBConfig* list = glXChooseFBConfig(dpy, DefaultScreen(dpy), attributes, &n);
  GLXFBConfig c = n > 0 ? list[0] : NULL;
  XFree(list);
  return c;
}

static Window make_window(XVisualInfo* v, int w, int h) {
  XSetWindowAttributes a;
  memset(&a, 0, sizeof a);
  a.colormap = XCreateColormap(dpy, RootWindow(dpy, v->screen), v->visual, AllocNone);
  Window win = XCreateWindow(dpy, RootWindow(dpy, v->screen), 0, 0, (unsigned)w, (unsigned)h, 0, v->depth,
                             InputOutput, v->visual, CWColormap, &a);
  XMapWindow(dpy, win);
  XSync(dpy, False);
  return win;
}

/* The pixel the X server holds at (x, y) of a drawable, as 0xRRGGBB. */
static unsigned long x_pixel(Drawable d, int x, int y) {
  XImage* image = XGetImage(dpy, d, x, y, 1, 1, AllPlanes, ZPixmap);
  if (!image) return 0xdeadbeef;
  unsigned long p = XGetPixel(image, 0, 0) & 0xffffff;
  XDestroyImage(image);
  return p;
}

static unsigned long gl_pixel(int x, int y) {
  unsigned char rgb[3];
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x, y, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  return ((unsigned long)rgb[0] << 16) | ((unsigned long)rgb[1] << 8) | rgb[2];
}

static void clear_to(float r, float g, float b) {
  glClearColor(r, g, b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

static void windows_and_swaps(void) {
  GLXFBConfig c = choose(True);
  check(c != NULL, "fbconfig.double", "no double-buffered RGBA config with depth");
  if (!c) return;
  int depth = 0, doubled = 0;
  glXGetFBConfigAttrib(dpy, c, GLX_DEPTH_SIZE, &depth);
  glXGetFBConfigAttrib(dpy, c, GLX_DOUBLEBUFFER, &doubled);
  check(depth >= 16 && doubled, "fbconfig.attributes", "depth or double-buffering not as asked");
  XVisualInfo* v = glXGetVisualFromFBConfig(dpy, c);
  Window win = make_window(v, 64, 48);
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
  check(ctx && glXMakeContextCurrent(dpy, win, win, ctx), "context.new", "no context or make current failed");
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  check(viewport[2] == 64 && viewport[3] == 48, "context.first_viewport", "viewport is not the window's size");
  clear_to(1, 0, 0);
  glXSwapBuffers(dpy, win);
  check(x_pixel(win, 32, 24) == 0xff0000, "swap.reaches_window", "the window does not show the swapped frame");
  /* The window grows: the next frame is drawn at its new size (checked where llvmpipe checks:
     glViewport, the swap). */
  XResizeWindow(dpy, win, 100, 80);
  XSync(dpy, False);
  glViewport(0, 0, 100, 80);
  clear_to(0, 0, 1);
  glXSwapBuffers(dpy, win);
  check(x_pixel(win, 90, 70) == 0x0000ff && gl_pixel(90, 70) == 0x0000ff, "resize.followed",
        "the frame after a resize does not cover the new area");
  glXMakeContextCurrent(dpy, None, None, NULL);
  check(glXGetCurrentContext() == NULL, "release", "a context is still current");
  glGetError(); /* no context: must not crash */
  glXDestroyContext(dpy, ctx);
  XDestroyWindow(dpy, win);
  XFree(v);
}

static void rect_at(float x0, float x1, float z, float r, float g, float b) {
  glColor3f(r, g, b);
  glBegin(GL_QUADS);
  glVertex3f(x0, -1, z), glVertex3f(x1, -1, z), glVertex3f(x1, 1, z), glVertex3f(x0, 1, z);
  glEnd();
}

static unsigned long read_from(GLenum buffer, int x, int y) {
  glReadBuffer(buffer);
  return gl_pixel(x, y);
}

/* The front and the back buffer of a double-buffered window are two buffers: the window shows
   the front one, glDrawBuffer and glReadBuffer name either, GL_FRONT_AND_BACK draws into both
   (each blended with its own pixels, both depth-tested against the same depth), and a swap
   copies the back one to the front. */
static void front_and_back(void) {
  GLXFBConfig c = choose(True);
  if (!c) return;
  XVisualInfo* v = glXGetVisualFromFBConfig(dpy, c);
  Window win = make_window(v, 64, 48);
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
  glXMakeContextCurrent(dpy, win, win, ctx);
  clear_to(1, 0, 0);
  glXSwapBuffers(dpy, win);
  clear_to(0, 0, 1);
  glFinish();
  check(x_pixel(win, 32, 24) == 0xff0000, "front.finish_shows_no_back", "glFinish showed the back buffer");
  check(read_from(GL_FRONT, 32, 24) == 0xff0000 && read_from(GL_BACK, 32, 24) == 0x0000ff,
        "front.read", "glReadBuffer(GL_FRONT / GL_BACK) does not read the buffer it names");
  glDrawBuffer(GL_FRONT);
  rect_at(-1, 0, 0, 0, 1, 0);
  glFlush();
  check(x_pixel(win, 10, 24) == 0x00ff00 && x_pixel(win, 50, 24) == 0xff0000, "front.draw_flush",
        "drawing into the front buffer is not shown at glFlush");
  check(read_from(GL_BACK, 10, 24) == 0x0000ff && read_from(GL_FRONT, 10, 24) == 0x00ff00, "front.back_untouched",
        "drawing into the front buffer changed the back one");
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glDrawBuffer(GL_BACK);
  glPopAttrib();
  GLint draw = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &draw);
  rect_at(0, 1, 0, 1, 1, 1);
  check(draw == GL_FRONT && read_from(GL_FRONT, 50, 24) == 0xffffff && read_from(GL_BACK, 50, 24) == 0x0000ff,
        "front.pop_attrib", "glPopAttrib did not bring the front buffer back");
  /* Both buffers: the near quad is drawn first, the far one fails the depth test in both. */
  glDrawBuffer(GL_FRONT_AND_BACK);
  glEnable(GL_DEPTH_TEST);
  glClear(GL_DEPTH_BUFFER_BIT);
  glBegin(GL_QUADS);
  glColor3f(1, 1, 0);
  glVertex3f(-0.5f, -1, -0.5f), glVertex3f(0.5f, -1, -0.5f), glVertex3f(0.5f, 1, -0.5f), glVertex3f(-0.5f, 1, -0.5f);
  glColor3f(1, 0, 1);
  glVertex3f(-1, -1, 0.5f), glVertex3f(1, -1, 0.5f), glVertex3f(1, 1, 0.5f), glVertex3f(-1, 1, 0.5f);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  check(read_from(GL_FRONT, 32, 24) == 0xffff00 && read_from(GL_BACK, 32, 24) == 0xffff00 &&
            read_from(GL_FRONT, 4, 24) == 0xff00ff && read_from(GL_BACK, 60, 24) == 0xff00ff,
        "front_and_back.depth", "GL_FRONT_AND_BACK did not draw the same fragments into both buffers");
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  clear_to(0, 0, 0); /* both buffers */
  rect_at(-1, 1, 0, 0, 0.5f, 0);
  glDrawBuffer(GL_BACK);
  rect_at(-1, 1, 0, 0.5f, 0, 0);
  glDisable(GL_BLEND);
  check(read_from(GL_FRONT, 32, 24) == 0x008000 && read_from(GL_BACK, 32, 24) == 0x808000,
        "front_and_back.blend", "GL_FRONT_AND_BACK's clear or blending is not each buffer's own");
  glXSwapBuffers(dpy, win);
  check(x_pixel(win, 32, 24) == 0x808000 && read_from(GL_FRONT, 32, 24) == 0x808000 &&
            read_from(GL_BACK, 32, 24) == 0x808000,
        "front.swap_copies_back", "after the swap the front buffer is not the back one");
  glDrawBuffer(GL_FRONT);
  clear_to(0, 1, 1);
  glXSwapBuffers(dpy, win); /* shows the back buffer; the draw buffer stays the front one */
  check(x_pixel(win, 32, 24) == 0x808000, "front.swap_shows_back", "the swap showed the front buffer's drawing");
  clear_to(1, 1, 1);
  glFinish();
  check(x_pixel(win, 32, 24) == 0xffffff && read_from(GL_BACK, 32, 24) == 0x808000, "front.after_swap",
        "drawing into the front buffer after a swap is not shown, or reached the back buffer");
  /* The window grows while the front buffer is the draw buffer: the swap finds the new size. */
  XResizeWindow(dpy, win, 80, 60);
  XSync(dpy, False);
  glXSwapBuffers(dpy, win);
  glViewport(0, 0, 80, 60);
  clear_to(1, 1, 0); /* the front buffer, at the new size */
  glFlush();
  glDrawBuffer(GL_BACK);
  clear_to(1, 0, 1);
  check(x_pixel(win, 70, 50) == 0xffff00 && read_from(GL_BACK, 70, 50) == 0xff00ff, "front.resized",
        "after a resize the front or the back buffer is not the drawable's size");
  glXSwapBuffers(dpy, win);
  check(x_pixel(win, 70, 50) == 0xff00ff, "front.resized_swap", "the swap after a resize did not show the back buffer");
  glXMakeContextCurrent(dpy, None, None, NULL);
  glXDestroyContext(dpy, ctx);
  XDestroyWindow(dpy, win);
  XFree(v);
}

static void single_buffered(void) {
  int attributes[] = {GLX_RGBA, GLX_RED_SIZE, 1, GLX_GREEN_SIZE, 1, GLX_BLUE_SIZE, 1, None};
  XVisualInfo* v = glXChooseVisual(dpy, DefaultScreen(dpy), attributes);
  check(v != NULL, "visual.single", "glXChooseVisual found no single-buffered RGBA visual");
  if (!v) return;
  int doubled = 1;
  glXGetConfig(dpy, v, GLX_DOUBLEBUFFER, &doubled);
  check(doubled == 0, "visual.single_config", "glXGetConfig says double-buffered");
  Window win = make_window(v, 40, 30);
  GLXContext ctx = glXCreateContext(dpy, v, NULL, True);
  glXMakeCurrent(dpy, win, ctx);
  clear_to(0, 1, 0);
  glFlush();
  check(x_pixel(win, 20, 15) == 0x00ff00, "single.flush_reaches_window", "glFlush did not show the frame");
  glXSwapBuffers(dpy, win); /* no effect on a single-buffered window, no error */
  check(x_pixel(win, 20, 15) == 0x00ff00, "single.swap", "the swap changed a single-buffered window");
  glXMakeCurrent(dpy, None, NULL);
  glXDestroyContext(dpy, ctx);
  XDestroyWindow(dpy, win);
  XFree(v);
}

static void sharing(void) {
  GLXFBConfig c = choose(True);
  GLXPbuffer pb = 0;
  int pbuffer_attributes[] = {GLX_PBUFFER_WIDTH, 16, GLX_PBUFFER_HEIGHT, 16, None};
  pb = glXCreatePbuffer(dpy, c, pbuffer_attributes);
  GLXContext a = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
  GLXContext b = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, a, True);
  GLXContext alone = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
  glXMakeContextCurrent(dpy, pb, pb, a);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  const unsigned char texel[4] = {10, 200, 30, 255};
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glXMakeContextCurrent(dpy, pb, pb, b);
  check(glIsTexture(tex), "share.texture_name", "the sharing context does not see the texture");
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  clear_to(0, 0, 0);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0), glVertex2f(-1, -1);
  glTexCoord2f(1, 0), glVertex2f(1, -1);
  glTexCoord2f(1, 1), glVertex2f(1, 1);
  glTexCoord2f(0, 1), glVertex2f(-1, 1);
  glEnd();
  check(gl_pixel(8, 8) == 0x0ac81e, "share.texture_image", "the shared texture's image is not drawn");
  glXMakeContextCurrent(dpy, pb, pb, alone);
  check(!glIsTexture(tex), "share.not_shared", "an unshared context sees another's texture");
  unsigned int width = 0;
  glXQueryDrawable(dpy, pb, GLX_WIDTH, &width);
  check(width == 16, "pbuffer.query", "glXQueryDrawable(GLX_WIDTH) is not the pbuffer's");
  clear_to(0, 0, 1);
  check(gl_pixel(3, 3) == 0x0000ff, "pbuffer.draw", "the pbuffer was not drawn");
  glXMakeContextCurrent(dpy, None, None, NULL);
  glXDestroyContext(dpy, a);
  glXDestroyContext(dpy, b);
  glXDestroyContext(dpy, alone);
  glXDestroyPbuffer(dpy, pb);
}

static void destroy_current(void) {
  GLXFBConfig c = choose(True);
  int pbuffer_attributes[] = {GLX_PBUFFER_WIDTH, 8, GLX_PBUFFER_HEIGHT, 8, None};
  GLXPbuffer pb = glXCreatePbuffer(dpy, c, pbuffer_attributes);
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
  glXMakeContextCurrent(dpy, pb, pb, ctx);
  glXDestroyContext(dpy, ctx); /* lives on while current (GLX 1.4 section 3.3.7) */
  clear_to(1, 1, 0);
  check(gl_pixel(4, 4) == 0xffff00 && glGetString(GL_VERSION) != NULL, "destroy.current_lives_on",
        "a destroyed current context stopped working");
  glXMakeContextCurrent(dpy, None, None, NULL);
  glXDestroyPbuffer(dpy, pb);
}

static void copy_context(void) {
  GLXFBConfig c = choose(True);
  int pbuffer_attributes[] = {GLX_PBUFFER_WIDTH, 8, GLX_PBUFFER_HEIGHT, 8, None};
  GLXPbuffer pb = glXCreatePbuffer(dpy, c, pbuffer_attributes);
  GLXContext from = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
  GLXContext to = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
  glXMakeContextCurrent(dpy, pb, pb, from);
  glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
  glDepthFunc(GL_GREATER);
  glXMakeContextCurrent(dpy, None, None, NULL);
  glXCopyContext(dpy, from, to, GL_COLOR_BUFFER_BIT); /* the colour group only */
  glXMakeContextCurrent(dpy, pb, pb, to);
  GLfloat clear[4];
  GLint depth_func = 0;
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  glGetIntegerv(GL_DEPTH_FUNC, &depth_func);
  check(clear[0] == 0.25f && clear[2] == 0.75f && depth_func == GL_LESS, "copy_context",
        "glXCopyContext did not copy exactly the groups of its mask");
  glXMakeContextCurrent(dpy, None, None, NULL);
  glXDestroyContext(dpy, from);
  glXDestroyContext(dpy, to);
  glXDestroyPbuffer(dpy, pb);
}

static void pixmap(void) {
  int attributes[] = {GLX_RGBA, GLX_RED_SIZE, 1, GLX_GREEN_SIZE, 1, GLX_BLUE_SIZE, 1, None};
  XVisualInfo* v = glXChooseVisual(dpy, DefaultScreen(dpy), attributes);
  if (!v) return;
  Pixmap pm = XCreatePixmap(dpy, RootWindow(dpy, v->screen), 20, 20, (unsigned)v->depth);
  GLXPixmap gp = glXCreateGLXPixmap(dpy, v, pm);
  GLXContext ctx = glXCreateContext(dpy, v, NULL, True);
  check(gp && glXMakeCurrent(dpy, gp, ctx), "pixmap.current", "could not draw to a GLX pixmap");
  clear_to(1, 0, 1);
  glFinish();
  check(x_pixel(pm, 10, 10) == 0xff00ff, "pixmap.draw", "the pixmap does not hold the drawing");
  glXMakeCurrent(dpy, None, NULL);
  glXDestroyContext(dpy, ctx);
  glXDestroyGLXPixmap(dpy, gp);
  XFreePixmap(dpy, pm);
  XFree(v);
}

struct Worker {
  GLXContext ctx;
  Window win;
  float r, g, b;
  unsigned long expect;
  int ok;
};

static void* draw_frames(void* p) {
  struct Worker* w = p;
  w->ok = glXMakeCurrent(dpy, w->win, w->ctx);
  for (int i = 0; i < 40 && w->ok; ++i) {
    clear_to(w->r, w->g, w->b);
    glBegin(GL_TRIANGLES);
    glColor3f(w->r, w->g, w->b);
    glVertex2f(-1, -1), glVertex2f(1, -1), glVertex2f(0, 1);
    glEnd();
    w->ok = gl_pixel(5, 5) == w->expect;
    glXSwapBuffers(dpy, w->win);
  }
  glXMakeCurrent(dpy, None, NULL);
  return NULL;
}

static void two_threads(void) {
  GLXFBConfig c = choose(True);
  XVisualInfo* v = glXGetVisualFromFBConfig(dpy, c);
  struct Worker w[2] = {{NULL, 0, 1, 0, 0, 0xff0000, 0}, {NULL, 0, 0, 0, 1, 0x0000ff, 0}};
  pthread_t threads[2];
  for (int i = 0; i < 2; ++i) {
    w[i].win = make_window(v, 32, 32);
    w[i].ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
  }
  for (int i = 0; i < 2; ++i) pthread_create(&threads[i], NULL, draw_frames, &w[i]);
  for (int i = 0; i < 2; ++i) pthread_join(threads[i], NULL);
  check(w[0].ok && w[1].ok, "threads.two_contexts", "a thread read another context's pixels");
  for (int i = 0; i < 2; ++i) glXDestroyContext(dpy, w[i].ctx), XDestroyWindow(dpy, w[i].win);
  XFree(v);
}

static void proc_addresses(void) {
  check(glXGetProcAddress((const GLubyte*)"glBegin") != NULL &&
            glXGetProcAddressARB((const GLubyte*)"glXCreateContextAttribsARB") != NULL,
        "getprocaddress", "a GL or GLX function has no address");
}

/* --errors: what wrong calls answer. */
static void report(const char* name, int returned) {
  const int e = last_error;
  if (e == 0) printf("%s: returned %d, no error\n", name, returned);
  else if (e >= glx_error_base && glx_error_base > 0) printf("%s: returned %d, GLX error %d\n", name, returned, e - glx_error_base);
  else printf("%s: returned %d, X error %d\n", name, returned, e);
  last_error = 0;
}

static GLXContext attribs_context(GLXFBConfig c, const int* attributes) {
  typedef GLXContext (*Create)(Display*, GLXFBConfig, GLXContext, Bool, const int*);
  Create create = (Create)glXGetProcAddressARB((const GLubyte*)"glXCreateContextAttribsARB");
  GLXContext ctx = create(dpy, c, NULL, True, attributes);
  XSync(dpy, False);
  return ctx;
}

static void errors(void) {
  GLXFBConfig c = choose(True);
  const int too_high[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 9, GLX_CONTEXT_MINOR_VERSION_ARB, 9, None};
  const int forward[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_FLAGS_ARB,
                         GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB, None};
  const int profile[] = {GLX_CONTEXT_PROFILE_MASK_ARB, 0x100, None};
  const int unknown[] = {0x7777, 1, None};
  const int fine[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 0, None};
  GLXContext ok = attribs_context(c, fine);
  report("create_context_attribs(1.0)", ok != NULL);
  report("create_context_attribs(9.9)", attribs_context(c, too_high) != NULL);
  report("create_context_attribs(forward-compatible 1.0)", attribs_context(c, forward) != NULL);
  report("create_context_attribs(bad profile mask)", attribs_context(c, profile) != NULL);
  report("create_context_attribs(unknown attribute)", attribs_context(c, unknown) != NULL);
  int index_attributes[] = {GLX_RENDER_TYPE, GLX_COLOR_INDEX_BIT, None};
  int n = -1;
  GLXFBConfig* none = glXChooseFBConfig(dpy, DefaultScreen(dpy), index_attributes, &n);
  report("choose_fbconfig(colour index) count", none ? n : 0);
  int no_rgba[] = {GLX_DOUBLEBUFFER, None};
  report("choose_visual(no GLX_RGBA)", glXChooseVisual(dpy, DefaultScreen(dpy), no_rgba) != NULL);
  int samples[] = {GLX_SAMPLE_BUFFERS, 1, GLX_SAMPLES, 64, None};
  glXChooseFBConfig(dpy, DefaultScreen(dpy), samples, &n);
  report("choose_fbconfig(64 samples) count", n);
  GLXContext dead = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
  glXDestroyContext(dpy, dead);
  XVisualInfo* v = glXGetVisualFromFBConfig(dpy, c);
  Window win = make_window(v, 16, 16);
  report("make_current(destroyed context)", glXMakeCurrent(dpy, win, dead));
  report("make_current(context, None drawable)", glXMakeCurrent(dpy, None, ok));
  XSync(dpy, False);
  if (glXGetCurrentContext() == ok) { /* drawing into no drawable must not crash */
    unsigned char rgba[4];
    clear_to(1, 0, 0);
    glBegin(GL_TRIANGLES), glVertex2f(-1, -1), glVertex2f(1, -1), glVertex2f(0, 1), glEnd();
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glFinish();
    while (glGetError() != GL_NO_ERROR) {}
    glXMakeCurrent(dpy, None, NULL);
  }
  glXDestroyContext(dpy, ok);
  XDestroyWindow(dpy, win);
  XFree(v);
}

int main(int argc, char** argv) {
  XInitThreads();
  dpy = XOpenDisplay(NULL);
  if (!dpy) {
    fprintf(stderr, "glx_contexts: cannot open display\n");
    return 2;
  }
  int event_base = 0, major = 0, minor = 0;
  check(glXQueryExtension(dpy, &glx_error_base, &event_base), "query_extension", "no GLX");
  check(glXQueryVersion(dpy, &major, &minor) && (major > 1 || minor >= 4), "query_version", "not GLX 1.4");
  XSetErrorHandler(on_error);
  if (argc > 1 && strcmp(argv[1], "--errors") == 0) {
    errors();
    XCloseDisplay(dpy);
    return 0;
  }
  windows_and_swaps();
  front_and_back();
  single_buffered();
  sharing();
  destroy_current();
  copy_context();
  pixmap();
  two_threads();
  proc_addresses();
  check(last_error == 0, "no_x_errors", "an X error was raised by a valid call");
  XCloseDisplay(dpy);
  printf("%d failed\n", failures);
  return failures ? 1 : 0;
}
