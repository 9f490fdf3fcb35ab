/* The accumulation buffer (GL 1.1 section 4.2.4), on a context asked for 16 accumulation bits:
 * scene antialiasing by jittered orthographic views (the Red Book's accanti) and by jittered
 * frustums with depth of field (accpersp / dof), motion blur (GL_MULT then GL_ACCUM per frame),
 * and every operation on colour bars: GL_LOAD, GL_ACCUM, GL_ADD (up and down), GL_MULT,
 * GL_RETURN with values that clamp above 1 and below 0, glClearAccum with negative values,
 * glClear(GL_ACCUM_BUFFER_BIT), the colour mask on GL_RETURN. Each technique uses the whole
 * buffer; its result is read back and the four are put together at the end. The values stay
 * inside the buffer's range [-1, 1] (what happens outside it is undefined). The bottom row
 * holds glGet results and error codes as pixels. */
#include <stdlib.h>
#include <string.h>

#include "conf.h"

enum { kW = 256, kH = 256, kP = 128 };

static const float kJitter[8][2] = {
    {-0.334818f, 0.435331f}, {0.286438f, -0.393495f}, {0.459462f, 0.141540f}, {-0.414498f, -0.192829f},
    {-0.183790f, 0.082102f}, {-0.079263f, -0.317383f}, {0.102254f, 0.299133f}, {0.164216f, -0.054399f}};

static unsigned char* panels[4];

static void save(int i) {
  panels[i] = (unsigned char*)malloc(kP * kP * 4);
  glReadPixels(0, 0, kP, kP, GL_RGBA, GL_UNSIGNED_BYTE, panels[i]);
}

static void lights(void) {
  const GLfloat pos[4] = {0.5f, 1.0f, 1.0f, 0.0f}, spec[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHTING);
  glEnable(GL_DEPTH_TEST);
}

static void material(float r, float g, float b) {
  const GLfloat dif[4] = {r, g, b, 1.0f}, spec[4] = {0.6f, 0.6f, 0.6f, 1.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, dif);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
}

/* Three objects with sharp edges: a sphere, a tilted wall, a tube. */
static void objects(void) {
  glPushMatrix();
  glTranslatef(-0.4f, 0.3f, -0.2f);
  material(0.9f, 0.3f, 0.2f);
  conf_sphere(0.45f, 20, 10);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0.35f, -0.2f, 0.1f);
  glRotatef(35.0f, 1.0f, 0.2f, 0.0f);
  glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
  material(0.2f, 0.8f, 0.3f);
  conf_wall(0.7f, 0.5f, 2);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0.2f, 0.25f, -0.6f);
  glRotatef(50.0f, 0.0f, 0.0f, 1.0f);
  material(0.3f, 0.4f, 0.9f);
  conf_tube(0.2f, 0.9f, 16);
  glPopMatrix();
}

static void accanti(void) {
  glViewport(0, 0, kP, kP);
  glClear(GL_ACCUM_BUFFER_BIT);
  for (int j = 0; j < 8; ++j) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, -2, 2);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(kJitter[j][0] * 2.0f / kP, kJitter[j][1] * 2.0f / kP, 0.0f);
    objects();
    glAccum(GL_ACCUM, 1.0f / 8.0f);
  }
  glAccum(GL_RETURN, 1.0f);
  save(0);
}

/* The Red Book's accFrustum: a frustum moved by a fraction of a pixel and an eye offset. */
static void acc_frustum(double px, double py, double eyedx, double eyedy, double focus) {
  const double l = -0.5, r = 0.5, b = -0.5, t = 0.5, n = 1.0, f = 10.0;
  double dx = -(px * (r - l) / kP + eyedx * n / focus), dy = -(py * (t - b) / kP + eyedy * n / focus);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(l + dx, r + dx, b + dy, t + dy, n, f);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef((float)-eyedx, (float)-eyedy, 0.0f);
}

static void accpersp_dof(void) {
  glViewport(0, 0, kP, kP);
  glClear(GL_ACCUM_BUFFER_BIT);
  for (int j = 0; j < 8; ++j) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    acc_frustum(kJitter[j][0], kJitter[j][1], 0.04 * kJitter[j][0], 0.04 * kJitter[j][1], 2.6);
    glTranslatef(0.0f, 0.0f, -2.6f);
    objects();
    glAccum(GL_ACCUM, 0.125f);
  }
  glAccum(GL_RETURN, 1.0f);
  save(1);
}

static void motion_blur(void) {
  glViewport(0, 0, kP, kP);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glClear(GL_ACCUM_BUFFER_BIT);
  for (int frame = 0; frame < 10; ++frame) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(-0.7f + 0.12f * frame, 0.08f * frame - 0.4f, 0.0f);
    glRotatef(12.0f * frame, 0.0f, 0.0f, 1.0f);
    objects();
    glAccum(GL_MULT, 0.7f);
    glAccum(GL_ACCUM, 0.3f);
  }
  glAccum(GL_RETURN, 1.0f);
  save(2);
}

