/* Every glGet value of OpenGL 1.1's state tables (chapter 6, tables 6.5-6.25 and the
 * implementation-dependent values), compared with Mesa's one by one: each pname is read with
 * glGetBooleanv, glGetIntegerv, glGetFloatv and glGetDoublev (and glIsEnabled for the
 * capabilities) into buffers filled with a marker, and every value and the error after each
 * call is printed to NAME.txt (tools/gl_values compares the two files) and drawn as a cell.
 * Three dumps: a fresh context, after changing the state through every command that sets it,
 * and after glInterleavedArrays. Limits where shadelab differs from Mesa on purpose
 * (docs/gl.md: GL_MAX_LIGHTS) are printed as "at least Mesa's". */
#include <stdio.h>
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

/* State of features libshadelab-gl does not implement yet: not dumped until each lands (take
 * its names out of this list then). */
static const GLenum kNotYet[] = {
  /* pixel transfer, zoom, maps, raster position, accumulation buffer */
  GL_ALPHA_BIAS, GL_ALPHA_SCALE, GL_RED_BIAS, GL_RED_SCALE, GL_GREEN_BIAS, GL_GREEN_SCALE,
  GL_BLUE_BIAS, GL_BLUE_SCALE, GL_DEPTH_BIAS, GL_DEPTH_SCALE, GL_INDEX_OFFSET, GL_INDEX_SHIFT,
  GL_MAP_COLOR, GL_MAP_STENCIL, GL_ZOOM_X, GL_ZOOM_Y, GL_MAX_PIXEL_MAP_TABLE,
  GL_PIXEL_MAP_A_TO_A_SIZE, GL_PIXEL_MAP_B_TO_B_SIZE, GL_PIXEL_MAP_G_TO_G_SIZE,
  GL_PIXEL_MAP_I_TO_A_SIZE, GL_PIXEL_MAP_I_TO_B_SIZE, GL_PIXEL_MAP_I_TO_G_SIZE,
  GL_PIXEL_MAP_I_TO_I_SIZE, GL_PIXEL_MAP_I_TO_R_SIZE, GL_PIXEL_MAP_R_TO_R_SIZE,
  GL_PIXEL_MAP_S_TO_S_SIZE, GL_CURRENT_RASTER_COLOR, GL_CURRENT_RASTER_DISTANCE,
  GL_CURRENT_RASTER_POSITION, GL_CURRENT_RASTER_POSITION_VALID,
  GL_CURRENT_RASTER_TEXTURE_COORDS, GL_ACCUM_CLEAR_VALUE,
  /* 1D textures, texture coordinate generation */
  GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
  GL_TEXTURE_GEN_Q,
};

static int not_yet(GLenum pname) {
  for (size_t k = 0; k < sizeof kNotYet / sizeof kNotYet[0]; ++k) {
    if (kNotYet[k] == pname) return 1;
  }
  return 0;
}

enum { kCols = 32, kRows = 24, kCells = kCols * kRows };
static unsigned cells[kCells];
static int n_cells = 0;
static FILE* out;

static unsigned hash_floats(const GLfloat* v, int n, GLenum error) {
  unsigned h = 2166136261u ^ error;
  for (int i = 0; i < n; ++i) h = (h ^ (unsigned)(long)(v[i] * 1000.0f)) * 16777619u;
  return h;
}

static void cell(unsigned v) {
  if (n_cells < kCells) cells[n_cells] = v;
  ++n_cells;
}

/* A limit shadelab sets differently on purpose (docs/gl.md), compared as "at least". */
static int at_least(GLenum pname, int* minimum) {
  if (pname == GL_MAX_LIGHTS) return *minimum = 8, 1;           /* Mesa 8, shadelab 32 */
  if (pname == GL_MAX_TEXTURE_SIZE) return *minimum = 8192, 1;  /* Mesa 16384, shadelab 8192 */
  return 0;
}

