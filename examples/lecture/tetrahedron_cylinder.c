/* Lecture 14, slides "Орой тус бүрийн хувьд нормалийг тодорхойлох" (one normal per vertex or
 * face) and "glEnable(GL_NORMALIZE)": the lit tetrahedron with one glNormal3f per face, and the
 * cylinder drawn as a GL_QUAD_STRIP with the per-vertex colour (cos t, 0, sin t) (SPEC figure 5).
 * Left: the tetrahedron, lit by GL_LIGHT0 (white, directional; we move it from the viewer's
 * direction, its default, to the upper left (-1, 1, 2, 0) so that the three faces differ).
 * Right: the cylinder, unlit so that its colours show ("colors are ignored" under lighting).
 * Camera (ours; the lecture gives none): perspective 40 degrees, the objects 6 units away; the
 * tetrahedron turned so that its vertex (1, 1, -1) points at the viewer (three faces show), the
 * cylinder tilted so that its inside shows. */
#include <math.h>

#include "common/lecture.h"

/* --- the lecture's code --------------------------------------------------------------- */
void triangle(float v[][3], int a, int b, int c) {
  glBegin(GL_TRIANGLES);
  glVertex3fv(v[a]);
  glVertex3fv(v[b]);
  glVertex3fv(v[c]);
  glEnd();
}

void tetrahedron() {
  float v[][3] = {{-1., -1., -1.}, {1., -1., 1.}, {-1., 1., 1.}, {1., 1., -1.}};

  glNormal3f(-1., -1., 1.);
  triangle(v, 0, 1, 2);

  glNormal3f(1., 1., 1.);
  triangle(v, 1, 3, 2);

  glNormal3f(-1., 1., -1.);
  triangle(v, 0, 2, 3);

  glNormal3f(1., -1., -1.);
  triangle(v, 0, 3, 1);
}

void cylinder(int nslice) {
  float t, dt;
  int j;
  // Draw a cylinder
  glBegin(GL_QUAD_STRIP);
  t = 0.;
  dt = (360. / nslice) * 3.1416 / 180.;
  for (j = 0; j <= nslice; ++j) {
    glColor3f(cos(t), 0., sin(t));
    glVertex3f(cos(t), 0., sin(t));
    glVertex3f(cos(t), 2., sin(t));
    t = t + dt;
  }
  glEnd();
}
/* --- end of the lecture's code ------------------------------------------------------- */

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_tetrahedron_cylinder.png", 640, 320)) return 1;
  glClearColor(0.12f, 0.12f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  /* Left: the lit tetrahedron. init() of the lecture: */
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE); /* the normals above are not unit length */
  double aspect = lecture_panel(&img, 0, 2, 0, 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lecture_perspective(40.0, aspect, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  GLfloat light_position[] = {-1., 1., 2., 0.};
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
  glTranslatef(0.0f, 0.0f, -6.0f);
  glRotatef(10.0f, 1.0f, 1.0f, 0.0f);
  glRotatef(144.74f, 1.0f, 0.0f, 0.0f);
  glRotatef(45.0f, 0.0f, 1.0f, 0.0f);
  tetrahedron();

  /* Right: the quad-strip cylinder with its per-vertex colours. */
  glDisable(GL_LIGHTING);
  glShadeModel(GL_SMOOTH);
  aspect = lecture_panel(&img, 1, 2, 0, 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lecture_perspective(40.0, aspect, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, -0.3f, -6.0f);
  glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
  glTranslatef(0.0f, -1.0f, 0.0f);
  cylinder(48);
  return lecture_end(&img);
}
