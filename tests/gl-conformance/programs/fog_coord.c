/* Fog coordinates (GL 1.4 sections 2.7, 2.8, 3.10; EXT_fog_coord): with GL_FOG_COORDINATE_SOURCE
 * GL_FOG_COORDINATE, fragments are fogged by the interpolated per-vertex fog coordinate instead
 * of their eye distance. Panels, 4 x 3: GL_LINEAR, GL_EXP and GL_EXP2 over quads whose vertices
 * carry coordinates from 0 to 12 (glFogCoordf, glFogCoordd and the vector forms); a quad whose
 * coordinates change sign across it (their absolute values, per vertex, as Mesa takes them);
 * glDrawArrays with a float fog coordinate array, glDrawElements with a strided double one,
 * glArrayElement; GL_FRAGMENT_DEPTH again (the coordinates unused, perspective depth fogs); a
 * display list with glFogCoord inside glBegin/glEnd and a compiled glDrawArrays; a lit sphere
 * under one current coordinate; a textured quad; lines and points. Values: the current fog
 * coordinate, the source, the array state, the attribute stacks, the raster distance, and
 * glGetError after wrong calls. */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <string.h>

#include "conf.h"

static ConfContext c;

static void ortho(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void fog_mode(int mode) {
  glFogi(GL_FOG_MODE, mode == 0 ? GL_LINEAR : mode == 1 ? GL_EXP : GL_EXP2);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 10.0f);
  glFogf(GL_FOG_DENSITY, mode == 1 ? 0.2f : 0.15f);
}

/* A 4 x 4 grid of quads over the panel; the fog coordinate of vertex (i, j) is i * 3 + j * 1.2,
 * given through each of the four commands in turn. */
static void coordinate_grid(void) {
  glBegin(GL_QUADS);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const int corner[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
      glColor3f(0.9f - 0.2f * (float)i, 0.3f + 0.15f * (float)j, 0.4f);
      for (int k = 0; k < 4; ++k) {
        const int x = corner[k][0], y = corner[k][1];
        const GLfloat f = 3.0f * (float)x * 0.8f + 1.2f * (float)y;
        const GLdouble d = f;
        switch ((x + y) % 4) {
          case 0: glFogCoordf(f); break;
          case 1: glFogCoordd(d); break;
          case 2: glFogCoordfv(&f); break;
          case 3: glFogCoorddv(&d); break;
        }
        glVertex2f(-0.9f + 0.45f * (float)x, -0.9f + 0.45f * (float)y);
      }
    }
  glEnd();
}

/* Coordinates of both signs: -8 on the left, +8 on the right, 0 in the middle. */
static void signed_coordinates(void) {
  glColor3f(1.0f, 0.9f, 0.2f);
  glBegin(GL_TRIANGLE_STRIP);
  glFogCoordf(-8.0f); glVertex2f(-0.9f, -0.9f);
  glFogCoordf(-8.0f); glVertex2f(-0.9f, 0.0f);
  glFogCoordf(8.0f); glVertex2f(0.9f, -0.9f);
  glFogCoordf(8.0f); glVertex2f(0.9f, 0.0f);
  glEnd();
  glBegin(GL_TRIANGLE_STRIP);
  glFogCoordf(-6.0f); glVertex2f(-0.9f, 0.1f);
  glFogCoordf(-6.0f); glVertex2f(-0.9f, 0.9f);
  glFogCoordf(0.0f); glVertex2f(0.0f, 0.1f);
  glFogCoordf(0.0f); glVertex2f(0.0f, 0.9f);
  glFogCoordf(6.0f); glVertex2f(0.9f, 0.1f);
  glFogCoordf(6.0f); glVertex2f(0.9f, 0.9f);
  glEnd();
}

static GLfloat positions[16][2];
static GLfloat colors[16][4];
static GLfloat fog_f[16];
static GLdouble fog_d[16][2]; /* a stride of two doubles */

static void fill_arrays(void) {
  for (int k = 0; k < 16; ++k) {
    const int col = k % 4, row = k / 4;
    positions[k][0] = -0.9f + 0.6f * (GLfloat)col;
    positions[k][1] = -0.9f + 0.6f * (GLfloat)row;
    colors[k][0] = 0.2f + 0.25f * (GLfloat)col;
    colors[k][1] = 0.9f - 0.2f * (GLfloat)row;
    colors[k][2] = 0.3f;
    colors[k][3] = 1.0f;
    fog_f[k] = (GLfloat)((k * 5) % 16) * 0.7f;
    fog_d[k][0] = 11.0 - (double)k * 0.6;
    fog_d[k][1] = 1e9; /* never read */
  }
}