static void bars(float shift) {
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 1, 0, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 8; ++i) {
    float x0 = i / 8.0f, x1 = (i + 1) / 8.0f, v = (i + shift) / 8.0f;
    glColor4f(v, 1.0f - v, 0.5f * v + 0.25f, 0.9f - 0.1f * i);
    glVertex2f(x0, 0);
    glVertex2f(x1, 0);
    glColor4f(1.0f - v, v, 0.3f, 0.2f + 0.1f * i);
    glVertex2f(x1, 1);
    glVertex2f(x0, 0);
    glVertex2f(x1, 1);
    glVertex2f(x0, 1);
  }
  glEnd();
}

/* Each operation in four horizontal strips of the panel. */
static void operations(void) {
  static unsigned char strip[kP * 32 * 4];
  unsigned char* out = (unsigned char*)malloc(kP * kP * 4);
  glViewport(0, 0, kP, kP);
  for (int s = 0; s < 4; ++s) {
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    bars(0.0f);
    if (s == 0) {  /* LOAD, ACCUM, ADD down, MULT up, RETURN above 1 */
      glAccum(GL_LOAD, 0.5f);
      bars(3.0f);
      glAccum(GL_ACCUM, 0.25f);
      glAccum(GL_ADD, -0.1f);
      glAccum(GL_MULT, 1.5f);
      glAccum(GL_RETURN, 1.25f);
    } else if (s == 1) {  /* negative clear value, GL_ADD up, GL_RETURN with a negative value */
      glClearAccum(-0.6f, 0.3f, -0.2f, -1.5f);
      glClear(GL_ACCUM_BUFFER_BIT);
      glAccum(GL_ACCUM, 0.5f);
      glAccum(GL_ADD, 0.05f);
      glAccum(GL_RETURN, -1.0f);
    } else if (s == 2) {  /* the colour mask on GL_RETURN */
      glAccum(GL_LOAD, 0.8f);
      glClear(GL_COLOR_BUFFER_BIT);
      bars(5.0f);
      glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
      glAccum(GL_RETURN, 1.0f);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    } else {  /* GL_MULT down, then a second return over what is there */
      glClearAccum(0.25f, 0.5f, 0.75f, 1.0f);
      glClear(GL_ACCUM_BUFFER_BIT);
      glAccum(GL_MULT, 0.3f);
      glAccum(GL_ACCUM, 0.6f);
      glAccum(GL_RETURN, 1.0f);
      glAccum(GL_ADD, 0.05f);
      glAccum(GL_RETURN, 0.5f);
    }
    glReadPixels(0, s * 32, kP, 32, GL_RGBA, GL_UNSIGNED_BYTE, strip);
    memcpy(out + (size_t)s * 32 * kP * 4, strip, sizeof strip);
  }
  glClearAccum(0, 0, 0, 0);
  panels[3] = out;
}

static GLubyte error_code(void) {
  GLenum e = glGetError();
  return (GLubyte)(e == GL_NO_ERROR ? 0 : e - GL_INVALID_ENUM + 1);
}

/* Queries and errors as pixels in the bottom row. */
static void state_row(GLubyte row[16 * 4]) {
  GLint bits[4];
  GLfloat clear[4];
  glGetIntegerv(GL_ACCUM_RED_BITS, &bits[0]);
  glGetIntegerv(GL_ACCUM_GREEN_BITS, &bits[1]);
  glGetIntegerv(GL_ACCUM_BLUE_BITS, &bits[2]);
  glGetIntegerv(GL_ACCUM_ALPHA_BITS, &bits[3]);
  glClearAccum(2.0f, -3.0f, 0.5f, -0.25f);
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, clear);
  glClearAccum(0, 0, 0, 0);
  glAccum(0x1234, 1.0f);
  GLubyte e1 = error_code();
  glBegin(GL_TRIANGLES);
  glAccum(GL_RETURN, 1.0f);
  glEnd();
  GLubyte e2 = error_code();
  memset(row, 255, 16 * 4);
  for (int i = 0; i < 4; ++i) {
    row[i * 4] = (GLubyte)(bits[i] * 8);
    row[16 + i * 4] = (GLubyte)((clear[i] + 1.0f) * 120.0f);
  }
  row[32] = (GLubyte)(e1 * 40), row[36] = (GLubyte)(e2 * 40);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init_accum(&c, argc, argv, kW, kH, 16)) return 1;
  glClearColor(0.05f, 0.05f, 0.08f, 1.0f);
  lights();
  accanti();
  accpersp_dof();
  motion_blur();
  operations();
  GLubyte row[16 * 4];
  state_row(row);
  glViewport(0, 0, kW, kH);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  for (int i = 0; i < 4; ++i) {
    glRasterPos2i((i % 2) * kP, (i / 2) * kP);
    glDrawPixels(kP, kP, GL_RGBA, GL_UNSIGNED_BYTE, panels[i]);
    free(panels[i]);
  }
  glPixelZoom(4.0f, 4.0f);
  glRasterPos2i(0, 0);
  glDrawPixels(16, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
  glPixelZoom(1.0f, 1.0f);
  return conf_finish(&c);
}
