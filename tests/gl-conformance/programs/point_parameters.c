/* Point parameters (GL 1.4 section 3.3; ARB_point_parameters, EXT_point_parameters): each
 * point's size derived from its eye distance d as size / sqrt(a + b d + c d^2), clamped to
 * [GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX]. Panels, 4 x 3, rows of points receding in perspective:
 * quadratic, linear and constant attenuation on aliased points; the same smooth and blended;
 * the minimum and maximum clamps; a fade threshold above the derived sizes (points are not
 * multisampled: it changes nothing, as in llvmpipe); glDrawArrays and glDrawElements of points;
 * triangles drawn in GL_POINT mode; parameters set in a display list; the clamps without
 * attenuation. Values: every parameter after every form, their errors, the point attribute
 * group. */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <string.h>

#include "conf.h"

static ConfContext c;

static void perspective(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 60.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void attenuation(float a, float b, float cc) {
  const GLfloat v[3] = {a, b, cc};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, v);
}

/* Five rows of six points, each row further away (z from -1.5 to -40), the points of a row
 * spread so that they stay inside the panel. */
static void receding_points(void) {
  glBegin(GL_POINTS);
  for (int row = 0; row < 5; ++row) {
    const float z = -1.5f - 9.5f * (float)row;
    for (int k = 0; k < 6; ++k) {
      const float x = (-0.4f + 0.16f * (float)k) * -z, y = (-0.38f + 0.18f * (float)row) * -z;
      glColor4f(0.3f + 0.12f * (float)k, 0.9f - 0.15f * (float)row, 0.4f + 0.1f * (float)(k % 3), 0.8f);
      glVertex3f(x + 0.013f * (float)row, y + 0.007f * (float)k, z);
    }
  }
  glEnd();
}

static GLfloat positions[24][3];
static GLfloat colors[24][3];
static const GLushort point_indices[] = {0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 23, 21, 19, 17};

static void fill_arrays(void) {
  for (int k = 0; k < 24; ++k) {
    const float z = -2.0f - 1.5f * (float)k;
    positions[k][0] = (-0.35f + 0.7f * (float)(k % 6) / 5.0f) * -z;
    positions[k][1] = (-0.35f + 0.7f * (float)(k / 6) / 3.0f) * -z;
    positions[k][2] = z;
    colors[k][0] = 0.9f;
    colors[k][1] = 0.2f + 0.03f * (float)k;
    colors[k][2] = 0.9f - 0.03f * (float)k;
  }
}

static void array_points(void) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, positions);
  glColorPointer(3, GL_FLOAT, 0, colors);
  glDrawArrays(GL_POINTS, 0, 12);
  glDrawElements(GL_POINTS, 16, GL_UNSIGNED_SHORT, point_indices);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

