/* The packed pixel types of GL 1.2 (UNSIGNED_BYTE_3_3_2 .. UNSIGNED_INT_2_10_10_10_REV, GL 1.5
 * section 3.6.4) in every command that reads or writes client pixels, byte for byte: the
 * error of every packed type with every pixel format in glReadPixels, glDrawPixels,
 * glTexImage2D and glGetTexImage; glReadPixels of known colours into each type with each
 * format it packs (RGB, or RGBA and BGRA), under pack alignments, row lengths, skips and byte
 * swapping, with and without colour scale and bias; glDrawPixels of packed images read back
 * as RGBA bytes; textures specified from packed images read back by glGetTexImage as RGBA
 * bytes and as every packed type. Every byte goes into the output image, which is compared with
 * Mesa's exactly.
 *
 * Left out, where shadelab does not yet do what Mesa does (docs/gl.md, "Pixel rectangles"):
 * textures read back into the 10-bit types (10_10_10_2, 2_10_10_10_REV: Mesa keeps a texture
 * specified from a packed image at that type's precision and widens from there; shadelab keeps
 * bytes). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "conf.h"

enum { kW = 32, kH = 24, kOutMax = 1 << 21, kScratch = 16 * 1024 };

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

/* With CONF_TRACE set, where each part of the output starts (for finding a difference). */
static void trace(const char* what, GLenum format, GLenum type, int k) {
  if (getenv("CONF_TRACE")) fprintf(stderr, "%ld: %s format 0x%x type 0x%x case %d\n", out_n, what, format, type, k);
}

static void emit_error(void) {
  unsigned short e = (unsigned short)glGetError();
  emit(&e, 2);
}

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

typedef struct Packed {
  GLenum type;
  int bytes, components;
} Packed;

static int ten_bits(GLenum t) { return t == GL_UNSIGNED_INT_10_10_10_2 || t == GL_UNSIGNED_INT_2_10_10_10_REV; }

static const Packed kPacked[] = {
    {GL_UNSIGNED_BYTE_3_3_2, 1, 3},        {GL_UNSIGNED_BYTE_2_3_3_REV, 1, 3},
    {GL_UNSIGNED_SHORT_5_6_5, 2, 3},       {GL_UNSIGNED_SHORT_5_6_5_REV, 2, 3},
    {GL_UNSIGNED_SHORT_4_4_4_4, 2, 4},     {GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, 4},
    {GL_UNSIGNED_SHORT_5_5_5_1, 2, 4},     {GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, 4},
    {GL_UNSIGNED_INT_8_8_8_8, 4, 4},       {GL_UNSIGNED_INT_8_8_8_8_REV, 4, 4},
    {GL_UNSIGNED_INT_10_10_10_2, 4, 4},    {GL_UNSIGNED_INT_2_10_10_10_REV, 4, 4},
};

static const GLenum kAllFormats[] = {GL_RGB, GL_BGR, GL_RGBA, GL_BGRA, GL_RED, GL_ALPHA, GL_LUMINANCE,
                                     GL_LUMINANCE_ALPHA, GL_COLOR_INDEX, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX};

