/* Texture commands in display lists (OpenGL 1.1 section 5.4), compared with Mesa: glTexImage1D,
 * glTexImage2D, glTexSubImage1D and glTexSubImage2D compiled under non-default unpack states
 * (row length, skipped pixels and rows, alignment, swapped bytes) keep the image as that state
 * read it at compile time, not the client memory nor the unpack state of the call; a list made
 * in GL_COMPILE_AND_EXECUTE; glTexGen planes compiled (an eye plane is transformed by the
 * modelview current when the list runs); glCopyTexImage2D / glCopyTexSubImage2D / glCopyTexImage1D
 * compiled, reading the framebuffer when the list runs; glPrioritizeTextures compiled; proxy
 * images executed at once, never compiled; errors of compiled commands raised when the list
 * runs; texture generation state through glPushAttrib / glPopAttrib. Texels read back with
 * glGetTexImage, the queries and the error codes are compared value by value (conf_value). */
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

static void default_unpack(void) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
}

/* glGetTexImage of level 0 of `target` as RGBA bytes, recorded byte by byte. */
static void record_texels(ConfContext* c, const char* name, GLenum target, int texels) {
  static unsigned char out[64 * 64 * 4];
  char key[128];
  memset(out, 0xa5, sizeof out);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  for (int i = 0; i < texels * 4; ++i) {
    snprintf(key, sizeof key, "%s byte %d", name, i);
    conf_value(c, key, out[i]);
  }
}

/* A 2D image compiled from the middle of a bigger RGB image (row length, skips, alignment);
 * the client memory and the unpack state change before the list runs. */
static GLuint image_2d_list(ConfContext* c, GLuint tex) {
  static unsigned char big[13 * 12 * 3 + 16];
  for (int i = 0; i < (int)sizeof big; ++i) big[i] = (unsigned char)(i * 29 + 11);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBindTexture(GL_TEXTURE_2D, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 13);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, big);
  /* A sub-image of luminance-alpha shorts with their bytes swapped. */
  static unsigned short la[3 * 4 * 2];
  for (int i = 0; i < 3 * 4 * 2; ++i) {
    unsigned short v = (unsigned short)(i * 4099 + 77);
    la[i] = (unsigned short)((v >> 8) | (v << 8));
  }
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 1, 3, 4, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT, la);
  glEndList();
  /* The pixel-store calls were executed at once (they are never compiled). */
  GLint swap = -1, row = -1;
  glGetIntegerv(GL_UNPACK_SWAP_BYTES, &swap);
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &row);
  conf_value(c, "unpack swap after compiling", swap);
  conf_value(c, "unpack row length after compiling", row);
  memset(big, 0, sizeof big);
  memset(la, 0, sizeof la);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 5);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  return list;
}

/* A 1D image and sub-image compiled and executed at once (GL_COMPILE_AND_EXECUTE). */
static GLuint image_1d_list(GLuint tex) {
  static unsigned char ramp[24 * 4];
  static float piece[5 * 3];
  for (int i = 0; i < 24 * 4; ++i) ramp[i] = (unsigned char)(255 - i * 3);
  for (int i = 0; i < 5 * 3; ++i) piece[i] = (float)((i * 5) % 7) / 6.0f;
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  glBindTexture(GL_TEXTURE_1D, tex);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 4);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glTexSubImage1D(GL_TEXTURE_1D, 0, 9, 5, GL_RGB, GL_FLOAT, piece);
  glEndList();
  default_unpack();
  return list;
}

/* Errors of compiled texture commands are raised when the list runs; proxies are executed at
 * once and not compiled. */
static void list_errors(ConfContext* c) {
  GLuint list = glGenLists(1);
  conf_error(c, "before compiling");
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, -2, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  glTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_LUMINANCE8, 64, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, NULL);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGB5, 32, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  glEndList();
  conf_error(c, "while compiling");
  GLint w = -1, h = -1, f = -1;
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_1D, 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_1D, 0, GL_TEXTURE_INTERNAL_FORMAT, &f);
  conf_value(c, "proxy 1D width after compiling", w);
  conf_value(c, "proxy 1D format after compiling", f);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
  conf_value(c, "proxy 2D width after compiling", w);
  conf_value(c, "proxy 2D height after compiling", h);
  /* Reset the proxies, then run the list: only the bad image is executed. */
  glTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_RGB, 0, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  glCallList(list);
  conf_error(c, "list with a negative width");
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_1D, 0, GL_TEXTURE_WIDTH, &w);
  conf_value(c, "proxy 1D width after the list", w);
  /* Enum and value errors compiled, raised in order at each call of the list. */
  GLuint bad = glGenLists(1);
  glNewList(bad, GL_COMPILE);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGB, GL_BYTE + 100, NULL);
  glEndList();
  glCallList(bad);
  conf_error(c, "compiled bad type");
  glNewList(bad, GL_COMPILE);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP + 1);
  glEndList();
  glCallList(bad);
  conf_error(c, "compiled bad texgen mode");
  glNewList(bad, GL_COMPILE);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 4, 4, 2);
  glEndList();
  glCallList(bad);
  conf_error(c, "compiled copy with border 2");
  glDeleteLists(bad, 1);
  glDeleteLists(list, 1);
}

