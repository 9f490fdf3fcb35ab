/* Wrap modes of OpenGL 1.3 and 1.4 (OpenGL 1.5 section 3.8.7): GL_MIRRORED_REPEAT and
 * GL_CLAMP_TO_BORDER on s and t, nearest and linear, magnified and minified through mipmaps,
 * with GL_CLAMP_TO_EDGE, GL_CLAMP and GL_REPEAT beside them; non-power-of-two images; 1D
 * textures; the border colour on RGBA, RGB and luminance textures (converted to the base
 * format, section 3.8.8: luminance takes red) and on an image given with a border (whose
 * border texels are not kept, as in Mesa's gallium drivers); a lit sphere whose coordinates
 * a texture matrix scales across several mirrored repeats; wrap parameters set in a display
 * list and restored by glPopAttrib. Every wrap parameter read back (GL_TEXTURE_WRAP_R too)
 * and the errors of wrong modes are recorded with conf_value. */
#include <stdio.h>

#include "conf.h"

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 4);
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

/* A floor seen in perspective, texture coordinates [s0, s0 + reps] x [t0, t0 + reps]. */
static void floor_cell(const ConfContext* c, int col, int row, float s0, float t0, float reps) {
  conf_panel(c, col, row, 4, 4);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, -0.8f, 0.0f);
  glRotatef(7.0f, 0, 1, 0);
  glBegin(GL_QUADS);
  glTexCoord2f(s0, t0);
  glVertex3f(-2, 0, -1.2f);
  glTexCoord2f(s0 + reps, t0);
  glVertex3f(2, 0, -1.2f);
  glTexCoord2f(s0 + reps, t0 + reps);
  glVertex3f(2, 0, -25);
  glTexCoord2f(s0, t0 + reps);
  glVertex3f(-2, 0, -25);
  glEnd();
}

static void wrap(GLenum target, GLenum s, GLenum t) {
  glTexParameteri(target, GL_TEXTURE_WRAP_S, s);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, t);
}

static void filter(GLenum target, GLenum min, GLenum mag) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, min);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, mag);
}

/* A w x h RGBA image whose texels all differ: a red ramp along s, green along t, a blue
 * checker, an alpha ramp. */
static void ramp_image(unsigned char* img, int w, int h, int shade) {
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      unsigned char* p = &img[(y * w + x) * 4];
      p[0] = (unsigned char)(20 + 220 * x / (w > 1 ? w - 1 : 1));
      p[1] = (unsigned char)(30 + 200 * y / (h > 1 ? h - 1 : 1));
      p[2] = (unsigned char)((x + y) % 2 ? shade : 255 - shade);
      p[3] = (unsigned char)(255 - 90 * ((x + 2 * y) % 3));
    }
}

