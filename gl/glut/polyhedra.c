/* GLUT's polyhedra as OpenGL 1.1 client code: glutWire/Solid Tetrahedron, Octahedron,
 * Dodecahedron, Icosahedron and RhombicDodecahedron, and glutWireCube, with the geometry of
 * freeglut 3 (Debian's libglut): the same vertices, faces, face normals, winding and order.
 * A solid is GL_TRIANGLES, each face counter-clockwise from outside with its face's normal at
 * every corner (a quad split as corners (0 1 2) (0 2 3), a pentagon as (0 1 2) (0 2 4) (4 2 3));
 * a wire shape is one GL_LINE_LOOP per face, in the same order and with the same normals, so
 * that every edge is drawn twice, once each way. It only calls gl* functions and keeps no state.
 * glutSolidCube is in shapes.c. */
#include <math.h>

#include <GL/gl.h>
#include <GL/shadelab_glut.h>

#define SHADELAB_PI 3.14159265358979323846

enum { kMaxVertices = 20, kMaxFaces = 20, kMaxCorners = 5 };

typedef struct {
  int face_count;
  int corners; /* per face: 3, 4 or 5 */
  float vertices[kMaxVertices][3];
  unsigned char faces[kMaxFaces][kMaxCorners]; /* counter-clockwise seen from outside */
  float normals[kMaxFaces][3];                 /* one per face */
} Polyhedron;

static void set_vertex(Polyhedron* p, int i, double x, double y, double z) {
  p->vertices[i][0] = (float)x, p->vertices[i][1] = (float)y, p->vertices[i][2] = (float)z;
}

static void set_face(Polyhedron* p, int f, const int* corners) {
  for (int k = 0; k < p->corners; ++k) p->faces[f][k] = (unsigned char)corners[k];
}

/* Each face's normal from its first three corners: cross(v1 - v0, v2 - v0), made unit length
 * when `unit` (else kept as it is, as freeglut's icosahedron has it). */
static void set_normals(Polyhedron* p, int unit) {
  for (int f = 0; f < p->face_count; ++f) {
    const float *a = p->vertices[p->faces[f][0]], *b = p->vertices[p->faces[f][1]],
                *c = p->vertices[p->faces[f][2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0]};
    const double length = unit ? sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) : 1.0;
    for (int k = 0; k < 3; ++k) p->normals[f][k] = (float)(n[k] / length);
  }
}

static void corner(const Polyhedron* p, int f, int k, float scale) {
  const float* v = p->vertices[p->faces[f][k]];
  glNormal3fv(p->normals[f]);
  glVertex3f(scale * v[0], scale * v[1], scale * v[2]);
}

/* Draws `p` with its vertices multiplied by `scale`, as faces or as their outlines. */
static void draw(const Polyhedron* p, float scale, int wire) {
  static const int kTriangles[3][9] = {{0, 1, 2}, {0, 1, 2, 0, 2, 3}, {0, 1, 2, 0, 2, 4, 4, 2, 3}};
  if (wire) {
    for (int f = 0; f < p->face_count; ++f) {
      glBegin(GL_LINE_LOOP);
      for (int k = 0; k < p->corners; ++k) corner(p, f, k, scale);
      glEnd();
    }
    return;
  }
  const int* split = kTriangles[p->corners - 3];
  glBegin(GL_TRIANGLES);
  for (int f = 0; f < p->face_count; ++f) {
    for (int k = 0; k < 3 * (p->corners - 2); ++k) corner(p, f, split[k], scale);
  }
  glEnd();
}

/* ---- Cube: the corners (+-1/2, +-1/2, +-1/2) ------------------------------------------------ */

