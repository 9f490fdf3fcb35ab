/* User clip planes (GL 1.1 section 2.11) and the state of points, lines and polygon modes
 * (sections 2.6.2, 3.3-3.5, tables 6.9-6.12): planes given in object space under one
 * modelview and drawn under another, lit spheres cut by one to eight planes (Mesa has 8),
 * lines, points and polygons in GL_LINE mode cut by planes, a plane compiled into a display
 * list, planes in perspective. The last panel draws the values observed (glGetError after
 * each call, glGetClipPlane, glGet of the point, line and polygon-mode state) as cells whose
 * colour encodes each value; the values are also recorded (conf_value) and compared with
 * Mesa's one by one. A 4 x 2 grid of panels. */
#include <math.h>
#include <stdio.h>

#include "conf.h"

#define COLS 4
#define ROWS 2

static void panel(const ConfContext* c, int col, int row, int perspective) {
  conf_panel(c, col, row, COLS, ROWS);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  if (perspective) glFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 10.0);
  else glOrtho(-1.2, 1.2, -0.9, 0.9, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void lights_on(void) {
  static const GLfloat pos[] = {0.4f, 0.8f, 1.0f, 0.0f};
  static const GLfloat diffuse[] = {0.9f, 0.7f, 0.4f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
}

static void lights_off(void) {
  glDisable(GL_LIGHTING);
  glDisable(GL_LIGHT0);
  glDisable(GL_DEPTH_TEST);
}

static void disable_planes(void) {
  for (int i = 0; i < 8; ++i) glDisable(GL_CLIP_PLANE0 + i);
}

/* One plane given under a rotation, the sphere drawn under another (the plane stays where it
 * was given, in eye space); two-sided lighting shows the inside. */
static void one_plane(void) {
  static const GLdouble eq[] = {1.0, 0.3, 0.2, 0.1};
  glPushMatrix();
  glRotatef(35.0f, 0, 0, 1);
  glClipPlane(GL_CLIP_PLANE0, eq);
  glPopMatrix();
  glEnable(GL_CLIP_PLANE0);
  lights_on();
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glRotatef(60.0f, 1, 0, 0);
  conf_sphere(0.8f, 24, 16);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  lights_off();
  disable_planes();
}

/* Eight planes around a sphere: a rounded octagonal cut. */
static void eight_planes(void) {
  for (int i = 0; i < 8; ++i) {
    double a = i * CONF_PI / 4.0 + 0.2;
    GLdouble eq[4] = {-cos(a), -sin(a), 0.15 * (i % 3), 0.62};
    glClipPlane(GL_CLIP_PLANE0 + i, eq);
    glEnable(GL_CLIP_PLANE0 + i);
  }
  lights_on();
  glRotatef(-30.0f, 1, 1, 0);
  conf_sphere(0.85f, 28, 18);
  lights_off();
  disable_planes();
}

/* Lines of every direction, flat and smooth colours, wide and thin, cut by two planes. */
static void lines(void) {
  static const GLdouble a[] = {1.0, 1.0, 0.0, 0.5}, b[] = {-1.0, 0.4, 0.0, 0.7};
  glClipPlane(GL_CLIP_PLANE2, a);
  glClipPlane(GL_CLIP_PLANE5, b);
  glEnable(GL_CLIP_PLANE2);
  glEnable(GL_CLIP_PLANE5);
  for (int w = 0; w < 3; ++w) {
    glLineWidth(1.0f + 2.0f * w);
    glShadeModel(w == 1 ? GL_FLAT : GL_SMOOTH);
    glBegin(GL_LINES);
    for (int i = 0; i < 12; ++i) {
      double t = i * CONF_PI / 12.0 + 0.1 * w;
      float r = 1.1f - 0.25f * w;
      glColor3f(1.0f, 0.2f + 0.06f * i, 0.3f * w);
      glVertex2f((float)(-r * cos(t)), (float)(-r * sin(t)) * 0.8f);
      glColor3f(0.2f, 0.5f, 1.0f - 0.05f * i);
      glVertex2f((float)(r * cos(t)), (float)(r * sin(t)) * 0.8f);
    }
    glEnd();
  }
  glShadeModel(GL_SMOOTH);
  glBegin(GL_LINE_LOOP);
  glColor3f(1, 1, 1);
  for (int i = 0; i < 9; ++i) glVertex2f((float)(0.9 * cos(i * 0.7)), (float)(0.7 * sin(i * 0.7)));
  glEnd();
  glLineWidth(1.0f);
  disable_planes();
}

/* Points of sizes 1 to 5 on a grid: those whose vertex a plane cuts away are not drawn. */
static void points(void) {
  static const GLdouble eq[] = {0.6, -1.0, 0.0, 0.3};
  glPushMatrix();
  glTranslatef(0.2f, 0.0f, 0.0f);
  glClipPlane((GL_CLIP_PLANE0 + 7), eq);
  glPopMatrix();
  glEnable((GL_CLIP_PLANE0 + 7));
  for (int i = 0; i < 14; ++i) {
    glPointSize(1.0f + (float)(i % 5));
    glBegin(GL_POINTS);
    for (int j = 0; j < 11; ++j) {
      glColor3f(0.3f + 0.05f * i, 0.9f - 0.07f * j, 0.5f);
      glVertex2f(-1.1f + 0.165f * i, -0.8f + 0.155f * j);
    }
    glEnd();
  }
  glPointSize(1.0f);
  disable_planes();
}

/* A sphere in GL_LINE mode (front) and GL_POINT mode (back), cut by a plane: no edge is
 * drawn along the cut. */
static void unfilled(void) {
  static const GLdouble eq[] = {0.0, -1.0, 0.3, 0.35};
  glClipPlane(GL_CLIP_PLANE1, eq);
  glEnable(GL_CLIP_PLANE1);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  glPointSize(2.0f);
  glColor3f(0.9f, 0.9f, 0.3f);
  glRotatef(25.0f, 1, 0, 0);
  conf_sphere(0.8f, 16, 10);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glPointSize(1.0f);
  disable_planes();
}

/* In perspective: quads with flat colours cut by a plane given with the camera transform. */
static void perspective(void) {
  static const GLdouble eq[] = {0.3, 1.0, 0.0, 0.2};
  glTranslatef(0.0f, 0.0f, -3.0f);
  glRotatef(-50.0f, 1, 0, 0);
  glClipPlane(GL_CLIP_PLANE3, eq);
  glEnable(GL_CLIP_PLANE3);
  glShadeModel(GL_FLAT);
  glBegin(GL_QUADS);
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      float x = -1.5f + 0.5f * i, y = -1.5f + 0.5f * j;
      glColor3f(0.2f + 0.13f * i, 0.2f + 0.13f * j, (i + j) % 2 ? 0.9f : 0.2f);
      glVertex2f(x, y), glVertex2f(x + 0.5f, y), glVertex2f(x + 0.5f, y + 0.5f), glVertex2f(x, y + 0.5f);
    }
  }
  glEnd();
  glShadeModel(GL_SMOOTH);
  disable_planes();
}

