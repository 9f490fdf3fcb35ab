/* Polygon stipple (GL 1.1 section 3.5.2): a 32 x 32 pattern in window coordinates (the panels
 * sit at different offsets, so each sees its own phase of it), read through the unpack
 * pixel-store state. Panels: a checkerboard, stripes and a diamond on flat and smooth
 * triangles and quads; a lit sphere in perspective; culling (front faces culled, back faces
 * stippled); the pattern given with GL_UNPACK_LSB_FIRST, with a row length, skips and an
 * alignment of 1; glGetPolygonStipple's pattern (packed with GL_PACK_LSB_FIRST and read back
 * with GL_UNPACK_LSB_FIRST) drawn again; stipple disabled between two stippled draws; depth
 * written only by the stipple's fragments. */
#include <string.h>

#include "conf.h"

static GLubyte checker[128], stripes[128], diamond[128];

static void make_patterns(void) {
  for (int y = 0; y < 32; ++y) {
    for (int b = 0; b < 4; ++b) {
      checker[y * 4 + b] = (GLubyte)((y / 2) % 2 ? 0xcc : 0x33);
      stripes[y * 4 + b] = (GLubyte)(y % 4 < 2 ? 0xff : (b == 1 ? 0x81 : 0x00));
      GLubyte d = 0;
      for (int bit = 0; bit < 8; ++bit) {
        int x = b * 8 + bit, dx = x < 16 ? 15 - x : x - 16, dy = y < 16 ? 15 - y : y - 16;
        if (dx + dy < 14 && (dx + dy) % 3 != 0) d |= (GLubyte)(0x80 >> bit);
      }
      diamond[y * 4 + b] = d;
    }
  }
}

static void ortho(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void smooth_triangle(void) {
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.2f, 0.2f);
  glVertex2f(0.05f, 0.05f);
  glColor3f(0.2f, 1.0f, 0.3f);
  glVertex2f(0.95f, 0.2f);
  glColor3f(0.3f, 0.4f, 1.0f);
  glVertex2f(0.4f, 0.95f);
  glEnd();
}

static void flat_quad(void) {
  glShadeModel(GL_FLAT);
  glBegin(GL_QUADS);
  glColor3f(0.2f, 0.2f, 0.2f);
  glVertex2f(0.1f, 0.1f);
  glVertex2f(0.9f, 0.1f);
  glVertex2f(0.9f, 0.9f);
  glColor3f(1.0f, 0.8f, 0.2f);
  glVertex2f(0.1f, 0.9f);
  glEnd();
  glShadeModel(GL_SMOOTH);
}

static void lit_sphere(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat dir[4] = {0.3f, 0.5f, 0.8f, 0.0f}, diffuse[4] = {0.3f, 0.7f, 1.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diffuse);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  glTranslatef(0.0f, 0.0f, -3.5f);
  conf_sphere(1.3f, 24, 16);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
}

static void culled(void) {
  ortho();
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glColor3f(0.9f, 0.9f, 0.9f);
  glRectf(0.1f, 0.1f, 0.5f, 0.9f); /* counter-clockwise: front, culled */
  glColor3f(0.9f, 0.4f, 0.1f);
  glRectf(0.9f, 0.1f, 0.5f, 0.9f); /* clockwise: back, drawn */
  glDisable(GL_CULL_FACE);
}

/* The diamond as a 40-pixel-wide image, LSB first, 3 rows and 5 pixels skipped. */
static void unpacked_pattern(void) {
  static GLubyte image[40 * 5 * 36 / 8];
  memset(image, 0, sizeof image);
  const int row_bytes = 5; /* 40 bits, alignment 1 */
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      int on = (diamond[y * 4 + x / 8] >> (7 - x % 8)) & 1;
      int bit = x + 5, row = y + 3;
      if (on) image[row * row_bytes + bit / 8] |= (GLubyte)(1 << (bit % 8));
    }
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 40);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 5);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
  glPolygonStipple(image);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
}

static void round_trip(void) {
  GLubyte got[128];
  glPolygonStipple(stripes);
  glPixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
  glGetPolygonStipple(got);
  glPixelStorei(GL_PACK_LSB_FIRST, GL_FALSE);
  glPolygonStipple(checker);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPolygonStipple(got); /* the stripes again */
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
}

static void depth_panel(void) {
  ortho();
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.9f, 0.2f, 0.6f);
  glBegin(GL_QUADS); /* stippled, in front */
  glVertex3f(0.0f, 0.2f, 0.5f);
  glVertex3f(1.0f, 0.2f, 0.5f);
  glVertex3f(1.0f, 0.8f, 0.5f);
  glVertex3f(0.0f, 0.8f, 0.5f);
  glEnd();
  glDisable(GL_POLYGON_STIPPLE);
  glColor3f(0.2f, 0.9f, 0.3f);
  glBegin(GL_QUADS); /* behind, unstippled: shows through the gaps only */
  glVertex3f(0.2f, 0.0f, -0.5f);
  glVertex3f(0.8f, 0.0f, -0.5f);
  glVertex3f(0.8f, 1.0f, -0.5f);
  glVertex3f(0.2f, 1.0f, -0.5f);
  glEnd();
  glEnable(GL_POLYGON_STIPPLE);
  glDisable(GL_DEPTH_TEST);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 345, 258)) return 1; /* panels not on multiples of 32 */
  make_patterns();
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_POLYGON_STIPPLE);
  const GLubyte* patterns[3] = {checker, stripes, diamond};
  for (int i = 0; i < 3; ++i) {
    glPolygonStipple(patterns[i]);
    conf_panel(&c, i, 0, 4, 3);
    ortho();
    smooth_triangle();
    conf_panel(&c, i, 1, 4, 3);
    ortho();
    flat_quad();
  }
  conf_panel(&c, 3, 0, 4, 3);
  lit_sphere();
  glPolygonStipple(checker);
  conf_panel(&c, 3, 1, 4, 3);
  culled();
  unpacked_pattern();
  conf_panel(&c, 0, 2, 4, 3);
  ortho();
  smooth_triangle();
  round_trip();
  conf_panel(&c, 1, 2, 4, 3);
  ortho();
  flat_quad();
  conf_panel(&c, 2, 2, 4, 3);
  ortho();
  glDisable(GL_POLYGON_STIPPLE);
  smooth_triangle();
  glEnable(GL_POLYGON_STIPPLE);
  glPolygonStipple(diamond);
  glColor3f(0.0f, 0.0f, 0.0f);
  glRectf(0.3f, 0.3f, 0.7f, 0.7f);
  conf_panel(&c, 3, 2, 4, 3);
  depth_panel();
  glDisable(GL_POLYGON_STIPPLE);
  return conf_finish(&c);
}
