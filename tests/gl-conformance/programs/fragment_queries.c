/* Errors and state queries of fog, scissor, alpha test, logic op, polygon stipple and dither
 * (GL 1.1 sections 3.5.2, 3.9, 4.1.2-4.1.7, 6.1), compared with Mesa value for value: each
 * check records the GL errors its calls raise and the values its queries return, and paints
 * one cell of a grid in a colour made from a hash of them (any difference from Mesa's answers
 * changes the colour); the answers are also printed. Covers the initial state, every glFog
 * parameter through each of glFogf/i/fv/iv (a scalar call with GL_FOG_COLOR, integer colours,
 * clamping), invalid modes, densities, functions, ops and sizes, GL 1.1's GL_LOGIC_OP alias,
 * GL_FOG_HINT, the glGet conversions (boolean, integer, float, double) of each value, calls
 * between glBegin and glEnd, glGetPolygonStipple through the pack state, and the state set
 * in display lists (the pattern unpacked when compiled). */
#include <stdio.h>
#include <string.h>

#include "conf.h"

#define kCells 48
static unsigned hashes[kCells];
static int n_checks = 0;
static unsigned current = 2166136261u;

static void mix(const void* p, size_t n) {
  const unsigned char* b = (const unsigned char*)p;
  for (size_t i = 0; i < n; ++i) current = (current ^ b[i]) * 16777619u;
}

static void record_errors(void) {
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
    printf(" error 0x%04x", e);
    mix(&e, sizeof e);
  }
}

static void begin_check(const char* what) { printf("check %d (%s):", n_checks, what); current = 2166136261u; }

static void end_check(void) {
  record_errors();
  printf("\n");
  if (n_checks < kCells) hashes[n_checks] = current;
  ++n_checks;
}

/* Every glGet form of one parameter with up to 4 values. */
static void get_all(GLenum pname, int n) {
  GLboolean b[4] = {0};
  GLint i[4] = {0};
  GLfloat f[4] = {0};
  GLdouble d[4] = {0};
  glGetBooleanv(pname, b);
  glGetIntegerv(pname, i);
  glGetFloatv(pname, f);
  glGetDoublev(pname, d);
  record_errors();
  for (int k = 0; k < n; ++k) {
    printf(" [%d %d %g %g]", b[k], i[k], f[k], d[k]);
    mix(&b[k], sizeof b[k]);
    mix(&i[k], sizeof i[k]);
    mix(&f[k], sizeof f[k]);
    mix(&d[k], sizeof d[k]);
  }
}

static void enabled(GLenum cap) {
  GLboolean e = glIsEnabled(cap);
  printf(" enabled(0x%04x)=%d", cap, e);
  mix(&e, sizeof e);
}

static void initial_state(void) {
  begin_check("initial fog");
  get_all(GL_FOG_MODE, 1), get_all(GL_FOG_DENSITY, 1), get_all(GL_FOG_START, 1), get_all(GL_FOG_END, 1);
  get_all(GL_FOG_INDEX, 1), get_all(GL_FOG_COLOR, 4), get_all(GL_FOG_HINT, 1);
  end_check();
  begin_check("initial fragment state");
  get_all(GL_SCISSOR_BOX, 4), get_all(GL_ALPHA_TEST_FUNC, 1), get_all(GL_ALPHA_TEST_REF, 1);
  get_all(GL_LOGIC_OP_MODE, 1);
  enabled(GL_FOG), enabled(GL_SCISSOR_TEST), enabled(GL_ALPHA_TEST), enabled(GL_COLOR_LOGIC_OP);
  enabled(GL_LOGIC_OP), enabled(GL_POLYGON_STIPPLE), enabled(GL_DITHER);
  end_check();
  begin_check("initial stipple");
  GLubyte p[128];
  memset(p, 0x5a, sizeof p);
  glGetPolygonStipple(p);
  mix(p, sizeof p);
  printf(" %02x %02x", p[0], p[127]);
  end_check();
}

