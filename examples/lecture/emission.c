/* Lecture 14, slides "Emission" (SPEC figure 14): a night scene in which the moon glows with
 * the emission (1, 1, .75, 1) while everything else is lit only by lights: three warm street
 * lamps (spot lights pointing down, GL_LIGHT1..3) and a faint blue moonlight (directional,
 * GL_LIGHT0). The moon lights nothing: emission is a property of its material, not a light
 * source, so the ground below it stays dark. The lecture's picture has 5 materials, 2 textures
 * and 16 spot lights; ours has 5 materials (ground, walls, roofs, teapot, moon), no texture and
 * 3 spots. Camera (ours): perspective 45 degrees from (0, 2, 10), looking slightly down. */
#include <GL/shadelab_glut.h>

#include "common/lecture.h"

static void material(const GLfloat* ambient_diffuse, const GLfloat* specular, GLfloat shininess) {
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient_diffuse);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, ambient_diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, shininess);
}

void draw_moon() {
  GLfloat moon[] = {.2, .2, .15, 1.}, none[] = {0., 0., 0., 1.};
  material(moon, none, 1.);
  glPushMatrix();
  glTranslatef(4.5, 5.5, -12.);
  glutSolidSphere(1.2, 40, 20);
  glPopMatrix();
}

static void ground(void) {
  glNormal3f(0., 1., 0.);
  glBegin(GL_QUADS);
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) {
      float x0 = -12. + .6 * i, z0 = -18. + .6 * j;
      glVertex3f(x0, 0., z0 + .6), glVertex3f(x0 + .6, 0., z0 + .6);
      glVertex3f(x0 + .6, 0., z0), glVertex3f(x0, 0., z0);
    }
  glEnd();
}

static void house(float x, float z, float w, float h) {
  GLfloat wall[] = {.7, .65, .55, 1.}, roof[] = {.5, .15, .1, 1.}, dull[] = {.1, .1, .1, 1.};
  glPushMatrix();
  glTranslatef(x, h / 2, z);
  material(wall, dull, 10.);
  glPushMatrix();
  glScalef(w, h, w);
  glutSolidCube(1.);
  glPopMatrix();
  material(roof, dull, 10.);
  glTranslatef(0., h / 2, 0.);
  glRotatef(-90., 1., 0., 0.); /* GLUT's cone points along +z */
  glutSolidCone(w * .75, h * .6, 4, 2);
  glPopMatrix();
}

static void street_lamp(GLenum light, float x, float z) {
  GLfloat position[] = {x, 3.5, z, 1.}, down[] = {0., -1., 0.};
  GLfloat warm[] = {1., .85, .55, 1.};
  glLightfv(light, GL_POSITION, position);
  glLightfv(light, GL_SPOT_DIRECTION, down);
  glLightf(light, GL_SPOT_CUTOFF, 45.);
  glLightf(light, GL_SPOT_EXPONENT, 2.);
  glLightf(light, GL_LINEAR_ATTENUATION, .05);
  glLightfv(light, GL_DIFFUSE, warm);
  glLightfv(light, GL_SPECULAR, warm);
  glEnable(light);
}

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_emission.png", 480, 360)) return 1;
  glClearColor(0.02f, 0.02f, 0.08f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_NORMALIZE);
  GLfloat night[] = {.05, .05, .08, 1.};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, night);
  glMatrixMode(GL_PROJECTION);
  lecture_perspective(45.0, 480.0 / 360.0, 1.0, 60.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(8., 1., 0., 0.);
  glTranslatef(0., -2., -10.);

  GLfloat moonlight_dir[] = {-.3, 1., .5, 0.}, moonlight[] = {.15, .15, .3, 1.};
  glLightfv(GL_LIGHT0, GL_POSITION, moonlight_dir);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, moonlight);
  glLightfv(GL_LIGHT0, GL_SPECULAR, moonlight);
  glEnable(GL_LIGHT0);
  street_lamp(GL_LIGHT1, -3.5, -1.);
  street_lamp(GL_LIGHT2, 0.5, 1.);
  street_lamp(GL_LIGHT3, 4., -3.);

  GLfloat grass[] = {.3, .5, .3, 1.}, none[] = {0., 0., 0., 1.};
  material(grass, none, 1.);
  ground();
  house(-5., -4., 2.2, 2.);
  house(1.5, -6., 2.6, 2.6);
  house(6., -2., 1.8, 1.6);
  GLfloat silver[] = {.5, .5, .55, 1.}, white[] = {1., 1., 1., 1.};
  material(silver, white, 80.);
  glPushMatrix();
  glTranslatef(0.5, .75, 1.);
  glutSolidTeapot(1.);
  glPopMatrix();

  /* --- the lecture's code ------------------------------------------------------------- */
  GLfloat emission[] = {1., 1., .75, 1.};
  glMaterialfv(GL_FRONT, GL_EMISSION, emission);

  draw_moon();

  GLfloat no_em[] = {0., 0., 0., 1.};
  glMaterialfv(GL_FRONT, GL_EMISSION, no_em);
  /* --- end of the lecture's code ------------------------------------------------------ */
  return lecture_end(&img);
}
