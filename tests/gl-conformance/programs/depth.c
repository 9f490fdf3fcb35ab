/* The depth buffer: all eight glDepthFunc comparisons (the first two rows: NEVER, LESS, EQUAL,
 * LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS), glDepthMask(GL_FALSE), glDepthRange (a split range
 * and a reversed one with GL_GREATER), and glClearDepth (the whole buffer is cleared to 0.75, so
 * far parts of the first surface fail GL_LESS everywhere).
 * In each cell a blue surface A (two quads, z = 0.5 x) is drawn with GL_LESS, then an orange
 * surface B with the function under test: B's left quad repeats A's left quad exactly (so that
 * GL_EQUAL has equal depths to find), B's right quad crosses A. */
#include "conf.h"

static void quad(const GLfloat v[4][3]) {
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) glVertex3fv(v[i]);
  glEnd();
}

static const GLfloat kLeft[4][3] = {
    {-0.9f, -0.9f, -0.45f}, {0.0f, -0.9f, 0.0f}, {0.0f, 0.9f, 0.0f}, {-0.9f, 0.9f, -0.45f}};
static const GLfloat kARight[4][3] = {
    {0.0f, -0.9f, 0.0f}, {0.9f, -0.9f, 0.45f}, {0.9f, 0.9f, 0.45f}, {0.0f, 0.9f, 0.0f}};
static const GLfloat kBRight[4][3] = {
    {0.0f, -0.9f, 0.225f}, {0.9f, -0.9f, -0.225f}, {0.9f, 0.9f, 0.225f}, {0.0f, 0.9f, 0.675f}};

static void surface_a(void) {
  glColor3f(0.2f, 0.4f, 1.0f);
  quad(kLeft);
  quad(kARight);
}

static void surface_b(void) {
  glColor3f(1.0f, 0.6f, 0.1f);
  quad(kLeft);
  quad(kBRight);
}

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(10.0f, 0, 0, 1); /* so that no edge runs along pixel centres */
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 255)) return 1;
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClearDepth(0.75);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  static const GLenum funcs[8] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                                  GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
  for (int i = 0; i < 8; ++i) {
    cell(&c, i % 4, i / 4);
    glDepthFunc(GL_LESS);
    surface_a();
    glDepthFunc(funcs[i]);
    surface_b();
  }
  glDepthFunc(GL_LESS);

  cell(&c, 0, 2); /* A without depth writes: B (GL_LESS) is drawn wherever it passes 0.75 */
  glDepthMask(GL_FALSE);
  surface_a();
  glDepthMask(GL_TRUE);
  surface_b();

  cell(&c, 1, 2); /* A in the far half of the range, B in the near half: B wins everywhere */
  glDepthRange(0.5, 1.0);
  surface_a();
  glDepthRange(0.0, 0.5);
  surface_b();
  glDepthRange(0.0, 1.0);

  cell(&c, 2, 2); /* reversed range with GL_GREATER: the nearer surface wins, as with GL_LESS
                     and the usual range. The cell's depth is first set to 0 (the far end of the
                     reversed range) by a quad drawn with GL_ALWAYS, glDepthRange(0, 0) and
                     colour writes off. */
  glDepthFunc(GL_ALWAYS);
  glDepthRange(0.0, 0.0);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glBegin(GL_QUADS);
  glVertex2f(-2, -2);
  glVertex2f(2, -2);
  glVertex2f(2, 2);
  glVertex2f(-2, 2);
  glEnd();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthRange(1.0, 0.0);
  glDepthFunc(GL_GREATER);
  surface_a();
  surface_b();
  glDepthRange(0.0, 1.0);
  glDepthFunc(GL_LESS);

  cell(&c, 3, 2); /* depth test disabled: drawing order wins, and the depth buffer is untouched */
  glDisable(GL_DEPTH_TEST);
  surface_b();
  surface_a();
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 1, 1);
  glBegin(GL_TRIANGLES); /* a white sliver at eye z = 0.8 (window depth 0.1): passes */
  glVertex3f(-0.6f, -0.2f, 0.8f);
  glVertex3f(0.6f, -0.1f, 0.8f);
  glVertex3f(0.0f, 0.2f, 0.8f);
  glEnd();
  return conf_finish(&c);
}
