/* GLUT's solid shapes as OpenGL 1.1 client code: GL_TRIANGLES with per-vertex normals,
 * counter-clockwise from outside. Orientations follow GLUT (sphere, cone and torus around z).
 * It only calls gl* functions, so it runs on libshadelab-gl or Mesa; it keeps no state. */
#include <math.h>

#include <GL/gl.h>
#include <GL/shadelab_glut.h>

#include "teapot_mesh.h"

#define SHADELAB_PI 3.14159265358979323846

typedef struct {
  float p[3], n[3];
} ShapeVertex;

static void emit(const ShapeVertex* v) {
  glNormal3f(v->n[0], v->n[1], v->n[2]);
  glVertex3f(v->p[0], v->p[1], v->p[2]);
}

static void triangle(const ShapeVertex* a, const ShapeVertex* b, const ShapeVertex* c) {
  emit(a);
  emit(b);
  emit(c);
}

/* A quad a, b, c, d (counter-clockwise) as triangles (a, b, c), (a, c, d); `skip_first` /
 * `skip_second` leave out a triangle that collapses at a pole or apex. */
static void quad(const ShapeVertex* a, const ShapeVertex* b, const ShapeVertex* c,
                 const ShapeVertex* d, int skip_first, int skip_second) {
  if (!skip_first) triangle(a, b, c);
  if (!skip_second) triangle(a, c, d);
}

static ShapeVertex sphere_vertex(double radius, double phi, double theta) {
  ShapeVertex v;
  double x = sin(phi) * cos(theta), y = sin(phi) * sin(theta), z = cos(phi);
  v.n[0] = (float)x, v.n[1] = (float)y, v.n[2] = (float)z;
  v.p[0] = (float)(radius * x), v.p[1] = (float)(radius * y), v.p[2] = (float)(radius * z);
  return v;
}

void glutSolidSphere(GLdouble radius, GLint slices, GLint stacks) {
  if (slices < 3 || stacks < 2) return;
  glBegin(GL_TRIANGLES);
  for (GLint j = 0; j < stacks; ++j) {
    double phi0 = SHADELAB_PI * j / stacks, phi1 = SHADELAB_PI * (j + 1) / stacks;
    for (GLint i = 0; i < slices; ++i) {
      double th0 = 2.0 * SHADELAB_PI * i / slices, th1 = 2.0 * SHADELAB_PI * (i + 1) / slices;
      ShapeVertex a = sphere_vertex(radius, phi0, th0), b = sphere_vertex(radius, phi1, th0);
      ShapeVertex c = sphere_vertex(radius, phi1, th1), d = sphere_vertex(radius, phi0, th1);
      quad(&a, &b, &c, &d, j == stacks - 1, j == 0);
    }
  }
  glEnd();
}

static ShapeVertex cone_side(double base, double height, double z_frac, double theta) {
  ShapeVertex v;
  double len = sqrt(base * base + height * height);
  double r = base * (1.0 - z_frac);
  v.p[0] = (float)(r * cos(theta)), v.p[1] = (float)(r * sin(theta)), v.p[2] = (float)(height * z_frac);
  v.n[0] = (float)(cos(theta) * height / len), v.n[1] = (float)(sin(theta) * height / len);
  v.n[2] = (float)(base / len);
  return v;
}

void glutSolidCone(GLdouble base, GLdouble height, GLint slices, GLint stacks) {
  if (slices < 3 || stacks < 1 || !(base * base + height * height > 0.0)) return;
  glBegin(GL_TRIANGLES);
  ShapeVertex centre = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}};
  for (GLint i = 0; i < slices; ++i) {
    double th0 = 2.0 * SHADELAB_PI * i / slices, th1 = 2.0 * SHADELAB_PI * (i + 1) / slices;
    ShapeVertex p0 = cone_side(base, height, 0.0, th0), p1 = cone_side(base, height, 0.0, th1);
    p0.n[0] = p0.n[1] = p1.n[0] = p1.n[1] = 0.0f;
    p0.n[2] = p1.n[2] = -1.0f;
    triangle(&centre, &p1, &p0); /* the base, facing -z */
    for (GLint k = 0; k < stacks; ++k) {
      double z0 = (double)k / stacks, z1 = (double)(k + 1) / stacks;
      ShapeVertex a = cone_side(base, height, z0, th0), b = cone_side(base, height, z0, th1);
      ShapeVertex c = cone_side(base, height, z1, th1), d = cone_side(base, height, z1, th0);
      quad(&a, &b, &c, &d, 0, k == stacks - 1);
    }
  }
  glEnd();
}

