/* Level-of-detail state of OpenGL 1.2 and 1.4 (OpenGL 1.5 sections 3.8.8 and 3.8.10):
 * GL_TEXTURE_LOD_BIAS of the texture object and of the texture unit (glTexEnv
 * GL_TEXTURE_FILTER_CONTROL), alone and together, GL_TEXTURE_MIN_LOD / GL_TEXTURE_MAX_LOD
 * (equal ones forcing a level, a maximum of 0 forcing magnification), GL_TEXTURE_BASE_LEVEL /
 * GL_TEXTURE_MAX_LEVEL with the completeness rules (a base above the maximum, levels below
 * the base missing, a level of another internal format), on receding floors and frontal
 * quads textured with a chain whose levels have different colours, so that the level taken
 * shows; 1D textures; the state in a display list and through glPushAttrib(GL_TEXTURE_BIT).
 * Every parameter's default and value read back in each query form, GL_MAX_TEXTURE_LOD_BIAS,
 * GL_GENERATE_MIPMAP_HINT and the errors are recorded with conf_value (the unit's bias is read
 * with glGetTexEnviv only where it is an integer: Mesa truncates it, the specification
 * rounds). */
#include <stdio.h>

#include "conf.h"

static const unsigned char kLevelColour[7][3] = {{220, 40, 40},  {40, 200, 60},  {50, 80, 230}, {230, 220, 40},
                                                 {220, 60, 220}, {40, 210, 210}, {250, 250, 250}};

/* Level `level` of the chain, size n: its colour, with a faint checker of 2-texel squares. */
static void level_image(GLenum target, int level, int n, int height) {
  static unsigned char data[64 * 64 * 4];
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < n; ++x) {
      unsigned char* p = &data[(y * n + x) * 4];
      int on = (x / 2 + y / 2) % 2;
      for (int k = 0; k < 3; ++k) p[k] = (unsigned char)(kLevelColour[level][k] - (on ? 30 : 0));
      p[3] = 255;
    }
  if (target == GL_TEXTURE_1D) glTexImage1D(GL_TEXTURE_1D, level, GL_RGBA, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
  else glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, n, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
}

/* A 32x32 chain, levels 0 to 5 (or from `first`). */
static GLuint chain(int first) {
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  for (int l = first, n = 32 >> first; n >= 1; ++l, n /= 2) level_image(GL_TEXTURE_2D, l, n, n);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  return tex;
}

static void floor_cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 4);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, -0.7f, 0.0f);
  glRotatef(9.0f, 0, 1, 0);
  glBegin(GL_QUADS);
  glTexCoord2f(0.03f, 0.05f);
  glVertex3f(-2, 0, -1.1f);
  glTexCoord2f(4.03f, 0.05f);
  glVertex3f(2, 0, -1.1f);
  glTexCoord2f(4.03f, 24.05f);
  glVertex3f(2, 0, -35);
  glTexCoord2f(0.03f, 24.05f);
  glVertex3f(-2, 0, -35);
  glEnd();
}

/* A frontal quad showing `reps` repeats across its 64 pixels. */
static void frontal_cell(const ConfContext* c, int col, int row, float reps) {
  conf_panel(c, col, row, 4, 4);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_QUADS);
  glTexCoord2f(0.013f, 0.021f);
  glVertex2f(-1, -1);
  glTexCoord2f(0.013f + reps, 0.021f);
  glVertex2f(1, -1);
  glTexCoord2f(0.013f + reps, 0.021f + reps);
  glVertex2f(1, 1);
  glTexCoord2f(0.013f, 0.021f + reps);
  glVertex2f(-1, 1);
  glEnd();
}

static void record_lod(ConfContext* c, GLenum target, const char* what) {
  static const GLenum pnames[] = {GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD, GL_TEXTURE_BASE_LEVEL,
                                  GL_TEXTURE_MAX_LEVEL, GL_TEXTURE_LOD_BIAS, GL_GENERATE_MIPMAP};
  double v[12];
  for (int i = 0; i < 6; ++i) {
    GLfloat f = -7;
    GLint n = -7;
    glGetTexParameterfv(target, pnames[i], &f);
    glGetTexParameteriv(target, pnames[i], &n);
    v[2 * i] = f, v[2 * i + 1] = n;
  }
  GLfloat unit = -7;
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &unit);
  char key[96];
  snprintf(key, sizeof key, "%s min max base maxlevel bias generate (f, i)", what);
  conf_values(c, key, v, 12);
  snprintf(key, sizeof key, "%s unit bias", what);
  conf_value(c, key, unit);
}

