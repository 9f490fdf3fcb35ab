/* Normal handling: normals given with length 3 (unnormalized) with and without GL_NORMALIZE,
 * unit normals under a uniform glScalef(0.5) with GL_RESCALE_NORMAL (and without, where the
 * shrunken normals darken and flatten the lighting), and a non-uniform scale with GL_NORMALIZE.
 * Normals are transformed by the inverse transpose of the modelview. */
#include <math.h>

#include "conf.h"

/* A sphere whose normals are `scale` times the unit normal. */
static void scaled_sphere(float r, float scale) {
  const int slices = 36, stacks = 18;
  glBegin(GL_TRIANGLES);
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const int di[6] = {0, 0, 1, 0, 1, 1}, dj[6] = {0, 1, 1, 0, 1, 0};
      for (int k = 0; k < 6; ++k) {
        double t = 2.0 * CONF_PI * (i + di[k]) / slices, p = CONF_PI * (j + dj[k]) / stacks;
        float x = (float)(sin(p) * sin(t)), y = (float)cos(p), z = (float)(sin(p) * cos(t));
        glNormal3f(scale * x, scale * y, scale * z);
        glVertex3f(r * x, r * y, r * z);
      }
    }
  }
  glEnd();
}

static void panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 3, 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.2, 1.2, -1.2, 1.2, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 255, 256)) return 1;
  glClearColor(0.05f, 0.05f, 0.05f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat pos[] = {-0.5f, 0.7f, 1.0f, 0.0f};
  const GLfloat dif[] = {0.2f, 0.6f, 0.9f, 1}, spec[] = {0.7f, 0.7f, 0.7f, 1};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 24.0f);

  panel(&c, 0, 0); /* length-3 normals, no normalization: saturated */
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  scaled_sphere(1.0f, 3.0f);
  panel(&c, 1, 0); /* length-3 normals with GL_NORMALIZE */
  glEnable(GL_NORMALIZE);
  scaled_sphere(1.0f, 3.0f);
  glDisable(GL_NORMALIZE);
  panel(&c, 2, 0); /* length-0.4 normals, no normalization: dark */
  scaled_sphere(1.0f, 0.4f);

  panel(&c, 0, 1); /* glScalef(0.5) makes unit normals length 2: no rescaling */
  glScalef(0.5f, 0.5f, 0.5f);
  scaled_sphere(2.0f, 1.0f);
  panel(&c, 1, 1); /* the same with GL_RESCALE_NORMAL */
  glEnable(GL_RESCALE_NORMAL);
  glScalef(0.5f, 0.5f, 0.5f);
  scaled_sphere(2.0f, 1.0f);
  glDisable(GL_RESCALE_NORMAL);
  panel(&c, 2, 1); /* a non-uniform scale (an ellipsoid) with GL_NORMALIZE */
  glEnable(GL_NORMALIZE);
  glScalef(1.0f, 0.5f, 0.8f);
  scaled_sphere(1.0f, 1.0f);
  return conf_finish(&c);
}
