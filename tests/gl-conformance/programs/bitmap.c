/* glBitmap (GL 1.1 section 3.7) as GLUT's bitmap fonts use it: glyphs from a font table (width,
 * height, origin, advance, rows of bytes from the bottom), drawn as strings that advance the
 * raster position, with the unpack state GLUT sets (alignment 1) and others: GL_UNPACK_LSB_FIRST,
 * row length and skips into a glyph atlas, alignments 2, 4 and 8 with odd widths; fractional
 * origins and advances; bitmaps clipped at the window's four edges; a raster position moved out
 * of the window by advances (still valid) and back; an invalid raster position (nothing drawn,
 * no advance); glyphs against a depth buffer and blended; an empty bitmap that only moves. */
#include <string.h>

#include "conf.h"

enum { kW = 256, kH = 192 };

typedef struct Glyph {
  int width, height;
  float xorig, yorig, advance;
  GLubyte bits[32]; /* rows of (width + 7) / 8 bytes, bottom row first (alignment 1) */
} Glyph;

static Glyph font[16];

/* A font table of 16 glyphs: a frame, a diagonal and a pattern per glyph, widths 5 to 12,
 * heights 7 to 13, origins and advances as GLUT's fonts give them. */
static void make_font(void) {
  for (int g = 0; g < 16; ++g) {
    Glyph* f = &font[g];
    f->width = 5 + g % 8;
    f->height = 7 + (g * 5) % 7;
    f->xorig = (float)(g % 3) - 1.0f;
    f->yorig = (float)(g % 4 == 0 ? 2 : 0);
    f->advance = (float)f->width + 1.0f;
    memset(f->bits, 0, sizeof f->bits);
    const int stride = (f->width + 7) / 8;
    for (int y = 0; y < f->height; ++y) {
      for (int x = 0; x < f->width; ++x) {
        int on = y == 0 || y == f->height - 1 || x == 0 || x == f->width - 1 || x == (y * f->width) / f->height ||
                 ((x * 3 + y * (g + 1)) % 5 == 0);
        if (on) f->bits[y * stride + x / 8] |= (GLubyte)(0x80 >> (x % 8));
      }
    }
  }
}

static void glyph(int g) {
  const Glyph* f = &font[g & 15];
  glBitmap(f->width, f->height, f->xorig, f->yorig, f->advance, 0.0f, f->bits);
}

static void text(const char* s) {
  for (; *s; ++s) glyph(*s - 'a');
}

static void glut_store(void) {
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
}

static void strings(void) {
  glut_store();
  glColor3f(1.0f, 1.0f, 1.0f);
  glRasterPos2i(4, 170);
  text("abcdefghijklmnop");
  glColor3f(1.0f, 0.4f, 0.2f);
  glRasterPos2f(4.5f, 154.75f); /* fractional position */
  text("ponmlkjihgfedcba");
  glColor3f(0.3f, 1.0f, 0.5f); /* the colour is taken at glRasterPos: this one is not used */
  glRasterPos2f(4.0f, 140.0f);
  glColor3f(0.2f, 0.2f, 1.0f);
  for (int i = 0; i < 20; ++i) glBitmap(font[i % 16].width, font[i % 16].height, 0.0f, 0.0f, 6.5f, 0.25f, font[i % 16].bits);
  glBitmap(0, 0, 0.0f, 0.0f, 10.0f, 0.0f, NULL); /* a space */
  glyph(3);
}

/* GL_UNPACK_LSB_FIRST: the same bytes read from the other end of each byte. */
static void lsb_first(void) {
  glut_store();
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glColor3f(1.0f, 1.0f, 0.0f);
  glRasterPos2i(4, 122);
  text("abcdefghijklmnop");
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
}

/* A 40 x 24 atlas read through row length and skips, with each alignment. */
static void atlas(void) {
  static GLubyte bits[24 * 8];
  for (int y = 0; y < 24; ++y) {
    for (int b = 0; b < 8; ++b) bits[y * 8 + b] = (GLubyte)((y * 37 + b * 91) ^ (0x81 << (y % 4)));
  }
  glut_store();
  glColor3f(0.9f, 0.5f, 0.9f);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 64);
  for (int i = 0; i < 8; ++i) {
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, i * 5);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, i % 3 * 4);
    glRasterPos2i(4 + i * 14, 100);
    glBitmap(11, 9, 0.0f, 0.0f, 0.0f, 0.0f, bits);
  }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glColor3f(0.4f, 0.9f, 0.9f);
  const int aligns[4] = {1, 2, 4, 8};
  for (int i = 0; i < 4; ++i) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, aligns[i]);
    glRasterPos2i(120 + i * 30, 100);
    glBitmap(13, 10, 0.0f, 0.0f, 0.0f, 0.0f, bits);
    glRasterPos2i(120 + i * 30, 86);
    glBitmap(3, 10, 0.0f, 0.0f, 0.0f, 0.0f, bits);
  }
  glut_store();
}

/* Bitmaps that cross the window's edges, and a position moved out of the window and back. */
static void edges(void) {
  glut_store();
  glColor3f(1.0f, 0.7f, 0.7f);
  glRasterPos2i(2, 60);
  glBitmap(font[7].width, font[7].height, 6.0f, 0.0f, 0.0f, 0.0f, font[7].bits); /* past the left edge */
  glRasterPos2i(40, 2);
  glBitmap(font[7].width, font[7].height, 0.0f, 5.0f, 0.0f, 0.0f, font[7].bits); /* below the bottom */
  glRasterPos2i(kW - 4, 60);
  glyph(9); /* past the right edge */
  glRasterPos2i(60, kH - 5);
  glyph(12); /* past the top */
  glRasterPos2i(kW - 20, 40);
  text("abcdefgh"); /* advances out of the window: still valid */
  glBitmap(0, 0, 0.0f, 0.0f, -60.0f, -8.0f, NULL);
  text("ij");
  /* Invalid raster position: nothing drawn and no advance. */
  glRasterPos2i(-5, 20);
  text("kkkk");
  glRasterPos2i(100, 20);
  text("kl");
}

/* Against a depth buffer (the raster depth) and blended (the raster colour's alpha). */
static void depth_blend(void) {
  glut_store();
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.3f, 0.3f, 0.3f);
  glBegin(GL_TRIANGLES);
  glVertex3f(130, 10, 0.0f);
  glVertex3f(250, 10, 0.0f);
  glVertex3f(250, 70, 0.0f);
  glEnd();
  glColor3f(0.2f, 1.0f, 0.2f);
  glRasterPos3f(134.0f, 30.0f, 0.5f); /* behind the triangle */
  text("abcdefghijk");
  glRasterPos3f(134.0f, 14.0f, -0.5f); /* in front */
  text("abcdefghijk");
  glFlush(); /* Mesa 22.3 draws bitmaps it keeps for later with the state at that time */
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(1.0f, 0.2f, 0.2f, 0.5f);
  glRasterPos2i(140, 50);
  text("mnopabc");
  glDisable(GL_BLEND);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, kW, kH)) return 1;
  make_font();
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  strings();
  lsb_first();
  atlas();
  edges();
  depth_blend();
  return conf_finish(&c);
}
