/* Points, lines and polygon modes in display lists (GL 1.1 sections 3.3-3.5, 5.4), which
 * shadelab compiles into meshes at glEndList and draws vertex by vertex when the state at
 * glCallList asks for it: lines and line strips, loops and points compiled (widths, sizes and
 * stipple set inside and outside the list, flat and smooth, lit); GL_COMPILE_AND_EXECUTE;
 * filled polygons compiled and called under glPolygonMode GL_LINE and GL_POINT; edge flags
 * from glEdgeFlag inside a compiled glBegin/glEnd and from an edge-flag array dereferenced by
 * glArrayElement and glDrawArrays at compile time (the arrays changed before the call); line
 * glDrawArrays / glDrawElements compiled; a list called under a user clip plane and a new
 * modelview; a stippled strip of 3,000 vertices; evaluator meshes in GL_LINE and GL_POINT
 * modes compiled; stippled glRect outlines; hidden-line removal (GL_POLYGON_OFFSET_LINE) from
 * lists; wide smooth lines and points blended. A 4 x 3 grid of panels. */
#include <math.h>

#include "conf.h"

enum { kCols = 4, kRows = 3 };

static void panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, kCols, kRows);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.2, 1.2, -1.2, 1.2, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void star_lines(int rays, float r) {
  glBegin(GL_LINES);
  for (int i = 0; i < rays; ++i) {
    double a = 2.0 * CONF_PI * (i + 0.25) / rays;
    glColor3f(1, 0.3f + 0.02f * i, 0.2f);
    glVertex2f(0, 0);
    glColor3f(0.2f, 0.5f, 1);
    glVertex2f(r * (float)cos(a), r * (float)sin(a));
  }
  glEnd();
}

/* Lines, strips and loops compiled, widths and stipple inside the list. */
static void lines_list(void) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glLineWidth(2.0f);
  glPushMatrix();
  glTranslatef(-0.55f, 0.55f, 0);
  star_lines(12, 0.5f);
  glPopMatrix();
  glLineWidth(1.0f);
  glShadeModel(GL_FLAT);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i < 10; ++i) {
    glColor3f(0.1f * i, 1 - 0.1f * i, 0.5f);
    glVertex2f(0.1f + 0.1f * i, 0.2f + 0.7f * (i % 2));
  }
  glEnd();
  glShadeModel(GL_SMOOTH);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x33ff);
  glLineWidth(3.0f);
  glBegin(GL_LINE_LOOP);
  for (int i = 0; i < 7; ++i) {
    double a = 2.0 * CONF_PI * i / 7;
    glColor3f(0.3f + 0.1f * i, 1, 0.3f);
    glVertex2f(-0.55f + 0.45f * (float)cos(a), -0.55f + 0.45f * (float)sin(a));
  }
  glEnd();
  glDisable(GL_LINE_STIPPLE);
  glLineWidth(1.0f);
  glEndList();
  glCallList(list);
  /* Called again under state set outside the list: a wider line and a stipple. */
  glLineWidth(4.0f);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x0f0f);
  glTranslatef(0.55f, -0.6f, 0);
  glScalef(0.8f, 0.8f, 1);
  glCallList(list);
  glDisable(GL_LINE_STIPPLE);
  glLineWidth(1.0f);
  glDeleteLists(list, 1);
}

/* Points compiled with GL_COMPILE_AND_EXECUTE, sizes and smoothing in the list; then called
 * lit with a normal per point. */
