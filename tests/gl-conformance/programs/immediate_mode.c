/* glBegin/glEnd primitives whose vertices change course half-way: a lit sphere whose diffuse
 * material changes after half of its vertices (the earlier ones keep the material they had),
 * a lit sphere with some vertices given as glVertex4f with w = 2 (the same points), an unlit
 * wall with per-vertex colours under a rotation and a non-uniform scale, and a textured lit
 * sphere under a texture matrix that scales and turns the coordinates, with GL_NORMALIZE
 * under a non-uniform scale. Each panel has its own modelview, fixed at glBegin; shadelab
 * defers lighting to the pipeline until a vertex or a material change stops it
 * (gl/src/draw.cpp, settle_lighting). */
#include <math.h>
#include <stddef.h>

#include "conf.h"

static void panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 2, 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.2, 1.2, -1.2, 1.2, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* A point of the unit sphere: normal, texture coordinates and position (w = 2 when `homogeneous`). */
static void sphere_point(int i, int j, int slices, int stacks, int homogeneous) {
  double t = 2.0 * CONF_PI * i / slices, p = CONF_PI * j / stacks;
  float x = (float)(sin(p) * sin(t)), y = (float)cos(p), z = (float)(sin(p) * cos(t));
  glNormal3f(x, y, z);
  glTexCoord2f((float)i / slices, (float)j / stacks);
  if (homogeneous) glVertex4f(2.0f * x, 2.0f * y, 2.0f * z, 2.0f);
  else glVertex3f(x, y, z);
}

/* A sphere; from triangle `change_at` on, `change` runs before each vertex (NULL: nothing). */
static void sphere(int change_at, void (*change)(int)) {
  const int slices = 32, stacks = 16;
  int triangle = 0;
  glBegin(GL_TRIANGLES);
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const int di[6] = {0, 0, 1, 0, 1, 1}, dj[6] = {0, 1, 1, 0, 1, 0};
      for (int k = 0; k < 6; ++k) {
        if (k % 3 == 0) ++triangle;
        int late = triangle >= change_at;
        if (late && change) change(k);
        sphere_point(i + di[k], j + dj[k], slices, stacks, late && !change);
      }
    }
  }
  glEnd();
}

static void warmer_material(int k) {
  (void)k;
  const GLfloat warm[] = {0.9f, 0.4f, 0.2f, 1};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, warm);
}

static GLuint make_texture(void) {
  static unsigned char texels[16 * 16 * 4];
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      unsigned char* t = &texels[(y * 16 + x) * 4];
      int on = ((x / 2) + (y / 2)) % 2;
      t[0] = (unsigned char)(on ? 250 : 40);
      t[1] = (unsigned char)(on ? 230 : 120);
      t[2] = (unsigned char)(on ? 90 : 220);
      t[3] = 255;
    }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  return tex;
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0.05f, 0.05f, 0.08f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat pos[] = {-0.6f, 0.8f, 1.0f, 0.0f};
  const GLfloat cool[] = {0.3f, 0.5f, 0.9f, 1}, spec[] = {0.6f, 0.6f, 0.6f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, cool);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);

  panel(&c, 0, 0); /* the material changes half-way through the sphere */
  glRotatef(25.0f, 1, 0, 0);
  sphere(32 * 16, warmer_material);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, cool);

  panel(&c, 1, 0); /* the lower half's vertices given with w = 2 */
  glRotatef(-30.0f, 0, 1, 0);
  sphere(32 * 16, NULL);

  panel(&c, 0, 1); /* unlit, per-vertex colours, rotated and squeezed */
  glDisable(GL_LIGHTING);
  glRotatef(30.0f, 0, 0, 1);
  glScalef(1.2f, 0.6f, 1.0f);
  glBegin(GL_QUADS);
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      float x0 = -0.9f + 0.3f * i, y0 = -0.9f + 0.3f * j;
      const float xs[4] = {x0, x0 + 0.3f, x0 + 0.3f, x0}, ys[4] = {y0, y0, y0 + 0.3f, y0 + 0.3f};
      for (int k = 0; k < 4; ++k) {
        glColor3f(0.5f + 0.5f * xs[k], 0.5f + 0.5f * ys[k], (float)((i + j + k) % 3) / 2.0f);
        glVertex3f(xs[k], ys[k], 0.0f);
      }
    }
  glEnd();
  glEnable(GL_LIGHTING);

  panel(&c, 1, 1); /* textured under a texture matrix, normals renormalized */
  GLuint tex = make_texture();
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_NORMALIZE);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glRotatef(15.0f, 0, 0, 1);
  glScalef(2.0f, 3.0f, 1.0f);
  glMatrixMode(GL_MODELVIEW);
  glScalef(0.8f, 1.1f, 0.9f);
  sphere(1 << 30, NULL);
  glDisable(GL_NORMALIZE);
  glDisable(GL_TEXTURE_2D);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glDeleteTextures(1, &tex);
  return conf_finish(&c);
}
