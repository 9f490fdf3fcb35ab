/* glCopyPixels (GL 1.1 section 4.3.3): a lit scene copied as colour (to the side, onto itself
 * overlapping in every direction, zoomed, negatively zoomed), through scale and bias and the R
 * and G colour maps, with blending and the depth test on the copies; depth copied (the raster
 * colour drawn, tested with geometry after) and stencil copied (shown through the stencil test,
 * zoomed); sources crossing the window's edge (only the pixels inside are copied); the error
 * codes of wrong calls (a strip of pixels at the top).
 *
 * Left out, where Mesa departs from the specification: depth scale and bias and the index
 * transfer operations on depth and stencil copies (Mesa ignores them), the B and A colour
 * maps (Mesa's give other values: a colour mask keeps B and A while maps apply), fog; zooms
 * that put pixel centres exactly on the boundary of two zoomed pixels (llvmpipe's interpolation
 * picks either: the zooms here are multiples of 1/5). */
#include "conf.h"

enum { kW = 256, kH = 256 };

static void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_TRIANGLES);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

static void ortho(void) {
  glViewport(0, 0, kW, kH);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* A lit sphere and a smooth triangle in the 64 x 64 square at (0, 0), depth and stencil too. */
static void scene(void) {
  glViewport(0, 0, 64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat dir[4] = {-0.4f, 0.5f, 1.0f, 0.0f}, dif[4] = {0.9f, 0.6f, 0.3f, 0.7f};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
  conf_sphere(0.7f, 24, 12);
  glDisable(GL_LIGHTING);
  glBegin(GL_TRIANGLES);
  glColor4f(1, 0, 0, 1);
  glVertex3f(-1.0f, -1.0f, 0.5f);
  glColor4f(0, 1, 0, 0.5f);
  glVertex3f(1.0f, -0.8f, -0.5f);
  glColor4f(0, 0, 1, 0.2f);
  glVertex3f(-0.2f, 0.9f, 0.0f);
  glEnd();
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  ortho();
}

static void colors(void) {
  glRasterPos2i(70, 0);
  glCopyPixels(0, 0, 64, 64, GL_COLOR); /* beside */
  glRasterPos2i(140, 0);
  glCopyPixels(0, 0, 64, 64, GL_COLOR);
  glRasterPos2i(150, 7);
  glCopyPixels(140, 0, 64, 64, GL_COLOR); /* onto itself, up and right */
  glRasterPos2i(70, 70);
  glCopyPixels(0, 0, 64, 64, GL_COLOR);
  glRasterPos2i(66, 62);
  glCopyPixels(70, 70, 64, 64, GL_COLOR); /* down and left */
  glPixelZoom(1.6f, 0.6f);
  glRasterPos2i(140, 80);
  glCopyPixels(0, 0, 64, 64, GL_COLOR);
  glPixelZoom(-1.0f, 1.0f);
  glRasterPos2i(255, 130);
  glCopyPixels(0, 0, 40, 40, GL_COLOR);
  glPixelZoom(-0.6f, -1.4f);
  glRasterPos2i(210, 195);
  glCopyPixels(0, 0, 64, 40, GL_COLOR);
  glPixelZoom(1.0f, 1.0f);
  glRasterPos2i(0, 130);
  glCopyPixels(-20, -10, 50, 40, GL_COLOR); /* across the edges: only what is inside */
}

static void transfer(void) {
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_BIAS, 0.2f);
  glPixelTransferf(GL_BLUE_SCALE, 1.5f);
  glPixelTransferf(GL_ALPHA_BIAS, -0.25f);
  glRasterPos2i(0, 180);
  glCopyPixels(0, 0, 40, 40, GL_COLOR);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glPixelTransferf(GL_GREEN_BIAS, 0.0f);
  glPixelTransferf(GL_BLUE_SCALE, 1.0f);
  glPixelTransferf(GL_ALPHA_BIAS, 0.0f);
  GLfloat r[256];
  for (int i = 0; i < 256; ++i) r[i] = 1.0f - (float)i / 255.0f;
  const GLfloat g[2] = {0.25f, 0.75f}, one[1] = {0.5f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 256, r);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, g);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 1, one);
  glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 1, one);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_FALSE, GL_FALSE); /* Mesa's B and A maps: see above */
  glRasterPos2i(44, 180);
  glCopyPixels(0, 0, 40, 40, GL_COLOR);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
}

