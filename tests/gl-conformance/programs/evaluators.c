/* Evaluators (GL 1.1 section 5.1) compared with Mesa, in a 4 x 3 grid: a bicubic patch through
 * glEvalMesh2(GL_FILL) lit with GL_AUTO_NORMAL; a rational patch (GL_MAP2_VERTEX_4) with
 * auto normals; an unlit patch coloured by GL_MAP2_COLOR_4; a patch textured through
 * GL_MAP2_TEXTURE_COORD_2; glEvalCoord2 and glEvalPoint2 inside the program's own glBegin;
 * curves (glMap1) closing triangle fans, coloured by GL_MAP1_COLOR_4, and glEvalPoint1;
 * patches of unequal orders (2 x 5, 6 x 3, 4 x 1) with auto normals; partial meshes over a
 * reversed grid (glMapGrid2d); maps and meshes in display lists, a map redefined after the
 * list was compiled; GL_MAP2_NORMAL and colour material under lighting; glPushAttrib(GL_EVAL_BIT).
 * glBegin/glEvalCoord2/glEnd compiled in a list (replayed command by command, not compiled as
 * geometry). Printed to NAME.txt and compared exactly: glGetMap{f,d,i}v of every target
 * (initial and defined maps), the grid and enable state, and the glGetError sequence of wrong
 * calls.
 *
 * Not compared: the current colour, normal and texture coordinates after evaluation. Section
 * 5.1 leaves them unchanged (shadelab does, tests/gl/eval_test.cpp); Mesa 22.3 leaves whatever
 * its vertex template held in the slot an evaluated attribute was given (see
 * docs/gl-conformance.md, "Evaluators"). So after each evaluation the program specifies the
 * current values again before anything uses them, and never prints them. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "conf.h"

enum { kCols = 4, kRows = 3 };
static FILE* out;

static void panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, kCols, kRows);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-4.5, 4.5, -4.5, 4.5, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* The Red Book's bezsurf control points: 4 x 4 x 3. */
static const GLfloat kPatch[4][4][3] = {
    {{-1.5f, -1.5f, 4.0f}, {-0.5f, -1.5f, 2.0f}, {0.5f, -1.5f, -1.0f}, {1.5f, -1.5f, 2.0f}},
    {{-1.5f, -0.5f, 1.0f}, {-0.5f, -0.5f, 3.0f}, {0.5f, -0.5f, 0.0f}, {1.5f, -0.5f, -1.0f}},
    {{-1.5f, 0.5f, 4.0f}, {-0.5f, 0.5f, 0.0f}, {0.5f, 0.5f, 3.0f}, {1.5f, 0.5f, 4.0f}},
    {{-1.5f, 1.5f, -2.0f}, {-0.5f, 1.5f, -2.0f}, {0.5f, 1.5f, 0.0f}, {1.5f, 1.5f, -1.0f}}};

static void lights(int on) {
  const GLfloat pos[] = {0.3f, 0.6f, 1.0f, 0.0f}, amb[] = {0.2f, 0.2f, 0.2f, 1.0f};
  const GLfloat diff[] = {0.7f, 0.6f, 0.3f, 1.0f}, spec[] = {1.0f, 1.0f, 1.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diff);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  if (on) glEnable(GL_LIGHTING), glEnable(GL_LIGHT0);
  else glDisable(GL_LIGHTING);
}

static void view(float angle) {
  glRotatef(angle, 1.0f, 0.3f, 0.0f);
  glRotatef(25.0f, 0.0f, 0.0f, 1.0f);
}

