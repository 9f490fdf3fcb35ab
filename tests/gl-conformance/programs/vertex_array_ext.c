/* EXT_vertex_array, the vertex arrays of 1995 programs (OpenGL 1.1 made them core): a lit,
 * textured ring and a strip of coloured quads drawn from arrays set by glVertexPointerEXT,
 * glNormalPointerEXT, glColorPointerEXT, glTexCoordPointerEXT and glEdgeFlagPointerEXT (with
 * counts smaller and larger than the draws use), by glDrawArraysEXT, glArrayElementEXT and GL
 * 1.1's glDrawElements, compiled into a display list (the list keeps the vertices; the arrays
 * changed afterwards), unfilled with edge flags. Values: glGetPointervEXT and the arrays' state
 * through GL 1.1's queries, and the errors of a bad size, type and stride. */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "conf.h"

#ifndef GL_EXT_vertex_array
GLAPI void APIENTRY glVertexPointerEXT(GLint size, GLenum type, GLsizei stride, GLsizei count, const void* pointer);
GLAPI void APIENTRY glNormalPointerEXT(GLenum type, GLsizei stride, GLsizei count, const void* pointer);
GLAPI void APIENTRY glColorPointerEXT(GLint size, GLenum type, GLsizei stride, GLsizei count, const void* pointer);
GLAPI void APIENTRY glIndexPointerEXT(GLenum type, GLsizei stride, GLsizei count, const void* pointer);
GLAPI void APIENTRY glTexCoordPointerEXT(GLint size, GLenum type, GLsizei stride, GLsizei count, const void* pointer);
GLAPI void APIENTRY glEdgeFlagPointerEXT(GLsizei stride, GLsizei count, const GLboolean* pointer);
GLAPI void APIENTRY glArrayElementEXT(GLint i);
GLAPI void APIENTRY glDrawArraysEXT(GLenum mode, GLint first, GLsizei count);
GLAPI void APIENTRY glGetPointervEXT(GLenum pname, void** params);
#endif

enum { kSegments = 24 };

/* A ring of quads as a strip: positions, normals and texture coordinates interleaved by hand
 * (stride 8 floats), colours in an array of their own. */
static float ring[(kSegments + 1) * 2][8];
static unsigned char colors[(kSegments + 1) * 2][4];
static GLboolean edges[16];

static void make_ring(void) {
  for (int i = 0; i <= kSegments; ++i) {
    const float a = (float)(2.0 * CONF_PI * i / kSegments), ca = cosf(a), sa = sinf(a);
    for (int k = 0; k < 2; ++k) {
      float* v = ring[i * 2 + k];
      v[0] = ca * 0.8f, v[1] = k ? 0.4f : -0.4f, v[2] = sa * 0.8f;
      v[3] = ca, v[4] = 0, v[5] = sa;
      v[6] = (float)i / kSegments * 3.0f, v[7] = (float)k;
      unsigned char* c = colors[i * 2 + k];
      c[0] = (unsigned char)(128 + 127 * ca), c[1] = (unsigned char)(128 + 127 * sa), c[2] = (unsigned char)(k ? 230 : 60);
      c[3] = 255;
    }
  }
  for (int i = 0; i < 16; ++i) edges[i] = (GLboolean)(i % 3 != 1);
}

