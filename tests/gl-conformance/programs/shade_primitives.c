/* Every polygon primitive (GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,
 * GL_QUAD_STRIP, GL_POLYGON; the columns) drawn flat and smooth, unlit with a different colour
 * at every vertex and lit with a different normal at every vertex (the rows: unlit flat, unlit
 * smooth, lit flat, lit smooth). Flat shading takes the colour of the provoking vertex: the last
 * vertex of each triangle, strip or fan triangle, quad and quad-strip quad (the quad strip's
 * fourth vertex of v0 v1 v3 v2), the first vertex of a polygon (OpenGL 1.1 section 2.13.7).
 * How a quad is split into triangles is left to the implementation (Mesa's llvmpipe and softpipe
 * split GL_QUADS differently), so in the smooth rows the quads and the quad strip have
 * horizontal edges top and bottom and one colour (normal) per edge: every split interpolates
 * them alike. quad_split tests the split itself. */
#include <math.h>

#include "conf.h"

typedef struct Prim {
  GLenum mode;
  int count;
  float xy[6][2];
} Prim;

static const Prim kPrims[6] = {
    {GL_TRIANGLES, 6,
     {{0.1f, 0.08f}, {0.92f, 0.12f}, {0.48f, 0.44f}, {0.12f, 0.56f}, {0.9f, 0.53f}, {0.53f, 0.92f}}},
    {GL_TRIANGLE_STRIP, 6,
     {{0.13f, 0.07f}, {0.87f, 0.21f}, {0.11f, 0.41f}, {0.86f, 0.56f}, {0.14f, 0.71f}, {0.88f, 0.93f}}},
    {GL_TRIANGLE_FAN, 6,
     {{0.11f, 0.09f}, {0.9f, 0.13f}, {0.87f, 0.52f}, {0.68f, 0.88f}, {0.35f, 0.93f}, {0.09f, 0.62f}}},
    {GL_QUADS, 8,
     {{0.1f, 0.07f}, {0.9f, 0.07f}, {0.83f, 0.43f}, {0.16f, 0.43f}, {0.0f, 0.0f}, {0.0f, 0.0f}}},
    {GL_QUAD_STRIP, 6,
     {{0.09f, 0.08f}, {0.91f, 0.08f}, {0.16f, 0.49f}, {0.83f, 0.49f}, {0.11f, 0.91f}, {0.89f, 0.91f}}},
    {GL_POLYGON, 6,
     {{0.5f, 0.06f}, {0.9f, 0.27f}, {0.91f, 0.71f}, {0.52f, 0.94f}, {0.1f, 0.73f}, {0.08f, 0.3f}}},
};

/* The second quad of the GL_QUADS column (a non-rectangular one). */
static const float kQuad2[4][2] = {{0.14f, 0.57f}, {0.86f, 0.57f}, {0.93f, 0.93f}, {0.08f, 0.93f}};

static const GLfloat kPalette[8][3] = {{1, 0, 0}, {0, 0.8f, 0}, {0.1f, 0.2f, 1}, {1, 1, 0},
                                       {0, 1, 1}, {1, 0, 1}, {1, 1, 1}, {1, 0.5f, 0}};

static void vertex(int k, float x, float y, int lit) {
  if (lit) {
    double a = 0.9 * k;
    glNormal3f((GLfloat)(1.6 * cos(a)), (GLfloat)(1.6 * sin(a)), 1.0f);
  } else {
    glColor3fv(kPalette[k % 8]);
  }
  glVertex2f(x, y);
}

static void draw(const Prim* p, int lit, int smooth) {
  int paired = smooth && (p->mode == GL_QUADS || p->mode == GL_QUAD_STRIP);
  glBegin(p->mode);
  for (int k = 0; k < p->count; ++k) {
    const float* xy = k < 4 || p->mode != GL_QUADS ? p->xy[k] : kQuad2[k - 4];
    /* GL_QUADS: v0 v1 bottom, v2 v3 top; GL_QUAD_STRIP: rungs (v0 v1), (v2 v3), (v4 v5). */
    vertex(paired ? k & ~1 : k, xy[0], xy[1], lit);
  }
  glEnd();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 252, 256)) return 1;
  glClearColor(0.15f, 0.15f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  const GLfloat dir[] = {0.3f, 0.2f, 1.0f, 0.0f}, dif[] = {0.9f, 0.7f, 0.3f, 1};
  const GLfloat spec[] = {0.5f, 0.5f, 0.8f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 8.0f);
  for (int row = 0; row < 4; ++row) {
    int lit = row >= 2;
    glShadeModel(row % 2 == 0 ? GL_FLAT : GL_SMOOTH);
    if (lit) glEnable(GL_LIGHTING);
    for (int col = 0; col < 6; ++col) {
      conf_panel(&c, col, row, 6, 4);
      draw(&kPrims[col], lit, row % 2 == 1);
    }
  }
  return conf_finish(&c);
}
