/* Texture sub-images and copies (OpenGL 1.1 sections 3.8.2, 6.1.4): glTexSubImage2D pieces
 * in several formats and types under unpack states (alignment, row length, skipped pixels and
 * rows, swapped bytes), glTexSubImage1D, glCopyTexImage2D of a lit sphere drawn just before
 * (the copy must see it), into RGB, luminance and alpha textures, glCopyTexSubImage2D of
 * another drawing into part of one, glCopyTexImage1D of a row; each texture then drawn
 * magnified. glGetTexImage of the results in several formats and types under pack states is
 * compared byte for byte with Mesa's (conf_value). */
#include <stdio.h>
#include <string.h>

#include "conf.h"

static void quad(float x0, float y0, float x1, float y1) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(x0, y0);
  glTexCoord2f(1, 0);
  glVertex2f(x1, y0);
  glTexCoord2f(1, 1);
  glVertex2f(x1, y1);
  glTexCoord2f(0, 1);
  glVertex2f(x0, y1);
  glEnd();
}

static void flat_cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void nearest(GLenum target) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

/* Records `n` bytes of `data` (values byte by byte). */
static void record_bytes(ConfContext* c, const char* name, const unsigned char* data, int n) {
  char key[128];
  for (int i = 0; i < n; ++i) {
    snprintf(key, sizeof key, "%s byte %d", name, i);
    conf_value(c, key, data[i]);
  }
}

static void default_unpack(void) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
}

/* A 32x32 RGB checker with sub-images of several formats and types written into it. */
static GLuint patched_texture(void) {
  static unsigned char base[32 * 32 * 3];
  for (int i = 0; i < 32 * 32; ++i) {
    int on = ((i % 32) / 4 + (i / 32) / 4) % 2;
    base[i * 3 + 0] = on ? 230 : 40;
    base[i * 3 + 1] = on ? 220 : 60;
    base[i * 3 + 2] = on ? 200 : 90;
  }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 32, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, base);
  static unsigned char rgba[8 * 8 * 4];
  for (int i = 0; i < 8 * 8 * 4; ++i) rgba[i] = (unsigned char)(i * 13 + 7);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 3, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  /* Luminance 5x7 out of a 9-wide image, skipping 2 pixels and 1 row, rows 4-aligned. */
  static unsigned char lum[12 * 12];
  for (int i = 0; i < 12 * 12; ++i) lum[i] = (unsigned char)(255 - i * 5);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 9);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 20, 2, 5, 7, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
  default_unpack();
  /* RGB unsigned shorts with their bytes swapped. */
  static unsigned short rgb16[6 * 4 * 3];
  for (int i = 0; i < 6 * 4 * 3; ++i) {
    unsigned short v = (unsigned short)(i * 2731 + 999);
    rgb16[i] = (unsigned short)((v >> 8) | (v << 8));
  }
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 12, 14, 6, 4, GL_RGB, GL_UNSIGNED_SHORT, rgb16);
  default_unpack();
  /* BGRA floats, signed bytes as luminance-alpha, single channels. */
  static float bgra[4 * 4 * 4];
  for (int i = 0; i < 4 * 4 * 4; ++i) bgra[i] = (float)((i * 7) % 11) / 10.0f;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 22, 4, 4, GL_BGRA, GL_FLOAT, bgra);
  static signed char la[5 * 3 * 2];
  for (int i = 0; i < 5 * 3 * 2; ++i) la[i] = (signed char)(i * 9 - 60);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 24, 24, 5, 3, GL_LUMINANCE_ALPHA, GL_BYTE, la);
  static unsigned char channel[3 * 5];
  for (int i = 0; i < 15; ++i) channel[i] = (unsigned char)(i * 17);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 26, 10, 3, 5, GL_RED, GL_UNSIGNED_BYTE, channel);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 26, 16, 3, 5, GL_GREEN, GL_UNSIGNED_BYTE, channel);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 14, 26, 5, 3, GL_BLUE, GL_UNSIGNED_BYTE, channel);
  static GLint ints[2 * 2 * 3] = {0x7fffffff, 0, 0x40000000, -5, 0x20000000, 0x7fffffff,
                                  1000, 0x60000000, 0x10000000, 0x7ff00000, 3, 0x55555555};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 30, 2, 2, GL_RGB, GL_INT, ints);
  default_unpack();
  nearest(GL_TEXTURE_2D);
  return tex;
}