static void points_list(void) {
  GLuint list = glGenLists(2);
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  for (int s = 1; s <= 6; ++s) {
    glPointSize((float)s + 0.5f * (s % 2));
    glBegin(GL_POINTS);
    for (int i = 0; i < 6; ++i) {
      glColor3f(0.2f + 0.15f * s, 0.2f + 0.12f * i, 1.0f - 0.1f * s);
      glVertex2f(-1.0f + 0.17f * i, 1.0f - 0.16f * s);
    }
    glEnd();
  }
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glPointSize(7.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 5; ++i) glVertex2f(0.2f + 0.2f * i, 0.9f);
  glEnd();
  glDisable(GL_BLEND);
  glDisable(GL_POINT_SMOOTH);
  glPointSize(1.0f);
  glEndList();
  const GLfloat pos[] = {0.3f, 0.6f, 1.0f, 0.0f};
  glNewList(list + 1, GL_COMPILE);
  glBegin(GL_POINTS);
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 5; ++j) {
      double a = 2.0 * CONF_PI * i / 8;
      glNormal3f((float)cos(a), (float)sin(a), 0.5f + 0.1f * j);
      glVertex2f(0.15f + 0.12f * i, -0.2f - 0.18f * j);
    }
  }
  glEnd();
  glEndList();
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glPointSize(4.0f);
  glCallList(list + 1);
  glDisable(GL_LIGHTING);
  glDisable(GL_NORMALIZE);
  glPointSize(3.0f);
  glTranslatef(-1.0f, 0.0f, 0.0f);
  glCallList(list + 1); /* unlit: the current colour */
  glPointSize(1.0f);
  glDeleteLists(list, 2);
}

/* Filled polygons compiled, called with the faces in line and point modes. */
static void unfilled_calls(void) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 4; ++i) {
    float x = -0.5f + 0.25f * i;
    glColor3f(1, 0.25f * i, 0.2f);
    glVertex2f(x, -0.4f);
    glColor3f(0.2f, 1, 0.25f * i);
    glVertex2f(x + 0.22f, -0.4f);
    glColor3f(0.3f, 0.3f, 1);
    glVertex2f(x + 0.1f, i % 2 ? -0.05f : 0.2f);
  }
  glEnd();
  glBegin(GL_QUADS);
  glColor3f(0.9f, 0.9f, 0.3f);
  glVertex2f(-0.5f, 0.3f), glVertex2f(0.5f, 0.3f), glVertex2f(0.5f, 0.5f), glVertex2f(-0.5f, 0.5f);
  glEnd();
  glBegin(GL_POLYGON);
  for (int i = 0; i < 6; ++i) {
    double a = 2.0 * CONF_PI * i / 6;
    glColor3f(0.5f + 0.08f * i, 0.4f, 1 - 0.1f * i);
    glVertex2f(0.3f * (float)cos(a), -0.75f + 0.2f * (float)sin(a));
  }
  glEnd();
  glEndList();
  glPushMatrix();
  glTranslatef(-0.55f, 0.45f, 0);
  glScalef(0.9f, 0.9f, 1);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glCallList(list);
  glTranslatef(1.2f, 0, 0);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glPointSize(3.0f);
  glCallList(list);
  glPointSize(1.0f);
  glPopMatrix();
  glTranslatef(0, -0.6f, 0);
  glScalef(0.9f, 0.9f, 1);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_FILL);
  glLineWidth(2.0f);
  glCallList(list);
  glLineWidth(1.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDeleteLists(list, 1);
}

/* Edge flags in lists: glEdgeFlag inside glBegin/glEnd; an edge-flag array read at compile
 * time by glArrayElement and glDrawArrays (changed before the list is called). */
