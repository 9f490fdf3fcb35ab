/* Occlusion queries (GL 1.5 section 4.1.6, ARB_occlusion_query): the number of samples that
 * pass the depth test (and every test before it) between glBeginQuery(GL_SAMPLES_PASSED) and
 * glEndQuery, for every kind of fragment: filled polygons of every primitive, hidden and half
 * hidden spheres, points and lines (wide, smooth, stippled), polygons drawn as lines and
 * points, the polygon stipple, the scissor, alpha, stencil and depth tests, colour and depth
 * writes off, vertex arrays, display lists (glBeginQuery / glEndQuery compiled too),
 * glBitmap, glDrawPixels (colour and depth) and glCopyPixels fragments. Each scene draws in a
 * panel of a 4 x 4 grid; its count is recorded (conf_value) and must equal Mesa's. Then the
 * query objects' names, glIsQuery, GL_CURRENT_QUERY, GL_QUERY_COUNTER_BITS, results read with
 * both glGetQueryObject forms, and the errors of the specification (a query begun while one
 * is active, the name 0, an unknown target or pname, a result asked of an active or never
 * begun query, deleting the active query). The last panel draws the values as cells.
 * GL_QUERY_RESULT_AVAILABLE is read only after GL_QUERY_RESULT (Mesa may answer GL_FALSE
 * before the draws are done; shadelab's results are ready at glEndQuery). */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdio.h>

#include "conf.h"

#define COLS 4
#define ROWS 4

static ConfContext* conf;
static GLuint query;

enum { kCols = 12, kRows = 10, kCells = kCols * kRows };
static unsigned values[kCells];
static int n_values = 0;

static void record(const char* what, double v) {
  char name[96];
  snprintf(name, sizeof name, "%03d %s", n_values, what);
  conf_value(conf, name, v);
  if (n_values < kCells) values[n_values] = (unsigned)v;
  ++n_values;
}

static void record_error(const char* what) {
  char name[96];
  snprintf(name, sizeof name, "error %s", what);
  record(name, (double)glGetError());
}

/* Panel `i` of the grid: its viewport and scissor box, depth and stencil cleared, an ortho
 * projection over [-1, 1]^2 (z from -1 to 1 is depth 1 to 0). */
static void panel(int i) {
  conf_panel(conf, i % COLS, i / COLS, COLS, ROWS);
  const int w = conf->width / COLS, h = conf->height / ROWS;
  glScissor((i % COLS) * w, conf->height - (i / COLS + 1) * h, w, h);
  glEnable(GL_SCISSOR_TEST);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDepthFunc(GL_LESS);
  glEnable(GL_DEPTH_TEST);
}

/* The result of `query`, read both ways (they must agree), recorded under `what`. */
static void record_result(const char* what) {
  GLuint u = 0;
  GLint s = 0, available = 0;
  glGetQueryObjectuiv(query, GL_QUERY_RESULT, &u);
  glGetQueryObjectiv(query, GL_QUERY_RESULT, &s);
  glGetQueryObjectiv(query, GL_QUERY_RESULT_AVAILABLE, &available);
  record(what, (double)u);
  char name[96];
  snprintf(name, sizeof name, "%s: int form agrees, available", what);
  record(name, (double)((GLuint)s == u) + 2.0 * (double)available);
}

static void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

static void lit(int on) {
  static const GLfloat pos[] = {0.3f, 0.6f, 1.0f, 0.0f};
  if (on) {
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
  } else {
    glDisable(GL_LIGHTING);
    glDisable(GL_LIGHT0);
  }
}

/* ---- scenes, one per panel ---- */