static void patch_fill(int n) {
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &kPatch[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glMapGrid2f(n, 0.0f, 1.0f, n, 0.0f, 1.0f);
  glEvalMesh2(GL_FILL, 0, n, 0, n);
}

static void rational_patch(void) {
  GLfloat p[3][3][4];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      float w = (i == 1 || j == 1) ? 0.7071f : 1.0f;
      if (i == 1 && j == 1) w = 0.5f;
      p[i][j][0] = (float)(i - 1) * 2.0f * w, p[i][j][1] = (float)(j - 1) * 2.0f * w;
      p[i][j][2] = ((i == 1) + (j == 1)) * 1.5f * w, p[i][j][3] = w;
    }
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 12, 3, 0, 1, 4, 3, &p[0][0][0]);
  glEnable(GL_MAP2_VERTEX_4);
  glMapGrid2f(12, 0.0f, 1.0f, 12, 0.0f, 1.0f);
  glEvalMesh2(GL_FILL, 0, 12, 0, 12);
  glDisable(GL_MAP2_VERTEX_4);
}

static void colour_patch(void) {
  const GLfloat colours[2][2][4] = {{{1, 0, 0, 1}, {0, 1, 0, 1}}, {{0, 0, 1, 1}, {1, 1, 0, 1}}};
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, &colours[0][0][0]);
  glEnable(GL_MAP2_COLOR_4);
  patch_fill(10);
  glDisable(GL_MAP2_COLOR_4);
}

static GLuint checker(void) {
  static GLubyte img[16][16][3];
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      int on = ((x / 2) + (y / 2)) % 2;
      img[y][x][0] = (GLubyte)(on ? 230 : 20), img[y][x][1] = (GLubyte)(x * 15), img[y][x][2] = (GLubyte)(y * 15);
    }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, img);
  return tex;
}

static void textured_patch(void) {
  const GLfloat tex[2][2][2] = {{{0, 0}, {0, 1}}, {{1, 0}, {1, 1}}};
  GLuint t = checker();
  glEnable(GL_TEXTURE_2D);
  glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 2, 2, 0, 1, 4, 2, &tex[0][0][0]);
  glEnable(GL_MAP2_TEXTURE_COORD_2);
  patch_fill(8);
  glDisable(GL_MAP2_TEXTURE_COORD_2);
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &t);
}

/* glEvalCoord2 in the program's own quads, and glEvalPoint2 in a strip, with colour. */
static void own_primitives(void) {
  const GLfloat colours[2][2][4] = {{{1, 1, 1, 1}, {0, 0.5f, 1, 1}}, {{1, 0.3f, 0, 1}, {0.2f, 1, 0.2f, 1}}};
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &kPatch[0][0][0]);
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, &colours[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3), glEnable(GL_MAP2_COLOR_4);
  glPushMatrix();
  glTranslatef(-2.0f, 0.0f, 0.0f);
  glBegin(GL_QUADS);
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      float u = (float)i / 6.0f, v = (float)j / 6.0f, d = 1.0f / 6.0f;
      glEvalCoord2f(u, v), glEvalCoord2d(u + d, v);
      GLfloat uv[2] = {u + d, v + d};
      GLdouble uvd[2] = {u, v + d};
      glEvalCoord2fv(uv), glEvalCoord2dv(uvd);
    }
  glEnd();
  glTranslatef(4.0f, 0.0f, 0.0f);
  glMapGrid2d(5, 0.0, 1.0, 5, 0.0, 1.0);
  for (int j = 0; j < 5; ++j) {
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i <= 5; ++i) glEvalPoint2(i, j), glEvalPoint2(i, j + 1);
    glEnd();
  }
  glPopMatrix();
  glDisable(GL_MAP2_VERTEX_3), glDisable(GL_MAP2_COLOR_4);
}

