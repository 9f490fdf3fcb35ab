/* glPolygonOffset with GL_POLYGON_OFFSET_FILL: coplanar decals on a tilted plane pulled forward
 * (factor -1, units -1: visible) and pushed back (factor 2, units 2: hidden), and a units-only
 * offset on a plane facing the viewer (slope 0). glColorMask: a glClear that writes only green,
 * quads written through red-only, green-and-blue-only, alpha-only and no channels, and a
 * depth-only pass (colour writes off) that cuts a hole into what is drawn behind it. */
#include "conf.h"

static void rect(float x0, float y0, float x1, float y1) {
  glBegin(GL_QUADS);
  glVertex2f(x0, y0);
  glVertex2f(x1, y0);
  glVertex2f(x1, y1);
  glVertex2f(x0, y1);
  glEnd();
}

static void tilted_camera(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 2, 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -3.0f);
  glRotatef(-60.0f, 1, 0, 0);
  glRotatef(15.0f, 0, 0, 1);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_FALSE); /* a clear through the colour mask */
  glClearColor(1.0f, 0.5f, 1.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_DEPTH_TEST);

  tilted_camera(&c, 0, 0); /* decals on a tilted plane */
  glColor3f(0.6f, 0.6f, 0.6f);
  rect(-1.5f, -1.5f, 1.5f, 1.5f);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -1.0f);
  glColor3f(1.0f, 0.3f, 0.2f);
  rect(-1.2f, -1.0f, -0.1f, 1.1f);
  glPolygonOffset(2.0f, 2.0f);
  glColor3f(0.2f, 0.3f, 1.0f);
  rect(0.1f, -1.1f, 1.3f, 1.0f);
  glPolygonOffset(-1.0f, -1.0f);
  glColor3f(1.0f, 1.0f, 0.2f);
  rect(0.4f, -0.3f, 0.9f, 0.4f); /* on top of the hidden blue one */
  glDisable(GL_POLYGON_OFFSET_FILL);

  conf_panel(&c, 1, 0, 2, 2); /* units only, on a plane facing the viewer */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(7.0f, 0, 0, 1);
  glColor3f(0.5f, 0.8f, 0.5f);
  rect(-0.9f, -0.9f, 0.9f, 0.9f);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, -4.0f);
  glColor3f(0.9f, 0.2f, 0.6f);
  rect(-0.6f, -0.6f, 0.2f, 0.6f);
  glPolygonOffset(0.0f, 4.0f);
  glColor3f(0.1f, 0.1f, 0.1f); /* behind: hidden */
  rect(0.3f, -0.6f, 0.7f, 0.6f);
  glDisable(GL_POLYGON_OFFSET_FILL);

  conf_panel(&c, 0, 1, 2, 2); /* colour masks on overlapping quads */
  glDisable(GL_DEPTH_TEST);
  glColor4f(0.5f, 0.5f, 0.5f, 1.0f);
  rect(-0.95f, -0.95f, 0.95f, 0.95f);
  glColor4f(1.0f, 0.9f, 0.8f, 0.3f);
  glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
  rect(-0.8f, -0.1f, 0.1f, 0.8f);
  glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_FALSE);
  rect(-0.1f, -0.1f, 0.8f, 0.8f);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  rect(-0.8f, -0.8f, 0.1f, 0.0f);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  rect(-0.1f, -0.8f, 0.8f, 0.0f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  tilted_camera(&c, 1, 1); /* a depth-only pass cuts a hole */
  glEnable(GL_DEPTH_TEST);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glBegin(GL_TRIANGLES);
  glVertex3f(-0.7f, -0.6f, 0.3f);
  glVertex3f(0.8f, -0.4f, 0.3f);
  glVertex3f(0.0f, 0.9f, 0.3f);
  glEnd();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glColor3f(0.9f, 0.7f, 0.2f);
  rect(-1.3f, -1.3f, 1.3f, 1.3f);
  return conf_finish(&c);
}
