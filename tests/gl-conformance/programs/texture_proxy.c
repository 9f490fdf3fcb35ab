/* Proxy textures (OpenGL 1.1 section 3.8.1): glTexImage1D/2D on GL_PROXY_TEXTURE_1D/2D and
 * every glGetTexLevelParameter of the proxies, compared value by value with Mesa (recorded
 * with conf_value): sizes up to and past GL_MAX_TEXTURE_SIZE at several levels, borders,
 * internal formats and their component sizes, proxies cleared by an image that does not fit,
 * proxies left alone by a call that is an error, the real targets untouched. Then GLU's
 * closestFit as gluBuild2DMipmaps runs it (level-1 proxies halved until one fits) for odd
 * sizes, and the mipmap chain built at the sizes it found, drawn minified. */
#include <stdio.h>

#include "conf.h"

static const GLenum kLevelNames[] = {GL_TEXTURE_WIDTH,         GL_TEXTURE_HEIGHT,         GL_TEXTURE_BORDER,
                                     GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_RED_SIZE,    GL_TEXTURE_GREEN_SIZE,
                                     GL_TEXTURE_BLUE_SIZE,      GL_TEXTURE_ALPHA_SIZE,     GL_TEXTURE_LUMINANCE_SIZE,
                                     GL_TEXTURE_INTENSITY_SIZE};

/* Every level parameter of (target, level), as integers and as floats. */
static void record_level(ConfContext* c, const char* what, GLenum target, GLint level) {
  char key[160];
  for (unsigned i = 0; i < sizeof kLevelNames / sizeof kLevelNames[0]; ++i) {
    GLint v = -1;
    GLfloat f = -1.0f;
    glGetTexLevelParameteriv(target, level, kLevelNames[i], &v);
    glGetTexLevelParameterfv(target, level, kLevelNames[i], &f);
    snprintf(key, sizeof key, "%s level %d pname 0x%04x iv", what, level, kLevelNames[i]);
    conf_value(c, key, v);
    snprintf(key, sizeof key, "%s level %d pname 0x%04x fv", what, level, kLevelNames[i]);
    conf_value(c, key, f);
  }
  snprintf(key, sizeof key, "%s level %d", what, level);
  conf_error(c, key);
}

