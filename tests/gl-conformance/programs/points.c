/* Points (GL 1.1 section 3.3): sizes 1 to 12 and fractional ones, on pixel centres, corners
 * and anywhere; flat colours; smooth points blended and unblended; lit points; points near and
 * beyond the viewport's edges (a point whose centre is outside is not drawn, a wide one inside
 * reaches past the viewport); points in perspective with depth testing; glDrawArrays and
 * glDrawElements of points. A 4 x 2 grid of panels. */
#include <math.h>

#include "conf.h"

#define COLS 4
#define ROWS 2

static unsigned long long seed = 777;
static float rnd(void) {
  seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
  return (float)((seed >> 33) & 0xffffff) / 16777216.0f;
}

static void panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, COLS, ROWS);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, c->width / COLS, 0, c->height / ROWS, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void sizes(int quantize) {
  for (int i = 0; i < 12; ++i) {
    for (int j = 0; j < 4; ++j) {
      float x = 6.0f + 7.8f * i + (quantize ? 0.0f : 0.37f * j), y = 10.0f + 24.0f * j;
      if (quantize == 1) x = floorf(x) + 0.5f, y = floorf(y) + 0.5f;
      glPointSize(i < 8 ? 1.0f + i : 0.6f + 1.5f * (i - 7) + 0.45f * j);
      glBegin(GL_POINTS);
      glColor3f(0.3f + 0.06f * i, 1.0f - 0.2f * j, 0.4f);
      glVertex2f(x, y);
      glEnd();
    }
  }
}

static void random_points(int w, int h) {
  for (int i = 0; i < 60; ++i) {
    glPointSize(1.0f + (float)(i % 7));
    glBegin(GL_POINTS);
    glColor3f(rnd(), rnd(), rnd());
    glVertex2f(rnd() * w, rnd() * h);
    glEnd();
  }
}

static void smooth_points(int blend) {
  glEnable(GL_POINT_SMOOTH);
  if (blend) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }
  for (int i = 0; i < 16; ++i) {
    glPointSize(1.0f + 1.3f * i);
    glBegin(GL_POINTS);
    glColor4f(1, 0.8f - 0.04f * i, 0.3f, 0.5f + 0.03f * i);
    glVertex2f(10.0f + 23.5f * (i % 4) + 0.3f * i, 12.0f + 24.0f * (i / 4));
    glEnd();
  }
  glDisable(GL_BLEND);
  glDisable(GL_POINT_SMOOTH);
  glPointSize(1);
}

static void edge_points(int w, int h) {
  /* around the viewport's border: centres just inside and just outside */
  for (int i = 0; i < 20; ++i) {
    float t = (float)i / 19.0f;
    glPointSize(1.0f + (float)(i % 6) * 2.0f);
    glBegin(GL_POINTS);
    glColor3f(1, t, 0.2f);
    glVertex2f(t * w, (i % 2) ? -0.4f : 0.6f);
    glVertex2f(t * w, h + ((i % 2) ? 0.4f : -0.6f));
    glColor3f(0.2f, t, 1);
    glVertex2f((i % 2) ? -0.5f : 0.5f, t * h);
    glVertex2f(w + ((i % 2) ? 0.5f : -0.5f), t * h);
    glEnd();
  }
}

static void lit_points(void) {
  static const GLfloat light_pos[] = {-1, 1, 1, 0};
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -3);
  glRotatef(25, 1, 0, 0);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  glEnable(GL_DEPTH_TEST);
  glPointSize(4);
  glBegin(GL_POINTS);
  for (int i = 0; i < 12; ++i) {
    for (int j = 0; j < 8; ++j) {
      double a = 2.0 * CONF_PI * i / 12, b = CONF_PI * (j + 0.5) / 8;
      float x = (float)(sin(b) * cos(a)), y = (float)cos(b), z = (float)(sin(b) * sin(a));
      glNormal3f(x, y, z);
      glVertex3f(x, y, z);
    }
  }
  glEnd();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  glPointSize(1);
}

static void array_points(void) {
  GLfloat v[50][3];
  GLfloat col[50][3];
  GLuint idx[20];
  for (int i = 0; i < 50; ++i) {
    v[i][0] = 4 + rnd() * 88, v[i][1] = 4 + rnd() * 88, v[i][2] = 0;
    col[i][0] = rnd(), col[i][1] = rnd(), col[i][2] = 1;
  }
  for (int i = 0; i < 20; ++i) idx[i] = (GLuint)(i * 7 % 50);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, v);
  glColorPointer(3, GL_FLOAT, 0, col);
  glPointSize(2);
  glDrawArrays(GL_POINTS, 0, 30);
  glPointSize(5);
  glDrawElements(GL_POINTS, 20, GL_UNSIGNED_INT, idx);
  glPointSize(1);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 384, 192)) return 1;
  const int w = c.width / COLS, h = c.height / ROWS;
  glClearColor(0.1f, 0.12f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  panel(&c, 0, 0);
  sizes(0);
  panel(&c, 1, 0);
  sizes(1);
  panel(&c, 2, 0);
  random_points(w, h);
  panel(&c, 3, 0);
  smooth_points(1);
  panel(&c, 0, 1);
  smooth_points(0);
  panel(&c, 1, 1);
  edge_points(w, h);
  conf_panel(&c, 2, 1, COLS, ROWS);
  lit_points();
  panel(&c, 3, 1);
  array_points();
  return conf_finish(&c);
}
