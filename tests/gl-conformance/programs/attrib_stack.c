/* The attribute stacks (GL 1.1 section 6.1.14), compared with Mesa value by value: for every
 * attribute group alone, GL_ALL_ATTRIB_BITS and an empty mask, a fresh context is given one
 * set of values, pushes the group, takes a second set of values for everything, pops, and
 * prints every glGet value (state_dump's table), every capability, texture, light and material
 * parameters: what the group restored and what it left changed. The same for the client groups
 * (pixel storage, vertex arrays), the stack limits and their errors (overflow, underflow,
 * inside glBegin/glEnd, pushes compiled into a display list), a bound texture deleted while
 * pushed. Then a lit, textured scene is drawn after a push of everything, a change of
 * everything and a pop (compared pixel by pixel), beside the values drawn as cells. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "conf.h"

typedef struct Pname {
  GLenum pname;
  const char* name;
  int count;
} Pname;

static const Pname kPnames[] = {
#include "state_dump_pnames.inc"
};
enum { kPnameCount = sizeof kPnames / sizeof kPnames[0] };

/* State of features libshadelab-gl does not implement yet (as in state_dump.c). */
static const GLenum kNotYet[] = {
  GL_ALPHA_BIAS, GL_ALPHA_SCALE, GL_RED_BIAS, GL_RED_SCALE, GL_GREEN_BIAS, GL_GREEN_SCALE,
  GL_BLUE_BIAS, GL_BLUE_SCALE, GL_DEPTH_BIAS, GL_DEPTH_SCALE, GL_INDEX_OFFSET, GL_INDEX_SHIFT,
  GL_MAP_COLOR, GL_MAP_STENCIL, GL_ZOOM_X, GL_ZOOM_Y, GL_MAX_PIXEL_MAP_TABLE,
  GL_PIXEL_MAP_A_TO_A_SIZE, GL_PIXEL_MAP_B_TO_B_SIZE, GL_PIXEL_MAP_G_TO_G_SIZE,
  GL_PIXEL_MAP_I_TO_A_SIZE, GL_PIXEL_MAP_I_TO_B_SIZE, GL_PIXEL_MAP_I_TO_G_SIZE,
  GL_PIXEL_MAP_I_TO_I_SIZE, GL_PIXEL_MAP_I_TO_R_SIZE, GL_PIXEL_MAP_R_TO_R_SIZE,
  GL_PIXEL_MAP_S_TO_S_SIZE, GL_CURRENT_RASTER_COLOR, GL_CURRENT_RASTER_DISTANCE,
  GL_CURRENT_RASTER_POSITION, GL_CURRENT_RASTER_POSITION_VALID,
  GL_CURRENT_RASTER_TEXTURE_COORDS, GL_ACCUM_CLEAR_VALUE,
  GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
  GL_TEXTURE_GEN_Q,
  GL_FEEDBACK_BUFFER_SIZE, GL_FEEDBACK_BUFFER_TYPE, GL_SELECTION_BUFFER_SIZE,
  GL_NAME_STACK_DEPTH, GL_MAX_NAME_STACK_DEPTH,
  /* Limits where shadelab differs from Mesa on purpose (docs/gl.md). */
  GL_MAX_LIGHTS, GL_MAX_TEXTURE_SIZE,
};

static int not_yet(GLenum pname) {
  for (size_t k = 0; k < sizeof kNotYet / sizeof kNotYet[0]; ++k) {
    if (kNotYet[k] == pname) return 1;
  }
  return 0;
}

enum { kCols = 64, kRows = 48, kCells = kCols * kRows };
static unsigned cells[kCells];
static int n_cells = 0;
static FILE* out;

static void cell(unsigned v) {
  /* Every value folds into a cell (the later ones onto the first cells again). */
  int i = n_cells++ % kCells;
  cells[i] = (cells[i] ^ v) * 16777619u;
}

