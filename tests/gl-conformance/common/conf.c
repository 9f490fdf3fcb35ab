/* Shared helper of the GL conformance programs (see conf.h). */
#include "conf.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb_image_write.h>

int conf_init(ConfContext* c, int argc, char** argv, int width, int height) {
  return conf_init_accum(c, argc, argv, width, height, 0);
}

int conf_init_accum(ConfContext* c, int argc, char** argv, int width, int height, int accum_bits) {
  c->ctx = NULL;
  c->buffer = NULL;
  c->width = width;
  c->height = height;
  c->out_path = argc > 1 ? argv[1] : NULL;
  c->values = NULL;
  if (!c->out_path) {
    fprintf(stderr, "usage: %s OUTPUT.png\n", argc > 0 ? argv[0] : "program");
    return 0;
  }
  c->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, accum_bits, NULL);
  if (!c->ctx) {
    fprintf(stderr, "OSMesaCreateContextExt failed\n");
    return 0;
  }
  c->buffer = (unsigned char*)calloc((size_t)width * height * 4, 1);
  if (!c->buffer || !OSMesaMakeCurrent(c->ctx, c->buffer, GL_UNSIGNED_BYTE, width, height)) {
    fprintf(stderr, "OSMesaMakeCurrent failed\n");
    return 0;
  }
  fprintf(stderr, "renderer: %s | %s\n", (const char*)glGetString(GL_RENDERER),
          (const char*)glGetString(GL_VERSION));
  glViewport(0, 0, width, height);
  return 1;
}

int conf_check_error(const char* where) {
  GLenum e = glGetError();
  if (e == GL_NO_ERROR) return 0;
  fprintf(stderr, "unexpected GL error 0x%04x at %s\n", (unsigned)e, where);
  while (glGetError() != GL_NO_ERROR) {
  }
  return 1;
}

FILE* conf_open_values(const ConfContext* c) {
  size_t n = strlen(c->out_path);
  char* path = (char*)malloc(n + 5);
  if (!path) return NULL;
  strcpy(path, c->out_path);
  if (n >= 4 && strcmp(path + n - 4, ".png") == 0) path[n - 4] = '\0';
  strcat(path, ".txt");
  FILE* f = fopen(path, "w");
  if (!f) fprintf(stderr, "cannot write %s\n", path);
  free(path);
  return f;
}

