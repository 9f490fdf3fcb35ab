/* Pixel commands in display lists (GL 1.1 section 5.4): glBitmap and glDrawPixels keep their
 * image as the unpack state of compile time reads it (row length, skips, alignment, byte
 * swapping, GL_UNPACK_LSB_FIRST), whatever the unpack state is when the list runs, and the
 * client memory may change after glEndList; glPixelMap*, glPixelTransfer*, glPixelZoom,
 * glRasterPos*, glCopyPixels and glBitmap's advance are replayed; GL_COMPILE_AND_EXECUTE
 * draws while compiling; glPixelStore and glReadPixels are executed at once, never compiled;
 * errors of compiled commands are raised when the list runs (a strip of error codes at the
 * top).
 *
 * Left out, where Mesa departs from the specification: glBitmap with a null bitmap in a list
 * (Mesa 22.3 records GL_OUT_OF_MEMORY and drops the command, so the raster position does not
 * move; shadelab compiles it: a bitmap of no size only moves the raster position). */
#include <string.h>

#include "conf.h"

enum { kW = 256, kH = 160 };

/* A 24 x 12 atlas of bits (rows of 3 bytes, alignment 1), read through skips. */
static GLubyte atlas[12 * 4];

static void make_atlas(void) {
  for (int y = 0; y < 12; ++y) {
    for (int b = 0; b < 4; ++b) atlas[y * 4 + b] = (GLubyte)(0x5a ^ (y * 37 + b * 91) ^ (y == 0 || y == 11 ? 0xff : 0));
  }
}

static void default_store(void) {
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

/* A different unpack state, set when the lists run. */
static void other_store(void) {
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 5);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
}

/* Bitmaps compiled under several unpack states, with their advances. */
static GLuint bitmap_list(void) {
  GLuint list = glGenLists(1);
  static GLubyte bits[12 * 4];
  memcpy(bits, atlas, sizeof bits);
  glNewList(list, GL_COMPILE);
  default_store();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glBitmap(13, 10, 0.0f, 0.0f, 16.0f, 0.0f, bits);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glBitmap(13, 10, 1.5f, -0.5f, 16.0f, 0.0f, bits);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 32);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBitmap(17, 9, 0.0f, 0.0f, 20.0f, 1.0f, bits);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 9);
  glBitmap(11, 8, 0.0f, 2.0f, 14.0f, -1.0f, bits);
  glBitmap(0, 0, 0.0f, 0.0f, 6.0f, 0.0f, bits); /* only moves */
  glEndList();
  memset(bits, 0xff, sizeof bits); /* the list keeps its own copy */
  return list;
}

static void bitmaps(GLuint list) {
  other_store();
  glColor3f(1.0f, 0.9f, 0.2f);
  glRasterPos2i(4, 120);
  glCallList(list);
  glCallList(list);
  glColor3f(0.3f, 0.8f, 1.0f);
  glRasterPos2f(6.5f, 104.25f);
  glCallList(list);
  /* GL_COMPILE_AND_EXECUTE draws while compiling, with the state of that moment. */
  GLuint both = glGenLists(1);
  default_store();
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glColor3f(1.0f, 0.3f, 0.6f);
  glRasterPos2i(140, 120);
  glNewList(both, GL_COMPILE_AND_EXECUTE);
  glBitmap(15, 11, 0.0f, 0.0f, 18.0f, 0.0f, atlas);
  glBitmap(15, 11, 0.0f, 0.0f, 18.0f, 0.0f, atlas);
  glEndList();
  other_store();
  glRasterPos2i(140, 104);
  glCallList(both);
}

/* Images of several formats and types compiled with one unpack state, run with another. */
static GLuint image_list(GLushort* rgba16, GLfloat* rgbf, GLubyte* lum) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  default_store();
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 12);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glRasterPos2i(4, 60);
  glDrawPixels(10, 9, GL_RGBA, GL_UNSIGNED_SHORT, rgba16);
  default_store();
  glRasterPos2i(20, 60);
  glPixelZoom(2.0f, 1.5f);
  glDrawPixels(8, 8, GL_RGB, GL_FLOAT, rgbf);
  glPixelZoom(-1.0f, 1.0f);
  glRasterPos2i(60, 60);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glDrawPixels(7, 9, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum); /* rows padded to 8 bytes */
  glPixelZoom(1.0f, 1.0f);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 4);
  glRasterPos2i(70, 60);
  glDrawPixels(9, 9, GL_GREEN, GL_UNSIGNED_BYTE, lum);
  glEndList();
  return list;
}

