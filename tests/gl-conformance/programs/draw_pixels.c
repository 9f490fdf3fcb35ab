/* glDrawPixels (GL 1.1 section 3.6.4): images of every colour format (RGBA, RGB, BGRA, BGR, RED,
 * GREEN, BLUE, ALPHA, LUMINANCE, LUMINANCE_ALPHA) in every type (UNSIGNED_BYTE, BYTE,
 * UNSIGNED_SHORT, SHORT, UNSIGNED_INT, INT, FLOAT); zoomed by glPixelZoom (enlarged, reduced,
 * fractional, negative in x, y or both); unpacked with row length, skips, alignments and byte
 * swapping; through scale and bias and the R and G colour maps; colour indices (GL_BITMAP)
 * through the I_TO_* maps; depth images (the raster colour, tested against geometry after);
 * stencil images (shown through the stencil test, with a write mask); blending, the depth
 * test, texturing at the raster texture coordinates, the colour mask; and the error codes of
 * wrong calls (a strip of pixels at the top).
 *
 * Left out, where Mesa departs from the specification: depth scale and bias and the index
 * transfer operations on depth and stencil images (Mesa ignores them), the B and A colour maps
 * (Mesa's give other values: a colour mask keeps B and A while maps apply) and colour maps of
 * sizes other than 2 and 256 (Mesa rounds the indices down), colour indices of types other than GL_BITMAP (Mesa draws
 * them black), fog (Mesa takes fog coordinate 0, not the raster distance), zooms that put pixel
 * centres exactly on the boundary of two zoomed pixels (llvmpipe's interpolation picks either). */
#include <math.h>
#include <string.h>

#include "conf.h"

enum { kW = 320, kH = 256 };

static void pos(float x, float y) { glRasterPos2f(x, y); }

static int type_size(GLenum t) {
  if (t == GL_UNSIGNED_BYTE || t == GL_BYTE) return 1;
  if (t == GL_UNSIGNED_SHORT || t == GL_SHORT) return 2;
  return 4;
}

static int components(GLenum f) {
  switch (f) {
    case GL_RGBA: case GL_BGRA: return 4;
    case GL_RGB: case GL_BGR: return 3;
    case GL_LUMINANCE_ALPHA: return 2;
    default: return 1;
  }
}

/* A value in [-0.2, 1] as an element of `type` (table 2.6's inverse), rounded. */
static void put(unsigned char* p, GLenum type, double v) {
  switch (type) {
    case GL_UNSIGNED_BYTE: { GLubyte x = (GLubyte)lround(fmax(v, 0) * 255); memcpy(p, &x, 1); break; }
    case GL_BYTE: { GLbyte x = (GLbyte)lround(v * 127); memcpy(p, &x, 1); break; }
    case GL_UNSIGNED_SHORT: { GLushort x = (GLushort)lround(fmax(v, 0) * 65535); memcpy(p, &x, 2); break; }
    case GL_SHORT: { GLshort x = (GLshort)lround(v * 32767); memcpy(p, &x, 2); break; }
    case GL_UNSIGNED_INT: { GLuint x = (GLuint)llround(fmax(v, 0) * 4294967295.0); memcpy(p, &x, 4); break; }
    case GL_INT: { GLint x = (GLint)llround(v * 2147483647.0); memcpy(p, &x, 4); break; }
    default: { GLfloat x = (GLfloat)v; memcpy(p, &x, 4); break; }
  }
}

/* An image of w x h pixels with rows padded to `align`: component k of pixel (x, y) a gradient. */
static void make_image(unsigned char* out, int w, int h, GLenum format, GLenum type, int align) {
  int n = components(format), s = type_size(type);
  int stride = (w * n * s + align - 1) / align * align;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int k = 0; k < n; ++k) {
        double v = fmod(0.13 * x + 0.21 * y + 0.37 * k + 0.05, 1.2) - 0.1;
        put(out + y * stride + (x * n + k) * s, type, v);
      }
    }
  }
}

static const GLenum kFormats[] = {GL_RGBA, GL_RGB, GL_BGRA, GL_BGR, GL_RED, GL_GREEN, GL_BLUE,
                                  GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA};
