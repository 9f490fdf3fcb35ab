/* ARB_texture_rectangle (core in OpenGL 3.1): one-level 2D textures of any size addressed by
 * texel coordinates (s in [0, width], t in [0, height]). Drawn: a 24 x 10 image through
 * nearest and linear filters, past its edges with GL_CLAMP, GL_CLAMP_TO_EDGE and
 * GL_CLAMP_TO_BORDER, through a texture matrix, in glDrawPixels and glBitmap (raster texture
 * coordinates in texels; glBitmap's at texel (0, 0) only, as Mesa samples it there whatever the
 * coordinates), modulating a 2D texture from unit 1, defined by glTexSubImage2D,
 * glCopyTexImage2D and glCopyTexSubImage2D and in a display list, the target precedence (cube
 * map over rectangle over 2D; an incomplete rectangle gives way). Values: the parameters'
 * defaults, bindings, proxies, feedback's texture coordinates, glGetTexImage, and the errors of
 * levels, borders, repeat wraps and mipmap filters. */
#include <stdio.h>
#include <string.h>

#include "conf.h"

#ifndef GL_TEXTURE_RECTANGLE_ARB
#define GL_TEXTURE_RECTANGLE_ARB 0x84F5
#define GL_TEXTURE_BINDING_RECTANGLE_ARB 0x84F6
#define GL_PROXY_TEXTURE_RECTANGLE_ARB 0x84F7
#define GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB 0x84F8
#endif

enum { kW = 24, kH = 10 };
static unsigned char image[kW * kH * 4];

static void make_image(void) {
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      unsigned char* p = &image[(y * kW + x) * 4];
      p[0] = (unsigned char)(x * 10);
      p[1] = (unsigned char)(y * 25);
      p[2] = (unsigned char)(((x / 3 + y / 2) & 1) ? 230 : 40);
      p[3] = 255;
    }
  }
}

/* A quad from (x0, y0) to (x1, y1) with texture coordinates (s0, t0) to (s1, t1). */
static void quad(float x0, float y0, float x1, float y1, float s0, float t0, float s1, float t1) {
  glBegin(GL_QUADS);
  glTexCoord2f(s0, t0), glVertex2f(x0, y0);
  glTexCoord2f(s1, t0), glVertex2f(x1, y0);
  glTexCoord2f(s1, t1), glVertex2f(x1, y1);
  glTexCoord2f(s0, t1), glVertex2f(x0, y1);
  glEnd();
}

static void filter(GLenum f) {
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, (GLint)f);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAG_FILTER, (GLint)f);
}