static void edge_flag_lists(void) {
  GLuint list = glGenLists(1);
  static const GLfloat v[] = {-0.9f, 0.1f, -0.1f, 0.1f, -0.1f, 0.9f, -0.9f, 0.9f,
                              0.1f, 0.1f, 0.9f, 0.1f, 0.9f, 0.9f, 0.1f, 0.9f};
  GLboolean flags[8] = {1, 0, 1, 0, 0, 1, 0, 1};
  glNewList(list, GL_COMPILE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glLineWidth(2.0f);
  glBegin(GL_POLYGON);
  for (int i = 0; i < 8; ++i) {
    double a = 2.0 * CONF_PI * i / 8;
    glEdgeFlag(i % 3 != 0);
    glColor3f(1, 0.4f + 0.07f * i, 0.3f);
    glVertex2f(-0.5f + 0.38f * (float)cos(a), -0.55f + 0.38f * (float)sin(a));
  }
  glEnd();
  glEdgeFlag(GL_TRUE);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, v);
  glEdgeFlagPointer(0, flags);
  glColor3f(0.3f, 1, 0.5f);
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) glArrayElement(i);
  glEnd();
  glColor3f(0.4f, 0.6f, 1);
  glDrawArrays(GL_QUADS, 4, 4);
  glDisableClientState(GL_EDGE_FLAG_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glLineWidth(1.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glEndList();
  for (int i = 0; i < 8; ++i) flags[i] = 1;
  glEdgeFlag(GL_TRUE);
  glCallList(list);
  /* Mesa leaves the current values unchanged after a list whose glBegin/glEnd is followed by a
   * glDrawArrays (docs/gl-conformance.md); GL 1.1 leaves the last glArrayElement's flag. */
  glEdgeFlag(GL_TRUE);
  glDeleteLists(list, 1);
}

/* Line draws from vertex arrays compiled (dereferenced at compile time). */
static void array_lines_list(void) {
  GLfloat v[30][2];
  GLubyte col[30][4];
  for (int i = 0; i < 30; ++i) {
    v[i][0] = -1.0f + 2.0f * (float)((i * 37) % 29) / 29.0f;
    v[i][1] = -1.0f + 2.0f * (float)((i * 53) % 31) / 31.0f;
    col[i][0] = (GLubyte)(i * 8), col[i][1] = (GLubyte)(255 - i * 8), col[i][2] = 180, col[i][3] = 255;
  }
  static const GLushort loop[] = {20, 21, 22, 23, 24, 25};
  GLuint list = glGenLists(1);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, v);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, col);
  glNewList(list, GL_COMPILE);
  glDrawArrays(GL_LINES, 0, 10);
  glLineWidth(2.0f);
  glDrawArrays(GL_LINE_STRIP, 10, 10);
  glDrawElements(GL_LINE_LOOP, 6, GL_UNSIGNED_SHORT, loop);
  glPointSize(5.0f);
  glDrawArrays(GL_POINTS, 26, 4);
  glPointSize(1.0f);
  glLineWidth(1.0f);
  glEndList();
  for (int i = 0; i < 30; ++i) v[i][0] = 0.0f; /* the list keeps the compiled vertices */
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glScalef(0.9f, 0.9f, 1);
  glCallList(list);
  glDeleteLists(list, 1);
}

/* Lines and a wire sphere in a list, called under a clip plane given under another modelview. */
static void clipped_list(void) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  star_lines(24, 1.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glColor3f(0.8f, 0.8f, 0.8f);
  conf_sphere(0.6f, 12, 8);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glEndList();
  const GLdouble eq[] = {1.0, 0.6, 0.0, 0.1};
  glPushMatrix();
  glRotatef(25, 0, 0, 1);
  glClipPlane(GL_CLIP_PLANE0, eq);
  glPopMatrix();
  glEnable(GL_CLIP_PLANE0);
  glRotatef(30, 1, 1, 0);
  glCallList(list);
  glDisable(GL_CLIP_PLANE0);
  glDeleteLists(list, 1);
}

/* A long stippled strip (the stipple runs on across the whole strip) and a long loop. */
static void long_strip_list(void) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x3f3f);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i < 3000; ++i) {
    double t = i / 3000.0, a = 2.0 * CONF_PI * 6.0 * t;
    glColor3f((float)t, 0.6f, 1.0f - (float)t);
    glVertex2f((float)((0.2 + 0.8 * t) * cos(a)), (float)((0.2 + 0.8 * t) * sin(a)));
  }
  glEnd();
  glDisable(GL_LINE_STIPPLE);
  glBegin(GL_LINE_LOOP);
  for (int i = 0; i < 200; ++i) {
    double a = 2.0 * CONF_PI * i / 200;
    glColor3f(1, 1, (float)(i % 2));
    glVertex2f(1.1f * (float)cos(a), 1.1f * (float)sin(a));
  }
  glEnd();
  glEndList();
  glCallList(list);
  glDeleteLists(list, 1);
}

