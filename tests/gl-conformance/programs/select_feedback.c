/* Selection and feedback (OpenGL 1.1 sections 5.2, 5.3), compared with Mesa value by value
 * (conf_value): every feedback type over points, lines, every polygon primitive, primitives
 * clipped by the view volume and a user clip plane, polygons in line and point mode with edge
 * flags, culling, two-sided lighting, generated and transformed texture coordinates,
 * perspective w, vertex arrays, glDrawElements, display lists, evaluators, glRect, the pixel
 * rectangle tokens, glPassThrough and overflow; selection of a grid of objects picked through a
 * pick matrix, nested names, depth ranges, raster positions, overflow; the name stack's and
 * glRenderMode's errors and state. The image is drawn in GL_RENDER mode around draws, clears
 * and pixel copies made in the other two modes (which must leave it alone), and shows the hit
 * records as cells. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "conf.h"

enum { kFeedbackSize = 8192, kSelectSize = 1024 };
static GLfloat feedback[kFeedbackSize];
static GLuint selection[kSelectSize];

static void record_feedback(ConfContext* c, const char* what, GLint n) {
  char key[160];
  snprintf(key, sizeof key, "%s count", what);
  conf_value(c, key, n);
  for (GLint i = 0; i < n && i < kFeedbackSize; ++i) {
    snprintf(key, sizeof key, "%s [%d]", what, i);
    conf_value(c, key, feedback[i]);
  }
  conf_error(c, what);
}

static void record_selection(ConfContext* c, const char* what, GLint hits, int values) {
  char key[160];
  snprintf(key, sizeof key, "%s hits", what);
  conf_value(c, key, hits);
  for (int i = 0; i < values && i < kSelectSize; ++i) {
    snprintf(key, sizeof key, "%s [%d]", what, i);
    conf_value(c, key, selection[i]);
  }
  conf_error(c, what);
}

/* The number of values the hit records take. */
static int hit_values(GLint hits) {
  int k = 0;
  for (GLint h = 0; h < hits && k < kSelectSize; ++h) k += 3 + (int)selection[k];
  return k;
}

static void ortho(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void begin_feedback(GLenum type) {
  memset(feedback, 0, sizeof feedback);
  glFeedbackBuffer(kFeedbackSize, type, feedback);
  glRenderMode(GL_FEEDBACK);
}

static void polygons(void) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0); glTexCoord2f(0, 0); glVertex3f(-0.9f, -0.9f, 0.1f);
  glColor3f(0, 1, 0); glTexCoord2f(1, 0); glVertex3f(-0.3f, -0.9f, 0.2f);
  glColor3f(0, 0, 1); glTexCoord2f(0, 1); glVertex3f(-0.6f, -0.3f, 0.3f);
  glEnd();
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 5; ++i) {
    glColor3f(0.2f * i, 0.5f, 1.0f - 0.2f * i);
    glVertex2f(-0.2f + 0.15f * i, (i & 1) ? -0.3f : -0.9f);
  }
  glEnd();
  glBegin(GL_TRIANGLE_FAN);
  glVertex2f(0.6f, -0.6f);
  for (int i = 0; i < 5; ++i) glVertex2f(0.6f + 0.3f * cosf(0.5f * i), -0.6f + 0.3f * sinf(0.5f * i));
  glEnd();
  glBegin(GL_QUADS);
  glColor4f(1, 1, 0, 0.5f); glVertex2f(-0.9f, 0.0f); glVertex2f(-0.5f, 0.0f);
  glColor4f(0, 1, 1, 0.25f); glVertex2f(-0.5f, 0.4f); glVertex2f(-0.9f, 0.4f);
  glEnd();
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i < 3; ++i) {
    glVertex2f(-0.3f + 0.2f * i, 0.0f);
    glVertex2f(-0.3f + 0.2f * i, 0.3f + 0.05f * i);
  }
  glEnd();
  glBegin(GL_POLYGON);
  for (int i = 0; i < 6; ++i) glVertex2f(0.6f + 0.3f * cosf(1.04f * i), 0.3f + 0.3f * sinf(1.04f * i));
  glEnd();
}

