/* Texture environments on lit, textured spheres: GL_MODULATE, GL_REPLACE and GL_DECAL with an
 * RGB texture (top row) and an RGBA texture whose alpha falls from left to right, blended over
 * a striped backdrop (middle row; DECAL with RGBA mixes the lit colour and the texture by the
 * texture's alpha and keeps the fragment's alpha). Bottom row: the separate specular colour
 * (GL_LIGHT_MODEL_COLOR_CONTROL, OpenGL 1.2): a dark modulated texture with a single colour (the
 * highlight is darkened by the texture) and with GL_SEPARATE_SPECULAR_COLOR (a white highlight
 * added after texturing), and GL_REPLACE with the separate specular colour. */
#include <math.h>

#include "conf.h"

static GLuint make_texture(int with_alpha) {
  static unsigned char texels[32 * 32 * 4];
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      unsigned char* t = &texels[(y * 32 + x) * 4];
      int on = ((x / 4) + (y / 4)) % 2;
      t[0] = (unsigned char)(on ? 240 : 30);
      t[1] = (unsigned char)(on ? 200 : 90 + 4 * y);
      t[2] = (unsigned char)(on ? 60 : 200);
      t[3] = (unsigned char)(with_alpha ? 255 - 8 * x : 255);
    }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, with_alpha ? GL_RGBA : GL_RGB, 32, 32, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, texels);
  return tex;
}

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 3, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.1, 1.1, -1.1, 1.1, -2.0, 2.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void backdrop(void) {
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) {
    glColor3f(i % 2 ? 0.9f : 0.1f, 0.3f, i % 2 ? 0.1f : 0.8f);
    float x0 = -1.1f + 0.55f * i + 0.013f, x1 = x0 + 0.55f; /* edges off pixel centres */
    glVertex3f(x0, -1.1f, -1.5f);
    glVertex3f(x1, -1.1f, -1.5f);
    glVertex3f(x1, 1.1f, -1.5f);
    glVertex3f(x0, 1.1f, -1.5f);
  }
  glEnd();
  glEnable(GL_LIGHTING);
  glEnable(GL_TEXTURE_2D);
}

static void sphere(void) {
  glPushMatrix();
  glRotatef(20.0f, 1, 0, 0);
  glRotatef(-30.0f, 0, 1, 0);
  conf_sphere(1.0f, 36, 18);
  glPopMatrix();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 255, 255)) return 1;
  glClearColor(0.2f, 0.2f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_TEXTURE_2D);
  const GLfloat dir[] = {-0.5f, 0.6f, 1, 0}, dif[] = {0.7f, 0.9f, 0.6f, 0.8f};
  const GLfloat spec[] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
  GLuint rgb = make_texture(0), rgba = make_texture(1);
  static const GLint envs[3] = {GL_MODULATE, GL_REPLACE, GL_DECAL};

  glBindTexture(GL_TEXTURE_2D, rgb);
  for (int i = 0; i < 3; ++i) {
    cell(&c, i, 0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, envs[i]);
    sphere();
  }
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int i = 0; i < 3; ++i) {
    cell(&c, i, 1);
    backdrop();
    glBindTexture(GL_TEXTURE_2D, rgba);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, envs[i]);
    glEnable(GL_BLEND);
    sphere();
    glDisable(GL_BLEND);
  }

  /* Separate specular colour. A dark texture: modulate by (0.35, 0.35, 0.35). */
  glBindTexture(GL_TEXTURE_2D, rgb);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  const GLfloat dark[] = {0.35f, 0.35f, 0.35f, 1};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, dark);
  cell(&c, 0, 2);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  sphere();
  cell(&c, 1, 2);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  sphere();
  cell(&c, 2, 2);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  sphere();
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glDeleteTextures(1, &rgb);
  glDeleteTextures(1, &rgba);
  return conf_finish(&c);
}
