/* GL 1.3's multitexture (ARB_multitexture): texture units applied in order, each combining its
 * texel with the colour the unit before it made. Panels: a checker base modulated by a
 * luminance light map on unit 1 (glMultiTexCoord2f in glBegin/glEnd); the same through vertex
 * arrays (glClientActiveTexture, a texture-coordinate array per unit, glDrawArrays); units 0
 * and 2 with unit 1 off (glDrawElements); GL_ADD (ARB_texture_env_add) of an intensity and an
 * RGBA texture; a lit sphere with unit 1's coordinates generated (sphere map) under a texture
 * matrix of its own; a display list changing units and coordinates; three units (modulate, blend
 * with an environment colour, decal); 1D, 2D and 3D textures on three units; an incomplete
 * texture on unit 1 (the unit is skipped); glInterleavedArrays on unit 1 with unit 0's current
 * coordinates; glDrawPixels and glBitmap textured by two units at the raster position's
 * coordinates; glPushAttrib / glPopAttrib of the texture and enable groups. Then the per-unit
 * state (bindings, enables, environments, texture matrices and stacks, current and raster
 * coordinates, texgen, arrays) after each, and the errors. */
#define GL_GLEXT_PROTOTYPES
#include <math.h>
#include <stdio.h>

#include "conf.h"

static GLuint checker, lightmap, intensity, rgba_tex, strip_1d, volume_3d, incomplete;

static GLuint texture_2d(int w, int h, GLenum internal, GLenum format, const unsigned char* texels, GLenum filter) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  glTexImage2D(GL_TEXTURE_2D, 0, internal, w, h, 0, format, GL_UNSIGNED_BYTE, texels);
  return t;
}

static void make_textures(void) {
  static unsigned char rgb[16 * 16 * 3], lum[8 * 8], inten[8 * 8], rgba[16 * 16 * 4], line[16 * 4],
      vol[4 * 4 * 4 * 4];
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      unsigned char* t = &rgb[(y * 16 + x) * 3];
      const int on = (x / 4 + y / 4) % 2;
      t[0] = (unsigned char)(on ? 230 : 40), t[1] = (unsigned char)(on ? 180 : 70 + 8 * y), t[2] = (unsigned char)(on ? 50 : 210);
      unsigned char* a = &rgba[(y * 16 + x) * 4];
      a[0] = (unsigned char)(16 * x), a[1] = (unsigned char)(255 - 16 * y), a[2] = 128, a[3] = (unsigned char)(x < 8 ? 255 : 60 + 10 * y);
    }
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const float dx = x - 3.5f, dy = y - 3.5f;
      const float v = 1.0f - sqrtf(dx * dx + dy * dy) / 5.0f;
      lum[y * 8 + x] = (unsigned char)(v > 0.1f ? 255.0f * v : 25.0f);
      inten[y * 8 + x] = (unsigned char)((x + y) % 3 == 0 ? 200 : 30);
    }
  for (int x = 0; x < 16; ++x) line[4 * x] = (unsigned char)(x * 16), line[4 * x + 1] = 255, line[4 * x + 2] = (unsigned char)(255 - 16 * x), line[4 * x + 3] = 255;
  for (int i = 0; i < 64; ++i) {
    vol[4 * i] = (unsigned char)((i & 3) * 80), vol[4 * i + 1] = (unsigned char)(((i >> 2) & 3) * 80);
    vol[4 * i + 2] = (unsigned char)((i >> 4) * 80), vol[4 * i + 3] = 255;
  }
  checker = texture_2d(16, 16, GL_RGB, GL_RGB, rgb, GL_NEAREST);
  lightmap = texture_2d(8, 8, GL_LUMINANCE, GL_LUMINANCE, lum, GL_LINEAR);
  intensity = texture_2d(8, 8, GL_INTENSITY, GL_LUMINANCE, inten, GL_NEAREST);
  rgba_tex = texture_2d(16, 16, GL_RGBA, GL_RGBA, rgba, GL_LINEAR);
  glGenTextures(1, &strip_1d);
  glBindTexture(GL_TEXTURE_1D, strip_1d);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, line);
  glGenTextures(1, &volume_3d);
  glBindTexture(GL_TEXTURE_3D, volume_3d);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol);
  /* Mipmapped by default with one level: incomplete. */
  glGenTextures(1, &incomplete);
  glBindTexture(GL_TEXTURE_2D, incomplete);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb);
}

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.1, 1.1, -1.1, 1.1, -2.0, 2.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* Unit `unit` active, with `texture` bound to `target` and enabled, in `mode`. */
static void unit_on(int unit, GLenum target, GLuint texture, GLint mode) {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(target, texture);
  glEnable(target);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, mode);
}