/* Texture generation state compiled: an eye-linear plane taken with the modelview of the call
 * of the list, object-linear planes, the modes; drawn on a sphere. */
static GLuint texgen_list(void) {
  GLuint list = glGenLists(1);
  const GLfloat s_plane[4] = {2.0f, 0.5f, 0.0f, 0.5f};
  const GLdouble t_plane[4] = {0.0, 1.5, 1.0, 0.5};
  const GLint q_plane[4] = {0, 0, 0, 1};
  glNewList(list, GL_COMPILE);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGenfv(GL_S, GL_EYE_PLANE, s_plane);
  glTexGenf(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGendv(GL_T, GL_OBJECT_PLANE, t_plane);
  glTexGend(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGeniv(GL_Q, GL_OBJECT_PLANE, q_plane);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEndList();
  return list;
}

static void record_texgen(ConfContext* c) {
  GLfloat p[4];
  double d[4];
  glGetTexGenfv(GL_S, GL_EYE_PLANE, p);
  for (int i = 0; i < 4; ++i) d[i] = p[i];
  conf_values(c, "S eye plane", d, 4);
  glGetTexGenfv(GL_T, GL_OBJECT_PLANE, p);
  for (int i = 0; i < 4; ++i) d[i] = p[i];
  conf_values(c, "T object plane", d, 4);
  GLint mode = -1;
  glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, &mode);
  conf_value(c, "T mode", mode);
  conf_value(c, "gen S enabled", glIsEnabled(GL_TEXTURE_GEN_S));
}

/* glPushAttrib(GL_TEXTURE_BIT) keeps the texture generation modes and planes (the eye plane
 * as stored, not transformed again by the modelview of the pop) and their enables. */
static void texgen_attrib(ConfContext* c) {
  const GLfloat eye[4] = {1.0f, 2.0f, 0.5f, -1.0f}, object[4] = {0.25f, 0.0f, 1.0f, 2.0f};
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(30, 0, 0, 1);
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_R, GL_EYE_PLANE, eye);
  glTexGenfv(GL_R, GL_OBJECT_PLANE, object);
  glEnable(GL_TEXTURE_GEN_R);
  glPushAttrib(GL_TEXTURE_BIT);
  glLoadIdentity();
  glScalef(2, 3, 4);
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGenfv(GL_R, GL_EYE_PLANE, object);
  glTexGenfv(GL_R, GL_OBJECT_PLANE, eye);
  glDisable(GL_TEXTURE_GEN_R);
  glPopAttrib();
  GLfloat p[4];
  double d[4];
  glGetTexGenfv(GL_R, GL_EYE_PLANE, p);
  for (int i = 0; i < 4; ++i) d[i] = p[i];
  conf_values(c, "R eye plane after the pop", d, 4);
  glGetTexGenfv(GL_R, GL_OBJECT_PLANE, p);
  for (int i = 0; i < 4; ++i) d[i] = p[i];
  conf_values(c, "R object plane after the pop", d, 4);
  GLint mode = -1;
  glGetTexGeniv(GL_R, GL_TEXTURE_GEN_MODE, &mode);
  conf_value(c, "R mode after the pop", mode);
  conf_value(c, "gen R enabled after the pop", glIsEnabled(GL_TEXTURE_GEN_R));
  glDisable(GL_TEXTURE_GEN_R);
  glLoadIdentity();
  conf_error(c, "texgen attributes");
}

