/* Lecture 14, slide "point light source хувьд, attenuation factor" (SPEC figure 9): a point
 * light (GL_LIGHT1) 2 units in front of the white wall, without attenuation (the defaults
 * a = 1, b = 0, c = 0; left) and with the lecture's constants: constant 0, linear .5,
 * quadratic 0 (right), i.e. A_f = 1 / (.5 d): 1 at the wall's centre (d = 2), a third at its
 * corners (d = 6). Ours: the light at (0, 0, 2), the 8 x 8 wall (40 x 40 quads) at z = 0, viewer
 * at (0, 0, 8); GL_LIGHT1's colours set to white (its defaults are black). */
#include "common/lecture.h"

static void panel(const LectureImage* img, int index) {
  double aspect = lecture_panel(img, index, 2, 0, 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lecture_perspective(60.0, aspect, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0., 0., -8.); /* viewer at (0, 0, 8) */
  GLfloat position[] = {0., 0., 2., 1.};
  glLightfv(GL_LIGHT1, GL_POSITION, position);
  wall(40);
}

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_attenuation.png", 640, 320)) return 1;
  glClearColor(0.3f, 0.3f, 0.35f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT1);
  GLfloat white[] = {1., 1., 1., 1.};
  glLightfv(GL_LIGHT1, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT1, GL_SPECULAR, white);
  GLfloat ambient[] = {.2, .2, .2, 1.}, diffuse[] = {.8, .8, .8, 1.}, specular[] = {.3, .3, .3, 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 30.);

  panel(&img, 0); /* default: a = 1, b = 0, c = 0 (no attenuation) */
  /* --- the lecture's code ------------------------------------------------------------- */
  glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, .0);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, .5);
  glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.);
  /* --- end of the lecture's code ------------------------------------------------------ */
  panel(&img, 1);
  return lecture_end(&img);
}