/* Curves: a cubic and a quintic closing fans around a centre, coloured along the curve. */
static void curves(void) {
  const GLfloat ctrl[4][3] = {{-3.5f, -3.0f, 0}, {-2.0f, 3.5f, 0}, {2.0f, -3.5f, 0}, {3.5f, 3.0f, 0}};
  const GLdouble quintic[6][4] = {{-3, 0, 0, 1}, {-3, 4, 0, 1}, {0, 6, 0, 2}, {3, 4, 0, 1}, {4, 0, 0, 1}, {3, -2, 0, 0.5}};
  const GLfloat colours[3][4] = {{1, 0, 0, 1}, {0, 1, 0, 0.5f}, {0, 0.3f, 1, 1}};
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &ctrl[0][0]);
  glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 3, &colours[0][0]);
  glEnable(GL_MAP1_VERTEX_3), glEnable(GL_MAP1_COLOR_4);
  glColor3f(1, 1, 1);
  glBegin(GL_TRIANGLE_FAN);
  glVertex2f(0.0f, -4.0f);
  for (int i = 0; i <= 30; ++i) glEvalCoord1f((float)i / 30.0f);
  glEnd();
  glDisable(GL_MAP1_VERTEX_3);
  glMap1d(GL_MAP1_VERTEX_4, 2.0, 4.0, 4, 6, &quintic[0][0]);
  glEnable(GL_MAP1_VERTEX_4);
  glMapGrid1d(24, 2.0, 4.0);
  glTranslatef(0.0f, -1.0f, 0.5f);
  glScalef(0.6f, 0.6f, 1.0f);
  glBegin(GL_TRIANGLE_FAN);
  glVertex2f(0.0f, 1.0f);
  for (int i = 0; i <= 24; ++i) glEvalPoint1(i);
  glEnd();
  glBegin(GL_POLYGON);  /* double and vector forms */
  for (int i = 0; i <= 12; ++i) {
    GLdouble u = 2.0 + i / 6.0;
    GLfloat uf = (GLfloat)u;
    if (i % 3 == 0) glEvalCoord1d(u);
    else if (i % 3 == 1) glEvalCoord1fv(&uf);
    else glEvalCoord1dv(&u);
  }
  glEnd();
  glDisable(GL_MAP1_VERTEX_4), glDisable(GL_MAP1_COLOR_4);
}

/* Unequal orders with auto normals: 2 x 5, 6 x 3, 4 x 1 (the last a curve: no normal). */
static void unequal_orders(void) {
  GLfloat p[6][5][3];
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j) {
      p[i][j][0] = (float)i - 2.5f, p[i][j][1] = (float)j - 2.0f;
      p[i][j][2] = (float)(((i * 7 + j * 3) % 5) - 2) * 0.8f;
    }
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_MAP2_VERTEX_3);
  glPushMatrix();
  glTranslatef(-2.2f, 2.0f, 0.0f), glScalef(0.45f, 0.45f, 0.45f);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 15, 2, 0, 1, 3, 5, &p[0][0][0]);
  glMapGrid2f(8, 0.0f, 1.0f, 8, 0.0f, 1.0f);
  glEvalMesh2(GL_FILL, 0, 8, 0, 8);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(2.2f, 2.0f, 0.0f), glScalef(0.45f, 0.45f, 0.45f);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 15, 6, 0, 1, 3, 3, &p[0][0][0]);
  glEvalMesh2(GL_FILL, 0, 8, 0, 8);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0.0f, -2.0f, 0.0f), glScalef(0.6f, 0.6f, 0.6f);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 15, 6, 0, 1, 3, 4, &p[0][0][0]);
  glEvalMesh2(GL_FILL, 0, 8, 0, 8);
  glPopMatrix();
  glDisable(GL_MAP2_VERTEX_3);
  glDisable(GL_AUTO_NORMAL);
}

