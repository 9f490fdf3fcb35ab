/* A GLUT program with a multisampled window (GLUT_MULTISAMPLE), in the style of the classic
   examples: what multisampling changes, panel by panel, compared frame by frame with Mesa's
   llvmpipe by compare_with_mesa.sh (docs/platform.md). Built with
   `cc glut_multisample.c -lGL -lglut`; nothing of shadelab's.
     glut_multisample [--frames N]
   Exits with status 1 when the window has no multisample buffer (GL_SAMPLE_BUFFERS 0) or a GL
   error is left. Panels (4 columns, 3 rows, bottom row first): smooth-shaded triangles crossing
   in depth; lines of width 1 and 3 with GL_LINE_SMOOTH on (ignored when multisampling);
   points; a textured, rotated checkerboard; glSampleCoverage 0.5 and its inverse; alpha to
   coverage over a gradient of alpha; a triangle with GL_MULTISAMPLE off; glDrawPixels and
   glBitmap; a scissored glClear; a stencil mask drawn by a triangle; blended triangles;
   glCopyPixels of the first panel. Each frame turns the shapes a little. */
#include <GL/glut.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int frame = 0, last_frame = 0, width = 400, height = 400;
static GLuint checker = 0;

/* The cell (column, row) as a box of the window: x, y, w, h. */
static void cell(int column, int row, float* box) {
  box[2] = (float)width / 4.0f, box[3] = (float)height / 3.0f;
  box[0] = box[2] * (float)column, box[1] = box[3] * (float)row;
}

/* Model coordinates [-1, 1]^2 onto the cell, turned by `angle` degrees. */
static void enter_cell(int column, int row, float angle) {
  float b[4];
  cell(column, row, b);
  glPushMatrix();
  glTranslatef(b[0] + b[2] / 2.0f, b[1] + b[3] / 2.0f, 0.0f);
  glScalef(b[2] * 0.45f, b[3] * 0.45f, 1.0f);
  glRotatef(angle, 0.0f, 0.0f, 1.0f);
}

static void triangle(float r, float g, float b, float a, float z) {
  glBegin(GL_TRIANGLES);
  glColor4f(r, g, b, a);
  glVertex3f(-0.9f, -0.7f, z);
  glColor4f(g, b, r, a);
  glVertex3f(0.85f, -0.5f, -z);
  glColor4f(b, r, g, a);
  glVertex3f(-0.1f, 0.9f, z);
  glEnd();
}

static void quad(float x0, float y0, float x1, float y1) {
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f), glVertex2f(x0, y0);
  glTexCoord2f(1.0f, 0.0f), glVertex2f(x1, y0);
  glTexCoord2f(1.0f, 1.0f), glVertex2f(x1, y1);
  glTexCoord2f(0.0f, 1.0f), glVertex2f(x0, y1);
  glEnd();
}

