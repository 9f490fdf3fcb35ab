/* Lines (GL 1.1 section 3.4): GL_LINES, GL_LINE_STRIP and GL_LINE_LOOP in glBegin/glEnd and
 * vertex arrays; widths 1 to 8 and fractional ones at every angle; ends on pixel centres,
 * corners and anywhere (the diamond-exit rule); flat and smooth colours; stipple patterns and
 * repeat factors along strips and loops; smooth lines blended; lit lines; lines clipped by the
 * view volume in ortho and perspective; depth-tested lines against a sphere. A 4 x 3 grid of
 * panels, each in its own viewport. */
#include <math.h>

#include "conf.h"

#define COLS 4
#define ROWS 3

static unsigned long long seed = 12345;
static float rnd(void) {
  seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
  return (float)((seed >> 33) & 0xffffff) / 16777216.0f;
}

/* A pixel-exact ortho projection for a panel of w x h pixels. */
static void pixel_ortho(int w, int h) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, w, 0, h, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, COLS, ROWS);
  pixel_ortho(c->width / COLS, c->height / ROWS);
}

/* A star of lines from the centre, one width per ray, ends on pixel centres. */
static void star(float cx, float cy, float r, int rays, int integer_ends) {
  for (int i = 0; i < rays; ++i) {
    double a = 2.0 * CONF_PI * (i + 0.3) / rays;
    float x = cx + r * (float)cos(a), y = cy + r * (float)sin(a);
    if (integer_ends) x = floorf(x) + 0.5f, y = floorf(y) + 0.5f;
    glLineWidth((float)(1 + i % 8));
    glBegin(GL_LINES);
    glColor3f(1, 0.2f + 0.1f * (i % 8), 0.2f);
    glVertex2f(cx, cy);
    glColor3f(0.2f, 0.4f, 1);
    glVertex2f(x, y);
    glEnd();
  }
}

/* Short lines at random positions and widths: ends anywhere, on centres and on corners. */
static void random_lines(int w, int h, int n, int quantize) {
  glBegin(GL_LINES);
  for (int i = 0; i < n; ++i) {
    float x0 = rnd() * w, y0 = rnd() * h;
    float x1 = x0 + (rnd() - 0.5f) * 30, y1 = y0 + (rnd() - 0.5f) * 30;
    if (quantize == 1) x0 = floorf(x0) + 0.5f, y0 = floorf(y0) + 0.5f, x1 = floorf(x1) + 0.5f, y1 = floorf(y1) + 0.5f;
    if (quantize == 2) x0 = floorf(x0), y0 = floorf(y0), x1 = floorf(x1), y1 = floorf(y1);
    glColor3f(rnd(), rnd(), rnd());
    glVertex2f(x0, y0);
    glColor3f(rnd(), rnd(), rnd());
    glVertex2f(x1, y1);
  }
  glEnd();
}

static void strips(void) {
  glShadeModel(GL_FLAT);
  glLineWidth(1);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i < 12; ++i) {
    glColor3f(i % 3 == 0, i % 3 == 1, i % 3 == 2);
    glVertex2f(6.0f + 7.0f * i, 10.0f + (i % 2) * 20.0f);
  }
  glEnd();
  glShadeModel(GL_SMOOTH);
  glLineWidth(3);
  glBegin(GL_LINE_LOOP);
  for (int i = 0; i < 7; ++i) {
    double a = 2.0 * CONF_PI * i / 7;
    glColor3f(0.5f + 0.5f * (float)cos(a), 0.5f + 0.5f * (float)sin(a), 0.6f);
    glVertex2f(48.0f + 30.0f * (float)cos(a), 62.0f + 28.0f * (float)sin(a));
  }
  glEnd();
  glLineWidth(1);
}

static void stipples(void) {
  static const GLushort patterns[] = {0x0f0f, 0xaaaa, 0x00ff, 0x3333, 0x1c47, 0x8001};
  glEnable(GL_LINE_STIPPLE);
  for (int i = 0; i < 6; ++i) {
    glLineStipple(1 + i % 3, patterns[i]);
    glLineWidth((float)(1 + (i % 2)));
    glBegin(i < 3 ? GL_LINES : GL_LINE_STRIP);
    glColor3f(1, 1, 0.3f);
    glVertex2f(4, 6.0f + 14 * i);
    glColor3f(0.3f, 1, 1);
    glVertex2f(60, 10.0f + 14 * i);
    glVertex2f(90, 2.0f + 14 * i);
    glVertex2f(70, 12.0f + 14 * i);
    glEnd();
  }
  glLineStipple(2, 0x0f0f); /* the pattern runs on along a loop */
  glBegin(GL_LINE_LOOP);
  glColor3f(1, 0.5f, 1);
  glVertex2f(10, 88);
  glVertex2f(40, 92);
  glVertex2f(60, 84);
  glEnd();
  glDisable(GL_LINE_STIPPLE);
  glLineStipple(1, 0xffff);
}

