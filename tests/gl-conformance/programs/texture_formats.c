/* Every OpenGL 1.1 internal format (1-4, the ALPHA, LUMINANCE, LUMINANCE_ALPHA, INTENSITY,
 * RGB and RGBA families with their sized variants, R3_G3_B2) under every texture environment
 * mode (GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND with an environment colour), on a lit,
 * translucent surface blended over a checker, so that what each format keeps of the colour and
 * alpha, its precision, and how each mode combines each base format all show (OpenGL 1.1
 * sections 3.8.1, 3.8.9, tables 3.15, 3.22). A row per format, a column per mode. The
 * component sizes and internal format each reports and the texels glGetTexImage returns (as
 * floats, so the stored precision is compared exactly) are recorded with conf_value. */
#include <stdio.h>

#include "conf.h"

static const GLint kFormats[] = {
    1, 2, 3, 4, GL_ALPHA, GL_ALPHA4, GL_ALPHA8, GL_ALPHA12, GL_ALPHA16, GL_LUMINANCE, GL_LUMINANCE4,
    GL_LUMINANCE8, GL_LUMINANCE12, GL_LUMINANCE16, GL_LUMINANCE_ALPHA, GL_LUMINANCE4_ALPHA4,
    GL_LUMINANCE6_ALPHA2, GL_LUMINANCE8_ALPHA8, GL_LUMINANCE12_ALPHA4, GL_LUMINANCE12_ALPHA12,
    GL_LUMINANCE16_ALPHA16, GL_INTENSITY, GL_INTENSITY4, GL_INTENSITY8, GL_INTENSITY12, GL_INTENSITY16, GL_RGB,
    GL_R3_G3_B2, GL_RGB4, GL_RGB5, GL_RGB8, GL_RGB10, GL_RGB12, GL_RGB16, GL_RGBA, GL_RGBA2, GL_RGBA4,
    GL_RGB5_A1, GL_RGBA8, GL_RGB10_A2, GL_RGBA12, GL_RGBA16};
#define N_FORMATS ((int)(sizeof kFormats / sizeof kFormats[0]))
static const GLenum kModes[4] = {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND};

static unsigned char g_texels[8 * 8 * 4];

/* 8x8 texels: hue-like colours, alpha from 0 to 255 across, with values that round
 * differently at 1 to 5 bits. */
static void make_texels(void) {
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      unsigned char* t = &g_texels[(y * 8 + x) * 4];
      t[0] = (unsigned char)(x * 36 + y * 3);
      t[1] = (unsigned char)(255 - y * 34 - x);
      t[2] = (unsigned char)((x + y) * 17 + 5);
      t[3] = (unsigned char)(x * 32 + y * 4 + 3);
    }
}

static void record_format(ConfContext* c, GLint internal) {
  static const GLenum names[] = {GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_RED_SIZE,     GL_TEXTURE_GREEN_SIZE,
                                 GL_TEXTURE_BLUE_SIZE,       GL_TEXTURE_ALPHA_SIZE,   GL_TEXTURE_LUMINANCE_SIZE,
                                 GL_TEXTURE_INTENSITY_SIZE};
  char key[96];
  for (int i = 0; i < 7; ++i) {
    GLint v = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, names[i], &v);
    snprintf(key, sizeof key, "format 0x%04x pname 0x%04x", internal, names[i]);
    conf_value(c, key, v);
  }
  static GLfloat texels[8 * 8 * 4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, texels);
  for (int i = 0; i < 16; ++i) {
    snprintf(key, sizeof key, "format 0x%04x texel %d", internal, i);
    conf_values(c, key, (double[]){texels[i * 4], texels[i * 4 + 1], texels[i * 4 + 2], texels[i * 4 + 3]}, 4);
  }
  snprintf(key, sizeof key, "format 0x%04x", internal);
  conf_error(c, key);
}

static void checker(const ConfContext* c) {
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_BLEND);
  glViewport(0, 0, c->width, c->height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, c->width, 0, c->height, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_QUADS);
  for (int y = 0; y < c->height; y += 6)
    for (int x = 0; x < c->width; x += 6) {
      float g = ((x + y) / 6) % 2 ? 0.85f : 0.35f;
      glColor3f(g, g, g);
      glVertex2i(x, y);
      glVertex2i(x + 6, y);
      glVertex2i(x + 6, y + 6);
      glVertex2i(x, y + 6);
    }
  glEnd();
}

static void lit_cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 8, N_FORMATS / 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat light[4] = {-0.8f, 0.9f, 1.2f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  conf_wall(1.9f, 1.9f, 4);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 8 * 36, N_FORMATS / 2 * 22)) return 1;
  make_texels();
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  checker(&c);

  const GLfloat diffuse[4] = {0.9f, 0.8f, 0.7f, 0.75f}, ambient[4] = {0.3f, 0.3f, 0.35f, 0.75f};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
  const GLfloat env[4] = {0.2f, 0.55f, 0.95f, 0.6f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int f = 0; f < N_FORMATS; ++f) {
    glTexImage2D(GL_TEXTURE_2D, 0, kFormats[f], 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_texels);
    record_format(&c, kFormats[f]);
    for (int m = 0; m < 4; ++m) {
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)kModes[m]);
      glEnable(GL_LIGHTING);
      glEnable(GL_LIGHT0);
      glEnable(GL_TEXTURE_2D);
      glEnable(GL_BLEND);
      lit_cell(&c, (f % 2) * 4 + m, f / 2);
    }
  }
  return conf_finish(&c);
}
