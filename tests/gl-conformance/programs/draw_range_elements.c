/* GL 1.2's glDrawRangeElements and GL 1.4's glMultiDrawArrays / glMultiDrawElements: a lit
 * sphere drawn by range with 16-bit indices, ranges wider than the indices, ribbons of triangle strips in one glMultiDrawArrays, fans and line
 * strips in one glMultiDrawElements (8- and 32-bit indices), every command compiled into a
 * display list (the arrays changed before the list runs) and in GL_COMPILE_AND_EXECUTE; then
 * the glGetError code of each wrong call (and of the right ones), compared with Mesa's. */
#define GL_GLEXT_PROTOTYPES
#include <math.h>
#include <string.h>

#include "conf.h"

enum { kSlices = 20, kStacks = 10, kGrid = (kSlices + 1) * (kStacks + 1) };
static GLfloat sphere_pos[kGrid][3];
static GLushort sphere_idx[kSlices * kStacks * 6];
static GLfloat ribbon_pos[4][16][2];
static GLubyte ribbon_col[4][16][4];
static GLfloat fan_pos[3][10][2];
static GLfloat fan_col[3][10][3];

static void build(void) {
  int m = 0;
  for (int j = 0; j <= kStacks; ++j)
    for (int i = 0; i <= kSlices; ++i) {
      double t = 2.0 * CONF_PI * i / kSlices, p = CONF_PI * j / kStacks;
      GLfloat* v = sphere_pos[j * (kSlices + 1) + i];
      v[0] = (GLfloat)(sin(p) * sin(t)), v[1] = (GLfloat)cos(p), v[2] = (GLfloat)(sin(p) * cos(t));
    }
  const int di[6] = {0, 0, 1, 0, 1, 1}, dj[6] = {0, 1, 1, 0, 1, 0};
  for (int j = 0; j < kStacks; ++j)
    for (int i = 0; i < kSlices; ++i)
      for (int k = 0; k < 6; ++k) sphere_idx[m++] = (GLushort)((j + dj[k]) * (kSlices + 1) + i + di[k]);
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 16; ++k) {
      ribbon_pos[r][k][0] = -1.0f + 2.0f * (k / 2) / 7.0f;
      ribbon_pos[r][k][1] = -0.9f + 0.5f * r + 0.3f * (k % 2) + 0.1f * (float)sin(k * 0.7);
      ribbon_col[r][k][0] = (GLubyte)(60 * r + 20), ribbon_col[r][k][1] = (GLubyte)(15 * k);
      ribbon_col[r][k][2] = (GLubyte)(255 - 15 * k), ribbon_col[r][k][3] = 255;
    }
  for (int f = 0; f < 3; ++f) {
    const float cx = -0.6f + 0.6f * f, cy = 0.1f * f - 0.1f;
    fan_pos[f][0][0] = cx, fan_pos[f][0][1] = cy;
    fan_col[f][0][0] = 1.0f, fan_col[f][0][1] = 1.0f, fan_col[f][0][2] = 1.0f;
    for (int k = 1; k < 10; ++k) {
      const double a = 2.0 * CONF_PI * (k - 1) / 8.0;
      fan_pos[f][k][0] = cx + (0.25f + 0.03f * f) * (float)cos(a);
      fan_pos[f][k][1] = cy + (0.25f + 0.03f * f) * (float)sin(a);
      fan_col[f][k][0] = 0.3f * f, fan_col[f][k][1] = (float)k / 9.0f, fan_col[f][k][2] = 1.0f - 0.3f * f;
    }
  }
}

static void panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 3, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.2, 1.2, -1.2, 1.2, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* The lit sphere: glDrawRangeElements over the whole sphere, in three ranges. */
static void sphere(void) {
  const GLfloat diffuse[4] = {0.9f, 0.5f, 0.2f, 1.0f};
  const GLfloat light[4] = {0.4f, 0.6f, 1.0f, 0.0f};
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, diffuse);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, sphere_pos);
  glNormalPointer(GL_FLOAT, 0, sphere_pos);
  const int third = kSlices * kStacks * 2 / 3 * 3, total = kSlices * kStacks * 6;
  for (int part = 0; part < 3; ++part) {
    const GLushort* idx = sphere_idx + part * third;
    const int n = part < 2 ? third : total - 2 * third;
    GLuint lo = 0xffff, hi = 0;
    for (int k = 0; k < n; ++k) lo = idx[k] < lo ? idx[k] : lo, hi = idx[k] > hi ? idx[k] : hi;
    glDrawRangeElements(GL_TRIANGLES, lo, hi, n, GL_UNSIGNED_SHORT, idx);
  }
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
}

/* Ranges wider than the indices need (indices outside the range are undefined: llvmpipe then
 * fetches only the vertices of the range, shadelab draws them as glDrawElements does). */