/* Wide points and lines in a list under depth testing against a filled surface. */
static void depth_list(void) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glColor3f(0.3f, 0.3f, 0.5f);
  glBegin(GL_QUADS);
  glVertex3f(-1, -1, -0.5f), glVertex3f(1, -1, 0.5f), glVertex3f(1, 1, 0.5f), glVertex3f(-1, 1, -0.5f);
  glEnd();
  glLineWidth(3.0f);
  glBegin(GL_LINES);
  for (int i = 0; i < 10; ++i) {
    float y = -0.9f + 0.2f * i;
    glColor3f(1, 0.8f, 0.2f);
    glVertex3f(-1.0f, y, -0.3f + 0.06f * i);
    glColor3f(0.2f, 1, 0.8f);
    glVertex3f(1.0f, y, 0.3f - 0.06f * i);
  }
  glEnd();
  glPointSize(6.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 7; ++i) {
    glColor3f(1, 0.3f, 1);
    glVertex3f(-0.9f + 0.3f * i, 0.1f * (i % 3) - 0.1f, 0.4f - 0.12f * i);
  }
  glEnd();
  glPointSize(1.0f);
  glLineWidth(1.0f);
  glEndList();
  glEnable(GL_DEPTH_TEST);
  glCallList(list);
  glDisable(GL_DEPTH_TEST);
  glDeleteLists(list, 1);
}

/* Evaluator meshes and curves drawn as lines and points (GL 1.1 section 5.1), compiled. */
static void eval_list(void) {
  GLfloat cp[4][4][3];
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      cp[i][j][0] = -0.9f + 0.6f * (float)j;
      cp[i][j][1] = -0.9f + 0.6f * (float)i;
      cp[i][j][2] = ((i == 1 || i == 2) && (j == 1 || j == 2)) ? 0.8f : 0.0f;
    }
  }
  static const GLfloat curve[4][3] = {{-1.0f, 0.9f, 0}, {-0.3f, 0.1f, 0}, {0.3f, 1.1f, 0}, {1.0f, 0.3f, 0}};
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &cp[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &curve[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glColor3f(1, 0.5f, 0.2f);
  glMapGrid2f(8, 0, 1, 6, 0, 1);
  glEvalMesh2(GL_LINE, 0, 8, 0, 6);
  glColor3f(0.2f, 1, 0.3f);
  glPointSize(3);
  glMapGrid2f(5, 0.1f, 0.9f, 5, 0.1f, 0.9f);
  glEvalMesh2(GL_POINT, 0, 5, 0, 5);
  glColor3f(0.4f, 0.6f, 1);
  glLineWidth(2);
  glMapGrid1f(20, 0, 1);
  glEvalMesh1(GL_LINE, 0, 20);
  glColor3f(1, 1, 1);
  glPointSize(4);
  glEvalMesh1(GL_POINT, 0, 20);
  glPointSize(1);
  glLineWidth(1);
  glDisable(GL_MAP2_VERTEX_3);
  glDisable(GL_MAP1_VERTEX_3);
  glEndList();
  glRotatef(20, 1, 0, 0);
  glCallList(list);
  glDeleteLists(list, 1);
}

/* glRect outlines (drawn as Mesa draws rectangles: quads) stippled, and filled beside. */
static void rect_list(void) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x0f3f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  for (int i = 0; i < 5; ++i) {
    glColor3f(1, 0.2f + 0.15f * (float)i, 0.3f);
    glRectf(-0.9f + 0.1f * (float)i, -0.9f + 0.1f * (float)i, 0.9f - 0.12f * (float)i, 0.9f - 0.08f * (float)i);
  }
  glLineStipple(3, 0x5555);
  glColor3f(0.3f, 0.9f, 1);
  glRecti(1, 1, -1, -1); /* clockwise: a back face */
  glDisable(GL_LINE_STIPPLE);
  glPolygonMode(GL_FRONT, GL_FILL);
  glPolygonMode(GL_BACK, GL_POINT);
  glPointSize(3);
  glColor3f(0.9f, 0.9f, 0.3f);
  glRectf(0.3f, -0.2f, -0.2f, 0.3f); /* back facing: its corners */
  glRectf(-0.15f, -0.15f, 0.15f, 0.15f); /* front facing: filled */
  glPointSize(1);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glEndList();
  glCallList(list);
  glDeleteLists(list, 1);
}