/* glGetTexImage of the patched texture in several ways. */
static void read_back(ConfContext* c) {
  static unsigned char out[32 * 32 * 16 + 256];
  memset(out, 0xa5, sizeof out);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  record_bytes(c, "RGBA ubyte", out, 32 * 32 * 4);
  memset(out, 0xa5, sizeof out);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  glPixelStorei(GL_PACK_ROW_LENGTH, 35);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
  glPixelStorei(GL_PACK_SKIP_ROWS, 2);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_BGR, GL_UNSIGNED_BYTE, out);
  record_bytes(c, "BGR ubyte packed", out, 112 * 34); /* rows of 105 bytes padded to 112 */
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  memset(out, 0xa5, sizeof out);
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT, out);
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
  record_bytes(c, "LUMINANCE_ALPHA ushort swapped", out, 32 * 32 * 4);
  static GLfloat f[32 * 32];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_GREEN, GL_FLOAT, f);
  for (int i = 0; i < 32 * 32; i += 3) {
    char key[64];
    snprintf(key, sizeof key, "GREEN float %d", i);
    conf_value(c, key, f[i]);
  }
  static GLbyte b[32 * 32 * 3];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_BYTE, b);
  record_bytes(c, "RGB byte", (const unsigned char*)b, 32 * 32 * 3);
  static GLint i32[32 * 32];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_BLUE, GL_INT, i32);
  static GLuint u32[32 * 32];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_ALPHA, GL_UNSIGNED_INT, u32);
  static GLshort s16[32 * 32];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_SHORT, s16);
  for (int i = 0; i < 32 * 32; i += 5) {
    char key[64];
    snprintf(key, sizeof key, "BLUE int %d", i);
    conf_value(c, key, i32[i]);
    snprintf(key, sizeof key, "ALPHA uint %d", i);
    conf_value(c, key, u32[i]);
    snprintf(key, sizeof key, "RED short %d", i);
    conf_value(c, key, s16[i]);
  }
  conf_error(c, "read back");
}

/* Flat rectangles of exact colours in cell (3, 1) (pixel units), copied byte for byte into
 * 2D and 1D textures (a copy reaching past the framebuffer's edge into an existing texture
 * leaves the texels outside as they were), recorded with glGetTexImage. */
static void exact_copies(ConfContext* c) {
  const int x0 = 3 * (c->width / 4), y0 = c->height - 2 * (c->height / 3);
  glViewport(0, 0, c->width, c->height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, c->width, 0, c->height, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  for (int k = 0; k < 8; ++k) {
    glColor4ub((GLubyte)(k * 31), (GLubyte)(255 - k * 17), (GLubyte)(k * k * 3), (GLubyte)(60 + k * 20));
    glRecti(x0 + k * 7, y0 + k * 5, x0 + 40 + k * 3, y0 + 30 + k * 2);
  }
  GLuint t[2];
  glGenTextures(2, t);
  glBindTexture(GL_TEXTURE_2D, t[0]);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, x0 + 2, y0 + 1, 40, 36, 0);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 30, 28, c->width - 5, y0 + 4, 10, 8);
  static unsigned char out[40 * 36 * 4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  record_bytes(c, "copied rectangles", out, 40 * 36 * 4);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, x0 + 5, y0 + 3, 17, 13, 0);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  record_bytes(c, "copied luminance-alpha", out, 17 * 13 * 4);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5_A1, x0 + 5, y0 + 3, 17, 13, 0);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  record_bytes(c, "copied RGB5_A1", out, 17 * 13 * 4);
  glBindTexture(GL_TEXTURE_1D, t[1]);
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_INTENSITY, x0, y0 + 12, 48, 0);
  glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 40, x0 + 3, y0 + 20, 8);
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  record_bytes(c, "copied row", out, 48 * 4);
  conf_error(c, "exact copies");
  glDeleteTextures(2, t);
}

