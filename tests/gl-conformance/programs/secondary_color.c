/* The secondary colour and the colour sum (GL 1.4 sections 2.7, 2.8, 3.9; EXT_secondary_color).
 * Panels, 4 x 3: unlit smooth triangles with a secondary colour per vertex, GL_COLOR_SUM on and
 * off; flat shading (the provoking vertex's secondary colour); a modulated texture with the sum
 * added after it; every glSecondaryColor3 form in a fan; glDrawArrays, glDrawElements and
 * glArrayElement with secondary colour arrays of several types and sizes; a display list with
 * glSecondaryColor inside glBegin/glEnd and a compiled glDrawArrays (the client data changed
 * afterwards); lighting with and without the separate specular colour (the lit secondary colour,
 * the current one unused); the sum before fog and blending; lines and points. Values: the
 * current secondary colour after every form and extreme arguments, the array state, the
 * attribute stacks, the raster position's secondary colour, and glGetError after wrong calls. */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <string.h>

#include "conf.h"

#ifndef GL_CURRENT_RASTER_SECONDARY_COLOR
#define GL_CURRENT_RASTER_SECONDARY_COLOR 0x845F
#endif

static ConfContext c;

static void ortho(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* Two triangles: primary colours dim, secondary colours strong and different per vertex. */
static void summed_triangles(void) {
  glBegin(GL_TRIANGLES);
  glColor3f(0.3f, 0.1f, 0.1f); glSecondaryColor3f(0.0f, 0.6f, 0.1f); glVertex2f(-0.9f, -0.9f);
  glColor3f(0.1f, 0.3f, 0.1f); glSecondaryColor3f(0.7f, 0.0f, 0.2f); glVertex2f(0.9f, -0.9f);
  glColor3f(0.1f, 0.1f, 0.3f); glSecondaryColor3f(0.2f, 0.3f, 0.7f); glVertex2f(-0.9f, 0.9f);
  glColor4f(0.5f, 0.5f, 0.1f, 0.5f); glSecondaryColor3f(0.6f, 0.6f, 0.0f); glVertex2f(0.9f, -0.7f);
  glColor3f(0.1f, 0.5f, 0.5f); glSecondaryColor3f(0.0f, 0.0f, 0.9f); glVertex2f(0.9f, 0.9f);
  glColor3f(0.6f, 0.2f, 0.6f); glSecondaryColor3f(0.9f, 0.9f, 0.9f); glVertex2f(-0.7f, 0.9f);
  glEnd();
}

static GLuint make_texture(void) {
  static unsigned char texels[8 * 8 * 4];
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      unsigned char* t = &texels[(y * 8 + x) * 4];
      int on = (x / 2 + y / 2) % 2;
      t[0] = (unsigned char)(on ? 220 : 30);
      t[1] = (unsigned char)(on ? 200 : 60);
      t[2] = (unsigned char)(on ? 40 : 180);
      t[3] = 255;
    }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  return tex;
}

