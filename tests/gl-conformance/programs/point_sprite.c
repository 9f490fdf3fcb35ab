/* ARB_point_sprite (core in OpenGL 2.0): with GL_POINT_SPRITE_ARB enabled each point is a
 * square of its size (fractional sizes too, smooth points squared), and the texture units with
 * GL_COORD_REPLACE_ARB take (s, t) across it, t from the top. Drawn: sprites of sizes 1.5 to 33
 * at pixel centres and between them, nearest and linear, a replaced unit over a unit that keeps
 * the vertex's coordinates, distance-attenuated sprites under a perspective, smooth points with
 * sprites on, replacement without the enable (none), sprites in a display list. Values: the
 * enable and each unit's replacement through glGet, the attribute stack and errors. */
#define GL_GLEXT_PROTOTYPES 1
#include <stdio.h>
#include <string.h>

#include "conf.h"

#ifndef GL_POINT_SPRITE_ARB
#define GL_POINT_SPRITE_ARB 0x8861
#define GL_COORD_REPLACE_ARB 0x8862
#endif

static void point(float x, float y, float size) {
  glPointSize(size);
  glBegin(GL_POINTS);
  glVertex2f(x, y);
  glEnd();
}

/* Sprites of several sizes. Neither their edges nor their texel boundaries lie on a pixel
 * centre: there shadelab's s and t are exact, llvmpipe's a rounding away (its nearest texel the
 * other one, its repeating wrap at an edge the far texel). */
