/* Geometry in display lists (GL 1.1 section 5.4), which shadelab compiles once into meshes
 * and draws through its vertex-array path, or vertex by vertex when the state at glCallList
 * rules that out, in a 4 x 3 grid: a lit sphere; the same with per-vertex colours under
 * GL_COLOR_MATERIAL (vertex by vertex) and unlit (meshes); flat-shaded lit quads (vertex by
 * vertex) beside a flat triangle strip; quad strips, fans and polygons; a textured strip under
 * a texture matrix; w = 2 vertices lit and unlit; the current colour, normal and texture
 * coordinates a list leaves (glBegin/glEnd: its last ones; glDrawArrays: unchanged); a
 * glDrawElements sphere with a colour array, with and without colour material; a strip of
 * 20,000 vertices; an attribute first set after a primitive's first vertex (that vertex
 * takes the colour current when the list is called); quads partly outside the view. */
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

static void lighting(int on) {
  const GLfloat pos[] = {0.5f, 0.8f, 1.0f, 0.0f}, pos1[] = {-1.0f, -0.5f, 1.5f, 1.0f};
  const GLfloat blue[] = {0.3f, 0.4f, 1.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightfv(GL_LIGHT1, GL_POSITION, pos1);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, blue);
  if (on) {
    glEnable(GL_LIGHTING), glEnable(GL_LIGHT0), glEnable(GL_LIGHT1);
  } else {
    glDisable(GL_LIGHTING);
  }
}

/* A sphere as glBegin(GL_TRIANGLES), with per-vertex colours when `colors`. */
static void sphere(float r, int slices, int stacks, int colors) {
  glBegin(GL_TRIANGLES);
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const int di[6] = {0, 1, 1, 0, 1, 0}, dj[6] = {0, 0, 1, 0, 1, 1};
      for (int k = 0; k < 6; ++k) {
        double t = 2.0 * CONF_PI * (i + di[k]) / slices, p = CONF_PI * (j + dj[k]) / stacks;
        float x = (float)(sin(p) * sin(t)), y = (float)cos(p), z = (float)(sin(p) * cos(t));
        if (colors) glColor3f(0.5f + 0.5f * x, 0.5f + 0.5f * y, 0.5f - 0.5f * z);
        glNormal3f(x, y, z);
        glVertex3f(r * x, r * y, r * z);
      }
    }
  glEnd();
}

static void quad_grid(float x0, float y0, float size, int n, int mode) {
  glBegin(mode);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      float x = x0 + size * (float)i / (float)n, y = y0 + size * (float)j / (float)n, s = size / (float)n;
      const float cx[4] = {0, 1, 1, 0}, cy[4] = {0, 0, 1, 1};
      for (int k = 0; k < 4; ++k) {
        glNormal3f(0.4f * (cx[k] - 0.5f) + 0.2f * (float)i / (float)n, 0.3f * (cy[k] - 0.5f), 1.0f);
        glVertex2f(x + s * cx[k], y + s * cy[k]);
      }
    }
  glEnd();
}

static void strips(void) {
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= 6; ++i) {
    float x = -1.1f + 0.35f * (float)i;
    glColor3f((float)i / 6.0f, 0.3f, 1.0f - (float)i / 6.0f), glVertex2f(x, 0.2f);
    glColor3f(1.0f, (float)(i % 2), 0.2f), glVertex2f(x + 0.1f * (float)(i % 3), 1.0f);
  }
  glEnd();
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1, 1, 1), glVertex2f(-0.5f, -0.5f);
  for (int i = 0; i <= 8; ++i) {
    double a = CONF_PI * i / 8.0;
    glColor3f((float)(i % 3) / 2.0f, (float)(i % 2), (float)(i % 4) / 3.0f);
    glVertex2f(-0.5f + 0.6f * (float)cos(a), -0.5f - 0.6f * (float)sin(a));
  }
  glEnd();
  glBegin(GL_POLYGON);
  for (int i = 0; i < 7; ++i) {
    double a = 2.0 * CONF_PI * i / 7.0;
    glColor3f((float)(i % 2), (float)(i % 3) / 2.0f, 1.0f - (float)i / 7.0f);
    glVertex2f(0.6f + 0.45f * (float)cos(a), -0.5f + 0.45f * (float)sin(a));
  }
  glEnd();
}