static void cell(const ConfContext* c, int col, int row, int lit) {
  conf_panel(c, col, row, 2, 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.6, 0.6, 1.5, 8);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -3.2f);
  glRotatef(25, 1, 0, 0);
  glRotatef(15 * (float)(col + 2 * row), 0, 1, 0);
  if (lit) glEnable(GL_LIGHTING);
  else glDisable(GL_LIGHTING);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0.1f, 0.12f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  make_ring();
  const char* extensions = (const char*)glGetString(GL_EXTENSIONS);
  conf_value(&c, "GL_EXT_vertex_array listed", strstr(extensions, "GL_EXT_vertex_array ") != NULL);

  static unsigned char checker[8 * 8 * 3];
  for (int i = 0; i < 64; ++i) memset(&checker[i * 3], ((i / 8 + i % 8) & 1) ? 250 : 70, 3);
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, checker);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

  const GLsizei n = (kSegments + 1) * 2;
  glVertexPointerEXT(3, GL_FLOAT, 8 * sizeof(float), n, &ring[0][0]);
  glNormalPointerEXT(GL_FLOAT, 8 * sizeof(float), n, &ring[0][3]);
  glTexCoordPointerEXT(2, GL_FLOAT, 8 * sizeof(float), 4, &ring[0][6]); /* a count below the draw's */
  glColorPointerEXT(4, GL_UNSIGNED_BYTE, 0, n + 100, colors);         /* and above it */
  conf_error(&c, "pointers");
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);

  /* Cell (0, 0): the lit, textured ring by glDrawArraysEXT. */
  cell(&c, 0, 0, 1);
  glEnable(GL_TEXTURE_2D);
  glDrawArraysEXT(GL_QUAD_STRIP, 0, n);
  glDisable(GL_TEXTURE_2D);
  /* Cell (1, 0): half of it by glArrayElementEXT, unlit, as triangles. */
  cell(&c, 1, 0, 0);
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < n / 2 + 1; ++i) glArrayElementEXT(i);
  glEnd();
  /* Cell (0, 1): a display list of glDrawArraysEXT; the arrays changed after it. */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glDrawArraysEXT(GL_QUAD_STRIP, 4, n - 8);
  glEndList();
  memset(colors, 0, sizeof colors);
  cell(&c, 0, 1, 1);
  glCallList(list);
  /* Cell (1, 1): quads drawn as lines, edge flags from glEdgeFlagPointerEXT. */
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glEdgeFlagPointerEXT(0, 16, edges);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  cell(&c, 1, 1, 0);
  glColor3f(1.0f, 0.9f, 0.4f);
  glDrawArraysEXT(GL_QUADS, 0, 16);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisableClientState(GL_EDGE_FLAG_ARRAY);

  /* The state: glGetPointervEXT and GL 1.1's queries see the same arrays. */
  void* p = NULL;
  glGetPointervEXT(GL_VERTEX_ARRAY_POINTER, &p);
  conf_value(&c, "vertex pointer", p == (void*)&ring[0][0]);
  glGetPointervEXT(GL_EDGE_FLAG_ARRAY_POINTER, &p);
  conf_value(&c, "edge flag pointer", p == (void*)edges);
  glGetPointerv(GL_TEXTURE_COORD_ARRAY_POINTER, &p);
  conf_value(&c, "texcoord pointer", p == (void*)&ring[0][6]);
  GLint v = -1;
  glGetIntegerv(GL_VERTEX_ARRAY_STRIDE, &v);
  conf_value(&c, "vertex stride", v);
  glGetIntegerv(GL_COLOR_ARRAY_SIZE, &v);
  conf_value(&c, "color size", v);
  glGetIntegerv(GL_TEXTURE_COORD_ARRAY_TYPE, &v);
  conf_value(&c, "texcoord type", v);
  static GLshort indices[8];
  glIndexPointerEXT(GL_SHORT, 2, 8, indices);
  conf_error(&c, "index pointer");
  glGetIntegerv(GL_INDEX_ARRAY_TYPE, &v);
  conf_value(&c, "index type", v);
  glGetIntegerv(GL_INDEX_ARRAY_STRIDE, &v);
  conf_value(&c, "index stride", v);

  /* Errors, as GL 1.1's commands give them. */
  glVertexPointerEXT(5, GL_FLOAT, 0, 4, ring);
  conf_error(&c, "vertex size 5");
  glVertexPointerEXT(3, GL_UNSIGNED_BYTE, 0, 4, ring);
  conf_error(&c, "vertex type unsigned byte");
  glNormalPointerEXT(GL_FLOAT, -4, 4, ring);
  conf_error(&c, "normal stride -4");
  glColorPointerEXT(2, GL_FLOAT, 0, 4, colors);
  conf_error(&c, "color size 2");
  glTexCoordPointerEXT(2, GL_FLOAT, 0, -1, ring);
  conf_error(&c, "texcoord count -1");
  glDisableClientState(GL_VERTEX_ARRAY);
  return conf_finish(&c);
}
