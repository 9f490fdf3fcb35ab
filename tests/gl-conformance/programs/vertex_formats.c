/* Every vertex-specification command of OpenGL 1.1 in every type and size (sections 2.7, 2.9),
 * drawn in 128 panels and compared with Mesa: glVertex{2,3,4}{s,i,f,d}[v] (w = 2 for the
 * four-component forms), glColor{3,4}{b,s,i,f,d,ub,us,ui}[v] with values across each type's
 * range (negative ones clamp), glNormal3{b,s,i,f,d}[v] on lit fans, glTexCoord{1,2,3,4}{s,i,f,d}[v]
 * on a checker texture (r reaches t through the texture matrix, q = 2 throughout a draw),
 * glRect{s,i,f,d}[v]. The current colour, normal, texture coordinates and index after
 * extreme values of every type (glIndex* included, which colours nothing in RGBA) are printed
 * to NAME.txt and compared with Mesa's exactly. */
#include <math.h>
#include <stdio.h>

#include "conf.h"

enum { kCols = 16, kRows = 8 };
static FILE* out;
static int panel_index = 0;
static const ConfContext* ctx;

static void next_panel(void) {
  conf_panel(ctx, panel_index % kCols, panel_index / kCols, kCols, kRows);
  ++panel_index;
}

/* ---- glVertex: a fan of 6 triangles with integer coordinates in [-8, 8]. ---- */

static const int kStar[8][2] = {{0, 0}, {8, 0}, {4, 7}, {-4, 7}, {-8, 0}, {-4, -7}, {4, -7}, {8, 0}};

static void vertex_form(int form, int x, int y) {
  /* form: size 2..4 (form / 8), type s i f d (form / 2 % 4), vector (form % 2) */
  int size = 2 + form / 8, type = form / 2 % 4, vec = form % 2;
  int m = size == 4 ? 2 : 1; /* w = 2: coordinates doubled */
  GLshort s[4] = {(GLshort)(x * m), (GLshort)(y * m), (GLshort)(-m), (GLshort)m};
  GLint i[4] = {x * m, y * m, -m, m};
  GLfloat f[4] = {(GLfloat)(x * m), (GLfloat)(y * m), (GLfloat)-m, (GLfloat)m};
  GLdouble d[4] = {x * m, y * m, -m, m};
  switch (size * 100 + type * 10 + vec) {
    case 200: glVertex2s(s[0], s[1]); break;
    case 201: glVertex2sv(s); break;
    case 210: glVertex2i(i[0], i[1]); break;
    case 211: glVertex2iv(i); break;
    case 220: glVertex2f(f[0], f[1]); break;
    case 221: glVertex2fv(f); break;
    case 230: glVertex2d(d[0], d[1]); break;
    case 231: glVertex2dv(d); break;
    case 300: glVertex3s(s[0], s[1], s[2]); break;
    case 301: glVertex3sv(s); break;
    case 310: glVertex3i(i[0], i[1], i[2]); break;
    case 311: glVertex3iv(i); break;
    case 320: glVertex3f(f[0], f[1], f[2]); break;
    case 321: glVertex3fv(f); break;
    case 330: glVertex3d(d[0], d[1], d[2]); break;
    case 331: glVertex3dv(d); break;
    case 400: glVertex4s(s[0], s[1], s[2], s[3]); break;
    case 401: glVertex4sv(s); break;
    case 410: glVertex4i(i[0], i[1], i[2], i[3]); break;
    case 411: glVertex4iv(i); break;
    case 420: glVertex4f(f[0], f[1], f[2], f[3]); break;
    case 421: glVertex4fv(f); break;
    case 430: glVertex4d(d[0], d[1], d[2], d[3]); break;
    case 431: glVertex4dv(d); break;
  }
}