/* Corner i has the signs of bits 2, 1, 0 (x, y, z; a set bit is minus): 0 is (+ + +). */
static void cube(Polyhedron* p) {
  static const int kFaces[6][4] = {
      {0, 4, 6, 2}, /* +z */
      {0, 2, 3, 1}, /* +x */
      {0, 1, 5, 4}, /* +y */
      {4, 5, 7, 6}, /* -x */
      {7, 3, 2, 6}, /* -y */
      {3, 7, 5, 1}, /* -z */
  };
  p->face_count = 6, p->corners = 4;
  for (int i = 0; i < 8; ++i)
    set_vertex(p, i, i & 4 ? -0.5 : 0.5, i & 2 ? -0.5 : 0.5, i & 1 ? -0.5 : 0.5);
  for (int f = 0; f < 6; ++f) set_face(p, f, kFaces[f]);
  set_normals(p, 1);
}

void glutWireCube(GLdouble size) {
  Polyhedron p;
  cube(&p);
  draw(&p, (float)size, 1);
}

/* ---- Tetrahedron: circumradius 1, a vertex on +x ------------------------------------------ */

/* Vertices (1, 0, 0), (-1/3, 2 sqrt(2)/3, 0), (-1/3, -sqrt(2)/3, +-sqrt(6)/3). Face i is the one
 * opposite vertex i (its normal is minus that vertex), its corners the other three in increasing
 * order, the last two swapped where that order would face inward. */
static void tetrahedron(Polyhedron* p) {
  const double third = 1.0 / 3.0, s2 = sqrt(2.0) / 3.0, s6 = sqrt(6.0) / 3.0;
  p->face_count = 4, p->corners = 3;
  set_vertex(p, 0, 1.0, 0.0, 0.0);
  set_vertex(p, 1, -third, 2.0 * s2, 0.0);
  set_vertex(p, 2, -third, -s2, s6);
  set_vertex(p, 3, -third, -s2, -s6);
  for (int f = 0; f < 4; ++f) {
    int c[3], n = 0;
    for (int i = 0; i < 4; ++i) {
      if (i != f) c[n++] = i;
    }
    set_face(p, f, c);
  }
  set_normals(p, 1);
  for (int f = 0; f < 4; ++f) {
    const float* opposite = p->vertices[f];
    const float* n = p->normals[f];
    if (n[0] * opposite[0] + n[1] * opposite[1] + n[2] * opposite[2] > 0.0f) {
      const int c[3] = {p->faces[f][0], p->faces[f][2], p->faces[f][1]};
      set_face(p, f, c);
    }
  }
  set_normals(p, 1);
}

void glutSolidTetrahedron(void) {
  Polyhedron p;
  tetrahedron(&p);
  draw(&p, 1.0f, 0);
}

void glutWireTetrahedron(void) {
  Polyhedron p;
  tetrahedron(&p);
  draw(&p, 1.0f, 1);
}

/* ---- Octahedron: the unit points on the axes ---------------------------------------------- */

/* Vertices +x, +y, +z, -x, -y, -z (0 to 5). One face per octant, the octants in the order of
 * their signs (x, y, z) from (+ + +) to (- - -); each face starts at its x vertex and runs
 * counter-clockwise from outside: x y z where the signs' product is positive, x z y where not. */
static void octahedron(Polyhedron* p) {
  p->face_count = 8, p->corners = 3;
  for (int i = 0; i < 6; ++i) {
    const double s = i < 3 ? 1.0 : -1.0;
    set_vertex(p, i, i % 3 == 0 ? s : 0.0, i % 3 == 1 ? s : 0.0, i % 3 == 2 ? s : 0.0);
  }
  for (int f = 0; f < 8; ++f) {
    const int x = f & 4 ? 3 : 0, y = f & 2 ? 4 : 1, z = f & 1 ? 5 : 2;
    const int negatives = !!(f & 4) + !!(f & 2) + !!(f & 1);
    const int even[3] = {x, y, z}, odd[3] = {x, z, y};
    set_face(p, f, negatives % 2 == 0 ? even : odd);
  }
  set_normals(p, 1);
}

void glutSolidOctahedron(void) {
  Polyhedron p;
  octahedron(&p);
  draw(&p, 1.0f, 0);
}