/* A lit sphere in cell (col, row), drawn to be copied. */
static void sphere_cell(const ConfContext* c, int col, int row, float hue) {
  conf_panel(c, col, row, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.2, 1.2, -1.2, 1.2, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat diffuse[4] = {0.9f * hue, 0.5f, 1.0f - 0.8f * hue, 0.5f}, light[4] = {0.5f, 0.8f, 1.0f, 0.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, diffuse);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glDisable(GL_TEXTURE_2D);
  conf_sphere(1.0f, 24, 12);
  glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 192)) return 1;
  glClearColor(0.15f, 0.1f, 0.2f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  exact_copies(&c);
  GLuint patched = patched_texture();
  read_back(&c);
  flat_cell(&c, 0, 0);
  glEnable(GL_TEXTURE_2D);
  quad(-1, -1, 1, 1);

  /* 1D: sub-images into a 16-texel ramp, drawn as a band. */
  static unsigned char ramp[16 * 3], piece[4 * 4];
  for (int i = 0; i < 16 * 3; ++i) ramp[i] = (unsigned char)(i * 5);
  for (int i = 0; i < 16; ++i) piece[i] = (unsigned char)(250 - i * 9);
  GLuint one_d;
  glGenTextures(1, &one_d);
  glBindTexture(GL_TEXTURE_1D, one_d);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, ramp);
  glTexSubImage1D(GL_TEXTURE_1D, 0, 5, 4, GL_RGBA, GL_UNSIGNED_BYTE, piece);
  glTexSubImage1D(GL_TEXTURE_1D, 0, 12, 3, GL_LUMINANCE, GL_UNSIGNED_BYTE, piece);
  nearest(GL_TEXTURE_1D);
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_1D);
  flat_cell(&c, 1, 0);
  quad(-1, -1, 1, 1);
  glDisable(GL_TEXTURE_1D);

  /* Copies of a sphere drawn just before, into three internal formats. */
  sphere_cell(&c, 2, 0, 0.2f);
  const int cw = c.width / 4, ch = c.height / 3;
  GLuint copies[3];
  glGenTextures(3, copies);
  const GLenum internal[3] = {GL_RGB, GL_LUMINANCE, GL_ALPHA};
  for (int i = 0; i < 3; ++i) {
    glBindTexture(GL_TEXTURE_2D, copies[i]);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, internal[i], 2 * cw + 4, c.height - ch + 2, 48, 40, 0);
    nearest(GL_TEXTURE_2D);
  }
  conf_error(&c, "copies");
  /* Another sphere copied into part of the first copy. */
  sphere_cell(&c, 3, 0, 0.9f);
  glBindTexture(GL_TEXTURE_2D, copies[0]);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 10, 8, 3 * cw + 20, c.height - ch + 10, 24, 20);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int i = 0; i < 3; ++i) {
    glBindTexture(GL_TEXTURE_2D, copies[i]);
    flat_cell(&c, i, 1);
    glRotatef(8.0f * (float)(i + 1), 0, 0, 1);
    glColor4f(1.0f, 0.9f, 0.6f, 1.0f);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    quad(-0.9f, -0.9f, 0.9f, 0.9f);
  }
  glDisable(GL_BLEND);
  /* A row of the framebuffer as a 1D texture, and a sub-copy into it. */
  glBindTexture(GL_TEXTURE_1D, one_d);
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGB8, 2 * cw, c.height - ch / 2, 64, 0);
  glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 40, 3 * cw + 10, c.height - ch / 2 - 3, 20);
  conf_error(&c, "1D copies");
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_1D);
  flat_cell(&c, 3, 1);
  quad(-1, -1, 1, 1);
  glDisable(GL_TEXTURE_1D);

  /* The patched texture once more, after the copies, minified and rotated (linear). */
  glBindTexture(GL_TEXTURE_2D, patched);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int k = 0; k < 4; ++k) {
    flat_cell(&c, k, 2);
    glRotatef(11.0f * (float)k, 0, 0, 1);
    float s = 0.5f + 0.3f * (float)k;
    quad(-s, -s, s, s);
  }
  glDeleteTextures(3, copies);
  glDeleteTextures(1, &patched);
  glDeleteTextures(1, &one_d);
  return conf_finish(&c);
}
