/* Lecture 14, slide "mesh sizes (Important) өөрчлөлт" (SPEC figure 7): a shiny white wall
 * rendered with Gouraud shading under a directional white light, tessellated 1 x 1, 2 x 2,
 * 4 x 4, 10 x 10 and 20 x 20. Lighting is computed at the vertices only, so the 1 x 1 wall has
 * no highlight in its middle (its four corners are all far from the highlight) and the
 * highlight appears, and sharpens, as vertices come near its centre.
 *   example_mesh_size [OUTPUT.png]            the five sizes side by side
 *   example_mesh_size [OUTPUT.png] --mesh N   one N x N wall
 * Light and viewer as in the lecture: ambient 0, diffuse (.7, .7, .7), specular (1, 1, 1),
 * direction (0, 0, 1, 0); viewing position (0, 0, 8). Ours: the wall is 8 x 8 at z = 0 and
 * nearly fills a 60-degree view; the material is white with specular 1 and shininess 128 so the highlight is
 * a spot; GL_LIGHT_MODEL_LOCAL_VIEWER is on (the lecture turns it on just before this slide), so
 * the highlight has a place: where the half vector of (0, 0, 1) and the direction to the eye is
 * the wall's normal, its centre. */
#include <stdlib.h>

#include "common/lecture.h"

/* --- the lecture's code --------------------------------------------------------------- */
void wallLight() {
  GLfloat ambient0[] = {0., 0., 0., 1.};
  GLfloat diffuse0[] = {.7, .7, .7, 1.};
  GLfloat specular0[] = {1., 1., 1., 1.};
  GLfloat position[] = {0., 0., 1., 0.};  // Light direction
  glLightfv(GL_LIGHT0, GL_AMBIENT, ambient0);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse0);
  glLightfv(GL_LIGHT0, GL_SPECULAR, specular0);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
}
/* --- end of the lecture's code ------------------------------------------------------- */

static void draw_panel(const LectureImage* img, int index, int count, int n) {
  double aspect = lecture_panel(img, index, count, 0, 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lecture_perspective(60.0, aspect, 1.0, 20.0); /* 9.2 units seen at 8: a margin round the wall */
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  wallLight(); /* in eye space: the direction (0, 0, 1) points at the viewer */
  glTranslatef(0., 0., -8.); /* Viewing position (0, 0, 8) */
  wall(n);
}

int main(int argc, char** argv) {
  const char* mesh = lecture_option(argc, argv, "--mesh");
  int single = mesh ? atoi(mesh) : 0;
  if (mesh && (single < 1 || single > 200)) return 1;
  static const int sizes[5] = {1, 2, 4, 10, 20};
  int count = single ? 1 : 5;
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_mesh_size.png", 200 * count, 200)) return 1;
  glClearColor(0.3f, 0.3f, 0.35f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glShadeModel(GL_SMOOTH); /* Gouraud */
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  GLfloat ambient[] = {.2, .2, .2, 1.}, diffuse[] = {.5, .5, .5, 1.}, specular[] = {1., 1., 1., 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 128.);
  for (int i = 0; i < count; ++i) draw_panel(&img, i, count, single ? single : sizes[i]);
  return lecture_end(&img);
}
