/* glReadPixels of every GL 1.1 format and type, byte for byte: the framebuffer is filled with
 * known colours, depths and stencil indices through glDrawPixels (exact in both libraries), then
 * read back in RGBA, RGB, BGRA, BGR, RED, GREEN, BLUE, ALPHA, LUMINANCE, LUMINANCE_ALPHA,
 * DEPTH_COMPONENT and STENCIL_INDEX as UNSIGNED_BYTE, BYTE, UNSIGNED_SHORT, SHORT, UNSIGNED_INT, INT
 * and FLOAT, from rectangles inside and across the framebuffer's edges, with pack alignments,
 * row lengths, skips and byte swapping, with and without the pixel transfer operations (colour
 * scale and bias, colour maps of several sizes, depth scale and bias, index shift, offset and
 * stencil map), and the error codes of wrong calls. Every byte read (the destination is
 * prefilled, so bytes a read leaves alone count too) goes into the output image, which is
 * compared with Mesa's exactly.
 *
 * Left out, where Mesa departs from the specification: values of exactly 1.0 packed as
 * UNSIGNED_INT or INT after luminance or transfer operations (Mesa overflows to 0 and INT_MIN), so
 * those reads take dark regions and transfer operations that keep every value below 1;
 * FLOAT after transfer operations above 1 (Mesa does not clamp); STENCIL_INDEX as BITMAP (Mesa
 * loops forever); byte swapping with a row length shorter than the rectangle (Mesa swaps the
 * overlapping rows' bytes once per row). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "conf.h"

enum { kW = 64, kH = 48, kDarkY = 40, kOutMax = 1 << 22, kScratch = 96 * 1024 };

static unsigned char* out;
static long out_n;

static void emit(const void* p, long n) {
  if (out_n + n > kOutMax) {
    fprintf(stderr, "output full\n");
    exit(5);
  }
  memcpy(out + out_n, p, (size_t)n);
  out_n += n;
}

static void emit_error(void) {
  unsigned short e = (unsigned short)glGetError();
  emit(&e, 2);
}

/* Colours: every byte value in each channel; rows from kDarkY have R, G, B < 85 and A < 255
 * (their luminance stays below 1). */