static void textured(GLuint tex) {
  glBindTexture(GL_TEXTURE_2D, tex);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBegin(GL_QUADS);
  glColor3f(1.0f, 1.0f, 1.0f);
  /* (Texture coordinates off the texel edges at pixel centres: nearest sampling there is not
   * what this program compares.) */
  glSecondaryColor3f(0.0f, 0.0f, 0.0f); glTexCoord2f(0.013f, 0.017f); glVertex2f(-0.9f, -0.9f);
  glSecondaryColor3f(0.5f, 0.0f, 0.0f); glTexCoord2f(0.981f, 0.017f); glVertex2f(0.9f, -0.9f);
  glSecondaryColor3f(0.0f, 0.5f, 0.0f); glTexCoord2f(0.981f, 0.977f); glVertex2f(0.9f, 0.9f);
  glSecondaryColor3f(0.0f, 0.0f, 0.5f); glTexCoord2f(0.013f, 0.977f); glVertex2f(-0.9f, 0.9f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
}

/* Every glSecondaryColor3 form, one fan triangle each (16 triangles around the centre). */
static void every_form(void) {
  static const GLbyte b[3] = {100, -20, 50};
  static const GLshort s[3] = {30000, 8000, -100};
  static const GLint i[3] = {2000000000, -5, 900000000};
  static const GLfloat f[3] = {0.25f, 0.75f, 1.5f};
  static const GLdouble d[3] = {0.9, -0.3, 0.45};
  static const GLubyte ub[3] = {255, 64, 128};
  static const GLushort us[3] = {65535, 30000, 1000};
  static const GLuint ui[3] = {4000000000u, 1000000000u, 0u};
  glColor3f(0.1f, 0.1f, 0.1f);
  glBegin(GL_TRIANGLE_FAN);
  glSecondaryColor3f(0.0f, 0.0f, 0.0f);
  glVertex2f(0.0f, 0.0f);
  for (int k = 0; k <= 16; ++k) {
    switch (k % 16) {
      case 0: glSecondaryColor3b(b[0], b[1], b[2]); break;
      case 1: glSecondaryColor3bv(b); break;
      case 2: glSecondaryColor3s(s[0], s[1], s[2]); break;
      case 3: glSecondaryColor3sv(s); break;
      case 4: glSecondaryColor3i(i[0], i[1], i[2]); break;
      case 5: glSecondaryColor3iv(i); break;
      case 6: glSecondaryColor3f(f[0], f[1], f[2]); break;
      case 7: glSecondaryColor3fv(f); break;
      case 8: glSecondaryColor3d(d[0], d[1], d[2]); break;
      case 9: glSecondaryColor3dv(d); break;
      case 10: glSecondaryColor3ub(ub[0], ub[1], ub[2]); break;
      case 11: glSecondaryColor3ubv(ub); break;
      case 12: glSecondaryColor3us(us[0], us[1], us[2]); break;
      case 13: glSecondaryColor3usv(us); break;
      case 14: glSecondaryColor3ui(ui[0], ui[1], ui[2]); break;
      case 15: glSecondaryColor3uiv(ui); break;
    }
    const double a = 2.0 * CONF_PI * k / 16.0;
    glVertex2f((GLfloat)(0.9 * cos(a)), (GLfloat)(0.9 * sin(a)));
  }
  glEnd();
}

static GLfloat positions[16][2];
static GLfloat colors[16][3];
static GLfloat sec_f[16][3];
static GLubyte sec_ub[16][4];
static GLshort sec_s[16][3];

static void fill_arrays(void) {
  for (int k = 0; k < 16; ++k) {
    const int col = k % 4, row = k / 4;
    positions[k][0] = -0.9f + 0.6f * (GLfloat)col;
    positions[k][1] = -0.9f + 0.6f * (GLfloat)row;
    colors[k][0] = 0.1f * (GLfloat)(k % 3);
    colors[k][1] = 0.05f * (GLfloat)(k % 5);
    colors[k][2] = 0.2f;
    sec_f[k][0] = (GLfloat)(k % 4) / 3.0f;
    sec_f[k][1] = (GLfloat)(k / 4) / 3.0f;
    sec_f[k][2] = (GLfloat)((k * 7) % 16) / 15.0f;
    for (int j = 0; j < 3; ++j) {
      sec_ub[k][j] = (GLubyte)(sec_f[k][j] * 250.0f);
      sec_s[k][j] = (GLshort)(sec_f[k][j] * 32000.0f - (j == 1 ? 8000.0f : 0.0f));
    }
    sec_ub[k][3] = 7;
  }
}

static const GLuint grid_indices[] = {0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6,
                                      4, 5, 9, 4, 9, 8, 5, 6, 10, 5, 10, 9, 6, 7, 11, 6, 11, 10,
                                      8, 9, 13, 8, 13, 12, 9, 10, 14, 9, 14, 13, 10, 11, 15, 10, 15, 14};

static void arrays_panel(int which) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glColorPointer(3, GL_FLOAT, 0, colors);
  if (which == 0) glSecondaryColorPointer(3, GL_FLOAT, 0, sec_f);
  if (which == 1) glSecondaryColorPointer(4, GL_UNSIGNED_BYTE, 0, sec_ub);
  if (which == 2) glSecondaryColorPointer(3, GL_SHORT, 0, sec_s);
  if (which == 0) glDrawElements(GL_TRIANGLES, 54, GL_UNSIGNED_INT, grid_indices);
  if (which == 1) {
    glDrawArrays(GL_POINTS, 0, 16);
    glDrawElements(GL_TRIANGLES, 18, GL_UNSIGNED_INT, grid_indices);
  }
  if (which == 2) {
    glBegin(GL_TRIANGLES);
    for (int k = 18; k < 54; ++k) glArrayElement((GLint)grid_indices[k]);
    glEnd();
    glDrawElements(GL_TRIANGLES, 18, GL_UNSIGNED_INT, grid_indices);
  }
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

static GLuint make_list(void) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPushMatrix();
  glScalef(0.5f, 0.5f, 1.0f);
  glTranslatef(-0.9f, -0.9f, 0.0f);
  summed_triangles();
  glPopMatrix();
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glSecondaryColorPointer(3, GL_FLOAT, 0, sec_f);
  glPushMatrix();
  glTranslatef(0.45f, 0.45f, 0.0f);
  glScalef(0.5f, 0.5f, 1.0f);
  glColor3f(0.2f, 0.0f, 0.0f);
  glDrawElements(GL_TRIANGLES, 54, GL_UNSIGNED_INT, grid_indices);
  glPopMatrix();
  glEndList();
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  memset(sec_f, 0, sizeof sec_f); /* the list keeps the colours of compile time */
  return list;
}

