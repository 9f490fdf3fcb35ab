/* EXT_packed_depth_stencil (core in OpenGL 3.0) on the window-system framebuffer and in
 * textures: glDrawPixels of GL_DEPTH_STENCIL / GL_UNSIGNED_INT_24_8 images (zoomed, scissored,
 * through the stencil write mask and the depth mask), glCopyPixels of GL_DEPTH_STENCIL,
 * glReadPixels of both with and without the depth scale and bias and the stencil offset and
 * shift; GL_DEPTH24_STENCIL8 textures from client images, from glTexSubImage2D of depth alone
 * and from the framebuffer, drawn as luminance and compared against r. Each buffer is shown
 * by drawing over it: colour bands where the stencil test passes, and quads at fixed depths
 * where the depth test passes. Values: the pixels read back, the texture's levels and texels,
 * GL_EXTENSIONS, and the errors of the wrong pairs of format and type. */
#include <stdio.h>
#include <string.h>

#include "conf.h"

#ifndef GL_DEPTH_STENCIL_EXT
#define GL_DEPTH_STENCIL_EXT 0x84F9
#define GL_UNSIGNED_INT_24_8_EXT 0x84FA
#define GL_DEPTH24_STENCIL8_EXT 0x88F0
#define GL_TEXTURE_STENCIL_SIZE_EXT 0x88F1
#endif

enum { kSize = 16 };

static GLuint image[kSize * kSize];

/* Depth rises along x, stencil counts along y in steps of 16 (0x00, 0x10, ... 0xf0). */
static void make_image(void) {
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const GLuint depth = (GLuint)(x * 0xffffff / (kSize - 1));
      image[y * kSize + x] = depth << 8 | (GLuint)(y * 16);
    }
  }
}

static void rect(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z), glVertex3f(x1, y0, z), glVertex3f(x1, y1, z), glVertex3f(x0, y1, z);
  glEnd();
}

/* Shows the cell's stencil as bands (stencil >= each threshold: brighter) and its depth as
 * quads at depths 0.25, 0.5, 0.75 that pass GL_LESS where the depth buffer holds more. */
static void reveal(void) {
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  for (int k = 1; k < 8; ++k) {
    glStencilFunc(GL_LEQUAL, (GLint)(k * 32), 0xff);
    glColor3f(0.12f * (float)k, 0.0f, 0.0f);
    rect(0, 0, 64, 64, 0.0f);
  }
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  for (int k = 1; k <= 3; ++k) {
    /* glOrtho's z in [-1, 1] maps -z to window depth (1 - z) / 2... here depth d at z = 1 - 2d. */
    const float d = 0.25f * (float)k;
    glColor4f(0.0f, 0.3f * (float)k, 0.0f, 1.0f);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    rect(0, 0, 64, 64, 1.0f - 2.0f * d);
    glDisable(GL_BLEND);
  }
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
}

/* A textured square from (lo, lo) to (hi, hi), texel edges between pixel centres when the
 * texture's size divides hi - lo. */
static void textured_quad(float lo, float hi) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0), glVertex2f(lo, lo);
  glTexCoord2f(1, 0), glVertex2f(hi, lo);
  glTexCoord2f(1, 1), glVertex2f(hi, hi);
  glTexCoord2f(0, 1), glVertex2f(lo, hi);
  glEnd();
}

