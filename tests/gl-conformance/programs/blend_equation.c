/* GL 1.4's blending (section 4.1.7, the imaging subset's blending made core): glBlendEquation
 * with each of its five equations over every pair of the fifteen source and destination
 * factors (GL 1.1's, GL 1.4's source colour as a source factor and destination colour as a
 * destination factor, and the four constant-colour factors), glBlendFuncSeparate's alpha
 * factors apart from the colour's, and glBlendColor's constant near the 8-bit rounding points.
 * Panels 0-4 (GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX): cell
 * (column s, row d) blends with source factor s and destination factor d. In each cell the
 * destination is a quad drawn without blending whose colour and alpha vary from left to right;
 * the source quad's vary from bottom to top. Panel 5: the colour factors vary with the cell,
 * the alpha factors are (column, row); panel 6: the constant colour varies by row, a factor
 * pair reading it by column. Alpha is stored in the framebuffer (the PNG keeps it) and
 * compared too. The last panel draws the values recorded (conf_value): every blend query
 * after glBlendFunc, glBlendFuncSeparate, glBlendEquation, glBlendColor (clamped), their
 * errors (unknown enums, inside glBegin/glEnd), glPushAttrib(GL_COLOR_BUFFER_BIT) and display
 * lists. GL_BLEND_EQUATION_ALPHA (GL 2.0) and the dual-source factors are not used: Mesa
 * accepts them, GL 1.5 does not know them. */
#define GL_GLEXT_PROTOTYPES 1
#include <stdio.h>

#include "conf.h"

#define COLS 4
#define ROWS 2
#define N 15

static const GLenum kFactors[N] = {
    GL_ZERO,          GL_ONE,           GL_SRC_COLOR,           GL_ONE_MINUS_SRC_COLOR,
    GL_DST_COLOR,     GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA,     GL_ONE_MINUS_SRC_ALPHA,
    GL_DST_ALPHA,     GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA_SATURATE, GL_CONSTANT_COLOR,
    GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA};
static const GLenum kEquations[5] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};

static void panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, COLS, ROWS);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, N, 0.0, N, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* The destination of cell (x, y), drawn without blending, then the source over it with the
 * blend state of the moment. */
static void cell(int x, int y) {
  const float x0 = (float)x + 0.04f, x1 = (float)x + 0.96f, y0 = (float)y + 0.04f, y1 = (float)y + 0.96f;
  glDisable(GL_BLEND);
  glBegin(GL_QUADS);
  glColor4f(0.2f, 0.6f, 0.9f, 0.8f);
  glVertex2f(x0, y0);
  glColor4f(0.9f, 0.35f, 0.1f, 0.15f);
  glVertex2f(x1, y0);
  glVertex2f(x1, y1);
  glColor4f(0.2f, 0.6f, 0.9f, 0.8f);
  glVertex2f(x0, y1);
  glEnd();
  glEnable(GL_BLEND);
  glBegin(GL_QUADS);
  glColor4f(0.85f, 0.45f, 0.3f, 0.9f);
  glVertex2f(x0 + 0.1f, y0 + 0.1f);
  glVertex2f(x1 - 0.1f, y0 + 0.1f);
  glColor4f(0.1f, 0.9f, 0.55f, 0.25f);
  glVertex2f(x1 - 0.1f, y1 - 0.1f);
  glVertex2f(x0 + 0.1f, y1 - 0.1f);
  glEnd();
  glDisable(GL_BLEND);
}

static void equation_panel(int e) {
  glBlendEquation(kEquations[e]);
  for (int d = 0; d < N; ++d) {
    for (int s = 0; s < N; ++s) {
      glBlendFunc(kFactors[s], kFactors[d]);
      cell(s, d);
    }
  }
  glBlendEquation(GL_FUNC_ADD);
}

static void separate_panel(void) {
  for (int row = 0; row < N; ++row) {
    for (int col = 0; col < N; ++col) {
      glBlendEquation(kEquations[(row + col) % 3]);
      glBlendFuncSeparate(kFactors[(row + col) % N], kFactors[(2 * row + 3 * col + 1) % N], kFactors[col],
                          kFactors[row]);
      cell(col, row);
    }
  }
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ZERO);
}

/* Rows: constant colours on and around the points where 8-bit rounding changes (k + 1/2) / 255,
 * and out of range (clamped when given). Columns: factor pairs reading them. */