static void wrap(GLenum w) {
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, (GLint)w);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_T, (GLint)w);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0.15f, 0.1f, 0.3f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  make_image();
  const char* extensions = (const char*)glGetString(GL_EXTENSIONS);
  conf_value(&c, "GL_ARB_texture_rectangle listed", strstr(extensions, "GL_ARB_texture_rectangle ") != NULL);
  conf_value(&c, "GL_NV_texture_rectangle listed", strstr(extensions, "GL_NV_texture_rectangle ") != NULL);
  GLint n = -1;
  glGetIntegerv(GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB, &n);
  conf_value(&c, "max rectangle size", n);

  GLuint tex[4];
  glGenTextures(4, tex);
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[0]);
  static const GLenum params[] = {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R, GL_TEXTURE_MIN_FILTER,
                                  GL_TEXTURE_MAG_FILTER, GL_TEXTURE_BASE_LEVEL};
  double v[8];
  for (int i = 0; i < 6; ++i) {
    GLint p = -1;
    glGetTexParameteriv(GL_TEXTURE_RECTANGLE_ARB, params[i], &p);
    v[i] = p;
  }
  conf_values(&c, "defaults wrap s t r min mag base", v, 6);
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, kW, kH, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
  conf_error(&c, "TexImage2D rectangle");
  glGetIntegerv(GL_TEXTURE_BINDING_RECTANGLE_ARB, &n);
  conf_value(&c, "binding", n == (GLint)tex[0]);
  glGetTexLevelParameteriv(GL_TEXTURE_RECTANGLE_ARB, 0, GL_TEXTURE_WIDTH, &n);
  conf_value(&c, "level 0 width", n);
  glGetTexLevelParameteriv(GL_TEXTURE_RECTANGLE_ARB, 0, GL_TEXTURE_HEIGHT, &n);
  conf_value(&c, "level 0 height", n);
  glEnable(GL_TEXTURE_RECTANGLE_ARB);
  conf_value(&c, "enabled", glIsEnabled(GL_TEXTURE_RECTANGLE_ARB));
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  /* Row 0: nearest (texels 2 x 4 pixels: edges between pixel centres), linear magnified 2.5x,
   * linear at one texel a pixel, a part of the image stretched. */
  conf_pixel_panel(&c, 0, 0, 4, 4);
  filter(GL_NEAREST);
  quad(8, 8, 56, 48, 0, 0, kW, kH);
  conf_pixel_panel(&c, 1, 0, 4, 4);
  filter(GL_LINEAR);
  quad(2, 2, 62, 27, 0, 0, kW, kH);
  quad(20, 40, 20 + kW, 40 + kH, 0, 0, kW, kH);
  conf_pixel_panel(&c, 2, 0, 4, 4);
  quad(4, 4, 60, 60, 5.5f, 2.25f, 17.5f, 8.75f);
  /* Past the edges: s from -6 to 30, t from -4 to 14. */
  conf_pixel_panel(&c, 3, 0, 4, 4);
  filter(GL_NEAREST);
  wrap(GL_CLAMP_TO_EDGE);
  quad(2, 2, 38, 20, -6, -4, 30, 14);
  filter(GL_LINEAR);
  wrap(GL_CLAMP);
  quad(2, 22, 38, 40, -6, -4, 30, 14);
  static const float border[4] = {1.0f, 0.8f, 0.0f, 1.0f};
  glTexParameterfv(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_BORDER_COLOR, border);
  wrap(GL_CLAMP_TO_BORDER);
  quad(2, 42, 38, 60, -6, -4, 30, 14);
  wrap(GL_CLAMP_TO_EDGE);

  /* Row 1: a texture matrix in texels (scaled and translated), modulation by the colour, a
   * rectangle on unit 1 modulating a 2D checker on unit 0. */
  conf_pixel_panel(&c, 0, 1, 4, 4);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(12, 5, 0);
  glScalef(0.5f, 0.5f, 1);
  glMatrixMode(GL_MODELVIEW);
  quad(4, 4, 60, 60, -20, -10, 20, 10);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  conf_pixel_panel(&c, 1, 1, 4, 4);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBegin(GL_QUADS);
  glColor3f(1, 1, 1), glTexCoord2f(0, 0), glVertex2f(4, 4);
  glColor3f(1, 0.2f, 0.2f), glTexCoord2f(kW, 0), glVertex2f(60, 4);
  glColor3f(0.2f, 1, 0.2f), glTexCoord2f(kW, kH), glVertex2f(60, 60);
  glColor3f(0.2f, 0.2f, 1), glTexCoord2f(0, kH), glVertex2f(4, 60);
  glEnd();
  glColor3f(1, 1, 1);
  glDisable(GL_TEXTURE_RECTANGLE_ARB);
  static unsigned char checker[8 * 8 * 4];
  for (int i = 0; i < 64; ++i) memset(&checker[i * 4], ((i / 8 + i % 8) & 1) ? 255 : 90, 4);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[0]);
  glEnable(GL_TEXTURE_RECTANGLE_ARB);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  conf_pixel_panel(&c, 2, 1, 4, 4);
  glBegin(GL_QUADS);
  glMultiTexCoord2f(GL_TEXTURE0, 0, 0), glMultiTexCoord2f(GL_TEXTURE1, 0, 0), glVertex2f(8, 8);
  glMultiTexCoord2f(GL_TEXTURE0, 1, 0), glMultiTexCoord2f(GL_TEXTURE1, kW, 0), glVertex2f(56, 8);
  glMultiTexCoord2f(GL_TEXTURE0, 1, 1), glMultiTexCoord2f(GL_TEXTURE1, kW, kH), glVertex2f(56, 56);
  glMultiTexCoord2f(GL_TEXTURE0, 0, 1), glMultiTexCoord2f(GL_TEXTURE1, 0, kH), glVertex2f(8, 56);
  glEnd();
  glDisable(GL_TEXTURE_RECTANGLE_ARB);
  glActiveTexture(GL_TEXTURE0);

  /* Precedence: with 2D and rectangle enabled the rectangle is drawn; an empty rectangle
   * texture gives way to 2D. */
  glEnable(GL_TEXTURE_RECTANGLE_ARB);
  conf_pixel_panel(&c, 3, 1, 4, 4);
  filter(GL_NEAREST);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0), glVertex2f(4, 4);
  glTexCoord2f(kW, 0), glVertex2f(28, 4);
  glTexCoord2f(kW, kH), glVertex2f(28, 28);
  glTexCoord2f(0, kH), glVertex2f(4, 28);
  glEnd();
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[2]); /* no image: incomplete */
  quad(34, 4, 58, 28, 0, 0, 1, 1);
  glDisable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[0]);

  /* Row 2: glDrawPixels and glBitmap textured at the raster position's coordinates (texels). */
  conf_pixel_panel(&c, 0, 2, 4, 4);
  glTexCoord2f(6, 3);
  glRasterPos2i(4, 4);
  static unsigned char gray[20 * 12 * 4];
  memset(gray, 200, sizeof gray);
  glDrawPixels(20, 12, GL_RGBA, GL_UNSIGNED_BYTE, gray);
  /* (Mesa's glBitmap samples a rectangle texture at (0, 0) whatever the raster position's
   * coordinates: the glyph takes texel (0, 0) here, which both agree on.) */
  glTexCoord2f(0.5f, 0.5f);
  glRasterPos2i(30, 30);
  static const GLubyte glyph[8] = {0x18, 0x3c, 0x7e, 0xff, 0xff, 0x7e, 0x3c, 0x18};
  glBitmap(8, 8, 0, 0, 0, 0, glyph);
  GLfloat raster[4];
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, raster);
  for (int i = 0; i < 4; ++i) v[i] = raster[i];
  conf_values(&c, "raster texture coordinates", v, 4);

  /* glTexSubImage2D, glCopyTexImage2D and glCopyTexSubImage2D. */
  conf_pixel_panel(&c, 1, 2, 4, 4);
  glTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, 4, 2, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, image);
  conf_error(&c, "TexSubImage2D rectangle");
  quad(8, 8, 56, 48, 0, 0, kW, kH);
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[3]);
  filter(GL_NEAREST);
  glCopyTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGB, 8, 200, 30, 20, 0);
  conf_error(&c, "CopyTexImage2D rectangle");
  glCopyTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, 0, 0, 72, 180, 10, 10);
  conf_error(&c, "CopyTexSubImage2D rectangle");
  conf_pixel_panel(&c, 2, 2, 4, 4);
  quad(2, 2, 62, 42, 0, 0, 30, 20);
  static unsigned char back[30 * 20 * 4];
  glGetTexImage(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  conf_error(&c, "GetTexImage rectangle");
  for (int i = 0; i < 8; ++i) v[i] = back[(i * 2 * 30 + i * 3) * 4 + (i % 3)];
  conf_values(&c, "copied texels", v, 8);

  /* A display list that defines and draws a rectangle texture. */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[2]);
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, kW / 2, kH, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  quad(4, 4, 52, 44, 0, 0, kW / 2, kH);
  glEndList();
  memset(image, 0, sizeof image); /* the list keeps its own copy */
  conf_pixel_panel(&c, 3, 2, 4, 4);
  glCallList(list);

  /* The enable and the binding through the attribute stack; the cube map over the rectangle. */
  glPushAttrib(GL_ENABLE_BIT | GL_TEXTURE_BIT);
  glDisable(GL_TEXTURE_RECTANGLE_ARB);
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 0);
  glPopAttrib();
  conf_value(&c, "enable after pop", glIsEnabled(GL_TEXTURE_RECTANGLE_ARB));
  glGetIntegerv(GL_TEXTURE_BINDING_RECTANGLE_ARB, &n);
  conf_value(&c, "binding after pop", n == (GLint)tex[2]);
  GLuint cube;
  glGenTextures(1, &cube);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  static unsigned char face[4 * 4 * 4];
  memset(face, 128, sizeof face);
  for (int f = 0; f < 6; ++f) {
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, face);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_CUBE_MAP);
  conf_pixel_panel(&c, 0, 3, 4, 4);
  glBegin(GL_QUADS);
  glTexCoord3f(1, 0, 0), glVertex2f(4, 4);
  glTexCoord3f(1, 0, 0), glVertex2f(28, 4);
  glTexCoord3f(1, 0, 0), glVertex2f(28, 28);
  glTexCoord3f(1, 0, 0), glVertex2f(4, 28);
  glEnd();
  glDisable(GL_TEXTURE_CUBE_MAP);

  /* Feedback reports the coordinates as given, in texels. */
  GLfloat feedback[64];
  glFeedbackBuffer(64, GL_3D_COLOR_TEXTURE, feedback);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_POINTS);
  glTexCoord2f(12.5f, 3.25f);
  glVertex2f(10, 10);
  glEnd();
  const GLint values = glRenderMode(GL_RENDER);
  conf_value(&c, "feedback values", values);
  for (int i = 0; i < 4; ++i) v[i] = feedback[1 + 3 + 4 + i];
  conf_values(&c, "feedback texture coordinates", v, 4);
  glDisable(GL_TEXTURE_RECTANGLE_ARB);

  /* Proxies and errors. */
  glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, 300, 7, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_TEXTURE_WIDTH, &n);
  conf_value(&c, "proxy width", n);
  glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, 1 << 20, 7, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_RECTANGLE_ARB, 0, GL_TEXTURE_WIDTH, &n);
  conf_value(&c, "proxy width too large", n);
  conf_error(&c, "proxy too large");
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[0]);
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_error(&c, "TexImage2D level 1");
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, 4, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_error(&c, "TexImage2D border 1");
  glTexImage1D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_error(&c, "TexImage1D rectangle");
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, GL_REPEAT);
  conf_error(&c, "wrap REPEAT");
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
  conf_error(&c, "wrap MIRRORED_REPEAT");
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, GL_CLAMP);
  conf_error(&c, "wrap CLAMP");
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  conf_error(&c, "min filter LINEAR_MIPMAP_LINEAR");
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_BASE_LEVEL, 1);
  conf_error(&c, "base level 1");
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_BASE_LEVEL, 0);
  conf_error(&c, "base level 0");
  glCopyTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA, 0, 0, 4, 4, 0);
  conf_error(&c, "CopyTexImage2D level 1");
  glTexSubImage2D(GL_TEXTURE_RECTANGLE_ARB, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  conf_error(&c, "TexSubImage2D level 1");
  glGetTexImage(GL_TEXTURE_RECTANGLE_ARB, 1, GL_RGBA, GL_UNSIGNED_BYTE, back);
  conf_error(&c, "GetTexImage level 1");
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex[1]); /* a 2D texture's name */
  conf_error(&c, "bind a 2D name");
  return conf_finish(&c);
}
