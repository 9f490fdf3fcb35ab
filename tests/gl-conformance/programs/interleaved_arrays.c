/* Vertex arrays in every layout OpenGL 1.1 allows (section 2.8), compared with Mesa: the 14
 * glInterleavedArrays formats, each drawn with glDrawArrays, glDrawElements (unsigned byte
 * indices) and glArrayElement between glBegin and glEnd; then every gl*Pointer type and size
 * (vertex 2-4 x short/int/float/double, normal byte..double, colour 3-4 x the 8 types, texture
 * coordinates 1-4 x short..double) drawn with glDrawElements with unsigned byte, short and
 * int indices in turn, in every polygon mode of glBegin; index and edge-flag arrays enabled
 * throughout (they change nothing drawn in an RGBA context filling polygons). The current
 * attributes glArrayElement leaves outside glBegin/glEnd, for each colour and normal type, are
 * printed to NAME.txt and compared with Mesa's exactly. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "conf.h"

enum { kCols = 16, kRows = 8, kFan = 8 };
static const ConfContext* ctx;
static int panel_index = 0;
static FILE* out;

static void next_panel(void) {
  conf_panel(ctx, panel_index % kCols, panel_index / kCols, kCols, kRows);
  ++panel_index;
}

/* A fan of kFan vertices around the centre of [-1, 1]^2: position, normal leaning outwards,
 * colour, texture coordinates. */
typedef struct Attribs {
  float pos[4], normal[3], color[4], tex[4];
} Attribs;

static void fan_vertex(int k, Attribs* a) {
  double t = 2.0 * CONF_PI * (k - 1) / (kFan - 2), r = k == 0 ? 0.0 : 0.85;
  a->pos[0] = (float)(r * cos(t)), a->pos[1] = (float)(r * sin(t)), a->pos[2] = 0.0f, a->pos[3] = 1.0f;
  a->normal[0] = (float)(0.7 * r * cos(t)), a->normal[1] = (float)(0.7 * r * sin(t));
  a->normal[2] = (float)sqrt(1.0 - 0.49 * r * r);
  a->color[0] = (float)(0.5 + 0.5 * cos(t) * r), a->color[1] = (float)(0.5 + 0.5 * sin(t) * r);
  a->color[2] = k == 0 ? 1.0f : 0.2f, a->color[3] = 0.6f + 0.05f * k;
  a->tex[0] = 2.0f * a->pos[0] + 0.03f, a->tex[1] = 2.0f * a->pos[1] + 0.03f, a->tex[2] = 0.0f, a->tex[3] = 1.0f;
}

/* ---- glInterleavedArrays ---- */

static const GLenum kFormats[14] = {
    GL_V2F, GL_V3F, GL_C4UB_V2F, GL_C4UB_V3F, GL_C3F_V3F, GL_N3F_V3F, GL_C4F_N3F_V3F,
    GL_T2F_V3F, GL_T4F_V4F, GL_T2F_C4UB_V3F, GL_T2F_C3F_V3F, GL_T2F_N3F_V3F,
    GL_T2F_C4F_N3F_V3F, GL_T4F_C4F_N3F_V4F};
/* Per format: texture coordinates, colour components (-4: four unsigned bytes), normal,
 * vertex components. */
static const int kLayout[14][4] = {
    {0, 0, 0, 2}, {0, 0, 0, 3}, {0, -4, 0, 2}, {0, -4, 0, 3}, {0, 3, 0, 3}, {0, 0, 1, 3}, {0, 4, 1, 3},
    {2, 0, 0, 3}, {4, 0, 0, 4}, {2, -4, 0, 3}, {2, 3, 0, 3}, {2, 0, 1, 3}, {2, 4, 1, 3}, {4, 4, 1, 4}};

static unsigned char interleaved[kFan * 64];

/* Packs the fan in format f's layout (with `pad` unused bytes after each element); returns
 * the stride. */
