/* Lecture 14, slide "Shiny Teapot" and "shiny red материалын тусгалыг тодорхойлох" (SPEC
 * figure 4): ambient = diffuse (.41, .135, .067, 1), specular (1, 1, 1, 1), shininess 125,
 * under a white directional light from (1, 1, 1). The highlight is white, the colour of the
 * light. Camera (ours): perspective 40 degrees from 6 units, slightly above. */
#include <GL/shadelab_glut.h>

#include "common/lecture.h"

void drawTeapot() { glutSolidTeapot(1.0); }

/* --- the lecture's code --------------------------------------------------------------- */
void shinyRedMaterial() {
  GLfloat diffuse[] = {.41, .135, .067, 1.};
  GLfloat specular[] = {1., 1., 1., 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, diffuse);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 125.);
}
/* --- end of the lecture's code ------------------------------------------------------- */

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_shiny_teapot.png", 400, 400)) return 1;
  glClearColor(0.9f, 0.9f, 0.9f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  lecture_teapot_view(1.0); /* light from (1, 1, 1) in eye space; the teapot 6 units away */
  shinyRedMaterial();
  drawTeapot();
  return lecture_end(&img);
}