static void print_floats(const char* phase, const char* what, const GLfloat* v, int n) {
  GLenum e = glGetError();
  fprintf(out, "%s %s:", phase, what);
  unsigned h = e;
  for (int k = 0; k < n; ++k) {
    fprintf(out, " %.9g", v[k]);
    h = (h ^ (unsigned)(long)(v[k] * 1000.0f)) * 16777619u;
  }
  fprintf(out, " err %x\n", e);
  cell(h);
}

static void dump(const char* phase) {
  for (int k = 0; k < kPnameCount; ++k) {
    const Pname* p = &kPnames[k];
    if (not_yet(p->pname)) continue;
    GLfloat f[17];
    for (int j = 0; j < 17; ++j) f[j] = -12345.0f;
    glGetFloatv(p->pname, f);
    print_floats(phase, p->name, f, p->count);
  }
  static const GLenum kCaps[] = {
    GL_BLEND, GL_COLOR_MATERIAL, GL_CULL_FACE, GL_DEPTH_TEST, GL_DITHER, GL_LIGHT0, GL_LIGHT1,
    GL_LIGHT7, GL_LIGHTING, GL_LINE_SMOOTH, GL_LINE_STIPPLE, GL_NORMALIZE, GL_POINT_SMOOTH,
    GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH,
    GL_STENCIL_TEST, GL_TEXTURE_2D, GL_ALPHA_TEST, GL_FOG, GL_COLOR_LOGIC_OP, GL_INDEX_LOGIC_OP,
    GL_SCISSOR_TEST, GL_POLYGON_STIPPLE, GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY,
    GL_INDEX_ARRAY, GL_TEXTURE_COORD_ARRAY, GL_EDGE_FLAG_ARRAY, GL_CLIP_PLANE0, GL_CLIP_PLANE3,
    GL_CLIP_PLANE0 + 7,
  };
  for (size_t k = 0; k < sizeof kCaps / sizeof kCaps[0]; ++k) {
    GLfloat on = glIsEnabled(kCaps[k]);
    char what[32];
    snprintf(what, sizeof what, "enabled 0x%04x", kCaps[k]);
    print_floats(phase, what, &on, 1);
  }
  static const GLenum kTexParams[] = {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER,
                                      GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_PRIORITY,
                                      GL_TEXTURE_BORDER_COLOR};
  for (size_t k = 0; k < sizeof kTexParams / sizeof kTexParams[0]; ++k) {
    GLfloat v[4] = {-1, -1, -1, -1};
    glGetTexParameterfv(GL_TEXTURE_2D, kTexParams[k], v);
    char what[32];
    snprintf(what, sizeof what, "texparameter 0x%04x", kTexParams[k]);
    print_floats(phase, what, v, 4);
  }
  GLfloat v[4] = {-1, -1, -1, -1};
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, v);
  print_floats(phase, "env color", v, 4);
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, v);
  print_floats(phase, "env mode", v, 1);
  {
    /* The stipple pattern, read through whatever pack state the client groups left, into a
     * buffer large enough for any of them; two sums of its bytes. */
    static GLubyte pattern[8192];
    memset(pattern, 0, sizeof pattern);
    glGetPolygonStipple(pattern);
    GLfloat sums[2] = {0, 0};
    for (size_t i = 0; i < sizeof pattern; ++i) {
      sums[0] += (GLfloat)pattern[i];
      sums[1] += (GLfloat)(pattern[i] * (i % 61));
    }
    print_floats(phase, "stipple", sums, 2);
  }
  static const GLenum kLightParams[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION,
                                        GL_SPOT_DIRECTION, GL_SPOT_CUTOFF, GL_LINEAR_ATTENUATION};
  for (size_t k = 0; k < sizeof kLightParams / sizeof kLightParams[0]; ++k) {
    GLfloat l[4] = {-1, -1, -1, -1};
    glGetLightfv(GL_LIGHT1, kLightParams[k], l);
    char what[32];
    snprintf(what, sizeof what, "light1 0x%04x", kLightParams[k]);
    print_floats(phase, what, l, 4);
  }
  static const GLenum kMaterialParams[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION,
                                           GL_SHININESS};
  for (size_t k = 0; k < sizeof kMaterialParams / sizeof kMaterialParams[0]; ++k) {
    GLfloat m[4] = {-1, -1, -1, -1};
    glGetMaterialfv(GL_FRONT, kMaterialParams[k], m);
    char what[32];
    snprintf(what, sizeof what, "material 0x%04x", kMaterialParams[k]);
    print_floats(phase, what, m, 4);
    glGetMaterialfv(GL_BACK, kMaterialParams[k], m);
    snprintf(what, sizeof what, "back material 0x%04x", kMaterialParams[k]);
    print_floats(phase, what, m, 4);
  }
  for (int i = 0; i < 8; ++i) { /* Mesa's 8 user clip planes, in eye space */
    GLdouble d[4] = {-7, -7, -7, -7};
    glGetClipPlane((GLenum)(GL_CLIP_PLANE0 + i), d);
    GLfloat f[4] = {(GLfloat)d[0], (GLfloat)d[1], (GLfloat)d[2], (GLfloat)d[3]};
    char what[32];
    snprintf(what, sizeof what, "clip plane %d", i);
    print_floats(phase, what, f, 4);
  }
}