/* Partial meshes over a reversed grid, a domain that is not [0, 1]. */
static void partial_meshes(void) {
  GLdouble d[4][4][3];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 3; ++k) d[i][j][k] = kPatch[i][j][k];
  glMap2d(GL_MAP2_VERTEX_3, 2.0, 4.0, 12, 4, -1.0, 1.0, 3, 4, &d[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  glMapGrid2d(10, 4.0, 2.0, 10, 1.0, -1.0);
  glEvalMesh2(GL_FILL, 2, 8, 0, 10);
  glTranslatef(0.0f, 0.0f, 1.0f);
  glEvalMesh2(GL_FILL, 0, 10, 7, 10);
  glDisable(GL_AUTO_NORMAL);
  glDisable(GL_MAP2_VERTEX_3);
}

/* Maps and meshes compiled into lists; the map is redefined after compiling. */
static void in_lists(void) {
  const GLfloat colours[2][2][4] = {{{1, 0.8f, 0, 1}, {0.2f, 0.2f, 1, 1}}, {{0.9f, 0.1f, 0.5f, 1}, {0, 1, 0.6f, 1}}};
  GLfloat flat[4][4][3];
  memcpy(flat, kPatch, sizeof flat);
  GLuint l = glGenLists(2);
  glNewList(l, GL_COMPILE);
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, &colours[0][0][0]);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &flat[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3), glEnable(GL_MAP2_COLOR_4);
  glMapGrid2f(9, 0.0f, 1.0f, 9, 0.0f, 1.0f);
  glEndList();
  glNewList(l + 1, GL_COMPILE);
  glEvalMesh2(GL_FILL, 0, 9, 0, 9);
  glEndList();
  for (int i = 0; i < 4; ++i) flat[i][i][2] = 6.0f; /* changed after compiling: not seen */
  glPushMatrix();
  glTranslatef(-1.8f, 0.0f, 0.0f), glScalef(0.9f, 0.9f, 0.9f);
  glCallList(l), glCallList(l + 1);
  glTranslatef(4.0f, 0.0f, 0.0f);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &flat[0][0][0]);
  glCallList(l + 1);
  glPopMatrix();
  glDisable(GL_MAP2_VERTEX_3), glDisable(GL_MAP2_COLOR_4);
  glDeleteLists(l, 2);
}

/* GL_MAP2_NORMAL's normals under lighting, and colour material following GL_MAP2_COLOR_4. */
static void normals_and_material(void) {
  const GLfloat normals[2][2][3] = {{{-0.6f, -0.6f, 0.5f}, {-0.6f, 0.6f, 0.5f}}, {{0.6f, -0.6f, 0.5f}, {0.6f, 0.6f, 0.5f}}};
  const GLfloat colours[2][2][4] = {{{1, 0, 0, 1}, {0, 1, 0, 1}}, {{0, 0, 1, 1}, {1, 1, 1, 1}}};
  glMap2f(GL_MAP2_NORMAL, 0, 1, 3, 2, 0, 1, 6, 2, &normals[0][0][0]);
  glEnable(GL_MAP2_NORMAL);
  glPushMatrix();
  glTranslatef(-2.0f, 0.0f, 0.0f), glScalef(0.8f, 0.8f, 0.8f);
  patch_fill(10);
  glPopMatrix();
  glDisable(GL_MAP2_NORMAL);
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, &colours[0][0][0]);
  glEnable(GL_MAP2_COLOR_4), glEnable(GL_AUTO_NORMAL), glEnable(GL_COLOR_MATERIAL);
  glColor3f(0.5f, 0.5f, 0.5f);
  glPushMatrix();
  glTranslatef(2.0f, 0.0f, 0.0f), glScalef(0.8f, 0.8f, 0.8f);
  patch_fill(10);
  glPopMatrix();
  glDisable(GL_COLOR_MATERIAL), glDisable(GL_AUTO_NORMAL), glDisable(GL_MAP2_COLOR_4);
  glDisable(GL_MAP2_VERTEX_3);
}

/* glPushAttrib(GL_EVAL_BIT): enables and grids back after the pop, the maps not. */
static void attrib_eval(void) {
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &kPatch[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3), glEnable(GL_AUTO_NORMAL);
  glMapGrid2f(6, 0.0f, 1.0f, 6, 0.0f, 1.0f);
  glPushAttrib(GL_EVAL_BIT);
  glDisable(GL_MAP2_VERTEX_3), glDisable(GL_AUTO_NORMAL);
  glMapGrid2f(2, 0.0f, 0.5f, 2, 0.0f, 0.5f);
  glEvalMesh2(GL_FILL, 0, 2, 0, 2); /* no vertex map: nothing */
  glPopAttrib();
  glEvalMesh2(GL_FILL, 0, 6, 0, 6);
  glDisable(GL_MAP2_VERTEX_3), glDisable(GL_AUTO_NORMAL);
}

