/* EGL through GLVND, headless, for shadelab's platform tests (tests/platform): plain EGL 1.5 +
   OpenGL, linked with -lEGL -lOpenGL and nothing of shadelab's, so that it runs on any vendor.

     egl_surfaceless            functional checks; "ok NAME" / "FAIL NAME: ..." per check, exit 1
                                if any failed
     egl_surfaceless --errors   what each wrong call returns and the EGL error it leaves, one line
                                each (compared between Mesa and shadelab by the test)

   Checks: the surfaceless platform and the default display, configurations, a pbuffer drawn and
   read back, a surfaceless context (EGL_KHR_surfaceless_context), texture sharing, two threads
   with two contexts, destroying a current context, eglGetProcAddress. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

static EGLDisplay dpy;
static EGLConfig config;
static int failures = 0;

static void check(int ok, const char* name, const char* detail) {
  if (ok) printf("ok %s\n", name);
  else printf("FAIL %s: %s\n", name, detail), ++failures;
}

static unsigned long pixel(int x, int y) {
  unsigned char rgb[3];
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x, y, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  return ((unsigned long)rgb[0] << 16) | ((unsigned long)rgb[1] << 8) | rgb[2];
}

static EGLSurface pbuffer(int w, int h) {
  const EGLint attributes[] = {EGL_WIDTH, w, EGL_HEIGHT, h, EGL_NONE};
  return eglCreatePbufferSurface(dpy, config, attributes);
}

static EGLContext context(EGLContext share) { return eglCreateContext(dpy, config, share, NULL); }

static void triangle(float r, float g, float b) {
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(r, g, b);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1), glVertex2f(3, -1), glVertex2f(-1, 3);
  glEnd();
}

static void pbuffers_and_contexts(void) {
  EGLSurface pb = pbuffer(64, 32);
  EGLContext a = context(EGL_NO_CONTEXT);
  check(pb != EGL_NO_SURFACE && a != EGL_NO_CONTEXT, "create", "no pbuffer or no context");
  check(eglMakeCurrent(dpy, pb, pb, a), "make_current", "eglMakeCurrent failed");
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  check(viewport[2] == 64 && viewport[3] == 32, "first_viewport", "viewport is not the pbuffer's size");
  triangle(1, 0.5f, 0);
  check(pixel(10, 10) == 0xff8000, "pbuffer.draw", "the pbuffer does not hold the triangle");
  EGLint w = 0;
  eglQuerySurface(dpy, pb, EGL_WIDTH, &w);
  check(w == 64, "pbuffer.query", "EGL_WIDTH is not the pbuffer's");
  check(eglSwapBuffers(dpy, pb) && pixel(10, 10) == 0xff8000, "pbuffer.swap", "a pbuffer swap changed it");
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  const unsigned char texel[4] = {1, 2, 3, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  EGLContext b = context(a), alone = context(EGL_NO_CONTEXT);
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, b); /* surfaceless */
  check(glGetString(GL_VERSION) != NULL && glIsTexture(tex), "surfaceless.shared_texture",
        "a surfaceless context sharing the texture does not see it");
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, alone);
  check(!glIsTexture(tex), "not_shared", "an unshared context sees another's texture");
  eglMakeCurrent(dpy, pb, pb, a);
  eglDestroyContext(dpy, a); /* lives on while current (EGL 1.5 section 3.7.2) */
  triangle(0, 1, 0);
  check(pixel(5, 5) == 0x00ff00, "destroy.current_lives_on", "a destroyed current context stopped working");
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  check(eglGetCurrentContext() == EGL_NO_CONTEXT, "release", "a context is still current");
  eglDestroyContext(dpy, b);
  eglDestroyContext(dpy, alone);
  eglDestroySurface(dpy, pb);
}

struct Worker {
  EGLContext ctx;
  EGLSurface surface;
  float r, g, b;
  unsigned long expect;
  int ok;
};

static void* draw_frames(void* p) {
  struct Worker* w = p;
  w->ok = eglMakeCurrent(dpy, w->surface, w->surface, w->ctx);
  for (int i = 0; i < 40 && w->ok; ++i) {
    triangle(w->r, w->g, w->b);
    w->ok = pixel(3, 3) == w->expect;
    eglSwapBuffers(dpy, w->surface);
  }
  eglReleaseThread();
  return NULL;
}

