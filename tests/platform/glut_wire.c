/* freeglut's wire shapes and its polyhedra, drawn by a program written for shadelab's platform
   tests (tests/platform) as a GLUT program draws them: glutWireSphere, Cube, Torus, Cone,
   Teapot, Tetrahedron, Octahedron, Dodecahedron, Icosahedron and RhombicDodecahedron, lit and
   unlit, with wide and stippled lines, beside the solid polyhedra, each in its own viewport of a
   4 x 4 grid. What GLUT draws them with (vertex arrays of lines and loops, or glBegin/glEnd) is
   freeglut's choice: the program only calls GLUT. Built with `cc glut_wire.c -lGL -lglut` and
   nothing of shadelab's: it runs on Mesa and on shadelab alike.

     glut_wire [--single] [--frames N] [--dump N FILE.ppm]

   --single         a single-buffered window (GLUT_SINGLE): each frame ends with glFlush
   --frames N       exits (status 0) after showing frame N
   --dump N FILE    before showing frame N, writes the frame as a binary PPM (glReadPixels) */
#include <GL/freeglut.h> /* glutWire/SolidRhombicDodecahedron */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { kCols = 4, kRows = 4, kCell = 96 };

static int frame = 0, last_frame = 0, dump_frame = 0, single = 0;
static const char* dump_path = NULL;

static void write_ppm(const char* path) {
  int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
  unsigned char* pixels = malloc((size_t)w * h * 3);
  FILE* f = fopen(path, "wb");
  if (!pixels || !f) {
    fprintf(stderr, "glut_wire: cannot write %s\n", path);
    exit(1);
  }
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, pixels);
  fprintf(f, "P6\n%d %d\n255\n", w, h);
  for (int y = h - 1; y >= 0; --y) fwrite(pixels + (size_t)y * w * 3, 1, (size_t)w * 3, f);
  fclose(f);
  free(pixels);
}

/* Cell `i` of the grid, row 0 at the top, with a perspective view of the unit box. */
static void cell(int i, float turn) {
  const int col = i % kCols, row = i / kCols;
  glViewport(col * kCell, (kRows - 1 - row) * kCell, kCell, kCell);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.0f);
  glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(-30.0f + turn, 0.0f, 1.0f, 0.0f);
}

static void lit(int on, float r, float g, float b) {
  if (on) {
    GLfloat diffuse[] = {r, g, b, 1.0f}, ambient[] = {r * 0.3f, g * 0.3f, b * 0.3f, 1.0f};
    GLfloat specular[] = {0.8f, 0.8f, 0.8f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
    glEnable(GL_LIGHTING);
  } else {
    glDisable(GL_LIGHTING);
    glColor3f(r, g, b);
  }
}

static void display(void) {
  ++frame;
  const float turn = 7.0f * (float)frame;
  glClearColor(0.1f, 0.1f, 0.14f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const GLfloat light_direction[] = {1.0f, 1.0f, 1.0f, 0.0f};
  int i = 0;
  cell(i++, turn);
  glLightfv(GL_LIGHT0, GL_POSITION, light_direction);
  lit(1, 0.9f, 0.4f, 0.3f);
  glutWireSphere(1.0, 16, 10);
  cell(i++, turn);
  lit(0, 0.4f, 0.9f, 0.5f);
  glutWireSphere(0.9, 7, 5);
  cell(i++, turn);
  lit(1, 0.3f, 0.6f, 1.0f);
  glutWireCube(1.3);
  cell(i++, turn);
  lit(0, 1.0f, 0.9f, 0.3f);
  glLineWidth(2.0f);
  glutWireCube(1.2);
  glLineWidth(1.0f);
  cell(i++, turn);
  lit(1, 0.8f, 0.5f, 0.9f);
  glutWireTorus(0.3, 0.8, 10, 20);
  cell(i++, turn);
  lit(1, 0.5f, 0.9f, 0.9f);
  glRotatef(-90.0f, 1.0f, 0.0f, 0.0f); /* GLUT's cone points along +z */
  glTranslatef(0.0f, 0.0f, -0.8f);
  glutWireCone(0.8, 1.6, 12, 4);
  cell(i++, turn);
  lit(1, 0.9f, 0.6f, 0.3f);
  glutWireTeapot(0.8);
  cell(i++, turn);
  lit(0, 0.9f, 0.9f, 0.9f);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x3333);
  glutWireTeapot(0.8);
  glDisable(GL_LINE_STIPPLE);
  cell(i++, turn);
  lit(1, 1.0f, 0.4f, 0.4f);
  glutWireTetrahedron();
  cell(i++, turn);
  lit(1, 0.4f, 1.0f, 0.4f);
  glutWireOctahedron();
  cell(i++, turn);
  lit(1, 0.4f, 0.6f, 1.0f);
  glScalef(0.6f, 0.6f, 0.6f);
  glutWireDodecahedron();
  cell(i++, turn);
  lit(0, 1.0f, 0.7f, 0.2f);
  glutWireIcosahedron();
  cell(i++, turn);
  lit(1, 0.7f, 0.7f, 1.0f);
  glutWireRhombicDodecahedron();
  cell(i++, turn); /* the solids of the polyhedra */
  lit(1, 0.8f, 0.3f, 0.3f);
  glTranslatef(-0.5f, 0.0f, 0.0f);
  glScalef(0.5f, 0.5f, 0.5f);
  glutSolidOctahedron();
  glTranslatef(2.0f, 0.0f, 0.0f);
  glutSolidIcosahedron();
  cell(i++, turn);
  lit(1, 0.3f, 0.8f, 0.5f);
  glScalef(0.55f, 0.55f, 0.55f);
  glutSolidDodecahedron();
  cell(i++, turn);
  lit(1, 0.6f, 0.6f, 0.9f);
  glutSolidRhombicDodecahedron();

  if (dump_path && frame == dump_frame) write_ppm(dump_path);
  if (single) glFlush();
  else glutSwapBuffers();
  if (last_frame > 0 && frame >= last_frame) exit(0);
}

static void tick(int value) {
  (void)value;
  glutPostRedisplay();
  glutTimerFunc(20, tick, 0);
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--single") == 0) single = 1;
    else if (strcmp(argv[i], "--frames") == 0 && i + 1 < argc) last_frame = atoi(argv[++i]);
    else if (strcmp(argv[i], "--dump") == 0 && i + 2 < argc) dump_frame = atoi(argv[++i]), dump_path = argv[++i];
  }
  glutInitDisplayMode((single ? GLUT_SINGLE : GLUT_DOUBLE) | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(kCols * kCell, kRows * kCell);
  glutCreateWindow("shadelab platform test: GLUT wire shapes");
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glutDisplayFunc(display);
  glutTimerFunc(20, tick, 0);
  glutMainLoop();
  return 0;
}
