/* GLUT's round shapes as OpenGL 1.1 client code: glutSolid/Wire Sphere, Cone and Torus, with
 * the geometry of freeglut 3 (the vertices, normals, primitives, winding and drawing order that
 * Debian's libglut gives), plus glutSolidCube. Solids are GL_TRIANGLE_STRIPs, counter-clockwise
 * from outside; wire shapes are the lines between the same vertices, with the same normals.
 * It only calls gl* functions, so it runs on libshadelab-gl or Mesa; it keeps no state.
 * The polyhedra are in polyhedra.c, the teapot in teapot.c. */
#include <math.h>

#include <GL/gl.h>
#include <GL/shadelab_glut.h>

#define SHADELAB_PI 3.14159265358979323846

typedef struct {
  float p[3], n[3];
} ShapeVertex;

static void emit(const ShapeVertex* v) {
  glNormal3f(v->n[0], v->n[1], v->n[2]);
  glVertex3f(v->p[0], v->p[1], v->p[2]);
}

/* cos and sin of the angle 2 pi k / n for 0 <= k <= |n|; n < 0 turns clockwise (seen from the
 * positive axis). k = 0 and k = |n| give exactly (1, 0), so that a closed ring's seam vertices
 * coincide bit for bit. */
static void ring_angle(int k, int n, double* c, double* s) {
  if (k == 0 || k == (n < 0 ? -n : n)) {
    *c = 1.0, *s = 0.0;
    return;
  }
  double a = 2.0 * SHADELAB_PI * k / n;
  *c = cos(a), *s = sin(a);
}

/* ---- Sphere -------------------------------------------------------------------------------- */

/* Vertex `j` of ring `i` of a sphere: ring 0 is the pole at +z, ring `stacks` the pole at -z,
 * rings equally spaced in the polar angle; slices turn clockwise seen from +z, slice 0 on +x.
 * The normal is the unit direction. */
static ShapeVertex sphere_vertex(double radius, GLint slices, GLint stacks, GLint i, GLint j) {
  double cos_theta, sin_theta, cos_phi = 1.0, sin_phi = 0.0;
  ring_angle(j, -slices, &cos_theta, &sin_theta);
  if (i == stacks) {
    cos_phi = -1.0;
  } else if (i > 0) {
    cos_phi = cos(SHADELAB_PI * i / stacks), sin_phi = sin(SHADELAB_PI * i / stacks);
  }
  const double d[3] = {cos_theta * sin_phi, sin_theta * sin_phi, cos_phi};
  ShapeVertex v;
  for (int k = 0; k < 3; ++k) v.n[k] = (float)d[k], v.p[k] = (float)(radius * d[k]);
  return v;
}

void glutSolidSphere(GLdouble radius, GLint slices, GLint stacks) {
  if (slices < 1 || stacks < 2) return;
  /* One strip per band between rings i and i + 1, alternating the lower and the upper ring and
   * closing on slice 0; the bands at the poles repeat the pole vertex. */
  for (GLint i = 0; i < stacks; ++i) {
    glBegin(GL_TRIANGLE_STRIP);
    for (GLint j = 0; j <= slices; ++j) {
      const GLint jj = j == slices ? 0 : j;
      ShapeVertex lower = sphere_vertex(radius, slices, stacks, i + 1, jj);
      ShapeVertex upper = sphere_vertex(radius, slices, stacks, i, jj);
      emit(&lower);
      emit(&upper);
    }
    glEnd();
  }
}

void glutWireSphere(GLdouble radius, GLint slices, GLint stacks) {
  if (slices < 1 || stacks < 2) return;
  for (GLint j = 0; j < slices; ++j) { /* the meridians, pole to pole */
    glBegin(GL_LINE_STRIP);
    for (GLint i = 0; i <= stacks; ++i) {
      ShapeVertex v = sphere_vertex(radius, slices, stacks, i, j);
      emit(&v);
    }
    glEnd();
  }
  for (GLint i = 1; i < stacks; ++i) { /* then the parallels, top down */
    glBegin(GL_LINE_LOOP);
    for (GLint j = 0; j < slices; ++j) {
      ShapeVertex v = sphere_vertex(radius, slices, stacks, i, j);
      emit(&v);
    }
    glEnd();
  }
}

/* ---- Cone ---------------------------------------------------------------------------------- */

/* Vertex `j` of ring `i` of a cone's side: ring 0 is the base's rim at z = 0, ring `stacks` the
 * apex at z = height (a ring of coincident vertices, one normal per slice); slices turn clockwise
 * seen from +z. Side normals lean up by the cone's half angle. */
static ShapeVertex cone_side(double base, double height, GLint slices, GLint stacks, GLint i,
                             GLint j) {
  double c, s;
  ring_angle(j, -slices, &c, &s);
  const double length = sqrt(base * base + height * height);
  const double r = base * (stacks - i) / stacks;
  ShapeVertex v = {
      {(float)(c * r), (float)(s * r), (float)(height * i / stacks)},
      {(float)(c * height / length), (float)(s * height / length), (float)(base / length)}};
  return v;
}

