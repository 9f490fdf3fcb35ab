/* Shared helper of the GL conformance programs: an OSMesa context on a caller-owned RGBA
 * GL_UNSIGNED_BYTE buffer, a PNG writer, panel viewports and a few tessellated shapes.
 * Plain OpenGL 1.1 + OSMesa client code: it is compiled twice, once against Mesa's headers
 * and libOSMesa, once against shadelab's gl/include headers and libshadelab-gl. */
#ifndef SHADELAB_GL_CONFORMANCE_CONF_H
#define SHADELAB_GL_CONFORMANCE_CONF_H

#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CONF_PI 3.14159265358979323846

typedef struct ConfContext {
  OSMesaContext ctx;
  unsigned char* buffer; /* width * height * 4 bytes, bottom row first (as OSMesa stores it) */
  int width;
  int height;
  const char* out_path;
  FILE* values; /* conf_value's file (conf_open_values), opened at its first record */
} ConfContext;

/* Creates an RGBA context (24-bit depth, 8-bit stencil) on a width x height buffer and makes
 * it current; the output path is argv[1]. Prints the reason and returns 0 on failure. */
int conf_init(ConfContext* c, int argc, char** argv, int width, int height);
/* The same with accumulation bits per channel asked for (OSMesaCreateContextExt's accumBits). */
int conf_init_accum(ConfContext* c, int argc, char** argv, int width, int height, int accum_bits);

/* glFinish, checks glGetError, writes the buffer as a PNG (flipped so that the PNG's first row
 * is the top of the image), destroys the context. Returns the process exit code. */
int conf_finish(ConfContext* c);

/* Writes an RGBA buffer stored bottom row first as a PNG, top row first. 1 on success. */
int conf_write_png(const char* path, const unsigned char* rgba, int width, int height);

/* Sets the viewport to cell (col, row) of an ncols x nrows grid over the whole buffer;
 * row 0 is the top row. Cell sizes are width / ncols and height / nrows (integer division). */
void conf_panel(const ConfContext* c, int col, int row, int ncols, int nrows);
/* conf_panel, with an orthographic projection in the cell's pixels (x from 0 to the cell's
 * width, y from 0 to its height, z from -1 to 1) and an identity modelview matrix. */
void conf_pixel_panel(const ConfContext* c, int col, int row, int ncols, int nrows);

/* Opens the text file beside the output PNG (its path with ".png" replaced by ".txt") for a
 * program whose values are compared with Mesa's one by one (tools/gl_values.cpp: a line per
 * value, "label: tokens"). NULL (and a message) on failure. */
FILE* conf_open_values(const ConfContext* c);

/* Draws values[0..n) as cells of a cols x rows grid over the whole buffer, each coloured by a
 * hash of its value (so that a different value shows in the image too); sets the viewport,
 * both matrices and unlit drawing. */
void conf_value_cells(const ConfContext* c, const unsigned* values, int n, int cols, int rows);

/* Writes `n` bytes as a PNG of RGBA pixels, `width` pixels a row (the last row padded with
 * zeros): data compared byte for byte by gl_compare --tolerance 0. 1 on success. */
int conf_write_bytes_png(const char* path, const unsigned char* bytes, long n, int width);

/* Reports an unexpected GL error (and where) on stderr; returns 1 if there was one. */
int conf_check_error(const char* where);

/* Records a named value (a query's answer, a glGetError code, a texel read back) as a line
 * "name: value" (%.9g) of the values file (conf_open_values, opened at the first record and
 * closed by conf_finish), for programs in GL_CONFORMANCE_VALUE_PROGRAMS: state and errors are
 * compared with Mesa's value by value by gl_values, not through pixels. */
void conf_value(ConfContext* c, const char* name, double value);
/* conf_value of "name[i]" for each of n values. */
void conf_values(ConfContext* c, const char* name, const double* values, int n);
/* Records glGetError() as "error name", then clears any further error. */
void conf_error(ConfContext* c, const char* name);

/* Shapes, all with per-vertex normals, drawn with glBegin(GL_TRIANGLES) (so that lighting tests
 * do not depend on how an implementation splits quads). */
/* UV sphere of radius r around the origin, poles on y; texture coordinates (u, v) in [0, 1]. */
void conf_sphere(float r, int slices, int stacks);
/* A wall in the plane z = 0 from (-w/2, -h/2) to (w/2, h/2), normal +z, n x n cells, texture
 * coordinates in [0, 1]. */
void conf_wall(float w, float h, int n);
/* Open tube of radius r around the y axis from y = 0 to y = h, outward normals, counter-clockwise
 * seen from outside. */
void conf_tube(float r, float h, int slices);

#ifdef __cplusplus
}
#endif

#endif