static void vertex_panels(void) {
  for (int form = 0; form < 24; ++form) {
    next_panel();
    glBegin(GL_TRIANGLE_FAN);
    for (int k = 0; k < 8; ++k) {
      glColor3f(0.2f + 0.1f * k, 1.0f - 0.1f * k, 0.5f + 0.05f * (form % 8));
      vertex_form(form, kStar[k][0], kStar[k][1]);
    }
    glEnd();
  }
}

/* ---- glColor: a quad of two triangles, four colours given as fractions of each type. ---- */

static const float kQuadColors[4][4] = {
    {1.0f, 0.0f, 0.25f, 1.0f}, {-0.5f, 1.0f, 0.5f, 0.75f}, {0.3f, 0.6f, 1.0f, 0.5f}, {0.0f, -1.0f, 0.8f, 0.25f}};

static void color_form(int form, const float* c) {
  /* form: size 3 or 4 (form / 16), type b s i f d ub us ui (form / 2 % 8), vector (form % 2) */
  int size = 3 + form / 16, type = form / 2 % 8, vec = form % 2;
  GLbyte b[4];
  GLshort s[4];
  GLint i[4];
  GLfloat f[4];
  GLdouble d[4];
  GLubyte ub[4];
  GLushort us[4];
  GLuint ui[4];
  for (int k = 0; k < 4; ++k) {
    double v = c[k], u = v < 0.0 ? 0.0 : v;
    b[k] = (GLbyte)lround(v * 127.0), s[k] = (GLshort)lround(v * 32767.0), i[k] = (GLint)lround(v * 2147483647.0);
    f[k] = (GLfloat)v, d[k] = v;
    ub[k] = (GLubyte)lround(u * 255.0), us[k] = (GLushort)lround(u * 65535.0), ui[k] = (GLuint)llround(u * 4294967295.0);
  }
  switch (size * 100 + type * 10 + vec) {
    case 300: glColor3b(b[0], b[1], b[2]); break;
    case 301: glColor3bv(b); break;
    case 310: glColor3s(s[0], s[1], s[2]); break;
    case 311: glColor3sv(s); break;
    case 320: glColor3i(i[0], i[1], i[2]); break;
    case 321: glColor3iv(i); break;
    case 330: glColor3f(f[0], f[1], f[2]); break;
    case 331: glColor3fv(f); break;
    case 340: glColor3d(d[0], d[1], d[2]); break;
    case 341: glColor3dv(d); break;
    case 350: glColor3ub(ub[0], ub[1], ub[2]); break;
    case 351: glColor3ubv(ub); break;
    case 360: glColor3us(us[0], us[1], us[2]); break;
    case 361: glColor3usv(us); break;
    case 370: glColor3ui(ui[0], ui[1], ui[2]); break;
    case 371: glColor3uiv(ui); break;
    case 400: glColor4b(b[0], b[1], b[2], b[3]); break;
    case 401: glColor4bv(b); break;
    case 410: glColor4s(s[0], s[1], s[2], s[3]); break;
    case 411: glColor4sv(s); break;
    case 420: glColor4i(i[0], i[1], i[2], i[3]); break;
    case 421: glColor4iv(i); break;
    case 430: glColor4f(f[0], f[1], f[2], f[3]); break;
    case 431: glColor4fv(f); break;
    case 440: glColor4d(d[0], d[1], d[2], d[3]); break;
    case 441: glColor4dv(d); break;
    case 450: glColor4ub(ub[0], ub[1], ub[2], ub[3]); break;
    case 451: glColor4ubv(ub); break;
    case 460: glColor4us(us[0], us[1], us[2], us[3]); break;
    case 461: glColor4usv(us); break;
    case 470: glColor4ui(ui[0], ui[1], ui[2], ui[3]); break;
    case 471: glColor4uiv(ui); break;
  }
}

static void color_panels(void) {
  static const int corner[4][2] = {{-8, -8}, {8, -8}, {8, 8}, {-8, 8}};
  static const int order[6] = {0, 1, 2, 0, 2, 3};
  glEnable(GL_BLEND); /* alpha shows in the image */
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int form = 0; form < 32; ++form) {
    next_panel();
    glBegin(GL_TRIANGLES);
    for (int k = 0; k < 6; ++k) {
      color_form(form, kQuadColors[order[k]]);
      glVertex2i(corner[order[k]][0], corner[order[k]][1]);
    }
    glEnd();
  }
  glDisable(GL_BLEND);
}