/* A checker drawn into the framebuffer, then copied by a compiled list. */
static void checker_cell(const ConfContext* c, int col, int row, float shade) {
  flat_cell(c, col, row);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_TEXTURE_1D);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      float on = (float)((x + y) % 2);
      /* Colours away from the halves of 1/255: a flat 0.3 is stored 76 by llvmpipe and 77
       * by shadelab (a framebuffer rounding difference, not the copy's). */
      glColor3f(shade * on, 0.25f + 0.5f * on, 1.0f - shade * on);
      glRectf(-1.0f + 0.5f * (float)x, -1.0f + 0.5f * (float)y, -0.5f + 0.5f * (float)x, -0.5f + 0.5f * (float)y);
    }
  }
  glColor3f(1, 1, 1);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 192)) return 1;
  glClearColor(0.2f, 0.15f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const int cw = c.width / 4, ch = c.height / 3;

  GLuint tex[4];
  glGenTextures(4, tex);
  GLuint list2d = image_2d_list(&c, tex[0]);
  conf_error(&c, "compiling the 2D list");
  glCallList(list2d);
  conf_error(&c, "calling the 2D list");
  nearest(GL_TEXTURE_2D);
  record_texels(&c, "2D list", GL_TEXTURE_2D, 8 * 8);
  default_unpack();
  glEnable(GL_TEXTURE_2D);
  flat_cell(&c, 0, 0);
  quad(-1, -1, 1, 1);
  glDisable(GL_TEXTURE_2D);

  GLuint list1d = image_1d_list(tex[1]);
  nearest(GL_TEXTURE_1D);
  record_texels(&c, "1D executed", GL_TEXTURE_1D, 16);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  glCallList(list1d);
  record_texels(&c, "1D replayed", GL_TEXTURE_1D, 16);
  glEnable(GL_TEXTURE_1D);
  flat_cell(&c, 1, 0);
  quad(-1, -1, 1, 1);
  glDisable(GL_TEXTURE_1D);

  /* Copies compiled, run after the framebuffer changed. */
  GLuint copy_list = glGenLists(1);
  glNewList(copy_list, GL_COMPILE);
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2 * cw + 4, c.height - ch + 4, 32, 32, 0);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 8, 8, 3 * cw + 10, c.height - ch + 10, 16, 12);
  glBindTexture(GL_TEXTURE_1D, tex[3]);
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_LUMINANCE, 2 * cw, c.height - ch + 20, 64, 0);
  glEndList();
  checker_cell(&c, 2, 0, 0.875f);
  checker_cell(&c, 3, 0, 0.375f);
  glCallList(copy_list);
  conf_error(&c, "copies");
  nearest(GL_TEXTURE_2D);
  record_texels(&c, "2D copy", GL_TEXTURE_2D, 32 * 32);
  glBindTexture(GL_TEXTURE_1D, tex[3]);
  nearest(GL_TEXTURE_1D);
  record_texels(&c, "1D copy", GL_TEXTURE_1D, 64);
  glEnable(GL_TEXTURE_2D);
  flat_cell(&c, 0, 1);
  glRotatef(20, 0, 0, 1);
  quad(-0.8f, -0.8f, 0.8f, 0.8f);
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_1D);
  flat_cell(&c, 1, 1);
  quad(-1, -1, 1, 1);
  glDisable(GL_TEXTURE_1D);

  /* Texture generation from a list, under a modelview of the call. */
  GLuint gen = texgen_list();
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_DEPTH_TEST);
  for (int k = 0; k < 2; ++k) {
    conf_panel(&c, 2 + k, 1, 4, 3);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -3);
    glRotatef(35.0f * (float)(k + 1), 0.3f, 1, 0);
    glCallList(gen);
    glColor3f(1.0f, 0.9f, 0.8f);
    conf_sphere(0.9f, 24, 16);
    if (k == 0) record_texgen(&c);
  }
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_TEXTURE_2D);
  glColor3f(1, 1, 1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  /* Priorities compiled; residency is a query. */
  GLuint prio = glGenLists(1);
  const GLclampf priorities[3] = {0.25f, 1.5f, -1.0f};
  glNewList(prio, GL_COMPILE);
  glPrioritizeTextures(3, tex, priorities);
  glEndList();
  GLfloat p = -1.0f;
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &p);
  conf_value(&c, "priority before the list", p);
  glCallList(prio);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &p);
  conf_value(&c, "priority after the list", p);
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &p);
  conf_value(&c, "clamped priority after the list", p);
  GLboolean resident[4] = {7, 7, 7, 7};
  conf_value(&c, "all resident", glAreTexturesResident(4, tex, resident));
  conf_error(&c, "priorities");

  list_errors(&c);
  texgen_attrib(&c);

  /* The 2D list once more, drawn rotated and minified, after its texture was replaced. */
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  glCallList(list2d);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_2D);
  for (int k = 0; k < 4; ++k) {
    flat_cell(&c, k, 2);
    glRotatef(13.0f * (float)k, 0, 0, 1);
    float s = 0.35f + 0.2f * (float)k;
    quad(-s, -s, s, s);
  }
  glDisable(GL_TEXTURE_2D);
  glDeleteLists(list2d, 1);
  glDeleteLists(list1d, 1);
  glDeleteLists(copy_list, 1);
  glDeleteLists(gen, 1);
  glDeleteLists(prio, 1);
  glDeleteTextures(4, tex);
  return conf_finish(&c);
}
