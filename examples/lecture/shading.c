/* Lecture 14, slides "Constant (Flat) Shading", "Mach band" and "Gouraud shading" (SPEC
 * figure 17): the same coarse sphere (16 slices, 8 stacks) with glShadeModel(GL_FLAT) (one
 * colour per polygon, taken at its provoking vertex: facets and Mach bands at their edges)
 * and glShadeModel(GL_SMOOTH) (colours computed at the vertices and interpolated). Phong
 * shading (per-pixel normals) is not part of OpenGL 1.x; shadelab's own renderer has it.
 * Light: white, directional from (1, 1, 1); material: the shiny red of the lecture with
 * shininess 30; camera (ours): perspective 40 degrees from 5 units. */
#include <GL/shadelab_glut.h>

#include "common/lecture.h"

static void panel(const LectureImage* img, int index, GLenum model) {
  lecture_lit_view(lecture_panel(img, index, 2, 0, 1));
  glTranslatef(0.0f, 0.0f, -5.0f);
  glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
  /* --- the lecture's code ------------------------------------------------------------- */
  glShadeModel(model); /* glShadeModel( GL_FLAT); or glShadeModel( GL_SMOOTH); */
  /* --- end of the lecture's code ------------------------------------------------------ */
  glutSolidSphere(1.5, 16, 8);
}

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_shading.png", 640, 320)) return 1;
  glClearColor(0.9f, 0.9f, 0.9f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  GLfloat red[] = {.41, .135, .067, 1.}, white[] = {1., 1., 1., 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, red);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 30.);
  panel(&img, 0, GL_FLAT);   /* Constant Shading */
  panel(&img, 1, GL_SMOOTH); /* Gouraud Shading */
  return lecture_end(&img);
}