/* ---- glNormal3: a lit fan whose normals lean outwards. ---- */

static void normal_form(int form, const double* n) {
  GLbyte b[3];
  GLshort s[3];
  GLint i[3];
  GLfloat f[3];
  for (int k = 0; k < 3; ++k) {
    b[k] = (GLbyte)lround(n[k] * 127.0), s[k] = (GLshort)lround(n[k] * 32767.0);
    i[k] = (GLint)lround(n[k] * 2147483647.0), f[k] = (GLfloat)n[k];
  }
  switch (form) {
    case 0: glNormal3b(b[0], b[1], b[2]); break;
    case 1: glNormal3bv(b); break;
    case 2: glNormal3s(s[0], s[1], s[2]); break;
    case 3: glNormal3sv(s); break;
    case 4: glNormal3i(i[0], i[1], i[2]); break;
    case 5: glNormal3iv(i); break;
    case 6: glNormal3f(f[0], f[1], f[2]); break;
    case 7: glNormal3fv(f); break;
    case 8: glNormal3d(n[0], n[1], n[2]); break;
    case 9: glNormal3dv(n); break;
  }
}

static void normal_panels(void) {
  const GLfloat light_pos[4] = {0.3f, 0.5f, 1.0f, 0.0f}, diffuse[4] = {1.0f, 0.8f, 0.4f, 1.0f};
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  for (int form = 0; form < 10; ++form) {
    next_panel();
    glBegin(GL_TRIANGLE_FAN);
    for (int k = 0; k < 8; ++k) {
      double a = atan2(kStar[k][1], kStar[k][0]), r = k == 0 ? 0.0 : 0.8;
      double n[3] = {r * cos(a), r * sin(a), sqrt(1.0 - r * r)};
      normal_form(form, n);
      glVertex2i(kStar[k][0], kStar[k][1]);
    }
    glEnd();
  }
  glDisable(GL_LIGHTING);
}

/* ---- glTexCoord: integer texel coordinates, scaled by the texture matrix. ---- */

static void texcoord_form(int form, int s0, int t0) {
  /* form: size 1..4 (form / 8), type s i f d (form / 2 % 4), vector (form % 2). Size 3 puts t
   * into r (the texture matrix moves it back); size 4 doubles everything with q = 2. */
  int size = 1 + form / 8, type = form / 2 % 4, vec = form % 2;
  int m = size == 4 ? 2 : 1;
  int v[4] = {s0 * m, size == 3 ? 0 : t0 * m, size == 3 ? t0 : 0, m};
  GLshort s[4];
  GLint i[4];
  GLfloat f[4];
  GLdouble d[4];
  for (int k = 0; k < 4; ++k) s[k] = (GLshort)v[k], i[k] = v[k], f[k] = (GLfloat)v[k], d[k] = v[k];
  switch (size * 100 + type * 10 + vec) {
    case 100: glTexCoord1s(s[0]); break;
    case 101: glTexCoord1sv(s); break;
    case 110: glTexCoord1i(i[0]); break;
    case 111: glTexCoord1iv(i); break;
    case 120: glTexCoord1f(f[0]); break;
    case 121: glTexCoord1fv(f); break;
    case 130: glTexCoord1d(d[0]); break;
    case 131: glTexCoord1dv(d); break;
    case 200: glTexCoord2s(s[0], s[1]); break;
    case 201: glTexCoord2sv(s); break;
    case 210: glTexCoord2i(i[0], i[1]); break;
    case 211: glTexCoord2iv(i); break;
    case 220: glTexCoord2f(f[0], f[1]); break;
    case 221: glTexCoord2fv(f); break;
    case 230: glTexCoord2d(d[0], d[1]); break;
    case 231: glTexCoord2dv(d); break;
    case 300: glTexCoord3s(s[0], s[1], s[2]); break;
    case 301: glTexCoord3sv(s); break;
    case 310: glTexCoord3i(i[0], i[1], i[2]); break;
    case 311: glTexCoord3iv(i); break;
    case 320: glTexCoord3f(f[0], f[1], f[2]); break;
    case 321: glTexCoord3fv(f); break;
    case 330: glTexCoord3d(d[0], d[1], d[2]); break;
    case 331: glTexCoord3dv(d); break;
    case 400: glTexCoord4s(s[0], s[1], s[2], s[3]); break;
    case 401: glTexCoord4sv(s); break;
    case 410: glTexCoord4i(i[0], i[1], i[2], i[3]); break;
    case 411: glTexCoord4iv(i); break;
    case 420: glTexCoord4f(f[0], f[1], f[2], f[3]); break;
    case 421: glTexCoord4fv(f); break;
    case 430: glTexCoord4d(d[0], d[1], d[2], d[3]); break;
    case 431: glTexCoord4dv(d); break;
  }
}