static GLfloat arrays[64];
static GLuint textures[2];

/* Every piece of state, to values that depend on `k` (0 or 1). */
static void set_state(int k) {
  const GLfloat a = 0.125f + 0.25f * (GLfloat)k;
  glMatrixMode(k ? GL_PROJECTION : GL_TEXTURE);
  glViewport(3 + k, 5, 101 - k, 77);
  glDepthRange(0.25 * k, 0.75);
  glColor4f(a, 1.0f - a, a * 2.0f, 0.5f);
  glNormal3f(a, -a, 1.0f);
  glTexCoord4f(a, 2.0f, 3.0f * a, 4.0f);
  glIndexf(3.0f + (GLfloat)k);
  glEdgeFlag((GLboolean)k);
  if (k) glEnable(GL_LIGHTING); else glDisable(GL_LIGHTING);
  glEnable(k ? GL_LIGHT1 : GL_LIGHT7);
  GLfloat light[4] = {a, 0.5f, 1.0f - a, 1.0f};
  glLightfv(GL_LIGHT1, GL_AMBIENT, light);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, light);
  glLightfv(GL_LIGHT1, GL_POSITION, light);
  glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, light);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 30.0f + 10.0f * (GLfloat)k);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, a);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, light);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, k);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1 - k);
  glMaterialfv(GL_FRONT, GL_SPECULAR, light);
  glMaterialfv(GL_BACK, GL_EMISSION, light);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 10.0f + 20.0f * (GLfloat)k);
  glColorMaterial(k ? GL_BACK : GL_FRONT, k ? GL_SPECULAR : GL_EMISSION);
  if (k) glEnable(GL_COLOR_MATERIAL); else glDisable(GL_COLOR_MATERIAL);
  glShadeModel(k ? GL_FLAT : GL_SMOOTH);
  if (k) glEnable(GL_NORMALIZE); else glDisable(GL_NORMALIZE);
  if (k) glEnable(GL_CULL_FACE); else glDisable(GL_CULL_FACE);
  glCullFace(k ? GL_FRONT : GL_FRONT_AND_BACK);
  glFrontFace(k ? GL_CW : GL_CCW);
  if (k) glDisable(GL_DEPTH_TEST); else glEnable(GL_DEPTH_TEST);
  glDepthFunc(k ? GL_GEQUAL : GL_EQUAL);
  glDepthMask((GLboolean)k);
  glClearDepth(0.5 * k);
  glClearColor(a, 0.5f, 0.75f, 1.0f - a);
  glClearStencil(3 + k);
  glClearIndex(2.0f + (GLfloat)k);
  glIndexMask(0x55u << k);
  glColorMask((GLboolean)k, GL_FALSE, GL_TRUE, (GLboolean)(1 - k));
  if (k) glEnable(GL_BLEND); else glDisable(GL_BLEND);
  glBlendFunc(k ? GL_SRC_ALPHA : GL_DST_COLOR, k ? GL_ONE_MINUS_SRC_ALPHA : GL_SRC_ALPHA);
  if (k) glDisable(GL_STENCIL_TEST); else glEnable(GL_STENCIL_TEST);
  glStencilFunc(k ? GL_NOTEQUAL : GL_LESS, 5 + k, 0x0fu << k);
  glStencilOp(k ? GL_INCR : GL_ZERO, k ? GL_DECR : GL_REPLACE, k ? GL_INVERT : GL_INCR);
  glStencilMask(0x3cu << k);
  if (k) glEnable(GL_POLYGON_OFFSET_FILL); else glDisable(GL_POLYGON_OFFSET_FILL);
  if (k) glDisable(GL_POLYGON_OFFSET_LINE); else glEnable(GL_POLYGON_OFFSET_LINE);
  if (k) glEnable(GL_POLYGON_OFFSET_POINT); else glDisable(GL_POLYGON_OFFSET_POINT);
  if (k) glDisable(GL_POLYGON_SMOOTH); else glEnable(GL_POLYGON_SMOOTH);
  if (k) glEnable(GL_LINE_SMOOTH); else glDisable(GL_LINE_SMOOTH);
  if (k) glDisable(GL_LINE_STIPPLE); else glEnable(GL_LINE_STIPPLE);
  if (k) glEnable(GL_POINT_SMOOTH); else glDisable(GL_POINT_SMOOTH);
  glPolygonOffset(1.5f + (GLfloat)k, -2.0f);
  glPointSize(2.0f + 1.5f * (GLfloat)k);
  glLineWidth(1.5f + (GLfloat)k);
  glLineStipple(2 + 3 * k, (GLushort)(k ? 0xf0f0 : 0x3333));
  glPolygonMode(GL_FRONT, k ? GL_LINE : GL_POINT);
  glPolygonMode(GL_BACK, k ? GL_FILL : GL_LINE);
  {
    /* Planes under the modelview of the moment, taken to eye space when given. */
    const GLdouble eq[4] = {1.0 + k, -2.0, 0.5 * k, 3.0};
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glTranslatef(1.0f + (GLfloat)k, 2.0f, -3.0f);
    glRotatef(30.0f + 20.0f * (GLfloat)k, 0.0f, 1.0f, 1.0f);
    glClipPlane((GLenum)(GL_CLIP_PLANE0 + 3 * k), eq);
    glClipPlane((GLenum)(GL_CLIP_PLANE0 + 7), eq);
    glPopMatrix();
    glMatrixMode(k ? GL_PROJECTION : GL_TEXTURE);
  }
  if (k) glEnable(GL_CLIP_PLANE0); else glDisable(GL_CLIP_PLANE0);
  if (k) glDisable(GL_CLIP_PLANE3); else glEnable(GL_CLIP_PLANE3);
  if (k) glEnable((GLenum)(GL_CLIP_PLANE0 + 7)); else glDisable((GLenum)(GL_CLIP_PLANE0 + 7));
  if (k) glDisable(GL_DITHER); else glEnable(GL_DITHER);
  glHint(GL_PERSPECTIVE_CORRECTION_HINT, k ? GL_NICEST : GL_FASTEST);
  glHint(GL_POINT_SMOOTH_HINT, k ? GL_FASTEST : GL_NICEST);
  glHint(GL_LINE_SMOOTH_HINT, k ? GL_NICEST : GL_FASTEST);
  glHint(GL_POLYGON_SMOOTH_HINT, k ? GL_FASTEST : GL_NICEST);
  glHint(GL_FOG_HINT, k ? GL_NICEST : GL_FASTEST);
  glListBase(100u + (GLuint)k);
  if (k) glEnable(GL_ALPHA_TEST); else glDisable(GL_ALPHA_TEST);
  glAlphaFunc(k ? GL_GREATER : GL_LEQUAL, a);
  if (k) glDisable(GL_FOG); else glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, k ? GL_LINEAR : GL_EXP2);
  glFogf(GL_FOG_DENSITY, 2.0f * a);
  glFogf(GL_FOG_START, -a);
  glFogf(GL_FOG_END, 10.0f + a);
  glFogf(GL_FOG_INDEX, 1.0f + (GLfloat)k);
  glFogfv(GL_FOG_COLOR, light);
  if (k) glEnable(GL_COLOR_LOGIC_OP); else glDisable(GL_COLOR_LOGIC_OP);
  if (k) glDisable(GL_INDEX_LOGIC_OP); else glEnable(GL_INDEX_LOGIC_OP);
  glLogicOp(k ? GL_XOR : GL_NAND);
  if (k) glEnable(GL_SCISSOR_TEST); else glDisable(GL_SCISSOR_TEST);
  glScissor(1 + k, -2, 30 - k, 40 + k);
  if (k) glDisable(GL_POLYGON_STIPPLE); else glEnable(GL_POLYGON_STIPPLE);
  {
    /* Read through the unpack state of the moment (row length, skips): more than 128 bytes. */
    static GLubyte pattern[1024];
    for (int i = 0; i < 1024; ++i) pattern[i] = (GLubyte)(i * (3 + 2 * k) + k);
    glPolygonStipple(pattern);
  }
  glBindTexture(GL_TEXTURE_2D, textures[k]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, k ? GL_LINEAR : GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, k ? GL_NEAREST : GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, k ? GL_CLAMP : GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, k ? GL_REPEAT : GL_CLAMP);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, a);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, light);
  /* The other texture's parameters change too (the pushed binding's must come back). */
  glBindTexture(GL_TEXTURE_2D, textures[1 - k]);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 1.0f - a);
  glBindTexture(GL_TEXTURE_2D, textures[k]);
  if (k) glEnable(GL_TEXTURE_2D); else glDisable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, k ? GL_DECAL : GL_BLEND);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, light);
  glPixelStorei(GL_PACK_ALIGNMENT, k ? 2 : 8);
  glPixelStorei(GL_PACK_ROW_LENGTH, 17 + k);
  glPixelStorei(GL_PACK_SKIP_ROWS, 3 + k);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 4 + k);
  glPixelStorei(GL_PACK_SWAP_BYTES, k);
  glPixelStorei(GL_PACK_LSB_FIRST, 1 - k);
  glPixelStorei(GL_UNPACK_ALIGNMENT, k ? 1 : 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 9 + k);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1 + k);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2 + k);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, 1 - k);
  glPixelStorei(GL_UNPACK_LSB_FIRST, k);
  glVertexPointer(3 - k, k ? GL_SHORT : GL_FLOAT, 10 + k, arrays + 1 + k);
  glNormalPointer(k ? GL_BYTE : GL_INT, 7 + k, arrays + 2 + k);
  glColorPointer(3 + k, k ? GL_UNSIGNED_INT : GL_FLOAT, k, arrays + 3 + k);
  glIndexPointer(k ? GL_DOUBLE : GL_SHORT, 16 + k, arrays + 4 + k);
  glTexCoordPointer(1 + k, k ? GL_INT : GL_DOUBLE, 5 + k, arrays + 5 + k);
  glEdgeFlagPointer(3 + k, arrays + 6 + k);
  if (k) glEnableClientState(GL_VERTEX_ARRAY); else glDisableClientState(GL_VERTEX_ARRAY);
  if (k) glDisableClientState(GL_NORMAL_ARRAY); else glEnableClientState(GL_NORMAL_ARRAY);
  if (k) glEnableClientState(GL_COLOR_ARRAY); else glDisableClientState(GL_COLOR_ARRAY);
  if (k) glDisableClientState(GL_INDEX_ARRAY); else glEnableClientState(GL_INDEX_ARRAY);
  if (k) glEnableClientState(GL_TEXTURE_COORD_ARRAY); else glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  if (k) glDisableClientState(GL_EDGE_FLAG_ARRAY); else glEnableClientState(GL_EDGE_FLAG_ARRAY);
}