static void constant_panel(void) {
  static const GLenum pairs[N][2] = {
      {GL_CONSTANT_COLOR, GL_ZERO},           {GL_ZERO, GL_CONSTANT_COLOR},
      {GL_CONSTANT_ALPHA, GL_ZERO},           {GL_ZERO, GL_CONSTANT_ALPHA},
      {GL_ONE_MINUS_CONSTANT_COLOR, GL_ZERO}, {GL_ZERO, GL_ONE_MINUS_CONSTANT_COLOR},
      {GL_ONE_MINUS_CONSTANT_ALPHA, GL_ZERO}, {GL_ZERO, GL_ONE_MINUS_CONSTANT_ALPHA},
      {GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR}, {GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA},
      {GL_CONSTANT_COLOR, GL_CONSTANT_ALPHA}, {GL_ONE_MINUS_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_COLOR},
      {GL_SRC_ALPHA, GL_ONE_MINUS_CONSTANT_COLOR}, {GL_CONSTANT_COLOR, GL_ONE},
      {GL_ONE, GL_CONSTANT_ALPHA}};
  for (int row = 0; row < N; ++row) {
    const float k = ((float)(row * 17 + 3) + 0.5f) / 255.0f;
    const float off = (row % 3 - 1) * 0.0004f;
    if (row == N - 1) glBlendColor(-0.5f, 1.5f, 0.25f, 2.0f);
    else glBlendColor(k + off, 1.0f - k - off, 0.5f * k, 0.3f + k * 0.5f);
    for (int col = 0; col < N; ++col) {
      glBlendEquation(col % 2 ? GL_FUNC_REVERSE_SUBTRACT : GL_FUNC_ADD);
      if (col >= 12) glBlendEquation(GL_FUNC_ADD);
      glBlendFunc(pairs[col][0], pairs[col][1]);
      cell(col, row);
    }
  }
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ZERO);
}

/* ---- values ---- */
enum { kCols = 20, kRows = 16, kCells = kCols * kRows };
static unsigned values[kCells];
static int n_values = 0;
static ConfContext* conf;

static void record(const char* what, double v) {
  char name[96];
  snprintf(name, sizeof name, "%03d %s", n_values, what);
  conf_value(conf, name, v);
  if (n_values < kCells) values[n_values] = (unsigned)(long long)(v * 1000.0);
  ++n_values;
}

static void record_error(const char* what) {
  char name[96];
  snprintf(name, sizeof name, "error %s", what);
  record(name, (double)glGetError());
}

static void blend_state(const char* when) {
  static const struct {
    GLenum pname;
    const char* name;
  } kInts[] = {{GL_BLEND_SRC, "GL_BLEND_SRC"},
               {GL_BLEND_DST, "GL_BLEND_DST"},
               {GL_BLEND_SRC_RGB, "GL_BLEND_SRC_RGB"},
               {GL_BLEND_DST_RGB, "GL_BLEND_DST_RGB"},
               {GL_BLEND_SRC_ALPHA, "GL_BLEND_SRC_ALPHA"},
               {GL_BLEND_DST_ALPHA, "GL_BLEND_DST_ALPHA"},
               {GL_BLEND_EQUATION, "GL_BLEND_EQUATION"}};
  char name[96];
  for (int i = 0; i < (int)(sizeof kInts / sizeof kInts[0]); ++i) {
    GLint v = -1;
    glGetIntegerv(kInts[i].pname, &v);
    snprintf(name, sizeof name, "%s %s", when, kInts[i].name);
    record(name, (double)v);
  }
  GLfloat f[4] = {-1, -1, -1, -1};
  GLint iv[4] = {0, 0, 0, 0};
  GLboolean b[4] = {9, 9, 9, 9};
  glGetFloatv(GL_BLEND_COLOR, f);
  glGetIntegerv(GL_BLEND_COLOR, iv);
  glGetBooleanv(GL_BLEND_COLOR, b);
  for (int i = 0; i < 4; ++i) {
    snprintf(name, sizeof name, "%s GL_BLEND_COLOR float[%d]", when, i);
    record(name, (double)f[i]);
    snprintf(name, sizeof name, "%s GL_BLEND_COLOR int[%d]", when, i);
    record(name, (double)iv[i]);
    snprintf(name, sizeof name, "%s GL_BLEND_COLOR bool[%d]", when, i);
    record(name, (double)b[i]);
  }
  snprintf(name, sizeof name, "%s GL_BLEND enabled", when);
  record(name, (double)glIsEnabled(GL_BLEND));
  snprintf(name, sizeof name, "%s error", when);
  record(name, (double)glGetError());
}