/* The framebuffer: every byte value in each channel. */
static void fill(void) {
  static unsigned char rgba[kW * kH * 4];
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      unsigned char* p = rgba + (y * kW + x) * 4;
      int i = y * kW + x;
      p[0] = (unsigned char)(i * 5), p[1] = (unsigned char)(i * 3 + 7), p[2] = (unsigned char)(255 - i);
      p[3] = (unsigned char)(i * 11 + x);
    }
  }
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glRasterPos2i(0, 0);
  glDrawPixels(kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

typedef struct Store {
  int alignment, row_length, skip_pixels, skip_rows, swap;
} Store;

static const Store kStores[] = {
    {4, 0, 0, 0, 0}, {1, 0, 0, 0, 1}, {8, 0, 0, 0, 0}, {2, 37, 3, 2, 0}, {4, 35, 1, 1, 1},
};
/* Unpacking: byte swapping only of images without a row length or skips (Mesa's unpacking
 * with both leaves the last column and row black). */
static const Store kUnpackStores[] = {
    {4, 0, 0, 0, 0}, {1, 0, 0, 0, 1}, {8, 0, 0, 0, 0}, {2, 37, 3, 2, 0}, {2, 0, 0, 0, 1},
};

static void set_pack(const Store* s) {
  glPixelStorei(GL_PACK_ALIGNMENT, s->alignment);
  glPixelStorei(GL_PACK_ROW_LENGTH, s->row_length);
  glPixelStorei(GL_PACK_SKIP_PIXELS, s->skip_pixels);
  glPixelStorei(GL_PACK_SKIP_ROWS, s->skip_rows);
  glPixelStorei(GL_PACK_SWAP_BYTES, s->swap);
}

static void set_unpack(const Store* s) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, s->alignment);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, s->row_length);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, s->skip_pixels);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, s->skip_rows);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, s->swap);
}

/* Bytes an image of w x h spans under the store (rows padded), past its skips. */
static long extent(const Store* s, int w, int h, int bytes) {
  long l = s->row_length ? s->row_length : w;
  long stride = bytes >= s->alignment ? l * bytes : (l * bytes + s->alignment - 1) / s->alignment * s->alignment;
  return stride * (s->skip_rows + h) + (long)(s->skip_pixels + 1) * bytes;
}

/* The formats a packed type packs. */
static int formats_of(const Packed* p, GLenum formats[2]) {
  if (p->components == 3) {
    formats[0] = GL_RGB;
    return 1;
  }
  formats[0] = GL_RGBA, formats[1] = GL_BGRA;
  return 2;
}

static void errors(void) {
  static unsigned char scratch[4096];
  static unsigned char image[8 * 8 * 4];
  memset(image, 0x5a, sizeof image);
  const Store plain = {4, 0, 0, 0, 0};
  set_pack(&plain);
  set_unpack(&plain);
  for (int t = 0; t < COUNT(kPacked); ++t) {
    for (int f = 0; f < COUNT(kAllFormats); ++f) {
      const GLenum type = kPacked[t].type, format = kAllFormats[f];
      glReadPixels(0, 0, 4, 4, format, type, scratch);
      emit_error();
      glRasterPos2i(10, 10);
      glDrawPixels(2, 2, format, type, image);
      emit_error();
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, format, type, image);
      emit_error();
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
      glGetTexImage(GL_TEXTURE_2D, 0, format, type, scratch);
      emit_error();
    }
  }
  fill(); /* the error cases' glDrawPixels drew nothing, but keep the framebuffer known */
}

static void reads(int transfer) {
  static unsigned char scratch[kScratch];
  int k = transfer;
  if (transfer) {
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_GREEN_BIAS, 0.25f);
    glPixelTransferf(GL_BLUE_SCALE, 0.75f);
  }
  for (int t = 0; t < COUNT(kPacked); ++t) {
    GLenum formats[2];
    const int nf = formats_of(&kPacked[t], formats);
    for (int f = 0; f < nf; ++f) {
      for (int s = 0; s < COUNT(kStores); ++s, ++k) {
        const Store* st = &kStores[(s + k) % COUNT(kStores)];
        const int w = s == 0 ? kW : 13 + s, h = s == 0 ? kH : 5 + s, x = s == 0 ? 0 : 3 * s, y = s == 0 ? 0 : s;
        long n = extent(st, w, h, kPacked[t].bytes);
        if (n > kScratch) n = kScratch;
        memset(scratch, 0xcd, sizeof scratch);
        set_pack(st);
        trace(transfer ? "read transferred" : "read", formats[f], kPacked[t].type, s);
        glReadPixels(x, y, w, h, formats[f], kPacked[t].type, scratch);
        emit_error();
        emit(scratch, n);
      }
    }
  }
  if (transfer) {
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_GREEN_BIAS, 0.0f);
    glPixelTransferf(GL_BLUE_SCALE, 1.0f);
  }
}

