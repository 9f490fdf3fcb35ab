/* The cost of a multisample buffer: a lit sphere of 3,200 triangles (40 triangle strips, drawn
 * with glBegin/glEnd) at 1920x1080, cleared, drawn, finished and read (one pixel: the resolve
 * of a multisample buffer happens there), on an EGL pbuffer without samples and on one with 4,
 * side by side; prints the median of 20 frames of each. Runs on whichever EGL vendor GLVND
 * selects (docs/performance.md):
 *   __EGL_VENDOR_LIBRARY_FILENAMES=build/gl/platform/shadelab.json build/bench/bench_multisample */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { kWidth = 1920, kHeight = 1080, kFrames = 21 };

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static int by_value(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

static void sphere_strips(void) {
  for (int i = 0; i < 40; ++i) {
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j <= 40; ++j) {
      const float th = (float)j * 6.2831853f / 40.0f;
      for (int k = 0; k < 2; ++k) {
        const float ph = (float)(i + k) * 3.1415927f / 40.0f;
        const float n[3] = {sinf(ph) * cosf(th), cosf(ph), sinf(ph) * sinf(th)};
        glNormal3fv(n);
        glVertex3f(1.5f * n[0], 1.5f * n[1], 1.5f * n[2]);
      }
    }
    glEnd();
  }
}

/* The median frame time with `samples` samples (0: none); -1 without such a configuration. */
static double measure(EGLDisplay dpy, int samples, int* reported) {
  const EGLint attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                               EGL_DEPTH_SIZE, 24, EGL_SAMPLE_BUFFERS, samples > 0, EGL_SAMPLES, samples, EGL_NONE};
  EGLConfig config;
  EGLint n = 0;
  if (!eglChooseConfig(dpy, attributes, &config, 1, &n) || n != 1) return -1.0;
  const EGLint size[] = {EGL_WIDTH, kWidth, EGL_HEIGHT, kHeight, EGL_NONE};
  EGLSurface surface = eglCreatePbufferSurface(dpy, config, size);
  EGLContext context = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
  if (surface == EGL_NO_SURFACE || context == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, surface, surface, context)) return -1.0;
  glGetIntegerv(GL_SAMPLES, reported);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1.0, 1.0, -0.5625, 0.5625, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  double times[kFrames];
  for (int f = 0; f < kFrames; ++f) {
    const double start = now_ms();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -4.0f);
    glRotatef(5.0f * (float)f, 0.0f, 1.0f, 0.0f);
    sphere_strips();
    glFinish();
    unsigned char pixel[4];
    glReadPixels(kWidth / 2, kHeight / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    times[f] = now_ms() - start;
  }
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(dpy, context);
  eglDestroySurface(dpy, surface);
  qsort(times + 1, kFrames - 1, sizeof times[0], by_value);  /* the first frame left out */
  return times[kFrames / 2];
}

int main(void) {
  EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, NULL, NULL) || !eglBindAPI(EGL_OPENGL_API)) {
    fprintf(stderr, "bench_multisample: no surfaceless EGL display with OpenGL\n");
    return 1;
  }
  int reported0 = 0, reported4 = 0;
  const double single = measure(dpy, 0, &reported0), multi = measure(dpy, 4, &reported4);
  printf("lit sphere, 3,200 triangles, %dx%d, median of %d frames\n", kWidth, kHeight, kFrames - 1);
  printf("  no samples: %.2f ms (GL_SAMPLES %d)\n", single, reported0);
  if (multi < 0.0) printf("  4 samples: no such configuration\n");
  else printf("  4 samples: %.2f ms (GL_SAMPLES %d), %.1fx\n", multi, reported4, multi / single);
  eglTerminate(dpy);
  return 0;
}