static void fill(void) {
  static unsigned char rgba[kW * kH * 4], stencil[kW * kH];
  static GLfloat depth[kW * kH];
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      unsigned char* p = rgba + (y * kW + x) * 4;
      int i = y * kW + x;
      if (y < kDarkY) {
        p[0] = (unsigned char)(i * 5), p[1] = (unsigned char)(i * 3 + 7), p[2] = (unsigned char)(255 - i);
        p[3] = (unsigned char)(i * 11 + x);
      } else {
        p[0] = (unsigned char)(i % 85), p[1] = (unsigned char)((i * 7) % 85), p[2] = (unsigned char)((i * 13) % 85);
        p[3] = (unsigned char)((i * 17) % 255);
      }
      unsigned z24 = (unsigned)(i * 4099u * 257u + 12345u) & 0xffffffu;
      if (x == 0) z24 = 0;
      if (x == 1) z24 = 0xffffffu;
      depth[i] = (GLfloat)(z24 / 16777215.0); /* stored as these 24 bits by both libraries */
      stencil[i] = (unsigned char)(i * 29 + y);
    }
  }
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glRasterPos2i(0, 0);
  glDrawPixels(kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDrawPixels(kW, kH, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  glDisable(GL_DEPTH_TEST);
  glDrawPixels(kW, kH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

typedef struct Pack {
  int alignment, row_length, skip_pixels, skip_rows, swap;
} Pack;

typedef struct Rect {
  int x, y, w, h;
} Rect;

static int components(GLenum f) {
  switch (f) {
    case GL_RGBA: case GL_BGRA: return 4;
    case GL_RGB: case GL_BGR: return 3;
    case GL_LUMINANCE_ALPHA: return 2;
    default: return 1;
  }
}

static int type_size(GLenum t) {
  if (t == GL_UNSIGNED_BYTE || t == GL_BYTE) return 1;
  if (t == GL_UNSIGNED_SHORT || t == GL_SHORT) return 2;
  return 4;
}

/* Bytes a read of the rectangle spans under the pack parameters (rows padded). */
static long extent(const Pack* p, const Rect* r, GLenum format, GLenum type) {
  long s = type_size(type), n = components(format), l = p->row_length ? p->row_length : r->w;
  long stride = s >= p->alignment ? n * s * l : (n * s * l + p->alignment - 1) / p->alignment * p->alignment;
  return stride * (p->skip_rows + r->h) + (p->skip_pixels + 1) * n * s;
}

static void read_one(const Pack* p, const Rect* r, GLenum format, GLenum type) {
  static unsigned char scratch[kScratch];
  if (getenv("CONF_TRACE")) {
    fprintf(stderr, "%ld: format 0x%x type 0x%x rect %d %d %d %d pack %d %d %d %d %d\n", out_n, format, type, r->x,
            r->y, r->w, r->h, p->alignment, p->row_length, p->skip_pixels, p->skip_rows, p->swap);
  }
  long n = extent(p, r, format, type);
  if (n > kScratch) n = kScratch;
  memset(scratch, 0xcd, sizeof scratch);
  glPixelStorei(GL_PACK_ALIGNMENT, p->alignment);
  glPixelStorei(GL_PACK_ROW_LENGTH, p->row_length);
  glPixelStorei(GL_PACK_SKIP_PIXELS, p->skip_pixels);
  glPixelStorei(GL_PACK_SKIP_ROWS, p->skip_rows);
  glPixelStorei(GL_PACK_SWAP_BYTES, p->swap);
  glReadPixels(r->x, r->y, r->w, r->h, format, type, scratch);
  emit_error();
  emit(scratch, n);
}

static const GLenum kColorFormats[] = {GL_RGBA, GL_RGB, GL_BGRA, GL_BGR, GL_RED, GL_GREEN,
                                       GL_BLUE, GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA};
static const GLenum kTypes[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                GL_UNSIGNED_INT, GL_INT, GL_FLOAT};
#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

static const Pack kPacks[] = {
    {4, 0, 0, 0, 0}, {1, 0, 0, 0, 0}, {2, 0, 0, 0, 1}, {8, 0, 0, 0, 0},
    {4, 70, 3, 2, 0}, {1, 67, 0, 1, 1}, {8, 0, 5, 0, 1},
};
static const Rect kRects[] = {{0, 0, kW, kDarkY}, {5, 3, 13, 7}, {50, 30, 20, 9}, {-3, -2, 9, 6}};
static const Rect kDark[] = {{0, kDarkY, kW, kH - kDarkY}, {7, kDarkY + 1, 11, 5}, {60, 44, 9, 7}};

static int is_luminance(GLenum f) { return f == GL_LUMINANCE || f == GL_LUMINANCE_ALPHA; }
static int is_32bit_int(GLenum t) { return t == GL_UNSIGNED_INT || t == GL_INT; }

/* Every colour format and type over the rectangles (luminance as 32-bit integers over the dark
 * ones), each with a pack state of its own. */
static void colors(int dark_only) {
  int k = 0;
  for (int f = 0; f < COUNT(kColorFormats); ++f) {
    for (int t = 0; t < COUNT(kTypes); ++t) {
      int dark = dark_only || (is_luminance(kColorFormats[f]) && is_32bit_int(kTypes[t]));
      const Rect* rects = dark ? kDark : kRects;
      int nrects = dark ? COUNT(kDark) : COUNT(kRects);
      for (int r = 0; r < nrects; ++r, ++k) read_one(&kPacks[k % COUNT(kPacks)], &rects[r], kColorFormats[f], kTypes[t]);
    }
  }
}

static void depth_stencil(void) {
  int k = 3;
  for (int t = 0; t < COUNT(kTypes); ++t) {
    for (int r = 0; r < COUNT(kRects); ++r, ++k) {
      read_one(&kPacks[k % COUNT(kPacks)], &kRects[r], GL_DEPTH_COMPONENT, kTypes[t]);
      read_one(&kPacks[(k + 2) % COUNT(kPacks)], &kRects[r], GL_STENCIL_INDEX, kTypes[t]);
    }
  }
}

static void set_transfer(float s0, float s1, float s2, float s3, float b0, float b1, float b2, float b3) {
  glPixelTransferf(GL_RED_SCALE, s0);
  glPixelTransferf(GL_GREEN_SCALE, s1);
  glPixelTransferf(GL_BLUE_SCALE, s2);
  glPixelTransferf(GL_ALPHA_SCALE, s3);
  glPixelTransferf(GL_RED_BIAS, b0);
  glPixelTransferf(GL_GREEN_BIAS, b1);
  glPixelTransferf(GL_BLUE_BIAS, b2);
  glPixelTransferf(GL_ALPHA_BIAS, b3);
}

/* Colour maps of sizes 1, 2, 5 and 256 (and 3 for alpha) with values below 1. */
static void set_maps(void) {
  GLfloat big[256];
  for (int i = 0; i < 256; ++i) big[i] = 0.9f * (float)((i * 37) % 256) / 255.0f;
  const GLfloat two[2] = {0.1f, 0.85f}, five[5] = {0.9f, 0.05f, 0.5f, 0.25f, 0.75f}, three[3] = {0.3f, 0.6f, 0.2f};
  const GLushort one[1] = {40000};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 256, big);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 5, five);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 2, two);
  glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 3, three);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  read_one(&kPacks[0], &kRects[0], GL_RGBA, GL_UNSIGNED_BYTE);
  read_one(&kPacks[1], &kRects[1], GL_RGBA, GL_FLOAT);
  read_one(&kPacks[2], &kRects[0], GL_BGRA, GL_UNSIGNED_SHORT);
  glPixelMapusv(GL_PIXEL_MAP_B_TO_B, 1, one);
  read_one(&kPacks[3], &kRects[2], GL_RGB, GL_UNSIGNED_INT);
  read_one(&kPacks[4], &kDark[0], GL_LUMINANCE_ALPHA, GL_SHORT);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
}