void conf_value_cells(const ConfContext* c, const unsigned* values, int n, int cols, int rows) {
  glViewport(0, 0, c->width, c->height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, cols, rows, 0, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  for (int i = 0; i < n && i < cols * rows; ++i) {
    /* 9 bits of a hash of the value, 3 per channel, each step 33/255 apart. */
    unsigned v = values[i] * 2654435761u, h = (v ^ (v >> 9) ^ (v >> 18) ^ (v >> 27)) & 511u;
    glColor3ub((GLubyte)(20 + 33 * (h & 7)), (GLubyte)(20 + 33 * ((h >> 3) & 7)), (GLubyte)(20 + 33 * (h >> 6)));
    float x = (float)(i % cols), y = (float)(i / cols);
    glBegin(GL_TRIANGLES);
    glVertex2f(x + 0.1f, y + 0.1f), glVertex2f(x + 0.9f, y + 0.1f), glVertex2f(x + 0.9f, y + 0.9f);
    glVertex2f(x + 0.1f, y + 0.1f), glVertex2f(x + 0.9f, y + 0.9f), glVertex2f(x + 0.1f, y + 0.9f);
    glEnd();
  }
}

int conf_write_png(const char* path, const unsigned char* rgba, int width, int height) {
  stbi_flip_vertically_on_write(1);
  return stbi_write_png(path, width, height, 4, rgba, width * 4) != 0;
}

int conf_write_bytes_png(const char* path, const unsigned char* bytes, long n, int width) {
  long pixels = (n + 3) / 4, rows = (pixels + width - 1) / width;
  unsigned char* rgba = (unsigned char*)calloc((size_t)(rows * width * 4), 1);
  if (!rgba) return 0;
  for (long i = 0; i < n; ++i) rgba[i] = bytes[i];
  stbi_flip_vertically_on_write(0);
  int ok = stbi_write_png(path, width, (int)rows, 4, rgba, width * 4) != 0;
  free(rgba);
  return ok;
}

int conf_finish(ConfContext* c) {
  int rc = 0;
  glFinish();
  if (conf_check_error("end of program")) rc = 3;
  if (!conf_write_png(c->out_path, c->buffer, c->width, c->height)) {
    fprintf(stderr, "cannot write %s\n", c->out_path);
    rc = 2;
  }
  OSMesaDestroyContext(c->ctx);
  free(c->buffer);
  if (c->values && fclose(c->values) != 0) rc = 2;
  return rc;
}

void conf_value(ConfContext* c, const char* name, double value) {
  if (!c->values) c->values = conf_open_values(c);
  if (c->values) fprintf(c->values, "%s: %.9g\n", name, value);
}

void conf_values(ConfContext* c, const char* name, const double* values, int n) {
  char key[256];
  for (int i = 0; i < n; ++i) {
    snprintf(key, sizeof key, "%s[%d]", name, i);
    conf_value(c, key, values[i]);
  }
}

void conf_error(ConfContext* c, const char* name) {
  char key[256];
  snprintf(key, sizeof key, "error %s", name);
  conf_value(c, key, (double)glGetError());
  while (glGetError() != GL_NO_ERROR) {
  }
}

void conf_panel(const ConfContext* c, int col, int row, int ncols, int nrows) {
  int w = c->width / ncols, h = c->height / nrows;
  glViewport(col * w, c->height - (row + 1) * h, w, h);
}

void conf_pixel_panel(const ConfContext* c, int col, int row, int ncols, int nrows) {
  conf_panel(c, col, row, ncols, nrows);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, c->width / ncols, 0, c->height / nrows, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void sphere_vertex(float r, int i, int j, int slices, int stacks) {
  double theta = 2.0 * CONF_PI * i / slices; /* around y */
  double phi = CONF_PI * j / stacks;         /* from the north pole */
  float x = (float)(sin(phi) * sin(theta)), y = (float)cos(phi), z = (float)(sin(phi) * cos(theta));
  glNormal3f(x, y, z);
  glTexCoord2f((float)i / slices, 1.0f - (float)j / stacks);
  glVertex3f(r * x, r * y, r * z);
}

void conf_sphere(float r, int slices, int stacks) {
  glBegin(GL_TRIANGLES);
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      /* counter-clockwise seen from outside: (i, j) -> (i, j+1) -> (i+1, j+1) */
      sphere_vertex(r, i, j, slices, stacks);
      sphere_vertex(r, i, j + 1, slices, stacks);
      sphere_vertex(r, i + 1, j + 1, slices, stacks);
      sphere_vertex(r, i, j, slices, stacks);
      sphere_vertex(r, i + 1, j + 1, slices, stacks);
      sphere_vertex(r, i + 1, j, slices, stacks);
    }
  }
  glEnd();
}

static void wall_vertex(float w, float h, int n, int i, int j) {
  float u = (float)i / n, v = (float)j / n;
  glTexCoord2f(u, v);
  glVertex3f(-0.5f * w + u * w, -0.5f * h + v * h, 0.0f);
}

void conf_wall(float w, float h, int n) {
  glNormal3f(0.0f, 0.0f, 1.0f);
  glBegin(GL_TRIANGLES);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      wall_vertex(w, h, n, i, j);
      wall_vertex(w, h, n, i + 1, j);
      wall_vertex(w, h, n, i + 1, j + 1);
      wall_vertex(w, h, n, i, j);
      wall_vertex(w, h, n, i + 1, j + 1);
      wall_vertex(w, h, n, i, j + 1);
    }
  }
  glEnd();
}

static void tube_vertex(float r, float y, int i, int slices) {
  double t = 2.0 * CONF_PI * i / slices;
  float x = (float)sin(t), z = (float)cos(t);
  glNormal3f(x, 0.0f, z);
  glVertex3f(r * x, y, r * z);
}

void conf_tube(float r, float h, int slices) {
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < slices; ++i) {
    tube_vertex(r, 0.0f, i, slices);
    tube_vertex(r, 0.0f, i + 1, slices);
    tube_vertex(r, h, i + 1, slices);
    tube_vertex(r, 0.0f, i, slices);
    tube_vertex(r, h, i + 1, slices);
    tube_vertex(r, h, i, slices);
  }
  glEnd();
}