static void reset(void) {
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -1000.0f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 1000.0f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0.0f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.0f);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  glColor3f(0.35f, 0.5f, 0.65f); /* an untextured quad shows in this colour */

  GLuint tex = chain(0);
  record_lod(&c, GL_TEXTURE_2D, "default");
  GLfloat max_bias = -1;
  glGetFloatv(GL_MAX_TEXTURE_LOD_BIAS, &max_bias);
  conf_value(&c, "max lod bias", max_bias);
  GLint hint = -1;
  glGetIntegerv(GL_GENERATE_MIPMAP_HINT, &hint);
  conf_value(&c, "generate mipmap hint", hint);
  glHint(GL_GENERATE_MIPMAP_HINT, GL_NICEST);
  glGetIntegerv(GL_GENERATE_MIPMAP_HINT, &hint);
  conf_value(&c, "generate mipmap hint nicest", hint);

  /* Row 0: biases on trilinear floors: none, the texture's +1.5, the unit's -1, both (2 and
   * -0.75) with nearest levels. */
  floor_cell(&c, 0, 0);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.5f);
  floor_cell(&c, 1, 0);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0.0f);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -1.0f);
  GLint unit_bias = 7;
  glGetTexEnviv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &unit_bias);
  conf_value(&c, "unit bias -1 as integer", unit_bias);
  floor_cell(&c, 2, 0);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 2.0f);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -0.75f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  record_lod(&c, GL_TEXTURE_2D, "both biases");
  floor_cell(&c, 3, 0);
  reset();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);

  /* Row 1: a minimum LOD of 2 on a magnified quad; a maximum of 1.5 on a floor; both 3; a
   * maximum of 0 (magnification everywhere, the nearest magnification filter). */
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 2.0f);
  frontal_cell(&c, 0, 1, 0.7f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -1000.0f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 1.5f);
  floor_cell(&c, 1, 1);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 3.0f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 3.0f);
  record_lod(&c, GL_TEXTURE_2D, "min max 3");
  floor_cell(&c, 2, 1);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -1000.0f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 0.0f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  floor_cell(&c, 3, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  reset();

  /* Row 2: base level 2; maximum level 2; base 1 to 3 with a non-mipmap filter (level 1
   * only); a base above the maximum (incomplete: the plain colour) beside a chain given from
   * level 2 only, with base level 2 (complete). */
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR);
  floor_cell(&c, 0, 2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  floor_cell(&c, 1, 2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 3);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  frontal_cell(&c, 2, 2, 3.0f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 3);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  conf_panel(&c, 3, 2, 4, 4);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRectf(-1, -1, 0, 1);
  GLuint partial = chain(2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(0, -1);
  glTexCoord2f(3, 0);
  glVertex2f(1, -1);
  glTexCoord2f(3, 6);
  glVertex2f(1, 1);
  glTexCoord2f(0, 6);
  glVertex2f(0, 1);
  glEnd();
  record_lod(&c, GL_TEXTURE_2D, "partial chain");

  /* Row 3: a level of another internal format inside [base, max] (incomplete), then outside
   * it (complete); a 1D chain with base level 1 and a bias; the state set in a display list
   * and restored by glPopAttrib; a magnified quad whose bias turns it minified. */
  glBindTexture(GL_TEXTURE_2D, tex);
  reset();
  static unsigned char grey[8 * 8 * 3];
  for (int i = 0; i < 8 * 8 * 3; ++i) grey[i] = 128;
  glTexImage2D(GL_TEXTURE_2D, 2, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, grey);
  frontal_cell(&c, 0, 3, 9.0f); /* incomplete: plain colour */
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
  conf_panel(&c, 0, 3, 4, 4);
  glBegin(GL_QUADS); /* complete again: levels 0 and 1, over the right half */
  glTexCoord2f(0, 0);
  glVertex2f(0, -1);
  glTexCoord2f(4, 0);
  glVertex2f(1, -1);
  glTexCoord2f(4, 9);
  glVertex2f(1, 1);
  glTexCoord2f(0, 9);
  glVertex2f(0, 1);
  glEnd();
  level_image(GL_TEXTURE_2D, 2, 8, 8);
  reset();

  GLuint one_d;
  glGenTextures(1, &one_d);
  glBindTexture(GL_TEXTURE_1D, one_d);
  for (int l = 0, n = 64; n >= 1; ++l, n /= 2) level_image(GL_TEXTURE_1D, l, n, 1);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_BASE_LEVEL, 1);
  glTexParameterf(GL_TEXTURE_1D, GL_TEXTURE_LOD_BIAS, 0.5f);
  record_lod(&c, GL_TEXTURE_1D, "1D");
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_1D);
  floor_cell(&c, 1, 3);
  glDisable(GL_TEXTURE_1D);
  glEnable(GL_TEXTURE_2D);

  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.0f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 2.5f);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -0.5f);
  glEndList();
  record_lod(&c, GL_TEXTURE_2D, "before the list");
  glCallList(list);
  record_lod(&c, GL_TEXTURE_2D, "after the list");
  glPushAttrib(GL_TEXTURE_BIT);
  reset();
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 4.0f);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  record_lod(&c, GL_TEXTURE_2D, "pushed and changed");
  glPopAttrib();
  record_lod(&c, GL_TEXTURE_2D, "popped");
  floor_cell(&c, 2, 3);
  reset();

  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 2.0f);
  frontal_cell(&c, 3, 3, 0.6f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

  /* Values: float parameters through the integer forms and back; errors. */
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 2.5f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 7);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, -3.25f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2.0f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 5);
  record_lod(&c, GL_TEXTURE_2D, "values");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1);
  conf_error(&c, "base level -1");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, -2);
  conf_error(&c, "max level -2");
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 2000.0f);
  conf_error(&c, "min lod 2000");
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 100.0f);
  conf_error(&c, "lod bias 100");
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  conf_error(&c, "filter control env mode");
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS, 1.0f);
  conf_error(&c, "env lod bias");
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 20.0f);
  conf_error(&c, "unit lod bias 20");
  GLfloat f = -7;
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_COLOR, &f);
  conf_error(&c, "get filter control env colour");
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS, &f);
  conf_error(&c, "get env lod bias");
  glHint(GL_GENERATE_MIPMAP_HINT, GL_LINEAR);
  conf_error(&c, "generate mipmap hint linear");
  record_lod(&c, GL_TEXTURE_2D, "after the errors");
  /* (glPopAttrib(GL_HINT_BIT) restores GL_GENERATE_MIPMAP_HINT by the specification; Mesa 22
   * leaves it: docs/gl.md.) */
  conf_error(&c, "end");

  glDeleteLists(list, 1);
  glDeleteTextures(1, &tex);
  glDeleteTextures(1, &partial);
  glDeleteTextures(1, &one_d);
  return conf_finish(&c);
}