static const GLenum kTypes[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                GL_UNSIGNED_INT, GL_INT, GL_FLOAT};

/* Every format x type, 9 x 7 pixels each, in the lower left. */
static void formats(void) {
  static unsigned char img[9 * 7 * 4 * 4];
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (int f = 0; f < 10; ++f) {
    for (int t = 0; t < 7; ++t) {
      make_image(img, 9, 7, kFormats[f], kTypes[t], 4);
      pos(2.0f + 11.0f * t, 2.0f + 9.0f * f);
      glDrawPixels(9, 7, kFormats[f], kTypes[t], img);
    }
  }
}

/* A 10 x 8 RGB image at several zooms. */
static void zooms(void) {
  static unsigned char img[10 * 8 * 3];
  make_image(img, 10, 8, GL_RGB, GL_UNSIGNED_BYTE, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  /* Multiples of 1/5: no pixel centre falls on the boundary of two zoomed pixels. */
  const float z[][2] = {{1, 1}, {2, 2}, {2.4f, 1.6f}, {0.6f, 0.8f}, {-1, 1}, {-2, -1.4f},
                        {1, -2}, {0.4f, 3}, {3, -0.6f}, {1.8f, 1.2f}};
  const float at[][2] = {{90, 4}, {104, 4}, {128, 4}, {156, 4}, {180, 4}, {206, 36},
                         {214, 20}, {226, 4}, {232, 30}, {270, 4.5f}};
  for (int i = 0; i < 10; ++i) {
    glPixelZoom(z[i][0], z[i][1]);
    pos(at[i][0] + 0.5f * (i % 3), at[i][1] + 0.25f * (i % 2));
    glDrawPixels(10, 8, GL_RGB, GL_UNSIGNED_BYTE, img);
  }
  glPixelZoom(1, 1);
}

/* Row length, skips, alignment and byte swapping, from one 16 x 12 RGB image. */
static void unpacking(void) {
  static unsigned char rgb[16 * 12 * 3 + 64], swapped[16 * 12 * 3 * 2];
  make_image(rgb, 16, 12, GL_RGB, GL_UNSIGNED_BYTE, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 16);
  for (int i = 0; i < 4; ++i) {
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, i * 3);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, i * 2);
    pos(90.0f + 12.0f * i, 60.0f);
    glDrawPixels(9, 7, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  /* The same bytes read with each alignment (15-byte rows padded to 15, 16, 16, 16). Each from
   * a buffer of its own: Mesa 22.3's glDrawPixels cache takes an image drawn before from the
   * same address and size as the same image, whatever the alignment. */
  static unsigned char copies[4][16 * 12 * 3 + 64];
  const int aligns[4] = {1, 2, 4, 8};
  for (int i = 0; i < 4; ++i) {
    memcpy(copies[i], rgb, sizeof copies[i]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, aligns[i]);
    pos(140.0f + 12.0f * i, 60.0f);
    glDrawPixels(5, 7, GL_RGB, GL_UNSIGNED_BYTE, copies[i]);
  }
  make_image(swapped, 7, 7, GL_RGB, GL_UNSIGNED_SHORT, 1);
  for (int i = 0; i < 7 * 7 * 3; ++i) { /* stored big-endian */
    unsigned char t = swapped[2 * i];
    swapped[2 * i] = swapped[2 * i + 1], swapped[2 * i + 1] = t;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  pos(190.0f, 60.0f);
  glDrawPixels(7, 7, GL_RGB, GL_UNSIGNED_SHORT, swapped);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

/* Scale and bias, the R and G maps, colour indices through the I_TO_* maps. */
static void transfer(void) {
  static unsigned char img[12 * 8 * 4];
  make_image(img, 12, 8, GL_RGBA, GL_UNSIGNED_BYTE, 4);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_BIAS, 0.3f);
  glPixelTransferf(GL_BLUE_SCALE, -1.0f);
  glPixelTransferf(GL_BLUE_BIAS, 1.0f);
  glPixelTransferf(GL_ALPHA_SCALE, 2.0f);
  pos(210.0f, 60.0f);
  glDrawPixels(12, 8, GL_RGBA, GL_UNSIGNED_BYTE, img);
  pos(224.0f, 60.0f);
  glDrawPixels(12, 8, GL_LUMINANCE, GL_UNSIGNED_BYTE, img);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glPixelTransferf(GL_GREEN_BIAS, 0.0f);
  glPixelTransferf(GL_BLUE_SCALE, 1.0f);
  glPixelTransferf(GL_BLUE_BIAS, 0.0f);
  glPixelTransferf(GL_ALPHA_SCALE, 1.0f);
  GLfloat r[256], g2[2] = {0.15f, 0.9f}, b1[1] = {0.4f}, a1[1] = {0.8f};
  for (int i = 0; i < 256; ++i) r[i] = (float)((i * 7) % 256) / 255.0f;
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 256, r);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, g2);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 1, b1);
  glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 1, a1);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_FALSE, GL_FALSE); /* Mesa's B and A maps: see above */
  pos(238.0f, 60.0f);
  glDrawPixels(12, 8, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 256, r);
  pos(252.0f, 60.0f);
  glDrawPixels(12, 8, GL_RGB, GL_UNSIGNED_BYTE, img);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  const GLfloat ir[2] = {0.9f, 0.1f}, ig[2] = {0.3f, 0.8f}, ib[4] = {0.5f, 0.2f, 0.7f, 1.0f}, ia[1] = {1.0f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, ir);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 2, ig);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 4, ib);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 1, ia);
  const GLubyte bits[8] = {0xf0, 0x0f, 0xaa, 0x55, 0xcc, 0x33, 0x81, 0x7e};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  pos(268.0f, 60.0f);
  glDrawPixels(8, 8, GL_COLOR_INDEX, GL_BITMAP, bits);
  glPixelZoom(2.0f, 1.0f);
  pos(280.0f, 60.0f);
  glDrawPixels(8, 8, GL_COLOR_INDEX, GL_BITMAP, bits);
  glPixelZoom(1.0f, 1.0f);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