static void lines_and_points(void) {
  glBegin(GL_POINTS);
  glColor3f(1, 0.5f, 0.25f);
  glVertex3f(0.1f, 0.2f, 0.3f);
  glVertex3f(1.5f, 0.0f, 0.0f); /* outside: no token */
  glVertex3f(-0.1f, -0.2f, -0.3f);
  glEnd();
  glBegin(GL_LINES);
  glVertex2f(-0.8f, 0.8f); glVertex2f(0.8f, 0.7f);
  glVertex2f(-0.8f, 0.6f); glVertex2f(1.8f, 0.5f); /* clipped at x = 1 */
  glEnd();
  glBegin(GL_LINE_STRIP);
  glVertex2f(-0.8f, -0.8f); glVertex2f(0.0f, 0.9f); glVertex2f(0.8f, -0.8f);
  glEnd();
  glBegin(GL_LINE_LOOP);
  glVertex2f(-0.5f, -0.5f); glVertex2f(0.5f, -0.5f); glVertex2f(0.0f, 0.5f);
  glEnd();
}

static void feedback_types(ConfContext* c) {
  static const GLenum kTypes[] = {GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE};
  char what[80];
  ortho();
  glTexCoord4f(0.5f, 0.25f, 0.125f, 2.0f);
  for (int t = 0; t < 5; ++t) {
    begin_feedback(kTypes[t]);
    lines_and_points();
    glPassThrough(7.5f);
    polygons();
    glPassThrough(-1.0f);
    snprintf(what, sizeof what, "type 0x%04x", kTypes[t]);
    record_feedback(c, what, glRenderMode(GL_RENDER));
  }
}

static void feedback_clipping(ConfContext* c) {
  ortho();
  begin_feedback(GL_3D_COLOR);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0); glVertex3f(-0.5f, -0.5f, 0.0f);
  glColor3f(0, 1, 0); glVertex3f(1.7f, -0.3f, 0.5f);
  glColor3f(0, 0, 1); glVertex3f(0.2f, 1.6f, -1.5f);
  glEnd();
  glBegin(GL_QUADS);
  glVertex2f(-1.5f, -1.5f); glVertex2f(1.5f, -1.5f); glVertex2f(1.5f, 1.5f); glVertex2f(-1.5f, 1.5f);
  glEnd();
  record_feedback(c, "view volume", glRenderMode(GL_RENDER));

  static const GLdouble plane[4] = {1.0, 1.0, 0.0, -0.2};
  glClipPlane(GL_CLIP_PLANE2, plane);
  glEnable(GL_CLIP_PLANE2);
  begin_feedback(GL_3D_COLOR);
  polygons();
  lines_and_points();
  record_feedback(c, "user clip plane", glRenderMode(GL_RENDER));
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  begin_feedback(GL_3D);
  polygons();
  record_feedback(c, "user clip plane, line mode", glRenderMode(GL_RENDER));
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisable(GL_CLIP_PLANE2);

  /* Perspective: w, and the near plane. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -3.0f);
  begin_feedback(GL_4D_COLOR_TEXTURE);
  glBegin(GL_TRIANGLES);
  glTexCoord2f(0, 0); glVertex3f(-1.0f, -1.0f, 0.0f);
  glTexCoord2f(1, 0); glVertex3f(1.0f, -1.0f, -4.0f);
  glTexCoord2f(0, 1); glVertex3f(0.0f, 1.0f, 2.5f); /* in front of the near plane */
  glEnd();
  glBegin(GL_POINTS);
  glVertex3f(0.3f, 0.2f, 0.0f);
  glEnd();
  record_feedback(c, "perspective", glRenderMode(GL_RENDER));
}

