/* Display lists (GL 1.1 section 5.4), everything drawn through them, in a 4 x 3 grid:
 * nested lists (a list calling lists that push, transform and pop); glCallLists with every
 * type (GL_BYTE .. GL_4_BYTES) and glListBase; GL_COMPILE_AND_EXECUTE; state set inside a list
 * (glColor, glMaterial, glLight under the list's own glMultMatrix, glPushMatrix/glPopMatrix,
 * glEnable) that stays after it; a list calling another that is redefined, then deleted;
 * glTexImage2D in a list (the image read with the unpack state at compile time, then the
 * client image and unpack state changed); glDrawElements and glDrawArrays in lists with the
 * arrays changed afterwards (GL_QUADS with non-affine colours: the split of quads in lists);
 * glBegin in one list and glEnd in another, glMaterial between them, glArrayElement in lists,
 * glCallList between glBegin and glEnd; a chain of 70 lists each calling the next, of which
 * only the first 64 run (GL_MAX_LIST_NESTING). */
#include <math.h>
#include <string.h>

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

static void lit(int on) {
  if (on) {
    const GLfloat pos[] = {0.4f, 0.7f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
  } else {
    glDisable(GL_LIGHTING);
  }
}

static void square(float x, float y, float s) {
  glBegin(GL_TRIANGLES);
  glVertex2f(x, y), glVertex2f(x + s, y), glVertex2f(x + s, y + s);
  glVertex2f(x, y), glVertex2f(x + s, y + s), glVertex2f(x, y + s);
  glEnd();
}

/* Panel 0: a sphere list called by a list that pushes, translates, scales and pops, called
 * three times by a third list. */
static void nested(GLuint base) {
  const GLfloat red[] = {0.9f, 0.2f, 0.1f, 1.0f};
  glNewList(base, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  conf_sphere(0.45f, 16, 10);
  glEndList();
  glNewList(base + 1, GL_COMPILE);
  glPushMatrix();
  glTranslatef(0.55f, 0.0f, 0.0f);
  glScalef(0.8f, 0.8f, 0.8f);
  glCallList(base);
  glPopMatrix();
  glEndList();
  glNewList(base + 2, GL_COMPILE);
  glCallList(base);
  glRotatef(120.0f, 0.0f, 0.0f, 1.0f);
  glCallList(base + 1);
  glRotatef(120.0f, 0.0f, 0.0f, 1.0f);
  glCallList(base + 1);
  glEndList();
  lit(1);
  glScalef(0.9f, 0.9f, 0.9f);
  glCallList(base + 2);
  lit(0);
}

/* Panel 1: eight coloured squares per row, one row per glCallLists type; the lists move the
 * next square along (glTranslatef inside them). */
static void call_lists(GLuint base) {
  for (int i = 0; i < 8; ++i) {
    glNewList(base + (GLuint)i, GL_COMPILE);
    glColor3f((i & 1) ? 1.0f : 0.2f, (i & 2) ? 1.0f : 0.2f, (i & 4) ? 1.0f : 0.3f);
    square(0.0f, 0.0f, 0.22f);
    glTranslatef(0.27f, 0.0f, 0.0f);
    glEndList();
  }
  const GLbyte b[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  const GLubyte ub[8] = {7, 6, 5, 4, 3, 2, 1, 0};
  const GLshort s[8] = {1, 3, 5, 7, 0, 2, 4, 6};
  const GLushort us[8] = {6, 4, 2, 0, 7, 5, 3, 1};
  const GLint in[8] = {2, 2, 3, 3, 4, 4, 5, 5};
  const GLuint ui[8] = {0, 7, 1, 6, 2, 5, 3, 4};
  const GLfloat f[8] = {3.0f, 1.0f, 4.0f, 1.0f, 5.0f, 0.0f, 2.0f, 6.0f};
  const GLubyte two[16] = {0, 1, 0, 3, 0, 5, 0, 7, 0, 0, 0, 2, 0, 4, 0, 6};
  const GLubyte three[24] = {0, 0, 7, 0, 0, 0, 0, 0, 7, 0, 0, 0, 0, 0, 7, 0, 0, 0, 0, 0, 7, 0, 0, 0};
  const GLubyte four[32] = {0, 0, 0, 4, 0, 0, 0, 3, 0, 0, 0, 2, 0, 0, 0, 1,
                            0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3};
  const struct { GLenum type; const void* data; } rows[] = {
      {GL_BYTE, b}, {GL_UNSIGNED_BYTE, ub}, {GL_SHORT, s}, {GL_UNSIGNED_SHORT, us}, {GL_INT, in},
      {GL_UNSIGNED_INT, ui}, {GL_FLOAT, f}, {GL_2_BYTES, two}, {GL_3_BYTES, three}, {GL_4_BYTES, four}};
  glListBase(base);
  for (int r = 0; r < 10; ++r) {
    glPushMatrix();
    glTranslatef(-1.1f, 0.95f - 0.23f * (float)r, 0.0f);
    glScalef(1.0f, 0.8f, 1.0f);
    glCallLists(8, rows[r].type, rows[r].data);
    glPopMatrix();
  }
  glListBase(0);
}

/* Panel 2: GL_COMPILE_AND_EXECUTE draws at once (left), the list again on the right. */
static void compile_and_execute(GLuint list) {
  glPushMatrix();
  glTranslatef(-0.55f, 0.0f, 0.0f);
  lit(1);
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  glColor3f(0.2f, 0.8f, 0.3f);
  glEnable(GL_COLOR_MATERIAL);
  conf_sphere(0.5f, 14, 9);
  glDisable(GL_COLOR_MATERIAL);
  glEndList();
  glTranslatef(1.1f, 0.0f, 0.0f);
  glCallList(list);
  glPopMatrix();
  lit(0);
}

/* Panel 3: a list that only sets state (colour, material, a light placed by the list's own
 * matrix, lighting on); a sphere drawn after it uses that state. */
static void state_in_list(GLuint list) {
  const GLfloat m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.3f, -0.2f, 0, 1};
  const GLfloat pos[] = {-1.0f, 1.0f, 1.5f, 1.0f};
  const GLfloat spec[] = {1, 1, 1, 1}, shine = 40.0f, blue[] = {0.2f, 0.3f, 1.0f, 1.0f};
  glNewList(list, GL_COMPILE);
  glPushMatrix();
  glMultMatrixf(m);
  glLightfv(GL_LIGHT1, GL_POSITION, pos);
  glPopMatrix();
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, shine);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
  glEnable(GL_LIGHT1);
  glEnable(GL_LIGHTING);
  glMultMatrixf(m);
  glEndList();
  glCallList(list);
  conf_sphere(0.7f, 18, 12);
  glDisable(GL_LIGHT1);
  glDisable(GL_LIGHTING);
  const GLfloat none[] = {0, 0, 0, 1};
  glMaterialfv(GL_FRONT, GL_SPECULAR, none);
}

/* Panel 4: list B calls list A; A is redefined (B draws the new A), then deleted (B draws
 * nothing of it). */
static void redefine(GLuint a, GLuint b) {
  glNewList(a, GL_COMPILE);
  glColor3f(1.0f, 0.1f, 0.1f);
  square(-0.3f, -0.3f, 0.6f);
  glEndList();
  glNewList(b, GL_COMPILE);
  glCallList(a);
  glColor3f(0.9f, 0.9f, 0.9f);
  square(-0.1f, -0.1f, 0.2f);
  glEndList();
  glPushMatrix();
  glTranslatef(-0.6f, 0.6f, 0.0f);
  glCallList(b);  /* red */
  glPopMatrix();
  glNewList(a, GL_COMPILE);
  glColor3f(0.1f, 1.0f, 0.2f);
  square(-0.4f, -0.2f, 0.8f);
  glEndList();
  glPushMatrix();
  glTranslatef(0.6f, 0.6f, 0.0f);
  glCallList(b);  /* green */
  glPopMatrix();
  glDeleteLists(a, 1);
  glPushMatrix();
  glTranslatef(0.0f, -0.6f, 0.0f);
  glCallList(b);  /* the white square only */
  glPopMatrix();
}

/* Panel 5: glTexImage2D in a list reads the image with the unpack state of compile time
 * (alignment 1, a row length and skips); the client image and unpack state change before
 * the list is called. */
static void texture_in_list(GLuint list) {
  enum { kW = 5, kH = 4, kRow = 7 };
  static GLubyte image[(kH + 1) * kRow * 3];
  for (int y = 0; y < kH + 1; ++y)
    for (int x = 0; x < kRow; ++x) {
      GLubyte* p = &image[(y * kRow + x) * 3];
      p[0] = (GLubyte)(40 * x), p[1] = (GLubyte)(60 * y), p[2] = (GLubyte)((x + y) % 2 ? 255 : 30);
    }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, kRow);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, kW, kH, 0, GL_RGB, GL_UNSIGNED_BYTE, image);
  glEndList();
  memset(image, 0, sizeof image);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glCallList(list);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_TRIANGLES);
  glTexCoord2f(0, 0), glVertex2f(-1, -1), glTexCoord2f(1, 0), glVertex2f(1, -1), glTexCoord2f(1, 1), glVertex2f(1, 1);
  glTexCoord2f(0, 0), glVertex2f(-1, -1), glTexCoord2f(1, 1), glVertex2f(1, 1), glTexCoord2f(0, 1), glVertex2f(-1, 1);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glDeleteTextures(1, &tex);
}

