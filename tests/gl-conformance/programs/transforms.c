/* Transformations and matrix stacks: glFrustum (symmetric and off-centre), glOrtho, glRotate
 * about an unnormalized axis, glScale, glTranslate (float and double forms), glLoadMatrix{f,d},
 * glMultMatrix{f,d} (a shear), a projection loaded by hand, deep modelview pushes and pops, the
 * projection stack, and a hierarchy built with glPushMatrix/glPopMatrix. Unlit cubes with one
 * colour per face, depth-tested. */
#include "conf.h"

static void cube(float s) {
  static const GLfloat col[6][3] = {{0.9f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.2f}, {0.2f, 0.3f, 0.9f},
                                    {0.9f, 0.9f, 0.2f}, {0.2f, 0.9f, 0.9f}, {0.9f, 0.3f, 0.9f}};
  static const GLfloat v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  static const int f[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6},
                              {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
  glBegin(GL_QUADS);
  for (int i = 0; i < 6; ++i) {
    glColor3fv(col[i]);
    for (int k = 0; k < 4; ++k) glVertex3f(s * v[f[i][k]][0], s * v[f[i][k]][1], s * v[f[i][k]][2]);
  }
  glEnd();
}

static void frustum(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 255, 255)) return 1;
  glClearColor(0.12f, 0.12f, 0.12f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  conf_panel(&c, 0, 0, 3, 3); /* symmetric frustum, rotation about (1, 1, 0) unnormalized */
  frustum();
  glTranslatef(0.0f, 0.0f, -3.5f);
  glRotatef(35.0f, 1.0f, 1.0f, 0.0f);
  cube(0.8f);

  conf_panel(&c, 1, 0, 3, 3); /* off-centre frustum, double-precision calls */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.2, 0.8, -0.7, 0.3, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslated(0.0, 0.0, -3.5);
  glRotated(-25.0, 0.0, 1.0, 0.0);
  glRotated(20.0, 1.0, 0.0, 0.0);
  cube(0.8f);

  conf_panel(&c, 2, 0, 3, 3); /* non-symmetric glOrtho */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.5, 1.0, -1.0, 1.6, -3.0, 3.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(30.0f, 1, 0, 0);
  glRotatef(45.0f, 0, 1, 0);
  cube(0.7f);

  conf_panel(&c, 0, 1, 3, 3); /* non-uniform scale and translation */
  frustum();
  glTranslatef(0.3f, -0.2f, -4.0f);
  glRotatef(30.0f, 0.2f, 1.0f, 0.1f);
  glScalef(1.4f, 0.4f, 0.8f);
  glScaled(1.0, 1.5, 1.0);
  cube(0.8f);

  conf_panel(&c, 1, 1, 3, 3); /* glLoadMatrixf: a hand-made look-at from (2, 1.5, 3) */
  frustum();
  {
    /* Rows of the rotation are the camera axes; column-major storage. */
    const GLfloat m[16] = {0.8320503f, -0.1966227f, 0.5187629f, 0,
                           0,          0.9348402f,  0.3550500f, 0,
                           -0.5547002f, -0.2949340f, 0.7781443f, 0,
                           0.0000000f, 0.0000000f, -3.9051249f, 1};
    glLoadMatrixf(m);
  }
  cube(0.7f);

  conf_panel(&c, 2, 1, 3, 3); /* glLoadMatrixd then glMultMatrixd with a shear */
  frustum();
  {
    const GLdouble t[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -4, 1};
    const GLdouble shear[16] = {1, 0, 0, 0, 0.6, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const GLfloat rot[16] = {0.8660254f, 0, -0.5f, 0, 0, 1, 0, 0, 0.5f, 0, 0.8660254f, 0, 0, 0, 0, 1};
    glLoadMatrixd(t);
    glMultMatrixd(shear);
    glMultMatrixf(rot);
  }
  cube(0.7f);

  conf_panel(&c, 0, 2, 3, 3); /* projection by glLoadMatrixf, pushed and popped around it */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glPushMatrix();
  {
    /* glFrustum(-0.4, 0.4, -0.4, 0.4, 1, 10) written out */
    const GLfloat p[16] = {2.5f, 0, 0, 0, 0, 2.5f, 0, 0, 0, 0, -11.0f / 9.0f, -1,
                           0, 0, -20.0f / 9.0f, 0};
    glLoadMatrixf(p);
  }
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.0f);
  glRotatef(-40.0f, 1, 1, 1);
  cube(0.8f);
  glMatrixMode(GL_PROJECTION);
  glPopMatrix(); /* back to identity: the next cube is in clip space directly */
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.75f, 0.75f, 0.0f);
  glRotatef(20.0f, 0, 0, 1);
  cube(0.15f);

  conf_panel(&c, 1, 2, 3, 3); /* deep pushes: 30 levels (a spiral of small cubes), all popped */
  frustum();
  glTranslatef(0.0f, 0.0f, -4.0f);
  glRotatef(25.0f, 1, 1, 0);
  for (int i = 0; i < 30; ++i) {
    glPushMatrix();
    glTranslatef(0.25f, 0.0f, 0.0f);
    glRotatef(11.0f, 0, 0, 1);
    cube(0.06f);
  }
  for (int i = 0; i < 30; ++i) glPopMatrix();
  cube(0.4f);

  conf_panel(&c, 2, 2, 3, 3); /* a hierarchy: arm segments pushed on the stack */
  frustum();
  glTranslatef(-1.5f, -1.0f, -4.0f);
  for (int i = 0; i < 4; ++i) {
    glPushMatrix();
    glTranslatef(0.4f, 0.0f, 0.0f);
    glScalef(0.4f, 0.15f, 0.15f);
    cube(1.0f);
    glPopMatrix();
    glTranslatef(0.8f, 0.0f, 0.0f);
    glRotatef(30.0f, 0, 0, 1);
  }
  return conf_finish(&c);
}
