/* Shared helper of the lecture's examples: an off-screen OSMesa context on an RGBA buffer, a
 * PNG writer, and the small pieces of camera set-up that the lecture takes for granted
 * (a perspective projection without GLU, panels side by side). Plain OpenGL 1.1 + OSMesa:
 * it builds against libshadelab-gl and against Mesa's libOSMesa alike. */
#ifndef SHADELAB_LECTURE_H
#define SHADELAB_LECTURE_H

#include <GL/gl.h>
#include <GL/osmesa.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct LectureImage {
  OSMesaContext ctx;
  unsigned char* buffer; /* width * height * 4 bytes, bottom row first */
  int width;
  int height;
  const char* path; /* the PNG to write */
} LectureImage;

/* Creates a width x height RGBA context (depth 24, stencil 8) and makes it current. The PNG's
 * name is the first command-line argument that does not start with "--", else `default_name`.
 * Returns 0 (and says why on stderr) on failure. */
int lecture_begin(LectureImage* img, int argc, char** argv, const char* default_name, int width,
                  int height);

/* glFinish, writes the PNG (top row first), destroys the context; returns the exit status. */
int lecture_end(LectureImage* img);

/* The value of "--name VALUE" on the command line, or NULL. */
const char* lecture_option(int argc, char** argv, const char* name);

/* gluPerspective without GLU: fovy in degrees, aspect = width / height. */
void lecture_perspective(double fovy_degrees, double aspect, double z_near, double z_far);

/* Panel `index` of `count` side by side in a row of `rows` rows (row 0 at the top): sets the
 * viewport and returns its aspect ratio. */
double lecture_panel(const LectureImage* img, int index, int count, int row, int rows);

/* The lecture's usual view: a 40-degree perspective of `aspect`, the modelview reset, and
 * the white directional light from (1, 1, 1) set in eye space. */
void lecture_lit_view(double aspect);

/* The lit view with the teapot seen from 6 units, turned 20 degrees about x and -20 about y
 * (the shiny-teapot figure). */
void lecture_teapot_view(double aspect);

/* Panel `index` of `count` in one row, with the teapot view: the lit-versus-unlit,
 * reflection-terms and light-colours figures. */
void lecture_teapot_panel(const LectureImage* img, int index, int count);

/* The lecture's wall (its mesh-size slides): the 8 x 8 square at z = 0 facing +z, drawn as
 * n x n GL_QUADS with one normal. Used by the mesh-size, spot, attenuation and
 * directional-versus-point examples. */
void wall(int n);

#ifdef __cplusplus
}
#endif

#endif
