/* glBlendFunc with every OpenGL 1.1 factor: the 9 source factors (columns: ZERO, ONE,
 * DST_COLOR, ONE_MINUS_DST_COLOR, SRC_ALPHA, ONE_MINUS_SRC_ALPHA, DST_ALPHA,
 * ONE_MINUS_DST_ALPHA, SRC_ALPHA_SATURATE) against the 8 destination factors (rows: ZERO, ONE,
 * SRC_COLOR, ONE_MINUS_SRC_COLOR, SRC_ALPHA, ONE_MINUS_SRC_ALPHA, DST_ALPHA,
 * ONE_MINUS_DST_ALPHA). In each cell the destination is a quad drawn without blending whose
 * colour and alpha vary from left to right; the source quad's colour and alpha vary from bottom
 * to top. Alpha is stored in the framebuffer (the PNG keeps it) and compared too. */
#include "conf.h"

static const GLenum kSrc[9] = {GL_ZERO,          GL_ONE,
                               GL_DST_COLOR,     GL_ONE_MINUS_DST_COLOR,
                               GL_SRC_ALPHA,     GL_ONE_MINUS_SRC_ALPHA,
                               GL_DST_ALPHA,     GL_ONE_MINUS_DST_ALPHA,
                               GL_SRC_ALPHA_SATURATE};
static const GLenum kDst[8] = {GL_ZERO,      GL_ONE,           GL_SRC_COLOR,
                               GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA,
                               GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA};

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 252, 256)) return 1;
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glShadeModel(GL_SMOOTH);
  for (int row = 0; row < 8; ++row) {
    for (int col = 0; col < 9; ++col) {
      conf_panel(&c, col, row, 9, 8);
      glDisable(GL_BLEND);
      glBegin(GL_QUADS); /* destination: left to right */
      glColor4f(0.2f, 0.6f, 0.9f, 0.8f);
      glVertex2f(0, 0);
      glColor4f(0.9f, 0.35f, 0.1f, 0.15f);
      glVertex2f(1, 0);
      glVertex2f(1, 1);
      glColor4f(0.2f, 0.6f, 0.9f, 0.8f);
      glVertex2f(0, 1);
      glEnd();
      glBlendFunc(kSrc[col], kDst[row]);
      glEnable(GL_BLEND);
      glBegin(GL_QUADS); /* source: bottom to top, inset */
      glColor4f(0.85f, 0.45f, 0.3f, 0.9f);
      glVertex2f(0.1f, 0.1f);
      glVertex2f(0.9f, 0.1f);
      glColor4f(0.1f, 0.9f, 0.55f, 0.25f);
      glVertex2f(0.9f, 0.9f);
      glVertex2f(0.1f, 0.9f);
      glEnd();
    }
  }
  glDisable(GL_BLEND);
  return conf_finish(&c);
}