static void two_threads(void) {
  struct Worker w[2] = {{0, 0, 1, 0, 0, 0xff0000, 0}, {0, 0, 0, 0, 1, 0x0000ff, 0}};
  pthread_t threads[2];
  for (int i = 0; i < 2; ++i) w[i].ctx = context(EGL_NO_CONTEXT), w[i].surface = pbuffer(16, 16);
  for (int i = 0; i < 2; ++i) pthread_create(&threads[i], NULL, draw_frames, &w[i]);
  for (int i = 0; i < 2; ++i) pthread_join(threads[i], NULL);
  check(w[0].ok && w[1].ok, "threads.two_contexts", "a thread read another context's pixels");
  for (int i = 0; i < 2; ++i) eglDestroyContext(dpy, w[i].ctx), eglDestroySurface(dpy, w[i].surface);
}

static void report(const char* name, int returned) { printf("%s: returned %d, error 0x%x\n", name, returned, eglGetError()); }

static void errors(void) {
  const EGLint too_high[] = {EGL_CONTEXT_MAJOR_VERSION, 9, EGL_CONTEXT_MINOR_VERSION, 9, EGL_NONE};
  const EGLint unknown[] = {0x7777, 1, EGL_NONE};
  const EGLint forward[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE, EGL_TRUE, EGL_NONE};
  report("create_context(9.9)", eglCreateContext(dpy, config, EGL_NO_CONTEXT, too_high) != EGL_NO_CONTEXT);
  report("create_context(unknown attribute)", eglCreateContext(dpy, config, EGL_NO_CONTEXT, unknown) != EGL_NO_CONTEXT);
  report("create_context(forward-compatible 1.0)", eglCreateContext(dpy, config, EGL_NO_CONTEXT, forward) != EGL_NO_CONTEXT);
  report("create_context(no config)", eglCreateContext(dpy, NULL, EGL_NO_CONTEXT, NULL) != EGL_NO_CONTEXT);
  const EGLint window_bit[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLint n = -1;
  eglChooseConfig(dpy, window_bit, NULL, 0, &n);
  report("choose_config(window surfaces) count", n);
  const EGLint bad_size[] = {EGL_WIDTH, -1, EGL_HEIGHT, 4, EGL_NONE};
  report("create_pbuffer(width -1)", eglCreatePbufferSurface(dpy, config, bad_size) != EGL_NO_SURFACE);
  EGLContext dead = context(EGL_NO_CONTEXT);
  eglDestroyContext(dpy, dead);
  report("make_current(destroyed context)", eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, dead));
  report("query_string(bad name)", eglQueryString(dpy, 0x7777) != NULL);
}

int main(int argc, char** argv) {
  dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  EGLint major = 0, minor = 0;
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor)) {
    fprintf(stderr, "egl_surfaceless: no surfaceless EGL display\n");
    return 2;
  }
  check(major == 1 && minor >= 5, "version", "not EGL 1.5");
  check(eglBindAPI(EGL_OPENGL_API), "bind_api", "no OpenGL API");
  const EGLint attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                               EGL_RED_SIZE, 8, EGL_DEPTH_SIZE, 16, EGL_NONE};
  EGLint n = 0;
  check(eglChooseConfig(dpy, attributes, &config, 1, &n) && n == 1, "choose_config", "no pbuffer config");
  EGLint depth = 0;
  eglGetConfigAttrib(dpy, config, EGL_DEPTH_SIZE, &depth);
  check(depth >= 16, "config.depth", "EGL_DEPTH_SIZE below the minimum asked for");
  if (argc > 1 && strcmp(argv[1], "--errors") == 0) {
    errors();
    eglTerminate(dpy);
    return 0;
  }
  pbuffers_and_contexts();
  two_threads();
  check(eglGetProcAddress("glBegin") != NULL, "getprocaddress", "glBegin has no address");
  EGLDisplay default_display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  check(default_display != EGL_NO_DISPLAY && eglInitialize(default_display, NULL, NULL), "default_display",
        "no default display");
  eglTerminate(dpy);
  printf("%d failed\n", failures);
  return failures ? 1 : 0;
}
