/* GLUT's teapot as OpenGL 1.1 client code, glutSolidTeapot and glutWireTeapot, with the
 * tessellation of freeglut 3: the Utah teapot's 32 Bezier patches sampled on grids of 8 x 8
 * (solid) or 10 x 10 (wire), lid toward +y, spout toward +x, its height centred on the origin,
 * scaled by size / 2 from Newell's data. The solid is GL_TRIANGLES wound clockwise seen from
 * outside, as GLUT's teapot always was (outward normals: glFrontFace(GL_CW) for culling); the
 * wire teapot is GL_LINE_STRIPs along each patch's grid lines. The grids come from the core's
 * make_teapot through teapot_gen.cpp. It only calls gl* functions and keeps no state. */
#include <GL/gl.h>
#include <GL/shadelab_glut.h>

#include "teapot_mesh.h"

/* Sample (r, c) of patch p on grids of n x n, scaled by `size`. */
static void sample(const float (*grid)[8], int n, int p, int r, int c, float size, int textured) {
  const float* v = grid[(p * n + r) * n + c];
  glNormal3f(v[3], v[4], v[5]);
  if (textured) glTexCoord2f(v[6], v[7]);
  glVertex3f(size * v[0], size * v[1], size * v[2]);
}

void glutSolidTeapot(GLdouble size) {
  const int n = shadelab_glut_teapot_solid_samples;
  const float s = (float)size;
  glBegin(GL_TRIANGLES);
  for (int p = 0; p < shadelab_glut_teapot_patch_count; ++p) {
    for (int r = 0; r + 1 < n; ++r) {
      for (int c = 0; c + 1 < n; ++c) {
        sample(shadelab_glut_teapot_solid, n, p, r, c, s, 1);
        sample(shadelab_glut_teapot_solid, n, p, r + 1, c, s, 1);
        sample(shadelab_glut_teapot_solid, n, p, r + 1, c + 1, s, 1);
        sample(shadelab_glut_teapot_solid, n, p, r, c, s, 1);
        sample(shadelab_glut_teapot_solid, n, p, r + 1, c + 1, s, 1);
        sample(shadelab_glut_teapot_solid, n, p, r, c + 1, s, 1);
      }
    }
  }
  glEnd();
}

void glutWireTeapot(GLdouble size) {
  const int n = shadelab_glut_teapot_wire_samples, patches = shadelab_glut_teapot_patch_count;
  const float s = (float)size;
  for (int p = 0; p < patches; ++p) { /* every patch's lines along u, then every patch's along v */
    for (int c = 0; c < n; ++c) {
      glBegin(GL_LINE_STRIP);
      for (int r = 0; r < n; ++r) sample(shadelab_glut_teapot_wire, n, p, r, c, s, 0);
      glEnd();
    }
  }
  for (int p = 0; p < patches; ++p) {
    for (int r = 0; r < n; ++r) {
      glBegin(GL_LINE_STRIP);
      for (int c = 0; c < n; ++c) sample(shadelab_glut_teapot_wire, n, p, r, c, s, 0);
      glEnd();
    }
  }
}