static ShapeVertex torus_vertex(double inner, double outer, double psi, double phi) {
  ShapeVertex v;
  double ring = outer + cos(phi) * inner;
  v.p[0] = (float)(cos(psi) * ring), v.p[1] = (float)(sin(psi) * ring), v.p[2] = (float)(sin(phi) * inner);
  v.n[0] = (float)(cos(psi) * cos(phi)), v.n[1] = (float)(sin(psi) * cos(phi)), v.n[2] = (float)sin(phi);
  return v;
}

void glutSolidTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings) {
  if (sides < 3 || rings < 3) return;
  glBegin(GL_TRIANGLES);
  for (GLint j = 0; j < rings; ++j) {
    double psi0 = 2.0 * SHADELAB_PI * j / rings, psi1 = 2.0 * SHADELAB_PI * (j + 1) / rings;
    for (GLint i = 0; i < sides; ++i) {
      double phi0 = 2.0 * SHADELAB_PI * i / sides, phi1 = 2.0 * SHADELAB_PI * (i + 1) / sides;
      ShapeVertex a = torus_vertex(innerRadius, outerRadius, psi0, phi0);
      ShapeVertex b = torus_vertex(innerRadius, outerRadius, psi1, phi0);
      ShapeVertex c = torus_vertex(innerRadius, outerRadius, psi1, phi1);
      ShapeVertex d = torus_vertex(innerRadius, outerRadius, psi0, phi1);
      quad(&a, &b, &c, &d, 0, 0);
    }
  }
  glEnd();
}

void glutSolidCube(GLdouble size) {
  /* Per face: normal n and axes u, v with u x v = n. */
  static const float faces[6][3][3] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
  };
  static const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  float h = (float)(0.5 * size);
  glBegin(GL_TRIANGLES);
  for (int f = 0; f < 6; ++f) {
    ShapeVertex v[4];
    for (int k = 0; k < 4; ++k) {
      for (int i = 0; i < 3; ++i) {
        const float* n = faces[f][0];
        v[k].n[i] = n[i];
        v[k].p[i] = h * (n[i] + corners[k][0] * faces[f][1][i] + corners[k][1] * faces[f][2][i]);
      }
    }
    quad(&v[0], &v[1], &v[2], &v[3], 0, 0);
  }
  glEnd();
}

void glutSolidTetrahedron(void) {
  static const float v[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  /* Each face is counter-clockwise seen from outside; its normal points away from the
   * opposite vertex. */
  static const int faces[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
  const float s = 0.57735026918962576f; /* 1 / sqrt(3) */
  glBegin(GL_TRIANGLES);
  for (int f = 0; f < 4; ++f) {
    const float* opposite = v[faces[f][3]];
    glNormal3f(-opposite[0] * s, -opposite[1] * s, -opposite[2] * s);
    for (int k = 0; k < 3; ++k) glVertex3fv(v[faces[f][k]]);
  }
  glEnd();
}

void glutSolidTeapot(GLdouble size) {
  float s = (float)size;
  glBegin(GL_TRIANGLES);
  for (int t = 0; t < shadelab_glut_teapot_triangle_count; ++t) {
    for (int k = 0; k < 3; ++k) {
      const float* v = shadelab_glut_teapot_vertices[shadelab_glut_teapot_triangles[t][k]];
      glNormal3f(v[3], v[4], v[5]);
      glTexCoord2f(v[6], v[7]);
      glVertex3f(s * v[0], s * v[1], s * v[2]);
    }
  }
  glEnd();
}