static void dump_pname(const char* phase, const Pname* p) {
  if (not_yet(p->pname)) return;
  /* One more than the largest count: the marker after the values shows nothing more was written. */
  GLboolean b[17];
  GLint i[17];
  GLfloat f[17];
  GLdouble d[17];
  memset(b, 0x5a, sizeof b);
  for (int k = 0; k < 17; ++k) i[k] = -12345, f[k] = -12345.0f, d[k] = -12345.0;
  glGetBooleanv(p->pname, b);
  GLenum eb = glGetError();
  glGetIntegerv(p->pname, i);
  GLenum ei = glGetError();
  glGetFloatv(p->pname, f);
  GLenum ef = glGetError();
  glGetDoublev(p->pname, d);
  GLenum ed = glGetError();
  int minimum;
  if (at_least(p->pname, &minimum)) {
    fprintf(out, "%s %s at least %d: %d %d %d %d err %x %x %x %x\n", phase, p->name, minimum,
            i[0] >= minimum, f[0] >= minimum, d[0] >= minimum, b[0] == GL_TRUE, eb, ei, ef, ed);
    cell(i[0] >= minimum);
    return;
  }
  fprintf(out, "%s %s b:", phase, p->name);
  for (int k = 0; k < p->count + 1; ++k) fprintf(out, " %d", b[k]);
  fprintf(out, " err %x\n%s %s i:", eb, phase, p->name);
  /* Mesa converts matrices for glGetIntegerv as colours (2^31 - 1 for 1.0), where the
   * specification (section 6.1.2) rounds them, as shadelab does: their integers are not
   * compared. */
  int matrix = p->count == 16;
  for (int k = 0; k < p->count + 1; ++k) fprintf(out, " %d", matrix ? 0 : i[k]);
  fprintf(out, " err %x\n%s %s f:", ei, phase, p->name);
  for (int k = 0; k < p->count + 1; ++k) fprintf(out, " %.9g", f[k]);
  fprintf(out, " err %x\n%s %s d:", ef, phase, p->name);
  for (int k = 0; k < p->count + 1; ++k) fprintf(out, " %.17g", d[k]);
  fprintf(out, " err %x\n", ed);
  cell(hash_floats(f, p->count, ef));
}

static const GLenum kCaps[] = {
  GL_ALPHA_TEST, GL_AUTO_NORMAL, GL_BLEND, GL_CLIP_PLANE0, GL_CLIP_PLANE2, GL_CLIP_PLANE5,
  GL_CLIP_PLANE0 + 7, GL_COLOR_LOGIC_OP,
  GL_COLOR_MATERIAL, GL_CULL_FACE, GL_DEPTH_TEST, GL_DITHER, GL_FOG, GL_INDEX_LOGIC_OP,
  GL_LIGHT0, GL_LIGHT7, GL_LIGHTING, GL_LINE_SMOOTH, GL_LINE_STIPPLE, GL_MAP1_COLOR_4,
  GL_MAP1_INDEX, GL_MAP1_NORMAL, GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_4,
  GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP2_COLOR_4, GL_MAP2_INDEX, GL_MAP2_NORMAL,
  GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3, GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4,
  GL_NORMALIZE, GL_POINT_SMOOTH, GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE,
  GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH, GL_POLYGON_STIPPLE, GL_SCISSOR_TEST,
  GL_STENCIL_TEST, GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T,
  GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q, GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY,
  GL_INDEX_ARRAY, GL_TEXTURE_COORD_ARRAY, GL_EDGE_FLAG_ARRAY,
  /* not capabilities: GL_INVALID_ENUM */
  GL_MATRIX_MODE, GL_FRONT, 0x1234,
};

static void dump_caps(const char* phase) {
  for (size_t k = 0; k < sizeof kCaps / sizeof kCaps[0]; ++k) {
    if (not_yet(kCaps[k])) continue;
    GLboolean on = glIsEnabled(kCaps[k]);
    GLenum e = glGetError();
    fprintf(out, "%s glIsEnabled(0x%04x): %d err %x\n", phase, kCaps[k], on, e);
    cell(on * 7u + e);
  }
}

static const GLenum kPointers[] = {
  GL_VERTEX_ARRAY_POINTER, GL_NORMAL_ARRAY_POINTER, GL_COLOR_ARRAY_POINTER,
  GL_INDEX_ARRAY_POINTER, GL_TEXTURE_COORD_ARRAY_POINTER, GL_EDGE_FLAG_ARRAY_POINTER,
  GL_MATRIX_MODE,
};