static void images(void) {
  static GLushort rgba16[12 * 10 * 4];
  static GLfloat rgbf[8 * 8 * 3];
  static GLubyte lum[8 * 16];
  for (int i = 0; i < 12 * 10 * 4; ++i) {
    GLushort v = (GLushort)((i * 2731) & 0xffff);
    rgba16[i] = (GLushort)((v << 8) | (v >> 8)); /* stored byte-swapped */
    if (i % 4 == 3) rgba16[i] = 0xffff;
  }
  for (int i = 0; i < 8 * 8 * 3; ++i) rgbf[i] = (float)((i * 7) % 23) / 22.0f;
  for (int i = 0; i < 8 * 16; ++i) lum[i] = (GLubyte)(i * 2);
  GLuint list = image_list(rgba16, rgbf, lum);
  memset(rgba16, 0, sizeof rgba16);
  memset(rgbf, 0, sizeof rgbf);
  memset(lum, 0, sizeof lum);
  other_store();
  glCallList(list);
  glTranslatef(90.0f, 0.0f, 0.0f); /* the raster positions move with the modelview */
  glCallList(list);
  glLoadIdentity();
}

/* Pixel maps, transfer modes, a colour-index bitmap image and a copy, all compiled. */
static void transfer(void) {
  static GLfloat map[4] = {0.1f, 0.9f, 0.4f, 0.7f};
  static GLubyte index_bits[8 * 2];
  for (int i = 0; i < 16; ++i) index_bits[i] = (GLubyte)(i % 2 ? 0x3c : 0xa5);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, map);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 2, map + 2);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 2, map + 1);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 2, map + 1);
  default_store();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glRasterPos2i(200, 60);
  glPixelZoom(3.0f, 2.0f);
  glDrawPixels(16, 8, GL_COLOR_INDEX, GL_BITMAP, index_bits);
  glPixelZoom(1.0f, 1.0f);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_BIAS, 0.25f);
  glRasterPos2i(200, 20);
  glCopyPixels(4, 104, 40, 30, GL_COLOR);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glPixelTransferf(GL_GREEN_BIAS, 0.0f);
  glEndList();
  map[0] = map[1] = map[2] = map[3] = 0.0f; /* the list keeps the values of compile time */
  memset(index_bits, 0, sizeof index_bits);
  other_store();
  glCallList(list);
}

/* GL_INVALID_ENUM .. GL_OUT_OF_MEMORY as 1 .. 6, no error as 0. */
static GLubyte error_code(void) {
  GLenum e = glGetError();
  return (GLubyte)(e == GL_NO_ERROR ? 0 : e - GL_INVALID_ENUM + 1);
}

/* Errors of compiled commands come when the list runs; none while compiling. */
static void errors(void) {
  static GLubyte img[16];
  GLubyte codes[8];
  int n = 0;
  GLuint list = glGenLists(4);
  glNewList(list, GL_COMPILE);
  glDrawPixels(2, 2, 0x1234, GL_UNSIGNED_BYTE, img);
  glEndList();
  codes[n++] = error_code();
  glNewList(list + 1, GL_COMPILE);
  glBitmap(-1, 2, 0.0f, 0.0f, 0.0f, 0.0f, img);
  glEndList();
  codes[n++] = error_code();
  glNewList(list + 2, GL_COMPILE);
  glDrawPixels(-2, 2, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glEndList();
  codes[n++] = error_code();
  glNewList(list + 3, GL_COMPILE);
  glDrawPixels(1, 1, GL_RGB, GL_BITMAP, img);
  glEndList();
  codes[n++] = error_code();
  glRasterPos2i(4, 150);
  for (GLuint i = 0; i < 4; ++i) {
    glCallList(list + i);
    codes[n++] = error_code();
  }
  GLubyte strip[8 * 4];
  for (int i = 0; i < n; ++i) strip[i * 4] = strip[i * 4 + 1] = strip[i * 4 + 2] = (GLubyte)(codes[i] * 40), strip[i * 4 + 3] = 255;
  default_store();
  glPixelZoom(4.0f, 4.0f);
  glRasterPos2i(4, 150);
  glDrawPixels(n, 1, GL_RGBA, GL_UNSIGNED_BYTE, strip);
  glPixelZoom(1.0f, 1.0f);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, kW, kH)) return 1;
  glClearColor(0.1f, 0.12f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  make_atlas();
  bitmaps(bitmap_list());
  images();
  transfer();
  errors();
  return conf_finish(&c);
}