/* Panel 6: glDrawElements (a lit sphere from arrays) and glDrawArrays (non-affine quads)
 * compiled, then the arrays overwritten: the lists keep what the arrays held. */
static void arrays_in_list(GLuint list) {
  enum { kS = 16, kT = 10 };
  static GLfloat pos[(kS + 1) * (kT + 1)][3];
  static GLuint idx[kS * kT * 6];
  int n = 0;
  for (int j = 0; j <= kT; ++j)
    for (int i = 0; i <= kS; ++i) {
      double t = 2.0 * CONF_PI * i / kS, p = CONF_PI * j / kT;
      GLfloat* v = pos[j * (kS + 1) + i];
      v[0] = (GLfloat)(sin(p) * sin(t)), v[1] = (GLfloat)cos(p), v[2] = (GLfloat)(sin(p) * cos(t));
    }
  for (int j = 0; j < kT; ++j)
    for (int i = 0; i < kS; ++i) {
      GLuint a = (GLuint)(j * (kS + 1) + i), b = a + 1, c = a + kS + 1, d = c + 1;
      GLuint tri[6] = {a, c, b, b, c, d};
      memcpy(&idx[n], tri, sizeof tri);
      n += 6;
    }
  static GLfloat quad_pos[8][2] = {{-1.1f, -1.1f}, {-0.1f, -1.0f}, {-0.3f, -0.2f}, {-1.0f, -0.4f},
                                   {0.1f, -1.1f}, {1.1f, -1.1f}, {1.0f, -0.1f}, {0.2f, -0.5f}};
  static GLfloat quad_col[8][3] = {{1, 0, 0}, {0, 1, 0}, {1, 1, 1}, {0, 0, 1},
                                   {1, 1, 0}, {0, 0, 0}, {0, 1, 1}, {1, 0, 1}};
  glNewList(list, GL_COMPILE);
  glPushMatrix();
  glTranslatef(0.0f, 0.45f, 0.0f);
  glScalef(0.6f, 0.6f, 0.6f);
  glVertexPointer(3, GL_FLOAT, 0, pos);
  glNormalPointer(GL_FLOAT, 0, pos);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_INT, idx);
  glDisableClientState(GL_NORMAL_ARRAY);
  glPopMatrix();
  glVertexPointer(2, GL_FLOAT, 0, quad_pos);
  glColorPointer(3, GL_FLOAT, 0, quad_col);
  glEnableClientState(GL_COLOR_ARRAY);
  glDrawArrays(GL_QUADS, 0, 8);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glEndList();
  memset(pos, 0, sizeof pos);
  memset(idx, 0, sizeof idx);
  memset(quad_pos, 0, sizeof quad_pos);
  lit(1);
  glEnable(GL_COLOR_MATERIAL);
  glColor3f(0.9f, 0.7f, 0.2f);
  glCallList(list);
  glDisable(GL_COLOR_MATERIAL);
  lit(0);
}