/* Vertex `j` of the base's rim, facing -z. */
static ShapeVertex cone_rim(double base, GLint slices, GLint j) {
  double c, s;
  ring_angle(j, -slices, &c, &s);
  ShapeVertex v = {{(float)(c * base), (float)(s * base), 0.0f}, {0.0f, 0.0f, -1.0f}};
  return v;
}

void glutSolidCone(GLdouble base, GLdouble height, GLint slices, GLint stacks) {
  if (slices < 1 || stacks < 1 || !(base * base + height * height > 0.0)) return;
  const ShapeVertex centre = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}};
  glBegin(GL_TRIANGLE_STRIP); /* the base: the centre and the rim in turn */
  for (GLint j = 0; j <= slices; ++j) {
    ShapeVertex rim = cone_rim(base, slices, j == slices ? 0 : j);
    emit(&centre);
    emit(&rim);
  }
  glEnd();
  for (GLint i = 0; i < stacks; ++i) { /* the side, one strip per stack, bottom up */
    glBegin(GL_TRIANGLE_STRIP);
    for (GLint j = 0; j <= slices; ++j) {
      const GLint jj = j == slices ? 0 : j;
      ShapeVertex below = cone_side(base, height, slices, stacks, i, jj);
      ShapeVertex above = cone_side(base, height, slices, stacks, i + 1, jj);
      emit(&below);
      emit(&above);
    }
    glEnd();
  }
}

void glutWireCone(GLdouble base, GLdouble height, GLint slices, GLint stacks) {
  if (slices < 1 || stacks < 1 || !(base * base + height * height > 0.0)) return;
  glBegin(GL_LINES); /* one line per slice from the rim to the apex */
  for (GLint j = 0; j < slices; ++j) {
    ShapeVertex rim = cone_side(base, height, slices, stacks, 0, j);
    ShapeVertex apex = cone_side(base, height, slices, stacks, stacks, j);
    emit(&rim);
    emit(&apex);
  }
  glEnd();
  for (GLint i = 0; i < stacks; ++i) { /* a circle per stack, the rim first; none at the apex */
    glBegin(GL_LINE_LOOP);
    for (GLint j = 0; j < slices; ++j) {
      ShapeVertex v = cone_side(base, height, slices, stacks, i, j);
      emit(&v);
    }
    glEnd();
  }
}

/* ---- Torus --------------------------------------------------------------------------------- */

/* Vertex `i` of ring `j` of a torus around the z axis: rings turn counter-clockwise around z
 * (ring 0 on +x), and each ring's vertices clockwise around the tube (vertex 0 outermost).
 * The normal points away from the tube's centre line. */
static ShapeVertex torus_vertex(double inner, double outer, GLint sides, GLint rings, GLint i,
                                GLint j) {
  double cos_psi, sin_psi, cos_phi, sin_phi;
  ring_angle(j, rings, &cos_psi, &sin_psi);
  ring_angle(i, -sides, &cos_phi, &sin_phi);
  const double r = outer + cos_phi * inner;
  ShapeVertex v = {{(float)(cos_psi * r), (float)(sin_psi * r), (float)(sin_phi * inner)},
                   {(float)(cos_psi * cos_phi), (float)(sin_psi * cos_phi), (float)sin_phi}};
  return v;
}

void glutSolidTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings) {
  if (sides < 2 || rings < 2) return;
  /* One strip per side: around the axis between tube vertex i and the next. */
  for (GLint i = 0; i < sides; ++i) {
    const GLint next = i + 1 == sides ? 0 : i + 1;
    glBegin(GL_TRIANGLE_STRIP);
    for (GLint j = 0; j <= rings; ++j) {
      const GLint jj = j == rings ? 0 : j;
      ShapeVertex a = torus_vertex(innerRadius, outerRadius, sides, rings, i, jj);
      ShapeVertex b = torus_vertex(innerRadius, outerRadius, sides, rings, next, jj);
      emit(&a);
      emit(&b);
    }
    glEnd();
  }
}

void glutWireTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings) {
  if (sides < 2 || rings < 2) return;
  for (GLint j = 0; j < rings; ++j) { /* the circles around the tube */
    glBegin(GL_LINE_LOOP);
    for (GLint i = 0; i < sides; ++i) {
      ShapeVertex v = torus_vertex(innerRadius, outerRadius, sides, rings, i, j);
      emit(&v);
    }
    glEnd();
  }
  for (GLint i = 0; i < sides; ++i) { /* then the circles around the axis */
    glBegin(GL_LINE_LOOP);
    for (GLint j = 0; j < rings; ++j) {
      ShapeVertex v = torus_vertex(innerRadius, outerRadius, sides, rings, i, j);
      emit(&v);
    }
    glEnd();
  }
}

/* ---- Cube ---------------------------------------------------------------------------------- */

static void triangle(const ShapeVertex* a, const ShapeVertex* b, const ShapeVertex* c) {
  emit(a);
  emit(b);
  emit(c);
}

void glutSolidCube(GLdouble size) {
  /* Per face: normal n and axes u, v with u x v = n. */
  static const float faces[6][3][3] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
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
    /* The quad v0 v1 v2 v3 (counter-clockwise) as triangles (v0, v1, v2), (v0, v2, v3). */
    triangle(&v[0], &v[1], &v[2]);
    triangle(&v[0], &v[2], &v[3]);
  }
  glEnd();
}
