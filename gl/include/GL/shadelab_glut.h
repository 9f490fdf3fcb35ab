/* GLUT's solid shapes with GLUT's signatures, from libshadelab-glut: plain OpenGL 1.1 client
 * code (glBegin/glNormal/glTexCoord/glVertex), so it works on top of libshadelab-gl or Mesa's
 * libOSMesa alike. Every shape is drawn as counter-clockwise GL_TRIANGLES (front faces
 * outward) with unit normals, centred at the origin of the current modelview.
 * Needs <GL/gl.h> from either implementation; no windowing functions. */
#ifndef SHADELAB_GLUT_H
#define SHADELAB_GLUT_H

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The Utah teapot (from shadelab's Bezier patch tessellation) as glutSolidTeapot(size):
 * lid toward +y, spout toward +x, body rim radius about `size`. Texture coordinates are the
 * patch parameters. */
void glutSolidTeapot(GLdouble size);

/* Sphere around the z axis (poles at z = +-radius), `slices` around z, `stacks` along it. */
void glutSolidSphere(GLdouble radius, GLint slices, GLint stacks);

/* Axis-aligned cube of edge `size`, one normal per face. */
void glutSolidCube(GLdouble size);

/* Torus around the z axis: tube radius `innerRadius`, distance from the centre to the tube's
 * centre `outerRadius`; `sides` around the tube, `rings` around the axis. */
void glutSolidTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings);

/* Cone along +z: base disk of radius `base` at z = 0 (facing -z), apex at z = height. */
void glutSolidCone(GLdouble base, GLdouble height, GLint slices, GLint stacks);

/* Regular tetrahedron of radius sqrt(3): vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1). */
void glutSolidTetrahedron(void);

#ifdef __cplusplus
}
#endif

#endif /* SHADELAB_GLUT_H */