static void display(void) {
  ++frame;
  const float turn = 7.0f * (float)frame;
  glClearColor(0.08f, 0.1f, 0.16f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  /* Triangles crossing in depth. */
  glEnable(GL_DEPTH_TEST);
  enter_cell(0, 0, 10.0f + turn);
  triangle(1.0f, 0.3f, 0.1f, 1.0f, 0.5f);
  glRotatef(60.0f, 0.0f, 0.0f, 1.0f);
  triangle(0.1f, 0.5f, 1.0f, 1.0f, -0.5f);
  glPopMatrix();
  glDisable(GL_DEPTH_TEST);

  /* Lines, smooth asked for. */
  enter_cell(1, 0, turn);
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int i = 0; i < 8; ++i) {
    const float a = (float)i * 0.39f;
    glLineWidth(i < 4 ? 1.0f : 3.0f);
    glBegin(GL_LINES);
    glColor3f(1.0f, 0.9f - 0.1f * (float)i, 0.3f);
    glVertex2f(0.1f * cosf(a), 0.1f * sinf(a));
    glVertex2f(0.95f * cosf(a + 0.3f), 0.95f * sinf(a + 0.3f));
    glEnd();
  }
  glDisable(GL_BLEND);
  glDisable(GL_LINE_SMOOTH);
  glLineWidth(1.0f);
  glPopMatrix();

  /* Points. */
  enter_cell(2, 0, 0.0f);
  glEnable(GL_POINT_SMOOTH);
  for (int i = 0; i < 3; ++i) {
    glPointSize(1.0f + 3.0f * (float)i);
    glBegin(GL_POINTS);
    for (int j = 0; j < 4; ++j) {
      glColor3f(0.3f + 0.2f * (float)j, 1.0f, 0.5f);
      glVertex2f(-0.7f + 0.47f * (float)j + 0.013f * (float)frame, -0.6f + 0.6f * (float)i + 0.17f);
    }
    glEnd();
  }
  glDisable(GL_POINT_SMOOTH);
  glPointSize(1.0f);
  glPopMatrix();

  /* A textured, rotated checkerboard. */
  enter_cell(3, 0, 20.0f + turn);
  glEnable(GL_TEXTURE_2D);
  glColor3f(1.0f, 1.0f, 1.0f);
  quad(-0.8f, -0.8f, 0.8f, 0.8f);
  glDisable(GL_TEXTURE_2D);
  glPopMatrix();

  /* Sample coverage: half the samples, then the other half in another colour. */
  enter_cell(0, 1, 15.0f + turn);
  glColor3f(0.9f, 0.9f, 0.2f);
  quad(-0.9f, -0.5f, 0.5f, 0.9f);
  glEnable(GL_SAMPLE_COVERAGE);
  glSampleCoverage(0.5f, GL_FALSE);
  glColor3f(0.2f, 0.4f, 1.0f);
  quad(-0.6f, -0.9f, 0.9f, 0.4f);
  glSampleCoverage(0.5f, GL_TRUE);
  glColor3f(1.0f, 0.2f, 0.6f);
  quad(-0.3f, -0.3f, 0.7f, 0.7f);
  glSampleCoverage(1.0f, GL_FALSE);
  glDisable(GL_SAMPLE_COVERAGE);
  glPopMatrix();

  /* Alpha to coverage: alpha from 0 at the left to 1 at the right. */
  enter_cell(1, 1, 0.0f);
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glBegin(GL_QUADS);
  glColor4f(1.0f, 0.5f, 0.2f, 0.0f), glVertex2f(-0.9f, -0.9f);
  glColor4f(1.0f, 0.5f, 0.2f, 1.0f), glVertex2f(0.9f, -0.9f);
  glColor4f(0.2f, 0.9f, 1.0f, 1.0f), glVertex2f(0.9f, 0.9f);
  glColor4f(0.2f, 0.9f, 1.0f, 0.0f), glVertex2f(-0.9f, 0.9f);
  glEnd();
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glPopMatrix();

  /* Multisampling off: single-sample rasterization. */
  enter_cell(2, 1, 30.0f + turn);
  glDisable(GL_MULTISAMPLE);
  triangle(0.9f, 0.2f, 0.9f, 1.0f, 0.0f);
  glEnable(GL_MULTISAMPLE);
  glPopMatrix();

  /* glDrawPixels and glBitmap. */
  {
    float b[4];
    cell(3, 1, b);
    static GLubyte image[24 * 24 * 4];
    for (int y = 0; y < 24; ++y) {
      for (int x = 0; x < 24; ++x) {
        GLubyte* p = image + (y * 24 + x) * 4;
        p[0] = (GLubyte)(x * 10), p[1] = (GLubyte)(y * 10), p[2] = (GLubyte)(((x ^ y) & 4) ? 255 : 40), p[3] = 255;
      }
    }
    static const GLubyte bits[8] = {0x18, 0x3c, 0x7e, 0xff, 0xff, 0x7e, 0x3c, 0x18};
    glRasterPos2f(b[0] + 8.0f, b[1] + 8.0f);
    glDrawPixels(24, 24, GL_RGBA, GL_UNSIGNED_BYTE, image);
    glColor3f(1.0f, 1.0f, 1.0f);
    glRasterPos2f(b[0] + 40.0f, b[1] + 12.0f);
    glBitmap(8, 8, 0.0f, 0.0f, 0.0f, 0.0f, bits);
  }

  /* A scissored clear. */
  {
    float b[4];
    cell(0, 2, b);
    glEnable(GL_SCISSOR_TEST);
    glScissor((int)b[0] + 10, (int)b[1] + 10, (int)b[2] / 2, (int)b[3] / 2);
    glClearColor(0.6f, 0.2f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    enter_cell(0, 2, turn);
    glColor3f(0.9f, 0.9f, 0.9f);
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.2f, -0.9f), glVertex2f(0.9f, -0.1f), glVertex2f(0.1f, 0.9f);
    glEnd();
    glPopMatrix();
  }

  /* A stencil mask drawn by a triangle, then a quad through it. */
  enter_cell(1, 2, 40.0f + turn);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  triangle(1.0f, 1.0f, 1.0f, 1.0f, 0.0f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glLoadIdentity();
  enter_cell(1, 2, 0.0f);
  glColor3f(0.3f, 1.0f, 0.6f);
  quad(-1.0f, -1.0f, 1.0f, 1.0f);
  glPopMatrix();
  glDisable(GL_STENCIL_TEST);
  glLoadIdentity();

  /* Blended triangles. */
  enter_cell(2, 2, turn);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  triangle(1.0f, 0.2f, 0.2f, 0.6f, 0.0f);
  glRotatef(120.0f, 0.0f, 0.0f, 1.0f);
  triangle(0.2f, 1.0f, 0.3f, 0.5f, 0.0f);
  glDisable(GL_BLEND);
  glPopMatrix();

  /* glCopyPixels of the first panel. */
  {
    float from[4], to[4];
    cell(0, 0, from);
    cell(3, 2, to);
    glRasterPos2f(to[0], to[1]);
    glCopyPixels((int)from[0], (int)from[1], (int)from[2], (int)from[3], GL_COLOR);
  }

  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    fprintf(stderr, "glut_multisample: GL error 0x%x in frame %d\n", error, frame);
    exit(1);
  }
  glutSwapBuffers();
  if (last_frame > 0 && frame >= last_frame) exit(0);
}