static int pack_format(int f, int pad) {
  int at = 0;
  for (int k = 0; k < kFan; ++k) {
    Attribs a;
    fan_vertex(k, &a);
    if (kLayout[f][3] == 4) a.pos[0] *= 2.0f, a.pos[1] *= 2.0f, a.pos[2] *= 2.0f, a.pos[3] = 2.0f;
    memcpy(interleaved + at, a.tex, sizeof(float) * kLayout[f][0]), at += 4 * kLayout[f][0];
    if (kLayout[f][1] == -4) {
      for (int i = 0; i < 4; ++i) interleaved[at + i] = (unsigned char)lround(a.color[i] * 255.0f);
      at += 4;
    } else {
      memcpy(interleaved + at, a.color, sizeof(float) * kLayout[f][1]), at += 4 * kLayout[f][1];
    }
    if (kLayout[f][2]) memcpy(interleaved + at, a.normal, sizeof a.normal), at += 12;
    memcpy(interleaved + at, a.pos, sizeof(float) * kLayout[f][3]), at += 4 * kLayout[f][3];
    at += pad;
  }
  return at / kFan;
}

static void draw_fan(int method) {
  static const GLubyte indices[kFan] = {0, 1, 2, 3, 4, 5, 6, 7};
  if (method == 0) glDrawArrays(GL_TRIANGLE_FAN, 0, kFan);
  if (method == 1) glDrawElements(GL_TRIANGLE_FAN, kFan, GL_UNSIGNED_BYTE, indices);
  if (method == 2) {
    glBegin(GL_TRIANGLE_FAN);
    for (int k = 0; k < kFan; ++k) glArrayElement(k);
    glEnd();
  }
}

static void interleaved_panels(void) {
  for (int f = 0; f < 14; ++f) {
    int pad = f % 2 ? 4 : 0; /* odd formats: an explicit stride with padding */
    int stride = pack_format(f, pad);
    for (int method = 0; method < 3; ++method) {
      next_panel();
      glColor4f(0.9f, 0.9f, 0.3f, 1.0f);
      glNormal3f(0.0f, 0.0f, 1.0f);
      glInterleavedArrays(kFormats[f], pad ? stride : 0, interleaved);
      if (kLayout[f][2]) glEnable(GL_LIGHTING);
      if (kLayout[f][0]) glEnable(GL_TEXTURE_2D);
      draw_fan(method);
      glDisable(GL_LIGHTING);
      glDisable(GL_TEXTURE_2D);
    }
  }
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
}

/* ---- every pointer type and size ---- */

static unsigned char array_data[kFan * 64];
static const GLenum kModes[6] = {GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,
                                 GL_QUAD_STRIP, GL_POLYGON};
/* The fan's vertices in the order each mode needs to cover the same disc (mostly). */
static const GLubyte kOrder[6][18] = {
    {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 6, 0, 6, 7},
    {1, 2, 0, 3, 4, 0, 5, 6, 0, 7, 7, 7},
    {0, 1, 2, 3, 4, 5, 6, 7},
    {0, 1, 2, 3, 0, 3, 4, 5, 0, 5, 6, 7},
    {0, 1, 2, 3, 6, 4, 5, 4},
    {1, 2, 3, 4, 5, 6}};
static const int kOrderCount[6] = {18, 12, 8, 12, 8, 6};

/* Component k of `v` stored as `type` at `p`, scaled as colours and normals convert when
 * `normalized` (integers: the largest value stands for 1). */
static int store(void* p, GLenum type, double v, int normalized) {
  switch (type) {
    case GL_BYTE: { GLbyte x = (GLbyte)lround(normalized ? v * 127.0 : v); memcpy(p, &x, 1); return 1; }
    case GL_UNSIGNED_BYTE: { GLubyte x = (GLubyte)lround(normalized ? (v < 0 ? 0 : v) * 255.0 : v); memcpy(p, &x, 1); return 1; }
    case GL_SHORT: { GLshort x = (GLshort)lround(normalized ? v * 32767.0 : v); memcpy(p, &x, 2); return 2; }
    case GL_UNSIGNED_SHORT: { GLushort x = (GLushort)lround(normalized ? (v < 0 ? 0 : v) * 65535.0 : v); memcpy(p, &x, 2); return 2; }
    case GL_INT: { GLint x = (GLint)llround(normalized ? v * 2147483647.0 : v); memcpy(p, &x, 4); return 4; }
    case GL_UNSIGNED_INT: { GLuint x = (GLuint)llround(normalized ? (v < 0 ? 0 : v) * 4294967295.0 : v); memcpy(p, &x, 4); return 4; }
    case GL_FLOAT: { GLfloat x = (GLfloat)v; memcpy(p, &x, 4); return 4; }
    default: { GLdouble x = v; memcpy(p, &x, 8); return 8; }
  }
}

