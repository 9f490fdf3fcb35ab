/* Positional lights (w != 0) and each attenuation term: no attenuation (the defaults 1, 0, 0),
 * a constant term below 1 (the light gets brighter), a pure linear term and all
 * three terms together. The light's ambient part is attenuated too. The light is 1.2 in front
 * of a finely tessellated wall, off-centre; one panel puts the light at w = 2 (the position is
 * (x/w, y/w, z/w)). */
#include "conf.h"

static void scene(GLfloat kc, GLfloat kl, GLfloat kq, const GLfloat* pos) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.55, 0.55, -0.55, 0.55, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, kc);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, kl);
  glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, kq);
  glPushMatrix();
  glTranslatef(0.0f, 0.0f, -3.0f);
  conf_wall(2.4f, 2.4f, 32);
  glPopMatrix();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat amb[] = {0.25f, 0.2f, 0.2f, 1}, dif[] = {0.7f, 0.65f, 0.55f, 1};
  const GLfloat spec[] = {0.6f, 0.6f, 0.6f, 1}, none[] = {0, 0, 0, 1};
  glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, dif);
  glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, none);
  const GLfloat m_amb[] = {0.5f, 0.5f, 0.5f, 1}, m_dif[] = {0.7f, 0.7f, 0.7f, 1};
  glMaterialfv(GL_FRONT, GL_AMBIENT, m_amb);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, m_dif);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 16.0f);

  const GLfloat pos[] = {0.5f, 0.35f, -1.8f, 1.0f};
  const GLfloat pos_w2[] = {1.0f, 0.7f, -3.6f, 2.0f}; /* the same point, w = 2 */
  conf_panel(&c, 0, 0, 2, 2);
  scene(1.0f, 0.0f, 0.0f, pos);
  conf_panel(&c, 1, 0, 2, 2);
  scene(0.75f, 0.0f, 0.0f, pos_w2);
  conf_panel(&c, 0, 1, 2, 2);
  scene(0.0f, 0.8f, 0.0f, pos);
  conf_panel(&c, 1, 1, 2, 2);
  scene(0.2f, 0.3f, 0.6f, pos);
  return conf_finish(&c);
}