static void smooth_lines(int w, int h) {
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int i = 0; i < 6; ++i) {
    glLineWidth(i < 3 ? 1.0f : 2.5f + i);
    glBegin(GL_LINES);
    glColor4f(1, 0.9f, 0.3f, 1);
    glVertex2f(5.0f + i * 3, 5.0f + i * 15);
    glColor4f(0.3f, 0.8f, 1, 0.8f);
    glVertex2f(w - 5.0f, 9.0f + i * 13 + i * i);
    glEnd();
  }
  (void)h;
  glDisable(GL_BLEND);
  glDisable(GL_LINE_SMOOTH);
  glLineWidth(1);
}

static void lit_lines(void) {
  static const GLfloat light_pos[] = {1, 1, 2, 0};
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  glLineWidth(2);
  glBegin(GL_LINES);
  for (int i = 0; i < 24; ++i) {
    double a = 2.0 * CONF_PI * i / 24;
    glNormal3f((float)cos(a), (float)sin(a), 0.3f);
    glVertex2f(0.2f * (float)cos(a), 0.2f * (float)sin(a));
    glNormal3f((float)cos(a), (float)sin(a), 1.0f);
    glVertex2f(0.9f * (float)cos(a), 0.9f * (float)sin(a));
  }
  glEnd();
  glDisable(GL_LIGHTING);
  glLineWidth(1);
}

static void clipped_lines(int perspective) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  if (perspective) glFrustum(-0.5, 0.5, -0.5, 0.5, 1, 10);
  else glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  if (perspective) glTranslatef(0, 0, -2.5f);
  for (int i = 0; i < 16; ++i) {
    double a = 2.0 * CONF_PI * i / 16 + 0.1;
    glLineWidth((float)(1 + i % 4));
    glBegin(GL_LINES);
    glColor3f(1, (float)(i % 4) / 3.0f, 0.2f);
    glVertex3f(0.1f * (float)cos(a), 0.1f * (float)sin(a), perspective ? -1.5f : 0.0f);
    glColor3f(0.2f, 0.5f, 1);
    glVertex3f(2.0f * (float)cos(a), 2.0f * (float)sin(a), perspective ? 1.8f : 0.5f);
    glEnd();
  }
  glLineWidth(1);
}

static void depth_lines(void) {
  static const GLfloat light_pos[] = {0, 0, 1, 0};
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.6, 0.6, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -3);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  conf_sphere(0.8f, 24, 16);
  glDisable(GL_LIGHTING);
  glLineWidth(2);
  glBegin(GL_LINES); /* through the sphere: hidden where inside it */
  for (int i = 0; i < 10; ++i) {
    float y = -0.9f + 0.2f * i;
    glColor3f(1, 1, (float)i / 9);
    glVertex3f(-1.2f, y, -0.6f + 0.15f * i);
    glVertex3f(1.2f, -y, 0.6f - 0.1f * i);
  }
  glEnd();
  glDisable(GL_DEPTH_TEST);
  glLineWidth(1);
}

static void array_lines(void) {
  GLfloat v[40][2];
  GLubyte col[40][4];
  for (int i = 0; i < 40; ++i) {
    v[i][0] = 4 + rnd() * 88;
    v[i][1] = 4 + rnd() * 88;
    col[i][0] = (GLubyte)(rnd() * 255), col[i][1] = (GLubyte)(rnd() * 255), col[i][2] = 200, col[i][3] = 255;
  }
  static const GLushort loop[] = {30, 31, 32, 33, 34, 35};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, v);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, col);
  glDrawArrays(GL_LINES, 0, 16);
  glLineWidth(2);
  glDrawArrays(GL_LINE_STRIP, 16, 14);
  glDrawElements(GL_LINE_LOOP, 6, GL_UNSIGNED_SHORT, loop);
  glLineWidth(1);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 384, 288)) return 1;
  const int w = c.width / COLS, h = c.height / ROWS;
  glClearColor(0.1f, 0.1f, 0.12f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  panel(&c, 0, 0);
  star(w / 2.0f, h / 2.0f, w * 0.45f, 24, 1);
  panel(&c, 1, 0);
  star(w / 2.0f + 0.3f, h / 2.0f - 0.2f, w * 0.47f, 31, 0);
  panel(&c, 2, 0);
  random_lines(w, h, 40, 0);
  panel(&c, 3, 0);
  random_lines(w, h, 30, 1);
  glLineWidth(3);
  random_lines(w, h, 10, 2);
  glLineWidth(1);
  panel(&c, 0, 1);
  strips();
  panel(&c, 1, 1);
  stipples();
  panel(&c, 2, 1);
  smooth_lines(w, h);
  panel(&c, 3, 1);
  array_lines();
  conf_panel(&c, 0, 2, COLS, ROWS);
  lit_lines();
  conf_panel(&c, 1, 2, COLS, ROWS);
  clipped_lines(0);
  conf_panel(&c, 2, 2, COLS, ROWS);
  clipped_lines(1);
  conf_panel(&c, 3, 2, COLS, ROWS);
  depth_lines();
  return conf_finish(&c);
}
