/* Directional lights (w = 0): one white light with a specular highlight, three coloured lights
 * with their own ambient terms and a changed global ambient, all eight lights at once, and a
 * light whose direction is given under a rotated modelview (positions are transformed by the
 * modelview in force at the glLight call). Smooth shading, perspective (glFrustum). */
#include <math.h>

#include "conf.h"

static void material(const GLfloat* amb, const GLfloat* dif, const GLfloat* spec, GLfloat shin) {
  glMaterialfv(GL_FRONT, GL_AMBIENT, amb);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, shin);
}

static void camera(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.55, 0.55, -0.55, 0.55, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void sphere_at_origin(void) {
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, -4.0f);
  conf_sphere(1.3f, 40, 20);
  glPopMatrix();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glShadeModel(GL_SMOOTH);

  /* Panel 1: the default light 0 turned to (1, 1, 1, 0), red plastic. */
  const GLfloat red_a[] = {0.3f, 0.05f, 0.05f, 1}, red_d[] = {0.8f, 0.1f, 0.1f, 1};
  const GLfloat white[] = {1, 1, 1, 1}, black[] = {0, 0, 0, 1};
  conf_panel(&c, 0, 0, 2, 2);
  camera();
  const GLfloat dir1[] = {1, 1, 1, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, dir1);
  glEnable(GL_LIGHT0);
  material(red_a, red_d, white, 32.0f);
  sphere_at_origin();

  /* Panel 2: three coloured lights with ambient parts, global ambient (0.05, 0.1, 0.05). */
  conf_panel(&c, 1, 0, 2, 2);
  camera();
  const GLfloat global[] = {0.05f, 0.1f, 0.05f, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, global);
  glDisable(GL_LIGHT0);
  const GLfloat pos[3][4] = {{-1, 0.3f, 0.6f, 0}, {1, 0.3f, 0.6f, 0}, {0, -1, 0.4f, 0}};
  const GLfloat col[3][4] = {{0.9f, 0.2f, 0.1f, 1}, {0.1f, 0.9f, 0.2f, 1}, {0.2f, 0.3f, 1, 1}};
  const GLfloat amb[3][4] = {{0.1f, 0, 0, 1}, {0, 0.1f, 0, 1}, {0, 0, 0.1f, 1}};
  for (int i = 0; i < 3; ++i) {
    glLightfv(GL_LIGHT1 + i, GL_POSITION, pos[i]);
    glLightfv(GL_LIGHT1 + i, GL_DIFFUSE, col[i]);
    glLightfv(GL_LIGHT1 + i, GL_SPECULAR, col[i]);
    glLightfv(GL_LIGHT1 + i, GL_AMBIENT, amb[i]);
    glEnable(GL_LIGHT1 + i);
  }
  const GLfloat grey_a[] = {0.5f, 0.5f, 0.5f, 1}, grey_d[] = {0.7f, 0.7f, 0.7f, 1};
  const GLfloat spec[] = {0.6f, 0.6f, 0.6f, 1};
  material(grey_a, grey_d, spec, 20.0f);
  sphere_at_origin();

  /* Panel 3: all eight lights, dim and from different directions. */
  conf_panel(&c, 0, 1, 2, 2);
  camera();
  for (int i = 0; i < 8; ++i) {
    double t = 2.0 * CONF_PI * i / 8.0;
    GLfloat p[4] = {(GLfloat)cos(t), (GLfloat)sin(t), 0.8f, 0.0f};
    GLfloat d[4] = {0.06f + 0.05f * (i % 3), 0.06f + 0.05f * ((i + 1) % 3),
                    0.06f + 0.05f * ((i + 2) % 3), 1.0f};
    glLightfv(GL_LIGHT0 + i, GL_POSITION, p);
    glLightfv(GL_LIGHT0 + i, GL_DIFFUSE, d);
    glLightfv(GL_LIGHT0 + i, GL_SPECULAR, d);
    glLightfv(GL_LIGHT0 + i, GL_AMBIENT, black);
    glEnable(GL_LIGHT0 + i);
  }
  material(black, white, white, 64.0f);
  sphere_at_origin();

  /* Panel 4: a single light whose direction (0, 0, 1, 0) is given under a modelview rotated by
   * 60 degrees about y and 30 about x: it must light the sphere from the upper right. */
  conf_panel(&c, 1, 1, 2, 2);
  camera();
  for (int i = 1; i < 8; ++i) glDisable(GL_LIGHT0 + i);
  const GLfloat yellow[] = {1, 0.9f, 0.4f, 1}, blueish[] = {0.3f, 0.5f, 1, 1};
  glPushMatrix();
  glRotatef(60.0f, 0, 1, 0);
  glRotatef(-30.0f, 1, 0, 0);
  const GLfloat z[] = {0, 0, 1, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, z);
  glPopMatrix();
  glLightfv(GL_LIGHT0, GL_DIFFUSE, yellow);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  material(black, blueish, white, 128.0f);
  sphere_at_origin();
  return conf_finish(&c);
}