static void lit_sphere(int separate) {
  const GLfloat dir[4] = {0.3f, 0.6f, 0.8f, 0.0f};
  const GLfloat diffuse[4] = {0.2f, 0.3f, 0.8f, 1.0f}, specular[4] = {0.9f, 0.9f, 0.7f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, separate ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
  glSecondaryColor3f(0.0f, 0.8f, 0.0f); /* unused under lighting */
  glPushMatrix();
  glTranslatef(separate ? 0.4f : -0.4f, 0.0f, 0.0f);
  conf_sphere(0.45f, 20, 12);
  glPopMatrix();
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glDisable(GL_LIGHTING);
}

static void fogged_and_blended(void) {
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 1.0f);
  const GLfloat fog_color[4] = {0.2f, 0.2f, 0.6f, 1.0f};
  glFogfv(GL_FOG_COLOR, fog_color);
  glBegin(GL_QUADS); /* ortho: eye z from 0.9 (left) to 0.1 (right) */
  glColor3f(0.4f, 0.1f, 0.1f); glSecondaryColor3f(0.5f, 0.5f, 0.0f); glVertex3f(-0.9f, -0.9f, 0.9f);
  glVertex3f(0.9f, -0.9f, 0.1f);
  glSecondaryColor3f(0.0f, 0.5f, 0.5f); glVertex3f(0.9f, 0.0f, 0.1f);
  glVertex3f(-0.9f, 0.0f, 0.9f);
  glEnd();
  glDisable(GL_FOG);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBegin(GL_TRIANGLES);
  glColor4f(0.2f, 0.2f, 0.2f, 0.4f); glSecondaryColor3f(0.8f, 0.2f, 0.0f); glVertex2f(-0.9f, 0.1f);
  glColor4f(0.2f, 0.2f, 0.2f, 0.8f); glSecondaryColor3f(0.0f, 0.2f, 0.8f); glVertex2f(0.9f, 0.1f);
  glColor4f(0.2f, 0.2f, 0.2f, 0.1f); glSecondaryColor3f(0.3f, 0.9f, 0.3f); glVertex2f(0.0f, 0.9f);
  glEnd();
  glDisable(GL_BLEND);
}

static void lines_and_points(void) {
  glLineWidth(3.0f);
  glBegin(GL_LINES);
  for (int k = 0; k < 6; ++k) {
    const float y = -0.9f + 0.3f * (float)k;
    glColor3f(0.1f, 0.1f, 0.2f);
    glSecondaryColor3f(0.9f, 0.1f * (float)k, 0.0f); glVertex2f(-0.9f, y);
    glSecondaryColor3f(0.0f, 0.5f, 0.15f * (float)k); glVertex2f(0.2f, y + 0.1f);
  }
  glEnd();
  glLineWidth(1.0f);
  glPointSize(5.0f);
  glBegin(GL_POINTS);
  for (int k = 0; k < 6; ++k) {
    glSecondaryColor3f(0.15f * (float)k, 0.9f - 0.15f * (float)k, 0.4f);
    glVertex2f(0.5f + 0.08f * (float)(k % 2), -0.8f + 0.3f * (float)k);
  }
  glEnd();
  glPointSize(1.0f);
}