static void loose_range(void) {
  glColor3f(0.2f, 0.8f, 0.4f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, sphere_pos);
  glDrawRangeElements(GL_TRIANGLES, 0, kGrid + 50, kSlices * kStacks * 3, GL_UNSIGNED_SHORT, sphere_idx);
  glColor3f(0.9f, 0.9f, 0.2f);
  glDrawRangeElements(GL_LINES, 0, kGrid - 1, 60, GL_UNSIGNED_SHORT, sphere_idx + kSlices * kStacks * 3);
  glDisableClientState(GL_VERTEX_ARRAY);
}

static void ribbons(void) {
  const GLint first[4] = {0, 16, 32, 48};
  const GLsizei count[4] = {16, 12, 0, 16};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, ribbon_pos);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, ribbon_col);
  glMultiDrawArrays(GL_TRIANGLE_STRIP, first, count, 4);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

/* A null pointer among glMultiDrawElements' draws nothing of the call; Mesa 22.3 crashes on
 * one compiled into a display list, so lists get none. */
static void fans(int with_null) {
  static const GLubyte fan8[10] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  static const GLuint fan32[2][10] = {{10, 11, 12, 13, 14, 15, 16, 17, 18, 19}, {20, 21, 22, 23, 24, 25, 26, 27, 28, 29}};
  static const GLuint strip32[3][5] = {{1, 3, 5, 7, 9}, {11, 13, 15, 17, 19}, {21, 23, 25, 27, 29}};
  const GLsizei count[3] = {10, 7, 10};
  const GLvoid* idx8[1] = {fan8};
  const GLvoid* idx32[3] = {fan32[0], with_null ? NULL : fan32[1], fan32[1]};
  const GLsizei count_strip[3] = {5, 5, 3};
  const GLvoid* strips[3] = {strip32[0], strip32[1], strip32[2]};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, fan_pos);
  glColorPointer(3, GL_FLOAT, 0, fan_col);
  glMultiDrawElements(GL_TRIANGLE_FAN, count, GL_UNSIGNED_BYTE, idx8, 1);
  glMultiDrawElements(GL_TRIANGLE_FAN, count, GL_UNSIGNED_INT, idx32, 3);
  if (with_null) glMultiDrawElements(GL_TRIANGLE_FAN, count, GL_UNSIGNED_INT, idx32, 1);
  glDisableClientState(GL_COLOR_ARRAY);
  glColor3f(1.0f, 0.2f, 0.2f);
  glLineWidth(2.0f);
  glMultiDrawElements(GL_LINE_STRIP, count_strip, GL_UNSIGNED_INT, strips, 3);
  glLineWidth(1.0f);
  glDisableClientState(GL_VERTEX_ARRAY);
}

/* The three commands compiled into a list: the arrays' contents of compile time are drawn. */
static GLuint compiled(GLenum mode) {
  GLuint list = glGenLists(1);
  glNewList(list, mode);
  glPushMatrix();
  glScalef(0.5f, 0.5f, 0.5f);
  glTranslatef(-1.0f, 1.0f, 0.0f);
  sphere();
  glTranslatef(2.0f, 0.0f, 0.0f);
  ribbons();
  glTranslatef(-1.0f, -2.0f, 0.0f);
  fans(0);
  glPopMatrix();
  glEndList();
  return list;
}