/* Fills array_data with `size` components of attribute `which` (0 position, 1 normal,
 * 2 colour, 3 texture) per element, `stride` bytes apart (0: tight); returns the stride used. */
static int fill(int which, int size, GLenum type, int stride, double scale) {
  int at = 0, used = 0;
  for (int k = 0; k < kFan; ++k) {
    Attribs a;
    fan_vertex(k, &a);
    const float* v = which == 0 ? a.pos : which == 1 ? a.normal : which == 2 ? a.color : a.tex;
    int start = at;
    for (int i = 0; i < size; ++i) at += store(array_data + at, type, v[i] * (i < 3 ? scale : 1.0), which == 1 || which == 2);
    used = at - start;
    if (stride) at = start + stride;
  }
  return stride ? stride : used;
}

static void draw_elements(int n) {
  int mode = n % 6, type = n % 3;
  static GLushort shorts[18];
  static GLuint ints[18];
  for (int i = 0; i < kOrderCount[mode]; ++i) shorts[i] = kOrder[mode][i], ints[i] = kOrder[mode][i];
  if (type == 0) glDrawElements(kModes[mode], kOrderCount[mode], GL_UNSIGNED_BYTE, kOrder[mode]);
  if (type == 1) glDrawElements(kModes[mode], kOrderCount[mode], GL_UNSIGNED_SHORT, shorts);
  if (type == 2) glDrawElements(kModes[mode], kOrderCount[mode], GL_UNSIGNED_INT, ints);
}

static float float_positions[kFan][3];
static float float_colors[kFan][4];

static void base_arrays(void) {
  for (int k = 0; k < kFan; ++k) {
    Attribs a;
    fan_vertex(k, &a);
    memcpy(float_positions[k], a.pos, sizeof float_positions[k]);
    memcpy(float_colors[k], a.color, sizeof float_colors[k]);
  }
  glVertexPointer(3, GL_FLOAT, 0, float_positions);
  glColorPointer(4, GL_FLOAT, 0, float_colors);
  glEnableClientState(GL_VERTEX_ARRAY);
}

static void pointer_panels(void) {
  static const GLenum kAll[8] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE};
  static const GLenum kSifd[4] = {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE};
  static const GLenum kNormal[5] = {GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE};
  int n = 0;
  base_arrays();
  /* Positions: integers need a larger scale (the projection below shrinks them back). */
  for (int size = 2; size <= 4; ++size)
    for (int t = 0; t < 4; ++t, ++n) {
      next_panel();
      glMatrixMode(GL_PROJECTION);
      glPushMatrix();
      glScalef(1.0f / 64.0f, 1.0f / 64.0f, 1.0f);
      glVertexPointer(size, kSifd[t], fill(0, size, kSifd[t], (n % 2) * 40, 64.0), array_data);
      glEnableClientState(GL_COLOR_ARRAY);
      draw_elements(n);
      glDisableClientState(GL_COLOR_ARRAY);
      glPopMatrix();
      glMatrixMode(GL_MODELVIEW);
    }
  glVertexPointer(3, GL_FLOAT, 0, float_positions);
  glEnable(GL_LIGHTING);
  glEnableClientState(GL_NORMAL_ARRAY);
  for (int t = 0; t < 5; ++t, ++n) {
    next_panel();
    glNormalPointer(kNormal[t], fill(1, 3, kNormal[t], (n % 2) * 36, 1.0), array_data);
    draw_elements(n);
  }
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisable(GL_LIGHTING);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int size = 3; size <= 4; ++size)
    for (int t = 0; t < 8; ++t, ++n) {
      next_panel();
      glColorPointer(size, kAll[t], fill(2, size, kAll[t], (n % 2) * 36, 1.0), array_data);
      draw_elements(n);
    }
  glDisable(GL_BLEND);
  glDisableClientState(GL_COLOR_ARRAY);
  glEnable(GL_TEXTURE_2D);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  for (int size = 1; size <= 4; ++size)
    for (int t = 0; t < 4; ++t, ++n) {
      next_panel();
      /* Integer coordinates: eight per texel, brought back by the texture matrix. */
      glMatrixMode(GL_TEXTURE);
      glLoadIdentity();
      glScalef(1.0f / 32.0f, 1.0f / 32.0f, 1.0f);
      glMatrixMode(GL_MODELVIEW);
      glTexCoordPointer(size, kSifd[t], fill(3, size, kSifd[t], (n % 2) * 44, 32.0), array_data);
      draw_elements(n);
    }
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisable(GL_TEXTURE_2D);
}