static void clear_cell(void) {
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

/* A GL_UNSIGNED_INT_24_8 pixel as two values (the 24 depth bits, the 8 stencil bits): %.9g
 * would round the whole 32-bit number. */
static void packed_values(ConfContext* c, const char* what, const GLuint* px, int n) {
  double v[16];
  for (int i = 0; i < n; ++i) v[2 * i] = (double)(px[i] >> 8), v[2 * i + 1] = (double)(px[i] & 0xffu);
  conf_values(c, what, v, 2 * n);
}

static void read_back(ConfContext* c, const char* what, int x, int y) {
  GLuint px[4];
  memset(px, 0, sizeof px);
  glReadPixels(x, y, 4, 1, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, px);
  char key[96];
  snprintf(key, sizeof key, "%s depth-stencil", what);
  packed_values(c, key, px, 4);
  GLuint depth[4];
  GLubyte stencil[4];
  glReadPixels(x, y, 4, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
  glReadPixels(x, y, 4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
  for (int i = 0; i < 4; ++i) px[i] = (depth[i] >> 8) << 8 | stencil[i];
  snprintf(key, sizeof key, "%s depth and stencil apart", what);
  packed_values(c, key, px, 4);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  make_image();
  const char* extensions = (const char*)glGetString(GL_EXTENSIONS);
  conf_value(&c, "GL_EXT_packed_depth_stencil listed", strstr(extensions, "GL_EXT_packed_depth_stencil ") != NULL);
  glEnable(GL_SCISSOR_TEST);

  /* Cell (0, 0): the image drawn at (8, 8), then revealed. */
  conf_pixel_panel(&c, 0, 0, 4, 4);
  glScissor(0, 192, 64, 64);
  clear_cell();
  glRasterPos2i(8, 8);
  glDrawPixels(kSize, kSize, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, image);
  conf_error(&c, "DrawPixels depth-stencil");
  read_back(&c, "drawn", 10, 192 + 12);
  reveal();

  /* Cell (1, 0): zoomed 3 x 2, under a scissor box, with stencil write mask 0xe0; the depth
   * test on (the image's depths go in whatever the depth test says, as Mesa writes them). */
  conf_pixel_panel(&c, 1, 0, 4, 4);
  glScissor(64, 192, 64, 64);
  clear_cell();
  glScissor(64, 192, 40, 50);
  glStencilMask(0xe0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  glPixelZoom(3.0f, 2.0f);
  glRasterPos2i(4, 4);
  glDrawPixels(kSize, kSize, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, image);
  glPixelZoom(1.0f, 1.0f);
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
  glStencilMask(0xff);
  glScissor(64, 192, 64, 64);
  read_back(&c, "zoomed masked", 64 + 20, 192 + 20);
  reveal();

  /* Cell (2, 0): the depth mask off: stencil written, depth kept. */
  conf_pixel_panel(&c, 2, 0, 4, 4);
  glScissor(128, 192, 64, 64);
  clear_cell();
  glDepthMask(GL_FALSE);
  glRasterPos2i(20, 20);
  glDrawPixels(kSize, kSize, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, image);
  glDepthMask(GL_TRUE);
  read_back(&c, "depth mask off", 128 + 22, 192 + 30);
  reveal();

  /* Cell (3, 0): read back through the depth scale and bias and the stencil shift and offset.
   * (Drawn through them, the image would differ: Mesa's glDrawPixels of GL_DEPTH_STENCIL
   * leaves the transfer operations out, where shadelab applies them as GL asks.) */
  conf_pixel_panel(&c, 3, 0, 4, 4);
  glScissor(192, 192, 64, 64);
  clear_cell();
  glRasterPos2i(30, 6);
  glDrawPixels(kSize, kSize, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, image);
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
  glPixelTransferi(GL_INDEX_SHIFT, -1);
  glPixelTransferi(GL_INDEX_OFFSET, 3);
  read_back(&c, "transfer out", 192 + 32, 192 + 12);
  glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  reveal();

  /* Cell (0, 1): glCopyPixels of depth and stencil from cell (0, 0), flipped by zoom -1. */
  conf_pixel_panel(&c, 0, 1, 4, 4);
  glScissor(0, 128, 64, 64);
  clear_cell();
  glRasterPos2i(8, 40);
  glPixelZoom(1.0f, -1.0f);
  glCopyPixels(0, 192, 40, 32, GL_DEPTH_STENCIL_EXT);
  conf_error(&c, "CopyPixels depth-stencil");
  glPixelZoom(1.0f, 1.0f);
  read_back(&c, "copied", 14, 128 + 20);
  reveal();

  /* Cell (1, 1): a copy with stencil write mask 0x30 over a stencil of 0x0f. */
  conf_pixel_panel(&c, 1, 1, 4, 4);
  glScissor(64, 128, 64, 64);
  glClearStencil(0x0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glClearStencil(0);
  glStencilMask(0x30);
  glRasterPos2i(4, 4);
  glCopyPixels(0, 192, 64, 64, GL_DEPTH_STENCIL_EXT);
  glStencilMask(0xff);
  read_back(&c, "copied masked", 64 + 12, 128 + 16);
  reveal();

  /* Textures: a GL_DEPTH24_STENCIL8 image from the client, drawn as luminance. */
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8_EXT, kSize, kSize, 0, GL_DEPTH_STENCIL_EXT,
               GL_UNSIGNED_INT_24_8_EXT, image);
  conf_error(&c, "TexImage2D depth-stencil");
  static const GLenum pnames[] = {GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_STENCIL_SIZE_EXT,
                                  GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_RED_SIZE, GL_TEXTURE_ALPHA_SIZE};
  double v[6];
  for (int i = 0; i < 6; ++i) {
    GLint n = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, pnames[i], &n);
    v[i] = n;
  }
  conf_values(&c, "level format depth stencil luminance red alpha", v, 6);
  /* Depth alone into part of it: the stencil indices there stay. */
  static float ramp[4 * 4];
  for (int i = 0; i < 16; ++i) ramp[i] = 0.0625f * (float)i;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 4, 4, GL_DEPTH_COMPONENT, GL_FLOAT, ramp);
  conf_error(&c, "TexSubImage2D depth into depth-stencil");
  static GLuint texels[32 * 32];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, texels);
  conf_error(&c, "GetTexImage depth-stencil");
  /* The stencil indices under the depth-only image are left undefined (Mesa's are not the
   * ones before): the texels around it whole, its own depths alone. */
  GLuint picked[6];
  for (int i = 0; i < 6; ++i) picked[i] = texels[(3 + i) * kSize + 3 + i];
  packed_values(&c, "texels beside the sub-image", picked, 1);
  packed_values(&c, "texels beside the sub-image, far", picked + 5, 1);
  for (int i = 1; i < 5; ++i) v[i - 1] = (double)(picked[i] >> 8);
  conf_values(&c, "depths of the sub-image's diagonal", v, 4);
  static float depths[kSize * kSize];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  conf_error(&c, "GetTexImage depth of depth-stencil");
  for (int i = 0; i < 6; ++i) v[i] = depths[5 * kSize + 2 + i];
  conf_values(&c, "depths of row 5", v, 6);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  conf_pixel_panel(&c, 2, 1, 4, 4);
  glScissor(128, 128, 64, 64);
  glClear(GL_COLOR_BUFFER_BIT);
  textured_quad(8, 56);

  /* Compared against r: r rises along the quad's x (GL_LEQUAL: lit where r <= depth). */
  conf_pixel_panel(&c, 3, 1, 4, 4);
  glScissor(192, 128, 64, 64);
  glClear(GL_COLOR_BUFFER_BIT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glBegin(GL_QUADS);
  glTexCoord3f(0, 0, 0.6f), glVertex2f(8, 8);
  glTexCoord3f(1, 0, 0.6f), glVertex2f(56, 8);
  glTexCoord3f(1, 1, 0.3f), glVertex2f(56, 56);
  glTexCoord3f(0, 1, 0.3f), glVertex2f(8, 56);
  glEnd();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);

  /* From the framebuffer: cell (0, 0)'s depth and stencil copied into a depth-stencil level. */
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8_EXT, 4, 196, 32, 32, 0);
  conf_error(&c, "CopyTexImage2D depth-stencil");
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, texels);
  for (int i = 0; i < 6; ++i) picked[i] = texels[(6 + 2 * i) * 32 + 5 + 3 * i];
  packed_values(&c, "copied texels", picked, 6);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 68, 196, 16, 16);
  conf_error(&c, "CopyTexSubImage2D depth-stencil");
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, texels);
  for (int i = 0; i < 6; ++i) picked[i] = texels[(1 + 2 * i) * 32 + 2 + 2 * i];
  packed_values(&c, "sub-copied texels", picked, 6);
  conf_pixel_panel(&c, 0, 2, 4, 4);
  glScissor(0, 64, 64, 64);
  glClear(GL_COLOR_BUFFER_BIT);
  textured_quad(0, 64);
  glDisable(GL_TEXTURE_2D);

  /* Errors of the wrong pairs. */
  GLuint one = 0;
  glDrawPixels(1, 1, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT, &one);
  conf_error(&c, "DrawPixels depth-stencil as unsigned int");
  glDrawPixels(1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8_EXT, &one);
  conf_error(&c, "DrawPixels depth as 24_8");
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT_24_8_EXT, &one);
  conf_error(&c, "ReadPixels RGBA as 24_8");
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL_EXT, GL_FLOAT, &one);
  conf_error(&c, "ReadPixels depth-stencil as float");
  glCopyPixels(0, 0, 1, 1, GL_DEPTH_STENCIL_EXT + 1);
  conf_error(&c, "CopyPixels of 24_8");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, &one);
  conf_error(&c, "TexImage2D RGBA from depth-stencil");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8_EXT, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, &one);
  conf_error(&c, "TexImage2D depth-stencil from RGBA");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, &one);
  conf_error(&c, "TexImage2D depth from depth-stencil");
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, texels);
  conf_error(&c, "GetTexImage depth-stencil of a depth texture");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL_EXT, 2, 2, 0, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, image);
  conf_error(&c, "TexImage2D unsized depth-stencil");
  GLint n = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE_EXT, &n);
  conf_value(&c, "unsized stencil size", n);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_DEPTH24_STENCIL8_EXT, 1, 1, 1, 0, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT,
               &one);
  conf_error(&c, "TexImage3D depth-stencil");
  glDisable(GL_SCISSOR_TEST);
  return conf_finish(&c);
}
