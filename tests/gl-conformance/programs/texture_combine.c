/* GL 1.3's GL_COMBINE texture environment (ARB_texture_env_combine, ARB_texture_env_dot3;
 * GL 1.4's crossbar, ARB_texture_env_crossbar): every function of table 3.24 on quads whose
 * primary colour varies across them: REPLACE, MODULATE scaled by 2, ADD of colour and alpha,
 * ADD_SIGNED scaled by 2, INTERPOLATE between two units' texels by the primary alpha (the
 * crossbar), SUBTRACT, DOT3_RGB bump mapping (a normal map against a light vector in the
 * primary colour), DOT3_RGBA, one-minus operands with the constant colour, two combining
 * units, GL_ALPHA_SCALE 4 blended, the state compiled into a display list and restored by
 * glPopAttrib. Then every combine parameter of every unit through glGetTexEnviv and
 * glGetTexEnvfv after each panel, and the errors of wrong functions, sources, operands and
 * scales. */
#define GL_GLEXT_PROTOTYPES
#include <math.h>
#include <stdio.h>

#include "conf.h"

static GLuint checker, normals, ramp;

static GLuint texture_2d(int w, int h, GLenum format, const unsigned char* texels, GLenum filter) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  glTexImage2D(GL_TEXTURE_2D, 0, format, w, h, 0, format, GL_UNSIGNED_BYTE, texels);
  return t;
}

static void make_textures(void) {
  static unsigned char rgba[16 * 16 * 4], bumps[16 * 16 * 3], grad[8 * 8 * 4];
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      unsigned char* t = &rgba[(y * 16 + x) * 4];
      const int on = (x / 4 + y / 4) % 2;
      t[0] = (unsigned char)(on ? 220 : 50), t[1] = (unsigned char)(on ? 170 : 80 + 8 * y), t[2] = (unsigned char)(on ? 60 : 200);
      t[3] = (unsigned char)(40 + 13 * x);
      /* A bumpy normal map: (n + 1) / 2 of hemispheres in 4 x 4 cells. */
      const float u = (x % 4) - 1.5f, v = (y % 4) - 1.5f;
      float nx = u / 2.5f, ny = v / 2.5f, nz = sqrtf(fmaxf(0.0f, 1.0f - nx * nx - ny * ny));
      unsigned char* n = &bumps[(y * 16 + x) * 3];
      n[0] = (unsigned char)(127.5f * (nx + 1.0f)), n[1] = (unsigned char)(127.5f * (ny + 1.0f)), n[2] = (unsigned char)(127.5f * (nz + 1.0f));
    }
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      unsigned char* g = &grad[(y * 8 + x) * 4];
      g[0] = (unsigned char)(32 * x), g[1] = (unsigned char)(255 - 32 * y), g[2] = (unsigned char)(16 * (x + y)), g[3] = (unsigned char)(255 - 24 * x);
    }
  checker = texture_2d(16, 16, GL_RGBA, rgba, GL_NEAREST);
  normals = texture_2d(16, 16, GL_RGB, bumps, GL_NEAREST);
  ramp = texture_2d(8, 8, GL_RGBA, grad, GL_LINEAR);
}

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.1, 1.1, -1.1, 1.1, -2.0, 2.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void env(GLenum pname, GLint value) { glTexEnvi(GL_TEXTURE_ENV, pname, value); }

/* Unit `unit` active with `texture` and GL_COMBINE, its functions `rgb` and `alpha`. */
static void combine(int unit, GLuint texture, GLint rgb, GLint alpha) {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, texture);
  glEnable(GL_TEXTURE_2D);
  env(GL_TEXTURE_ENV_MODE, GL_COMBINE);
  env(GL_COMBINE_RGB, rgb);
  env(GL_COMBINE_ALPHA, alpha);
}

/* Every unit back to GL 1.1's defaults (and off). */
static void reset(void) {
  static const GLenum sources[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  static const GLenum operands[3] = {GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
  const float zero[4] = {0, 0, 0, 0};
  for (int u = 3; u >= 0; --u) {
    glActiveTexture(GL_TEXTURE0 + u);
    glDisable(GL_TEXTURE_2D);
    env(GL_TEXTURE_ENV_MODE, GL_MODULATE);
    env(GL_COMBINE_RGB, GL_MODULATE);
    env(GL_COMBINE_ALPHA, GL_MODULATE);
    for (int i = 0; i < 3; ++i) {
      env(GL_SOURCE0_RGB + i, (GLint)sources[i]);
      env(GL_SOURCE0_ALPHA + i, (GLint)sources[i]);
      env(GL_OPERAND0_RGB + i, (GLint)operands[i]);
      env(GL_OPERAND0_ALPHA + i, GL_SRC_ALPHA);
    }
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 1.0f);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 1.0f);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, zero);
  }
}