/* `ints`: the glGetIntegerv form too (not for components outside [-1, 1], which Mesa 22 wraps
 * around where the specification clamps them, as shadelab does). */
static void record_current_as(const char* name, int ints) {
  GLfloat f[4];
  GLint i[4];
  GLdouble d[4];
  GLboolean b[4];
  char label[64];
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, f);
  glGetIntegerv(GL_CURRENT_SECONDARY_COLOR, i);
  glGetDoublev(GL_CURRENT_SECONDARY_COLOR, d);
  glGetBooleanv(GL_CURRENT_SECONDARY_COLOR, b);
  for (int k = 0; k < 4; ++k) {
    snprintf(label, sizeof label, "%s f[%d]", name, k);
    conf_value(&c, label, f[k]);
    snprintf(label, sizeof label, "%s i[%d]", name, k);
    if (ints) conf_value(&c, label, i[k]);
    snprintf(label, sizeof label, "%s d[%d]", name, k);
    conf_value(&c, label, d[k]);
    snprintf(label, sizeof label, "%s b[%d]", name, k);
    conf_value(&c, label, b[k]);
  }
}

static void record_current(const char* name) { record_current_as(name, 1); }

static void values(void) {
  record_current("initial");
  glSecondaryColor3b(-128, 127, 0);
  record_current("3b");
  glSecondaryColor3s(-32768, 32767, 1);
  record_current("3s");
  glSecondaryColor3i(-2147483647 - 1, 2147483647, 3);
  record_current("3i");
  glSecondaryColor3ub(0, 255, 1);
  record_current("3ub");
  glSecondaryColor3us(0, 65535, 1);
  record_current("3us");
  glSecondaryColor3ui(0, 4294967295u, 1);
  record_current("3ui");
  glSecondaryColor3f(-2.0f, 3.5f, 0.25f);
  record_current_as("3f", 0);
  glSecondaryColor3d(1e10, -1e10, 0.125);
  record_current_as("3d", 0);
  glBegin(GL_POINTS);
  glSecondaryColor3f(0.5f, 0.25f, 0.125f); /* legal between glBegin and glEnd */
  glEnd();
  conf_error(&c, "between begin and end");
  record_current("in begin");

  conf_value(&c, "color sum initially", glIsEnabled(GL_COLOR_SUM));
  glEnable(GL_COLOR_SUM);
  conf_value(&c, "color sum enabled", glIsEnabled(GL_COLOR_SUM));
  GLboolean bv = 0;
  glGetBooleanv(GL_COLOR_SUM, &bv);
  conf_value(&c, "color sum get", bv);
  /* (Not compared: glPopAttrib(GL_ENABLE_BIT), which Mesa 22 leaves GL_COLOR_SUM out of.) */
  glDisable(GL_COLOR_SUM);

  glPushAttrib(GL_CURRENT_BIT);
  glSecondaryColor3f(0.9f, 0.8f, 0.7f);
  glPopAttrib();
  record_current("after current pop");

  /* The array's state. */
  GLint v = -1;
  void* p = (void*)&v;
  conf_value(&c, "array enabled", glIsEnabled(GL_SECONDARY_COLOR_ARRAY));
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_SIZE, &v);
  conf_value(&c, "array size", v);
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_TYPE, &v);
  conf_value(&c, "array type", v);
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_STRIDE, &v);
  conf_value(&c, "array stride", v);
  glGetPointerv(GL_SECONDARY_COLOR_ARRAY_POINTER, &p);
  conf_value(&c, "array pointer null", p == NULL);
  glSecondaryColorPointer(4, GL_UNSIGNED_SHORT, 12, sec_s);
  conf_error(&c, "pointer size 4");
  glSecondaryColorPointer(3, GL_BYTE, 8, sec_ub);
  conf_error(&c, "pointer ubyte");
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_SIZE, &v);
  conf_value(&c, "array size after", v);
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_TYPE, &v);
  conf_value(&c, "array type after", v);
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_STRIDE, &v);
  conf_value(&c, "array stride after", v);
  glGetPointerv(GL_SECONDARY_COLOR_ARRAY_POINTER, &p);
  conf_value(&c, "array pointer", p == (void*)sec_ub);
  conf_value(&c, "array enabled after", glIsEnabled(GL_SECONDARY_COLOR_ARRAY));
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
  glSecondaryColorPointer(3, GL_FLOAT, 0, sec_f);
  glPopClientAttrib();
  conf_value(&c, "array enabled popped", glIsEnabled(GL_SECONDARY_COLOR_ARRAY));
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_TYPE, &v);
  conf_value(&c, "array type popped", v);
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);

  /* Errors: size, type, stride; the pointer stays as it was. */
  glSecondaryColorPointer(3, GL_SHORT, 6, sec_s);
  glSecondaryColorPointer(2, GL_FLOAT, 0, sec_f);
  conf_error(&c, "pointer size 2");
  glSecondaryColorPointer(5, GL_FLOAT, 0, sec_f);
  conf_error(&c, "pointer size 5");
  glSecondaryColorPointer(3, GL_BITMAP, 0, sec_f);
  conf_error(&c, "pointer type bitmap");
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_TYPE, &v);
  conf_value(&c, "array type after errors", v);
  /* Last: Mesa 22 raises the error and still takes the pointer (the specification: no effect). */
  glSecondaryColorPointer(3, GL_FLOAT, -4, sec_f);
  conf_error(&c, "pointer stride -4");
  glBegin(GL_POINTS);
  glSecondaryColorPointer(3, GL_FLOAT, 0, sec_f);
  glEnd();
  conf_error(&c, "pointer between begin and end");
  glBegin(GL_POINTS);
  glEnable(GL_COLOR_SUM);
  glEnd();
  conf_error(&c, "enable between begin and end");
  glDisable(GL_COLOR_SUM);

  /* The raster position's secondary colour: the current one unlit, lit with separate specular. */
  GLfloat f[4];
  glSecondaryColor3f(0.25f, 0.5f, 0.75f);
  glRasterPos2f(0.0f, 0.0f);
  glGetFloatv(GL_CURRENT_RASTER_SECONDARY_COLOR, f);
  conf_error(&c, "raster secondary query");
  conf_values(&c, "raster secondary unlit", (const double[]){f[0], f[1], f[2], f[3]}, 4);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  const GLfloat specular[4] = {0.5f, 0.25f, 1.0f, 1.0f};
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 0.0f);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glRasterPos2f(0.0f, 0.0f);
  glGetFloatv(GL_CURRENT_RASTER_SECONDARY_COLOR, f);
  conf_values(&c, "raster secondary lit rgb", (const double[]){f[0], f[1], f[2]}, 3);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glDisable(GL_LIGHTING);
  glDisable(GL_LIGHT0);
  const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glMaterialfv(GL_FRONT, GL_SPECULAR, black);
  conf_error(&c, "values end");
}