static void proxy2d(ConfContext* c, const char* what, GLint level, GLint internal, int w, int h, int border) {
  glTexImage2D(GL_PROXY_TEXTURE_2D, level, internal, w, h, border, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  char key[160];
  snprintf(key, sizeof key, "proxy 2D %s", what);
  conf_error(c, key);
  record_level(c, key, GL_PROXY_TEXTURE_2D, level);
}

static void proxy1d(ConfContext* c, const char* what, GLint level, GLint internal, int w, int border) {
  glTexImage1D(GL_PROXY_TEXTURE_1D, level, internal, w, border, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  char key[160];
  snprintf(key, sizeof key, "proxy 1D %s", what);
  conf_error(c, key);
  record_level(c, key, GL_PROXY_TEXTURE_1D, level);
}

static void proxy_sizes(ConfContext* c) {
  GLint max = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  conf_value(c, "GL_MAX_TEXTURE_SIZE", max);
  record_level(c, "fresh proxy 2D", GL_PROXY_TEXTURE_2D, 0);
  record_level(c, "fresh proxy 1D", GL_PROXY_TEXTURE_1D, 3);
  proxy2d(c, "64x32 RGB", 0, GL_RGB, 64, 32, 0);
  record_level(c, "proxy 2D untouched level", GL_PROXY_TEXTURE_2D, 1);
  proxy2d(c, "max x 1", 0, GL_RGBA, max, 1, 0);
  proxy2d(c, "max + 1", 0, GL_RGBA, max + 1, 1, 0);
  proxy2d(c, "max + 2 with border", 0, GL_RGBA, max + 2, 4, 1);
  proxy2d(c, "max + 3 with border", 0, GL_RGBA, max + 3, 4, 1);
  proxy2d(c, "max / 2 at level 1", 1, GL_RGBA, max / 2, 8, 0);
  proxy2d(c, "max / 2 + 1 at level 1", 1, GL_RGBA, max / 2 + 1, 8, 0);
  proxy2d(c, "1x1 at level 14", 14, GL_RGBA, 1, 1, 0);
  proxy2d(c, "2x1 at level 14", 14, GL_RGBA, 2, 1, 0);
  proxy2d(c, "non-power-of-two 100x37", 0, GL_LUMINANCE8_ALPHA8, 100, 37, 0);
  proxy2d(c, "18x18 border 1", 0, GL_RGB5_A1, 18, 18, 1);
  proxy2d(c, "1x4 border 1 (too narrow)", 0, GL_RGBA, 1, 4, 1);
  proxy2d(c, "0x0", 0, GL_ALPHA12, 0, 0, 0);
  proxy2d(c, "level 3 R3_G3_B2", 3, GL_R3_G3_B2, 10, 6, 0);
  record_level(c, "proxy 2D level 0 after level 3", GL_PROXY_TEXTURE_2D, 0);
  /* Errors leave the proxy as it was. */
  proxy2d(c, "bad internal format", 3, 7, 10, 6, 0);
  proxy2d(c, "border 2", 3, GL_RGBA, 4, 4, 2);
  proxy2d(c, "negative width", 3, GL_RGBA, -4, 4, 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 15, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_error(c, "proxy 2D level 15");
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_BITMAP, NULL);
  conf_error(c, "proxy 2D BITMAP");
  proxy1d(c, "300 ALPHA", 0, GL_ALPHA, 300, 0);
  proxy1d(c, "max + 1", 0, GL_ALPHA, max + 1, 0);
  proxy1d(c, "258 border 1 INTENSITY4", 2, GL_INTENSITY4, 258, 1);
  proxy1d(c, "LUMINANCE12 at level 13", 13, GL_LUMINANCE12, 2, 0);
  proxy1d(c, "LUMINANCE12 at level 13 too wide", 13, GL_LUMINANCE12, 3, 0);
  /* The real targets never saw any of it. */
  record_level(c, "real 2D", GL_TEXTURE_2D, 0);
  record_level(c, "real 1D", GL_TEXTURE_1D, 0);
}

static const GLint kFormats[] = {1, 2, 3, 4, GL_ALPHA4, GL_LUMINANCE6_ALPHA2, GL_INTENSITY16, GL_RGB10, GL_RGBA2,
                                 GL_RGB10_A2, GL_RGBA12};

static void proxy_formats(ConfContext* c) {
  char what[64];
  for (unsigned i = 0; i < sizeof kFormats / sizeof kFormats[0]; ++i) {
    snprintf(what, sizeof what, "internal 0x%04x", kFormats[i]);
    proxy2d(c, what, 2, kFormats[i], 16, 8, 0);
  }
}

static int nearest_power(int v) {
  int p = 1;
  while (p * 2 <= v) p *= 2;
  return p;
}

/* GLU's closestFit (libutil/mipmap.c) for a 2D image: sizes halved until level 1 fits. */
static void closest_fit(int w, int h, GLint internal, int* out_w, int* out_h) {
  int pw = nearest_power(w), ph = nearest_power(h);
  GLint proxy_width;
  do {
    int w1 = pw > 1 ? pw >> 1 : pw, h1 = ph > 1 ? ph >> 1 : ph;
    glTexImage2D(GL_PROXY_TEXTURE_2D, 1, internal, w1, h1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 1, GL_TEXTURE_WIDTH, &proxy_width);
    if (proxy_width == 0) {
      if (pw == 1 && ph == 1) break;
      pw = w1, ph = h1;
    }
  } while (proxy_width == 0);
  *out_w = pw;
  *out_h = ph;
}

static void glu_sizes(ConfContext* c) {
  static const int sizes[][2] = {{1, 1}, {3, 5}, {100, 37}, {257, 256}, {640, 480}, {20000, 3}, {40000, 40000}};
  char key[64];
  for (unsigned i = 0; i < sizeof sizes / sizeof sizes[0]; ++i) {
    int w, h;
    closest_fit(sizes[i][0], sizes[i][1], GL_RGB, &w, &h);
    snprintf(key, sizeof key, "closestFit %dx%d", sizes[i][0], sizes[i][1]);
    conf_values(c, key, (double[]){w, h}, 2);
  }
  conf_error(c, "closestFit");
}

/* The chain of a closestFit-sized 100x37 image (64x32 down to 1x1), each level a colour. */
static void draw_chain(ConfContext* c) {
  static unsigned char level[64 * 32 * 3];
  int w, h;
  closest_fit(100, 37, GL_RGB, &w, &h);
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int l = 0; w >= 1 || h >= 1; ++l) {
    if (w < 1) w = 1;
    if (h < 1) h = 1;
    for (int i = 0; i < w * h; ++i) {
      level[i * 3 + 0] = (unsigned char)(40 * l + (i % 7) * 9);
      level[i * 3 + 1] = (unsigned char)(200 - 25 * l);
      level[i * 3 + 2] = (unsigned char)((i / w) * 255 / h);
    }
    glTexImage2D(GL_TEXTURE_2D, l, GL_RGB, w, h, 0, GL_RGB, GL_UNSIGNED_BYTE, level);
    if (w == 1 && h == 1) break;
    w /= 2, h /= 2;
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glEnable(GL_TEXTURE_2D);
  for (int k = 0; k < 4; ++k) {
    conf_panel(c, k, 0, 4, 1);
    float r = 1.0f + 3.0f * k;
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(-1, -1);
    glTexCoord2f(r, 0);
    glVertex2f(1, -1);
    glTexCoord2f(r, r);
    glVertex2f(1, 1);
    glTexCoord2f(0, r);
    glVertex2f(-1, 1);
    glEnd();
  }
  glDeleteTextures(1, &tex);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 64)) return 1;
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  proxy_sizes(&c);
  proxy_formats(&c);
  glu_sizes(&c);
  draw_chain(&c);
  return conf_finish(&c);
}
