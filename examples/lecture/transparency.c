/* Lecture 14, slides "Transparent Objects" (SPEC figure 15 and section 5): 1. the blending
 * function src * alpha + dst * (1 - alpha) and glEnable(GL_BLEND); 2. the lecture's
 * transMaterial1 (ambient = diffuse (.7, 1, .85, .3), specular 1, shininess 100); 3. the
 * background (opaque) objects first, then the transparent one, both faces filled (no culling).
 * Ours: a checkered floor and wall and an opaque red sphere and blue cube behind a transparent
 * teapot, white light from (1, 1, 1); camera perspective 40 degrees from 7 units. */
#include <GL/shadelab_glut.h>

#include "common/lecture.h"

/* --- the lecture's code --------------------------------------------------------------- */
void transMaterial1() {
  GLfloat a[] = {.7, 1., .85, .3};
  GLfloat s[] = {1., 1., 1., 1.};

  glMaterialfv(GL_FRONT, GL_AMBIENT, a);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, a);
  glMaterialfv(GL_FRONT, GL_SPECULAR, s);

  glMaterialf(GL_FRONT, GL_SHININESS, 100.);
}
/* --- end of the lecture's code ------------------------------------------------------- */

static void opaque(const GLfloat* colour) {
  GLfloat spec[] = {.4, .4, .4, 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, colour);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, colour);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 30.);
}

static void checker_floor_and_wall(void) {
  GLfloat light[] = {.85, .85, .8, 1.}, dark[] = {.25, .25, .3, 1.};
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 10; ++i) {
      opaque((i + j) % 2 ? light : dark);
      float x = -5. + i, z = -5. + j, y = -1.5 + j * .9;
      glBegin(GL_QUADS);
      glNormal3f(0., 1., 0.); /* floor at y = -1.5 */
      glVertex3f(x, -1.5, z + 1.), glVertex3f(x + 1., -1.5, z + 1.);
      glVertex3f(x + 1., -1.5, z), glVertex3f(x, -1.5, z);
      glNormal3f(0., 0., 1.); /* wall at z = -5 */
      glVertex3f(x, y, -5.), glVertex3f(x + 1., y, -5.);
      glVertex3f(x + 1., y + .9, -5.), glVertex3f(x, y + .9, -5.);
      glEnd();
    }
}

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_transparency.png", 480, 360)) return 1;
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glMatrixMode(GL_PROJECTION);
  lecture_perspective(40.0, 480.0 / 360.0, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0., -.3, -7.);
  glRotatef(15., 1., 0., 0.);
  GLfloat light_position[] = {1., 1., 1., 0.};
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);

  /* 3. Background (opaque) objects first. */
  checker_floor_and_wall();
  GLfloat red[] = {.8, .1, .1, 1.}, blue[] = {.15, .25, .8, 1.};
  opaque(red);
  glPushMatrix();
  glTranslatef(-.9, -.4, -2.5);
  glutSolidSphere(1., 40, 20);
  glPopMatrix();
  opaque(blue);
  glPushMatrix();
  glTranslatef(1.6, -.7, -2.);
  glRotatef(30., 0., 1., 0.);
  glutSolidCube(1.4);
  glPopMatrix();

  /* --- the lecture's code ------------------------------------------------------------- */
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_BLEND);
  transMaterial1();
  /* --- end of the lecture's code ------------------------------------------------------ */
  glPushMatrix();
  glTranslatef(0., -.3, 0.);
  glRotatef(-25., 0., 1., 0.);
  glutSolidTeapot(1.2); /* both faces filled: no culling */
  glPopMatrix();
  glDisable(GL_BLEND);
  return lecture_end(&img);
}
