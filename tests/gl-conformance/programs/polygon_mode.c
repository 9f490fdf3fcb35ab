/* Polygon modes (GL 1.1 section 3.5.4) and edge flags (section 2.6.2): every polygon primitive
 * in GL_LINE and GL_POINT mode, front and back faces in different modes, culling, flat and
 * smooth colours, two-sided lighting, edge flags from glEdgeFlag and from an edge-flag array,
 * wide and stippled edges, polygons clipped by the view volume (no edge drawn along it), and
 * hidden-line removal with polygon offset (GL_POLYGON_OFFSET_FILL under lines, and
 * GL_POLYGON_OFFSET_LINE / _POINT over a surface). A 4 x 3 grid of panels. */
#include <math.h>

#include "conf.h"

#define COLS 4
#define ROWS 3

static void ortho_panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, COLS, ROWS);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void perspective_panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, COLS, ROWS);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -3);
}

/* Every polygon primitive, small, spread over the panel; front faces counter-clockwise. */
static void primitives(void) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0.3f, 0.3f);
  glVertex2f(-0.95f, 0.3f);
  glColor3f(1, 1, 0.3f);
  glVertex2f(-0.4f, 0.35f);
  glColor3f(0.3f, 1, 0.3f);
  glVertex2f(-0.7f, 0.9f);
  glColor3f(0.3f, 0.6f, 1); /* clockwise: back facing */
  glVertex2f(-0.3f, 0.3f);
  glVertex2f(-0.1f, 0.92f);
  glColor3f(1, 0.3f, 1);
  glVertex2f(0.2f, 0.4f);
  glEnd();
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 6; ++i) {
    glColor3f(0.4f + 0.1f * i, 1, 0.5f);
    glVertex2f(0.3f + 0.13f * i, 0.35f + 0.5f * (i % 2));
  }
  glEnd();
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1, 1, 1);
  glVertex2f(-0.65f, -0.2f);
  for (int i = 0; i < 6; ++i) {
    double a = CONF_PI * i / 5;
    glColor3f(0.3f, 0.5f + 0.1f * i, 1);
    glVertex2f(-0.65f + 0.32f * (float)cos(a), -0.2f + 0.32f * (float)sin(a));
  }
  glEnd();
  glBegin(GL_QUADS);
  glColor3f(1, 0.6f, 0.2f);
  glVertex2f(-0.2f, -0.3f);
  glVertex2f(0.25f, -0.25f);
  glColor3f(0.2f, 0.6f, 1);
  glVertex2f(0.22f, 0.15f);
  glVertex2f(-0.25f, 0.2f);
  glEnd();
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i < 5; ++i) {
    glColor3f(1, 0.2f * i, 0.6f);
    glVertex2f(0.35f + 0.14f * i, -0.3f);
    glVertex2f(0.35f + 0.14f * i, 0.1f + 0.03f * i);
  }
  glEnd();
  glBegin(GL_POLYGON);
  for (int i = 0; i < 7; ++i) {
    double a = 2.0 * CONF_PI * i / 7;
    glColor3f(0.5f + 0.5f * (float)cos(a), 0.5f + 0.5f * (float)sin(a), 0.8f);
    glVertex2f(0.5f * (float)cos(a), -0.68f + 0.28f * (float)sin(a));
  }
  glEnd();
  glRectf(0.6f, -0.95f, 0.9f, -0.6f);
}

/* A lit sphere: faces both ways in one draw. */
static void sphere(int slices, int stacks) {
  static const GLfloat light_pos[] = {1, 1, 1, 0};
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  conf_sphere(0.9f, slices, stacks);
  glDisable(GL_LIGHTING);
}