/* glClipPlane compiled into a list takes the modelview of when the list runs. */
static void in_list(void) {
  static const GLdouble eq[] = {1.0, 0.0, 0.0, 0.0};
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glClipPlane(GL_CLIP_PLANE4, eq);
  glEndList();
  glPushMatrix();
  glRotatef(-40.0f, 0, 0, 1);
  glCallList(list);
  glPopMatrix();
  glEnable(GL_CLIP_PLANE4);
  lights_on();
  conf_sphere(0.8f, 20, 14);
  lights_off();
  disable_planes();
  glDeleteLists(list, 1);
}

enum { kCols = 12, kRows = 9, kCells = kCols * kRows };
static unsigned values[kCells];
static int n_values = 0;
static ConfContext* conf;

static void record(const char* what, unsigned v) {
  char name[96];
  snprintf(name, sizeof name, "%03d %s", n_values, what);
  conf_value(conf, name, (double)v);
  if (n_values < kCells) values[n_values] = v;
  ++n_values;
}

static void error(const char* what) { record(what, glGetError()); }

static void get_ints(const char* what, GLenum pname, int n) {
  GLint v[4] = {-7, -7, -7, -7};
  glGetIntegerv(pname, v);
  for (int i = 0; i < n; ++i) record(what, (unsigned)v[i]);
}

static void get_floats(const char* what, GLenum pname, int n) {
  GLfloat v[4] = {-7, -7, -7, -7};
  glGetFloatv(pname, v);
  for (int i = 0; i < n; ++i) record(what, (unsigned)(GLint)(v[i] * 100.0f));
}

