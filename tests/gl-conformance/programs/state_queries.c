/* State queries and errors (no rendering under test): each check is a cell of an 8 x 5 grid,
 * green when the implementation answers as OpenGL 1.1 says, red when not; the failing checks
 * are also printed. Covers glGetLightfv (positions and spot directions stored in eye space,
 * defaults), glGetMaterialfv defaults, glGet{Booleanv,Integerv,Floatv,Doublev}, glIsEnabled,
 * glGetString, GL_INVALID_ENUM / GL_INVALID_VALUE / GL_INVALID_OPERATION with the state left
 * unchanged, GL_STACK_OVERFLOW / GL_STACK_UNDERFLOW at the limits reported by glGet, calls with
 * no current context, OSMesaGetCurrentContext, OSMesaGetIntegerv and OSMesaGetDepthBuffer. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "conf.h"

static int n_checks = 0, n_failed = 0;
static int results[40];

static void check(int ok, const char* what) {
  if (!ok) {
    ++n_failed;
    printf("check %d FAILED: %s\n", n_checks, what);
  }
  if (n_checks < 40) results[n_checks] = ok;
  ++n_checks;
}

static int near4(const GLfloat* a, float x, float y, float z, float w) {
  return fabsf(a[0] - x) < 1e-5f && fabsf(a[1] - y) < 1e-5f && fabsf(a[2] - z) < 1e-5f &&
         fabsf(a[3] - w) < 1e-5f;
}

static int got_error(GLenum expected) {
  GLenum e = glGetError();
  int ok = e == expected;
  if (!ok) printf("  glGetError() = 0x%04x, expected 0x%04x\n", e, expected);
  while (glGetError() != GL_NO_ERROR) {
  }
  return ok;
}

static void light_checks(void) {
  GLfloat v[4];
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glPushMatrix();
  glTranslatef(1.0f, 0.0f, 0.0f);
  const GLfloat pos[] = {1, 2, 3, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glRotatef(90.0f, 0, 1, 0);
  const GLfloat dir[] = {0, 0, -1};
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, dir);
  glPopMatrix();
  glGetLightfv(GL_LIGHT0, GL_POSITION, v);
  check(near4(v, 2, 2, 3, 1), "GL_POSITION is stored in eye space: (2, 2, 3, 1)");
  v[3] = 0;
  glGetLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, v);
  check(near4(v, -1, 0, 0, 0), "GL_SPOT_DIRECTION is stored in eye space: (-1, 0, 0)");
  glGetLightfv(GL_LIGHT1, GL_DIFFUSE, v);
  GLfloat w[4];
  glGetLightfv(GL_LIGHT0, GL_DIFFUSE, w);
  check(near4(v, 0, 0, 0, 1) && near4(w, 1, 1, 1, 1), "default light diffuse colours");
  glGetLightfv(GL_LIGHT2, GL_SPOT_CUTOFF, v);
  glGetLightfv(GL_LIGHT2, GL_CONSTANT_ATTENUATION, w);
  check(v[0] == 180.0f && w[0] == 1.0f, "default cutoff 180 and constant attenuation 1");
  glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 100.0f);
  int e1 = got_error(GL_INVALID_VALUE);
  glGetLightfv(GL_LIGHT2, GL_SPOT_CUTOFF, v);
  check(e1 && v[0] == 180.0f, "cutoff 100: GL_INVALID_VALUE, cutoff unchanged");
  glLightf(GL_LIGHT2, GL_LINEAR_ATTENUATION, -1.0f);
  int e2 = got_error(GL_INVALID_VALUE);
  glGetLightfv(GL_LIGHT2, GL_LINEAR_ATTENUATION, v);
  check(e2 && v[0] == 0.0f, "negative attenuation: GL_INVALID_VALUE, unchanged");
  GLint max_lights = 0;
  glGetIntegerv(GL_MAX_LIGHTS, &max_lights);
  glLightf(GL_LIGHT0 + max_lights, GL_SPOT_EXPONENT, 1.0f);
  check(max_lights >= 8 && got_error(GL_INVALID_ENUM), "GL_MAX_LIGHTS >= 8, light beyond: enum");
}

static void material_checks(void) {
  GLfloat v[4], w[4];
  glGetMaterialfv(GL_FRONT, GL_AMBIENT, v);
  glGetMaterialfv(GL_BACK, GL_DIFFUSE, w);
  check(near4(v, 0.2f, 0.2f, 0.2f, 1) && near4(w, 0.8f, 0.8f, 0.8f, 1), "default material");
  glMaterialf(GL_FRONT, GL_SHININESS, 50.0f);
  glMaterialf(GL_FRONT, GL_SHININESS, 129.0f);
  int e = got_error(GL_INVALID_VALUE);
  glGetMaterialfv(GL_FRONT, GL_SHININESS, v);
  check(e && v[0] == 50.0f, "shininess 129: GL_INVALID_VALUE, shininess unchanged");
  const GLfloat em[] = {0.25f, 0.5f, 0.75f, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, em);
  glGetMaterialfv(GL_BACK, GL_EMISSION, v);
  check(near4(v, 0.25f, 0.5f, 0.75f, 1), "GL_FRONT_AND_BACK emission read back from GL_BACK");
  GLint face = 0, mode = 0;
  glColorMaterial(GL_BACK, GL_SPECULAR);
  glGetIntegerv(GL_COLOR_MATERIAL_FACE, &face);
  glGetIntegerv(GL_COLOR_MATERIAL_PARAMETER, &mode);
  check(face == GL_BACK && mode == GL_SPECULAR, "glColorMaterial state");
}

static void enable_checks(void) {
  glEnable(GL_LIGHTING);
  check(glIsEnabled(GL_LIGHTING) && !glIsEnabled(GL_NORMALIZE) && !glIsEnabled(GL_DEPTH_TEST),
        "glIsEnabled after glEnable(GL_LIGHTING), defaults off");
  glEnable(0x1234);
  check(got_error(GL_INVALID_ENUM), "glEnable(0x1234): GL_INVALID_ENUM");
  glBegin(GL_TRIANGLES);
  glEnable(GL_DEPTH_TEST); /* not allowed between glBegin and glEnd */
  glEnd();
  check(got_error(GL_INVALID_OPERATION) && !glIsEnabled(GL_DEPTH_TEST),
        "glEnable between glBegin/glEnd: GL_INVALID_OPERATION, unchanged");
  glBegin(GL_TRIANGLES);
  glBegin(GL_TRIANGLES);
  glEnd();
  check(got_error(GL_INVALID_OPERATION), "nested glBegin: GL_INVALID_OPERATION");
  glEnd();
  check(got_error(GL_INVALID_OPERATION), "glEnd without glBegin: GL_INVALID_OPERATION");
  glBegin(0x1234);
  check(got_error(GL_INVALID_ENUM), "glBegin(0x1234): GL_INVALID_ENUM");
  glDrawArrays(GL_TRIANGLES, 0, -1);
  check(got_error(GL_INVALID_VALUE), "glDrawArrays count -1: GL_INVALID_VALUE");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_REPEAT);
  check(got_error(GL_INVALID_ENUM), "GL_TEXTURE_MIN_FILTER GL_REPEAT: GL_INVALID_ENUM");
}