static unsigned char scratch[64 * 64 * 4];

/* A fresh context on a scratch buffer, with the two textures of set_state. */
static OSMesaContext fresh_context(void) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, scratch, GL_UNSIGNED_BYTE, 64, 64)) {
    fprintf(stderr, "context failed\n");
    exit(1);
  }
  glGenTextures(2, textures);
  return ctx;
}

/* One group: set, push, set otherwise, pop, dump. */
static void server_group(const char* name, GLbitfield mask, int client) {
  OSMesaContext ctx = fresh_context();
  set_state(0);
  if (client) glPushClientAttrib(mask); else glPushAttrib(mask);
  fprintf(out, "%s push: err %x\n", name, glGetError());
  set_state(1);
  if (client) glPopClientAttrib(); else glPopAttrib();
  fprintf(out, "%s pop: err %x\n", name, glGetError());
  dump(name);
  OSMesaDestroyContext(ctx);
}

static void print_int(const char* what, GLenum pname) {
  GLint v = -1;
  glGetIntegerv(pname, &v);
  GLenum e = glGetError();
  fprintf(out, "%s: %d err %x\n", what, v, e);
  cell((unsigned)v * 7u + e);
}

/* Limits and errors: 17 pushes and pops of both stacks, glPushAttrib inside glBegin/glEnd,
 * pushes compiled into a list, a texture deleted while its binding is pushed. */
