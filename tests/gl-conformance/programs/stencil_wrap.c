/* GL 1.4's wrapping stencil operations (section 4.1.5): GL_INCR_WRAP and GL_DECR_WRAP for
 * stencil-fail, depth-fail and depth-pass, across 255 -> 0 and 0 -> 255, through a write mask
 * and a value mask, against GL_INCR / GL_DECR's saturation, and 300 overlapping layers counted
 * modulo 256. Each panel writes stencil values with colour writes off, then shows them: bits
 * 0-2 add to red, 3-5 to green, 6-7 to blue (eight GL_EQUAL passes with mask 1 << b, additive
 * blending), so the colour encodes the exact value. The values recorded (conf_value): stencil
 * bytes read back with glReadPixels, glGet of the operations, and the errors of wrong
 * operations; the last panel draws them as cells. */
#define GL_GLEXT_PROTOTYPES 1
#include <stdio.h>

#include "conf.h"

#define COLS 4
#define ROWS 2

static void panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, COLS, ROWS);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void rect(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

/* Three overlapping triangles: the centre is covered three times. */
static void overlaps(void) {
  glBegin(GL_TRIANGLES);
  glVertex2f(0.05f, 0.1f);
  glVertex2f(0.8f, 0.15f);
  glVertex2f(0.3f, 0.9f);
  glVertex2f(0.95f, 0.2f);
  glVertex2f(0.7f, 0.95f);
  glVertex2f(0.15f, 0.45f);
  glVertex2f(0.1f, 0.7f);
  glVertex2f(0.45f, 0.05f);
  glVertex2f(0.9f, 0.8f);
  glEnd();
}

static void show_values(void) {
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(0xff);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  for (int b = 0; b < 8; ++b) {
    glStencilFunc(GL_EQUAL, 1 << b, 1u << b);
    float level = (float)(32 << (b % 3)) / 255.0f;
    glColor4f(b < 3 ? level : 0.0f, b >= 3 && b < 6 ? level : 0.0f,
              b >= 6 ? (float)(64 << (b - 6)) / 255.0f : 0.0f, 0.0f);
    rect(0, 0, 1, 1, 0);
  }
  glDisable(GL_BLEND);
}

/* Starts a panel: the stencil of its pixels set to `value`, colour writes off. */
static void begin_writes(const ConfContext* c, int col, int row, GLint value) {
  panel(c, col, row);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glStencilMask(0xff);
  glStencilFunc(GL_ALWAYS, value, 0xff);
  glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
  rect(0, 0, 1, 1, 0);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
}

/* ---- values ---- */
enum { kCols = 16, kRows = 10, kCells = kCols * kRows };
static unsigned values[kCells];
static int n_values = 0;
static ConfContext* conf;

static void record(const char* what, double v) {
  char name[96];
  snprintf(name, sizeof name, "%03d %s", n_values, what);
  conf_value(conf, name, v);
  if (n_values < kCells) values[n_values] = (unsigned)v;
  ++n_values;
}

/* The stencil values of a row of the panel (col, row), 8 samples across its middle. */
static void read_stencil(const ConfContext* c, int col, int row, const char* what) {
  const int w = c->width / COLS, h = c->height / ROWS;
  const int x0 = col * w, y0 = c->height - (row + 1) * h;
  GLubyte s[8];
  char name[96];
  for (int i = 0; i < 8; ++i) {
    glReadPixels(x0 + w * (2 * i + 1) / 16, y0 + h / 2, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[i]);
    snprintf(name, sizeof name, "%s stencil[%d]", what, i);
    record(name, (double)s[i]);
  }
}

static void op_values(void) {
  static const GLenum pnames[3] = {GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS};
  char name[96];
  glStencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_INCR_WRAP);
  for (int i = 0; i < 3; ++i) {
    GLint v = 0;
    glGetIntegerv(pnames[i], &v);
    snprintf(name, sizeof name, "wrap ops %d", i);
    record(name, (double)v);
  }
  record("error after valid ops", (double)glGetError());
  glStencilOp(GL_DECR_WRAP + 1, GL_KEEP, GL_KEEP);
  record("error GL_DECR_WRAP + 1", (double)glGetError());
  glStencilOp(GL_KEEP, GL_INCR_WRAP - 1, GL_KEEP);
  record("error GL_INCR_WRAP - 1", (double)glGetError());
  glStencilOp(GL_KEEP, GL_KEEP, GL_FUNC_ADD);
  record("error GL_FUNC_ADD", (double)glGetError());
  for (int i = 0; i < 3; ++i) {
    GLint v = 0;
    glGetIntegerv(pnames[i], &v);
    snprintf(name, sizeof name, "after errors %d", i);
    record(name, (double)v);
  }
  /* The stencil group keeps them; lists compile them. */
  glPushAttrib(GL_STENCIL_BUFFER_BIT);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glPopAttrib();
  GLint v = 0;
  glGetIntegerv(GL_STENCIL_PASS_DEPTH_FAIL, &v);
  record("popped", (double)v);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glStencilOp(GL_DECR_WRAP, GL_INCR_WRAP, GL_DECR_WRAP);
  glEndList();
  glGetIntegerv(GL_STENCIL_FAIL, &v);
  record("compiled", (double)v);
  glCallList(list);
  glGetIntegerv(GL_STENCIL_FAIL, &v);
  record("called", (double)v);
  glDeleteLists(list, 1);
  record("error at the end", (double)glGetError());
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 320, 200)) return 1;
  conf = &c;
  glClearColor(0, 0, 0, 1);
  glClearStencil(0);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);

  begin_writes(&c, 0, 0, 0xfe); /* INCR_WRAP three times over 0xfe: 0xff, 0x00, 0x01 */
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
  overlaps();
  read_stencil(&c, 0, 0, "incr wrap");
  show_values();

  begin_writes(&c, 1, 0, 0x01); /* DECR_WRAP three times over 0x01: 0x00, 0xff, 0xfe */
  glStencilOp(GL_KEEP, GL_KEEP, GL_DECR_WRAP);
  overlaps();
  read_stencil(&c, 1, 0, "decr wrap");
  show_values();

  begin_writes(&c, 2, 0, 0xff); /* the stencil test failing: fail's INCR_WRAP */
  glStencilFunc(GL_NEVER, 0, 0xff);
  glStencilOp(GL_INCR_WRAP, GL_KEEP, GL_KEEP);
  overlaps();
  read_stencil(&c, 2, 0, "fail incr wrap");
  show_values();

  begin_writes(&c, 3, 0, 0x00); /* the depth test failing: zfail's DECR_WRAP */
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  rect(0.0f, 0.5f, 1.0f, 1.0f, 0.5f); /* the upper half nearer: eye z 0.5, depth 0.25 */
  glStencilOp(GL_KEEP, GL_DECR_WRAP, GL_INCR_WRAP);
  overlaps(); /* at depth 0.5: below the upper rect it fails, elsewhere passes */
  glDisable(GL_DEPTH_TEST);
  read_stencil(&c, 3, 0, "zfail decr wrap");
  show_values();

  begin_writes(&c, 0, 1, 0x00); /* a write mask of the low four bits: 0 - 1 writes 0x0f */
  glStencilMask(0x0f);
  glStencilOp(GL_KEEP, GL_KEEP, GL_DECR_WRAP);
  overlaps();
  read_stencil(&c, 0, 1, "masked decr wrap");
  show_values();

  begin_writes(&c, 1, 1, 0xfd); /* INCR saturates (left half), INCR_WRAP wraps (right half) */
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  for (int i = 0; i < 4; ++i) rect(0.0f, 0.1f * (float)i, 0.5f, 1.0f, 0.0f);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
  for (int i = 0; i < 4; ++i) rect(0.5f, 0.1f * (float)i, 1.0f, 1.0f, 0.0f);
  read_stencil(&c, 1, 1, "incr against incr wrap");
  show_values();

  begin_writes(&c, 2, 1, 0x00); /* 300 layers of shrinking quads counted modulo 256 */
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
  for (int i = 0; i < 300; ++i) {
    const float t = 0.45f * (float)i / 300.0f;
    rect(t, t * 0.3f, 1.0f - t * 0.5f, 1.0f - t, 0.0f);
  }
  read_stencil(&c, 2, 1, "layers");
  show_values();

  op_values();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilMask(0xff);
  glDisable(GL_STENCIL_TEST);
  conf_panel(&c, 3, 1, COLS, ROWS);
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
