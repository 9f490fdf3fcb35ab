/* The GLUT shapes of shadelab-glut (the same client code in both builds, so any difference
 * comes from the GL library), every one wire and solid: the solids of the first rows lit with
 * the lecture's shiny red material (the teapot smooth, flat, scaled and culled too), then every
 * shape added with the wire shapes (wire sphere, cube, torus, cone, teapot, tetrahedron; wire
 * and solid octahedron, dodecahedron, icosahedron, rhombic dodecahedron), each lit and unlit,
 * two solids lit without GL_NORMALIZE (freeglut's icosahedron and rhombic dodecahedron normals
 * are not unit length), wide and stippled lines, a solid outlined by its wire shape. */
#include <GL/shadelab_glut.h>

#include "conf.h"

enum { kCols = 7, kRows = 6, kPanel = 85 };

static int panel_index = 0;

/* The next panel (left to right, top down) with the shape's view: the unit box seen from a
 * little above and to the side; `extent` widens the view for the larger shapes. */
static void next_panel(const ConfContext* c, float extent) {
  conf_panel(c, panel_index % kCols, panel_index / kCols, kCols, kRows);
  ++panel_index;
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5 * extent, 0.5 * extent, -0.5 * extent, 0.5 * extent, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.0f);
  glRotatef(25.0f, 1, 0, 0);
  glRotatef(-30.0f, 0, 1, 0);
}

static void cell(const ConfContext* c) { next_panel(c, 1.0f); }

/* Lit with the material `colour` (its diffuse and ambient; white specular), or unlit in it. */
static void lit(int on, float r, float g, float b) {
  if (on) {
    const GLfloat colour[] = {r, g, b, 1}, specular[] = {1, 1, 1, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT, colour);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, colour);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glEnable(GL_LIGHTING);
  } else {
    glDisable(GL_LIGHTING);
    glColor3f(r, g, b);
  }
}

static void upright(void) { /* GLUT's cone points along +z */
  glRotatef(-90.0f, 1, 0, 0);
  glTranslatef(0.0f, 0.0f, -0.8f);
}

/* The solids of the first version: teapot, sphere, cube, torus, cone, tetrahedron. */
static void first_solids(const ConfContext* c) {
  lit(1, .41f, .135f, .067f);
  cell(c);
  glutSolidTeapot(1.0);
  cell(c);
  glShadeModel(GL_FLAT);
  glutSolidTeapot(1.0);
  glShadeModel(GL_SMOOTH);
  cell(c);
  glutSolidSphere(1.0, 24, 12);
  cell(c);
  glutSolidCube(1.4);
  cell(c);
  glutSolidTorus(0.3, 0.9, 16, 32);
  cell(c);
  upright();
  glutSolidCone(0.9, 1.6, 24, 4);
  cell(c);
  glutSolidTetrahedron();
  cell(c); /* two teapots, one scaled: GL_NORMALIZE keeps their shading equal */
  glTranslatef(-0.6f, 0.0f, 0.0f);
  glutSolidTeapot(0.5);
  glTranslatef(1.2f, 0.0f, 0.0f);
  glScalef(0.5f, 0.5f, 0.5f);
  glutSolidTeapot(1.0);
  cell(c); /* cull back faces: GLUT's teapot is wound clockwise, so its front is GL_CW */
  glEnable(GL_CULL_FACE);
  glFrontFace(GL_CW);
  glutSolidTeapot(1.0);
  glFrontFace(GL_CCW);
  glDisable(GL_CULL_FACE);
}

/* The wire shapes, each lit and then unlit. */
static void wire_shapes(const ConfContext* c) {
  for (int on = 1; on >= 0; --on) {
    cell(c);
    lit(on, .9f, .4f, .3f);
    glutWireSphere(1.0, 16, 10);
    cell(c);
    lit(on, .3f, .6f, 1.0f);
    glutWireCube(1.3);
    cell(c);
    lit(on, .8f, .5f, .9f);
    glutWireTorus(0.3, 0.8, 10, 20);
    cell(c);
    lit(on, .5f, .9f, .9f);
    upright();
    glutWireCone(0.8, 1.6, 12, 4);
    cell(c);
    lit(on, .9f, .6f, .3f);
    glutWireTeapot(0.8);
    cell(c);
    lit(on, 1.0f, .4f, .4f);
    glutWireTetrahedron();
  }
}

/* The polyhedra, wire and solid, lit and unlit. */
static void polyhedra(const ConfContext* c) {
  for (int on = 1; on >= 0; --on) {
    cell(c);
    lit(on, .4f, 1.0f, .4f);
    glutWireOctahedron();
    cell(c);
    glutSolidOctahedron();
    next_panel(c, 1.5f);
    lit(on, .4f, .6f, 1.0f);
    glutWireDodecahedron();
    next_panel(c, 1.5f);
    glutSolidDodecahedron();
    cell(c);
    lit(on, 1.0f, .7f, .2f);
    glutWireIcosahedron();
    cell(c);
    glutSolidIcosahedron();
    cell(c);
    lit(on, .7f, .7f, 1.0f);
    glutWireRhombicDodecahedron();
    cell(c);
    glutSolidRhombicDodecahedron();
  }
}

/* Normals as the shapes give them (no GL_NORMALIZE), wide and stippled lines, a solid outlined
 * by its wire shape (the faces pushed back by polygon offset). */
static void variations(const ConfContext* c) {
  glDisable(GL_NORMALIZE);
  lit(1, .6f, .6f, .9f);
  cell(c);
  glutSolidIcosahedron();
  cell(c);
  glutSolidRhombicDodecahedron();
  glEnable(GL_NORMALIZE);
  cell(c);
  glLineWidth(2.0f);
  glutWireCube(1.2);
  glLineWidth(1.0f);
  cell(c);
  lit(0, .9f, .9f, .9f);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x3333);
  glutWireTeapot(0.8);
  glDisable(GL_LINE_STIPPLE);
  cell(c);
  glRotatef(60.0f, 0, 1, 0);
  lit(1, .3f, .8f, .5f);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  glutSolidTetrahedron();
  glDisable(GL_POLYGON_OFFSET_FILL);
  lit(0, 1.0f, 1.0f, 1.0f);
  glutWireTetrahedron();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, kCols * kPanel, kRows * kPanel)) return 1;
  glClearColor(0.1f, 0.1f, 0.12f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glMaterialf(GL_FRONT, GL_SHININESS, 60.0f);
  const GLfloat dir[] = {1, 1, 1, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);

  first_solids(&c);
  wire_shapes(&c);
  polyhedra(&c);
  variations(&c);
  return conf_finish(&c);
}