/* Pointers as offsets from `base` (0 when null). */
static void dump_pointers(const char* phase, const void* base) {
  for (size_t k = 0; k < sizeof kPointers / sizeof kPointers[0]; ++k) {
    void* p = (void*)1;
    glGetPointerv(kPointers[k], &p);
    GLenum e = glGetError();
    long offset = p == (void*)1 ? -1 : p ? (long)((const char*)p - (const char*)base) : 0;
    fprintf(out, "%s glGetPointerv(0x%04x): %ld err %x\n", phase, kPointers[k], offset, e);
    cell((unsigned)offset * 3u + e);
  }
}

/* glGetClipPlane of Mesa's 8 planes (eye space), and of one past them (GL_INVALID_ENUM). */
static void dump_clip_planes(const char* phase) {
  for (int i = 0; i <= 8; ++i) {
    GLdouble d[5] = {-7, -7, -7, -7, -7};
    glGetClipPlane((GLenum)(GL_CLIP_PLANE0 + i), d);
    GLenum e = glGetError();
    fprintf(out, "%s glGetClipPlane(%d): %.9g %.9g %.9g %.9g %.9g err %x\n", phase, i, d[0], d[1], d[2], d[3],
            d[4], e);
    GLfloat f[4] = {(GLfloat)d[0], (GLfloat)d[1], (GLfloat)d[2], (GLfloat)d[3]};
    cell(hash_floats(f, 4, e));
  }
}

static void dump(const char* phase, const void* base) {
  for (int k = 0; k < kPnameCount; ++k) dump_pname(phase, &kPnames[k]);
  dump_caps(phase);
  dump_clip_planes(phase);
  dump_pointers(phase, base);
  /* Unknown pnames */
  GLint v = 77;
  glGetIntegerv(0x1234, &v);
  fprintf(out, "%s glGetIntegerv(0x1234): %d err %x\n", phase, v, glGetError());
}

static GLfloat arrays[64];

/* Every piece of state shadelab's commands set, changed from its initial value. */
static void change_state(void) {
  glMatrixMode(GL_TEXTURE);
  glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
  glPushMatrix();
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1, 10);
  glPushMatrix();
  glPushMatrix();
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(1.0f, 2.0f, 3.0f);
  glScalef(2.0f, 2.0f, 2.0f);
  glPushMatrix();
  glViewport(3, 5, 101, 77);
  glDepthRange(0.25, 0.75);
  glColor4s(1000, -2000, 32767, -32768);
  glNormal3b(12, -100, 127);
  glTexCoord3i(3, -4, 5);
  glIndexi(7);
  glEdgeFlag(GL_FALSE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT3);
  glEnable(GL_NORMALIZE);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_BACK, GL_SPECULAR);
  glShadeModel(GL_FLAT);
  GLfloat ambient[] = {0.1f, 0.2f, 0.3f, 0.4f};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT_AND_BACK);
  glFrontFace(GL_CW);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GEQUAL);
  glDepthMask(GL_FALSE);
  glClearDepth(0.5);
  glClearColor(0.25f, 0.5f, 0.75f, 1.5f);
  glClearStencil(3);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NOTEQUAL, 5, 0x0f);
  glStencilOp(GL_INCR, GL_DECR, GL_INVERT);
  glStencilMask(0x3c);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, -2.0f);
  glPointSize(3.5f);
  glLineWidth(2.5f);
  glLineStipple(3, 0xf0f0);
  glEnable(GL_LINE_STIPPLE);
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_POLYGON_OFFSET_LINE);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  {
    const GLdouble eq[4] = {1.0, -2.0, 0.5, 3.0};
    glClipPlane(GL_CLIP_PLANE2, eq); /* under the translated and scaled modelview */
    glEnable(GL_CLIP_PLANE2);
  }
  glDisable(GL_DITHER);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GEQUAL, 0.3f);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_EXP2);
  glFogf(GL_FOG_DENSITY, 0.7f);
  glFogf(GL_FOG_START, -2.5f);
  glFogf(GL_FOG_END, 11.0f);
  glFogf(GL_FOG_INDEX, 3.0f);
  GLfloat fog_color[] = {0.2f, 1.5f, -0.5f, 0.6f};
  glFogfv(GL_FOG_COLOR, fog_color);
  glEnable(GL_COLOR_LOGIC_OP);
  glEnable(GL_INDEX_LOGIC_OP);
  glLogicOp(GL_OR_REVERSE);
  glEnable(GL_SCISSOR_TEST);
  glScissor(7, -3, 50, 60);
  glEnable(GL_POLYGON_STIPPLE);
  glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
  glHint(GL_POINT_SMOOTH_HINT, GL_FASTEST);
  glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
  glHint(GL_POLYGON_SMOOTH_HINT, GL_FASTEST);
  glHint(GL_FOG_HINT, GL_NICEST);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glPixelStorei(GL_PACK_ROW_LENGTH, 17);
  glPixelStorei(GL_PACK_SKIP_ROWS, 3);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 4);
  glPixelStorei(GL_PACK_SWAP_BYTES, 1);
  glPixelStorei(GL_PACK_LSB_FIRST, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 9);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, 1);
  glPixelStorei(GL_UNPACK_LSB_FIRST, 1);
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glEnable(GL_TEXTURE_2D);
  glVertexPointer(3, GL_SHORT, 10, arrays + 1);
  glNormalPointer(GL_BYTE, 7, arrays + 2);
  glColorPointer(3, GL_UNSIGNED_INT, 0, arrays + 3);
  glIndexPointer(GL_DOUBLE, 16, arrays + 4);
  glTexCoordPointer(1, GL_INT, 5, arrays + 5);
  glEdgeFlagPointer(3, arrays + 6);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_INDEX_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
}

