/* Display-list errors and state (GL 1.1 section 5.4), compared with Mesa value by value: each
 * value observed (a glGetError after a call, what glGenLists / glIsList / glGet return) is
 * printed and drawn as a cell of a 16 x 12 grid whose colour encodes it, so that any value
 * differing from Mesa's differs in the image. Covers glNewList's and glEndList's errors,
 * glGenLists / glDeleteLists / glIsList / glCallList(s) argument errors, the calls GL forbids
 * between glBegin and glEnd, errors compiled into a list (raised when it executes; at once in
 * GL_COMPILE_AND_EXECUTE), commands executed immediately while compiling, GL_LIST_INDEX /
 * GL_LIST_MODE / GL_LIST_BASE / GL_MAX_LIST_NESTING, a list calling itself, lists shared
 * with a second context (and not with a third). */
#include <stdio.h>
#include <stdlib.h>

#include "conf.h"

enum { kCols = 16, kRows = 12, kCells = kCols * kRows };
static unsigned values[kCells];
static int n_values = 0;

static void record(const char* what, unsigned v) {
  printf("%3d %-58s 0x%x\n", n_values, what, v);
  if (n_values < kCells) values[n_values] = v;
  ++n_values;
}

static void error(const char* what) { record(what, glGetError()); }

static GLint get_int(GLenum pname) {
  GLint v = -1;
  glGetIntegerv(pname, &v);
  return v;
}

static void new_list_errors(GLuint a) {
  glNewList(0, GL_COMPILE);
  error("glNewList(0)");
  glNewList(a, GL_POINTS);
  error("glNewList(bad mode)");
  glNewList(a, GL_COMPILE);
  error("glNewList(a, GL_COMPILE)");
  record("GL_LIST_INDEX while compiling", (unsigned)get_int(GL_LIST_INDEX) - a);
  record("GL_LIST_MODE while compiling", (unsigned)get_int(GL_LIST_MODE));
  record("glIsList(a) while compiling it", glIsList(a));
  glNewList(a + 1, GL_COMPILE);
  error("glNewList while compiling");
  glGetError();
  glEndList();
  error("glEndList");
  record("glIsList(a) after glEndList", glIsList(a));
  record("GL_LIST_INDEX after", (unsigned)get_int(GL_LIST_INDEX));
  record("GL_LIST_MODE after", (unsigned)get_int(GL_LIST_MODE));
  glEndList();
  error("glEndList without glNewList");
  record("GL_MAX_LIST_NESTING", (unsigned)get_int(GL_MAX_LIST_NESTING));
}

static void name_errors(GLuint a) {
  record("glGenLists(-1)", glGenLists(-1));
  error("  its error");
  record("glGenLists(0)", glGenLists(0));
  error("  its error");
  GLuint b = glGenLists(3);
  record("glGenLists(3) - a", b - a);
  record("glIsList(reserved)", glIsList(b + 2));
  record("glIsList(past reserved)", glIsList(b + 3));
  glDeleteLists(b, -1);
  error("glDeleteLists(-1)");
  glDeleteLists(b + 1, 1);
  error("glDeleteLists(b + 1, 1)");
  record("glIsList(deleted)", glIsList(b + 1));
  record("glIsList(kept)", glIsList(b + 2));
  glDeleteLists(0xfffffff0u, 100);
  error("glDeleteLists wrapping around");
  glDeleteLists(b, 0);
  error("glDeleteLists(b, 0)");
  record("glIsList(0)", glIsList(0));
  record("glGenLists(2) after a delete - a", glGenLists(2) - a);
}

static void call_errors(GLuint a) {
  const GLint ids[2] = {0, 1};
  glCallList(0);
  error("glCallList(0)");
  glCallList(a + 1000);
  error("glCallList(undefined)");
  glCallLists(2, GL_DOUBLE, ids);
  error("glCallLists(bad type)");
  glCallLists(-1, GL_INT, ids);
  error("glCallLists(-1)");
  glCallLists(-1, GL_DOUBLE, ids);
  error("glCallLists(-1, bad type)");
  glCallLists(0, GL_INT, NULL);
  error("glCallLists(0, NULL)");
  glCallLists(2, GL_INT, NULL);
  error("glCallLists(2, NULL)");
}