static void clip_plane_values(void) {
  static const GLdouble eq[] = {1.0, 2.0, -3.0, 0.5};
  GLdouble out[4] = {-9, -9, -9, -9};
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(1.0f, 2.0f, 3.0f);
  glScalef(2.0f, 1.0f, 0.5f);
  glClipPlane((GL_CLIP_PLANE0 + 6), eq);
  error("glClipPlane(6)");
  glLoadIdentity();
  glGetClipPlane((GL_CLIP_PLANE0 + 6), out);
  error("glGetClipPlane(6)");
  for (int i = 0; i < 4; ++i) record("plane 6 in eye space x 1000", (unsigned)(GLint)lround(out[i] * 1000.0));
  glClipPlane(GL_CLIP_PLANE0 + 8, eq);
  error("glClipPlane(GL_CLIP_PLANE0 + 8)");
  glGetClipPlane(GL_CLIP_PLANE0 + 8, out);
  error("glGetClipPlane(GL_CLIP_PLANE0 + 8)");
  glClipPlane(GL_LIGHT0, eq);
  error("glClipPlane(GL_LIGHT0)");
  glEnable((GL_CLIP_PLANE0 + 7));
  error("glEnable((GL_CLIP_PLANE0 + 7))");
  record("glIsEnabled((GL_CLIP_PLANE0 + 7))", glIsEnabled((GL_CLIP_PLANE0 + 7)));
  record("glIsEnabled((GL_CLIP_PLANE0 + 6))", glIsEnabled((GL_CLIP_PLANE0 + 6)));
  glDisable((GL_CLIP_PLANE0 + 7));
  get_ints("GL_MAX_CLIP_PLANES", GL_MAX_CLIP_PLANES, 1);
  glBegin(GL_TRIANGLES);
  glClipPlane(GL_CLIP_PLANE0, eq);
  glEnd();
  error("glClipPlane inside glBegin");
}

static void point_line_values(void) {
  glLineWidth(0.0f);
  error("glLineWidth(0)");
  glLineWidth(-2.0f);
  error("glLineWidth(-2)");
  glLineWidth(3.5f);
  error("glLineWidth(3.5)");
  get_floats("GL_LINE_WIDTH x 100", GL_LINE_WIDTH, 1);
  glLineWidth(1.0f);
  glPointSize(0.0f);
  error("glPointSize(0)");
  glPointSize(2.25f);
  get_floats("GL_POINT_SIZE x 100", GL_POINT_SIZE, 1);
  glPointSize(1.0f);
  get_floats("GL_LINE_WIDTH_RANGE x 100", GL_LINE_WIDTH_RANGE, 2);
  get_floats("GL_LINE_WIDTH_GRANULARITY x 100", GL_LINE_WIDTH_GRANULARITY, 1);
  get_floats("GL_POINT_SIZE_RANGE x 100", GL_POINT_SIZE_RANGE, 2);
  get_floats("GL_POINT_SIZE_GRANULARITY x 100", GL_POINT_SIZE_GRANULARITY, 1);
  get_ints("GL_LINE_STIPPLE_PATTERN", GL_LINE_STIPPLE_PATTERN, 1);
  get_ints("GL_LINE_STIPPLE_REPEAT", GL_LINE_STIPPLE_REPEAT, 1);
  glLineStipple(0, 0x1234);
  error("glLineStipple(0, 0x1234)");
  get_ints("GL_LINE_STIPPLE_REPEAT after 0", GL_LINE_STIPPLE_REPEAT, 1);
  get_ints("GL_LINE_STIPPLE_PATTERN", GL_LINE_STIPPLE_PATTERN, 1);
  glLineStipple(300, 0xf0f0);
  get_ints("GL_LINE_STIPPLE_REPEAT after 300", GL_LINE_STIPPLE_REPEAT, 1);
  glLineStipple(1, 0xffff);
  record("glIsEnabled(GL_LINE_STIPPLE)", glIsEnabled(GL_LINE_STIPPLE));
  record("glIsEnabled(GL_LINE_SMOOTH)", glIsEnabled(GL_LINE_SMOOTH));
  record("glIsEnabled(GL_POINT_SMOOTH)", glIsEnabled(GL_POINT_SMOOTH));
  glBegin(GL_LINES);
  glLineWidth(2.0f);
  glEnd();
  error("glLineWidth inside glBegin");
}

