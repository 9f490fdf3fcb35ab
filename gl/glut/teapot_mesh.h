/* The teapot's sample grids, generated at build time by teapot_gen.cpp from make_teapot (size 1):
 * per patch an n x n grid of samples, row r (the patch's u) by column c (its v), sample
 * (p * n + r) * n + c, each x y z, unit normal nx ny nz, texture coordinate s t. Normals point
 * outward; the triangles (r, c) (r + 1, c) (r + 1, c + 1) and (r, c) (r + 1, c + 1) (r, c + 1)
 * are clockwise seen from outside, as freeglut's teapot is. */
#ifndef SHADELAB_GLUT_TEAPOT_MESH_H
#define SHADELAB_GLUT_TEAPOT_MESH_H

extern const int shadelab_glut_teapot_patch_count;
extern const int shadelab_glut_teapot_solid_samples; /* n of the solid teapot's grids (8) */
extern const float shadelab_glut_teapot_solid[][8];
extern const int shadelab_glut_teapot_wire_samples; /* n of the wire teapot's grids (10) */
extern const float shadelab_glut_teapot_wire[][8];

#endif