static void print_map(GLenum target) {
  GLfloat f[4 * 30 * 30];
  GLdouble d[4];
  GLint i[4], order[2] = {0, 0};
  glGetMapiv(target, GL_ORDER, order);
  int two = target >= GL_MAP2_COLOR_4;
  int n = order[0] * (two ? order[1] : 1);
  int comps = 0;
  switch ((target - (two ? GL_MAP2_COLOR_4 : GL_MAP1_COLOR_4))) {
    case 0: case 6: case 8: comps = 4; break;
    case 1: case 3: comps = 1; break;
    case 4: comps = 2; break;
    default: comps = 3;
  }
  glGetMapfv(target, GL_COEFF, f);
  fprintf(out, "map %#x order %d %d coeff", target, order[0], order[1]);
  for (int k = 0; k < n * comps && k < 64; ++k) fprintf(out, " %.9g", f[k]);
  fprintf(out, "\n");
  glGetMapdv(target, GL_DOMAIN, d);
  glGetMapiv(target, GL_DOMAIN, i);
  fprintf(out, "map %#x domain %.9g %.9g %.9g %.9g int %d %d %d %d\n", target, d[0], d[1], two ? d[2] : 0.0,
          two ? d[3] : 0.0, i[0], i[1], two ? i[2] : 0, two ? i[3] : 0);
  static GLint coeff[4 * 30 * 30]; /* every coefficient is written: as many as f holds */
  glGetMapiv(target, GL_COEFF, coeff);
  glGetMapdv(target, GL_ORDER, d);
  fprintf(out, "map %#x first coeff as int %d order as double %.9g err %x\n", target, coeff[0], d[0], glGetError());
}

static void print_state(const char* what) {
  GLfloat f[4];
  GLint i[4];
  fprintf(out, "%s: enabled", what);
  for (GLenum t = GL_MAP1_COLOR_4; t <= GL_MAP1_VERTEX_4; ++t) fprintf(out, " %d", glIsEnabled(t));
  for (GLenum t = GL_MAP2_COLOR_4; t <= GL_MAP2_VERTEX_4; ++t) fprintf(out, " %d", glIsEnabled(t));
  fprintf(out, " auto %d\n", glIsEnabled(GL_AUTO_NORMAL));
  glGetFloatv(GL_MAP1_GRID_DOMAIN, f);
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, i);
  fprintf(out, "%s: grid1 %.9g %.9g %d\n", what, f[0], f[1], i[0]);
  glGetFloatv(GL_MAP2_GRID_DOMAIN, f);
  glGetIntegerv(GL_MAP2_GRID_SEGMENTS, i);
  fprintf(out, "%s: grid2 %.9g %.9g %.9g %.9g %d %d\n", what, f[0], f[1], f[2], f[3], i[0], i[1]);
  glGetIntegerv(GL_MAX_EVAL_ORDER, i);
  GLboolean b;
  glGetBooleanv(GL_AUTO_NORMAL, &b);
  fprintf(out, "%s: max order %d auto normal %d err %x\n", what, i[0], b, glGetError());
}

/* The current values every panel starts from, specified again after each evaluation: Mesa
 * leaves stale values in the current attributes that an evaluation gave a vertex slot. */
static void set_current(void) {
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f), glNormal3f(0.0f, 0.6f, 0.8f), glTexCoord2f(0.125f, 0.375f);
}

/* glBegin/glEnd with glEvalCoord2 and glEvalPoint2 inside a list: such a primitive stays a
 * replay of its commands (gl/src/dlist_geometry.cpp). Two cases of Mesa 22.3 are left out
 * (docs/gl-conformance.md, "Evaluators"): GL_COMPILE_AND_EXECUTE (Mesa also compiles the
 * vertices its executed evaluation emits, so the list replays each evaluated vertex twice)
 * and glVertex before glEvalCoord in one compiled primitive (Mesa's replay draws none of it). */
