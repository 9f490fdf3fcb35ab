/* Lecture 14, slide "The pale yellowish pink material of Lok Yau Hall" (SPEC figure 13): the
 * lecture's material (ambient (.6, .59, .42), diffuse (.5, .5, .35), specular (.1, .1, .07),
 * shininess 1: a matte stone) under a directional white light coming from (1, 1, 1), on a small
 * neoclassical hall of our own: steps, a colonnade of six square columns, the main block, an
 * entablature and a triangular pediment. Camera (ours): perspective 35 degrees, from the front
 * left and a little above. The ground is a green lawn in a material of its own. */
#include "common/lecture.h"

/* --- the lecture's code --------------------------------------------------------------- */
void lokYauHallMaterial() {
  GLfloat ambient[] = {.6, .59, .42, 1.};
  GLfloat diffuse[] = {.5, .5, .35, 1.};
  GLfloat specular[] = {.1, .1, .07, 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 1.);
}
/* --- end of the lecture's code ------------------------------------------------------- */

/* An axis-aligned box from (x0, y0, z0) to (x1, y1, z1), one normal per face. */
void box(float x0, float y0, float z0, float x1, float y1, float z1) {
  glBegin(GL_QUADS);
  glNormal3f(0., 0., 1.);
  glVertex3f(x0, y0, z1), glVertex3f(x1, y0, z1), glVertex3f(x1, y1, z1), glVertex3f(x0, y1, z1);
  glNormal3f(0., 0., -1.);
  glVertex3f(x1, y0, z0), glVertex3f(x0, y0, z0), glVertex3f(x0, y1, z0), glVertex3f(x1, y1, z0);
  glNormal3f(1., 0., 0.);
  glVertex3f(x1, y0, z1), glVertex3f(x1, y0, z0), glVertex3f(x1, y1, z0), glVertex3f(x1, y1, z1);
  glNormal3f(-1., 0., 0.);
  glVertex3f(x0, y0, z0), glVertex3f(x0, y0, z1), glVertex3f(x0, y1, z1), glVertex3f(x0, y1, z0);
  glNormal3f(0., 1., 0.);
  glVertex3f(x0, y1, z1), glVertex3f(x1, y1, z1), glVertex3f(x1, y1, z0), glVertex3f(x0, y1, z0);
  glNormal3f(0., -1., 0.);
  glVertex3f(x0, y0, z0), glVertex3f(x1, y0, z0), glVertex3f(x1, y0, z1), glVertex3f(x0, y0, z1);
  glEnd();
}

/* The pediment: a triangular prism from z0 to z1 over the width [x0, x1], base at y, apex h. */
void pediment(float x0, float x1, float y, float h, float z0, float z1) {
  float xm = .5 * (x0 + x1), half = .5 * (x1 - x0);
  glBegin(GL_TRIANGLES);
  glNormal3f(0., 0., 1.);
  glVertex3f(x0, y, z1), glVertex3f(x1, y, z1), glVertex3f(xm, y + h, z1);
  glEnd();
  glBegin(GL_QUADS);
  glNormal3f(h, half, 0.); /* the right slope (GL_NORMALIZE makes it unit length) */
  glVertex3f(x1, y, z1), glVertex3f(x1, y, z0), glVertex3f(xm, y + h, z0), glVertex3f(xm, y + h, z1);
  glNormal3f(-h, half, 0.);
  glVertex3f(x0, y, z0), glVertex3f(x0, y, z1), glVertex3f(xm, y + h, z1), glVertex3f(xm, y + h, z0);
  glEnd();
}

void hall() {
  box(-3.2, -1.6, -1.6, 3.2, -1.4, 1.6); /* steps */
  box(-3.0, -1.4, -1.4, 3.0, -1.2, 1.4);
  box(-2.8, -1.2, -1.2, 2.8, 0.9, -0.3); /* the main block behind the colonnade */
  for (int i = 0; i < 6; ++i) {         /* columns */
    float x = -2.4 + .96 * i;
    box(x - .16, -1.2, .55, x + .16, 0.9, .87);
  }
  box(-2.9, 0.9, -1.3, 2.9, 1.25, 1.0); /* entablature */
  pediment(-2.9, 2.9, 1.25, 0.8, -1.3, 1.0);
}

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_lok_yau_hall.png", 480, 360)) return 1;
  glClearColor(0.55f, 0.7f, 0.9f, 1.0f); /* a sky */
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glMatrixMode(GL_PROJECTION);
  lecture_perspective(35.0, 480.0 / 360.0, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  /* The light source is a directional white light coming from (1, 1, 1), in world space. */
  glTranslatef(0., -0.2, -11.);
  glRotatef(15., 1., 0., 0.);
  glRotatef(25., 0., 1., 0.);
  GLfloat light_position[] = {1., 1., 1., 0.};
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);

  GLfloat lawn[] = {.25, .4, .2, 1.}, none[] = {0., 0., 0., 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, lawn);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, lawn);
  glMaterialfv(GL_FRONT, GL_SPECULAR, none);
  box(-6., -1.8, -5., 6., -1.6, 5.);
  lokYauHallMaterial();
  hall();
  return lecture_end(&img);
}
