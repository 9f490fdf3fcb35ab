/* GLUT's shapes with GLUT's signatures (those of freeglut's <GL/freeglut_std.h>, and
 * <GL/freeglut_ext.h> for the rhombic dodecahedron), from libshadelab-glut: plain OpenGL 1.1
 * client code (glBegin/glNormal/glTexCoord/glVertex), so it works on top of libshadelab-gl or
 * Mesa's libOSMesa alike. Every shape has the geometry of freeglut 3 (Debian's libglut): the
 * same vertices, normals, primitives, winding and position, so that an image drawn with either
 * library is the same. Solids are counter-clockwise from outside except the teapot (clockwise,
 * as GLUT's has always been); wire shapes draw freeglut's lines with the same normals, so they
 * can be lit. Everything sits at the origin of the current modelview, in its units.
 * Needs <GL/gl.h> from either implementation; no windowing functions. */
#ifndef SHADELAB_GLUT_H
#define SHADELAB_GLUT_H

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The Utah teapot, lid toward +y, spout toward +x, its height centred on the origin, body rim
 * radius about `size`. The solid is 32 patches of 7 x 7 quads as triangles, wound clockwise seen
 * from outside (cull with glFrontFace(GL_CW)), texture coordinates the patch parameters in
 * [0, 1]; the wire teapot is 10 lines each way across every patch. */
void glutSolidTeapot(GLdouble size);
void glutWireTeapot(GLdouble size);

/* Sphere around the z axis (poles at z = +-radius): `slices` meridians, `stacks` bands between
 * the poles. The solid is one triangle strip per band; the wire sphere draws the meridians
 * (pole to pole) and the stacks - 1 parallels. Nothing if slices < 1 or stacks < 2. */
void glutSolidSphere(GLdouble radius, GLint slices, GLint stacks);
void glutWireSphere(GLdouble radius, GLint slices, GLint stacks);

/* Axis-aligned cube of edge `size`, one normal per face; the wire cube outlines each face. */
void glutSolidCube(GLdouble size);
void glutWireCube(GLdouble size);

/* Torus around the z axis: tube radius `innerRadius`, distance from the centre to the tube's
 * centre `outerRadius`; `sides` around the tube, `rings` around the axis. The wire torus draws
 * the rings' circles and the sides' circles. Nothing if sides < 2 or rings < 2. */
void glutSolidTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings);
void glutWireTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings);

/* Cone along +z: base disk of radius `base` at z = 0 (facing -z), apex at z = height, `slices`
 * around, `stacks` along z. The wire cone draws a line per slice from the rim to the apex and a
 * circle at the bottom of each stack (the rim first). Nothing if slices < 1 or stacks < 1. */
void glutSolidCone(GLdouble base, GLdouble height, GLint slices, GLint stacks);
void glutWireCone(GLdouble base, GLdouble height, GLint slices, GLint stacks);

/* Regular tetrahedron of circumradius 1: vertices (1, 0, 0), (-1/3, 2 sqrt(2)/3, 0) and
 * (-1/3, -sqrt(2)/3, +-sqrt(6)/3). */
void glutSolidTetrahedron(void);
void glutWireTetrahedron(void);

/* Regular octahedron of circumradius 1, vertices on the axes. */
void glutSolidOctahedron(void);
void glutWireOctahedron(void);

/* Regular dodecahedron of circumradius sqrt(3): the cube's corners (+-1, +-1, +-1) and
 * (0, +-phi, +-1/phi), (+-1/phi, 0, +-phi), (+-phi, +-1/phi, 0), phi the golden ratio. */
void glutSolidDodecahedron(void);
void glutWireDodecahedron(void);

/* Regular icosahedron of circumradius 1 with vertices on +x and -x. Its normals are about 0.957
 * long, not 1, as freeglut's (use GL_NORMALIZE for exact lighting). */
void glutSolidIcosahedron(void);
void glutWireIcosahedron(void);

/* Rhombic dodecahedron of circumradius 1 with vertices on +z and -z. The normals of the eight
 * faces that meet those two vertices are sqrt(2)/2 long, not 1, as freeglut's. */
void glutSolidRhombicDodecahedron(void);
void glutWireRhombicDodecahedron(void);

#ifdef __cplusplus
}
#endif

#endif /* SHADELAB_GLUT_H */
