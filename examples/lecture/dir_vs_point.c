/* Lecture 14, slide "Гялалзсан цагаан объект дээрх directional source ба point source
 * харьцуулалт" (SPEC figure 8): the shiny white wall (20 x 20) under a directional source at
 * (0, 0, 1) (left) and a point source at (0, 0, 8) (right); viewing position (0, 0, 8). The
 * point source coincides with the eye: its highlight is tighter and the diffuse part falls off
 * toward the wall's edges, where the directional source lights the wall evenly.
 * Also the lecture's two position examples, point (2, 4, 6, 1) and directional (1, 1, 1, 0)
 * (bottom row). Light colours and the wall as in example_mesh_size; local viewer on. */
#include "common/lecture.h"

static void draw_panel(const LectureImage* img, int index, int row, GLenum light,
                       const GLfloat* position) {
  double aspect = lecture_panel(img, index, 2, row, 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lecture_perspective(60.0, aspect, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0., 0., -8.);                    /* Viewing position (0, 0, 8) */
  glLightfv(light, GL_POSITION, position); /* in the wall's (world) coordinates */
  glDisable(light == GL_LIGHT0 ? GL_LIGHT1 : GL_LIGHT0);
  glEnable(light);
  wall(20);
}

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_dir_vs_point.png", 400, 400)) return 1;
  glClearColor(0.3f, 0.3f, 0.35f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  GLfloat ambient0[] = {0., 0., 0., 1.};
  GLfloat diffuse0[] = {.7, .7, .7, 1.};
  GLfloat specular0[] = {1., 1., 1., 1.};
  for (GLenum light = GL_LIGHT0; light <= GL_LIGHT1; ++light) {
    glLightfv(light, GL_AMBIENT, ambient0);
    glLightfv(light, GL_DIFFUSE, diffuse0);
    glLightfv(light, GL_SPECULAR, specular0);
  }
  GLfloat ambient[] = {.2, .2, .2, 1.}, diffuse[] = {.5, .5, .5, 1.}, specular[] = {1., 1., 1., 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 128.);

  GLfloat directional[] = {0., 0., 1., 0.}; /* Dir. source at (0, 0, 1) */
  GLfloat point[] = {0., 0., 8., 1.};       /* Point source at (0, 0, 8) */
  draw_panel(&img, 0, 0, GL_LIGHT0, directional);
  draw_panel(&img, 1, 0, GL_LIGHT0, point);
  /* The lecture's position examples: a point light on GL_LIGHT0, a directional one on
   * GL_LIGHT1 (whose default colours are black, hence the loop above). */
  GLfloat light_position[] = {2., 4., 6., 1.};
  draw_panel(&img, 0, 1, GL_LIGHT0, light_position);
  GLfloat light_position1[] = {1., 1., 1., 0.};
  draw_panel(&img, 1, 1, GL_LIGHT1, light_position1);
  return lecture_end(&img);
}