static void point_mode_triangles(void) {
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glBegin(GL_TRIANGLE_STRIP);
  for (int k = 0; k < 10; ++k) {
    const float z = -2.0f - 3.0f * (float)k;
    glColor3f(0.2f + 0.08f * (float)k, 0.9f, 0.3f);
    glVertex3f((-0.4f + 0.08f * (float)k) * -z, (k % 2 ? 0.3f : -0.3f) * -z, z);
  }
  glEnd();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

static void record(const char* name, GLenum pname, int n) {
  GLfloat f[3] = {-1, -1, -1};
  GLint i[3] = {-1, -1, -1};
  GLdouble d[3] = {-1, -1, -1};
  GLboolean b[3] = {9, 9, 9};
  char label[80];
  glGetFloatv(pname, f);
  glGetIntegerv(pname, i);
  glGetDoublev(pname, d);
  glGetBooleanv(pname, b);
  for (int k = 0; k < n; ++k) {
    snprintf(label, sizeof label, "%s f[%d]", name, k);
    conf_value(&c, label, f[k]);
    snprintf(label, sizeof label, "%s i[%d]", name, k);
    conf_value(&c, label, i[k]);
    snprintf(label, sizeof label, "%s d[%d]", name, k);
    conf_value(&c, label, d[k]);
    snprintf(label, sizeof label, "%s b[%d]", name, k);
    conf_value(&c, label, b[k]);
  }
}

static void record_all(const char* when) {
  char label[80];
  snprintf(label, sizeof label, "%s min", when);
  record(label, GL_POINT_SIZE_MIN, 1);
  snprintf(label, sizeof label, "%s max", when);
  record(label, GL_POINT_SIZE_MAX, 1);
  snprintf(label, sizeof label, "%s fade", when);
  record(label, GL_POINT_FADE_THRESHOLD_SIZE, 1);
  snprintf(label, sizeof label, "%s attenuation", when);
  record(label, GL_POINT_DISTANCE_ATTENUATION, 3);
}

static void values(void) {
  record_all("initial");
  glPointParameterf(GL_POINT_SIZE_MIN, 2.5f);
  glPointParameteri(GL_POINT_SIZE_MAX, 40);
  const GLfloat fade = 3.25f;
  glPointParameterfv(GL_POINT_FADE_THRESHOLD_SIZE, &fade);
  const GLint att[3] = {2, 3, 4};
  glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, att);
  conf_error(&c, "set");
  record_all("set");
  glPointParameterf(GL_POINT_DISTANCE_ATTENUATION, 0.5f);
  conf_error(&c, "scalar attenuation f");
  record("scalar attenuation f", GL_POINT_DISTANCE_ATTENUATION, 3);
  glPointParameteri(GL_POINT_DISTANCE_ATTENUATION, 3);
  conf_error(&c, "scalar attenuation i");
  record("scalar attenuation i", GL_POINT_DISTANCE_ATTENUATION, 3);
  const GLint one_i = 7;
  glPointParameteriv(GL_POINT_SIZE_MIN, &one_i);
  record("min by iv", GL_POINT_SIZE_MIN, 1);
  const GLfloat neg = -1.0f;
  glPointParameterf(GL_POINT_SIZE_MIN, -1.0f);
  conf_error(&c, "min -1");
  glPointParameterfv(GL_POINT_SIZE_MAX, &neg);
  conf_error(&c, "max -1");
  glPointParameteri(GL_POINT_FADE_THRESHOLD_SIZE, -2);
  conf_error(&c, "fade -2");
  const GLfloat negatives[3] = {-1.0f, -2.0f, -3.0f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, negatives);
  conf_error(&c, "negative attenuation");
  glPointParameterf(GL_POINT_SIZE, 2.0f);
  conf_error(&c, "pname point size");
  glPointParameterf(GL_FOG_DENSITY, 2.0f);
  conf_error(&c, "pname fog density");
  glPointParameterf(GL_POINT_SIZE_MIN, 1000.0f);
  conf_error(&c, "min above max");
  record_all("after errors");
  glBegin(GL_POINTS);
  glPointParameterf(GL_POINT_SIZE_MIN, 1.0f);
  glEnd();
  conf_error(&c, "between begin and end");
  glPushAttrib(GL_POINT_BIT);
  glPointParameterf(GL_POINT_SIZE_MIN, 0.5f);
  glPointParameterf(GL_POINT_SIZE_MAX, 0.75f);
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 0.125f);
  attenuation(9.0f, 8.0f, 7.0f);
  glPopAttrib();
  record_all("after point pop");
  glPushAttrib(GL_ENABLE_BIT);
  attenuation(5.0f, 0.0f, 0.0f);
  glPopAttrib();
  record_all("after enable pop");
  /* A list sets them when it runs. */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPointParameterf(GL_POINT_SIZE_MIN, 1.5f);
  const GLfloat att_f[3] = {0.25f, 0.5f, 0.75f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att_f);
  glPointParameteriv(GL_POINT_SIZE_MAX, &one_i);
  glEndList();
  record_all("after compile");
  glCallList(list);
  record_all("after call");
  glDeleteLists(list, 1);
  /* Back to the defaults. */
  glPointParameterf(GL_POINT_SIZE_MIN, 0.0f);
  glPointParameterf(GL_POINT_SIZE_MAX, 255.0f);
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 1.0f);
  attenuation(1.0f, 0.0f, 0.0f);
  conf_error(&c, "values end");
}