static void limits(void) {
  OSMesaContext ctx = fresh_context();
  print_int("max attrib depth", GL_MAX_ATTRIB_STACK_DEPTH);
  print_int("max client attrib depth", GL_MAX_CLIENT_ATTRIB_STACK_DEPTH);
  char what[64];
  for (int i = 0; i < 17; ++i) {
    glPushAttrib(i % 2 ? GL_ALL_ATTRIB_BITS : GL_CURRENT_BIT);
    snprintf(what, sizeof what, "push %d", i);
    print_int(what, GL_ATTRIB_STACK_DEPTH);
    glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
    snprintf(what, sizeof what, "client push %d", i);
    print_int(what, GL_CLIENT_ATTRIB_STACK_DEPTH);
  }
  for (int i = 0; i < 17; ++i) {
    glPopAttrib();
    snprintf(what, sizeof what, "pop %d", i);
    print_int(what, GL_ATTRIB_STACK_DEPTH);
    glPopClientAttrib();
    snprintf(what, sizeof what, "client pop %d", i);
    print_int(what, GL_CLIENT_ATTRIB_STACK_DEPTH);
  }
  glBegin(GL_TRIANGLES);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glEnd();
  print_int("push in begin", GL_ATTRIB_STACK_DEPTH);
  glBegin(GL_TRIANGLES);
  glPopAttrib();
  glEnd();
  print_int("pop in begin", GL_ATTRIB_STACK_DEPTH);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPushAttrib(GL_LIGHTING_BIT);
  glEnable(GL_LIGHTING);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT); /* executed at once, not compiled */
  glEndList();
  print_int("compiled push", GL_ATTRIB_STACK_DEPTH);
  print_int("compiled client push", GL_CLIENT_ATTRIB_STACK_DEPTH);
  glCallList(list);
  print_int("called push", GL_ATTRIB_STACK_DEPTH);
  print_int("called lighting", GL_LIGHTING);
  glPopAttrib();
  print_int("popped lighting", GL_LIGHTING);
  glPopClientAttrib();
  /* A bound texture deleted while pushed: the pop binds its name again. */
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPushAttrib(GL_TEXTURE_BIT);
  glDeleteTextures(1, &textures[1]);
  print_int("deleted binding", GL_TEXTURE_BINDING_2D);
  glPopAttrib();
  print_int("popped binding", GL_TEXTURE_BINDING_2D);
  GLfloat mag = -1.0f;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &mag);
  print_floats("popped", "mag filter", &mag, 1);
  GLfloat is = glIsTexture(textures[1]);
  print_floats("popped", "is texture", &is, 1);
  OSMesaDestroyContext(ctx);
}