static void fragment_ops(void) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glRasterPos2i(90, 150);
  glCopyPixels(0, 0, 40, 40, GL_COLOR);
  glDisable(GL_BLEND);
  glColor3f(0.3f, 0.3f, 0.8f);
  quad(90, 200, 140, 250, 0.0f);
  glEnable(GL_DEPTH_TEST);
  glRasterPos3f(95.0f, 205.0f, 0.5f); /* behind the quad */
  glCopyPixels(0, 0, 20, 20, GL_COLOR);
  glRasterPos3f(118.0f, 205.0f, -0.5f); /* in front */
  glCopyPixels(0, 0, 20, 20, GL_COLOR);
  glDisable(GL_DEPTH_TEST);
}

/* Depth and stencil copies of the scene's buffers. */
static void depth_stencil(void) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glColor3f(0.8f, 0.8f, 0.2f);
  glRasterPos2i(150, 150);
  glCopyPixels(0, 0, 64, 64, GL_DEPTH);
  glDepthFunc(GL_LESS);
  glColor3f(0.1f, 0.7f, 0.7f);
  quad(150, 150, 214, 214, 0.0f); /* window depth 0.5: shows where the copied depth is farther */
  glDisable(GL_DEPTH_TEST);
  glPixelZoom(0.6f, 0.4f);
  glRasterPos2i(220, 220);
  glCopyPixels(0, 0, 64, 64, GL_STENCIL);
  glPixelZoom(1.0f, 1.0f);
  glRasterPos2i(220, 150);
  glCopyPixels(0, 0, 32, 64, GL_STENCIL);
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  for (int v = 0; v < 3; ++v) {
    glStencilFunc(GL_EQUAL, v, 0xff);
    glColor3f(v == 1 ? 1.0f : 0.2f, v == 2 ? 1.0f : 0.2f, v == 0 ? 0.6f : 0.1f);
    quad(218, 148, 254, 254, 0.0f);
  }
  glDisable(GL_STENCIL_TEST);
}

static GLubyte error_code(void) {
  GLenum e = glGetError();
  return (GLubyte)(e == GL_NO_ERROR ? 0 : e - GL_INVALID_ENUM + 1);
}

static void errors(void) {
  GLubyte codes[8];
  int n = 0;
  glRasterPos2i(200, 2);
  glCopyPixels(0, 0, -1, 4, GL_COLOR);
  codes[n++] = error_code();
  glCopyPixels(0, 0, 4, 4, 0x1234);
  codes[n++] = error_code();
  glCopyPixels(0, 0, 4, 4, GL_RGBA);
  codes[n++] = error_code();
  glReadBuffer(GL_NONE);
  glCopyPixels(0, 0, 4, 4, GL_COLOR);
  codes[n++] = error_code();
  glReadBuffer(GL_FRONT);
  glBegin(GL_TRIANGLES);
  glCopyPixels(0, 0, 4, 4, GL_COLOR);
  glEnd();
  codes[n++] = error_code();
  glRasterPos2i(-4, 2); /* invalid: nothing copied */
  glCopyPixels(0, 0, 40, 40, GL_COLOR);
  codes[n++] = error_code();
  GLubyte strip[8 * 4];
  for (int i = 0; i < n; ++i) strip[i * 4] = strip[i * 4 + 1] = strip[i * 4 + 2] = (GLubyte)(codes[i] * 40), strip[i * 4 + 3] = 255;
  glPixelZoom(4.0f, 4.0f);
  glRasterPos2i(4, 240);
  glDrawPixels(n, 1, GL_RGBA, GL_UNSIGNED_BYTE, strip);
  glPixelZoom(1.0f, 1.0f);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, kW, kH)) return 1;
  glClearColor(0.1f, 0.12f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  scene();
  colors();
  transfer();
  fragment_ops();
  depth_stencil();
  errors();
  return conf_finish(&c);
}