void glutWireOctahedron(void) {
  Polyhedron p;
  octahedron(&p);
  draw(&p, 1.0f, 1);
}

/* ---- Dodecahedron: circumradius sqrt(3) ---------------------------------------------------- */

#define PHI 1.6180339887498948482     /* the golden ratio, (1 + sqrt(5)) / 2 */
#define INV_PHI 0.6180339887498948482 /* 1 / PHI */

/* Vertices 0-7: the cube's corners (+-1, +-1, +-1), signs as the cube's above; 8-11:
 * (0, +-PHI, +-1/PHI); 12-15: (+-1/PHI, 0, +-PHI); 16-19: (+-PHI, +-1/PHI, 0), each group's
 * signs in the order (+ +), (+ -), (- +), (- -). The faces come in freeglut's order: the four
 * whose normals lie in the yz plane, then xz, then xy. */
static void dodecahedron(Polyhedron* p) {
  static const int kFaces[12][5] = {
      {8, 4, 14, 12, 0},  {9, 1, 13, 15, 5},  {10, 2, 12, 14, 6}, {11, 7, 15, 13, 3},
      {12, 2, 17, 16, 0}, {14, 4, 18, 19, 6}, {13, 1, 16, 17, 3}, {15, 7, 19, 18, 5},
      {16, 1, 9, 8, 0},   {17, 2, 10, 11, 3}, {18, 4, 8, 9, 5},   {19, 7, 11, 10, 6},
  };
  p->face_count = 12, p->corners = 5;
  for (int i = 0; i < 8; ++i)
    set_vertex(p, i, i & 4 ? -1.0 : 1.0, i & 2 ? -1.0 : 1.0, i & 1 ? -1.0 : 1.0);
  for (int i = 0; i < 4; ++i) {
    const double a = i & 2 ? -PHI : PHI, b = i & 1 ? -INV_PHI : INV_PHI;
    const double c = i & 2 ? -INV_PHI : INV_PHI, d = i & 1 ? -PHI : PHI;
    set_vertex(p, 8 + i, 0.0, a, b);
    set_vertex(p, 12 + i, c, 0.0, d);
    set_vertex(p, 16 + i, a, b, 0.0);
  }
  for (int f = 0; f < 12; ++f) set_face(p, f, kFaces[f]);
  set_normals(p, 1);
}

void glutSolidDodecahedron(void) {
  Polyhedron p;
  dodecahedron(&p);
  draw(&p, 1.0f, 0);
}

void glutWireDodecahedron(void) {
  Polyhedron p;
  dodecahedron(&p);
  draw(&p, 1.0f, 1);
}

/* ---- Icosahedron: circumradius 1, vertices on +x and -x ------------------------------------ */

/* Vertex 0 is +x and 11 is -x; 1-5 (upper ring u0-u4) lie at x = 1/sqrt(5) and 6-10 (lower ring
 * l0-l4) at x = -1/sqrt(5), at radius 2/sqrt(5) around the x axis: u_k at the angle 72 k degrees
 * from +y towards +z, l_k half a step further, between u_k and u_k+1. Faces: the five around
 * +x, the five with an upper edge, the five with a lower edge, the five around -x. The normals
 * are the cross products of the faces' first two edges, not made unit length (about 0.957 long),
 * as freeglut's are: lighting without GL_NORMALIZE sees them the same. */
