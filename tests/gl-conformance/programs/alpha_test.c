/* The alpha test (GL 1.1 section 4.1.3). Top two rows: the eight functions (GL_NEVER ..
 * GL_ALWAYS) with reference 0.5 on a quad whose alpha runs from 0 to 1 left to right (with
 * depth writes), then a quad behind it drawn with GL_LESS: it shows wherever the alpha test
 * kept no fragment, since rejected fragments write no depth. Bottom row: textured cut-outs
 * (an RGBA texture's round alpha, GL_GREATER 0.5) overlapping in perspective with depth; a lit
 * sphere whose alpha comes from its material and a modulated texture (GL_GEQUAL 0.6); the
 * alpha test with blending (GL_LESS 0.7); the alpha test before the stencil test (stencil
 * incremented only by kept fragments, then shown). */
#include <math.h>

#include "conf.h"

static const GLenum kFuncs[8] = {GL_NEVER, GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                                 GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};

static GLuint make_cutout(void) {
  static unsigned char texels[32 * 32 * 4];
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      unsigned char* t = &texels[(y * 32 + x) * 4];
      float dx = (float)x - 15.5f, dy = (float)y - 15.5f, r = sqrtf(dx * dx + dy * dy);
      float a = r < 11.0f ? 1.0f : r > 15.0f ? 0.0f : (15.0f - r) / 4.0f;
      t[0] = (unsigned char)(60 + 6 * x);
      t[1] = (unsigned char)(220 - 5 * y);
      t[2] = (unsigned char)((x / 4 + y / 4) % 2 ? 200 : 40);
      t[3] = (unsigned char)(255.0f * a + 0.5f);
    }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  return tex;
}

static void ortho(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void function_panel(GLenum func) {
  ortho();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(func, 0.5f);
  glBegin(GL_QUADS); /* alpha 0 -> 1 left to right, over 255 columns' worth of steps */
  glColor4f(0.9f, 0.3f, 0.2f, 0.0f);
  glVertex3f(0.05f, 0.1f, 0.0f);
  glColor4f(0.2f, 0.4f, 0.9f, 1.0f);
  glVertex3f(0.95f, 0.1f, 0.0f);
  glVertex3f(0.95f, 0.9f, 0.0f);
  glColor4f(0.9f, 0.3f, 0.2f, 0.0f);
  glVertex3f(0.05f, 0.9f, 0.0f);
  glEnd();
  glDisable(GL_ALPHA_TEST);
  glColor4f(0.9f, 0.9f, 0.3f, 1.0f); /* behind (z_eye -0.5): seen where no depth was written */
  glBegin(GL_QUADS);
  glVertex3f(0.0f, 0.3f, -0.5f);
  glVertex3f(1.0f, 0.3f, -0.5f);
  glVertex3f(1.0f, 0.7f, -0.5f);
  glVertex3f(0.0f, 0.7f, -0.5f);
  glEnd();
  glDisable(GL_DEPTH_TEST);
}

static void cutout(float x, float y, float z, float size) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0); glVertex3f(x - size, y - size, z);
  glTexCoord2f(1, 0); glVertex3f(x + size, y - size, z);
  glTexCoord2f(1, 1); glVertex3f(x + size, y + size, z);
  glTexCoord2f(0, 1); glVertex3f(x - size, y + size, z);
  glEnd();
}

static void cutouts(GLuint tex) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glBindTexture(GL_TEXTURE_2D, tex);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  cutout(0.0f, 0.0f, -3.0f, 0.8f); /* near first: the far ones must not show through */
  cutout(0.9f, 0.4f, -5.0f, 1.2f);
  cutout(-0.8f, -0.5f, -4.0f, 1.0f);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor4f(1.0f, 0.5f, 0.5f, 0.9f); /* alpha 0.9 x texture: a smaller disc */
  cutout(0.2f, -1.2f, -6.0f, 1.6f);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_DEPTH_TEST);
}

static void lit_sphere(GLuint tex) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.2, 1.2, -1.2, 1.2, -2.0, 2.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat dir[4] = {0.3f, 0.5f, 0.8f, 0.0f};
  const GLfloat diffuse[4] = {0.9f, 0.8f, 0.6f, 0.85f};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diffuse);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GEQUAL, 0.6f);
  glBindTexture(GL_TEXTURE_2D, tex);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glRotatef(20.0f, 1, 0, 0);
  conf_sphere(1.0f, 28, 16);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
}

static void blended(void) {
  ortho();
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_LESS, 0.7f);
  for (int i = 0; i < 3; ++i) {
    float x = 0.1f + 0.25f * (float)i;
    glBegin(GL_TRIANGLES);
    glColor4f(1.0f, 0.2f * (float)i, 0.3f, 0.1f);
    glVertex2f(x, 0.1f);
    glColor4f(0.2f, 0.9f, 0.4f, 1.0f);
    glVertex2f(x + 0.5f, 0.2f);
    glColor4f(0.3f, 0.3f, 1.0f, 0.6f);
    glVertex2f(x + 0.1f, 0.9f);
    glEnd();
  }
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_BLEND);
}

static void stencil_after_alpha(void) {
  ortho();
  glClearStencil(0);
  glEnable(GL_SCISSOR_TEST);
  GLint vp[4];
  glGetIntegerv(GL_VIEWPORT, vp);
  glScissor(vp[0], vp[1], vp[2], vp[3]);
  glClear(GL_STENCIL_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.4f);
  for (int i = 0; i < 3; ++i) { /* overlapping quads, alpha rising left to right */
    float y = 0.1f + 0.2f * (float)i;
    glBegin(GL_QUADS);
    glColor4f(0.5f, 0.5f, 0.5f, 0.0f);
    glVertex2f(0.0f, y);
    glColor4f(0.5f, 0.5f, 0.5f, 1.0f);
    glVertex2f(1.0f, y);
    glVertex2f(1.0f, y + 0.5f);
    glColor4f(0.5f, 0.5f, 0.5f, 0.0f);
    glVertex2f(0.0f, y + 0.5f);
    glEnd();
  }
  glDisable(GL_ALPHA_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  const float colors[4][3] = {{0.1f, 0.1f, 0.1f}, {0.9f, 0.2f, 0.2f}, {0.2f, 0.9f, 0.2f}, {0.2f, 0.2f, 0.9f}};
  for (int k = 1; k < 4; ++k) { /* each stencil count in its colour */
    glStencilFunc(GL_EQUAL, k, 0xff);
    glColor3fv(colors[k]);
    glRectf(0.0f, 0.0f, 1.0f, 1.0f);
  }
  glDisable(GL_STENCIL_TEST);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 400, 300)) return 1;
  GLuint tex = make_cutout();
  glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  for (int i = 0; i < 8; ++i) {
    conf_panel(&c, i % 4, i / 4, 4, 3);
    function_panel(kFuncs[i]);
  }
  conf_panel(&c, 0, 2, 4, 3);
  cutouts(tex);
  conf_panel(&c, 1, 2, 4, 3);
  lit_sphere(tex);
  conf_panel(&c, 2, 2, 4, 3);
  blended();
  conf_panel(&c, 3, 2, 4, 3);
  stencil_after_alpha();
  return conf_finish(&c);
}
