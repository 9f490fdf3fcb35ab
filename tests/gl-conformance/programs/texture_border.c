/* Texture borders and the border colour (OpenGL 1.1 sections 3.8.1, 3.8.3): images given with
 * a one-texel border (2D, 1D, every level of a mipmap chain) and GL_TEXTURE_BORDER_COLOR with
 * GL_CLAMP, linear and nearest, on s, t or both, next to GL_CLAMP_TO_EDGE and GL_REPEAT, and
 * a minified mipmapped quad. Mesa's gallium drivers (llvmpipe) keep no border texels: the
 * border is stripped when the image is stored, its size reported without it, and GL_CLAMP's
 * linear filter blends in the border colour; this program compares against exactly that. The
 * sizes reported for each level and the texels read back are recorded with conf_value. */
#include <stdio.h>

#include "conf.h"

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void quad(float s0, float t0, float s1, float t1) {
  glBegin(GL_QUADS);
  glTexCoord2f(s0, t0);
  glVertex2f(-1, -1);
  glTexCoord2f(s1, t0);
  glVertex2f(1, -1);
  glTexCoord2f(s1, t1);
  glVertex2f(1, 1);
  glTexCoord2f(s0, t1);
  glVertex2f(-1, 1);
  glEnd();
}

/* An n x n image whose outer ring (the border, when given with border 1) is red and whose
 * inside is a green-blue checker of 2-texel squares. */
static void bordered_image(unsigned char* img, int n, int shade) {
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      unsigned char* p = &img[(y * n + x) * 4];
      int edge = x == 0 || y == 0 || x == n - 1 || y == n - 1;
      int on = ((x - 1) / 2 + (y - 1) / 2) % 2;
      p[0] = (unsigned char)(edge ? 255 : shade);
      p[1] = (unsigned char)(edge ? 0 : on ? 220 : 60);
      p[2] = (unsigned char)(edge ? 0 : on ? 60 : 200);
      p[3] = 255;
    }
}

static void record_levels(ConfContext* c, GLenum target, const char* what, int levels) {
  char key[96];
  for (int l = 0; l < levels; ++l) {
    GLint w, h, b;
    glGetTexLevelParameteriv(target, l, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(target, l, GL_TEXTURE_HEIGHT, &h);
    glGetTexLevelParameteriv(target, l, GL_TEXTURE_BORDER, &b);
    snprintf(key, sizeof key, "%s level %d width height border", what, l);
    conf_values(c, key, (double[]){w, h, b}, 3);
  }
}

static void wrap(GLenum s, GLenum t) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, s);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, t);
}

static void filter(GLenum target, GLenum min, GLenum mag) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, min);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, mag);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 192)) return 1;
  glClearColor(0.2f, 0.2f, 0.25f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);

  static unsigned char img[18 * 18 * 4];
  bordered_image(img, 18, 120);
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 18, 18, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
  conf_error(&c, "TexImage2D with a border");
  record_levels(&c, GL_TEXTURE_2D, "2D", 1);
  static unsigned char back[18 * 18 * 4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  for (int i = 0; i < 16 * 16; i += 7) {
    char key[64];
    snprintf(key, sizeof key, "texel %d", i);
    conf_values(&c, key, (double[]){back[i * 4], back[i * 4 + 1], back[i * 4 + 2], back[i * 4 + 3]}, 4);
  }

  /* Top row: GL_CLAMP linear with three border colours, GL_CLAMP nearest. */
  const GLfloat colours[3][4] = {{0, 0, 0, 0}, {1.0f, 0.85f, 0.1f, 1.0f}, {0.3f, 0.3f, 1.0f, 0.5f}};
  filter(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR);
  wrap(GL_CLAMP, GL_CLAMP);
  for (int i = 0; i < 3; ++i) {
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, colours[i]);
    cell(&c, i, 0);
    glRotatef(5.0f * (float)i, 0, 0, 1);
    quad(-0.35f, -0.3f, 1.3f, 1.4f);
  }
  filter(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  cell(&c, 3, 0);
  quad(-0.35f, -0.3f, 1.3f, 1.4f);

  /* Middle row: clamp on s only, on t only, clamp to edge, repeat. */
  filter(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR);
  const GLenum modes[4][2] = {{GL_CLAMP, GL_REPEAT}, {GL_REPEAT, GL_CLAMP}, {GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE},
                              {GL_REPEAT, GL_REPEAT}};
  for (int i = 0; i < 4; ++i) {
    wrap(modes[i][0], modes[i][1]);
    cell(&c, i, 1);
    quad(-0.6f, -0.4f, 1.4f, 1.6f);
  }

  /* Bottom row: a mipmap chain with a border at every level (18, 10, 6, 4, 3: 16 .. 1
   * inside), minified; a 1D texture with a border under GL_CLAMP; and a 3x3 image with a
   * border (1x1 inside). */
  GLuint chain;
  glGenTextures(1, &chain);
  glBindTexture(GL_TEXTURE_2D, chain);
  for (int l = 0, n = 16; n >= 1; ++l, n /= 2) {
    bordered_image(img, n + 2, 60 + 40 * l);
    glTexImage2D(GL_TEXTURE_2D, l, GL_RGBA, n + 2, n + 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
  }
  record_levels(&c, GL_TEXTURE_2D, "chain", 6);
  filter(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  wrap(GL_CLAMP, GL_CLAMP);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, colours[1]);
  cell(&c, 0, 2);
  quad(-2.5f, -2.0f, 3.5f, 4.0f);
  wrap(GL_REPEAT, GL_REPEAT);
  cell(&c, 1, 2);
  glRotatef(20.0f, 0, 0, 1);
  quad(0.0f, 0.0f, 7.0f, 5.0f);

  static unsigned char row[34 * 4];
  for (int i = 0; i < 34; ++i) {
    row[i * 4 + 0] = (unsigned char)(i == 0 || i == 33 ? 255 : i * 7);
    row[i * 4 + 1] = (unsigned char)(i == 0 || i == 33 ? 0 : 255 - i * 7);
    row[i * 4 + 2] = 128;
    row[i * 4 + 3] = 255;
  }
  GLuint one_d;
  glGenTextures(1, &one_d);
  glBindTexture(GL_TEXTURE_1D, one_d);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 34, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
  record_levels(&c, GL_TEXTURE_1D, "1D", 1);
  filter(GL_TEXTURE_1D, GL_LINEAR, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP);
  glTexParameterfv(GL_TEXTURE_1D, GL_TEXTURE_BORDER_COLOR, colours[2]);
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_1D);
  cell(&c, 2, 2);
  quad(-0.4f, 0.0f, 1.4f, 1.0f);
  glDisable(GL_TEXTURE_1D);
  glEnable(GL_TEXTURE_2D);

  GLuint tiny;
  glGenTextures(1, &tiny);
  glBindTexture(GL_TEXTURE_2D, tiny);
  bordered_image(img, 3, 200);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 3, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
  record_levels(&c, GL_TEXTURE_2D, "3x3 with border", 1);
  filter(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR);
  wrap(GL_CLAMP, GL_CLAMP);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, colours[2]);
  cell(&c, 3, 2);
  quad(-1.0f, -1.0f, 2.0f, 2.0f);
  conf_error(&c, "end");

  glDeleteTextures(1, &tex);
  glDeleteTextures(1, &chain);
  glDeleteTextures(1, &one_d);
  glDeleteTextures(1, &tiny);
  return conf_finish(&c);
}