/* ---- glArrayElement outside glBegin/glEnd: the current attributes it leaves ---- */

static void current_after_array_element(void) {
  static const GLenum kAll[8] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE};
  static const GLenum kNormal[5] = {GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE};
  GLfloat c[4], nm[3];
  glEnableClientState(GL_COLOR_ARRAY);
  for (int t = 0; t < 8; ++t) {
    glColorPointer(4, kAll[t], fill(2, 4, kAll[t], 0, 1.0), array_data);
    glArrayElement(3);
    glGetFloatv(GL_CURRENT_COLOR, c);
    fprintf(out, "glArrayElement colour type %x: %.9g %.9g %.9g %.9g err %x\n", kAll[t], c[0], c[1], c[2], c[3], glGetError());
  }
  glDisableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  for (int t = 0; t < 5; ++t) {
    glNormalPointer(kNormal[t], fill(1, 3, kNormal[t], 0, 1.0), array_data);
    glArrayElement(5);
    glGetFloatv(GL_CURRENT_NORMAL, nm);
    fprintf(out, "glArrayElement normal type %x: %.9g %.9g %.9g err %x\n", kNormal[t], nm[0], nm[1], nm[2], glGetError());
  }
  glDisableClientState(GL_NORMAL_ARRAY);
  /* glDrawArrays leaves the current colour as it was (Mesa). */
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(4, GL_FLOAT, 0, float_colors);
  glDrawArrays(GL_TRIANGLE_FAN, 0, kFan);
  glGetFloatv(GL_CURRENT_COLOR, c);
  fprintf(out, "after glDrawArrays: %.9g %.9g %.9g %.9g err %x\n", c[0], c[1], c[2], c[3], glGetError());
  glDisableClientState(GL_COLOR_ARRAY);
}

static void make_texture(void) {
  static GLubyte texels[4][4][4];
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      texels[y][x][0] = (GLubyte)(60 * x + 40), texels[y][x][1] = (GLubyte)(60 * y + 40);
      texels[y][x][2] = (GLubyte)((x + y) % 2 ? 230 : 20), texels[y][x][3] = 255;
    }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 640, 320)) return 1;
  ctx = &c;
  out = conf_open_values(&c);
  if (!out) return 1;
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  const GLfloat light[4] = {0.4f, 0.3f, 1.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  make_texture();
  /* Index and edge-flag arrays enabled throughout: nothing they hold changes a filled RGBA draw. */
  static const GLfloat indices[kFan] = {1, 2, 3, 4, 5, 6, 7, 8};
  static const GLboolean flags[kFan] = {1, 0, 1, 0, 1, 0, 1, 0};
  glIndexPointer(GL_FLOAT, 0, indices);
  glEdgeFlagPointer(0, flags);
  glEnableClientState(GL_INDEX_ARRAY);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  interleaved_panels(); /* glInterleavedArrays disables both */
  glEnableClientState(GL_INDEX_ARRAY);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  pointer_panels();
  glDisableClientState(GL_INDEX_ARRAY);
  glDisableClientState(GL_EDGE_FLAG_ARRAY);
  current_after_array_element();
  fprintf(out, "panels: %d err %x\n", panel_index, glGetError());
  fclose(out);
  return conf_finish(&c);
}