static void polygon_mode_values(void) {
  get_ints("GL_POLYGON_MODE initial", GL_POLYGON_MODE, 2);
  glPolygonMode(GL_FRONT, GL_LINE);
  error("glPolygonMode(GL_FRONT, GL_LINE)");
  glPolygonMode(GL_BACK, GL_POINT);
  get_ints("GL_POLYGON_MODE front line, back point", GL_POLYGON_MODE, 2);
  glPolygonMode(GL_FRONT_AND_BACK, GL_TRIANGLES);
  error("glPolygonMode(bad mode)");
  glPolygonMode(GL_LEFT, GL_FILL);
  error("glPolygonMode(GL_LEFT)");
  glPolygonMode(GL_LEFT, GL_QUADS);
  error("glPolygonMode(bad face, bad mode)");
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  get_ints("GL_POLYGON_MODE fill", GL_POLYGON_MODE, 2);
  get_ints("GL_EDGE_FLAG initial", GL_EDGE_FLAG, 1);
  glEdgeFlag(GL_FALSE);
  get_ints("GL_EDGE_FLAG after glEdgeFlag(GL_FALSE)", GL_EDGE_FLAG, 1);
  glBegin(GL_POLYGON);
  glEdgeFlag(GL_TRUE);
  glEnd();
  error("glEdgeFlag inside glBegin");
  get_ints("GL_EDGE_FLAG after glEdgeFlag(GL_TRUE)", GL_EDGE_FLAG, 1);
  {
    GLboolean f = GL_FALSE;
    glEdgeFlagv(&f);
    get_ints("GL_EDGE_FLAG after glEdgeFlagv", GL_EDGE_FLAG, 1);
    glEdgeFlag(GL_TRUE);
  }
  glEdgeFlagPointer(-1, 0);
  error("glEdgeFlagPointer(-1)");
  {
    static const GLboolean flags[4] = {GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE};
    glEdgeFlagPointer(2, flags);
    error("glEdgeFlagPointer(2)");
    get_ints("GL_EDGE_FLAG_ARRAY_STRIDE", GL_EDGE_FLAG_ARRAY_STRIDE, 1);
    glEdgeFlagPointer(0, 0);
  }
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  record("glIsEnabled(GL_EDGE_FLAG_ARRAY)", glIsEnabled(GL_EDGE_FLAG_ARRAY));
  glDisableClientState(GL_EDGE_FLAG_ARRAY);
  record("glIsEnabled(GL_POLYGON_OFFSET_LINE)", glIsEnabled(GL_POLYGON_OFFSET_LINE));
  glEnable(GL_POLYGON_OFFSET_POINT);
  record("glIsEnabled(GL_POLYGON_OFFSET_POINT)", glIsEnabled(GL_POLYGON_OFFSET_POINT));
  glDisable(GL_POLYGON_OFFSET_POINT);
  error("no error left");
}

static void draw_values(const ConfContext* c) {
  conf_panel(c, 3, 1, COLS, ROWS);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kCols, kRows, 0, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  for (int i = 0; i < n_values && i < kCells; ++i) {
    /* 9 bits of the value, 3 per channel, each step 33/255 apart. */
    unsigned v = values[i], h = (v ^ (v >> 9) ^ (v >> 18) ^ (v >> 27)) & 511u;
    glColor3ub((GLubyte)(20 + 33 * (h & 7)), (GLubyte)(20 + 33 * ((h >> 3) & 7)), (GLubyte)(20 + 33 * (h >> 6)));
    float x = (float)(i % kCols), y = (float)(i / kCols);
    glRectf(x + 0.1f, y + 0.1f, x + 0.9f, y + 0.9f);
  }
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 384, 256)) return 1;
  conf = &c;
  glClearColor(0.1f, 0.1f, 0.12f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  panel(&c, 0, 0, 0);
  one_plane();
  panel(&c, 1, 0, 0);
  eight_planes();
  panel(&c, 2, 0, 0);
  lines();
  panel(&c, 3, 0, 0);
  points();
  panel(&c, 0, 1, 0);
  unfilled();
  panel(&c, 1, 1, 1);
  perspective();
  panel(&c, 2, 1, 0);
  in_list();
  clip_plane_values();
  point_line_values();
  polygon_mode_values();
  draw_values(&c);
  return conf_finish(&c);
}