static void feedback_polygon_modes(ConfContext* c) {
  ortho();
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  begin_feedback(GL_3D);
  polygons();
  glFrontFace(GL_CW);
  polygons();
  glFrontFace(GL_CCW);
  /* No glEdgeFlag here: once a program has called it (even with GL_TRUE, even outside
   * glBegin/glEnd), Mesa 22 reports no edge of a polygon in line mode in feedback mode, where
   * the specification reports those flagged; see docs/gl.md. */
  glBegin(GL_QUADS);
  glVertex2f(-0.5f, -0.5f); glVertex2f(0.5f, -0.5f); glVertex2f(0.5f, 0.5f); glVertex2f(-0.5f, 0.5f);
  glEnd();
  record_feedback(c, "polygon modes", glRenderMode(GL_RENDER));
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

  glEnable(GL_CULL_FACE);
  begin_feedback(GL_2D);
  polygons();
  glCullFace(GL_FRONT);
  polygons();
  glCullFace(GL_BACK);
  glFrontFace(GL_CW);
  polygons();
  glFrontFace(GL_CCW);
  record_feedback(c, "culling", glRenderMode(GL_RENDER));
  glDisable(GL_CULL_FACE);

  /* Wide, smooth and stippled lines and large points stay one token each. */
  glLineWidth(5.0f);
  glPointSize(7.0f);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x0f0f);
  begin_feedback(GL_3D);
  lines_and_points();
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_POINT_SMOOTH);
  lines_and_points();
  glShadeModel(GL_FLAT);
  lines_and_points();
  polygons();
  glShadeModel(GL_SMOOTH);
  record_feedback(c, "wide, smooth, stippled, flat", glRenderMode(GL_RENDER));
  glDisable(GL_LINE_SMOOTH);
  glDisable(GL_POINT_SMOOTH);
  glDisable(GL_LINE_STIPPLE);
  glLineWidth(1.0f);
  glPointSize(1.0f);
}

static void feedback_lighting_texturing(ConfContext* c) {
  ortho();
  static const GLfloat pos[4] = {0.3f, 0.5f, 1.0f, 0.0f};
  static const GLfloat diffuse[4] = {0.8f, 0.6f, 0.3f, 1.0f};
  static const GLfloat back[4] = {0.1f, 0.3f, 0.9f, 0.7f};
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_BACK, GL_DIFFUSE, back);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glNormal3f(0.0f, 0.0f, 1.0f);
  begin_feedback(GL_3D_COLOR);
  polygons();
  glFrontFace(GL_CW);
  polygons();
  glFrontFace(GL_CCW);
  lines_and_points();
  record_feedback(c, "two-sided lighting", glRenderMode(GL_RENDER));
  glDisable(GL_LIGHTING);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);

  /* Generated texture coordinates and the texture matrix, with and without a texture. */
  static const GLfloat splane[4] = {0.5f, 0.0f, 0.0f, 0.5f};
  static const GLfloat tplane[4] = {0.0f, 0.25f, 0.5f, 0.0f};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, splane);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGenfv(GL_T, GL_EYE_PLANE, tplane);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.25f, 0.0f, 0.0f);
  glScalef(2.0f, 3.0f, 1.0f);
  glMatrixMode(GL_MODELVIEW);
  /* With a texture: Mesa 22 applies texture generation and the texture matrix to what it
   * reports only while a texture is enabled, where the specification applies them always
   * (docs/gl.md); shadelab follows the specification. */
  glTexCoord4f(9, 9, 0.5f, 2.0f);
  static const GLubyte texels[4 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  begin_feedback(GL_3D_COLOR_TEXTURE);
  polygons();
  lines_and_points();
  glDisable(GL_TEXTURE_2D);
  record_feedback(c, "texture coordinates", glRenderMode(GL_RENDER));
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glTexCoord4f(0, 0, 0, 1);
}