static const struct {
  const char* name;
  GLbitfield mask;
} kGroups[] = {
  {"GL_CURRENT_BIT", GL_CURRENT_BIT}, {"GL_POINT_BIT", GL_POINT_BIT},
  {"GL_LINE_BIT", GL_LINE_BIT}, {"GL_POLYGON_BIT", GL_POLYGON_BIT},
  {"GL_POLYGON_STIPPLE_BIT", GL_POLYGON_STIPPLE_BIT}, {"GL_PIXEL_MODE_BIT", GL_PIXEL_MODE_BIT},
  {"GL_LIGHTING_BIT", GL_LIGHTING_BIT}, {"GL_FOG_BIT", GL_FOG_BIT},
  {"GL_DEPTH_BUFFER_BIT", GL_DEPTH_BUFFER_BIT}, {"GL_ACCUM_BUFFER_BIT", GL_ACCUM_BUFFER_BIT},
  {"GL_STENCIL_BUFFER_BIT", GL_STENCIL_BUFFER_BIT}, {"GL_VIEWPORT_BIT", GL_VIEWPORT_BIT},
  {"GL_TRANSFORM_BIT", GL_TRANSFORM_BIT}, {"GL_ENABLE_BIT", GL_ENABLE_BIT},
  {"GL_COLOR_BUFFER_BIT", GL_COLOR_BUFFER_BIT}, {"GL_HINT_BIT", GL_HINT_BIT},
  {"GL_EVAL_BIT", GL_EVAL_BIT}, {"GL_LIST_BIT", GL_LIST_BIT}, {"GL_TEXTURE_BIT", GL_TEXTURE_BIT},
  {"GL_SCISSOR_BIT", GL_SCISSOR_BIT}, {"GL_ALL_ATTRIB_BITS", GL_ALL_ATTRIB_BITS},
  {"no bits", 0},
};