/* A packed image of w x h whose elements run through many bit patterns. */
static void pattern(unsigned char* p, long n, int seed) {
  unsigned v = 0x9e3779b9u * (unsigned)(seed + 1);
  for (long i = 0; i < n; ++i) {
    v = v * 1664525u + 1013904223u;
    p[i] = (unsigned char)(v >> 24);
  }
}

static void draws(void) {
  static unsigned char image[kScratch], back[16 * 12 * 4];
  const Store plain = {4, 0, 0, 0, 0};
  int k = 0;
  for (int t = 0; t < COUNT(kPacked); ++t) {
    GLenum formats[2];
    const int nf = formats_of(&kPacked[t], formats);
    for (int f = 0; f < nf; ++f, ++k) {
      const Store* st = &kUnpackStores[k % COUNT(kUnpackStores)];
      pattern(image, sizeof image, k);
      set_unpack(st);
      trace("draw", formats[f], kPacked[t].type, k);
      glRasterPos2i(2, 3);
      glDrawPixels(16, 12, formats[f], kPacked[t].type, image);
      emit_error();
      set_pack(&plain);
      glReadPixels(2, 3, 16, 12, GL_RGBA, GL_UNSIGNED_BYTE, back);
      emit(back, sizeof back);
    }
  }
  set_unpack(&plain);
  fill();
}

static void textures(void) {
  static unsigned char image[kScratch], back[kScratch];
  const Store plain = {4, 0, 0, 0, 0};
  static const GLint kInternal[] = {GL_RGBA, GL_RGB, GL_RGBA8};
  int k = 0;
  for (int t = 0; t < COUNT(kPacked); ++t) {
    GLenum formats[2];
    const int nf = formats_of(&kPacked[t], formats);
    for (int f = 0; f < nf; ++f, ++k) {
      const GLint internal = kInternal[k % COUNT(kInternal)];
      pattern(image, sizeof image, 100 + k);
      set_unpack(&kUnpackStores[k % COUNT(kUnpackStores)]);
      trace("texture", formats[f], kPacked[t].type, k);
      glTexImage2D(GL_TEXTURE_2D, 0, internal, 8, 4, 0, formats[f], kPacked[t].type, image);
      emit_error();
      set_pack(&plain);
      memset(back, 0xcd, 8 * 4 * 4);
      glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
      emit_error();
      emit(back, 8 * 4 * 4);
      /* the texture read back into every packed type and format */
      for (int u = 0; u < COUNT(kPacked); ++u) {
        if (ten_bits(kPacked[u].type)) continue;
        GLenum uf[2];
        const int nuf = formats_of(&kPacked[u], uf);
        for (int g = 0; g < nuf; ++g) {
          const Store* st = &kStores[(k + u + g) % COUNT(kStores)];
          long n = extent(st, 8, 4, kPacked[u].bytes);
          memset(back, 0xcd, (size_t)n);
          set_pack(st);
          trace("texture read", uf[g], kPacked[u].type, k);
          glGetTexImage(GL_TEXTURE_2D, 0, uf[g], kPacked[u].type, back);
          emit_error();
          emit(back, n);
        }
      }
    }
  }
  set_unpack(&plain);
  set_pack(&plain);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, kW, kH)) return 1;
  out = (unsigned char*)calloc(kOutMax, 1);
  if (!out) return 1;
  fill();
  errors();
  reads(0);
  reads(1);
  draws();
  textures();
  int rc = 0;
  if (!conf_write_bytes_png(c.out_path, out, out_n, 256)) rc = 2;
  fprintf(stderr, "%ld bytes read back\n", out_n);
  OSMesaDestroyContext(c.ctx);
  free(c.buffer);
  free(out);
  return rc;
}
