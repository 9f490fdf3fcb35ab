/* GL 1.4's glWindowPos (GL 1.5 section 2.12): the raster position set in window coordinates,
 * whatever the matrices, the viewport and the lighting: glBitmap glyphs and glDrawPixels
 * images placed by every glWindowPos form, z mapped into the depth range against a depth
 * test, positions outside the window (valid, partly drawn), the raster colour from the current
 * colour (clamped, never lit), the raster texture coordinates without the texture matrix
 * (a textured glDrawPixels), the raster secondary colour from the current one (GL_COLOR_SUM)
 * and the raster distance from the current fog coordinate (GL_FOG_COORD_SRC), in display
 * lists; then every GL_CURRENT_RASTER_* value after each
 * form compared with Mesa's, and the errors. */
#define GL_GLEXT_PROTOTYPES
#include <string.h>

#include "conf.h"

static GLubyte glyph[16 * 2];
static GLubyte image[12][20][4];

static void record_raster(ConfContext* c, const char* when) {
  char label[128];
  GLfloat v[4];
  GLdouble d[4];
  GLboolean valid;
  glGetFloatv(GL_CURRENT_RASTER_POSITION, v);
  for (int k = 0; k < 4; ++k) d[k] = v[k];
  snprintf(label, sizeof label, "%s position", when);
  conf_values(c, label, d, 4);
  glGetDoublev(GL_CURRENT_RASTER_POSITION, d);
  snprintf(label, sizeof label, "%s position double", when);
  conf_values(c, label, d, 4);
  glGetFloatv(GL_CURRENT_RASTER_COLOR, v);
  for (int k = 0; k < 4; ++k) d[k] = v[k];
  snprintf(label, sizeof label, "%s color", when);
  conf_values(c, label, d, 4);
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, v);
  for (int k = 0; k < 4; ++k) d[k] = v[k];
  snprintf(label, sizeof label, "%s texcoords", when);
  conf_values(c, label, d, 4);
  glGetFloatv(0x845F /* GL_CURRENT_RASTER_SECONDARY_COLOR */, v);
  for (int k = 0; k < 4; ++k) d[k] = v[k];
  snprintf(label, sizeof label, "%s secondary color", when);
  conf_values(c, label, d, 4);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, v);
  snprintf(label, sizeof label, "%s distance", when);
  conf_value(c, label, v[0]);
  glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  snprintf(label, sizeof label, "%s valid", when);
  conf_value(c, label, valid);
  snprintf(label, sizeof label, "%s error", when);
  conf_error(c, label);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  for (int y = 0; y < 16; ++y) glyph[2 * y] = (GLubyte)(0xff >> (y % 8)), glyph[2 * y + 1] = (GLubyte)(0x0f << (y % 4));
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 20; ++x) {
      image[y][x][0] = (GLubyte)(12 * x), image[y][x][1] = (GLubyte)(20 * y), image[y][x][2] = 200, image[y][x][3] = 255;
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glClearColor(0.05f, 0.05f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  record_raster(&c, "initial");

  /* Matrices, viewport and lighting that glRasterPos would use: glWindowPos ignores them. */
  glViewport(30, 40, 100, 80);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(5, 5, -20);
  glMatrixMode(GL_TEXTURE);
  glScalef(2, 3, 4);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);

  const GLshort sv[3] = {10, 200, 0};
  const GLint iv[3] = {40, 200, 0};
  const GLfloat fv[3] = {70.5f, 200.25f, 0.5f};
  const GLdouble dv[3] = {100.75f, 200.5f, 1.0};
  glColor4f(1.0f, 0.5f, 0.25f, 1.0f);
  glTexCoord4f(0.5f, 0.25f, 2.0f, 1.0f);
  glWindowPos2s(10, 230), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "2s");
  glWindowPos2i(40, 230), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "2i");
  glWindowPos2f(70.5f, 230.5f), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "2f");
  glWindowPos2d(100.25, 230.75), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "2d");
  glColor4f(0.2f, 1.0f, 0.4f, 1.0f);
  glWindowPos3s(130, 230, 0), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "3s");
  glWindowPos3i(160, 230, 1), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "3i");
  glWindowPos3f(190.5f, 230, 0.25f), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "3f");
  glWindowPos3d(220, 230.5, 0.75), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "3d");
  glColor4f(1.5f, -0.5f, 0.5f, 2.0f);  /* clamped into the raster colour */
  glWindowPos2sv(sv), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "2sv");
  glWindowPos2iv(iv), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "2iv");
  glWindowPos2fv(fv), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "2fv");
  glWindowPos2dv(dv), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "2dv");
  glColor3f(0.6f, 0.6f, 1.0f);
  glWindowPos3sv(sv), glBitmap(16, 16, 0, 0, 30, 0, glyph), record_raster(&c, "3sv");
  glWindowPos3iv(iv), glBitmap(16, 16, 0, 0, 30, 0, glyph), record_raster(&c, "3iv");
  glWindowPos3fv(fv), glBitmap(16, 16, 0, 0, 30, 0, glyph), record_raster(&c, "3fv");
  glWindowPos3dv(dv), glBitmap(16, 16, 0, 0, 30, 0, glyph), record_raster(&c, "3dv");
  glDisable(GL_LIGHTING);

  /* Depth: images at z 0.2 and 0.8 in a depth range of [0.25, 0.75], crossing a depth test. */
  glDepthRange(0.25, 0.75);
  glEnable(GL_DEPTH_TEST);
  glWindowPos3f(20, 120, 0.8f), glDrawPixels(20, 12, GL_RGBA, GL_UNSIGNED_BYTE, image), record_raster(&c, "depth far");
  glWindowPos3f(30, 125, 0.2f), glDrawPixels(20, 12, GL_RGBA, GL_UNSIGNED_BYTE, image), record_raster(&c, "depth near");
  glWindowPos3f(40, 130, 0.5f), glDrawPixels(20, 12, GL_RGBA, GL_UNSIGNED_BYTE, image), record_raster(&c, "depth mid");
  glWindowPos3f(50, 110, -3.0f), record_raster(&c, "depth below 0");
  glWindowPos3f(50, 110, 7.0f), record_raster(&c, "depth above 1");
  glDisable(GL_DEPTH_TEST);
  glDepthRange(0, 1);

  /* Outside the window: still valid; the part inside is drawn. */
  glPixelZoom(2.0f, 2.0f);
  glWindowPos2i(-10, 150), glDrawPixels(20, 12, GL_RGBA, GL_UNSIGNED_BYTE, image), record_raster(&c, "left of window");
  glWindowPos2i(240, -8), glDrawPixels(20, 12, GL_RGBA, GL_UNSIGNED_BYTE, image), record_raster(&c, "below window");
  glPixelZoom(1.0f, 1.0f);
  glWindowPos2i(-1000, 5000), record_raster(&c, "far away");

  /* glDrawPixels textured with the raster texture coordinates (no texture matrix). */
  GLubyte texels[4][4][4];
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      texels[y][x][0] = (GLubyte)(60 * x), texels[y][x][1] = (GLubyte)(60 * y), texels[y][x][2] = 90, texels[y][x][3] = 255;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glEnable(GL_TEXTURE_2D);
  glTexCoord2f(0.6f, 0.1f);
  glWindowPos2i(100, 60), glDrawPixels(20, 12, GL_RGBA, GL_UNSIGNED_BYTE, image), record_raster(&c, "textured");
  glTexCoord2f(0.1f, 0.9f);
  glWindowPos2i(130, 60), glDrawPixels(20, 12, GL_RGBA, GL_UNSIGNED_BYTE, image), record_raster(&c, "textured 2");
  glDisable(GL_TEXTURE_2D);

  /* The secondary colour (clamped) summed into glyphs, and fog by the current fog coordinate
   * against fog by the (zero) distance of the other source. */
  glSecondaryColor3f(0.5f, -0.25f, 1.5f);
  glColor3f(0.25f, 0.5f, 0.0f);
  glEnable(GL_COLOR_SUM);
  glWindowPos2i(10, 90), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "secondary");
  glDisable(GL_COLOR_SUM);
  glSecondaryColor3f(0.0f, 0.0f, 0.0f);
  glColor3f(1.0f, 1.0f, 1.0f);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 10.0f);
  const GLfloat fog_color[4] = {0.0f, 0.0f, 1.0f, 1.0f};
  glFogfv(GL_FOG_COLOR, fog_color);
  glEnable(GL_FOG);
  glFogCoordf(7.5f);
  glWindowPos2i(40, 90), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "fog by depth");
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glWindowPos2i(70, 90), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "fog coordinate");
  glFogCoordf(2.5f);
  glWindowPos2i(100, 90), glBitmap(16, 16, 0, 0, 0, 0, glyph), record_raster(&c, "fog coordinate 2");
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glDisable(GL_FOG);

  /* In a display list. */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glWindowPos2f(160, 60);
  glDrawPixels(20, 12, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glWindowPos3fv(fv);
  glEndList();
  glColor3f(1, 1, 0);
  glWindowPos2i(0, 0);
  record_raster(&c, "list compiled");
  glCallList(list);
  record_raster(&c, "list called");
  glBitmap(16, 16, 0, 0, 0, 0, glyph);

  glBegin(GL_POINTS);
  glWindowPos2i(5, 5);
  glEnd();
  conf_error(&c, "WindowPos2i in glBegin");
  record_raster(&c, "after glBegin");
  glViewport(0, 0, 256, 256);
  glLoadIdentity();
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  return conf_finish(&c);
}
