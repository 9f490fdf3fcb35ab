/* The stencil buffer: glClearStencil, glStencilOp with every operation (KEEP, ZERO, REPLACE,
 * INCR and DECR with their saturation, INVERT) for stencil-fail, depth-fail and depth-pass,
 * glStencilMask (a write mask), and glStencilFunc with all eight functions and a compare mask.
 * Cells of the top two rows write stencil values with colour writes off, then show them: bit b
 * of the stored value adds 2^b / 255 to red and 2^(7 - b) / 255 to green (eight GL_EQUAL passes
 * with mask 1 << b, additive blending), so the colour encodes the exact value. The bottom row
 * draws coloured bands with each stencil function against a striped pattern. */
#include "conf.h"

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 3);
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
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  for (int b = 0; b < 8; ++b) {
    glStencilFunc(GL_EQUAL, 1 << b, 1u << b);
    float level = (float)(32 << (b % 3)) / 255.0f; /* bits 0-2: red, 3-5: green, 6-7: blue */
    glColor4f(b < 3 ? level : 0.0f, b >= 3 && b < 6 ? level : 0.0f,
              b >= 6 ? (float)(64 << (b - 6)) / 255.0f : 0.0f, 0.0f);
    rect(0, 0, 1, 1, 0);
  }
  glDisable(GL_BLEND);
}

static void write_mode(void) {
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 252)) return 1;
  glClearColor(0, 0, 0, 1);
  glClearStencil(0x10);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);

  cell(&c, 0, 0); /* INCR three times over the cleared 0x10 */
  write_mode();
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  overlaps();
  show_values();

  cell(&c, 1, 0); /* REPLACE with 1, then DECR three times: saturates at 0 */
  write_mode();
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  rect(0.1f, 0.1f, 0.9f, 0.9f, 0);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_DECR);
  overlaps();
  show_values();

  cell(&c, 2, 0); /* REPLACE with 0xfe, INCR three times: saturates at 0xff */
  write_mode();
  glStencilFunc(GL_ALWAYS, 0xfe, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  rect(0.0f, 0.5f, 1.0f, 1.0f, 0);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  overlaps();
  show_values();

  cell(&c, 3, 0); /* INVERT (odd covers flip all bits), then ZERO on a band */
  write_mode();
  glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
  overlaps();
  glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
  rect(0.0f, 0.0f, 1.0f, 0.2f, 0);
  show_values();

  cell(&c, 0, 1); /* glStencilMask(0x0f): REPLACE with 0xab keeps the high bits 0x10 */
  write_mode();
  glStencilMask(0x0f);
  glStencilFunc(GL_ALWAYS, 0xab, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  rect(0.1f, 0.1f, 0.7f, 0.7f, 0);
  glStencilMask(0xff);
  show_values();

  cell(&c, 1, 1); /* depth fail and depth pass: INCR where the depth test fails, REPLACE (0x40)
                     where it passes */
  write_mode();
  glEnable(GL_DEPTH_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  rect(0.0f, 0.0f, 0.6f, 1.0f, 0.5f); /* a near occluder (depth only) */
  glStencilFunc(GL_ALWAYS, 0x40, 0xff);
  glStencilOp(GL_KEEP, GL_INCR, GL_REPLACE);
  rect(0.2f, 0.2f, 0.95f, 0.8f, 0.0f);
  show_values();

  cell(&c, 2, 1); /* stencil fail: the test passes only where the value & 0x0f equals 0 */
  write_mode();
  glStencilFunc(GL_ALWAYS, 0x03, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  rect(0.0f, 0.0f, 0.5f, 1.0f, 0);
  glStencilFunc(GL_EQUAL, 0x00, 0x0f); /* 0x10 passes, 0x03 fails */
  glStencilOp(GL_INVERT, GL_KEEP, GL_INCR);
  rect(0.25f, 0.25f, 0.75f, 0.75f, 0);
  show_values();

  cell(&c, 3, 1); /* KEEP on pass, ZERO on stencil fail */
  write_mode();
  glStencilFunc(GL_NOTEQUAL, 0x10, 0xff); /* fails everywhere */
  glStencilOp(GL_ZERO, GL_KEEP, GL_KEEP);
  overlaps();
  show_values();

  /* Bottom row: stripes of values 0, 1, 2, 3 (vertical), then one band per function with
   * reference 2 and mask 0x03, coloured where the test passes. */
  static const GLenum funcs[8] = {GL_NEVER,   GL_LESS,     GL_LEQUAL, GL_GREATER,
                                  GL_GEQUAL,  GL_EQUAL,    GL_NOTEQUAL, GL_ALWAYS};
  for (int half = 0; half < 2; ++half) {
    cell(&c, half * 2, 2);
    glViewport(half * 128, 0, 128, 84);
    write_mode();
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    for (int v = 0; v < 4; ++v) {
      glStencilFunc(GL_ALWAYS, v | 0x10, 0xff);
      rect(0.25f * v, 0.0f, 0.25f * (v + 1), 1.0f, 0);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    for (int k = 0; k < 4; ++k) {
      int f = half * 4 + k;
      glStencilFunc(funcs[f], 2, 0x03);
      glColor3f(0.3f + 0.1f * f, 1.0f - 0.1f * f, 0.2f + 0.1f * (f % 3));
      rect(0.02f, 0.75f - 0.25f * k + 0.02f, 0.98f, 1.0f - 0.25f * k - 0.02f, 0);
    }
  }
  glDisable(GL_STENCIL_TEST);
  return conf_finish(&c);
}