static void make_texture(void) {
  static GLubyte texels[8][8][4];
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      int on = (x + y) % 2;
      texels[y][x][0] = (GLubyte)(on ? 250 : 30 + 25 * x);
      texels[y][x][1] = (GLubyte)(on ? 200 : 20 + 28 * y);
      texels[y][x][2] = (GLubyte)(on ? 40 : 180);
      texels[y][x][3] = 255;
    }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
}

static void texcoord_panels(void) {
  static const int corner[4][2] = {{-8, -8}, {8, -8}, {8, 8}, {-8, 8}};
  static const int tc[4][2] = {{0, 0}, {3, 0}, {3, 2}, {0, 2}};
  static const int order[6] = {0, 1, 2, 0, 2, 3};
  make_texture();
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int form = 0; form < 32; ++form) {
    next_panel();
    /* An eighth of a texel per unit, r moved into t for the three-component forms. */
    const GLfloat r_to_t[16] = {0.125f, 0, 0, 0, 0, 0.125f, 0, 0, 0, 0.125f, 0, 0, 0, 0, 0, 1};
    glMatrixMode(GL_TEXTURE);
    glLoadMatrixf(r_to_t);
    glTranslatef(0.03f, 0.03f, 0.03f); /* texel centres away from the sample points */
    glMatrixMode(GL_MODELVIEW);
    glBegin(GL_TRIANGLES);
    for (int k = 0; k < 6; ++k) {
      texcoord_form(form, tc[order[k]][0] + form % 3, tc[order[k]][1]);
      glVertex2i(corner[order[k]][0], corner[order[k]][1]);
    }
    glEnd();
  }
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glDisable(GL_TEXTURE_2D);
}

/* ---- glRect ---- */

static void rect_panels(void) {
  const GLshort s1[2] = {-7, -6}, s2[2] = {5, 7};
  const GLint i1[2] = {-6, -7}, i2[2] = {7, 4};
  const GLfloat f1[2] = {-7.5f, -3.25f}, f2[2] = {6.5f, 7.75f};
  const GLdouble d1[2] = {7.0, 7.0}, d2[2] = {-7.0, -5.5}; /* corners given the other way round */
  for (int form = 0; form < 8; ++form) {
    next_panel();
    glColor3f(0.9f - 0.1f * form, 0.3f + 0.08f * form, 0.6f);
    switch (form) {
      case 0: glRects(s1[0], s1[1], s2[0], s2[1]); break;
      case 1: glRectsv(s1, s2); break;
      case 2: glRecti(i1[0], i1[1], i2[0], i2[1]); break;
      case 3: glRectiv(i1, i2); break;
      case 4: glRectf(f1[0], f1[1], f2[0], f2[1]); break;
      case 5: glRectfv(f1, f2); break;
      case 6: glRectd(d1[0], d1[1], d2[0], d2[1]); break;
      case 7: glRectdv(d1, d2); break;
    }
  }
}