/* Hidden-line removal from lists: a surface, then its edges and vertices offset towards the eye. */
static void hidden_line_list(void) {
  GLuint list = glGenLists(2);
  glNewList(list, GL_COMPILE);
  conf_sphere(0.9f, 14, 10);
  glEndList();
  glNewList(list + 1, GL_COMPILE);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.15f, 0.15f, 0.2f);
  glCallList(list);
  glEnable(GL_POLYGON_OFFSET_LINE);
  glEnable(GL_POLYGON_OFFSET_POINT);
  glPolygonOffset(-1, -2);
  glColor3f(1, 1, 0.6f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glCallList(list);
  glPointSize(3);
  glColor3f(1, 0.3f, 0.3f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glCallList(list);
  glPointSize(1);
  glDisable(GL_POLYGON_OFFSET_LINE);
  glDisable(GL_POLYGON_OFFSET_POINT);
  glPolygonOffset(0, 0);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisable(GL_DEPTH_TEST);
  glEndList();
  glRotatef(30, 1, 0.3f, 0);
  glCallList(list + 1);
  glDeleteLists(list, 2);
}

/* Wide smooth lines and points blended, from a list. */
static void smooth_list(void) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_LINE_SMOOTH);
  for (int i = 0; i < 6; ++i) {
    glLineWidth(1.0f + (float)i);
    glBegin(GL_LINES);
    glColor3f(1, 0.3f + 0.1f * (float)i, 0.2f);
    glVertex2f(-0.95f, 0.9f - 0.17f * (float)i);
    glColor3f(0.2f, 0.6f, 1);
    glVertex2f(0.1f, 0.75f - 0.23f * (float)i);
    glEnd();
  }
  glDisable(GL_LINE_SMOOTH);
  glEnable(GL_POINT_SMOOTH);
  for (int i = 0; i < 6; ++i) {
    glPointSize(2.0f + 2.0f * (float)i);
    glBegin(GL_POINTS);
    glColor3f(0.4f + 0.1f * (float)i, 1, 0.5f);
    glVertex2f(0.5f + 0.07f * (float)(i % 2), 0.85f - 0.33f * (float)i);
    glEnd();
  }
  glDisable(GL_POINT_SMOOTH);
  glDisable(GL_BLEND);
  glLineWidth(1);
  glPointSize(1);
  glEndList();
  glCallList(list);
  glDeleteLists(list, 1);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 384, 288)) return 1;
  glClearColor(0.1f, 0.1f, 0.12f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  panel(&c, 0, 0);
  lines_list();
  panel(&c, 1, 0);
  points_list();
  panel(&c, 2, 0);
  unfilled_calls();
  panel(&c, 3, 0);
  edge_flag_lists();
  panel(&c, 0, 1);
  array_lines_list();
  panel(&c, 1, 1);
  clipped_list();
  panel(&c, 2, 1);
  long_strip_list();
  panel(&c, 3, 1);
  depth_list();
  panel(&c, 0, 2);
  eval_list();
  panel(&c, 1, 2);
  rect_list();
  panel(&c, 2, 2);
  hidden_line_list();
  panel(&c, 3, 2);
  smooth_list();
  return conf_finish(&c);
}