static const GLuint grid_indices[] = {0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6,
                                      4, 5, 9, 4, 9, 8, 5, 6, 10, 5, 10, 9, 6, 7, 11, 6, 11, 10,
                                      8, 9, 13, 8, 13, 12, 9, 10, 14, 9, 14, 13, 10, 11, 15, 10, 15, 14};

static void arrays_panel(int which) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glColorPointer(4, GL_FLOAT, 0, colors);
  if (which == 0) {
    glFogCoordPointer(GL_FLOAT, 0, fog_f);
    glDrawElements(GL_TRIANGLES, 54, GL_UNSIGNED_INT, grid_indices);
  } else if (which == 1) {
    glFogCoordPointer(GL_DOUBLE, 2 * sizeof(GLdouble), fog_d);
    glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_INT, grid_indices);
    glDrawArrays(GL_POINTS, 0, 16);
  } else {
    glFogCoordPointer(GL_FLOAT, 0, fog_f);
    glBegin(GL_TRIANGLES);
    for (int k = 18; k < 54; ++k) glArrayElement((GLint)grid_indices[k]);
    glEnd();
    glDisableClientState(GL_FOG_COORD_ARRAY);
    glFogCoordf(4.0f);
    glDrawElements(GL_TRIANGLES, 18, GL_UNSIGNED_INT, grid_indices); /* the current coordinate */
  }
  glDisableClientState(GL_FOG_COORD_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

static void perspective_quads(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(0.9f, 0.5f, 0.2f);
  glBegin(GL_QUADS); /* a floor from z = -1 to z = -20, fog coordinates that would fog it otherwise */
  glFogCoordf(0.0f); glVertex3f(-2.0f, -1.0f, -1.0f);
  glFogCoordf(0.0f); glVertex3f(2.0f, -1.0f, -1.0f);
  glFogCoordf(30.0f); glVertex3f(2.0f, -1.0f, -20.0f);
  glFogCoordf(30.0f); glVertex3f(-2.0f, -1.0f, -20.0f);
  glEnd();
  ortho();
}

static GLuint make_list(void) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPushMatrix();
  glScalef(0.5f, 0.5f, 1.0f);
  glTranslatef(-0.9f, -0.9f, 0.0f);
  coordinate_grid();
  glPopMatrix();
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, positions);
  glFogCoordPointer(GL_FLOAT, 0, fog_f);
  glPushMatrix();
  glTranslatef(0.45f, 0.45f, 0.0f);
  glScalef(0.5f, 0.5f, 1.0f);
  glColor3f(0.2f, 0.9f, 0.9f);
  glDrawElements(GL_TRIANGLES, 54, GL_UNSIGNED_INT, grid_indices);
  glPopMatrix();
  glEndList();
  glDisableClientState(GL_FOG_COORD_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  memset(fog_f, 0, sizeof fog_f); /* the list keeps the coordinates of compile time */
  return list;
}