static void eval_coords_in_lists(void) {
  const GLfloat colours[2][2][4] = {{{0.9f, 0.9f, 0.2f, 1}, {0.1f, 0.6f, 1, 1}}, {{1, 0.2f, 0.2f, 1}, {0.3f, 1, 0.3f, 1}}};
  GLuint l = glGenLists(1);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &kPatch[0][0][0]);
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, &colours[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3), glEnable(GL_MAP2_COLOR_4);
  glMapGrid2f(6, 0.0f, 1.0f, 6, 0.0f, 1.0f);
  glPushMatrix();
  glTranslatef(-2.0f, 1.5f, 0.0f), glScalef(0.8f, 0.8f, 0.8f);
  glNewList(l, GL_COMPILE);
  glBegin(GL_QUADS);
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      float u = (float)i / 6.0f, v = (float)j / 6.0f, d = 1.0f / 6.0f;
      glEvalCoord2f(u, v), glEvalCoord2f(u + d, v), glEvalCoord2f(u + d, v + d), glEvalCoord2f(u, v + d);
    }
  glEnd();
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i <= 6; ++i) glEvalPoint2(i, 0), glEvalPoint2(i, 1);
  glEnd();
  glEndList();
  glCallList(l);
  glTranslatef(5.0f, -3.0f, 0.0f);
  glCallList(l);
  glPopMatrix();
  glDisable(GL_MAP2_VERTEX_3), glDisable(GL_MAP2_COLOR_4);
  glDeleteLists(l, 1);
}