static void feedback_paths(ConfContext* c) {
  ortho();
  static const GLfloat verts[] = {-0.8f, -0.8f, 0.0f, -0.2f, -0.8f, 0.1f, -0.2f, -0.2f, 0.2f, -0.8f, -0.2f, 0.3f,
                                  0.2f,  0.2f,  0.0f, 0.8f,  0.2f,  0.1f, 0.8f,  0.8f,  0.2f, 0.2f,  0.8f,  0.3f};
  static const GLfloat colors[] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0, 1, 0, 1, 0, 1, 1, 1, 1, 1, 0.5f, 0.5f, 0.5f};
  static const GLuint indices[] = {4, 5, 6, 7, 0, 1, 2, 3};
  glVertexPointer(3, GL_FLOAT, 0, verts);
  glColorPointer(3, GL_FLOAT, 0, colors);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  glPassThrough(42.0f);
  glBegin(GL_QUADS);
  for (int i = 0; i < 8; ++i) glArrayElement(i);
  glEnd();
  glEndList();
  begin_feedback(GL_3D_COLOR);
  glDrawArrays(GL_QUADS, 0, 8);
  glDrawElements(GL_QUADS, 8, GL_UNSIGNED_INT, indices);
  glDrawArrays(GL_LINE_STRIP, 2, 5);
  glDrawElements(GL_POINTS, 3, GL_UNSIGNED_INT, indices + 2);
  glCallList(list);
  glRectf(-0.5f, -0.25f, 0.75f, 0.5f);
  glRecti(1, 1, 0, 0);
  record_feedback(c, "arrays, lists, rectangles", glRenderMode(GL_RENDER));
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDeleteLists(list, 1);

  /* An evaluator's curve and mesh. */
  static const GLfloat ctrl[4][3] = {{-0.8f, -0.8f, 0.0f}, {-0.3f, 0.8f, 0.5f}, {0.3f, -0.8f, -0.5f}, {0.8f, 0.8f, 0.0f}};
  glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &ctrl[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glMapGrid1f(6, 0.0f, 1.0f);
  begin_feedback(GL_3D);
  glEvalMesh1(GL_LINE, 0, 6);
  glEvalMesh1(GL_POINT, 1, 3);
  glBegin(GL_LINE_STRIP);
  glEvalCoord1f(0.25f);
  glEvalCoord1f(0.75f);
  glEnd();
  record_feedback(c, "evaluators", glRenderMode(GL_RENDER));
  glDisable(GL_MAP1_VERTEX_3);

  /* Pixel rectangles: a token and the raster position (none while it is invalid). */
  static const GLubyte bits[8] = {0xff, 0x81, 0x81, 0x81, 0x81, 0x81, 0x81, 0xff};
  static const GLubyte pixel[4] = {10, 20, 30, 40};
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
  glTexCoord4f(1, 2, 3, 4);
  begin_feedback(GL_4D_COLOR_TEXTURE);
  glRasterPos3f(-0.5f, -0.25f, 0.5f);
  glBitmap(8, 8, 0, 0, 3, 4, bits);
  glBitmap(8, 8, 0, 0, 3, 4, bits);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  glCopyPixels(0, 0, 4, 4, GL_COLOR);
  glRasterPos3f(2.0f, 0.0f, 0.0f); /* invalid */
  glBitmap(8, 8, 0, 0, 3, 4, bits);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  glCopyPixels(0, 0, 4, 4, GL_COLOR);
  record_feedback(c, "pixel rectangles", glRenderMode(GL_RENDER));
  glTexCoord4f(0, 0, 0, 1);

  /* Overflow: glRenderMode answers -1, the buffer holds what fitted. */
  memset(feedback, 0, sizeof feedback);
  glFeedbackBuffer(20, GL_3D, feedback);
  glRenderMode(GL_FEEDBACK);
  polygons();
  record_feedback(c, "overflow", glRenderMode(GL_RENDER));
  record_feedback(c, "overflow buffer", 24);
  glFeedbackBuffer(11, GL_2D, feedback);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0); glVertex2f(1, 0); glVertex2f(0, 1);
  glEnd();
  glPassThrough(1.0f);
  conf_value(c, "exactly full", glRenderMode(GL_RENDER));
}

/* A grid of 4 x 3 objects at depths of their own: squares, a line, a point and a triangle. */
static void draw_objects(int names) {
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i) {
      const float x = -0.75f + 0.5f * i, y = -0.66f + 0.66f * j, z = -0.8f + 0.13f * (i + 4 * j);
      if (names) glLoadName((GLuint)(10 * j + i));
      glColor3f(0.25f * i, 0.33f * j, 1.0f - 0.08f * (i + 4 * j));
      switch ((i + j) % 4) {
        case 0: glRectf(x - 0.2f, y - 0.25f, x + 0.2f, y + 0.25f); break;
        case 1:
          glBegin(GL_LINES);
          glVertex3f(x - 0.2f, y - 0.2f, z); glVertex3f(x + 0.2f, y + 0.2f, z + 0.1f);
          glEnd();
          break;
        case 2:
          glBegin(GL_POINTS);
          glVertex3f(x, y, z);
          glEnd();
          break;
        default:
          glBegin(GL_TRIANGLES);
          glVertex3f(x - 0.2f, y - 0.2f, z); glVertex3f(x + 0.2f, y - 0.2f, z + 0.2f);
          glVertex3f(x, y + 0.25f, z - 0.1f);
          glEnd();
      }
    }
  }
}

