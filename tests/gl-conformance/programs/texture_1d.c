/* One-dimensional textures (OpenGL 1.1 sections 3.8, 3.8.9): glTexImage1D, GL_TEXTURE_1D
 * enabled, texture objects bound to GL_TEXTURE_1D; magnification (nearest, linear) with
 * GL_REPEAT, a mipmap chain minified on a receding floor (trilinear and nearest), GL_CLAMP
 * blending in the border colour, the t coordinate ignored; which target applies when both
 * are enabled (2D when its texture is complete; 1D when the 2D texture is incomplete, as in
 * Mesa); contour stripes by object-linear and eye-linear texture generation on lit spheres
 * (the OpenGL Programming Guide's texgen example). Bindings and enables are recorded. */
#include "conf.h"

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* A quad with s from s0 to s1 across and t varying wildly (1D textures ignore it). */
static void band(float s0, float s1) {
  glBegin(GL_QUADS);
  glTexCoord2f(s0, -3.0f);
  glVertex2f(-1, -1);
  glTexCoord2f(s1, 5.0f);
  glVertex2f(1, -1);
  glTexCoord2f(s1, 0.25f);
  glVertex2f(1, 1);
  glTexCoord2f(s0, 9.0f);
  glVertex2f(-1, 1);
  glEnd();
}

static void filters(GLenum target, GLenum min, GLenum mag) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, min);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, mag);
}

/* 16 texels of saturated colours. */
static GLuint rainbow(void) {
  static const unsigned char colours[16][3] = {
      {230, 30, 30},  {240, 120, 20}, {240, 220, 20}, {120, 220, 40}, {30, 200, 60},  {20, 200, 170},
      {20, 150, 230}, {40, 60, 230},  {120, 40, 220}, {200, 40, 200}, {240, 240, 240}, {20, 20, 20},
      {128, 128, 128}, {200, 150, 100}, {100, 150, 200}, {250, 200, 210}};
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_1D, t);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, colours);
  return t;
}

/* 64 texels down to 1, each level a smooth ramp of its own tint. */
static GLuint chain(void) {
  static unsigned char level[64 * 4];
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_1D, t);
  for (int l = 0, n = 64; n >= 1; ++l, n /= 2) {
    for (int i = 0; i < n; ++i) {
      level[i * 4 + 0] = (unsigned char)(120 + 60 * ((i / 2) % 2) + 10 * l);
      level[i * 4 + 1] = (unsigned char)(90 + 15 * l);
      level[i * 4 + 2] = (unsigned char)(200 - 20 * l);
      level[i * 4 + 3] = 255;
    }
    glTexImage1D(GL_TEXTURE_1D, l, GL_RGBA, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, level);
  }
  return t;
}

static void floor_cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.4, 0.4, -0.4, 0.4, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, -1, 0);
  glRotatef(20.0f, 0, 1, 0);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex3f(-2, 0, -1);
  glTexCoord2f(0, 1);
  glVertex3f(2, 0, -1);
  glTexCoord2f(24, 1);
  glVertex3f(2, 0, -30);
  glTexCoord2f(24, 0);
  glVertex3f(-2, 0, -30);
  glEnd();
}