static void scene_quads(void) { /* every filled primitive: strips, fans, polygons, quads */
  glColor3f(0.8f, 0.3f, 0.2f);
  quad(-0.9f, -0.9f, 0.9f, 0.9f, 0.0f);
  glColor3f(0.2f, 0.7f, 0.3f);
  glBegin(GL_TRIANGLE_FAN);
  glVertex3f(0.0f, 0.0f, 0.5f);
  for (int i = 0; i <= 12; ++i) {
    float a = (float)i * (float)(2.0 * CONF_PI / 12.0);
    glVertex3f(0.6f * (float)cos(a), 0.6f * (float)sin(a), 0.5f);
  }
  glEnd();
  glBegin(GL_TRIANGLE_STRIP);
  glVertex3f(-0.95f, -0.95f, -0.5f), glVertex3f(-0.95f, 0.95f, -0.5f), glVertex3f(-0.7f, -0.95f, 0.9f);
  glVertex3f(-0.7f, 0.95f, 0.9f);
  glEnd();
  glBegin(GL_POLYGON);
  glVertex3f(0.3f, -0.9f, 0.8f), glVertex3f(0.95f, -0.6f, 0.8f), glVertex3f(0.9f, 0.1f, 0.8f), glVertex3f(0.4f, 0.0f, 0.8f);
  glEnd();
}

static void scene_hidden_sphere(void) { /* a wall, then a sphere behind it: nothing passes */
  glColor3f(0.4f, 0.4f, 0.5f);
  quad(-1.0f, -1.0f, 1.0f, 1.0f, 0.9f);
}

static void scene_half_hidden(void) { /* a lit sphere half behind a wall, in perspective */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 6.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -3.0f);
  glColor3f(0.5f, 0.5f, 0.5f);
  glBegin(GL_QUADS);
  glVertex3f(-2.0f, -2.0f, 0.2f), glVertex3f(0.1f, -2.0f, 0.2f), glVertex3f(0.1f, 2.0f, 0.2f), glVertex3f(-2.0f, 2.0f, 0.2f);
  glEnd();
}

static void scene_points_lines(void) {
  glDisable(GL_DEPTH_TEST);
  glColor3f(1.0f, 1.0f, 0.3f);
  glPointSize(1.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 10; ++i) glVertex2f(-0.89f + 0.16f * (float)i, 0.89f); /* on pixel centres */
  glEnd();
  glPointSize(4.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 6; ++i) glVertex2f(-0.8f + 0.3f * (float)i, 0.7f);
  glEnd();
  glEnable(GL_POINT_SMOOTH);
  glPointSize(5.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 5; ++i) glVertex2f(-0.694f + 0.31f * (float)i, 0.456f); /* no pixel centre on a rim */
  glEnd();
  glDisable(GL_POINT_SMOOTH);
  glPointSize(1.0f);
  glBegin(GL_LINES);
  glVertex2f(-0.9f, 0.2f), glVertex2f(0.85f, 0.3f);
  glEnd();
  glLineWidth(3.0f);
  glBegin(GL_LINE_STRIP);
  glVertex2f(-0.9f, 0.0f), glVertex2f(0.0f, -0.2f), glVertex2f(0.8f, 0.1f);
  glEnd();
  glLineWidth(1.0f);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x33f1);
  glBegin(GL_LINE_LOOP);
  glVertex2f(-0.8f, -0.4f), glVertex2f(0.7f, -0.35f), glVertex2f(0.1f, -0.6f);
  glEnd();
  glDisable(GL_LINE_STIPPLE);
  glEnable(GL_LINE_SMOOTH);
  glLineWidth(2.0f);
  glBegin(GL_LINES);
  glVertex2f(-0.9f, -0.9f), glVertex2f(0.9f, -0.75f);
  glEnd();
  glLineWidth(1.0f);
  glDisable(GL_LINE_SMOOTH);
}