/* gluPickMatrix's projection: a w x h pixel box around (x, y) of the viewport fills the view
 * volume. */
static void pick(double x, double y, double w, double h) {
  GLint vp[4];
  glGetIntegerv(GL_VIEWPORT, vp);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glTranslated((vp[2] - 2 * (x - vp[0])) / w, (vp[3] - 2 * (y - vp[1])) / h, 0);
  glScaled(vp[2] / w, vp[3] / h, 1.0);
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static unsigned select_cells[384];
static int n_select_cells = 0;

static void selection_tests(ConfContext* c) {
  char what[80];
  glSelectBuffer(kSelectSize, selection);
  /* The whole grid, then picking boxes across it. */
  ortho();
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(0);
  draw_objects(1);
  GLint hits = glRenderMode(GL_RENDER);
  record_selection(c, "whole grid", hits, hit_values(hits));
  static const double boxes[][4] = {{32, 48, 8, 8}, {100, 60, 40, 30}, {160, 100, 5, 5}, {48, 80, 120, 6}, {0, 0, 1, 1}};
  for (int b = 0; b < 5; ++b) {
    pick(boxes[b][0], boxes[b][1], boxes[b][2], boxes[b][3]);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(0);
    draw_objects(1);
    hits = glRenderMode(GL_RENDER);
    snprintf(what, sizeof what, "pick box %d", b);
    record_selection(c, what, hits, hit_values(hits));
    for (int k = 0; k < hit_values(hits) && n_select_cells < 384; ++k) select_cells[n_select_cells++] = selection[k];
  }

  /* Nested names, a depth range, culled and clipped primitives, raster positions. */
  ortho();
  glDepthRange(0.25, 0.75);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(1);
  glPushName(2);
  glBegin(GL_TRIANGLES);
  glVertex3f(-0.5f, -0.5f, 0.9f); glVertex3f(0.5f, -0.5f, -0.2f); glVertex3f(0.0f, 0.5f, 0.4f);
  glEnd();
  glPopName();
  glPushName(3);
  glEnable(GL_CULL_FACE);
  glBegin(GL_TRIANGLES); /* clockwise: culled, no hit */
  glVertex3f(-0.5f, -0.5f, 0.0f); glVertex3f(0.0f, 0.5f, 0.0f); glVertex3f(0.5f, -0.5f, 0.0f);
  glEnd();
  glDisable(GL_CULL_FACE);
  glLoadName(4);
  glBegin(GL_LINES); /* clipped by the near and far planes */
  glVertex3f(0.0f, 0.0f, 3.0f); glVertex3f(0.5f, 0.0f, -3.0f);
  glEnd();
  glLoadName(5);
  glRasterPos3f(0.0f, 0.0f, 0.5f);
  glLoadName(6);
  glRasterPos3f(3.0f, 0.0f, 0.5f); /* invalid: no hit */
  glLoadName(7);
  static const GLubyte bits[1] = {0x80};
  glRasterPos3f(0.0f, 0.0f, 0.0f);
  glLoadName(8);
  glBitmap(1, 1, 0, 0, 1, 1, bits); /* no hit (appendix B) */
  glLoadName(9);
  glBegin(GL_POINTS);
  glVertex3f(0.0f, 0.0f, -1.0f); /* the far plane: window depth 0.75 */
  glEnd();
  glDepthRange(0.0, 1.0);
  glLoadName(10);
  glBegin(GL_POINTS);
  glVertex3f(0.0f, 0.0f, -1.0f); /* window depth 1: Mesa writes 2^32 as 0 */
  glVertex3f(0.0f, 0.0f, 1.0f);
  glEnd();
  glLoadName(11);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glBegin(GL_QUADS);
  glVertex3f(-0.5f, -0.5f, 0.3f); glVertex3f(0.5f, -0.5f, 0.3f); glVertex3f(0.5f, 0.5f, -0.6f); glVertex3f(-0.5f, 0.5f, 0.3f);
  glEnd();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  GLint depth = -1;
  glGetIntegerv(GL_NAME_STACK_DEPTH, &depth);
  conf_value(c, "name stack depth in selection", depth);
  hits = glRenderMode(GL_RENDER);
  record_selection(c, "names and depths", hits, hit_values(hits));
  glGetIntegerv(GL_NAME_STACK_DEPTH, &depth);
  conf_value(c, "name stack depth after", depth);

  /* Overflow: -1, the records that fitted. */
  memset(selection, 0, sizeof selection);
  glSelectBuffer(7, selection);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(1);
  glPushName(2);
  draw_objects(0);
  glPopName();
  draw_objects(0);
  hits = glRenderMode(GL_RENDER);
  record_selection(c, "overflow", hits, 10);
  glSelectBuffer(kSelectSize, selection);
}

static void errors_and_state(ConfContext* c) {
  GLint v = -1;
  void* p = NULL;
  glGetIntegerv(GL_RENDER_MODE, &v);
  conf_value(c, "initial render mode", v);
  glGetIntegerv(GL_FEEDBACK_BUFFER_SIZE, &v);
  conf_value(c, "initial feedback size", v);
  glGetIntegerv(GL_FEEDBACK_BUFFER_TYPE, &v);
  conf_value(c, "initial feedback type", v);
  glGetIntegerv(GL_SELECTION_BUFFER_SIZE, &v);
  conf_value(c, "initial selection size", v);
  glGetIntegerv(GL_MAX_NAME_STACK_DEPTH, &v);
  conf_value(c, "GL_MAX_NAME_STACK_DEPTH", v);
  glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &p);
  conf_value(c, "initial feedback pointer is null", p == NULL);
  /* Modes without a buffer: an error, the mode entered all the same. */
  conf_value(c, "select without a buffer", glRenderMode(GL_SELECT));
  conf_error(c, "select without a buffer");
  glGetIntegerv(GL_RENDER_MODE, &v);
  conf_value(c, "mode after select without a buffer", v);
  conf_value(c, "feedback without a buffer", glRenderMode(GL_FEEDBACK));
  conf_error(c, "feedback without a buffer");
  glGetIntegerv(GL_RENDER_MODE, &v);
  conf_value(c, "mode after feedback without a buffer", v);
  glRenderMode(GL_RENDER);
  conf_value(c, "bad mode", glRenderMode(GL_POLYGON));
  conf_error(c, "bad mode");
  /* The name stack outside selection mode: ignored. */
  glLoadName(1);
  conf_error(c, "glLoadName in render mode");
  glPopName();
  conf_error(c, "glPopName in render mode");
  glPushName(3);
  glGetIntegerv(GL_NAME_STACK_DEPTH, &v);
  conf_value(c, "depth after glPushName in render mode", v);
  /* Buffers' errors. */
  glSelectBuffer(-1, selection);
  conf_error(c, "glSelectBuffer(-1)");
  glFeedbackBuffer(-1, GL_2D, feedback);
  conf_error(c, "glFeedbackBuffer(-1)");
  glFeedbackBuffer(10, GL_RGBA, feedback);
  conf_error(c, "glFeedbackBuffer(bad type)");
  glFeedbackBuffer(10, GL_3D, feedback);
  glFeedbackBuffer(10, GL_2D, NULL);
  conf_error(c, "glFeedbackBuffer(NULL)");
  glGetIntegerv(GL_FEEDBACK_BUFFER_SIZE, &v);
  conf_value(c, "feedback size after NULL", v);
  glGetIntegerv(GL_FEEDBACK_BUFFER_TYPE, &v);
  conf_value(c, "feedback type after NULL", v);
  glFeedbackBuffer(0, GL_3D_COLOR, NULL);
  conf_error(c, "glFeedbackBuffer(0, NULL)");
  glFeedbackBuffer(kFeedbackSize, GL_3D_COLOR, feedback);
  glGetIntegerv(GL_FEEDBACK_BUFFER_SIZE, &v);
  conf_value(c, "feedback size", v);
  glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &p);
  conf_value(c, "feedback pointer", p == (void*)feedback);
  glSelectBuffer(kSelectSize, selection);
  glGetIntegerv(GL_SELECTION_BUFFER_SIZE, &v);
  conf_value(c, "selection size", v);
  glGetPointerv(GL_SELECTION_BUFFER_POINTER, &p);
  conf_value(c, "selection pointer", p == (void*)selection);
  /* In selection mode. */
  glRenderMode(GL_SELECT);
  glGetIntegerv(GL_RENDER_MODE, &v);
  conf_value(c, "mode in selection", v);
  glSelectBuffer(10, selection);
  conf_error(c, "glSelectBuffer in selection mode");
  glLoadName(1);
  conf_error(c, "glLoadName on an empty stack");
  glPopName();
  conf_error(c, "glPopName on an empty stack");
  for (int i = 0; i < 70; ++i) glPushName((GLuint)i);
  conf_error(c, "glPushName past the maximum");
  glGetIntegerv(GL_NAME_STACK_DEPTH, &v);
  conf_value(c, "depth after 70 pushes", v);
  glBegin(GL_POINTS);
  glPushName(1);
  glLoadName(1);
  glPopName();
  glInitNames();
  glEnd();
  conf_error(c, "name stack inside glBegin");
  conf_value(c, "bad mode in selection", glRenderMode(GL_LINE));
  conf_error(c, "bad mode in selection");
  glGetIntegerv(GL_RENDER_MODE, &v);
  conf_value(c, "mode after a bad mode", v);
  glGetIntegerv(GL_NAME_STACK_DEPTH, &v);
  conf_value(c, "depth after a bad mode", v);
  conf_value(c, "selection again", glRenderMode(GL_SELECT));
  conf_value(c, "render", glRenderMode(GL_RENDER));
  /* In feedback mode. */
  glRenderMode(GL_FEEDBACK);
  glFeedbackBuffer(10, GL_2D, feedback);
  conf_error(c, "glFeedbackBuffer in feedback mode");
  glBegin(GL_POINTS);
  glRenderMode(GL_RENDER);
  glPassThrough(1.0f);
  glEnd();
  conf_error(c, "glRenderMode inside glBegin");
  glSelectBuffer(kSelectSize, selection);
  conf_error(c, "glSelectBuffer in feedback mode");
  conf_value(c, "render after feedback", glRenderMode(GL_RENDER));
}