static void reshape(int w, int h) {
  width = w, height = h;
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, (double)w, 0.0, (double)h, -1.0, 1.0);
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
    if (strcmp(argv[i], "--frames") == 0 && i + 1 < argc) last_frame = atoi(argv[++i]);
  }
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH | GLUT_STENCIL | GLUT_MULTISAMPLE);
  glutInitWindowSize(width, height);
  glutCreateWindow("shadelab platform test: multisampling");
  GLint buffers = 0, samples = 0;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &buffers);
  glGetIntegerv(GL_SAMPLES, &samples);
  if (buffers != 1 || samples < 2) {
    fprintf(stderr, "glut_multisample: no multisample buffer (GL_SAMPLE_BUFFERS %d, GL_SAMPLES %d)\n", buffers, samples);
    return 1;
  }
  static GLubyte texels[8 * 8 * 3];
  for (int i = 0; i < 64; ++i) {
    const int on = ((i % 8) ^ (i / 8)) & 1;
    texels[i * 3] = on ? 230 : 30, texels[i * 3 + 1] = on ? 200 : 60, texels[i * 3 + 2] = on ? 40 : 160;
  }
  glGenTextures(1, &checker);
  glBindTexture(GL_TEXTURE_2D, checker);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutTimerFunc(20, tick, 0);
  glutMainLoop();
  return 0;
}