static void lit_sphere_cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.1, 1.1, -1.1, 1.1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat light[4] = {0.3f, 0.6f, 1.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);  /* the sphere's far side is drawn too */
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 192)) return 1;
  glClearColor(0.1f, 0.12f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_TEXTURE_1D);
  GLint v = -1;
  glGetIntegerv(GL_TEXTURE_1D, &v);
  conf_value(&c, "GL_TEXTURE_1D enabled", v);

  GLuint bands = rainbow();
  glGetIntegerv(GL_TEXTURE_BINDING_1D, &v);
  conf_value(&c, "binding 1D", v == (GLint)bands);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &v);
  conf_value(&c, "binding 2D", v);
  cell(&c, 0, 0);
  filters(GL_TEXTURE_1D, GL_NEAREST, GL_NEAREST);
  glRotatef(4.0f, 0, 0, 1);
  band(-0.3f, 1.7f);
  cell(&c, 1, 0);
  filters(GL_TEXTURE_1D, GL_LINEAR, GL_LINEAR);
  glRotatef(-3.0f, 0, 0, 1);
  band(-0.3f, 1.7f);
  cell(&c, 2, 0);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_T, GL_CLAMP); /* ignored by 1D textures */
  const GLfloat border[4] = {1.0f, 0.9f, 0.1f, 1.0f};
  glTexParameterfv(GL_TEXTURE_1D, GL_TEXTURE_BORDER_COLOR, border);
  band(-0.45f, 1.55f);
  cell(&c, 3, 0);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  band(-0.45f, 1.55f);

  GLuint mips = chain();
  filters(GL_TEXTURE_1D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  floor_cell(&c, 0, 1);
  filters(GL_TEXTURE_1D, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
  floor_cell(&c, 1, 1);

  /* Both targets enabled: a complete 2D texture wins; an incomplete one gives way to 1D. */
  static const unsigned char two_d[4 * 3] = {250, 250, 250, 20, 20, 20, 20, 20, 20, 250, 250, 250};
  GLuint square;
  glGenTextures(1, &square);
  glBindTexture(GL_TEXTURE_2D, square);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, two_d);
  filters(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST);
  glBindTexture(GL_TEXTURE_1D, bands);
  filters(GL_TEXTURE_1D, GL_NEAREST, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  cell(&c, 2, 1);
  band(0.0f, 1.0f);
  filters(GL_TEXTURE_2D, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST); /* incomplete now */
  cell(&c, 3, 1);
  band(0.0f, 1.0f);
  glDisable(GL_TEXTURE_2D);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &v);
  conf_value(&c, "binding 2D after", v == (GLint)square);

  /* Contour stripes: object linear and eye linear generation of s on lit spheres. */
  static unsigned char stripes[32 * 3];
  for (int i = 0; i < 32; ++i) {
    stripes[i * 3 + 0] = i < 4 ? 255 : 40;
    stripes[i * 3 + 1] = i < 4 ? 40 : 180;
    stripes[i * 3 + 2] = i < 4 ? 40 : 230;
  }
  GLuint contour;
  glGenTextures(1, &contour);
  glBindTexture(GL_TEXTURE_1D, contour);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, stripes);
  filters(GL_TEXTURE_1D, GL_LINEAR, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  const GLfloat plane[4] = {1.5f, 1.5f, 1.5f, 0.0f};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  glEnable(GL_TEXTURE_GEN_S);
  lit_sphere_cell(&c, 0, 2);
  glRotatef(30.0f, 1, 0, 0);
  conf_sphere(1.0f, 32, 16);
  lit_sphere_cell(&c, 1, 2);
  glRotatef(60.0f, 0, 1, 0);
  glScalef(1.0f, 0.7f, 1.0f);
  conf_sphere(1.0f, 32, 16);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  lit_sphere_cell(&c, 2, 2);
  glTexGenfv(GL_S, GL_EYE_PLANE, plane); /* taken through this modelview */
  glRotatef(45.0f, 0, 0, 1);
  conf_sphere(1.0f, 32, 16);
  lit_sphere_cell(&c, 3, 2);
  glRotatef(70.0f, 0, 1, 0);
  conf_sphere(1.0f, 32, 16);
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_LIGHTING);
  conf_value(&c, "IsTexture 1D", glIsTexture(contour));

  glDeleteTextures(1, &bands);
  glDeleteTextures(1, &mips);
  glDeleteTextures(1, &square);
  glDeleteTextures(1, &contour);
  glGetIntegerv(GL_TEXTURE_BINDING_1D, &v);
  conf_value(&c, "binding 1D after delete", v);
  return conf_finish(&c);
}
