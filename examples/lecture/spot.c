/* Lecture 14, slides "Цагаан ханан дээрх cutoff angle өөрчлөлт" and "GL_SPOT_EXPONENT" (SPEC
 * figures 10 and 11): a spot light (GL_LIGHT2, direction (0, 0, -1)) on the white wall.
 * Top row: cutoff 50, 40, 30, 20 degrees (exponent 0): the lit disc shrinks, its radius on the
 * wall being 4 tan(cutoff). Bottom row: exponent 0, 10, 100 (cutoff 40): the light gathers
 * toward the centre.
 * Ours: the spot is 4 units in front of the 8 x 8 wall (at (0, 0, 4), the wall at z = 0),
 * viewer at (0, 0, 8) as in the other wall experiments; the wall is 48 x 48 quads so that the
 * per-vertex lighting draws a round disc; GL_LIGHT2's diffuse and specular are set to white (its
 * defaults are black). */
#include "common/lecture.h"

static void spot_panel(const LectureImage* img, int x, int y, int size, GLfloat cutoff,
                       GLfloat exponent) {
  glViewport(x, y, size, size);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lecture_perspective(60.0, 1.0, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0., 0., -8.); /* viewer at (0, 0, 8) */
  GLfloat position[] = {0., 0., 4., 1.};
  glLightfv(GL_LIGHT2, GL_POSITION, position);
  /* --- the lecture's code ------------------------------------------------------------- */
  GLfloat light_direction[] = {0, 0, -1};  // From the light
  glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, light_direction);
  glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, cutoff);     /* 20. in the lecture's example */
  glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, exponent); /* 10. in the lecture's example */
  /* --- end of the lecture's code ------------------------------------------------------ */
  wall(48);
  (void)img;
}

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_spot.png", 800, 400)) return 1;
  glClearColor(0.3f, 0.3f, 0.35f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT2);
  GLfloat white[] = {1., 1., 1., 1.};
  glLightfv(GL_LIGHT2, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT2, GL_SPECULAR, white);
  GLfloat ambient[] = {.2, .2, .2, 1.}, diffuse[] = {.8, .8, .8, 1.}, specular[] = {.3, .3, .3, 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 30.);
  static const GLfloat cutoffs[4] = {50., 40., 30., 20.};
  for (int i = 0; i < 4; ++i) spot_panel(&img, 200 * i, 200, 200, cutoffs[i], 0.);
  static const GLfloat exponents[3] = {0., 10., 100.};
  for (int i = 0; i < 3; ++i) spot_panel(&img, 100 + 200 * i, 0, 200, 40., exponents[i]);
  return lecture_end(&img);
}