#define CHECK(call)                                            \
  do {                                                         \
    call;                                                      \
    fprintf(out, "error %s: %#x\n", #call, glGetError()); \
  } while (0)

static void errors(void) {
  const GLfloat p[64] = {0};
  const GLdouble pd[64] = {0};
  CHECK(glMap1f(GL_MAP1_VERTEX_3, 0, 0, 3, 2, p));
  CHECK(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 0, p));
  CHECK(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 31, p));
  CHECK(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, 0));
  CHECK(glMap1f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, p));
  CHECK(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 2, 2, p));
  CHECK(glMap1f(GL_TEXTURE_2D, 0, 1, 3, 2, p));
  CHECK(glMap1f(GL_TEXTURE_2D, 0, 1, 3, 0, p));
  CHECK(glMap1d(GL_MAP1_INDEX, 1, 1, 1, 2, pd));
  CHECK(glMap1d(GL_MAP1_COLOR_4, 0, 1, 3, 2, pd));
  CHECK(glMap2f(GL_MAP2_VERTEX_3, 0, 0, 3, 2, 0, 1, 6, 2, p));
  CHECK(glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 1, 1, 6, 2, p));
  CHECK(glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 31, 0, 1, 6, 2, p));
  CHECK(glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 0, p));
  CHECK(glMap2f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, p));
  CHECK(glMap2f(GL_MAP2_VERTEX_3, 0, 1, 2, 2, 0, 1, 6, 2, p));
  CHECK(glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 2, 2, p));
  CHECK(glMap2d(GL_LIGHTING, 0, 1, 3, 2, 0, 1, 6, 2, pd));
  CHECK(glMap2d(GL_MAP2_TEXTURE_COORD_4, 0, 1, 4, 2, 0, 1, 8, 2, pd));
  GLfloat f[8];
  CHECK(glGetMapfv(GL_TEXTURE_2D, GL_ORDER, f));
  CHECK(glGetMapfv(GL_MAP1_VERTEX_3, GL_TEXTURE_2D, f));
  GLint iv[8];
  CHECK(glGetMapiv(GL_MAP2_NORMAL, GL_COLOR, iv));
  CHECK(glMapGrid1f(0, 0, 1));
  CHECK(glMapGrid1d(-1, 0, 1));
  CHECK(glMapGrid2f(1, 0, 1, 0, 0, 1));
  CHECK(glMapGrid2d(0, 0, 1, 1, 0, 1));
  CHECK(glMapGrid1f(3, 1, 1)); /* an empty domain is allowed */
  CHECK(glEvalMesh1(GL_FILL, 0, 1));
  CHECK(glEvalMesh1(GL_TRIANGLES, 0, 1));
  CHECK(glEvalMesh2(GL_LINES, 0, 1, 0, 1));
  CHECK(glEvalMesh2(GL_FILL, 3, 1, 4, 1)); /* empty ranges: nothing, no error */
  glBegin(GL_TRIANGLES);
  CHECK(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, p));
  CHECK(glMapGrid1f(2, 0, 1));
  CHECK(glEvalMesh2(GL_FILL, 0, 1, 0, 1));
  CHECK(glGetMapfv(GL_MAP1_VERTEX_3, GL_ORDER, f));
  CHECK(glEvalCoord1f(0.5f));
  CHECK(glEvalPoint2(0, 0));
  glEnd();
  fprintf(out, "after glEnd: %#x\n", glGetError());
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 480, 360)) return 1;
  out = conf_open_values(&c);
  if (!out) return 1;
  print_state("initial");
  for (GLenum t = GL_MAP1_COLOR_4; t <= GL_MAP1_VERTEX_4; ++t) print_map(t);
  for (GLenum t = GL_MAP2_COLOR_4; t <= GL_MAP2_VERTEX_4; ++t) print_map(t);
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  set_current();

  /* The strips of glEvalMesh2 over these patches turn clockwise where the auto normal faces
   * the viewer: with two-sided lighting they are back faces, lit through the reversed normal
   * (nearly black). The first panel makes them front faces, so that the normals light it. */
  glFrontFace(GL_CW);
  panel(&c, 0, 0), lights(1), view(-35.0f), glEnable(GL_AUTO_NORMAL), patch_fill(16), glDisable(GL_AUTO_NORMAL);
  glFrontFace(GL_CCW), set_current();
  panel(&c, 1, 0), view(-30.0f), glEnable(GL_AUTO_NORMAL), glScalef(1.3f, 1.3f, 1.3f), rational_patch();
  glDisable(GL_AUTO_NORMAL), lights(0), set_current();
  panel(&c, 2, 0), view(-30.0f), colour_patch(), set_current();
  panel(&c, 3, 0), view(-20.0f), textured_patch(), set_current();
  glClear(GL_DEPTH_BUFFER_BIT);
  panel(&c, 0, 1), view(-25.0f), glScalef(0.8f, 0.8f, 0.8f), own_primitives(), set_current();
  panel(&c, 1, 1), curves(), set_current();
  panel(&c, 2, 1), lights(1), view(-30.0f), unequal_orders(), lights(0), set_current();
  panel(&c, 3, 1), lights(1), view(-30.0f), glScalef(0.9f, 0.9f, 0.9f), partial_meshes(), lights(0), set_current();
  glClear(GL_DEPTH_BUFFER_BIT);
  panel(&c, 0, 2), view(-30.0f), in_lists(), set_current();
  panel(&c, 1, 2), lights(1), view(-30.0f), normals_and_material(), lights(0), set_current();
  panel(&c, 2, 2), lights(1), view(-30.0f), attrib_eval(), lights(0), set_current();
  print_state("after the pop");
  panel(&c, 3, 2), view(-25.0f), eval_coords_in_lists(), set_current();
  errors();
  for (GLenum t = GL_MAP1_COLOR_4; t <= GL_MAP1_VERTEX_4; ++t) print_map(t);
  for (GLenum t = GL_MAP2_COLOR_4; t <= GL_MAP2_VERTEX_4; ++t) print_map(t);
  print_state("final");
  fclose(out);
  return conf_finish(&c);
}