int main(int argc, char** argv) {
  if (!conf_init(&c, argc, argv, 400, 300)) return 1;
  values();
  fill_arrays();
  glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  perspective();
  glPointSize(14.0f);
  /* Row 0: aliased points, quadratic, linear, constant attenuation, and constant 0.01. */
  attenuation(0.5f, 0.0f, 0.01f);
  conf_panel(&c, 0, 0, 4, 3);
  receding_points();
  attenuation(0.2f, 0.15f, 0.0f);
  conf_panel(&c, 1, 0, 4, 3);
  receding_points();
  attenuation(4.0f, 0.0f, 0.0f);
  conf_panel(&c, 2, 0, 4, 3);
  receding_points();
  attenuation(0.0f, 0.0f, 0.02f); /* a zero constant term: huge near points, clamped */
  glPointParameterf(GL_POINT_SIZE_MAX, 18.0f);
  conf_panel(&c, 3, 0, 4, 3);
  receding_points();
  glPointParameterf(GL_POINT_SIZE_MAX, 255.0f);
  /* Row 1: smooth and blended; the clamps; a fade threshold; arrays. */
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  attenuation(0.5f, 0.0f, 0.01f);
  conf_panel(&c, 0, 1, 4, 3);
  receding_points();
  glDisable(GL_POINT_SMOOTH);
  glPointParameterf(GL_POINT_SIZE_MIN, 4.0f);
  glPointParameterf(GL_POINT_SIZE_MAX, 9.0f);
  conf_panel(&c, 1, 1, 4, 3);
  receding_points();
  glPointParameterf(GL_POINT_SIZE_MIN, 0.0f);
  glPointParameterf(GL_POINT_SIZE_MAX, 255.0f);
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 12.0f);
  conf_panel(&c, 2, 1, 4, 3);
  receding_points();
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 1.0f);
  glDisable(GL_BLEND);
  attenuation(0.3f, 0.1f, 0.005f);
  conf_panel(&c, 3, 1, 4, 3);
  array_points();
  /* Row 2: polygons in point mode; a display list; the clamps without attenuation; smooth
   * points under the clamps. */
  conf_panel(&c, 0, 2, 4, 3);
  glEnable(GL_DEPTH_TEST);
  point_mode_triangles();
  glDisable(GL_DEPTH_TEST);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  attenuation(1.0f, 0.0f, 0.004f);
  glPointParameterf(GL_POINT_SIZE_MIN, 2.0f);
  receding_points();
  glEndList();
  attenuation(1.0f, 0.0f, 0.0f);
  conf_panel(&c, 1, 2, 4, 3);
  glCallList(list);
  glPointParameterf(GL_POINT_SIZE_MIN, 0.0f);
  attenuation(1.0f, 0.0f, 0.0f);
  glPointSize(8.0f);
  glPointParameterf(GL_POINT_SIZE_MAX, 3.0f);
  conf_panel(&c, 2, 2, 4, 3);
  receding_points();
  glPointParameterf(GL_POINT_SIZE_MAX, 255.0f);
  glPointParameterf(GL_POINT_SIZE_MIN, 5.0f);
  glPointSize(2.0f);
  receding_points(); /* drawn over: the minimum wins */
  glPointParameterf(GL_POINT_SIZE_MIN, 0.0f);
  glEnable(GL_POINT_SMOOTH);
  glPointSize(16.0f);
  attenuation(0.2f, 0.2f, 0.0f);
  glPointParameterf(GL_POINT_SIZE_MIN, 3.0f);
  glPointParameterf(GL_POINT_SIZE_MAX, 11.0f);
  conf_panel(&c, 3, 2, 4, 3);
  receding_points();
  glDisable(GL_POINT_SMOOTH);
  attenuation(1.0f, 0.0f, 0.0f);
  glPointParameterf(GL_POINT_SIZE_MIN, 0.0f);
  glPointParameterf(GL_POINT_SIZE_MAX, 255.0f);
  glPointSize(1.0f);
  return conf_finish(&c);
}
