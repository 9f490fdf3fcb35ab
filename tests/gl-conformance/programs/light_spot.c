/* Spot lights on a finely tessellated wall: cutoff 15, 30 and 60 degrees with exponent 0, and
 * exponents 0 (cutoff 45), 8 and 64 with a tilted spot direction; the spot direction is
 * transformed by the modelview at the glLight call (one panel sets it under a rotation). Also a
 * light with several spots at once (GL_LIGHT1..3, coloured). */
#include "conf.h"

static void camera(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void wall(void) {
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, -3.0f);
  conf_wall(3.2f, 3.2f, 48);
  glPopMatrix();
}

static void spot(GLenum light, const GLfloat* pos, const GLfloat* dir, GLfloat cutoff,
                 GLfloat exponent) {
  glLightfv(light, GL_POSITION, pos);
  glLightfv(light, GL_SPOT_DIRECTION, dir);
  glLightf(light, GL_SPOT_CUTOFF, cutoff);
  glLightf(light, GL_SPOT_EXPONENT, exponent);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 255, 255)) return 1;
  glClearColor(0, 0, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat none[] = {0, 0, 0, 1}, white[] = {1, 1, 1, 1}, dim[] = {0.1f, 0.1f, 0.1f, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, dim);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  const GLfloat m_dif[] = {0.6f, 0.6f, 0.6f, 1}, m_spec[] = {0.3f, 0.3f, 0.3f, 1};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, m_dif);
  glMaterialfv(GL_FRONT, GL_SPECULAR, m_spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);

  const GLfloat pos[] = {0, 0, 0, 1}, down[] = {0, 0, -1};
  const GLfloat cutoffs[3] = {15.0f, 30.0f, 60.0f};
  for (int i = 0; i < 3; ++i) { /* top row: cutoffs, exponent 0 */
    conf_panel(&c, i, 0, 3, 3);
    camera();
    spot(GL_LIGHT0, pos, down, cutoffs[i], 0.0f);
    wall();
  }
  const GLfloat exps[3] = {0.0f, 8.0f, 64.0f};
  const GLfloat tilted[] = {0.3f, 0.2f, -1.0f}; /* not unit length on purpose */
  for (int i = 0; i < 3; ++i) { /* middle row: exponents, cutoff 45, tilted direction */
    conf_panel(&c, i, 1, 3, 3);
    camera();
    spot(GL_LIGHT0, pos, tilted, 45.0f, exps[i]);
    wall();
  }
  /* Bottom left: direction (0, 0, -1) given under a 20-degree rotation about y. */
  conf_panel(&c, 0, 2, 3, 3);
  camera();
  glPushMatrix();
  glRotatef(20.0f, 0, 1, 0);
  spot(GL_LIGHT0, pos, down, 25.0f, 2.0f);
  glPopMatrix();
  wall();
  /* Bottom middle: three coloured spots, light 0 off. */
  conf_panel(&c, 1, 2, 3, 3);
  camera();
  glDisable(GL_LIGHT0);
  const GLfloat cols[3][4] = {{1, 0.2f, 0.2f, 1}, {0.2f, 1, 0.2f, 1}, {0.3f, 0.3f, 1, 1}};
  const GLfloat dirs[3][3] = {{-0.25f, 0.15f, -1}, {0.25f, 0.15f, -1}, {0, -0.28f, -1}};
  for (int i = 0; i < 3; ++i) {
    glLightfv(GL_LIGHT1 + i, GL_DIFFUSE, cols[i]);
    glLightfv(GL_LIGHT1 + i, GL_SPECULAR, none);
    spot(GL_LIGHT1 + i, pos, dirs[i], 22.0f, 4.0f);
    glEnable(GL_LIGHT1 + i);
  }
  wall();
  for (int i = 0; i < 3; ++i) glDisable(GL_LIGHT1 + i);
  /* Bottom right: a positional spot with attenuation and a point 1.5 in front of the wall. */
  conf_panel(&c, 2, 2, 3, 3);
  camera();
  glEnable(GL_LIGHT0);
  const GLfloat near_pos[] = {-0.4f, 0.4f, -1.5f, 1};
  const GLfloat near_dir[] = {0.35f, -0.35f, -1};
  spot(GL_LIGHT0, near_pos, near_dir, 35.0f, 1.0f);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.4f);
  wall();
  return conf_finish(&c);
}