static GLuint checker(void) {
  static GLubyte img[8][8][3];
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      img[y][x][0] = (GLubyte)((x + y) % 2 ? 240 : 30), img[y][x][1] = (GLubyte)(30 * x), img[y][x][2] = (GLubyte)(30 * y);
    }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, img);
  return tex;
}

static void textured_strip(void) {
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i <= 8; ++i) {
    float x = -1.1f + 0.275f * (float)i, wave = 0.2f * (float)sin(i * 0.9);
    glTexCoord2f((float)i / 8.0f, 0.0f), glVertex2f(x, -0.9f + wave);
    glTexCoord2f((float)i / 8.0f, 1.0f), glVertex2f(x, 0.9f + wave);
  }
  glEnd();
}

static void homogeneous(void) {
  glBegin(GL_TRIANGLES);
  glNormal3f(0, 0, 1), glColor3f(1, 0.5f, 0);
  glVertex4f(-2.0f, -2.0f, 0.0f, 2.0f), glVertex4f(0.0f, -2.0f, 0.0f, 2.0f), glVertex4f(-1.0f, 0.0f, 0.0f, 2.0f);
  glNormal3f(0.5f, 0.5f, 0.7f), glColor3f(0.2f, 0.8f, 1);
  glVertex4f(0.2f, 0.2f, 0.0f, 1.0f), glVertex4f(2.2f, 0.2f, 0.0f, 2.0f), glVertex4f(1.0f, 2.0f, 0.0f, 2.0f);
  glEnd();
}