/* Values held as unsigned integers at their extremes: masks of all ones (glGetIntegerv clamps
 * them to 2^31 - 1, the float queries do not) and a list name past 2^31 (read back negative, as
 * Mesa's GLint of the name), queried while that list is being compiled. */
static void dump_extremes(void) {
  static const Pname kExtreme[] = {
    {GL_STENCIL_WRITEMASK, "GL_STENCIL_WRITEMASK", 1},
    {GL_STENCIL_VALUE_MASK, "GL_STENCIL_VALUE_MASK", 1},
    {GL_LIST_INDEX, "GL_LIST_INDEX", 1},
  };
  static const GLuint kNames[] = {0xFFFFFFFFu, 0x80000000u, 0x7FFFFFFFu};
  static const GLuint kMasks[] = {0xFFFFFFFFu, 0x80000001u, 0x7FFFFFFFu};
  char phase[32];
  for (int k = 0; k < 3; ++k) {
    glStencilMask(kMasks[k]);
    glStencilFunc(GL_ALWAYS, 0, kMasks[k]);
    glNewList(kNames[k], GL_COMPILE);
    snprintf(phase, sizeof phase, "extremes%d", k);
    for (int p = 0; p < 3; ++p) dump_pname(phase, &kExtreme[p]);
    glEndList();
    glDeleteLists(kNames[k], 1);
  }
  glStencilMask(0xFFFFFFFFu);
  glStencilFunc(GL_ALWAYS, 0, 0xFFFFFFFFu);
  fprintf(out, "extremes: err %x\n", glGetError());
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 192)) return 1;
  out = conf_open_values(&c);
  if (!out) return 1;
  glGetError();
  dump("fresh", arrays);
  change_state();
  fprintf(out, "changes: err %x\n", glGetError());
  dump("changed", arrays);
  glInterleavedArrays(GL_T2F_C4UB_V3F, 0, arrays + 8);
  fprintf(out, "interleaved: err %x\n", glGetError());
  dump("interleaved", arrays);
  dump_extremes();
  fclose(out);
  /* The drawing state the cells need, after the dumps changed it. */
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_COLOR_MATERIAL);
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_FOG);
  glDisable(GL_COLOR_LOGIC_OP);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_POLYGON_STIPPLE);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthRange(0.0, 1.0);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  conf_value_cells(&c, cells, n_cells, kCols, kRows);
  return conf_finish(&c);
}