/* ---- current values after extreme arguments of every type ---- */

static void print_current(const char* what) {
  GLfloat c[4], n[3], t[4], index;
  glGetFloatv(GL_CURRENT_COLOR, c);
  glGetFloatv(GL_CURRENT_NORMAL, n);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t);
  glGetFloatv(GL_CURRENT_INDEX, &index);
  fprintf(out, "%s: colour %.9g %.9g %.9g %.9g normal %.9g %.9g %.9g texcoord %.9g %.9g %.9g %.9g index %.9g err %x\n",
          what, c[0], c[1], c[2], c[3], n[0], n[1], n[2], t[0], t[1], t[2], t[3], index, glGetError());
}

static void current_values(void) {
  const GLbyte b[4] = {-128, -1, 0, 127};
  const GLshort s[4] = {-32768, -1, 1, 32767};
  const GLint i[4] = {-2147483647 - 1, -1, 12345678, 2147483647};
  const GLubyte ub[4] = {0, 1, 128, 255};
  const GLushort us[4] = {0, 1, 32768, 65535};
  const GLuint ui[4] = {0, 1, 2147483648u, 4294967295u};
  const GLdouble d[4] = {-0.5, 1e-300, 2.5, 1.0 / 3.0};
  glColor4bv(b), glNormal3bv(b + 1), glTexCoord4sv(s), glIndexubv(ub + 3);
  print_current("byte colour and normal, short texcoord, ubyte index");
  glColor4sv(s), glNormal3sv(s), glTexCoord3iv(i), glIndexsv(s);
  print_current("short colour and normal, int texcoord, short index");
  glColor4iv(i), glNormal3iv(i + 1), glTexCoord2dv(d), glIndexiv(i + 2);
  print_current("int colour and normal, double texcoord, int index");
  glColor4ubv(ub), glNormal3dv(d), glTexCoord1i(-7), glIndexdv(d + 2);
  print_current("ubyte colour, double normal, texcoord1, double index");
  glColor4usv(us), glNormal3f(0.25f, -0.5f, 2.0f), glTexCoord4f(1, 2, 3, 4), glIndexf(-3.5f);
  print_current("ushort colour, float normal and texcoord, float index");
  /* Not a shorter glTexCoord after a longer one here: Mesa 22's glGet then sometimes still
   * returns the components the shorter call sets to 0 and 1 (docs/gl-conformance.md). */
  glColor4uiv(ui), glTexCoord4d(0.1, 0.2, 0.3, -0.5), glIndexd(1e10);
  print_current("uint colour, double texcoord4, huge index");
  glColor3b(-128, 64, 127), glColor3us(1, 2, 3), glIndexi(-2147483647 - 1);
  print_current("colour3 forms keep alpha 1");
  glColor4d(2.0, -3.0, 1e30, -0.0);
  print_current("double colour out of range (kept as given)");
  glColor4f(0.5f, -0.25f, 1.0f, 0.0f); /* integers of colours in [-1, 1] only: Mesa overflows beyond */
  GLint ci[4];
  glGetIntegerv(GL_CURRENT_COLOR, ci);
  fprintf(out, "current colour as integers: %d %d %d %d\n", ci[0], ci[1], ci[2], ci[3]);
  glColor4f(1, 1, 1, 1);
  glNormal3f(0, 0, 1);
  glTexCoord4f(0, 0, 0, 1);
  glIndexi(1);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 640, 320)) return 1;
  ctx = &c;
  out = conf_open_values(&c);
  if (!out) return 1;
  current_values();
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-9.0, 9.0, -9.0, 9.0, -4.0, 4.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  vertex_panels();
  color_panels();
  normal_panels();
  texcoord_panels();
  rect_panels();
  fprintf(out, "panels: %d err %x\n", panel_index, glGetError());
  fclose(out);
  return conf_finish(&c);
}