static void icosahedron(Polyhedron* p) {
  const double x = 1.0 / sqrt(5.0), r = 2.0 / sqrt(5.0), step = 2.0 * SHADELAB_PI / 5.0;
  p->face_count = 20, p->corners = 3;
  set_vertex(p, 0, 1.0, 0.0, 0.0);
  for (int k = 0; k < 5; ++k) {
    set_vertex(p, 1 + k, x, r * cos(step * k), r * sin(step * k));
    set_vertex(p, 6 + k, -x, r * cos(step * (k + 0.5)), r * sin(step * (k + 0.5)));
  }
  set_vertex(p, 11, -1.0, 0.0, 0.0);
#define U(k) (1 + ((k) + 5) % 5)
#define L(k) (6 + ((k) + 5) % 5)
  for (int k = 0; k < 5; ++k) {
    const int top[3] = {0, U(k), U(k + 1)}, upper[3] = {U(k), L(k), U(k + 1)};
    const int lower[3] = {U(k), L(k - 1), L(k)}, bottom[3] = {11, L(k - 1), L(k - 2)};
    set_face(p, k, top);
    set_face(p, 5 + k, upper);
    set_face(p, 10 + k, lower);
    set_face(p, 15 + k, bottom);
  }
#undef U
#undef L
  set_normals(p, 0);
}

void glutSolidIcosahedron(void) {
  Polyhedron p;
  icosahedron(&p);
  draw(&p, 1.0f, 0);
}

void glutWireIcosahedron(void) {
  Polyhedron p;
  icosahedron(&p);
  draw(&p, 1.0f, 1);
}

/* ---- Rhombic dodecahedron: circumradius 1, vertices on +z and -z --------------------------- */

/* Vertex 0 is +z and 13 is -z; 1-4 (ring u) lie at z = 1/2, 9-12 (ring l) at z = -1/2, both at
 * radius sqrt(2)/2 on +x, +y, -x, -y; 5-8 (ring e) at z = 0 and radius 1 between them, e_k
 * between u_k and u_k+1. Faces: the four around +z, the four around the equator, the four
 * around -z. The normals are freeglut's: unit length on the equator, (+-sqrt(2)/4, +-sqrt(2)/4,
 * +-1/2) (length sqrt(2)/2) on the other eight. */
static void rhombic_dodecahedron(Polyhedron* p) {
  static const int kQuarterCos[4] = {1, 0, -1, 0}, kQuarterSin[4] = {0, 1, 0, -1};
  const double h = sqrt(0.5);
  p->face_count = 12, p->corners = 4;
  set_vertex(p, 0, 0.0, 0.0, 1.0);
  set_vertex(p, 13, 0.0, 0.0, -1.0);
  for (int k = 0; k < 4; ++k) {
    const int c = kQuarterCos[k], s = kQuarterSin[k], n = (k + 1) % 4;
    set_vertex(p, 1 + k, h * c, h * s, 0.5);
    set_vertex(p, 5 + k, h * (c - s), h * (s + c), 0.0); /* turned 45 degrees on */
    set_vertex(p, 9 + k, h * c, h * s, -0.5);
    const int top[4] = {0, 1 + k, 5 + k, 1 + n}, equator[4] = {5 + k, 9 + n, 5 + n, 1 + n};
    const int bottom[4] = {5 + k, 9 + k, 13, 9 + n};
    set_face(p, k, top);
    set_face(p, 4 + k, equator);
    set_face(p, 8 + k, bottom);
  }
  for (int k = 0; k < 4; ++k) {
    const float* e = p->vertices[5 + k];
    const int n = (k + 1) % 4;
    const float top[3] = {0.5f * e[0], 0.5f * e[1], 0.5f},
                bottom[3] = {0.5f * e[0], 0.5f * e[1], -0.5f};
    const float equator[3] = {(float)kQuarterCos[n], (float)kQuarterSin[n], 0.0f};
    for (int i = 0; i < 3; ++i) {
      p->normals[k][i] = top[i];
      p->normals[4 + k][i] = equator[i];
      p->normals[8 + k][i] = bottom[i];
    }
  }
}

void glutSolidRhombicDodecahedron(void) {
  Polyhedron p;
  rhombic_dodecahedron(&p);
  draw(&p, 1.0f, 0);
}

void glutWireRhombicDodecahedron(void) {
  Polyhedron p;
  rhombic_dodecahedron(&p);
  draw(&p, 1.0f, 1);
}
