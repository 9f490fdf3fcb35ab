/* The GLUT-style solids of shadelab-glut (the same client code in both builds, so any
 * difference comes from the GL library): glutSolidTeapot, glutSolidSphere, glutSolidCube,
 * glutSolidTorus, glutSolidCone and glutSolidTetrahedron, lit smooth (the teapot flat too),
 * with the lecture's shiny red material. */
#include <GL/shadelab_glut.h>

#include "conf.h"

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 3, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.0f);
  glRotatef(25.0f, 1, 0, 0);
  glRotatef(-30.0f, 0, 1, 0);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 255, 255)) return 1;
  glClearColor(0.1f, 0.1f, 0.12f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  const GLfloat amb[] = {.41f, .135f, .067f, 1}, spec[] = {1, 1, 1, 1};
  glMaterialfv(GL_FRONT, GL_AMBIENT, amb);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, amb);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 60.0f);
  const GLfloat dir[] = {1, 1, 1, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);

  cell(&c, 0, 0);
  glutSolidTeapot(1.0);
  cell(&c, 1, 0);
  glShadeModel(GL_FLAT);
  glutSolidTeapot(1.0);
  glShadeModel(GL_SMOOTH);
  cell(&c, 2, 0);
  glutSolidSphere(1.0, 24, 12);
  cell(&c, 0, 1);
  glutSolidCube(1.4);
  cell(&c, 1, 1);
  glutSolidTorus(0.3, 0.9, 16, 32);
  cell(&c, 2, 1);
  glRotatef(-90.0f, 1, 0, 0); /* GLUT's cone points along +z */
  glTranslatef(0.0f, 0.0f, -0.8f);
  glutSolidCone(0.9, 1.6, 24, 4);
  cell(&c, 0, 2);
  glutSolidTetrahedron();
  cell(&c, 1, 2); /* two teapots, one scaled: GL_NORMALIZE keeps their shading equal */
  glTranslatef(-0.6f, 0.0f, 0.0f);
  glutSolidTeapot(0.5);
  glTranslatef(1.2f, 0.0f, 0.0f);
  glScalef(0.5f, 0.5f, 0.5f);
  glutSolidTeapot(1.0);
  cell(&c, 2, 2); /* cull back faces: a closed teapot looks the same */
  glEnable(GL_CULL_FACE);
  glutSolidTeapot(1.0);
  glDisable(GL_CULL_FACE);
  return conf_finish(&c);
}