static void stack_checks(void) {
  GLint max_mv = 0, max_proj = 0, depth = 0;
  glGetIntegerv(GL_MAX_MODELVIEW_STACK_DEPTH, &max_mv);
  glGetIntegerv(GL_MAX_PROJECTION_STACK_DEPTH, &max_proj);
  check(max_mv >= 32 && max_proj >= 2, "stack limits (modelview >= 32, projection >= 2)");
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(1, 2, 3);
  for (int i = 1; i < max_mv; ++i) glPushMatrix();
  glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
  int no_error = got_error(GL_NO_ERROR);
  glPushMatrix();
  check(no_error && depth == max_mv && got_error(GL_STACK_OVERFLOW),
        "modelview push beyond the limit: GL_STACK_OVERFLOW");
  for (int i = 1; i < max_mv; ++i) glPopMatrix();
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  glPopMatrix();
  check(got_error(GL_STACK_UNDERFLOW) && m[12] == 1 && m[13] == 2 && m[14] == 3 && m[0] == 1,
        "pop at depth 1: GL_STACK_UNDERFLOW; GL_MODELVIEW_MATRIX kept");
  glMatrixMode(GL_PROJECTION);
  for (int i = 1; i < max_proj; ++i) glPushMatrix();
  glPushMatrix();
  int overflow = got_error(GL_STACK_OVERFLOW);
  for (int i = 1; i < max_proj; ++i) glPopMatrix();
  glGetIntegerv(GL_PROJECTION_STACK_DEPTH, &depth);
  check(overflow && depth == 1, "projection stack overflow and depth");
  glMatrixMode(GL_MODELVIEW);
}

