/* EXT_blend_equation_separate: glBlendEquationSeparateEXT blends the colour by one equation and
 * alpha by another. The first panel: cell (column r, row a) blends with colour equation r and
 * alpha equation a of the five (GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT,
 * GL_MIN, GL_MAX), colour factors (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) and alpha factors
 * (GL_ONE, GL_ONE); the destination's colour and alpha vary from left to right, the source's
 * from bottom to top. Alpha is stored in the framebuffer (the PNG keeps it) and compared too.
 * The second panel shows alpha itself: the same cells, then alpha copied into the colour by a
 * second blend (GL_DST_ALPHA, GL_ZERO over white). The last panel draws the values recorded
 * (conf_value): GL_BLEND_EQUATION_RGB_EXT and GL_BLEND_EQUATION_ALPHA_EXT after
 * glBlendEquationSeparateEXT and glBlendEquation (which sets both), their errors (an unknown
 * enum on either side sets neither; inside glBegin/glEnd), glPushAttrib(GL_COLOR_BUFFER_BIT),
 * display lists, and the extension in GL_EXTENSIONS. */
#define GL_GLEXT_PROTOTYPES 1
#include <stdio.h>
#include <string.h>

#include "conf.h"

#ifndef GL_BLEND_EQUATION_RGB_EXT
#define GL_BLEND_EQUATION_RGB_EXT 0x8009
#endif
#ifndef GL_BLEND_EQUATION_ALPHA_EXT
#define GL_BLEND_EQUATION_ALPHA_EXT 0x883D
#endif
/* Mesa's libOSMesa exports no EXT entry point of this extension: through OSMesaGetProcAddress,
 * as programs reach extensions. */
typedef void(APIENTRY* BlendEquationSeparateProc)(GLenum modeRGB, GLenum modeAlpha);
static BlendEquationSeparateProc glBlendEquationSeparateEXT_;
#define glBlendEquationSeparateEXT glBlendEquationSeparateEXT_

#define COLS 3
#define ROWS 1
#define N 5

static const GLenum kEquations[N] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};

static void panel(const ConfContext* c, int col) {
  conf_panel(c, col, 0, COLS, ROWS);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, N, 0.0, N, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void quad(float x0, float y0, float x1, float y1) {
  glBegin(GL_QUADS);
  glVertex2f(x0, y0), glVertex2f(x1, y0), glVertex2f(x1, y1), glVertex2f(x0, y1);
  glEnd();
}

/* Cell (x, y): the destination drawn without blending, the source blended over it. */
static void cell(int x, int y) {
  const float x0 = (float)x + 0.04f, x1 = (float)x + 0.96f, y0 = (float)y + 0.04f, y1 = (float)y + 0.96f;
  glDisable(GL_BLEND);
  glBegin(GL_QUADS);
  glColor4f(0.2f, 0.6f, 0.9f, 0.85f);
  glVertex2f(x0, y0);
  glColor4f(0.9f, 0.35f, 0.1f, 0.1f);
  glVertex2f(x1, y0);
  glVertex2f(x1, y1);
  glColor4f(0.2f, 0.6f, 0.9f, 0.85f);
  glVertex2f(x0, y1);
  glEnd();
  glEnable(GL_BLEND);
  glBegin(GL_QUADS);
  glColor4f(0.85f, 0.45f, 0.3f, 0.9f);
  glVertex2f(x0 + 0.1f, y0 + 0.1f);
  glVertex2f(x1 - 0.1f, y0 + 0.1f);
  glColor4f(0.1f, 0.7f, 0.5f, 0.2f);
  glVertex2f(x1 - 0.1f, y1 - 0.1f);
  glVertex2f(x0 + 0.1f, y1 - 0.1f);
  glEnd();
}

static void equation_cells(void) {
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE);
  for (int r = 0; r < N; ++r) {
    for (int a = 0; a < N; ++a) {
      glBlendEquationSeparateEXT(kEquations[r], kEquations[a]);
      cell(r, a);
    }
  }
  glBlendEquation(GL_FUNC_ADD);
  glDisable(GL_BLEND);
}

