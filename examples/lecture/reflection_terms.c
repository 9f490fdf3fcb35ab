/* Lecture 14, slides "Pure Ambient / Diffuse / Specular / Ambient + Diffuse + Specular" and
 * "Pure Ambient, Pure Diffuse, Pure Specular, Overall" of the shiny red material (SPEC figures
 * 3 and 12): the teapot with only one reflection term at a time, then all of them.
 * Pure ambient uses the lecture's globalAmbient (.9, .9, .9) with no light enabled: a flat
 * silhouette. Pure diffuse and pure specular use the white directional light from (1, 1, 1)
 * with the other material terms set to zero and no global ambient. Camera (ours): perspective
 * 40 degrees from 6 units. */
#include <GL/shadelab_glut.h>

#include "common/lecture.h"

void drawTeapot() { glutSolidTeapot(1.0); }

static void panel(const LectureImage* img, int index) { lecture_teapot_panel(img, index, 4); }

static void terms(const GLfloat* ambient, const GLfloat* diffuse, const GLfloat* specular) {
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 125.);
}

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_reflection_terms.png", 960, 240)) return 1;
  glClearColor(0.9f, 0.9f, 0.9f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_NORMALIZE);
  GLfloat red[] = {.41, .135, .067, 1.}, white[] = {1., 1., 1., 1.}, none[] = {0., 0., 0., 1.};
  GLfloat default_global[] = {.2, .2, .2, 1.};

  panel(&img, 0); /* Pure Ambient */
  /* --- the lecture's code ------------------------------------------------------------- */
  float globalAmbient[] = {0.9, 0.9, 0.9, 1.};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, globalAmbient);
  /* --- end of the lecture's code ------------------------------------------------------ */
  terms(red, none, none);
  drawTeapot();

  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, none);
  glEnable(GL_LIGHT0);
  panel(&img, 1); /* Pure Diffuse */
  terms(none, red, none);
  drawTeapot();
  panel(&img, 2); /* Pure Specular */
  terms(none, none, white);
  drawTeapot();
  panel(&img, 3); /* Overall: ambient + diffuse + specular, OpenGL's global ambient */
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, default_global);
  terms(red, red, white);
  drawTeapot();
  return lecture_end(&img);
}