static void begin_end_errors(GLuint a) {
  glBegin(GL_TRIANGLES);
  glNewList(a + 50, GL_COMPILE);
  glEnd();
  error("glNewList in glBegin");
  glBegin(GL_TRIANGLES);
  record("glGenLists in glBegin", glGenLists(1));
  glEnd();
  error("  its error");
  glBegin(GL_TRIANGLES);
  record("glIsList in glBegin", glIsList(a));
  glEnd();
  error("  its error");
  glBegin(GL_TRIANGLES);
  glDeleteLists(a, 1);
  glEnd();
  error("glDeleteLists in glBegin");
  record("  glIsList after", glIsList(a));
  glBegin(GL_TRIANGLES);
  glListBase(3);
  glEnd();
  error("glListBase in glBegin");
  glBegin(GL_TRIANGLES);
  glEndList();
  glEnd();
  error("glEndList in glBegin, no list");
  glBegin(GL_TRIANGLES);
  glCallList(a);
  glEnd();
  error("glCallList in glBegin");
  record("GL_LIST_BASE", (unsigned)get_int(GL_LIST_BASE));
}

/* Errors compiled into lists are raised when the list runs. */
static void compiled_errors(GLuint a) {
  glNewList(a + 60, GL_COMPILE);
  glEnable(0x1234);
  glEndList();
  error("compiling glEnable(bad)");
  glCallList(a + 60);
  error("  calling it");
  glNewList(a + 61, GL_COMPILE);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 100.0f);
  glEndList();
  error("compiling glLightf(cutoff 100)");
  glCallList(a + 61);
  error("  calling it");
  GLfloat cutoff = 0.0f;
  glGetLightfv(GL_LIGHT0, GL_SPOT_CUTOFF, &cutoff);
  record("  the cutoff after", (unsigned)cutoff);
  glNewList(a + 62, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glTranslatef(1.0f, 0.0f, 0.0f);
  glEnd();
  glEndList();
  error("compiling glTranslatef in glBegin");
  glCallList(a + 62);
  error("  calling it");
  GLfloat m[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  record("  translation after", (unsigned)(m[12] * 10.0f));
  glNewList(a + 63, GL_COMPILE);
  glDrawArrays(0x1234, 0, 3);
  glDrawArrays(GL_TRIANGLES, 0, -1);
  glEndList();
  error("compiling glDrawArrays(bad mode), (count -1)");
  glCallList(a + 63);
  error("  calling it");
  glGetError();
  glNewList(a + 64, GL_COMPILE_AND_EXECUTE);
  glMatrixMode(0x4321);
  error("glMatrixMode(bad) in GL_COMPILE_AND_EXECUTE");
  record("GL_LIST_MODE", (unsigned)get_int(GL_LIST_MODE));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 3);
  error("glPixelStorei(bad) while compiling");
  glEndList();
  glCallList(a + 64);
  error("  calling the list");
  glNewList(a + 65, GL_COMPILE);
  glListBase(7);
  glEndList();
  record("GL_LIST_BASE after compiling glListBase(7)", (unsigned)get_int(GL_LIST_BASE));
  glCallList(a + 65);
  record("  after calling it", (unsigned)get_int(GL_LIST_BASE));
  glListBase(0);
}

