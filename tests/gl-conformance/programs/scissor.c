/* The scissor test (GL 1.1 section 4.1.2) on drawing and on glClear (section 4.2.3: clears
 * honour it). A first frame is drawn and flushed, then a second one over it (the clears of
 * the second frame meet tiles the first one left cleared, drawn or partly cleared):
 * - colour clears in boxes inside the buffer, across its left and bottom edges (negative
 *   origin), across its right and top edges, of zero size, under a colour mask;
 * - a depth clear in a box, then a quad at middle depth drawn everywhere with GL_LESS;
 * - a stencil clear in a box (with a write mask), then a quad drawn where stencil equals it;
 * - lit spheres and smooth triangles drawn through boxes, with viewports that move
 *   (split-screen panels, each with its own box);
 * - a clear of the whole buffer to the same colour after partial clears. */
#include "conf.h"

static void ortho(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

static void clear_box(int x, int y, int w, int h, float r, float g, float b, GLbitfield mask) {
  glScissor(x, y, w, h);
  glClearColor(r, g, b, 1.0f);
  glClear(mask);
}

static void lit_spheres(const ConfContext* c) {
  const GLfloat dir[4] = {0.3f, 0.6f, 0.8f, 0.0f};
  const GLfloat diffuse[4] = {0.9f, 0.5f, 0.2f, 1.0f};
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diffuse);
  for (int i = 0; i < 3; ++i) { /* three panels in the top right, each with its own box */
    int x = c->width / 2 + i * c->width / 6, y = c->height / 2, w = c->width / 6, h = c->height / 2;
    glViewport(x, y, w, h);
    glScissor(x + 5 + 3 * i, y + 10 + 7 * i, w - 12 - 4 * i, h / 2);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.2, 1.2, -1.6, 1.6, -2.0, 2.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    conf_sphere(1.0f, 18, 12);
  }
  glDisable(GL_LIGHTING);
  glViewport(0, 0, c->width, c->height);
}

static void frame(const ConfContext* c, int second) {
  const int w = c->width, h = c->height;
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClearDepth(0.2);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  const int s = second ? 9 : 0; /* the second frame's boxes are elsewhere */
  clear_box(20 + s, 30, 60, 40, 0.9f, 0.2f, 0.2f, GL_COLOR_BUFFER_BIT);
  clear_box(-15, -10 + s, 50, 35, 0.2f, 0.9f, 0.2f, GL_COLOR_BUFFER_BIT);
  clear_box(w - 40, h - 30 - s, 100, 100, 0.2f, 0.3f, 0.9f, GL_COLOR_BUFFER_BIT);
  clear_box(100, 100, 0, 20, 1.0f, 1.0f, 1.0f, GL_COLOR_BUFFER_BIT); /* empty */
  glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_TRUE);
  clear_box(40 + s, 50, 70, 30, 1.0f, 1.0f, 1.0f, GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  /* Depth cleared to 1 in a box; a quad at depth 0.5 (window) passes GL_LESS only there. */
  glClearDepth(1.0);
  clear_box(120, 20 + s, 70, 60, 0.0f, 0.0f, 0.0f, GL_DEPTH_BUFFER_BIT);
  /* Stencil 0x5 (write mask 0x7 of 0xd) in a box; a quad drawn where stencil == 5. */
  glStencilMask(0x7);
  glClearStencil(0xd);
  clear_box(10, 110 - s, 90, 50, 0.0f, 0.0f, 0.0f, GL_STENCIL_BUFFER_BIT);
  glStencilMask(0xff);
  glDisable(GL_SCISSOR_TEST);
  ortho();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glColor3f(1.0f, 0.8f, 0.1f);
  quad(0.3f, 0.0f, 0.7f, 0.45f, 0.0f);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 5, 0xff);
  glColor3f(0.1f, 0.9f, 0.9f);
  quad(0.0f, 0.3f, 0.5f, 0.8f, 0.0f);
  glDisable(GL_STENCIL_TEST);
  /* Drawing through boxes: a smooth triangle, then lit spheres in panels. */
  glEnable(GL_SCISSOR_TEST);
  glScissor(15 + s, h - 70, 110, 45);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex2f(0.0f, 0.55f);
  glColor3f(0, 1, 0);
  glVertex2f(0.5f, 0.6f);
  glColor3f(0, 0, 1);
  glVertex2f(0.2f, 1.0f);
  glEnd();
  lit_spheres(c);
  /* Partial clears, then the whole buffer's strip to the colour of the first clear. */
  clear_box(w / 2, 0, w / 4, h / 4, 0.1f, 0.1f, 0.15f, GL_COLOR_BUFFER_BIT);
  clear_box(w / 2 + 8, 8, w / 4, h / 5, 0.6f, 0.6f, 0.2f, GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 300, 220)) return 1;
  GLint box[4];
  glGetIntegerv(GL_SCISSOR_BOX, box); /* the first binding's: the whole buffer */
  if (box[0] != 0 || box[1] != 0 || box[2] != c.width || box[3] != c.height) return 4;
  frame(&c, 0);
  glFinish();
  frame(&c, 1);
  return conf_finish(&c);
}