static void fog_calls(void) {
  const GLenum modes[5] = {GL_LINEAR, GL_EXP2, GL_EXP, GL_LINE, 0};
  for (int k = 0; k < 5; ++k) {
    begin_check("fog mode");
    if (k % 2) glFogf(GL_FOG_MODE, (GLfloat)modes[k]);
    else glFogi(GL_FOG_MODE, (GLint)modes[k]);
    get_all(GL_FOG_MODE, 1);
    end_check();
  }
  const GLfloat values[4] = {0.25f, -1.0f, 0.0f, 1e10f};
  for (int k = 0; k < 4; ++k) {
    begin_check("fog density, start, end, index");
    glFogf(GL_FOG_DENSITY, values[k]);
    GLint iv = k == 3 ? 2000000000 : (GLint)(values[k] * 4.0f);
    glFogiv(GL_FOG_START, &iv);
    glFogfv(GL_FOG_END, &values[(k + 1) % 4]);
    glFogi(GL_FOG_INDEX, k - 2);
    get_all(GL_FOG_DENSITY, 1), get_all(GL_FOG_START, 1), get_all(GL_FOG_END, 1), get_all(GL_FOG_INDEX, 1);
    end_check();
  }
  begin_check("fog colour as floats, clamped");
  const GLfloat color[4] = {1.5f, -0.25f, 0.3f, 0.75f};
  glFogfv(GL_FOG_COLOR, color);
  get_all(GL_FOG_COLOR, 4);
  end_check();
  begin_check("fog colour as integers");
  const GLint icolor[4] = {0x7fffffff, 0, -0x7fffffff, 0x40000000};
  glFogiv(GL_FOG_COLOR, icolor);
  get_all(GL_FOG_COLOR, 4);
  end_check();
  begin_check("fog colour through glFogf and glFogi");
  glFogf(GL_FOG_COLOR, 0.5f);
  get_all(GL_FOG_COLOR, 4);
  glFogi(GL_FOG_COLOR, 1);
  get_all(GL_FOG_COLOR, 4);
  end_check();
  begin_check("fog bad parameter names");
  glFogf(GL_FOG_BIT, 1.0f);
  glFogi(GL_SHININESS, 1);
  glFogfv(GL_LIGHT0, values);
  end_check();
  begin_check("fog hint");
  glHint(GL_FOG_HINT, GL_NICEST);
  get_all(GL_FOG_HINT, 1);
  glHint(GL_FOG_HINT, GL_LINE);
  get_all(GL_FOG_HINT, 1);
  end_check();
}

static void fragment_calls(void) {
  begin_check("scissor");
  glScissor(-5, -6, 10, 11);
  get_all(GL_SCISSOR_BOX, 4);
  glScissor(1, 2, -1, 4);
  glScissor(1, 2, 3, -4);
  get_all(GL_SCISSOR_BOX, 4);
  glScissor(7, 8, 0, 0);
  get_all(GL_SCISSOR_BOX, 4);
  end_check();
  const GLenum funcs[4] = {GL_GEQUAL, GL_NEVER, GL_LINE, GL_ALWAYS + 1};
  const GLfloat refs[4] = {0.25f, 1.5f, 0.75f, -0.5f};
  for (int k = 0; k < 4; ++k) {
    begin_check("alpha func");
    glAlphaFunc(funcs[k], refs[k]);
    get_all(GL_ALPHA_TEST_FUNC, 1), get_all(GL_ALPHA_TEST_REF, 1);
    end_check();
  }
  begin_check("alpha ref below 0");
  glAlphaFunc(GL_LESS, -0.5f);
  get_all(GL_ALPHA_TEST_REF, 1);
  end_check();
  const GLenum ops[4] = {GL_XOR, GL_SET, GL_CLEAR - 1, GL_SET + 1};
  for (int k = 0; k < 4; ++k) {
    begin_check("logic op");
    glLogicOp(ops[k]);
    get_all(GL_LOGIC_OP_MODE, 1);
    end_check();
  }
  begin_check("GL_LOGIC_OP is the index logic op");
  glEnable(GL_LOGIC_OP);
  enabled(GL_LOGIC_OP), enabled(GL_COLOR_LOGIC_OP);
  get_all(GL_LOGIC_OP, 1), get_all(GL_COLOR_LOGIC_OP, 1);
  glDisable(GL_LOGIC_OP);
  glEnable(GL_COLOR_LOGIC_OP);
  enabled(GL_LOGIC_OP), enabled(GL_COLOR_LOGIC_OP);
  glDisable(GL_COLOR_LOGIC_OP);
  end_check();
  begin_check("enables");
  const GLenum caps[6] = {GL_FOG, GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_POLYGON_STIPPLE, GL_DITHER, GL_COLOR_LOGIC_OP};
  for (int k = 0; k < 6; ++k) {
    glEnable(caps[k]);
    enabled(caps[k]);
    get_all(caps[k], 1);
    glDisable(caps[k]);
    enabled(caps[k]);
  }
  glEnable(GL_DITHER);
  end_check();
}

