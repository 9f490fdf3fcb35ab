/* How quads and polygons are split into triangles, seen through smooth shading: GL_QUADS,
 * GL_QUAD_STRIP and GL_POLYGON with a different colour at every vertex, and a lit, bumpy grid
 * drawn with GL_QUADS and per-vertex normals (the common way of drawing a lit surface). OpenGL
 * leaves the split to the implementation; Mesa's llvmpipe (the reference) splits a quad
 * v0 v1 v2 v3 into (v0, v1, v2) and (v0, v2, v3), a quad-strip quad v0 v1 v3 v2 likewise
 * from v0 (diagonal v0-v3), and a polygon as a fan from v0, when it hands the quads to its
 * rasterizer directly; a draw that goes through its draw pipeline (a vertex outside the view
 * volume, as in the third column's first cell) has its quads split along v1-v3 instead;
 * two-sided lighting (its second cell) does not change the split. Mesa's softpipe always splits GL_QUADS along v1-v3,
 * so it does not match this program (see docs/gl-conformance.md). */
#include <math.h>

#include "conf.h"

static const GLfloat kPalette[6][3] = {{1, 0, 0}, {0, 0.8f, 0}, {0.1f, 0.2f, 1},
                                       {1, 1, 0}, {0, 1, 1},    {1, 0, 1}};

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 3, 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void coloured(int k, float x, float y) {
  glColor3fv(kPalette[k % 6]);
  glVertex2f(x, y);
}

static void bumpy_vertex(int i, int j, int n) {
  double x = (double)i / n, y = (double)j / n;
  double h = 0.08 * sin(9.0 * x) * cos(7.0 * y);
  double dx = 0.08 * 9.0 * cos(9.0 * x) * cos(7.0 * y), dy = -0.08 * 7.0 * sin(9.0 * x) * sin(7.0 * y);
  glNormal3f((GLfloat)-dx, (GLfloat)-dy, 1.0f);
  glVertex3f((GLfloat)x, (GLfloat)y, (GLfloat)h);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0.15f, 0.15f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glShadeModel(GL_SMOOTH);

  cell(&c, 0, 0); /* GL_QUADS: a square, a kite and a trapezoid */
  glBegin(GL_QUADS);
  coloured(0, 0.05f, 0.55f), coloured(1, 0.45f, 0.56f), coloured(2, 0.44f, 0.95f), coloured(3, 0.06f, 0.94f);
  coloured(4, 0.75f, 0.53f), coloured(5, 0.96f, 0.75f), coloured(0, 0.75f, 0.97f), coloured(2, 0.54f, 0.74f);
  coloured(3, 0.07f, 0.06f), coloured(5, 0.93f, 0.08f), coloured(1, 0.71f, 0.46f), coloured(4, 0.27f, 0.44f);
  glEnd();

  cell(&c, 1, 0); /* GL_QUAD_STRIP with slanted rungs */
  glBegin(GL_QUAD_STRIP);
  for (int k = 0; k < 6; ++k) {
    float y = 0.06f + 0.3f * (float)(k / 2);
    coloured(k, k % 2 ? 0.94f : 0.06f, k % 2 ? y + 0.2f : y);
  }
  glEnd();

  cell(&c, 0, 1); /* GL_POLYGON: a convex hexagon */
  glBegin(GL_POLYGON);
  for (int k = 0; k < 6; ++k) {
    double a = 2.0 * CONF_PI * k / 6.0 + 0.2;
    coloured(k, (float)(0.5 + 0.45 * cos(a)), (float)(0.5 + 0.45 * sin(a)));
  }
  glEnd();

  cell(&c, 2, 0); /* the same quads in a draw with a vertex outside the view volume */
  glBegin(GL_QUADS);
  coloured(0, 0.05f, 0.55f), coloured(1, 0.45f, 0.56f), coloured(2, 0.44f, 0.95f), coloured(3, 0.06f, 0.94f);
  coloured(4, 0.75f, 0.53f), coloured(5, 0.96f, 0.75f), coloured(0, 0.75f, 0.97f), coloured(2, 0.54f, 0.74f);
  coloured(3, 0.07f, 0.06f), coloured(5, 0.93f, 0.08f), coloured(1, 0.71f, 0.46f), coloured(4, 0.27f, 0.44f);
  coloured(0, 1.5f, 0.10f), coloured(1, 1.9f, 0.10f), coloured(2, 1.9f, 0.40f), coloured(3, 1.5f, 0.40f);
  glEnd();

  cell(&c, 1, 1); /* a lit bumpy grid made of GL_QUADS */
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  const GLfloat dir[] = {-0.6f, 0.5f, 0.8f, 0}, dif[] = {0.3f, 0.6f, 0.9f, 1};
  const GLfloat spec[] = {0.8f, 0.8f, 0.8f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
  const int n = 8;
  glBegin(GL_QUADS);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      bumpy_vertex(i, j, n);
      bumpy_vertex(i + 1, j, n);
      bumpy_vertex(i + 1, j + 1, n);
      bumpy_vertex(i, j + 1, n);
    }
  glEnd();

  cell(&c, 2, 1); /* the same grid with two-sided lighting */
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glBegin(GL_QUADS);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      bumpy_vertex(i, j, n);
      bumpy_vertex(i + 1, j, n);
      bumpy_vertex(i + 1, j + 1, n);
      bumpy_vertex(i, j + 1, n);
    }
  glEnd();
  return conf_finish(&c);
}