/* Panel 7: what lists leave current, shown by drawing with it after each call. */
static void current_values(GLuint base) {
  static const GLfloat pos[3][2] = {{0, 0}, {1, 0}, {0, 1}}, col[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  glNewList(base, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glColor3f(0.2f, 0.2f, 0.2f), glVertex2f(-1.1f, 0.6f), glVertex2f(-0.6f, 0.6f);
  glColor3f(0.9f, 0.6f, 0.1f), glVertex2f(-0.85f, 1.1f);  /* current after the list */
  /* (Not an attribute after the last vertex: Mesa's lists do not leave those current.) */
  glEnd();
  glEndList();
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glColorPointer(3, GL_FLOAT, 0, col);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glNewList(base + 1, GL_COMPILE);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEndList();
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glCallList(base);
  glRectf(-0.5f, 0.6f, 0.0f, 1.1f);
  glColor3f(0.8f, 0.3f, 0.9f);
  glPushMatrix();
  glTranslatef(0.1f, -0.2f, 0.0f);
  glScalef(0.5f, 0.5f, 1.0f);
  glCallList(base + 1);
  glPopMatrix();
  glRectf(0.1f, 0.6f, 0.6f, 1.1f);
}

/* Panel 8: a glDrawElements sphere with a colour array, lit, with and without colour
 * material. */
static void elements_sphere(GLuint list) {
  enum { kS = 20, kT = 12 };
  static GLfloat pos[(kS + 1) * (kT + 1)][3], colour[(kS + 1) * (kT + 1)][4];
  static GLushort idx[kS * kT * 6];
  int n = 0;
  for (int j = 0; j <= kT; ++j)
    for (int i = 0; i <= kS; ++i) {
      double t = 2.0 * CONF_PI * i / kS, p = CONF_PI * j / kT;
      GLfloat* v = pos[j * (kS + 1) + i];
      v[0] = (GLfloat)(sin(p) * sin(t)), v[1] = (GLfloat)cos(p), v[2] = (GLfloat)(sin(p) * cos(t));
      GLfloat* c = colour[j * (kS + 1) + i];
      c[0] = (GLfloat)(i % 4) / 3.0f, c[1] = (GLfloat)j / kT, c[2] = 0.6f, c[3] = 1.0f;
    }
  for (int j = 0; j < kT; ++j)
    for (int i = 0; i < kS; ++i) {
      GLushort a = (GLushort)(j * (kS + 1) + i), b = (GLushort)(a + 1), c = (GLushort)(a + kS + 1), d = (GLushort)(c + 1);
      GLushort tri[6] = {a, c, b, b, c, d};
      memcpy(&idx[n], tri, sizeof tri);
      n += 6;
    }
  glVertexPointer(3, GL_FLOAT, 0, pos);
  glNormalPointer(GL_FLOAT, 0, pos);
  glColorPointer(4, GL_FLOAT, 0, colour);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glNewList(list, GL_COMPILE);
  glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_SHORT, idx);
  glEndList();
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  lighting(1);
  glPushMatrix();
  glTranslatef(-0.55f, 0.0f, 0.0f);
  glScalef(0.5f, 0.5f, 0.5f);
  glEnable(GL_COLOR_MATERIAL);
  glCallList(list);
  glDisable(GL_COLOR_MATERIAL);
  glTranslatef(2.2f, 0.0f, 0.0f);
  glCallList(list);
  glPopMatrix();
  lighting(0);
}

static void long_strip(void) {
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 20000; ++i) {
    double a = 40.0 * CONF_PI * i / 20000.0, r = 0.2 + 0.9 * i / 20000.0;
    glColor3f((float)(i % 1000) / 1000.0f, 0.5f, (float)(i % 333) / 333.0f);
    glVertex2f((float)(r * cos(a)), (float)(r * sin(a)) * (i % 2 ? 0.96f : 1.0f));
  }
  glEnd();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 480, 360)) return 1;
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const GLuint base = glGenLists(20);
  glNewList(base, GL_COMPILE), sphere(0.9f, 24, 14, 0), glEndList();
  glNewList(base + 1, GL_COMPILE), sphere(0.9f, 24, 14, 1), glEndList();
  glNewList(base + 2, GL_COMPILE), quad_grid(-1.1f, -1.1f, 2.2f, 6, GL_QUADS), glEndList();
  glNewList(base + 3, GL_COMPILE), strips(), glEndList();
  glNewList(base + 4, GL_COMPILE), textured_strip(), glEndList();
  glNewList(base + 5, GL_COMPILE), homogeneous(), glEndList();
  glNewList(base + 6, GL_COMPILE), long_strip(), glEndList();
  panel(&c, 0, 0), lighting(1), glCallList(base), lighting(0);
  panel(&c, 1, 0), lighting(1), glEnable(GL_COLOR_MATERIAL), glCallList(base + 1);
  glDisable(GL_COLOR_MATERIAL), lighting(0);
  panel(&c, 2, 0), glCallList(base + 1);
  panel(&c, 3, 0), lighting(1), glShadeModel(GL_FLAT), glCallList(base + 2);
  glShadeModel(GL_SMOOTH), lighting(0);
  glClear(GL_DEPTH_BUFFER_BIT);
  panel(&c, 0, 1), glCallList(base + 3);
  panel(&c, 1, 1);
  GLuint tex = checker();
  glEnable(GL_TEXTURE_2D);
  glMatrixMode(GL_TEXTURE), glRotatef(20.0f, 0, 0, 1), glScalef(2.0f, 1.0f, 1.0f), glMatrixMode(GL_MODELVIEW);
  glCallList(base + 4);
  glMatrixMode(GL_TEXTURE), glLoadIdentity(), glMatrixMode(GL_MODELVIEW);
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &tex);
  /* One directional light: Mesa lights w != 1 vertices at (x, y, z), not (x, y, z) / w. */
  panel(&c, 2, 1), lighting(1), glDisable(GL_LIGHT1), glCallList(base + 5), lighting(0);
  glTranslatef(0.0f, -1.0f, 0.0f), glCallList(base + 5);
  panel(&c, 3, 1), current_values(base + 7);
  glClear(GL_DEPTH_BUFFER_BIT);
  panel(&c, 0, 2), elements_sphere(base + 9);
  panel(&c, 1, 2), glCallList(base + 6);
  panel(&c, 2, 2);
  glNewList(base + 10, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1.0f, -1.0f);
  glColor3f(1.0f, 0.2f, 0.2f), glVertex2f(0.0f, -1.0f), glVertex2f(-0.5f, 0.0f);
  glEnd();
  glEndList();
  glColor3f(0.2f, 1.0f, 0.2f), glCallList(base + 10);
  glTranslatef(1.0f, 1.0f, 0.0f), glColor3f(0.2f, 0.2f, 1.0f), glCallList(base + 10);
  panel(&c, 3, 2);
  glScalef(1.6f, 1.6f, 1.0f);
  glCallList(base + 3);
  glTranslatef(-0.4f, 0.3f, 0.0f);
  glCallList(base + 2);
  return conf_finish(&c);
}