static void record_wrap(ConfContext* c, GLenum target, const char* what) {
  GLint v[3];
  glGetTexParameteriv(target, GL_TEXTURE_WRAP_S, &v[0]);
  glGetTexParameteriv(target, GL_TEXTURE_WRAP_T, &v[1]);
  glGetTexParameteriv(target, GL_TEXTURE_WRAP_R, &v[2]);
  GLfloat f;
  glGetTexParameterfv(target, GL_TEXTURE_WRAP_S, &f);
  char key[96];
  snprintf(key, sizeof key, "%s wrap s t r, s as float", what);
  conf_values(c, key, (double[]){v[0], v[1], v[2], f}, 4);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  static unsigned char img[64 * 64 * 4];

  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  record_wrap(&c, GL_TEXTURE_2D, "default");
  ramp_image(img, 8, 8, 90);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  const GLfloat yellow[4] = {1.0f, 0.85f, 0.1f, 1.0f}, blue[4] = {0.2f, 0.3f, 1.0f, 0.5f};

  /* Row 0: mirrored repeat and clamp to border, nearest and linear, magnified (the quads are
   * turned a little so that texel edges do not fall on pixel centres). */
  const GLenum filters[2] = {GL_NEAREST, GL_LINEAR};
  for (int i = 0; i < 2; ++i) {
    filter(GL_TEXTURE_2D, filters[i], filters[i]);
    wrap(GL_TEXTURE_2D, GL_MIRRORED_REPEAT, GL_MIRRORED_REPEAT);
    if (i == 0) record_wrap(&c, GL_TEXTURE_2D, "mirrored");
    cell(&c, i, 0);
    glRotatef(3.0f, 0, 0, 1);
    quad(-1.3f, -0.9f, 2.2f, 2.35f);
    wrap(GL_TEXTURE_2D, GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER);
    if (i == 0) record_wrap(&c, GL_TEXTURE_2D, "border");
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, yellow);
    cell(&c, 2 + i, 0);
    glRotatef(-4.0f, 0, 0, 1);
    quad(-0.45f, -0.3f, 1.35f, 1.5f);
  }

  /* Row 1: mixed modes (mirrored s with border t; border s with clamp-to-edge t and a
   * translucent border; border s with GL_CLAMP t), and a 5x3 image mirrored. */
  filter(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR);
  wrap(GL_TEXTURE_2D, GL_MIRRORED_REPEAT, GL_CLAMP_TO_BORDER);
  cell(&c, 0, 1);
  quad(-1.6f, -0.4f, 1.7f, 1.3f);
  wrap(GL_TEXTURE_2D, GL_CLAMP_TO_BORDER, GL_CLAMP_TO_EDGE);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, blue);
  cell(&c, 1, 1);
  quad(-0.5f, -0.6f, 1.4f, 1.5f);
  wrap(GL_TEXTURE_2D, GL_CLAMP_TO_BORDER, GL_CLAMP);
  cell(&c, 2, 1);
  glRotatef(10.0f, 0, 0, 1);
  quad(-0.3f, -0.45f, 1.25f, 1.3f);
  GLuint npot;
  glGenTextures(1, &npot);
  glBindTexture(GL_TEXTURE_2D, npot);
  ramp_image(img, 5, 3, 40);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  filter(GL_TEXTURE_2D, GL_LINEAR, GL_NEAREST);
  wrap(GL_TEXTURE_2D, GL_MIRRORED_REPEAT, GL_MIRRORED_REPEAT);
  cell(&c, 3, 1);
  glRotatef(-6.0f, 0, 0, 1);
  quad(-2.1f, -1.2f, 2.3f, 2.05f);

  /* Row 2: minified through mipmaps on receding floors (mirrored; border with a colour; the
   * 5x3 image's levels are not a chain, so it is not used here), and 1D textures. */
  GLuint chain;
  glGenTextures(1, &chain);
  glBindTexture(GL_TEXTURE_2D, chain);
  for (int l = 0, n = 32; n >= 1; ++l, n /= 2) {
    ramp_image(img, n, n, 40 + 30 * l);
    glTexImage2D(GL_TEXTURE_2D, l, GL_RGBA, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  }
  filter(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  wrap(GL_TEXTURE_2D, GL_MIRRORED_REPEAT, GL_MIRRORED_REPEAT);
  floor_cell(&c, 0, 2, -3.1f, 0.2f, 12.0f);
  wrap(GL_TEXTURE_2D, GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER);
  filter(GL_TEXTURE_2D, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, yellow);
  floor_cell(&c, 1, 2, -0.7f, -0.2f, 2.5f);

  static unsigned char row[24 * 4];
  ramp_image(row, 24, 1, 200);
  GLuint one_d;
  glGenTextures(1, &one_d);
  glBindTexture(GL_TEXTURE_1D, one_d);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 24, 0, GL_RGBA, GL_UNSIGNED_BYTE, row);
  filter(GL_TEXTURE_1D, GL_LINEAR, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER); /* ignored by 1D */
  record_wrap(&c, GL_TEXTURE_1D, "1D");
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_1D);
  cell(&c, 2, 2);
  glRotatef(25.0f, 0, 0, 1);
  quad(-1.4f, 0.0f, 2.6f, 1.0f);
  filter(GL_TEXTURE_1D, GL_NEAREST, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameterfv(GL_TEXTURE_1D, GL_TEXTURE_BORDER_COLOR, blue);
  cell(&c, 3, 2);
  glRotatef(-35.0f, 0, 0, 1);
  quad(-0.6f, 0.0f, 1.5f, 1.0f);
  glDisable(GL_TEXTURE_1D);
  glEnable(GL_TEXTURE_2D);

  /* Row 3: a lit sphere modulated by a mirrored texture scaled by the texture matrix; the
   * border colour on a luminance and an RGB texture; an image given with a border, clamped
   * to the border colour; wrap modes set in a display list, then pushed, changed and popped. */
  glBindTexture(GL_TEXTURE_2D, tex);
  filter(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR);
  wrap(GL_TEXTURE_2D, GL_MIRRORED_REPEAT, GL_MIRRORED_REPEAT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(-0.3f, 0.1f, 0.0f);
  glScalef(3.3f, 2.7f, 1.0f);
  cell(&c, 0, 3);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  const GLfloat light[4] = {0.4f, 0.6f, 1.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glRotatef(30.0f, 1, 0, 0);
  conf_sphere(0.9f, 24, 16);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  const GLfloat reddish[4] = {0.9f, 0.2f, 0.4f, 0.6f};
  GLuint lum;
  glGenTextures(1, &lum);
  glBindTexture(GL_TEXTURE_2D, lum);
  ramp_image(img, 4, 4, 100);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  filter(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR);
  wrap(GL_TEXTURE_2D, GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, reddish);
  conf_panel(&c, 1, 3, 4, 4);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_QUADS); /* left half: luminance */
  glTexCoord2f(-0.5f, -0.5f);
  glVertex2f(-1, -1);
  glTexCoord2f(1.5f, -0.5f);
  glVertex2f(0, -1);
  glTexCoord2f(1.5f, 1.5f);
  glVertex2f(0, 1);
  glTexCoord2f(-0.5f, 1.5f);
  glVertex2f(-1, 1);
  glEnd();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glBegin(GL_QUADS); /* right half: RGB (the border's alpha is 1) */
  glTexCoord2f(-0.5f, -0.5f);
  glVertex2f(0, -1);
  glTexCoord2f(1.5f, -0.5f);
  glVertex2f(1, -1);
  glTexCoord2f(1.5f, 1.5f);
  glVertex2f(1, 1);
  glTexCoord2f(-0.5f, 1.5f);
  glVertex2f(0, 1);
  glEnd();

  GLuint bordered;
  glGenTextures(1, &bordered);
  glBindTexture(GL_TEXTURE_2D, bordered);
  ramp_image(img, 10, 10, 160);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 10, 10, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
  filter(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR);
  wrap(GL_TEXTURE_2D, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, yellow);
  cell(&c, 2, 3);
  glRotatef(-8.0f, 0, 0, 1);
  quad(-0.35f, -1.2f, 1.3f, 1.9f);

  GLuint listed;
  glGenTextures(1, &listed);
  glBindTexture(GL_TEXTURE_2D, listed);
  ramp_image(img, 8, 8, 220);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  filter(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  wrap(GL_TEXTURE_2D, GL_MIRRORED_REPEAT, GL_CLAMP_TO_BORDER);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, blue);
  glEndList();
  record_wrap(&c, GL_TEXTURE_2D, "before the list");
  glCallList(list);
  record_wrap(&c, GL_TEXTURE_2D, "after the list");
  glPushAttrib(GL_TEXTURE_BIT);
  wrap(GL_TEXTURE_2D, GL_REPEAT, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R, GL_MIRRORED_REPEAT);
  record_wrap(&c, GL_TEXTURE_2D, "pushed and changed");
  glPopAttrib();
  record_wrap(&c, GL_TEXTURE_2D, "popped");
  cell(&c, 3, 3);
  glRotatef(4.0f, 0, 0, 1);
  quad(-1.2f, -0.4f, 1.9f, 1.45f);

  /* Errors: unknown modes, a mode for another parameter, the float forms. */
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT + 1);
  conf_error(&c, "wrap s mirrored + 1");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_LINEAR);
  conf_error(&c, "wrap t linear");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_BORDER);
  conf_error(&c, "wrap r border");
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLfloat)GL_CLAMP_TO_BORDER);
  conf_error(&c, "wrap s border as float");
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_R, GL_MIRRORED_REPEAT);
  conf_error(&c, "1D wrap r mirrored");
  record_wrap(&c, GL_TEXTURE_2D, "after the errors");
  record_wrap(&c, GL_TEXTURE_1D, "1D after the errors");
  conf_error(&c, "end");

  glDeleteLists(list, 1);
  GLuint names[7] = {tex, npot, chain, one_d, lum, bordered, listed};
  glDeleteTextures(7, names);
  return conf_finish(&c);
}