/* Draws made in selection and feedback mode, clears, accumulation and pixel copies there
 * leave the image as it was. */
static void image(ConfContext* c) {
  glViewport(0, 0, c->width, c->height / 2);
  ortho();
  glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  draw_objects(0);
  glFeedbackBuffer(kFeedbackSize, GL_2D, feedback);
  glRenderMode(GL_FEEDBACK);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glTranslatef(0.1f, 0.1f, 0.0f);
  draw_objects(0);
  glRasterPos2f(-1.0f, -1.0f);
  glCopyPixels(0, 0, 40, 40, GL_COLOR);
  glRenderMode(GL_SELECT);
  glClear(GL_COLOR_BUFFER_BIT);
  polygons();
  glRenderMode(GL_RENDER);
  glDisable(GL_DEPTH_TEST);
  glLoadIdentity();
  polygons();
  glViewport(0, 0, c->width, c->height);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 192, 144)) return 1;
  errors_and_state(&c);
  feedback_types(&c);
  feedback_clipping(&c);
  feedback_polygon_modes(&c);
  feedback_lighting_texturing(&c);
  feedback_paths(&c);
  selection_tests(&c);
  conf_value_cells(&c, select_cells, n_select_cells, 24, 8);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, c.width, c.height / 2);
  image(&c);
  glDisable(GL_SCISSOR_TEST);
  return conf_finish(&c);
}