static void edge_flags(void) {
  glBegin(GL_POLYGON); /* a hexagon with every other edge hidden */
  for (int i = 0; i < 6; ++i) {
    double a = 2.0 * CONF_PI * i / 6;
    glEdgeFlag(i % 2 ? GL_FALSE : GL_TRUE);
    glColor3f(1, 0.3f + 0.1f * i, 0.3f);
    glVertex2f(-0.45f + 0.4f * (float)cos(a), 0.45f + 0.4f * (float)sin(a));
  }
  glEnd();
  glEdgeFlag(GL_TRUE);
  glBegin(GL_QUADS); /* a quad strip drawn as separate quads, inner edges hidden */
  for (int i = 0; i < 3; ++i) {
    float x = 0.1f + 0.28f * i;
    glColor3f(0.3f, 1, 0.4f);
    glEdgeFlag(GL_TRUE);
    glVertex2f(x, 0.1f);
    glEdgeFlag(i == 2);
    glVertex2f(x + 0.28f, 0.1f);
    glEdgeFlag(GL_TRUE);
    glVertex2f(x + 0.28f, 0.8f);
    glEdgeFlag(i == 0);
    glVertex2f(x, 0.8f);
  }
  glEnd();
  glEdgeFlag(GL_TRUE);
  /* an edge-flag array on a triangle fan drawn as triangles */
  static const GLfloat v[18] = {-0.9f, -0.9f, -0.1f, -0.9f, -0.5f, -0.2f, -0.1f, -0.9f, 0.3f, -0.3f, -0.5f, -0.2f,
                                0.3f, -0.3f, 0.9f, -0.8f, 0.6f, -0.1f};
  static const GLboolean flags[9] = {1, 0, 1, 1, 0, 1, 1, 1, 0};
  glColor3f(0.4f, 0.7f, 1);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, v);
  glEdgeFlagPointer(0, flags);
  glDrawArrays(GL_TRIANGLES, 0, 9);
  glDisableClientState(GL_EDGE_FLAG_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

static void hidden_lines(int offset_lines) {
  glEnable(GL_DEPTH_TEST);
  glRotatef(30, 1, 0.3f, 0);
  if (!offset_lines) {
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1, 1);
  }
  glColor3f(0.15f, 0.15f, 0.2f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  conf_sphere(0.9f, 18, 12);
  glDisable(GL_POLYGON_OFFSET_FILL);
  if (offset_lines) {
    glEnable(GL_POLYGON_OFFSET_LINE);
    glEnable(GL_POLYGON_OFFSET_POINT);
    glPolygonOffset(-1, -2);
  }
  glColor3f(1, 1, 0.6f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  conf_sphere(0.9f, 18, 12);
  glPointSize(3);
  glColor3f(1, 0.3f, 0.3f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  conf_sphere(0.9f, 18, 12);
  glPointSize(1);
  glDisable(GL_POLYGON_OFFSET_LINE);
  glDisable(GL_POLYGON_OFFSET_POINT);
  glPolygonOffset(0, 0);
  glDisable(GL_DEPTH_TEST);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 384, 288)) return 1;
  glClearColor(0.08f, 0.08f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  ortho_panel(&c, 0, 0); /* lines, both faces */
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  primitives();
  ortho_panel(&c, 1, 0); /* points, both faces */
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glPointSize(3);
  primitives();
  glPointSize(1);
  ortho_panel(&c, 2, 0); /* front filled, back lines; flat */
  glShadeModel(GL_FLAT);
  glPolygonMode(GL_FRONT, GL_FILL);
  glPolygonMode(GL_BACK, GL_LINE);
  primitives();
  glShadeModel(GL_SMOOTH);
  ortho_panel(&c, 3, 0); /* front lines, back points, back faces culled after all */
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  glLineWidth(2);
  primitives();
  glEnable(GL_CULL_FACE);
  glTranslatef(0.05f, 0.05f, 0);
  glColor3f(1, 1, 1);
  glLineWidth(1);
  primitives();
  glDisable(GL_CULL_FACE);

  perspective_panel(&c, 0, 1); /* a lit wire sphere, two-sided, back faces points */
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  glPointSize(2);
  sphere(16, 10);
  glPointSize(1);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  ortho_panel(&c, 1, 1);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  edge_flags();
  ortho_panel(&c, 2, 1); /* stippled, wide edges */
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x33ff);
  glLineWidth(2);
  primitives();
  glDisable(GL_LINE_STIPPLE);
  glLineWidth(1);
  perspective_panel(&c, 3, 1); /* clipped by the view volume */
  glScalef(1.9f, 1.9f, 1);
  glRotatef(20, 0, 0, 1);
  primitives();

  perspective_panel(&c, 0, 2);
  hidden_lines(0);
  perspective_panel(&c, 1, 2);
  hidden_lines(1);
  ortho_panel(&c, 2, 2); /* smooth lines as polygon edges, blended */
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  primitives();
  glDisable(GL_BLEND);
  glDisable(GL_LINE_SMOOTH);
  perspective_panel(&c, 3, 2); /* wide points of a sphere, depth tested */
  glEnable(GL_DEPTH_TEST);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glPointSize(4);
  glColor3f(0.5f, 1, 0.7f);
  conf_sphere(0.9f, 14, 9);
  glDisable(GL_DEPTH_TEST);
  glPointSize(1);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  return conf_finish(&c);
}