static void errors(ConfContext* c) {
  static const GLubyte idx[6] = {0, 1, 2, 2, 1, 3};
  const GLint first[2] = {0, 4};
  const GLsizei count[2] = {3, 3}, bad_count[2] = {3, -1};
  const GLvoid* indices[2] = {idx, idx + 3};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, ribbon_pos);
  glDrawRangeElements(GL_TRIANGLES, 0, 3, 6, GL_UNSIGNED_BYTE, idx);
  conf_error(c, "DrawRangeElements right");
  glDrawRangeElements(GL_TRIANGLES, 3, 0, 6, GL_UNSIGNED_BYTE, idx);
  conf_error(c, "DrawRangeElements end < start");
  glDrawRangeElements(GL_TRIANGLES, 0, 3, -1, GL_UNSIGNED_BYTE, idx);
  conf_error(c, "DrawRangeElements count -1");
  glDrawRangeElements(0x1234, 0, 3, 6, GL_UNSIGNED_BYTE, idx);
  conf_error(c, "DrawRangeElements mode");
  glDrawRangeElements(GL_TRIANGLES, 0, 3, 6, GL_FLOAT, idx);
  conf_error(c, "DrawRangeElements type float");
  glDrawRangeElements(GL_TRIANGLES, 0, 3, 6, GL_BYTE, idx);
  conf_error(c, "DrawRangeElements type byte");
  glDrawRangeElements(0x1234, 3, 0, -1, GL_FLOAT, idx);
  conf_error(c, "DrawRangeElements all wrong");
  glDrawRangeElements(0x1234, 0, 3, -1, GL_FLOAT, idx);
  conf_error(c, "DrawRangeElements mode count type");
  glDrawRangeElements(GL_TRIANGLES, 0, 3, 6, GL_UNSIGNED_BYTE, idx);
  glDrawRangeElements(GL_TRIANGLES, 5, 5, 0, GL_UNSIGNED_BYTE, idx);
  conf_error(c, "DrawRangeElements count 0");
  glBegin(GL_TRIANGLES);
  glDrawRangeElements(GL_TRIANGLES, 0, 3, 6, GL_UNSIGNED_BYTE, idx);
  glEnd();
  conf_error(c, "DrawRangeElements in glBegin");

  glMultiDrawArrays(GL_TRIANGLES, first, count, 2);
  conf_error(c, "MultiDrawArrays right");
  glMultiDrawArrays(GL_TRIANGLES, first, count, 0);
  conf_error(c, "MultiDrawArrays drawcount 0");
  glMultiDrawArrays(GL_TRIANGLES, first, count, -1);
  conf_error(c, "MultiDrawArrays drawcount -1");
  glMultiDrawArrays(0x1234, first, count, 2);
  conf_error(c, "MultiDrawArrays mode");
  glMultiDrawArrays(GL_TRIANGLES, first, bad_count, 2);
  conf_error(c, "MultiDrawArrays count -1");
  glMultiDrawArrays(0x1234, first, count, -1);
  conf_error(c, "MultiDrawArrays mode drawcount");
  glMultiDrawArrays(0x1234, first, bad_count, 2);
  conf_error(c, "MultiDrawArrays mode count");
  glBegin(GL_TRIANGLES);
  glMultiDrawArrays(GL_TRIANGLES, first, count, 2);
  glEnd();
  conf_error(c, "MultiDrawArrays in glBegin");

  glMultiDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_BYTE, indices, 2);
  conf_error(c, "MultiDrawElements right");
  glMultiDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_BYTE, indices, -1);
  conf_error(c, "MultiDrawElements drawcount -1");
  glMultiDrawElements(0x1234, count, GL_UNSIGNED_BYTE, indices, 2);
  conf_error(c, "MultiDrawElements mode");
  glMultiDrawElements(GL_TRIANGLES, count, GL_SHORT, indices, 2);
  conf_error(c, "MultiDrawElements type");
  glMultiDrawElements(GL_TRIANGLES, bad_count, GL_UNSIGNED_BYTE, indices, 2);
  conf_error(c, "MultiDrawElements count -1");
  glMultiDrawElements(GL_TRIANGLES, bad_count, GL_SHORT, indices, 2);
  conf_error(c, "MultiDrawElements type count");
  glMultiDrawElements(0x1234, count, GL_SHORT, indices, -1);
  conf_error(c, "MultiDrawElements all wrong");
  glBegin(GL_TRIANGLES);
  glMultiDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_BYTE, indices, 2);
  glEnd();
  conf_error(c, "MultiDrawElements in glBegin");

  /* Compile errors: raised when the list runs. */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glDrawRangeElements(GL_TRIANGLES, 3, 0, 6, GL_UNSIGNED_BYTE, idx);
  glEndList();
  conf_error(c, "list DrawRangeElements compile");
  glCallList(list);
  conf_error(c, "list DrawRangeElements end < start");
  glNewList(list, GL_COMPILE);
  glMultiDrawArrays(GL_TRIANGLES, first, bad_count, 2);
  glEndList();
  glCallList(list);
  conf_error(c, "list MultiDrawArrays count -1");
  glNewList(list, GL_COMPILE);
  glMultiDrawElements(GL_TRIANGLES, count, GL_FLOAT, indices, 2);
  glEndList();
  glCallList(list);
  conf_error(c, "list MultiDrawElements type");
  glNewList(list, GL_COMPILE);
  glMultiDrawElements(0x1234, count, GL_UNSIGNED_BYTE, indices, 2);
  glEndList();
  glCallList(list);
  conf_error(c, "list MultiDrawElements mode");
  glDeleteLists(list, 1);
  glDisableClientState(GL_VERTEX_ARRAY);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 384, 384)) return 1;
  build();
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  panel(&c, 0, 0), sphere();
  panel(&c, 1, 0), loose_range();
  panel(&c, 2, 0), ribbons();
  panel(&c, 0, 1), fans(1);

  panel(&c, 1, 1);
  GLuint list = compiled(GL_COMPILE);
  /* The client data changes after compiling: the list keeps what it read. */
  for (int k = 0; k < kGrid; ++k) sphere_pos[k][0] *= 0.3f;
  memset(ribbon_col, 255, sizeof ribbon_col);
  fan_pos[1][0][0] += 0.5f;
  glCallList(list);
  panel(&c, 2, 1);
  glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
  glCallList(list);

  build();
  panel(&c, 0, 2);
  glRotatef(-20.0f, 0.0f, 0.0f, 1.0f);
  GLuint list2 = compiled(GL_COMPILE_AND_EXECUTE);
  panel(&c, 1, 2);
  glTranslatef(0.0f, 0.3f, 0.0f);
  glCallList(list2);
  panel(&c, 2, 2);
  glCallList(list);
  glCallList(list2);
  conf_check_error("draws");

  errors(&c);
  return conf_finish(&c);
}