static void begin_end_in_lists(GLuint a) {
  glNewList(a + 70, GL_COMPILE_AND_EXECUTE);
  glBegin(GL_TRIANGLES);
  glEndList();
  glEnd();  /* glGetError itself is an error between glBegin and glEnd */
  error("glEndList in an executed glBegin, then glEnd");
  record("  GL_LIST_MODE after", (unsigned)get_int(GL_LIST_MODE));
  record("  glIsList", glIsList(a + 70));
  glNewList(a + 71, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glVertex3f(0, 0, 5);  /* outside the view volume: nothing is drawn */
  glEndList();
  error("glEndList in a compiled glBegin");
  glCallList(a + 71);
  glVertex3f(1, 0, 5), glVertex3f(0, 1, 5);
  glEnd();
  error("  a list's glBegin ended outside it");
  glNewList(a + 72, GL_COMPILE);
  glCallList(a + 72);
  glColor3f(0.5f, 0.25f, 1.0f);
  glEndList();
  glCallList(a + 72);
  error("a list calling itself");
  GLfloat color[4];
  glGetFloatv(GL_CURRENT_COLOR, color);
  record("  the colour it sets", (unsigned)(color[1] * 100.0f));
}

static void shared_lists(GLuint a, const ConfContext* c) {
  static unsigned char pixels[16 * 16 * 4];
  glNewList(a + 80, GL_COMPILE);
  glColor3f(0.0f, 0.75f, 0.5f);
  glEndList();
  OSMesaContext shared = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, c->ctx);
  OSMesaContext alone = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  record("contexts made", shared != NULL && alone != NULL);
  if (!shared || !alone) return;
  OSMesaMakeCurrent(shared, pixels, GL_UNSIGNED_BYTE, 16, 16);
  record("shared: glIsList", glIsList(a + 80));
  glCallList(a + 80);
  GLfloat color[4];
  glGetFloatv(GL_CURRENT_COLOR, color);
  record("shared: the list's colour", (unsigned)(color[1] * 100.0f));
  record("shared: glGenLists(1) - a", glGenLists(1) - a);
  glNewList(a + 81, GL_COMPILE);
  glColor3f(0.0f, 0.0f, 0.0f);
  glEndList();
  OSMesaMakeCurrent(alone, pixels, GL_UNSIGNED_BYTE, 16, 16);
  record("not shared: glIsList", glIsList(a + 80));
  record("not shared: glGenLists(1)", glGenLists(1));
  OSMesaMakeCurrent(c->ctx, c->buffer, GL_UNSIGNED_BYTE, c->width, c->height);
  record("first context: the list the shared one made", glIsList(a + 81));
  OSMesaDestroyContext(shared);
  OSMesaDestroyContext(alone);
  record("after the shared context is destroyed", glIsList(a + 81));
  error("no error left");
}

static void draw(const ConfContext* c) {
  glViewport(0, 0, c->width, c->height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kCols, kRows, 0, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_LIGHTING);
  for (int i = 0; i < n_values && i < kCells; ++i) {
    /* 9 bits of the value, 3 per channel, each step 36/255 apart. */
    unsigned v = values[i], h = (v ^ (v >> 9) ^ (v >> 18) ^ (v >> 27)) & 511u;
    glColor3ub((GLubyte)(20 + 33 * (h & 7)), (GLubyte)(20 + 33 * ((h >> 3) & 7)), (GLubyte)(20 + 33 * (h >> 6)));
    float x = (float)(i % kCols), y = (float)(i / kCols);
    glBegin(GL_TRIANGLES);
    glVertex2f(x + 0.1f, y + 0.1f), glVertex2f(x + 0.9f, y + 0.1f), glVertex2f(x + 0.9f, y + 0.9f);
    glVertex2f(x + 0.1f, y + 0.1f), glVertex2f(x + 0.9f, y + 0.9f), glVertex2f(x + 0.1f, y + 0.9f);
    glEnd();
  }
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 320, 240)) return 1;
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  GLuint a = glGenLists(1);
  record("first glGenLists(1)", a);
  new_list_errors(a);
  name_errors(a);
  call_errors(a);
  begin_end_errors(a);
  compiled_errors(a);
  begin_end_in_lists(a);
  shared_lists(a, &c);
  draw(&c);
  return conf_finish(&c);
}