static void blend_values(void) {
  blend_state("after the panels");
  glBlendFunc(GL_SRC_COLOR, GL_DST_COLOR);
  blend_state("glBlendFunc(SRC_COLOR, DST_COLOR)");
  glBlendFuncSeparate(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA, GL_DST_ALPHA, GL_SRC_ALPHA_SATURATE);
  blend_state("glBlendFuncSeparate");
  glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
  glBlendColor(0.25f, 0.5f, 0.75f, 1.0f);
  blend_state("equation and colour");
  glBlendColor(-0.5f, 1.5f, 0.3f, 2.0f);
  blend_state("colour clamped");
  glBlendEquation(GL_MIN);
  glBlendFunc(GL_ONE_MINUS_DST_COLOR, GL_ONE_MINUS_SRC_COLOR);
  blend_state("GL_MIN, glBlendFunc after glBlendFuncSeparate");

  /* Errors: the state is left as it was. */
  glBlendFunc(0x1234, GL_ONE);
  record_error("glBlendFunc(0x1234, GL_ONE)");
  glBlendFunc(GL_ONE, GL_FUNC_ADD);
  record_error("glBlendFunc(GL_ONE, GL_FUNC_ADD)");
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, 0x8000);
  record_error("glBlendFuncSeparate(.., 0x8000)");
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_BLEND_COLOR, GL_ONE);
  record_error("glBlendFuncSeparate(.., GL_BLEND_COLOR, ..)");
  glBlendEquation(GL_BLEND_EQUATION);
  record_error("glBlendEquation(GL_BLEND_EQUATION)");
  glBlendEquation(GL_ZERO);
  record_error("glBlendEquation(GL_ZERO)");
  glBlendEquation(GL_LOGIC_OP);
  record_error("glBlendEquation(GL_LOGIC_OP)");
  glBegin(GL_TRIANGLES);
  glBlendColor(0.1f, 0.1f, 0.1f, 0.1f);
  glEnd();
  record_error("glBlendColor in glBegin");
  glBegin(GL_TRIANGLES);
  glBlendEquation(GL_FUNC_ADD);
  glEnd();
  record_error("glBlendEquation in glBegin");
  glBegin(GL_TRIANGLES);
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  glEnd();
  record_error("glBlendFuncSeparate in glBegin");
  blend_state("after the errors");

  /* The colour-buffer group keeps all of it. */
  glEnable(GL_BLEND);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glDisable(GL_BLEND);
  glBlendFuncSeparate(GL_ZERO, GL_ONE, GL_ONE, GL_ZERO);
  glBlendEquation(GL_MAX);
  glBlendColor(0.0f, 0.0f, 0.0f, 0.0f);
  blend_state("pushed, changed");
  glPopAttrib();
  blend_state("popped");
  glPushAttrib(GL_ENABLE_BIT);
  glBlendEquation(GL_FUNC_SUBTRACT);
  glPopAttrib();
  blend_state("GL_ENABLE_BIT leaves the equation");

  /* Display lists: compiled, not executed; then executed by glCallList. */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBlendColor(0.125f, 0.375f, 0.625f, 0.875f);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glBlendEquation(0x4321);
  glEndList();
  blend_state("list compiled");
  glCallList(list);
  blend_state("list called");
  glDeleteLists(list, 1);
  glDisable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ZERO);
  glBlendEquation(GL_FUNC_ADD);
  glBlendColor(0, 0, 0, 0);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 600, 300)) return 1;
  conf = &c;
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glShadeModel(GL_SMOOTH);
  glBlendColor(0.3f, 0.55f, 0.8f, 0.35f);
  for (int e = 0; e < 5; ++e) {
    panel(&c, e % COLS, e / COLS);
    equation_panel(e);
  }
  panel(&c, 1, 1);
  separate_panel();
  panel(&c, 2, 1);
  constant_panel();
  blend_values();
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