/* A quad whose primary colour and alpha vary across it; unit 0 over [0, 1]^2, unit 1 over
 * [0, 2]^2. */
static void quad(void) {
  static const float xy[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  static const float color[4][4] = {{0.9f, 0.2f, 0.1f, 0.1f}, {0.1f, 0.9f, 0.3f, 0.5f}, {0.2f, 0.4f, 0.95f, 0.9f}, {0.8f, 0.8f, 0.7f, 0.6f}};
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) {
    const float s = (xy[i][0] + 1.0f) * 0.5f, t = (xy[i][1] + 1.0f) * 0.5f;
    glColor4fv(color[i]);
    glMultiTexCoord2f(GL_TEXTURE0, s, t);
    glMultiTexCoord2f(GL_TEXTURE1, 2.0f * s, 2.0f * t);
    glVertex2f(0.96f * xy[i][0] + 0.011f, 0.96f * xy[i][1] + 0.007f);
  }
  glEnd();
}

static void record_state(ConfContext* c, const char* when) {
  static const GLenum pnames[] = {GL_TEXTURE_ENV_MODE, GL_COMBINE_RGB, GL_COMBINE_ALPHA, GL_SOURCE0_RGB, GL_SOURCE1_RGB,
                                  GL_SOURCE2_RGB, GL_SOURCE0_ALPHA, GL_SOURCE1_ALPHA, GL_SOURCE2_ALPHA,
                                  GL_OPERAND0_RGB, GL_OPERAND1_RGB, GL_OPERAND2_RGB, GL_OPERAND0_ALPHA,
                                  GL_OPERAND1_ALPHA, GL_OPERAND2_ALPHA, GL_RGB_SCALE, GL_ALPHA_SCALE};
  const int n = (int)(sizeof pnames / sizeof pnames[0]);
  char label[160];
  GLint active = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  for (int u = 0; u < 2; ++u) {
    double d[2 * 17];
    glActiveTexture(GL_TEXTURE0 + u);
    for (int k = 0; k < n; ++k) {
      GLint i = 0;
      GLfloat f = 0.0f;
      glGetTexEnviv(GL_TEXTURE_ENV, pnames[k], &i);
      glGetTexEnvfv(GL_TEXTURE_ENV, pnames[k], &f);
      d[2 * k] = i, d[2 * k + 1] = f;
    }
    snprintf(label, sizeof label, "%s unit %d", when, u);
    conf_values(c, label, d, 2 * n);
  }
  glActiveTexture((GLenum)active);
  snprintf(label, sizeof label, "%s error", when);
  conf_error(c, label);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 320, 240)) return 1;
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  record_state(&c, "initial");
  make_textures();
  const float constant[4] = {0.3f, 0.7f, 0.5f, 0.35f};

  cell(&c, 0, 0); /* REPLACE the texture's colour, the previous alpha */
  combine(0, checker, GL_REPLACE, GL_REPLACE);
  env(GL_SOURCE0_ALPHA, GL_PREVIOUS);
  quad();
  record_state(&c, "replace");
  reset();

  cell(&c, 1, 0); /* MODULATE scaled by 2 */
  combine(0, checker, GL_MODULATE, GL_MODULATE);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0f);
  quad();
  record_state(&c, "modulate x2");
  reset();

  cell(&c, 2, 0); /* ADD, colour and alpha, blended */
  combine(0, ramp, GL_ADD, GL_ADD);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  quad();
  glDisable(GL_BLEND);
  record_state(&c, "add");
  reset();

  cell(&c, 3, 0); /* ADD_SIGNED scaled by 2 */
  combine(0, checker, GL_ADD_SIGNED, GL_REPLACE);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0f);
  quad();
  record_state(&c, "add signed");
  reset();

  cell(&c, 0, 1); /* INTERPOLATE unit 0's and unit 1's texels by the primary alpha (crossbar) */
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, ramp);
  glEnable(GL_TEXTURE_2D);
  env(GL_TEXTURE_ENV_MODE, GL_REPLACE);
  combine(0, checker, GL_INTERPOLATE, GL_REPLACE);
  env(GL_SOURCE0_RGB, GL_TEXTURE0);
  env(GL_SOURCE1_RGB, GL_TEXTURE1);
  env(GL_SOURCE2_RGB, GL_PRIMARY_COLOR);
  env(GL_OPERAND2_RGB, GL_SRC_ALPHA);
  glActiveTexture(GL_TEXTURE1);
  env(GL_TEXTURE_ENV_MODE, GL_COMBINE);
  env(GL_COMBINE_RGB, GL_REPLACE);
  env(GL_SOURCE0_RGB, GL_PREVIOUS);
  quad();
  record_state(&c, "interpolate");
  reset();

  cell(&c, 1, 1); /* SUBTRACT: the primary colour minus the texture */
  combine(0, ramp, GL_SUBTRACT, GL_SUBTRACT);
  env(GL_SOURCE0_RGB, GL_PRIMARY_COLOR);
  env(GL_SOURCE1_RGB, GL_TEXTURE);
  env(GL_SOURCE0_ALPHA, GL_CONSTANT);
  env(GL_SOURCE1_ALPHA, GL_PRIMARY_COLOR);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
  quad();
  record_state(&c, "subtract");
  reset();

  cell(&c, 2, 1); /* DOT3_RGB: a normal map against the light vector in the primary colour,
                   * then modulated by a checker on unit 1 */
  combine(0, normals, GL_DOT3_RGB, GL_REPLACE);
  env(GL_SOURCE1_RGB, GL_PRIMARY_COLOR);
  env(GL_SOURCE0_ALPHA, GL_PRIMARY_COLOR);
  combine(1, checker, GL_MODULATE, GL_REPLACE);
  env(GL_SOURCE0_ALPHA, GL_PREVIOUS);
  quad();
  record_state(&c, "dot3 rgb");
  reset();

  cell(&c, 3, 1); /* DOT3_RGBA against the constant colour, scaled by 2 */
  combine(0, normals, GL_DOT3_RGBA, GL_MODULATE);
  env(GL_SOURCE1_RGB, GL_CONSTANT);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  quad();
  glDisable(GL_BLEND);
  record_state(&c, "dot3 rgba");
  reset();

  cell(&c, 0, 2); /* one-minus operands with the constant colour */
  combine(0, checker, GL_MODULATE, GL_ADD);
  env(GL_SOURCE1_RGB, GL_CONSTANT);
  env(GL_OPERAND0_RGB, GL_ONE_MINUS_SRC_COLOR);
  env(GL_OPERAND1_RGB, GL_ONE_MINUS_SRC_ALPHA);
  env(GL_OPERAND0_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
  quad();
  record_state(&c, "operands");
  reset();

  cell(&c, 1, 2); /* two combining units: modulate, then interpolate with the constant alpha */
  combine(0, checker, GL_MODULATE, GL_MODULATE);
  combine(1, ramp, GL_INTERPOLATE, GL_REPLACE);
  env(GL_SOURCE0_RGB, GL_PREVIOUS);
  env(GL_SOURCE1_RGB, GL_TEXTURE);
  env(GL_SOURCE2_RGB, GL_CONSTANT);
  env(GL_OPERAND2_RGB, GL_SRC_ALPHA);
  env(GL_SOURCE0_ALPHA, GL_PREVIOUS);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
  quad();
  record_state(&c, "two units");
  reset();

  cell(&c, 2, 2); /* GL_ALPHA_SCALE 4, blended */
  combine(0, ramp, GL_REPLACE, GL_MODULATE);
  glTexEnvi(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 4);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  quad();
  glDisable(GL_BLEND);
  record_state(&c, "alpha scale");
  reset();

  cell(&c, 3, 2); /* compiled into a list, changed under glPushAttrib, restored */
  {
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    combine(0, checker, GL_ADD_SIGNED, GL_MODULATE);
    env(GL_SOURCE1_RGB, GL_PRIMARY_COLOR);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 4.0f);
    glEndList();
    glCallList(list);
    glPushAttrib(GL_TEXTURE_BIT);
    env(GL_COMBINE_RGB, GL_SUBTRACT);
    env(GL_SOURCE1_RGB, GL_CONSTANT);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 1.0f);
    record_state(&c, "pushed");
    glPopAttrib();
    quad();
    record_state(&c, "popped");
  }
  reset();

  /* Errors. */
  glActiveTexture(GL_TEXTURE0);
  env(GL_COMBINE_ALPHA, GL_DOT3_RGB);
  conf_error(&c, "DOT3_RGB for alpha");
  env(GL_COMBINE_RGB, GL_BLEND);
  conf_error(&c, "BLEND as a function");
  env(GL_SOURCE0_RGB, GL_TEXTURE0 + 100);
  conf_error(&c, "GL_TEXTURE100 as a source");
  env(GL_SOURCE2_ALPHA, GL_SRC_COLOR);
  conf_error(&c, "SRC_COLOR as a source");
  env(GL_OPERAND1_ALPHA, GL_SRC_COLOR);
  conf_error(&c, "SRC_COLOR as an alpha operand");
  env(GL_OPERAND0_RGB, GL_CONSTANT);
  conf_error(&c, "CONSTANT as an operand");
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3.0f);
  conf_error(&c, "RGB_SCALE 3");
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 0.5f);
  conf_error(&c, "ALPHA_SCALE 0.5");
  env(GL_TEXTURE_ENV_MODE, GL_COMBINE);
  conf_error(&c, "GL_COMBINE accepted");
  record_state(&c, "after errors");
  return conf_finish(&c);
}
