/* The light model: GL_LIGHT_MODEL_LOCAL_VIEWER off and on (a flat shiny wall under a
 * directional light: uniform with an infinite viewer, a highlight with a local one; and a shiny
 * sphere), and GL_LIGHT_MODEL_TWO_SIDE on and off with a different back material (an open tube
 * seen from above, its inside made of back faces). */
#include "conf.h"

static void camera(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void shiny_wall_and_sphere(GLint local_viewer) {
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, local_viewer);
  camera();
  const GLfloat dir[] = {0.5f, 0.6f, 1.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, -3.0f);
  conf_wall(3.0f, 3.0f, 40);
  glTranslatef(0.5f, -0.5f, 0.6f);
  conf_sphere(0.45f, 32, 16);
  glPopMatrix();
}

static void tube(GLint two_side) {
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, two_side);
  camera();
  const GLfloat pos[] = {-1.0f, 2.0f, 1.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glPushMatrix();
  glTranslatef(0.0f, -0.2f, -3.2f);
  glRotatef(50.0f, 1, 0, 0);
  glTranslatef(0.0f, -0.6f, 0.0f);
  conf_tube(0.9f, 1.2f, 48);
  glPopMatrix();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0.2f, 0.2f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat amb[] = {0.1f, 0.1f, 0.1f, 1}, dif[] = {0.4f, 0.45f, 0.5f, 1};
  const GLfloat white[] = {1, 1, 1, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
  conf_panel(&c, 0, 0, 2, 2);
  shiny_wall_and_sphere(GL_FALSE);
  conf_panel(&c, 1, 0, 2, 2);
  shiny_wall_and_sphere(GL_TRUE);

  /* Front: warm red; back: cool blue with its own highlight colour and shininess. */
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);
  const GLfloat f_amb[] = {0.3f, 0.05f, 0.05f, 1}, f_dif[] = {0.9f, 0.2f, 0.1f, 1};
  const GLfloat b_amb[] = {0.05f, 0.05f, 0.3f, 1}, b_dif[] = {0.1f, 0.3f, 0.9f, 1};
  const GLfloat b_spec[] = {0.5f, 1.0f, 0.5f, 1};
  glMaterialfv(GL_FRONT, GL_AMBIENT, f_amb);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, f_dif);
  glMaterialf(GL_FRONT, GL_SHININESS, 10.0f);
  glMaterialfv(GL_BACK, GL_AMBIENT, b_amb);
  glMaterialfv(GL_BACK, GL_DIFFUSE, b_dif);
  glMaterialfv(GL_BACK, GL_SPECULAR, b_spec);
  glMaterialf(GL_BACK, GL_SHININESS, 5.0f);
  conf_panel(&c, 0, 1, 2, 2);
  tube(GL_TRUE);
  conf_panel(&c, 1, 1, 2, 2);
  tube(GL_FALSE);
  return conf_finish(&c);
}
