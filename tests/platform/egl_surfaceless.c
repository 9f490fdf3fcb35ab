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

static unsigned red_at(int x, int y) { return (unsigned)(pixel(x, y) >> 16); }

static void rect(float x0, float y0, float x1, float y1) {
  glBegin(GL_QUADS);
  glVertex2f(x0, y0), glVertex2f(x1, y0), glVertex2f(x1, y1), glVertex2f(x0, y1);
  glEnd();
}

/* A 4-sample configuration: coverage counted in samples (a white rectangle over black leaves
   255 * covered / 4 in an edge pixel), GL_MULTISAMPLE off, glSampleCoverage, alpha to coverage,
   pixel rectangles and clears writing every sample, depth read back. */
static void multisample(void) {
  const EGLint attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                               EGL_SAMPLE_BUFFERS, 1, EGL_SAMPLES, 4, EGL_DEPTH_SIZE, 24, EGL_NONE};
  EGLConfig ms;
  EGLint n = 0, samples = 0;
  check(eglChooseConfig(dpy, attributes, &ms, 1, &n) && n == 1, "multisample.config", "no 4-sample pbuffer config");
  if (n != 1) return;
  eglGetConfigAttrib(dpy, ms, EGL_SAMPLES, &samples);
  check(samples == 4, "multisample.config_samples", "EGL_SAMPLES is not 4");
  const EGLint size[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
  EGLSurface pb = eglCreatePbufferSurface(dpy, ms, size);
  EGLContext ctx = eglCreateContext(dpy, ms, EGL_NO_CONTEXT, NULL);
  eglMakeCurrent(dpy, pb, pb, ctx);
  GLint buffers = 0, count = 0;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &buffers);
  glGetIntegerv(GL_SAMPLES, &count);
  check(buffers == 1 && count == 4, "multisample.gl_samples", "GL_SAMPLE_BUFFERS / GL_SAMPLES are not 1 / 4");
  glOrtho(0, 16, 0, 16, -1, 1);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  rect(0, 0, 8.5f, 8);    /* samples at x 0.125, 0.375, 0.625, 0.875 in each pixel */
  rect(0, 10, 8.25f, 12); /* one sample of pixel 8 */
  check(red_at(7, 4) == 255 && red_at(8, 4) == 128 && red_at(9, 4) == 0, "multisample.edge_half",
        "an edge through the middle of a pixel does not cover half its samples");
  check(red_at(8, 11) == 64, "multisample.edge_quarter", "an edge a quarter into a pixel does not cover one sample");
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_MULTISAMPLE);
  rect(0, 0, 8.4f, 8);
  glEnable(GL_MULTISAMPLE);
  rect(0, 10, 8.4f, 12);
  check(red_at(8, 4) == 0 && red_at(8, 11) == 128, "multisample.disabled",
        "GL_MULTISAMPLE off does not sample the pixel's centre alone");
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SAMPLE_COVERAGE);
  glSampleCoverage(0.5f, GL_FALSE);
  rect(0, 0, 16, 8);
  glSampleCoverage(0.5f, GL_TRUE);
  glColor3f(0, 0, 1);
  rect(0, 0, 16, 4);
  glDisable(GL_SAMPLE_COVERAGE);
  check(pixel(3, 6) == 0x808080 && pixel(3, 2) == 0x8080ff,
        "multisample.coverage", "glSampleCoverage 0.5 and its inverse do not split the samples");
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glColor4f(1, 1, 1, 0.3f);
  rect(0, 0, 16, 8);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  check(red_at(4, 4) == 64, "multisample.alpha_to_coverage", "alpha 0.3 does not cover one sample of four");
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  glColor4f(1, 1, 1, 0.25f);
  rect(0, 0, 16, 4);
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glColor4f(1, 1, 1, 0.3f);
  rect(0, 4, 16, 8);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDisable(GL_SAMPLE_ALPHA_TO_ONE);
  rect(0, 8, 16, 10);
  glDisable(GL_BLEND);
  check(red_at(4, 2) == 255 && red_at(4, 6) == 64 && red_at(4, 9) == 77, "multisample.alpha_to_one",
        "GL_SAMPLE_ALPHA_TO_ONE does not blend with an alpha of 1");
  const unsigned char block[4 * 4] = {255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255};
  glRasterPos2i(12, 12);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, block);
  check(red_at(12, 12) == 255 && red_at(13, 13) == 255 && red_at(14, 14) == 0, "multisample.draw_pixels",
        "glDrawPixels does not write every sample of its pixels");
  glEnable(GL_SCISSOR_TEST);
  glScissor(10, 0, 2, 2);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  check(pixel(10, 0) == 0x00ff00 && pixel(12, 0) == 0xffffff, "multisample.scissored_clear",
        "a scissored clear does not clear every sample of its box alone");
  glClearDepth(0.5);
  glClear(GL_DEPTH_BUFFER_BIT);
  GLfloat depth = 0;
  glReadPixels(1, 1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  check(depth > 0.499f && depth < 0.501f, "multisample.depth", "the cleared depth does not read back");
  check(glGetError() == GL_NO_ERROR, "multisample.no_error", "a GL error was left");
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(dpy, ctx);
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
  multisample();
  check(eglGetProcAddress("glBegin") != NULL, "getprocaddress", "glBegin has no address");
  EGLDisplay default_display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  check(default_display != EGL_NO_DISPLAY && eglInitialize(default_display, NULL, NULL), "default_display",
        "no default display");
  eglTerminate(dpy);
  printf("%d failed\n", failures);
  return failures ? 1 : 0;
}
