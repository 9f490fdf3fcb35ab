/* The teapot tables generated at build time by teapot_gen.cpp (make_teapot, size 1):
 * per vertex position, unit normal and texture coordinate; counter-clockwise triangles. */
#ifndef SHADELAB_GLUT_TEAPOT_MESH_H
#define SHADELAB_GLUT_TEAPOT_MESH_H

extern const int shadelab_glut_teapot_vertex_count;
extern const float shadelab_glut_teapot_vertices[][8]; /* x y z, nx ny nz, s t */
extern const int shadelab_glut_teapot_triangle_count;
extern const unsigned int shadelab_glut_teapot_triangles[][3];

#endif