/* The scene: a lit, textured sphere after push everything / change everything / pop. */
static void scene(const ConfContext* c) {
  static GLubyte texels[8 * 8 * 4];
  for (int i = 0; i < 8 * 8; ++i) {
    int on = ((i % 8) + (i / 8)) % 2;
    texels[4 * i] = on ? 240 : 40, texels[4 * i + 1] = 120, texels[4 * i + 2] = on ? 30 : 200;
    texels[4 * i + 3] = 255;
  }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  GLfloat pos[4] = {1.0f, 1.0f, 2.0f, 0.0f}, spec[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
  glEnable(GL_DEPTH_TEST);
  glClear(GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.2, 1.2, -1.2, 1.2, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  conf_panel(c, 1, 1, 2, 2);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  glGenTextures(2, textures);
  set_state(1);
  glDisable(GL_LIGHT0);
  glPopClientAttrib();
  glPopAttrib();
  conf_sphere(1.0f, 24, 16);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 192)) return 1;
  out = conf_open_values(&c);
  if (!out) return 1;
  for (size_t g = 0; g < sizeof kGroups / sizeof kGroups[0]; ++g) server_group(kGroups[g].name, kGroups[g].mask, 0);
  server_group("GL_CLIENT_PIXEL_STORE_BIT", GL_CLIENT_PIXEL_STORE_BIT, 1);
  server_group("GL_CLIENT_VERTEX_ARRAY_BIT", GL_CLIENT_VERTEX_ARRAY_BIT, 1);
  server_group("GL_CLIENT_ALL_ATTRIB_BITS", GL_CLIENT_ALL_ATTRIB_BITS, 1);
  limits();
  fclose(out);
  OSMesaMakeCurrent(c.ctx, c.buffer, GL_UNSIGNED_BYTE, c.width, c.height);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  conf_value_cells(&c, cells, kCells, kCols, kRows);
  scene(&c);
  return conf_finish(&c);
}