static void inside_begin_end(void) {
  GLubyte p[128];
  const GLfloat one = 1.0f;
  const GLint ione = 1;
  begin_check("calls between glBegin and glEnd");
  glBegin(GL_TRIANGLES);
  glFogf(GL_FOG_START, 3.0f);
  glFogi(GL_FOG_MODE, GL_EXP);
  glFogfv(GL_FOG_END, &one);
  glFogiv(GL_FOG_END, &ione);
  glScissor(0, 0, 1, 1);
  glAlphaFunc(GL_LESS, 0.5f);
  glLogicOp(GL_AND);
  glPolygonStipple(p);
  glGetPolygonStipple(p);
  glEnd();
  record_errors();
  get_all(GL_FOG_START, 1), get_all(GL_SCISSOR_BOX, 4), get_all(GL_LOGIC_OP_MODE, 1);
  end_check();
}

static void stipple_pack(void) {
  GLubyte pattern[128], out[320]; /* also read as 32 rows of 8 bytes below */
  for (int i = 0; i < 128; ++i) pattern[i] = (GLubyte)(i * 37 + 11);
  begin_check("stipple through the pack state");
  glPolygonStipple(pattern);
  memset(out, 0xa5, sizeof out);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glPixelStorei(GL_PACK_ROW_LENGTH, 43);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_PACK_SKIP_ROWS, 2);
  glPixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
  glGetPolygonStipple(out);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  glPixelStorei(GL_PACK_LSB_FIRST, GL_FALSE);
  mix(out, sizeof out);
  printf(" %02x %02x %02x %02x", out[12], out[13], out[100], out[200]);
  end_check();
  begin_check("stipple unpacked with alignment 8 and read back");
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 33);
  glPolygonStipple(out);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glGetPolygonStipple(pattern);
  mix(pattern, sizeof pattern);
  printf(" %02x %02x", pattern[0], pattern[127]);
  end_check();
}

/* The state set through display lists: the pattern unpacked when the list is compiled (with
 * the unpack state of that moment), glGet executed at once while compiling. */
static void in_lists(void) {
  GLubyte pattern[128], got[128];
  for (int i = 0; i < 128; ++i) pattern[i] = (GLubyte)(i * 13 + 5);
  const GLfloat color[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  const GLint icolor[4] = {0x40000000, 0x20000000, 0, 0x7fffffff};
  begin_check("display list");
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 2.5f);
  glFogfv(GL_FOG_COLOR, color);
  glScissor(3, 4, 5, 6);
  glAlphaFunc(GL_NOTEQUAL, 0.125f);
  glLogicOp(GL_NAND);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE); /* executed at once */
  glPolygonStipple(pattern);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glGetPolygonStipple(got); /* executed at once: the pattern before the list runs */
  mix(got, sizeof got);
  glEnable(GL_FOG);
  glEndList();
  get_all(GL_FOG_MODE, 1), get_all(GL_FOG_START, 1), get_all(GL_SCISSOR_BOX, 4), enabled(GL_FOG);
  glCallList(list);
  get_all(GL_FOG_MODE, 1), get_all(GL_FOG_START, 1), get_all(GL_FOG_COLOR, 4), get_all(GL_SCISSOR_BOX, 4);
  get_all(GL_ALPHA_TEST_FUNC, 1), get_all(GL_ALPHA_TEST_REF, 1), get_all(GL_LOGIC_OP_MODE, 1), enabled(GL_FOG);
  glGetPolygonStipple(got);
  mix(got, sizeof got);
  printf(" %02x %02x", got[0], got[127]);
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  glFogiv(GL_FOG_COLOR, icolor);
  glFogf(GL_FOG_DENSITY, -2.0f); /* the error when the list runs (and now) */
  glEndList();
  get_all(GL_FOG_COLOR, 4);
  record_errors();
  glFogf(GL_FOG_DENSITY, 0.5f);
  glCallList(list);
  get_all(GL_FOG_COLOR, 4), get_all(GL_FOG_DENSITY, 1);
  glDisable(GL_FOG);
  glDeleteLists(list, 1);
  end_check();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 192, 144)) return 1;
  initial_state();
  fog_calls();
  fragment_calls();
  inside_begin_end();
  stipple_pack();
  in_lists();
  glViewport(0, 0, c.width, c.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 8.0, 0.0, 6.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  for (int i = 0; i < n_checks && i < kCells; ++i) {
    unsigned h = hashes[i];
    glColor3ub((GLubyte)(h >> 24), (GLubyte)(h >> 16), (GLubyte)(h >> 8));
    glRectf((float)(i % 8) + 0.05f, (float)(5 - i / 8) + 0.05f, (float)(i % 8) + 0.95f, (float)(5 - i / 8) + 0.95f);
  }
  printf("%d checks\n", n_checks);
  return conf_finish(&c);
}