static void sizes(void) {
  point(6.4f, 6.4f, 1.5f);
  point(14.25f, 6.25f, 4.0f);
  point(26.25f, 8.25f, 8.0f);
  point(46.25f, 12.75f, 16.0f);
  point(20.25f, 40.25f, 32.0f);
  point(50.25f, 44.75f, 12.0f);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0.1f, 0.1f, 0.25f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const char* extensions = (const char*)glGetString(GL_EXTENSIONS);
  conf_value(&c, "GL_ARB_point_sprite listed", strstr(extensions, "GL_ARB_point_sprite ") != NULL);
  conf_value(&c, "enabled at first", glIsEnabled(GL_POINT_SPRITE_ARB));
  GLint n = -1;
  glGetTexEnviv(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, &n);
  conf_value(&c, "coord replace at first", n);

  /* An 8 x 8 texture: a colour ramp along s, a darker band along t, a white corner texel. */
  static unsigned char texels[8 * 8 * 4];
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      unsigned char* p = &texels[(y * 8 + x) * 4];
      p[0] = (unsigned char)(x * 36), p[1] = (unsigned char)(y * 36), p[2] = (unsigned char)((x + y) % 3 ? 60 : 220);
      p[3] = 255;
    }
  }
  texels[0] = texels[1] = texels[2] = 255;
  GLuint tex[2];
  glGenTextures(2, tex);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  /* Row 0: the sizes, nearest; linear; replacement without the enable (the vertex's (0.3, 0.6)). */
  glTexCoord2f(0.3f, 0.6f);
  glEnable(GL_POINT_SPRITE_ARB);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_TRUE);
  conf_error(&c, "TexEnv coord replace");
  conf_pixel_panel(&c, 0, 0, 4, 4);
  sizes();
  conf_pixel_panel(&c, 1, 0, 4, 4);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  sizes();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  conf_pixel_panel(&c, 2, 0, 4, 4);
  glDisable(GL_POINT_SPRITE_ARB);
  sizes();
  /* Sprites on, replacement off: squares of the vertex's texel. */
  conf_pixel_panel(&c, 3, 0, 4, 4);
  glEnable(GL_POINT_SPRITE_ARB);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_FALSE);
  sizes();
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_TRUE);

  /* Row 1: smooth points with sprites on (squares), modulated by a smooth colour; two units,
   * unit 1 replaced and unit 0 not. */
  conf_pixel_panel(&c, 0, 1, 4, 4);
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  sizes();
  glDisable(GL_BLEND);
  glDisable(GL_POINT_SMOOTH);
  conf_pixel_panel(&c, 1, 1, 4, 4);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glPointSize(24.0f);
  glBegin(GL_POINTS);
  glColor3f(1, 0.5f, 0.5f), glVertex2f(16.25f, 16.25f);
  glColor3f(0.5f, 1, 0.5f), glVertex2f(46.25f, 20.25f);
  glColor3f(0.5f, 0.5f, 1), glVertex2f(30.25f, 46.25f);
  glEnd();
  glColor3f(1, 1, 1);
  static unsigned char stripes[4 * 4 * 4];
  for (int i = 0; i < 16; ++i) memset(&stripes[i * 4], (i % 4) < 2 ? 255 : 100, 4);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, stripes);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_TRUE);
  glActiveTexture(GL_TEXTURE0);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_FALSE);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  conf_pixel_panel(&c, 2, 1, 4, 4);
  glMultiTexCoord2f(GL_TEXTURE0, 0.8f, 0.2f);
  sizes();
  glGetTexEnviv(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, &n);
  conf_value(&c, "unit 0 coord replace", n);
  glActiveTexture(GL_TEXTURE1);
  glGetTexEnviv(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, &n);
  conf_value(&c, "unit 1 coord replace", n);
  glDisable(GL_TEXTURE_2D);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_FALSE);
  glActiveTexture(GL_TEXTURE0);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_TRUE);

  /* Distance-attenuated sprites along a receding row, under a perspective. */
  conf_pixel_panel(&c, 3, 1, 4, 4);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -1, 1, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  static const float attenuation[3] = {0.0f, 0.0f, 1.0f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
  glPointSize(40.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 6; ++i) glVertex3f(-0.6f + 0.25f * (float)i, -0.3f + 0.1f * (float)i, -2.0f - 2.5f * (float)i);
  glEnd();
  static const float none[3] = {1.0f, 0.0f, 0.0f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);

  /* Row 2: sprites in a display list (the enable and the replacement compiled too). */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEnable(GL_POINT_SPRITE_ARB);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_TRUE);
  glPointSize(16.0f);
  glBegin(GL_POINTS);
  glVertex2f(12.25f, 12.25f), glVertex2f(32.25f, 32.25f), glVertex2f(52.25f, 14.25f);
  glEnd();
  glEndList();
  glDisable(GL_POINT_SPRITE_ARB);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_FALSE);
  conf_pixel_panel(&c, 0, 2, 4, 4);
  glCallList(list);
  /* A sprite across the viewport's right edge, and a plain wide point there. */
  conf_pixel_panel(&c, 1, 2, 4, 4);
  point(58.25f, 44.25f, 24.0f);
  glDisable(GL_POINT_SPRITE_ARB);
  point(58.25f, 14.25f, 24.0f);
  glEnable(GL_POINT_SPRITE_ARB);
  /* The same under a perspective, across the left and bottom edges. */
  conf_pixel_panel(&c, 2, 2, 4, 4);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -1, 1, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  glPointSize(30.0f);
  glBegin(GL_POINTS);
  glVertex3f(-1.7f, 0.5f, -2.0f);
  glVertex3f(0.3f, -1.8f, -2.0f);
  glEnd();
  glDisable(GL_POINT_SPRITE_ARB);
  glBegin(GL_POINTS);
  glVertex3f(-1.7f, -1.0f, -2.0f);
  glEnd();
  glEnable(GL_POINT_SPRITE_ARB);
  conf_value(&c, "enabled after the list", glIsEnabled(GL_POINT_SPRITE_ARB));

  /* The attribute stack: the point group holds both, the enable group the enable. */
  glPushAttrib(GL_POINT_BIT);
  glDisable(GL_POINT_SPRITE_ARB);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_FALSE);
  glPopAttrib();
  conf_value(&c, "enabled after point pop", glIsEnabled(GL_POINT_SPRITE_ARB));
  glGetTexEnviv(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, &n);
  conf_value(&c, "coord replace after point pop", n);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_POINT_SPRITE_ARB);
  glPopAttrib();
  conf_value(&c, "enabled after enable pop", glIsEnabled(GL_POINT_SPRITE_ARB));
  GLboolean b = GL_FALSE;
  glGetBooleanv(GL_POINT_SPRITE_ARB, &b);
  conf_value(&c, "GetBooleanv", b);

  /* Errors. */
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  conf_error(&c, "TexEnv point sprite mode");
  glTexEnvi(GL_TEXTURE_ENV, GL_COORD_REPLACE_ARB, GL_TRUE);
  conf_error(&c, "TexEnv env coord replace");
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, 2);
  conf_error(&c, "TexEnv coord replace 2");
  glGetTexEnviv(GL_POINT_SPRITE_ARB, GL_TEXTURE_ENV_MODE, &n);
  conf_error(&c, "GetTexEnv point sprite mode");
  glDisable(GL_POINT_SPRITE_ARB);
  glDisable(GL_TEXTURE_2D);
  return conf_finish(&c);
}
