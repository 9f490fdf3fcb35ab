/* GL 1.3's transpose matrices: glLoadTransposeMatrixf/d and glMultTransposeMatrixf/d on the
 * modelview, projection and texture stacks (drawn: perspective and sheared quads, a texture
 * matrix on a checker texture), in display lists too, and the GL_TRANSPOSE_*_MATRIX queries
 * as floats, doubles and booleans compared value by value with Mesa's, with the errors. */
#define GL_GLEXT_PROTOTYPES
#include <string.h>

#include "conf.h"

static void record_matrices(ConfContext* c, const char* when) {
  static const GLenum names[] = {GL_TRANSPOSE_MODELVIEW_MATRIX, GL_TRANSPOSE_PROJECTION_MATRIX,
                                 GL_TRANSPOSE_TEXTURE_MATRIX, GL_MODELVIEW_MATRIX};
  static const char* labels[] = {"transpose modelview", "transpose projection", "transpose texture", "modelview"};
  char label[128];
  for (int q = 0; q < 4; ++q) {
    GLfloat f[16];
    GLdouble d[16], v[16];
    GLboolean b[16];
    glGetFloatv(names[q], f);
    glGetDoublev(names[q], d);
    glGetBooleanv(names[q], b);
    snprintf(label, sizeof label, "%s %s float", when, labels[q]);
    for (int k = 0; k < 16; ++k) v[k] = f[k];
    conf_values(c, label, v, 16);
    snprintf(label, sizeof label, "%s %s double", when, labels[q]);
    conf_values(c, label, d, 16);
    snprintf(label, sizeof label, "%s %s bool", when, labels[q]);
    for (int k = 0; k < 16; ++k) v[k] = b[k];
    conf_values(c, label, v, 16);
    conf_error(c, label);
  }
}

static void quad(void) {
  glBegin(GL_TRIANGLES);
  glTexCoord2f(0, 0), glColor3f(1, 0.2f, 0.2f), glVertex3f(-1, -1, 0);
  glTexCoord2f(1, 0), glColor3f(0.2f, 1, 0.2f), glVertex3f(1, -1, 0);
  glTexCoord2f(1, 1), glColor3f(0.2f, 0.2f, 1), glVertex3f(1, 1, 0);
  glTexCoord2f(0, 0), glColor3f(1, 0.2f, 0.2f), glVertex3f(-1, -1, 0);
  glTexCoord2f(1, 1), glColor3f(0.2f, 0.2f, 1), glVertex3f(1, 1, 0);
  glTexCoord2f(0, 1), glColor3f(1, 1, 1), glVertex3f(-1, 1, 0);
  glEnd();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  /* A perspective projection given row by row (glFrustum(-1, 1, -1, 1, 1, 10)). */
  const GLdouble n = 1.0, f = 10.0;
  const GLdouble frustum_rows[16] = {n, 0, 0, 0, 0, n, 0, 0, 0, 0, -(f + n) / (f - n), -2 * f * n / (f - n), 0, 0, -1, 0};
  /* A shear and translation, row by row. */
  const GLfloat shear_rows[16] = {1, 0.4f, 0, 0.1f, 0.2f, 1, 0, -0.2f, 0, 0, 1, -3.0f, 0, 0, 0, 1};
  const GLfloat scale_rows[16] = {0.7f, 0, 0, 0, 0, 0.6f, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const GLdouble tex_rows[16] = {2, 0.5, 0, 0.25, 0, 3, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  GLubyte checker[8][8][4];
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const GLubyte v = (GLubyte)(((x + y) % 2) ? 230 : 40);
      checker[y][x][0] = v, checker[y][x][1] = (GLubyte)(255 - v), checker[y][x][2] = 128, checker[y][x][3] = 255;
    }

  record_matrices(&c, "initial");
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);

  conf_panel(&c, 0, 0, 2, 2);
  glMatrixMode(GL_PROJECTION);
  glLoadTransposeMatrixd(frustum_rows);
  glMatrixMode(GL_MODELVIEW);
  glLoadTransposeMatrixf(shear_rows);
  glMultTransposeMatrixf(scale_rows);
  quad();
  record_matrices(&c, "panel 0");

  conf_panel(&c, 1, 0, 2, 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMultTransposeMatrixd(frustum_rows);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -2.5f);
  glRotatef(40, 0, 1, 0);
  glMultTransposeMatrixf(shear_rows);
  glTranslatef(0, 0, 3.0f);
  quad();
  record_matrices(&c, "panel 1");

  conf_panel(&c, 0, 1, 2, 2);
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
  glEnable(GL_TEXTURE_2D);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_TEXTURE);
  glLoadTransposeMatrixd(tex_rows);
  glMatrixMode(GL_MODELVIEW);
  glLoadTransposeMatrixf(scale_rows);
  quad();
  record_matrices(&c, "panel 2");
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);

  /* In a display list: recorded and replayed as given. */
  conf_panel(&c, 1, 1, 2, 2);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMatrixMode(GL_TEXTURE);
  glMultTransposeMatrixd(tex_rows);
  glMatrixMode(GL_MODELVIEW);
  glLoadTransposeMatrixf(shear_rows);
  glMultTransposeMatrixf(scale_rows);
  glTranslatef(0, 0, 3.0f);
  glEndList();
  glMatrixMode(GL_PROJECTION);
  glLoadTransposeMatrixd(frustum_rows);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glCallList(list);
  record_matrices(&c, "list");
  quad();
  glDisable(GL_TEXTURE_2D);

  glBegin(GL_TRIANGLES);
  glLoadTransposeMatrixf(shear_rows);
  glEnd();
  conf_error(&c, "LoadTransposeMatrixf in glBegin");
  glBegin(GL_TRIANGLES);
  glMultTransposeMatrixd(frustum_rows);
  glEnd();
  conf_error(&c, "MultTransposeMatrixd in glBegin");
  GLfloat m[16];
  glGetFloatv(GL_TRANSPOSE_MODELVIEW_MATRIX, m);
  conf_error(&c, "query after glBegin errors");
  glMatrixMode(GL_TEXTURE);
  glPushMatrix();
  glMultTransposeMatrixf(scale_rows);
  record_matrices(&c, "texture pushed");
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  return conf_finish(&c);
}