static void get_checks(ConfContext* c) {
  GLint vp[4];
  glViewport(3, 4, 50, 60);
  glGetIntegerv(GL_VIEWPORT, vp);
  check(vp[0] == 3 && vp[1] == 4 && vp[2] == 50 && vp[3] == 60, "GL_VIEWPORT");
  glViewport(0, 0, c->width, c->height);
  GLboolean b = GL_TRUE;
  glDepthMask(GL_FALSE);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &b);
  glDepthMask(GL_TRUE);
  check(b == GL_FALSE, "GL_DEPTH_WRITEMASK");
  GLdouble r[2] = {0, 0};
  glDepthRange(0.25, 0.75);
  glGetDoublev(GL_DEPTH_RANGE, r);
  glDepthRange(0.0, 1.0);
  check(r[0] == 0.25 && r[1] == 0.75, "GL_DEPTH_RANGE as doubles");
  GLfloat col[4];
  glColor4ub(255, 0, 51, 102);
  glGetFloatv(GL_CURRENT_COLOR, col);
  check(near4(col, 1.0f, 0.0f, 0.2f, 0.4f), "glColor4ub read back as floats");
  GLint bits[3];
  glGetIntegerv(GL_RED_BITS, &bits[0]);
  glGetIntegerv(GL_DEPTH_BITS, &bits[1]);
  glGetIntegerv(GL_STENCIL_BITS, &bits[2]);
  check(bits[0] == 8 && bits[1] >= 16 && bits[2] >= 8, "GL_RED_BITS 8, depth >= 16, stencil >= 8");
  const char* version = (const char*)glGetString(GL_VERSION);
  check(version && version[0] >= '1' && version[0] <= '9' && version[1] == '.',
        "glGetString(GL_VERSION) is 'major.minor ...'");
  GLint fmt = 0, w = 0, h = 0, yup = 0;
  OSMesaGetIntegerv(OSMESA_WIDTH, &w);
  OSMesaGetIntegerv(OSMESA_HEIGHT, &h);
  OSMesaGetIntegerv(OSMESA_FORMAT, &fmt);
  OSMesaGetIntegerv(OSMESA_Y_UP, &yup);
  check(OSMesaGetCurrentContext() == c->ctx && w == c->width && h == c->height &&
            fmt == OSMESA_RGBA && yup == 1,
        "OSMesaGetCurrentContext and OSMesaGetIntegerv");
  GLint dw = 0, dh = 0, bpv = 0;
  void* depth_buffer = NULL;
  GLboolean ok = OSMesaGetDepthBuffer(c->ctx, &dw, &dh, &bpv, &depth_buffer);
  check(ok && depth_buffer && dw == c->width && dh == c->height && bpv >= 2,
        "OSMesaGetDepthBuffer");
}

static void no_context_checks(ConfContext* c) {
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  int none = OSMesaGetCurrentContext() == NULL;
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f); /* no current context: nothing happens */
  glEnable(GL_BLEND);
  OSMesaMakeCurrent(c->ctx, c->buffer, GL_UNSIGNED_BYTE, c->width, c->height);
  GLfloat v[4];
  glGetFloatv(GL_COLOR_CLEAR_VALUE, v);
  check(none && near4(v, 0, 0, 0, 1) && !glIsEnabled(GL_BLEND) && got_error(GL_NO_ERROR),
        "calls without a current context change nothing");
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 255)) return 1;
  check(got_error(GL_NO_ERROR), "no error at start");
  light_checks();
  material_checks();
  enable_checks();
  stack_checks();
  get_checks(&c);
  no_context_checks(&c);
  printf("%d checks, %d failed\n", n_checks, n_failed);

  /* The picture: one cell per check, green or red; grey where there is no check. */
  glDisable(GL_LIGHTING);
  glClearColor(0.2f, 0.2f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  for (int i = 0; i < n_checks && i < 40; ++i) {
    conf_panel(&c, i % 8, i / 8, 8, 5);
    glColor3f(results[i] ? 0.1f : 0.9f, results[i] ? 0.8f : 0.1f, 0.1f);
    glBegin(GL_QUADS);
    glVertex2f(0.1f, 0.1f);
    glVertex2f(0.9f, 0.1f);
    glVertex2f(0.9f, 0.9f);
    glVertex2f(0.1f, 0.9f);
    glEnd();
  }
  return conf_finish(&c);
}
