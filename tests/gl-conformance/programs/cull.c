/* Face culling: glCullFace(GL_BACK / GL_FRONT / GL_FRONT_AND_BACK), glFrontFace(GL_CW), and a
 * mirroring glScalef(-1, 1, 1) that turns the window-space winding around. Each cell holds a
 * counter-clockwise triangle (red), a clockwise one (blue), a counter-clockwise strip (green:
 * its triangles alternate vertex order but all face the same way), a clockwise fan (yellow), a
 * counter-clockwise quad (cyan), a clockwise polygon (magenta), and a cube drawn without depth
 * testing so only culling hides its far faces. */
#include "conf.h"

static void shapes(void) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0.2f, 0.2f); /* counter-clockwise */
  glVertex2f(-0.95f, 0.35f);
  glVertex2f(-0.4f, 0.4f);
  glVertex2f(-0.7f, 0.92f);
  glColor3f(0.2f, 0.3f, 1); /* clockwise */
  glVertex2f(-0.3f, 0.35f);
  glVertex2f(0.0f, 0.93f);
  glVertex2f(0.25f, 0.4f);
  glEnd();
  glColor3f(0.2f, 0.9f, 0.2f);
  glBegin(GL_TRIANGLE_STRIP); /* counter-clockwise first triangle */
  glVertex2f(0.35f, 0.35f);
  glVertex2f(0.95f, 0.4f);
  glVertex2f(0.33f, 0.62f);
  glVertex2f(0.93f, 0.66f);
  glVertex2f(0.36f, 0.94f);
  glEnd();
  glColor3f(1, 1, 0.2f);
  glBegin(GL_TRIANGLE_FAN); /* clockwise */
  glVertex2f(-0.95f, -0.3f);
  glVertex2f(-0.9f, 0.25f);
  glVertex2f(-0.55f, 0.2f);
  glVertex2f(-0.4f, -0.25f);
  glEnd();
  glColor3f(0.2f, 1, 1);
  glBegin(GL_QUADS); /* counter-clockwise */
  glVertex2f(-0.3f, -0.3f);
  glVertex2f(0.25f, -0.25f);
  glVertex2f(0.2f, 0.22f);
  glVertex2f(-0.27f, 0.2f);
  glEnd();
  glColor3f(1, 0.3f, 1);
  glBegin(GL_POLYGON); /* clockwise */
  glVertex2f(0.62f, -0.3f);
  glVertex2f(0.37f, -0.1f);
  glVertex2f(0.5f, 0.22f);
  glVertex2f(0.8f, 0.24f);
  glVertex2f(0.93f, -0.05f);
  glEnd();
}

static void cube(void) {
  static const GLfloat v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  static const int f[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6},
                              {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
  glPushMatrix();
  glTranslatef(0.0f, -0.65f, 0.0f);
  glRotatef(30.0f, 1, 0, 0);
  glRotatef(35.0f, 0, 1, 0);
  glScalef(0.2f, 0.2f, 0.2f);
  glBegin(GL_QUADS);
  for (int i = 0; i < 6; ++i) {
    glColor3f(0.3f + 0.12f * i, 0.9f - 0.13f * i, 0.5f);
    for (int k = 0; k < 4; ++k) glVertex3fv(v[f[i][k]]);
  }
  glEnd();
  glPopMatrix();
}

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 3, 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -2.0, 2.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 255, 256)) return 1;
  glClearColor(0.15f, 0.15f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  cell(&c, 0, 0); /* no culling */
  shapes();
  cube();
  glEnable(GL_CULL_FACE);
  cell(&c, 1, 0); /* default: cull back faces, counter-clockwise is front */
  shapes();
  cube();
  cell(&c, 2, 0);
  glCullFace(GL_FRONT);
  shapes();
  cube();
  cell(&c, 0, 1); /* nothing but the background */
  glCullFace(GL_FRONT_AND_BACK);
  shapes();
  cube();
  cell(&c, 1, 1);
  glCullFace(GL_BACK);
  glFrontFace(GL_CW);
  shapes();
  cube();
  cell(&c, 2, 1); /* mirrored: counter-clockwise in object space is clockwise on screen */
  glFrontFace(GL_CCW);
  glScalef(-1.0f, 1.0f, 1.0f);
  shapes();
  cube();
  return conf_finish(&c);
}