static void scene_polygon_modes(void) { /* a filled wall, then polygons as lines and points over it */
  glColor3f(0.3f, 0.3f, 0.6f);
  quad(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f);
  glColor3f(1.0f, 1.0f, 1.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  quad(-0.8f, -0.8f, 0.3f, 0.3f, 0.5f);  /* in front: passes */
  quad(-0.3f, -0.3f, 0.8f, 0.8f, -0.5f); /* behind: hidden */
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glPointSize(3.0f);
  quad(-0.9f, -0.5f, 0.9f, 0.5f, 0.5f);
  glPointSize(1.0f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

static void scene_stipple_scissor(void) {
  static GLubyte pattern[128];
  for (int i = 0; i < 128; ++i) pattern[i] = (GLubyte)((i * 37) ^ (i >> 2) ^ 0x5a);
  glPolygonStipple(pattern);
  glEnable(GL_POLYGON_STIPPLE);
  glColor3f(0.9f, 0.5f, 0.1f);
  quad(-0.9f, -0.9f, 0.0f, 0.9f, 0.0f);
  glDisable(GL_POLYGON_STIPPLE);
  const int w = conf->width / COLS, h = conf->height / ROWS;
  glScissor(w + w / 2 + 3, conf->height - 2 * h + 7, 17, 23); /* inside this panel (5: column 1, row 1) */
  glEnable(GL_SCISSOR_TEST);
  quad(0.0f, -0.9f, 0.9f, 0.9f, 0.0f);
  glDisable(GL_SCISSOR_TEST);
}

static void scene_alpha_test(void) { /* alpha from 0 to 1 across, GL_GREATER 0.4 */
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.4f);
  glBegin(GL_QUADS);
  glColor4f(0.2f, 0.8f, 0.2f, 0.0f);
  glVertex2f(-0.9f, -0.9f);
  glColor4f(0.2f, 0.8f, 0.2f, 1.0f);
  glVertex2f(0.9f, -0.9f);
  glVertex2f(0.9f, 0.9f);
  glColor4f(0.2f, 0.8f, 0.2f, 0.0f);
  glVertex2f(-0.9f, 0.9f);
  glEnd();
  glDisable(GL_ALPHA_TEST);
}

static void scene_stencil(void) { /* a disc written into the stencil, then a quad where it is not */
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glBegin(GL_TRIANGLE_FAN);
  glVertex2f(0.0f, 0.0f);
  for (int i = 0; i <= 20; ++i) {
    float a = (float)i * (float)(2.0 * CONF_PI / 20.0);
    glVertex2f(0.7f * (float)cos(a), 0.7f * (float)sin(a));
  }
  glEnd();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glStencilFunc(GL_NOTEQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColor3f(0.6f, 0.2f, 0.7f);
  quad(-0.9f, -0.9f, 0.9f, 0.9f, 0.0f);
  glDisable(GL_STENCIL_TEST);
}

static void scene_masks_off(void) { /* nothing written, and still counted; GL_EQUAL on a cleared depth */
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  quad(-0.9f, -0.9f, 0.5f, 0.5f, 0.0f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_EQUAL);
  quad(-0.5f, -0.5f, 0.9f, 0.9f, -1.0f); /* depth 1.0: equal to the cleared depth */
  glDepthFunc(GL_LESS);
  GLint draw_buffer = GL_FRONT;
  glGetIntegerv(GL_DRAW_BUFFER, &draw_buffer);
  glDrawBuffer(GL_NONE);
  quad(0.0f, -0.9f, 0.9f, 0.0f, 0.3f);
  glDrawBuffer((GLenum)draw_buffer);
}

static void scene_arrays(void) {
  static GLfloat v[16][2];
  static GLubyte colors[16][4];
  static const GLushort idx[] = {0, 1, 2, 2, 1, 3, 4, 5, 6, 6, 5, 7, 8, 9, 10, 10, 9, 11, 12, 13, 14};
  for (int i = 0; i < 16; ++i) {
    v[i][0] = -0.9f + 0.12f * (float)i;
    v[i][1] = (i % 2 ? 0.8f : -0.7f) * (i % 3 ? 1.0f : 0.5f);
    colors[i][0] = (GLubyte)(i * 15), colors[i][1] = 200, colors[i][2] = (GLubyte)(255 - i * 15), colors[i][3] = 255;
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, v);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
  glDrawElements(GL_TRIANGLES, 21, GL_UNSIGNED_SHORT, idx);
  glDrawArrays(GL_LINE_STRIP, 0, 16);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
}

static void scene_bitmap(void) {
  static GLubyte glyph[16 * 4]; /* 16 rows of 2 bytes, each padded to the default unpack alignment of 4 */
  for (int i = 0; i < 64; ++i) glyph[i] = (GLubyte)((i * 73) ^ 0xa5);
  glColor3f(1.0f, 0.9f, 0.2f);
  glRasterPos2f(-0.9f, 0.5f);
  for (int i = 0; i < 5; ++i) glBitmap(16, 16, 0.0f, 0.0f, 17.0f, -3.0f, glyph);
  glRasterPos3f(-0.9f, -0.5f, -0.9f); /* depth 0.95, behind the quad drawn first: hidden */
  glColor3f(0.3f, 0.3f, 0.3f);
  glBitmap(16, 16, 0.0f, 0.0f, 17.0f, 0.0f, glyph);
}

static void scene_draw_pixels(void) {
  static GLubyte image[12 * 10 * 4];
  static GLfloat depth[12 * 10];
  for (int i = 0; i < 12 * 10; ++i) {
    image[4 * i] = (GLubyte)(i * 2), image[4 * i + 1] = 128, image[4 * i + 2] = (GLubyte)(255 - i), image[4 * i + 3] = 255;
    depth[i] = (float)(i % 12) / 11.0f;
  }
  glRasterPos2f(-0.9f, -0.9f);
  glPixelZoom(2.0f, 1.5f);
  glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glPixelZoom(1.0f, 1.0f);
  glColor3f(0.2f, 0.6f, 0.9f);
  glRasterPos3f(0.1f, 0.1f, 0.0f);
  glDrawPixels(12, 10, GL_DEPTH_COMPONENT, GL_FLOAT, depth); /* against nothing drawn: all pass */
  glRasterPos3f(0.1f, -0.6f, 0.0f);
  glColor3f(0.5f, 0.5f, 0.5f);
  quad(0.05f, -0.7f, 0.9f, 0.0f, 0.0f); /* depth 0.5 */
  glRasterPos3f(0.1f, -0.6f, 0.0f);
  glDrawPixels(12, 10, GL_DEPTH_COMPONENT, GL_FLOAT, depth); /* GL_LESS against 0.5: left part */
}

static void scene_copy_pixels(void) { /* the first panel's colours copied here, zoomed and not */
  const int h = conf->height / ROWS;
  glRasterPos2f(-0.9f, -0.9f);
  glCopyPixels(5, conf->height - h + 5, 30, 20, GL_COLOR);
  glPixelZoom(1.37f, 2.0f); /* no zoomed pixel's edge on a pixel centre (llvmpipe picks either) */
  glRasterPos2f(0.0f, 0.0f);
  glCopyPixels(10, conf->height - h + 10, 20, 15, GL_COLOR);
  glPixelZoom(1.0f, 1.0f);
}

static void scene_list_draws(void) { /* a list drawing two quads, one hidden by the other */
  glColor3f(0.9f, 0.2f, 0.4f);
  quad(-0.5f, -0.5f, 0.9f, 0.9f, 0.5f);
}

/* Runs `draw` in panel `i` between glBeginQuery and glEndQuery, and records its result. */
static void measure(int i, const char* what, void (*draw)(void)) {
  panel(i);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  draw();
  glEndQuery(GL_SAMPLES_PASSED);
  record_result(what);
}

static void scenes(void) {
  glGenQueries(1, &query);
  measure(0, "filled primitives", scene_quads);
  panel(1); /* the wall first, outside the query; then the sphere behind it */
  scene_hidden_sphere();
  lit(1);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  glTranslatef(0.0f, 0.0f, -0.5f);
  conf_sphere(0.6f, 20, 12);
  glEndQuery(GL_SAMPLES_PASSED);
  lit(0);
  record_result("sphere behind a wall");
  panel(2);
  scene_half_hidden();
  lit(1);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  conf_sphere(0.8f, 24, 16);
  glEndQuery(GL_SAMPLES_PASSED);
  lit(0);
  record_result("sphere half behind a wall");
  measure(3, "points and lines", scene_points_lines);
  measure(4, "polygon modes", scene_polygon_modes);
  measure(5, "stipple and scissor", scene_stipple_scissor);
  measure(6, "alpha test", scene_alpha_test);
  measure(7, "stencil test", scene_stencil);
  measure(8, "masks off", scene_masks_off);
  measure(9, "vertex arrays", scene_arrays);
  panel(10); /* a quad first, so that the second bitmap is hidden */
  glColor3f(0.2f, 0.2f, 0.8f);
  quad(-1.0f, -1.0f, 1.0f, 0.0f, 0.0f);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  scene_bitmap();
  glEndQuery(GL_SAMPLES_PASSED);
  record_result("bitmaps");
  measure(11, "draw pixels", scene_draw_pixels);
  measure(12, "copy pixels", scene_copy_pixels);

  /* Lists: a query compiled into one, around the list's draws. */
  panel(13);
  GLuint list = glGenLists(2);
  glNewList(list, GL_COMPILE);
  scene_list_draws();
  glEndList();
  glNewList(list + 1, GL_COMPILE);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  glCallList(list);
  glColor3f(0.3f, 0.9f, 0.4f);
  quad(-0.9f, -0.9f, 0.2f, 0.2f, 0.2f); /* partly behind the first */
  glEndQuery(GL_SAMPLES_PASSED);
  glEndList();
  record_error("compiling a query into a list");
  GLint current = -1;
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &current);
  record("GL_CURRENT_QUERY after compiling", (double)current);
  glCallList(list + 1);
  record_result("query in a list");
  glDeleteLists(list, 2);

  /* One query, then another on the same name: the result starts again; draws between the
   * two are not counted; a query around no draw counts 0. */
  panel(14);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  quad(-0.9f, -0.9f, 0.0f, 0.0f, 0.0f);
  glEndQuery(GL_SAMPLES_PASSED);
  record_result("first of two");
  quad(0.0f, 0.0f, 0.9f, 0.9f, 0.0f);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  quad(-0.5f, -0.5f, 0.5f, 0.5f, 0.5f);
  quad(-0.5f, -0.5f, 0.5f, 0.5f, 0.4f); /* behind the one just drawn */
  glEndQuery(GL_SAMPLES_PASSED);
  record_result("second of two");
  glBeginQuery(GL_SAMPLES_PASSED, query);
  glEndQuery(GL_SAMPLES_PASSED);
  record_result("no draws");
  glDeleteQueries(1, &query);
}

static void object_values(void) {
  GLint v = -1;
  glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, &v);
  record("GL_QUERY_COUNTER_BITS", (double)v);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
  record("GL_CURRENT_QUERY none", (double)v);
  GLuint names[3] = {0, 0, 0};
  glGenQueries(3, names);
  record("gen name 0", (double)names[0]);
  record("gen name 1", (double)names[1]);
  record("gen name 2", (double)names[2]);
  record("glIsQuery generated", (double)glIsQuery(names[0]));
  record("glIsQuery 0", (double)glIsQuery(0));
  GLuint u = 77;
  glGetQueryObjectuiv(names[0], GL_QUERY_RESULT, &u);
  record_error("result of a query never begun");
  record("left alone", (double)u);
  glBeginQuery(GL_SAMPLES_PASSED, names[1]);
  record_error("begin");
  record("glIsQuery active", (double)glIsQuery(names[1]));
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
  record("GL_CURRENT_QUERY active", (double)v);
  glBeginQuery(GL_SAMPLES_PASSED, names[2]);
  record_error("begin while active");
  glBeginQuery(GL_SAMPLES_PASSED, names[1]);
  record_error("begin the active one again");
  glGetQueryObjectuiv(names[1], GL_QUERY_RESULT, &u);
  record_error("result of the active query");
  glGetQueryObjectuiv(names[1], GL_QUERY_RESULT_AVAILABLE, &u);
  record_error("availability of the active query");
  glBegin(GL_TRIANGLES);
  glEndQuery(GL_SAMPLES_PASSED);
  glEnd();
  record_error("glEndQuery in glBegin");
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
  record("still active", (double)v);
  glEndQuery(0x1234);
  record_error("end of an unknown target");
  glEndQuery(GL_SAMPLES_PASSED);
  record_error("end");
  glEndQuery(GL_SAMPLES_PASSED);
  record_error("end with none active");
  glGetQueryObjectuiv(names[1], 0x1234, &u);
  record_error("unknown pname");
  glGetQueryObjectiv(names[1], GL_CURRENT_QUERY, &v);
  record_error("GL_CURRENT_QUERY of an object");
  glGetQueryObjectuiv(0, GL_QUERY_RESULT, &u);
  record_error("result of 0");
  glGetQueryObjectuiv(9999, GL_QUERY_RESULT, &u);
  record_error("result of an unknown name");
  glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_RESULT, &v);
  record_error("glGetQueryiv(GL_QUERY_RESULT)");
  glGetQueryiv(0x1234, GL_CURRENT_QUERY, &v);
  record_error("glGetQueryiv of an unknown target");
  glBeginQuery(0x1234, names[2]);
  record_error("begin of an unknown target");
  glBeginQuery(GL_SAMPLES_PASSED, 0);
  record_error("begin 0");
  glGenQueries(-1, names);
  record_error("glGenQueries(-1)");
  glDeleteQueries(-1, names);
  record_error("glDeleteQueries(-1)");

  /* A name never generated is begun (GL 1.5); new names come after it. */
  glBeginQuery(GL_SAMPLES_PASSED, 100);
  record_error("begin a name never generated");
  glEndQuery(GL_SAMPLES_PASSED);
  record("glIsQuery 100", (double)glIsQuery(100));
  GLuint next = 0;
  glGenQueries(1, &next);
  record("name after 100", (double)next);

  /* Deleting the active query ends it. */
  glBeginQuery(GL_SAMPLES_PASSED, names[2]);
  glDeleteQueries(1, &names[2]);
  record_error("delete the active query");
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
  record("GL_CURRENT_QUERY after deleting it", (double)v);
  record("glIsQuery deleted", (double)glIsQuery(names[2]));
  glEndQuery(GL_SAMPLES_PASSED);
  record_error("end after deleting it");
  const GLuint unknown[3] = {0, 5000, names[0]};
  glDeleteQueries(3, unknown);
  record_error("delete 0 and unknown names");
  record("glIsQuery names[1]", (double)glIsQuery(names[1]));
  glDeleteQueries(1, &names[1]);
  glDeleteQueries(1, &next);
  glDeleteQueries(1, (const GLuint[]){100});
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 400, 400)) return 1;
  conf = &c;
  glClearColor(0.05f, 0.05f, 0.08f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  scenes();
  object_values();
  glDisable(GL_DEPTH_TEST);
  conf_panel(&c, 3, 3, COLS, ROWS);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kCols, kRows, 0, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  for (int i = 0; i < n_values && i < kCells; ++i) {
    unsigned v = values[i] * 2654435761u, h = (v ^ (v >> 9) ^ (v >> 18) ^ (v >> 27)) & 511u;
    glColor3ub((GLubyte)(20 + 33 * (h & 7)), (GLubyte)(20 + 33 * ((h >> 3) & 7)), (GLubyte)(20 + 33 * (h >> 6)));
    float x = (float)(i % kCols), y = (float)(i / kCols);
    glRectf(x + 0.1f, y + 0.1f, x + 0.9f, y + 0.9f);
  }
  return conf_finish(&c);
}
