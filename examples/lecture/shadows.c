/* Lecture 14, slides "directional light source-с үүссэн сүүдэр" (ShadowB) and "point light
 * source үүсэх сүүдэр" (ShadowA) (SPEC figure 16 and section 6): the teapot's shadow on the
 * plane z + 5 = 0, drawn with lighting off in black through the lecture's projection matrices.
 * Left, ShadowB: directional light, (dx, dy, dz) = (.5, .5, 1), which is also the light's GL
 * position (.5, .5, 1, 0): the vector points from the plane toward the light. (The projection
 * p + alpha (dx, dy, dz) is the same for -(dx, dy, dz), but the matrix's w, M[15] = a dx + b dy +
 * c dz, would then be negative, and OpenGL clips away every vertex with a negative clip w: the
 * shadow would vanish.) Right, ShadowA: point light at (3, 2, 6); the shadow
 * is larger than the teapot because the light is near.
 * Ours: a lit wall on the plane (20 x 14, 40 x 28 quads), the shiny red teapot at the origin,
 * camera perspective 45 degrees from 13 units, turned 20 degrees to the left so the gap between
 * the teapot and its shadow shows. The shadow lies in the wall's plane; the lecture draws it
 * as is, we add glPolygonOffset(-1, -1) so that it does not fight with the wall for depth. */
#include <GL/shadelab_glut.h>

#include "common/lecture.h"

void drawTeapot() { glutSolidTeapot(1.0); }

/* --- the lecture's code --------------------------------------------------------------- */
// Set up the matrix M such that it projects a vertex on the plane
//      ax + by + cz + d = 0.
//      The direction of light is (dx, dy, dz).
void directionalLightShadow(double dx, double dy, double dz, double a, double b, double c,
                            double d, GLfloat M[16]) {
  M[0] = b * dy + c * dz; M[4] = -b * dx;          M[8] = -c * dx;           M[12] = -d * dx;
  M[1] = -a * dy;         M[5] = a * dx + c * dz;  M[9] = -c * dy;           M[13] = -d * dy;
  M[2] = -a * dz;         M[6] = -b * dz;          M[10] = a * dx + b * dy;  M[14] = -d * dz;
  M[3] = 0;               M[7] = 0;                M[11] = 0;                M[15] = a * dx + b * dy + c * dz;
}

// Set up the matrix M such that it projects a vertex on the plane
//      ax + by + cz + d = 0.
//      The light source is at (lx, ly, xz).
void pointSourceShadow(double lx, double ly, double lz, double a, double b, double c, double d,
                       GLfloat M[16]) {
  double new_d = d + (a * lx + b * ly + c * lz);
  M[0] = 1;          M[4] = 0;          M[8] = 0;           M[12] = 0;
  M[1] = 0;          M[5] = 1;          M[9] = 0;           M[13] = 0;
  M[2] = 0;          M[6] = 0;          M[10] = 1;          M[14] = 0;
  M[3] = -a / new_d; M[7] = -b / new_d; M[11] = -c / new_d; M[15] = 0;
}
/* --- end of the lecture's code ------------------------------------------------------- */

static void wall_on_plane(void) { /* z = -5, facing +z */
  GLfloat grey[] = {.75, .75, .7, 1.}, none[] = {0., 0., 0., 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, grey);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, grey);
  glMaterialfv(GL_FRONT, GL_SPECULAR, none);
  glNormal3f(0., 0., 1.);
  glBegin(GL_QUADS);
  for (int j = 0; j < 28; ++j)
    for (int i = 0; i < 40; ++i) {
      float x = -10. + .5 * i, y = -7. + .5 * j;
      glVertex3f(x, y, -5.), glVertex3f(x + .5, y, -5.);
      glVertex3f(x + .5, y + .5, -5.), glVertex3f(x, y + .5, -5.);
    }
  glEnd();
}

static void lit_teapot(void) {
  GLfloat diffuse[] = {.41, .135, .067, 1.}, specular[] = {1., 1., 1., 1.};
  glMaterialfv(GL_FRONT, GL_AMBIENT, diffuse);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 125.);
  drawTeapot();
}

static void camera(const LectureImage* img, int index, const GLfloat* light_position) {
  double aspect = lecture_panel(img, index, 2, 0, 1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lecture_perspective(45.0, aspect, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0., 0., -13.);
  glRotatef(20., 0., 1., 0.);
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
}

int main(int argc, char** argv) {
  LectureImage img;
  if (!lecture_begin(&img, argc, argv, "lecture_shadows.png", 800, 400)) return 1;
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  GLfloat M[16];

  /* ShadowB: directional light. */
  double dx = .5, dy = .5, dz = 1.;
  GLfloat toward_light[] = {.5, .5, 1., 0.};
  camera(&img, 0, toward_light);
  glEnable(GL_LIGHTING);
  wall_on_plane();
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1., -1.);
  /* --- the lecture's code ------------------------------------------------------------- */
  glDisable(GL_LIGHTING);
  glColor4f(0., 0., 0., 1.);
  glPushMatrix();
  directionalLightShadow(dx, dy, dz, 0, 0, 1, 5, M);
  glMultMatrixf(M);
  drawTeapot();  // Draw the teapot
  glPopMatrix();
  /* --- end of the lecture's code ------------------------------------------------------ */
  glDisable(GL_POLYGON_OFFSET_FILL);
  glEnable(GL_LIGHTING);
  lit_teapot();

  /* ShadowA: point light. */
  double light_x = 3., light_y = 2., light_z = 6.;
  GLfloat light_position[] = {3., 2., 6., 1.};
  camera(&img, 1, light_position);
  glEnable(GL_LIGHTING);
  wall_on_plane();
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1., -1.);
  /* --- the lecture's code ------------------------------------------------------------- */
  glDisable(GL_LIGHTING);
  glColor4f(0., 0., 0., 1.);

  glPushMatrix();
  glTranslatef(light_x, light_y, light_z);
  pointSourceShadow(light_x, light_y, light_z, 0, 0, 1, 5, M);
  glMultMatrixf(M);
  glTranslatef(-light_x, -light_y, -light_z);
  drawTeapot();  // Draw the teapot
  glPopMatrix();
  /* --- end of the lecture's code ------------------------------------------------------ */
  glDisable(GL_POLYGON_OFFSET_FILL);
  glEnable(GL_LIGHTING);
  lit_teapot();
  return lecture_end(&img);
}
