/* A classic GLUT + GLU program, written for shadelab's platform tests (tests/platform): a lit
   scene of GLUT and GLU shapes (the teapot, a torus, a GLU sphere, cylinder and disk) seen
   through gluPerspective and gluLookAt, double-buffered with a depth buffer, redrawn on a timer
   with the scene turned a little each frame. Built with `cc glut_scene.c -lGL -lGLU -lglut -lm`
   and nothing of shadelab's: it runs on Mesa and on shadelab alike.

     glut_scene [--single] [--frames N] [--dump N FILE.ppm] [--say TEXT]

   --single         a single-buffered window (GLUT_SINGLE): each frame ends with glFlush
   --frames N       exits (status 0) after showing frame N
   --dump N FILE    before showing frame N, writes the frame as a binary PPM (glReadPixels)
   --say TEXT       prints TEXT on standard output at the start, left in stdio's buffer */
#include <GL/glut.h>
#include <GL/glu.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int frame = 0, last_frame = 0, dump_frame = 0, single = 0;
static const char* dump_path = NULL;
static GLUquadric* quadric = NULL;

static void write_ppm(const char* path) {
  int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
  unsigned char* pixels = malloc((size_t)w * h * 3);
  FILE* f = fopen(path, "wb");
  if (!pixels || !f) {
    fprintf(stderr, "glut_scene: cannot write %s\n", path);
    exit(1);
  }
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, pixels);
  fprintf(f, "P6\n%d %d\n255\n", w, h);
  for (int y = h - 1; y >= 0; --y) fwrite(pixels + (size_t)y * w * 3, 1, (size_t)w * 3, f);
  fclose(f);
  free(pixels);
}

static void material(float r, float g, float b, float shininess) {
  GLfloat diffuse[] = {r, g, b, 1.0f};
  GLfloat ambient[] = {r * 0.25f, g * 0.25f, b * 0.25f, 1.0f};
  GLfloat specular[] = {0.7f, 0.7f, 0.7f, 1.0f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
}

static void display(void) {
  ++frame;
  glClearColor(0.1f, 0.12f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0.0, 2.5, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
  GLfloat light_position[] = {3.0f, 5.0f, 4.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
  glRotatef(10.0f * (float)frame, 0.0f, 1.0f, 0.0f);

  glPushMatrix();  /* the teapot, wound clockwise as GLUT's is */
  material(0.8f, 0.2f, 0.15f, 60.0f);
  glFrontFace(GL_CW);
  glutSolidTeapot(1.0);
  glFrontFace(GL_CCW);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(-2.3f, 0.0f, 0.0f);
  material(0.2f, 0.7f, 0.3f, 30.0f);
  gluSphere(quadric, 0.8, 32, 16);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(2.3f, -0.6f, 0.0f);
  glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
  material(0.25f, 0.35f, 0.85f, 90.0f);
  gluCylinder(quadric, 0.6, 0.3, 1.4, 24, 4);
  glTranslatef(0.0f, 0.0f, 1.4f);
  gluDisk(quadric, 0.0, 0.3, 24, 2);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0.0f, -1.2f, 0.0f);
  glRotatef(90.0f, 1.0f, 0.0f, 0.0f);
  material(0.85f, 0.75f, 0.3f, 20.0f);
  glutSolidTorus(0.25, 2.8, 16, 48);
  glPopMatrix();

  if (dump_path && frame == dump_frame) write_ppm(dump_path);
  if (single) glFlush();
  else glutSwapBuffers();
  if (last_frame > 0 && frame >= last_frame) exit(0);
}

static void reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40.0, (double)w / (double)(h > 0 ? h : 1), 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
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
    else if (strcmp(argv[i], "--say") == 0 && i + 1 < argc) printf("%s\n", argv[++i]);  /* buffered: no flush */
  }
  glutInitDisplayMode((single ? GLUT_SINGLE : GLUT_DOUBLE) | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(320, 240);
  glutCreateWindow("shadelab platform test: GLUT + GLU");
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glShadeModel(GL_SMOOTH);
  quadric = gluNewQuadric();
  gluQuadricNormals(quadric, GLU_SMOOTH);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutTimerFunc(20, tick, 0);
  glutMainLoop();
  return 0;
}