/* ---- values ---- */
enum { kCols = 8, kRows = 6, kCells = kCols * kRows };
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

static void equations(const char* when) {
  char name[96];
  GLint rgb = 0, alpha = 0, plain = 0;
  glGetIntegerv(GL_BLEND_EQUATION_RGB_EXT, &rgb);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA_EXT, &alpha);
  glGetIntegerv(GL_BLEND_EQUATION, &plain);
  snprintf(name, sizeof name, "%s rgb", when);
  record(name, (double)rgb);
  snprintf(name, sizeof name, "%s alpha", when);
  record(name, (double)alpha);
  snprintf(name, sizeof name, "%s GL_BLEND_EQUATION", when);
  record(name, (double)plain);
}

static void blend_values(void) {
  const char* extensions = (const char*)glGetString(GL_EXTENSIONS);
  record("GL_EXT_blend_equation_separate listed", extensions && strstr(extensions, "GL_EXT_blend_equation_separate ") ? 1 : 0);
  equations("initial");
  glBlendEquationSeparateEXT(GL_FUNC_REVERSE_SUBTRACT, GL_MAX);
  equations("separate");
  record("error after valid calls", (double)glGetError());
  glBlendEquationSeparateEXT(GL_FUNC_ADD, GL_SRC_ALPHA);
  record("error alpha GL_SRC_ALPHA", (double)glGetError());
  glBlendEquationSeparateEXT(GL_ZERO, GL_MIN);
  record("error rgb GL_ZERO", (double)glGetError());
  equations("after errors");
  glBegin(GL_POINTS);
  glBlendEquationSeparateEXT(GL_MIN, GL_MIN);
  glEnd();
  record("error inside begin/end", (double)glGetError());
  equations("after begin/end");
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glBlendEquation(GL_FUNC_SUBTRACT);
  equations("glBlendEquation sets both");
  glPopAttrib();
  equations("popped");
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBlendEquationSeparateEXT(GL_MIN, GL_FUNC_SUBTRACT);
  glEndList();
  equations("compiled");
  glCallList(list);
  equations("called");
  glDeleteLists(list, 1);
  glBlendEquation(GL_FUNC_ADD);
  record("error at the end", (double)glGetError());
}

/* The values as cells: each a colour made of the value's low bits. */
static void draw_values(void) {
  glDisable(GL_BLEND);
  for (int i = 0; i < n_values && i < kCells; ++i) {
    const unsigned v = values[i];
    const float x = (float)(i % kCols) * (float)N / kCols, y = (float)(i / kCols) * (float)N / kRows;
    glColor4f((float)(v & 0xff) / 255.0f, (float)((v >> 8) & 0xff) / 255.0f, (float)((v >> 4) & 0xff) / 255.0f, 1.0f);
    quad(x + 0.03f, y + 0.03f, x + (float)N / kCols - 0.03f, y + (float)N / kRows - 0.03f);
  }
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 480, 160)) return 1;
  conf = &c;
  glBlendEquationSeparateEXT_ = (BlendEquationSeparateProc)OSMesaGetProcAddress("glBlendEquationSeparateEXT");
  if (!glBlendEquationSeparateEXT_) {
    fprintf(stderr, "blend_equation_separate: no glBlendEquationSeparateEXT\n");
    return 1;
  }
  glClearColor(0.05f, 0.05f, 0.1f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT);

  panel(&c, 0);
  equation_cells();

  /* Alpha made visible: the cells again, then each pixel's colour replaced by its alpha
   * (white times the destination's alpha, alpha kept). */
  panel(&c, 1);
  equation_cells();
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_DST_ALPHA, GL_ZERO, GL_ZERO, GL_ONE);
  glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
  quad(0.0f, 0.0f, (float)N, (float)N);
  glDisable(GL_BLEND);

  blend_values();
  panel(&c, 2);
  draw_values();
  return conf_finish(&c);
}