static void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_TRIANGLES);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

/* Depth images (with the raster colour), then geometry tested against them; stencil images
 * shown through the stencil test. */
static void depth_stencil(void) {
  static GLfloat depth[24 * 16];
  static GLushort depth16[24 * 16];
  static GLubyte stencil[24 * 16];
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 24; ++x) {
      depth[y * 24 + x] = (float)x / 23.0f;
      depth16[y * 24 + x] = (GLushort)((y * 4096) & 0xffff);
      stencil[y * 24 + x] = (GLubyte)((x / 3) & 7);
    }
  }
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glColor3f(0.6f, 0.2f, 0.7f);
  pos(90.0f, 100.0f);
  glDrawPixels(24, 16, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  glPixelZoom(1.5f, -1.0f);
  glColor3f(0.1f, 0.5f, 0.3f);
  pos(120.0f, 116.0f);
  glDrawPixels(24, 16, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, depth16);
  glPixelZoom(1.0f, 1.0f);
  glDepthFunc(GL_LESS);
  glColor3f(1.0f, 0.9f, 0.2f);
  quad(86, 96, 160, 120, 0.0f); /* window depth 0.5: in front of the nearer half */
  glDisable(GL_DEPTH_TEST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  pos(170.0f, 100.0f);
  glDrawPixels(24, 16, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
  glPixelZoom(2.0f, 0.5f);
  glStencilMask(0x0e);
  pos(200.0f, 100.0f);
  glDrawPixels(24, 16, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
  glStencilMask(0xff);
  glPixelZoom(1.0f, 1.0f);
  glEnable(GL_STENCIL_TEST);
  for (int v = 0; v < 8; ++v) {
    glStencilFunc(GL_EQUAL, v, 0xff);
    glColor3f((float)(v & 1), (float)((v >> 1) & 1), 0.3f + 0.1f * v);
    quad(166, 96, 252, 120, 0.0f);
  }
  glDisable(GL_STENCIL_TEST);
}

/* Blending, the depth test, texturing, the colour mask. */
static void fragment_ops(void) {
  static unsigned char img[16 * 12 * 4];
  make_image(img, 16, 12, GL_RGBA, GL_UNSIGNED_BYTE, 4);
  glColor3f(0.2f, 0.4f, 0.9f);
  quad(88, 130, 300, 160, 0.2f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  pos(90.0f, 134.0f);
  glDrawPixels(16, 12, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glBlendFunc(GL_ONE, GL_ONE);
  pos(110.0f, 134.0f);
  glDrawPixels(16, 12, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, img);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glRasterPos3f(130.0f, 134.0f, 0.5f); /* behind the quad */
  glDrawPixels(16, 12, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glRasterPos3f(150.0f, 134.0f, -0.5f); /* in front */
  glDrawPixels(16, 12, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glDisable(GL_DEPTH_TEST);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  pos(170.0f, 134.0f);
  glDrawPixels(16, 12, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  GLubyte tex[4 * 4 * 4];
  for (int i = 0; i < 16; ++i) {
    tex[i * 4] = (GLubyte)(255 - i * 15), tex[i * 4 + 1] = (GLubyte)(i * 16), tex[i * 4 + 2] = 128;
    tex[i * 4 + 3] = (GLubyte)(255 - i * 8);
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  const GLenum env[3] = {GL_MODULATE, GL_REPLACE, GL_DECAL};
  for (int i = 0; i < 6; ++i) {
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env[i % 3]);
    glTexCoord2f(0.1f + 0.3f * (i % 3), 0.2f + 0.4f * (i / 3));
    pos(190.0f + 18.0f * i, 134.0f);
    glDrawPixels(16, 12, GL_RGBA, GL_UNSIGNED_BYTE, img);
  }
  glDisable(GL_TEXTURE_2D);
}

/* GL_INVALID_ENUM .. GL_OUT_OF_MEMORY as 1 .. 6, no error as 0. */
static GLubyte error_code(void) {
  GLenum e = glGetError();
  return (GLubyte)(e == GL_NO_ERROR ? 0 : e - GL_INVALID_ENUM + 1);
}

/* Error codes as a strip of pixels; a missing raster position draws nothing. */
static void errors(void) {
  static unsigned char img[4 * 4 * 4];
  GLubyte codes[12 * 4];
  int n = 0;
  pos(10.0f, 200.0f);
  glDrawPixels(-1, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
  codes[n++] = error_code();
  glDrawPixels(1, 1, 0x1234, GL_UNSIGNED_BYTE, img);
  codes[n++] = error_code();
  glDrawPixels(1, 1, GL_RGBA, 0x1234, img);
  codes[n++] = error_code();
  glDrawPixels(1, 1, GL_RGBA, GL_BITMAP, img);
  codes[n++] = error_code();
  glDrawPixels(1, 1, GL_DEPTH_COMPONENT, GL_BITMAP, img);
  codes[n++] = error_code();
  glDrawPixels(-1, 1, 0x1234, GL_UNSIGNED_BYTE, img);
  codes[n++] = error_code();
  glDrawPixels(0, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  codes[n++] = error_code();
  glBegin(GL_TRIANGLES);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glEnd();
  codes[n++] = error_code();
  glRasterPos2i(-10, 200); /* invalid: nothing drawn */
  glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, img);
  codes[n++] = error_code();
  for (int i = 0; i < n; ++i) {
    codes[i] = (GLubyte)(codes[i] * 40);
  }
  GLubyte strip[9 * 4];
  for (int i = 0; i < n; ++i) strip[i * 4] = strip[i * 4 + 1] = strip[i * 4 + 2] = codes[i], strip[i * 4 + 3] = 255;
  glPixelZoom(4.0f, 4.0f);
  pos(4.0f, 240.0f);
  glDrawPixels(n, 1, GL_RGBA, GL_UNSIGNED_BYTE, strip);
  glPixelZoom(1.0f, 1.0f);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, kW, kH)) return 1;
  glClearColor(0.15f, 0.1f, 0.1f, 0.5f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  formats();
  zooms();
  unpacking();
  transfer();
  depth_stencil();
  fragment_ops();
  errors();
  return conf_finish(&c);
}
