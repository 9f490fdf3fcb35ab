/* Lecture 14, slide "Гэрэлтүүлсэн ба гэрэлтүүлээгүй" (lit and unlit; SPEC figure 1) and
 * "Enable/Disable lighting": the same teapot with glDisable(GL_LIGHTING), where it takes the
 * current colour and looks flat, and with glEnable(GL_LIGHTING) ("colors are ignored"), where the
 * material and a white directional light from (1, 1, 1) give it its shape. Camera (ours):
 * perspective 40 degrees from 6 units. */
#include <GL/shadelab_glut.h>

#include "common/lecture.h"

void drawTeapot() { glutSolidTeapot(1.0); }

static void panel(const LectureImage* img, int index) { lecture_teapot_panel(img, index, 2); }

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_lit_vs_unlit.png", 640, 320)) return 1;
  glClearColor(0.9f, 0.9f, 0.9f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  GLfloat diffuse[] = {.41, .135, .067, 1.}, specular[] = {1., 1., 1., 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, diffuse);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 60.);
  glColor3f(.41, .135, .067);

  panel(&img, 0);
  glDisable(GL_LIGHTING);
  drawTeapot();
  panel(&img, 1);
  glEnable(GL_LIGHTING);  // colors are ignored
  drawTeapot();
  return lecture_end(&img);
}