/* Panel 7: glBegin in one list, the vertices (a glMaterial change half-way) and glEnd in
 * others; glArrayElement compiled (outside and inside glBegin/glEnd), a list of them called
 * between glBegin and glEnd; flat and smooth. */
static void split_primitive(GLuint base) {
  static const GLfloat tc[4][3] = {{0.6f, 0.2f, 0.2f}, {0.2f, 0.6f, 0.9f}, {0.9f, 0.9f, 0.2f}, {0.5f, 0.9f, 0.5f}};
  static const GLfloat tv[4][3] = {{0.2f, 0.2f, 0}, {1.0f, 0.3f, 0}, {1.0f, 1.0f, 0}, {0.3f, 0.9f, 0}};
  const GLfloat green[] = {0.2f, 0.9f, 0.3f, 1.0f}, white[] = {1, 1, 1, 1};
  glNewList(base, GL_COMPILE);
  glBegin(GL_TRIANGLE_STRIP);
  glEndList();
  glNewList(base + 1, GL_COMPILE);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glVertex2f(-1.0f, -1.0f), glVertex2f(0.0f, -1.1f), glVertex2f(-0.9f, 0.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
  glNormal3f(0.5f, 0.2f, 0.8f);
  glVertex2f(0.1f, -0.1f);
  glEndList();
  glNewList(base + 2, GL_COMPILE);
  glVertex2f(-0.8f, 0.3f);
  glEnd();
  glEndList();
  lit(1);
  glCallList(base);
  glCallList(base + 1);
  glCallList(base + 2);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, white);
  lit(0);
  glVertexPointer(3, GL_FLOAT, 0, tv);
  glColorPointer(3, GL_FLOAT, 0, tc);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glNewList(base + 3, GL_COMPILE);
  glArrayElement(2), glArrayElement(3);
  glEndList();
  glNewList(base + 4, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glArrayElement(0), glArrayElement(2), glArrayElement(3);
  glEnd();
  glEndList();
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  /* glCallList between glBegin and glEnd (not inside a compiled glBegin: Mesa's vbo_save
   * crashes on that, docs/gl-conformance.md). */
  glShadeModel(GL_FLAT);
  glBegin(GL_QUADS);
  glColor3f(0.3f, 0.3f, 0.9f), glVertex2f(0.2f, -1.0f);
  glColor3f(0.9f, 0.3f, 0.3f), glVertex2f(1.1f, -1.0f);
  glCallList(base + 3);
  glEnd();
  glShadeModel(GL_SMOOTH);
  glTranslatef(0.0f, -0.1f, 0.0f);
  glCallList(base + 4);
}

/* Panels 8-11: a chain of 70 lists, list i drawing square i of a 10 x 7 grid and calling
 * list i + 1: the lists past the 64th are not executed. Then quads in a list, smooth and
 * flat, whose split shows; a list compiled while another list's call is being compiled. */
static void nesting(GLuint base) {
  for (int i = 0; i < 70; ++i) {
    glNewList(base + (GLuint)i, GL_COMPILE);
    glColor3f((float)(i % 7) / 6.0f, (float)(i / 7) / 9.0f, 1.0f - (float)(i % 3) / 2.0f);
    square(-1.1f + 0.22f * (float)(i % 10), 0.9f - 0.3f * (float)(i / 10), 0.18f);
    glCallList(base + (GLuint)i + 1);
    glEndList();
  }
  glCallList(base);
}

static void quads(GLuint list) {
  glNewList(list, GL_COMPILE);
  glBegin(GL_QUADS);
  glColor3f(1, 0, 0), glVertex2f(-1.1f, -1.1f);
  glColor3f(0, 1, 0), glVertex2f(-0.1f, -1.0f);
  glColor3f(1, 1, 1), glVertex2f(-0.2f, -0.1f);
  glColor3f(0, 0, 1), glVertex2f(-1.0f, -0.3f);
  glColor3f(1, 1, 0), glVertex2f(0.1f, 0.1f);
  glColor3f(0, 0, 0), glVertex2f(1.1f, 0.0f);
  glColor3f(0, 1, 1), glVertex2f(1.0f, 1.1f);
  glColor3f(1, 0, 1), glVertex2f(0.0f, 0.9f);
  glEnd();
  glEndList();
  glCallList(list);
  glPushMatrix();
  glTranslatef(1.1f, -1.1f, 0.0f);
  glScalef(0.5f, 0.5f, 1.0f);
  glShadeModel(GL_FLAT);
  glCallList(list);
  glShadeModel(GL_SMOOTH);
  glPopMatrix();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 480, 360)) return 1;
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  GLuint base = glGenLists(100);
  panel(&c, 0, 0), nested(base);
  panel(&c, 1, 0), call_lists(base + 10);
  panel(&c, 2, 0), compile_and_execute(base + 20);
  panel(&c, 3, 0), state_in_list(base + 21);
  glClear(GL_DEPTH_BUFFER_BIT);
  panel(&c, 0, 1), redefine(base + 22, base + 23);
  panel(&c, 1, 1), texture_in_list(base + 24);
  panel(&c, 2, 1), arrays_in_list(base + 25);
  panel(&c, 3, 1), split_primitive(base + 30);
  glDisable(GL_DEPTH_TEST);
  panel(&c, 0, 2), nesting(glGenLists(70));
  panel(&c, 1, 2), quads(base + 40);
  panel(&c, 2, 2);
  glScalef(-1.0f, 1.0f, 1.0f);
  glCallList(base + 40);
  panel(&c, 3, 2);
  glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
  glCallList(base + 2);
  return conf_finish(&c);
}