static void all_units_off(void) {
  for (int u = 3; u >= 0; --u) {
    glActiveTexture(GL_TEXTURE0 + u);
    glDisable(GL_TEXTURE_1D);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_TEXTURE_3D);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  }
}

/* A quad with unit 0 at (s, t) over [0, 2]^2 and unit `other` over [-0.25, 1.25]^2. */
static void two_unit_quad(int other) {
  static const float xy[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) {
    const float s = (xy[i][0] + 1.0f) * 0.5f, t = (xy[i][1] + 1.0f) * 0.5f;
    glColor4f(0.9f, 0.8f - 0.3f * t, 0.6f + 0.3f * s, 1.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 2.0f * s, 2.0f * t);
    glMultiTexCoord2f(GL_TEXTURE0 + other, 1.5f * s - 0.25f, 1.5f * t - 0.25f);
    glVertex2f(0.97f * xy[i][0] + 0.013f, 0.97f * xy[i][1] + 0.007f);
  }
  glEnd();
}

static void record_state(ConfContext* c, const char* when) {
  char label[160];
  GLint active = 0, client = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &client);
  snprintf(label, sizeof label, "%s active", when);
  conf_value(c, label, active - GL_TEXTURE0);
  snprintf(label, sizeof label, "%s client active", when);
  conf_value(c, label, client - GL_TEXTURE0);
  for (int u = 0; u < 4; ++u) {
    double d[16];
    GLfloat f[16];
    GLint i;
    glActiveTexture(GL_TEXTURE0 + u);
    glClientActiveTexture(GL_TEXTURE0 + u);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &i);
    d[0] = i;
    glGetIntegerv(GL_TEXTURE_BINDING_1D, &i);
    d[1] = i;
    glGetIntegerv(GL_TEXTURE_BINDING_3D, &i);
    d[2] = i;
    d[3] = glIsEnabled(GL_TEXTURE_1D), d[4] = glIsEnabled(GL_TEXTURE_2D), d[5] = glIsEnabled(GL_TEXTURE_3D);
    d[6] = glIsEnabled(GL_TEXTURE_GEN_S), d[7] = glIsEnabled(GL_TEXTURE_GEN_T);
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &i);
    d[8] = i;
    glGetIntegerv(GL_TEXTURE_STACK_DEPTH, &i);
    d[9] = i;
    glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &i);
    d[10] = i;
    d[11] = glIsEnabled(GL_TEXTURE_COORD_ARRAY);
    glGetIntegerv(GL_TEXTURE_COORD_ARRAY_SIZE, &i);
    d[12] = i;
    glGetIntegerv(GL_TEXTURE_COORD_ARRAY_STRIDE, &i);
    d[13] = i;
    snprintf(label, sizeof label, "%s unit %d state", when, u);
    conf_values(c, label, d, 14);
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, f);
    for (int k = 0; k < 4; ++k) d[k] = f[k];
    snprintf(label, sizeof label, "%s unit %d current", when, u);
    conf_values(c, label, d, 4);
    glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, f);
    for (int k = 0; k < 4; ++k) d[k] = f[k];
    snprintf(label, sizeof label, "%s unit %d raster", when, u);
    conf_values(c, label, d, 4);
    glGetFloatv(GL_TEXTURE_ENV_COLOR, f);
    for (int k = 0; k < 4; ++k) d[k] = f[k];
    snprintf(label, sizeof label, "%s unit %d env color", when, u);
    conf_values(c, label, d, 4);
    glGetFloatv(GL_TEXTURE_MATRIX, f);
    for (int k = 0; k < 16; ++k) d[k] = f[k];
    snprintf(label, sizeof label, "%s unit %d matrix", when, u);
    conf_values(c, label, d, 16);
  }
  glActiveTexture((GLenum)active);
  glClientActiveTexture((GLenum)client);
  snprintf(label, sizeof label, "%s error", when);
  conf_error(c, label);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 320, 240)) return 1;
  glClearColor(0.08f, 0.08f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  GLint units = 0;
  glGetIntegerv(GL_MAX_TEXTURE_UNITS, &units);
  conf_value(&c, "at least four units", units >= 4);
  record_state(&c, "initial");
  make_textures();

  /* 1: a light map on unit 1 over a checker on unit 0, immediate mode. */
  cell(&c, 0, 0);
  unit_on(0, GL_TEXTURE_2D, checker, GL_MODULATE);
  unit_on(1, GL_TEXTURE_2D, lightmap, GL_MODULATE);
  two_unit_quad(1);
  record_state(&c, "light map");

  /* 2: the same from arrays, a coordinate array per unit. */
  cell(&c, 1, 0);
  {
    static const float pos[8] = {-0.95f, -0.93f, 0.96f, -0.95f, 0.95f, 0.94f, -0.94f, 0.96f};
    static const float t0[8] = {0, 0, 3, 0, 3, 3, 0, 3};
    static const float t1[12] = {-0.2f, -0.1f, 0, 1.2f, 0, 0, 1.1f, 1.3f, 0, 0.1f, 1.2f, 0};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glClientActiveTexture(GL_TEXTURE0);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, t0);
    glClientActiveTexture(GL_TEXTURE1);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(3, GL_FLOAT, 0, t1);
    glColor3f(1.0f, 0.9f, 0.8f);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    record_state(&c, "arrays");
    /* 3: units 0 and 2 (unit 1 off), glDrawElements; unit 2's array from client unit 2. */
    cell(&c, 2, 0);
    glActiveTexture(GL_TEXTURE1);
    glDisable(GL_TEXTURE_2D);
    unit_on(2, GL_TEXTURE_2D, rgba_tex, GL_DECAL);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY); /* client unit 1 */
    glClientActiveTexture(GL_TEXTURE2);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, t0);
    static const GLubyte idx[6] = {0, 1, 2, 0, 2, 3};
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, idx);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    record_state(&c, "elements");
  }
  all_units_off();

  /* 4: GL_ADD: an intensity texture added to a smooth quad, an RGBA texture added on unit 1. */
  cell(&c, 3, 0);
  unit_on(0, GL_TEXTURE_2D, intensity, GL_ADD);
  unit_on(1, GL_TEXTURE_2D, rgba_tex, GL_ADD);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  two_unit_quad(1);
  glDisable(GL_BLEND);
  record_state(&c, "add");
  all_units_off();

  /* 5: a lit sphere: unit 0 from the sphere's coordinates, unit 1 sphere-mapped under a
   * rotating texture matrix of its own. */
  cell(&c, 0, 1);
  {
    const float pos[4] = {0.5f, 0.8f, 1.0f, 0.0f};
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_DEPTH_TEST);
    unit_on(0, GL_TEXTURE_2D, checker, GL_MODULATE);
    unit_on(1, GL_TEXTURE_2D, lightmap, GL_MODULATE);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glMatrixMode(GL_TEXTURE);
    glPushMatrix();
    glTranslatef(0.5f, 0.5f, 0.0f);
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    glScalef(1.5f, 1.2f, 1.0f);
    glTranslatef(-0.5f, -0.5f, 0.0f);
    glMatrixMode(GL_MODELVIEW);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    conf_sphere(0.95f, 24, 16);
    record_state(&c, "sphere");
    glMatrixMode(GL_TEXTURE);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
  }
  all_units_off();

  /* 6: a display list: glActiveTexture, binds, enables and glMultiTexCoord compiled. */
  cell(&c, 1, 1);
  {
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    unit_on(0, GL_TEXTURE_2D, rgba_tex, GL_REPLACE);
    unit_on(1, GL_TEXTURE_2D, intensity, GL_MODULATE);
    glBegin(GL_TRIANGLES);
    glMultiTexCoord2f(GL_TEXTURE0, 0, 0), glMultiTexCoord2f(GL_TEXTURE1, 0, 0), glVertex2f(-0.9f, -0.9f);
    glMultiTexCoord2f(GL_TEXTURE0, 1, 0), glMultiTexCoord3f(GL_TEXTURE1, 2, 0, 0), glVertex2f(0.9f, -0.85f);
    glMultiTexCoord4f(GL_TEXTURE0, 0.5f, 1, 0, 1), glMultiTexCoord2d(GL_TEXTURE1, 1, 2), glVertex2f(0.05f, 0.92f);
    glEnd();
    glActiveTexture(GL_TEXTURE0);
    glEndList();
    glCallList(list);
    record_state(&c, "list");
  }
  all_units_off();

  /* 7: three units: modulate, blend with an environment colour, decal. */
  cell(&c, 2, 1);
  {
    const float env[4] = {0.2f, 0.9f, 0.4f, 1.0f};
    unit_on(0, GL_TEXTURE_2D, checker, GL_MODULATE);
    unit_on(1, GL_TEXTURE_2D, lightmap, GL_BLEND);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
    unit_on(2, GL_TEXTURE_2D, rgba_tex, GL_DECAL);
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; ++i) {
      const float x = (i == 1 || i == 2) ? 1.0f : 0.0f, y = i >= 2 ? 1.0f : 0.0f;
      glColor3f(0.8f, 0.8f, 0.9f);
      glTexCoord2f(x * 2, y * 2);
      glMultiTexCoord2f(GL_TEXTURE1, x, y);
      glMultiTexCoord2f(GL_TEXTURE2, 1 - y, x);
      glVertex2f(1.9f * x - 0.95f, 1.9f * y - 0.94f);
    }
    glEnd();
    record_state(&c, "three units");
  }
  all_units_off();

  /* 8: 1D on unit 0, 2D on unit 1, 3D on unit 3 (unit 2 off), each target's own unit. */
  cell(&c, 3, 1);
  unit_on(0, GL_TEXTURE_1D, strip_1d, GL_MODULATE);
  unit_on(1, GL_TEXTURE_2D, checker, GL_MODULATE);
  unit_on(3, GL_TEXTURE_3D, volume_3d, GL_MODULATE);
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 4; ++i) {
    const float x = (float)(i & 1), y = (float)(i >> 1);
    glColor3f(1, 1, 1);
    glMultiTexCoord1f(GL_TEXTURE0, x);
    glMultiTexCoord2f(GL_TEXTURE1, x * 1.5f, y);
    glMultiTexCoord3f(GL_TEXTURE3, x, y, 0.2f + 0.6f * x * y);
    glVertex2f(1.9f * x - 0.93f, 1.9f * y - 0.95f);
  }
  glEnd();
  record_state(&c, "targets");
  all_units_off();

  /* 9: an incomplete texture on unit 1 is skipped; unit 2 applies. */
  cell(&c, 0, 2);
  unit_on(0, GL_TEXTURE_2D, checker, GL_REPLACE);
  unit_on(1, GL_TEXTURE_2D, incomplete, GL_REPLACE);
  unit_on(2, GL_TEXTURE_2D, lightmap, GL_MODULATE);
  two_unit_quad(2);
  all_units_off();

  /* 10: glInterleavedArrays on client unit 1; unit 0 from the current coordinates. */
  cell(&c, 1, 2);
  {
    static const float data[4][5] = {{0, 0, -0.9f, -0.9f, 0}, {1.3f, 0, 0.9f, -0.9f, 0}, {1.3f, 1.2f, 0.9f, 0.9f, 0},
                                     {0, 1.2f, -0.9f, 0.9f, 0}};
    unit_on(0, GL_TEXTURE_2D, rgba_tex, GL_REPLACE);
    unit_on(1, GL_TEXTURE_2D, lightmap, GL_MODULATE);
    glMultiTexCoord2f(GL_TEXTURE0, 0.3f, 0.6f);
    glClientActiveTexture(GL_TEXTURE1);
    glInterleavedArrays(GL_T2F_V3F, 0, data);
    glDrawArrays(GL_QUADS, 0, 4);
    record_state(&c, "interleaved");
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
  }
  all_units_off();

  /* 11: glDrawPixels and glBitmap textured by units 0 and 1 at the raster coordinates. */
  cell(&c, 2, 2);
  {
    static GLubyte image[20 * 16 * 4], glyph[16 * 4];
    for (int i = 0; i < 20 * 16; ++i) image[4 * i] = (GLubyte)(i * 3), image[4 * i + 1] = 200, image[4 * i + 2] = (GLubyte)(i % 20 * 12), image[4 * i + 3] = 255;
    for (int i = 0; i < 16 * 4; ++i) glyph[i] = (GLubyte)((i * 37) ^ 0x5a);
    unit_on(0, GL_TEXTURE_2D, checker, GL_MODULATE);
    unit_on(1, GL_TEXTURE_2D, intensity, GL_ADD);
    glMultiTexCoord2f(GL_TEXTURE0, 0.3f, 0.3f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 0.0f);
    glRasterPos2f(-0.8f, -0.8f);
    glPixelZoom(2.0f, 2.0f);
    glDrawPixels(20, 16, GL_RGBA, GL_UNSIGNED_BYTE, image);
    glPixelZoom(1.0f, 1.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.6f, 0.1f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.2f, 0.1f);
    glColor3f(0.5f, 0.5f, 1.0f);
    glRasterPos2f(0.2f, 0.4f);
    glBitmap(16, 16, 0, 0, 0, 0, glyph);
    record_state(&c, "pixels");
  }
  all_units_off();

  /* 12: glPushAttrib / glPopAttrib of the texture and enable groups across units. */
  cell(&c, 3, 2);
  unit_on(0, GL_TEXTURE_2D, checker, GL_MODULATE);
  unit_on(1, GL_TEXTURE_2D, lightmap, GL_MODULATE);
  glPushAttrib(GL_TEXTURE_BIT | GL_ENABLE_BIT);
  unit_on(0, GL_TEXTURE_2D, intensity, GL_REPLACE);
  glActiveTexture(GL_TEXTURE1);
  glDisable(GL_TEXTURE_2D);
  unit_on(2, GL_TEXTURE_2D, rgba_tex, GL_ADD);
  record_state(&c, "pushed");
  glPopAttrib();
  record_state(&c, "popped");
  two_unit_quad(1);
  all_units_off();

  /* The default texture (name 0) is one object for every unit. */
  {
    static const GLubyte red[4] = {255, 0, 0, 255};
    GLint size = 0;
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, 0);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, red);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &size);
    conf_value(&c, "default texture shared by the units", size);
  }

  /* Errors. */
  glActiveTexture(GL_TEXTURE0 - 1);
  conf_error(&c, "ActiveTexture below GL_TEXTURE0");
  glActiveTexture(GL_TEXTURE0 + 1000);
  conf_error(&c, "ActiveTexture past the units");
  glClientActiveTexture(GL_TEXTURE0 + 1000);
  conf_error(&c, "ClientActiveTexture past the units");
  glBegin(GL_TRIANGLES);
  glActiveTexture(GL_TEXTURE1);
  glEnd();
  conf_error(&c, "ActiveTexture in glBegin");
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  conf_error(&c, "GL_ADD accepted");
  record_state(&c, "final");
  glLoadIdentity();
  return conf_finish(&c);
}
