/* Logic ops on an RGBA buffer (GL 1.1 section 4.1.7): the sixteen operations, GL_CLEAR ..
 * GL_SET, one per panel of a 4 x 4 grid. Each panel holds a pattern of coloured stripes with
 * alpha drawn normally, then, with GL_COLOR_LOGIC_OP, a quad whose colour and alpha vary
 * smoothly across it and a flat one. Blending is enabled too and must be ignored (the logic op
 * replaces it); the colour mask applies after the op (green masked in the last row's flat
 * quads). GL 1.1's GL_LOGIC_OP names the colour-index logic op: enabled alone, it changes
 * nothing in RGBA (a strip along each panel's top). */
#include "conf.h"

static void ortho(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void stripes(void) {
  static const float kColors[6][4] = {{1.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.5f, 0.5f}, {0.2f, 0.4f, 1.0f, 0.8f},
                                      {1.0f, 1.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 0.0f, 1.0f}, {0.6f, 0.3f, 0.8f, 0.3f}};
  for (int i = 0; i < 6; ++i) {
    glColor4fv(kColors[i]);
    glRectf((float)i / 6.0f, 0.0f, (float)(i + 1) / 6.0f, 1.0f);
  }
}

static void panel(GLenum op, int masked) {
  ortho();
  glDisable(GL_COLOR_LOGIC_OP);
  glDisable(GL_BLEND);
  stripes();
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(op);
  glBegin(GL_QUADS);
  glColor4f(1.0f, 0.3f, 0.0f, 0.2f);
  glVertex2f(0.05f, 0.1f);
  glColor4f(0.0f, 0.8f, 1.0f, 1.0f);
  glVertex2f(0.95f, 0.1f);
  glColor4f(0.5f, 0.0f, 0.6f, 0.6f);
  glVertex2f(0.95f, 0.45f);
  glColor4f(0.9f, 0.9f, 0.2f, 0.0f);
  glVertex2f(0.05f, 0.45f);
  glEnd();
  if (masked) glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glColor4f(0.8f, 0.55f, 0.25f, 0.65f);
  glRectf(0.1f, 0.55f, 0.9f, 0.8f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_COLOR_LOGIC_OP);
  glDisable(GL_BLEND);
  glEnable(GL_LOGIC_OP); /* the index logic op: no effect on RGBA */
  glLogicOp(GL_INVERT);
  glColor4f(0.3f, 0.7f, 0.4f, 1.0f);
  glRectf(0.0f, 0.88f, 1.0f, 1.0f);
  glDisable(GL_LOGIC_OP);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 320, 320)) return 1;
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  for (int i = 0; i < 16; ++i) {
    conf_panel(&c, i % 4, i / 4, 4, 4);
    panel((GLenum)(GL_CLEAR + i), i >= 12);
  }
  GLint mode;
  glGetIntegerv(GL_LOGIC_OP_MODE, &mode);
  return mode == GL_INVERT ? conf_finish(&c) : 4;
}