static void transfers(void) {
  set_transfer(0.5f, 0.75f, 0.6f, 0.9f, 0.05f, 0.1f, 0.0f, 0.02f);
  colors(0);
  set_transfer(0.75f, 0.75f, 0.75f, 0.75f, 0.05f, 0.05f, 0.05f, 0.05f);
  colors(1);
  set_transfer(1, 1, 1, 1, 0, 0, 0, 0);
  set_maps();
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
  glPixelTransferi(GL_INDEX_SHIFT, 2);
  glPixelTransferi(GL_INDEX_OFFSET, 5);
  depth_stencil();
  glPixelTransferf(GL_DEPTH_SCALE, 3.0f);
  glPixelTransferf(GL_DEPTH_BIAS, -1.0f);
  glPixelTransferi(GL_INDEX_SHIFT, -3);
  glPixelTransferi(GL_INDEX_OFFSET, -2);
  const GLuint smap[8] = {200, 1, 77, 3, 255, 0, 128, 9};
  glPixelMapuiv(GL_PIXEL_MAP_S_TO_S, 8, smap);
  glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
  depth_stencil();
  glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
}

static void errors(void) {
  unsigned char buf[64];
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, buf);
  emit_error();
  glReadPixels(0, 0, 1, -1, 0x1234, GL_UNSIGNED_BYTE, buf);
  emit_error();
  glReadPixels(0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, buf);
  emit_error();
  glReadPixels(0, 0, 1, 1, GL_RGBA, 0x1234, buf);
  emit_error();
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_BITMAP, buf);
  emit_error();
  glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, buf);
  emit_error();
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_BITMAP, buf);
  emit_error();
  glReadPixels(0, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, buf);
  emit_error();
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  emit_error();
  glPixelStorei(GL_PACK_ALIGNMENT, 3);
  emit_error();
  glPixelStorei(GL_PACK_ROW_LENGTH, -1);
  emit_error();
  glPixelStorei(0x1234, 1);
  emit_error();
  glReadBuffer(GL_NONE);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, buf);
  emit_error();
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, buf);
  emit_error();
  glReadBuffer(GL_FRONT);
  glBegin(GL_TRIANGLES);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, buf);
  glEnd();
  emit_error();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, kW, kH)) return 1;
  out = (unsigned char*)malloc(kOutMax);
  if (!out) return 1;
  fill();
  colors(0);
  depth_stencil();
  transfers();
  errors();
  int rc = 0;
  if (!conf_write_bytes_png(c.out_path, out, out_n, 512)) rc = 2;
  fprintf(stderr, "%ld bytes read back\n", out_n);
  OSMesaDestroyContext(c.ctx);
  free(c.buffer);
  free(out);
  return rc;
}
