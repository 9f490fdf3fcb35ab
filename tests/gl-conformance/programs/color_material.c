/* glColorMaterial in each mode (GL_AMBIENT_AND_DIFFUSE, GL_DIFFUSE, GL_AMBIENT, GL_SPECULAR,
 * GL_EMISSION) with per-vertex colours, and emission as a material property. With
 * GL_COLOR_MATERIAL enabled the current colour is written into the material; after
 * glDisable(GL_COLOR_MATERIAL) the material keeps the last colour (the last panel relies on it). */
#include <math.h>

#include "conf.h"

/* Sphere with per-vertex colours (0.5 + 0.5 x, 0.5 + 0.5 y, 0.5 + 0.5 z). */
static void colour_sphere(float r) {
  const int slices = 36, stacks = 18;
  glBegin(GL_TRIANGLES);
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const int di[6] = {0, 0, 1, 0, 1, 1}, dj[6] = {0, 1, 1, 0, 1, 0};
      for (int k = 0; k < 6; ++k) {
        double t = 2.0 * CONF_PI * (i + di[k]) / slices, p = CONF_PI * (j + dj[k]) / stacks;
        float x = (float)(sin(p) * sin(t)), y = (float)cos(p), z = (float)(sin(p) * cos(t));
        glColor3f(0.5f + 0.5f * x, 0.5f + 0.5f * y, 0.5f + 0.5f * z);
        glNormal3f(x, y, z);
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
  glOrtho(-1.1, 1.1, -1.1, 1.1, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(30.0f, 1, 0, 0);
  glRotatef(-40.0f, 0, 1, 0);
}

static void reset_material(void) {
  const GLfloat amb[] = {0.2f, 0.2f, 0.2f, 1}, dif[] = {0.5f, 0.5f, 0.5f, 1};
  const GLfloat spec[] = {0.3f, 0.3f, 0.3f, 1}, none[] = {0, 0, 0, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, none);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
}

static void colour_material_panel(const ConfContext* c, int col, int row, GLenum mode) {
  panel(c, col, row);
  reset_material();
  glColorMaterial(GL_FRONT, mode);
  glEnable(GL_COLOR_MATERIAL);
  colour_sphere(1.0f);
  glDisable(GL_COLOR_MATERIAL);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 255, 256)) return 1;
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat pos[] = {-0.4f, 0.6f, 1.0f, 0.0f}, global[] = {0.4f, 0.4f, 0.4f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, global);

  colour_material_panel(&c, 0, 0, GL_AMBIENT_AND_DIFFUSE);
  colour_material_panel(&c, 1, 0, GL_DIFFUSE);
  colour_material_panel(&c, 2, 0, GL_AMBIENT);
  colour_material_panel(&c, 0, 1, GL_SPECULAR);
  colour_material_panel(&c, 1, 1, GL_EMISSION);

  /* Emission without colour material, then a second sphere whose diffuse and ambient colours
   * are what glColor set while GL_COLOR_MATERIAL was still enabled. */
  panel(&c, 2, 1);
  reset_material();
  const GLfloat glow[] = {0.5f, 0.4f, 0.1f, 1}, none[] = {0, 0, 0, 1};
  glMaterialfv(GL_FRONT, GL_EMISSION, glow);
  glPushMatrix();
  glTranslatef(-0.45f, 0.45f, 0.0f);
  conf_sphere(0.5f, 24, 12);
  glPopMatrix();
  glMaterialfv(GL_FRONT, GL_EMISSION, none);
  glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glColor3f(0.2f, 0.9f, 0.3f);
  glDisable(GL_COLOR_MATERIAL);
  glColor3f(1.0f, 0.0f, 1.0f); /* ignored by lighting now */
  glTranslatef(0.45f, -0.45f, 0.0f);
  conf_sphere(0.5f, 24, 12);
  return conf_finish(&c);
}
