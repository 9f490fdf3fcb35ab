/* Lecture 14, slide "Гэрлийн үүсгүүрийн өнгөний компонентууд (r, g, b, a)" (SPEC figure 6):
 * the same teapot under GL_LIGHT0 with a grey ambient (.1, .1, .1) and white diffuse and
 * specular (left), and with a very pale red ambient (.1, 0, 0) and yellow diffuse and specular
 * (1, 1, 0) (right). The material is a white, fairly shiny one so that the light's colours show.
 * Light: directional from (1, 1, 1); camera (ours): perspective 40 degrees from 6 units. */
#include <GL/shadelab_glut.h>

#include "common/lecture.h"

void drawTeapot() { glutSolidTeapot(1.0); }

/* --- the lecture's code --------------------------------------------------------------- */
void greyWhiteLight() {
  GLfloat ambient0[] = {0.1, 0.1, 0.1, 1.};  // Grey
  GLfloat diffuse0[] = {1., 1., 1., 1.};     // White
  GLfloat specular0[] = {1., 1., 1., 1.};    // White
  glLightfv(GL_LIGHT0, GL_AMBIENT, ambient0);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse0);
  glLightfv(GL_LIGHT0, GL_SPECULAR, specular0);
}

void paleRedYellowLight() {
  GLfloat a[] = {0.1, 0., 0., 1.};  // Very pale red
  GLfloat d[] = {1., 1., 0., 1.};   // Yellow
  GLfloat s[] = {1., 1., 0., 1.};   // Yellow
  glLightfv(GL_LIGHT0, GL_AMBIENT, a);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, d);
  glLightfv(GL_LIGHT0, GL_SPECULAR, s);
}
/* --- end of the lecture's code ------------------------------------------------------- */

static void panel(const LectureImage* img, int index) { lecture_teapot_panel(img, index, 2); }

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_light_colours.png", 640, 320)) return 1;
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  GLfloat white[] = {.8, .8, .8, 1.}, spec[] = {1., 1., 1., 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, white);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, white);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 60.);
  /* No global ambient, so that only the light's own ambient colour fills the shadows. */
  GLfloat no_global[] = {0., 0., 0., 1.};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, no_global);

  panel(&img, 0);
  greyWhiteLight();
  drawTeapot();
  panel(&img, 1);
  paleRedYellowLight();
  drawTeapot();
  return lecture_end(&img);
}