int main(int argc, char** argv) {
  if (!conf_init(&c, argc, argv, 400, 300)) return 1;
  values();
  fill_arrays();
  GLuint tex = make_texture();
  glClearColor(0.05f, 0.05f, 0.05f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ortho();
  glEnable(GL_COLOR_SUM);
  conf_panel(&c, 0, 0, 4, 3);
  summed_triangles();
  conf_panel(&c, 1, 0, 4, 3);
  glDisable(GL_COLOR_SUM);
  summed_triangles(); /* the secondary colours unused */
  glEnable(GL_COLOR_SUM);
  conf_panel(&c, 2, 0, 4, 3);
  glShadeModel(GL_FLAT);
  summed_triangles();
  glShadeModel(GL_SMOOTH);
  conf_panel(&c, 3, 0, 4, 3);
  textured(tex);
  conf_panel(&c, 0, 1, 4, 3);
  every_form();
  for (int k = 0; k < 3; ++k) {
    conf_panel(&c, 1 + k, 1, 4, 3);
    arrays_panel(k);
  }
  GLuint list = make_list();
  conf_panel(&c, 0, 2, 4, 3);
  glCallList(list);
  conf_panel(&c, 1, 2, 4, 3);
  glEnable(GL_DEPTH_TEST);
  lit_sphere(0);
  lit_sphere(1);
  glDisable(GL_DEPTH_TEST);
  conf_panel(&c, 2, 2, 4, 3);
  fogged_and_blended();
  conf_panel(&c, 3, 2, 4, 3);
  lines_and_points();
  glDisable(GL_COLOR_SUM);
  return conf_finish(&c);
}