static void lit_sphere(float coordinate, float x) {
  const GLfloat dir[4] = {0.3f, 0.6f, 0.8f, 0.0f};
  const GLfloat diffuse[4] = {0.9f, 0.4f, 0.2f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glFogCoordf(coordinate);
  glPushMatrix();
  glTranslatef(x, 0.0f, 0.0f);
  conf_sphere(0.4f, 16, 10);
  glPopMatrix();
  glDisable(GL_LIGHTING);
}

static GLuint make_texture(void) {
  static unsigned char texels[8 * 8 * 4];
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      unsigned char* t = &texels[(y * 8 + x) * 4];
      int on = (x / 2 + y / 2) % 2;
      t[0] = (unsigned char)(on ? 240 : 20);
      t[1] = (unsigned char)(on ? 220 : 90);
      t[2] = (unsigned char)(on ? 60 : 200);
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

static void textured_lines_points(GLuint tex) {
  glBindTexture(GL_TEXTURE_2D, tex);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glFogCoordf(0.0f); glTexCoord2f(0.013f, 0.017f); glVertex2f(-0.9f, -0.9f);
  glFogCoordf(9.0f); glTexCoord2f(0.981f, 0.017f); glVertex2f(0.9f, -0.9f);
  glFogCoordf(9.0f); glTexCoord2f(0.981f, 0.977f); glVertex2f(0.9f, 0.0f);
  glFogCoordf(2.0f); glTexCoord2f(0.013f, 0.977f); glVertex2f(-0.9f, 0.0f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glColor3f(1.0f, 1.0f, 0.3f);
  glLineWidth(3.0f);
  glBegin(GL_LINES);
  for (int k = 0; k < 4; ++k) {
    glFogCoordf(0.0f); glVertex2f(-0.9f, 0.15f + 0.2f * (float)k);
    glFogCoordf(3.0f * (float)k + 1.0f); glVertex2f(0.3f, 0.2f + 0.2f * (float)k);
  }
  glEnd();
  glLineWidth(1.0f);
  glPointSize(6.0f);
  glBegin(GL_POINTS);
  for (int k = 0; k < 4; ++k) {
    glFogCoordf(2.5f * (float)k);
    glVertex2f(0.6f, 0.15f + 0.22f * (float)k);
  }
  glEnd();
  glPointSize(1.0f);
}

static void values(void) {
  GLfloat f = -1.0f;
  GLint i = -1;
  GLdouble d = -1.0;
  glGetFloatv(GL_CURRENT_FOG_COORD, &f);
  conf_value(&c, "initial coordinate", f);
  glFogCoordf(2.75f);
  glGetFloatv(GL_CURRENT_FOG_COORD, &f);
  conf_value(&c, "coordinate f", f);
  glFogCoordd(-3.25);
  glGetDoublev(GL_CURRENT_FOG_COORD, &d);
  conf_value(&c, "coordinate d", d);
  glFogCoordf(1e20f);
  glGetFloatv(GL_CURRENT_FOG_COORD, &f);
  conf_value(&c, "coordinate huge", f);
  glFogCoordf(7.6f);
  glGetIntegerv(GL_CURRENT_FOG_COORD, &i);
  conf_value(&c, "coordinate as integer", i);
  glBegin(GL_POINTS);
  glFogCoordf(1.5f); /* legal between glBegin and glEnd */
  glEnd();
  conf_error(&c, "between begin and end");
  glGetFloatv(GL_CURRENT_FOG_COORD, &f);
  conf_value(&c, "coordinate in begin", f);

  glGetIntegerv(GL_FOG_COORD_SRC, &i);
  conf_value(&c, "source initially", i);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glGetIntegerv(GL_FOG_COORD_SRC, &i);
  conf_value(&c, "source coordinate", i);
  glFogi(GL_FOG_COORD_SRC, GL_LINEAR);
  conf_error(&c, "source linear");
  glFogf(GL_FOG_COORD_SRC, 3.0f);
  conf_error(&c, "source 3");
  const GLint depth = GL_FRAGMENT_DEPTH;
  glFogiv(GL_FOG_COORD_SRC, &depth);
  glGetIntegerv(GL_FOG_COORD_SRC, &i);
  conf_value(&c, "source depth by iv", i);
  const GLfloat coord = (GLfloat)GL_FOG_COORD;
  glFogfv(GL_FOG_COORD_SRC, &coord);
  glGetIntegerv(GL_FOG_COORD_SRC, &i);
  conf_value(&c, "source coordinate by fv", i);
  /* (Not compared: glPopAttrib(GL_FOG_BIT), which Mesa 22 leaves the source out of.) */
  glPushAttrib(GL_CURRENT_BIT);
  glFogCoordf(99.0f);
  glPopAttrib();
  glGetFloatv(GL_CURRENT_FOG_COORD, &f);
  conf_value(&c, "coordinate after current pop", f);

  /* The raster distance from the eye position (not compared: with GL_FOG_COORD as the source,
   * GL 1.4 section 2.13 makes it the fog coordinate, where Mesa 22 keeps the eye distance). */
  ortho();
  glFogCoordf(4.5f);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glRasterPos3f(0.2f, 0.1f, -0.5f);
  glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &f);
  conf_value(&c, "raster distance by depth", f);

  /* The array's state. */
  void* p = (void*)&i;
  conf_value(&c, "array enabled", glIsEnabled(GL_FOG_COORD_ARRAY));
  glGetIntegerv(GL_FOG_COORD_ARRAY_TYPE, &i);
  conf_value(&c, "array type", i);
  glGetIntegerv(GL_FOG_COORD_ARRAY_STRIDE, &i);
  conf_value(&c, "array stride", i);
  glGetPointerv(GL_FOG_COORD_ARRAY_POINTER, &p);
  conf_value(&c, "array pointer null", p == NULL);
  glFogCoordPointer(GL_DOUBLE, 16, fog_d);
  conf_error(&c, "pointer double");
  glEnableClientState(GL_FOG_COORD_ARRAY);
  glGetIntegerv(GL_FOG_COORD_ARRAY_TYPE, &i);
  conf_value(&c, "array type after", i);
  glGetIntegerv(GL_FOG_COORD_ARRAY_STRIDE, &i);
  conf_value(&c, "array stride after", i);
  glGetPointerv(GL_FOG_COORD_ARRAY_POINTER, &p);
  conf_value(&c, "array pointer", p == (void*)fog_d);
  conf_value(&c, "array enabled after", glIsEnabled(GL_FOG_COORD_ARRAY));
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDisableClientState(GL_FOG_COORD_ARRAY);
  glFogCoordPointer(GL_FLOAT, 0, fog_f);
  glPopClientAttrib();
  conf_value(&c, "array enabled popped", glIsEnabled(GL_FOG_COORD_ARRAY));
  glGetIntegerv(GL_FOG_COORD_ARRAY_TYPE, &i);
  conf_value(&c, "array type popped", i);
  glDisableClientState(GL_FOG_COORD_ARRAY);
  glFogCoordPointer(GL_DOUBLE, 8, fog_d);
  glFogCoordPointer(GL_INT, 0, fog_f);
  conf_error(&c, "pointer int");
  glFogCoordPointer(GL_UNSIGNED_BYTE, 0, fog_f);
  conf_error(&c, "pointer ubyte");
  glGetIntegerv(GL_FOG_COORD_ARRAY_TYPE, &i);
  conf_value(&c, "array type after errors", i);
  /* Last: Mesa 22 raises the error and still takes the pointer (the specification: no effect). */
  glFogCoordPointer(GL_FLOAT, -4, fog_f);
  conf_error(&c, "pointer stride -4");
  glBegin(GL_POINTS);
  glFogCoordPointer(GL_FLOAT, 0, fog_f);
  glEnd();
  conf_error(&c, "pointer between begin and end");
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  conf_error(&c, "values end");
}

int main(int argc, char** argv) {
  if (!conf_init(&c, argc, argv, 400, 300)) return 1;
  values();
  fill_arrays();
  GLuint tex = make_texture();
  glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ortho();
  const GLfloat grey[4] = {0.55f, 0.55f, 0.6f, 1.0f};
  glFogfv(GL_FOG_COLOR, grey);
  glEnable(GL_FOG);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  for (int mode = 0; mode < 3; ++mode) {
    fog_mode(mode);
    conf_panel(&c, mode, 0, 4, 3);
    coordinate_grid();
  }
  fog_mode(0);
  conf_panel(&c, 3, 0, 4, 3);
  signed_coordinates();
  for (int k = 0; k < 3; ++k) {
    fog_mode(k);
    conf_panel(&c, k, 1, 4, 3);
    arrays_panel(k);
  }
  fog_mode(0);
  conf_panel(&c, 3, 1, 4, 3);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glFogf(GL_FOG_END, 25.0f);
  perspective_quads();
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  fog_mode(0);
  GLuint list = make_list();
  conf_panel(&c, 0, 2, 4, 3);
  glCallList(list);
  conf_panel(&c, 1, 2, 4, 3);
  glEnable(GL_DEPTH_TEST);
  lit_sphere(1.0f, -0.45f);
  lit_sphere(6.5f, 0.45f);
  glDisable(GL_DEPTH_TEST);
  conf_panel(&c, 2, 2, 4, 3);
  fog_mode(1);
  textured_lines_points(tex);
  conf_panel(&c, 3, 2, 4, 3);
  fog_mode(2);
  signed_coordinates();
  glDisable(GL_FOG);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  return conf_finish(&c);
}
