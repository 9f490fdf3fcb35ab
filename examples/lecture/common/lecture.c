/* Shared helper of the lecture's examples (see lecture.h). */
#include "lecture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb_image_write.h>

int lecture_begin(LectureImage* img, int argc, char** argv, const char* default_name, int width,
                  int height) {
  img->path = default_name;
  for (int i = 1; i < argc; ++i) {
    if (strncmp(argv[i], "--", 2) == 0) {
      ++i; /* skip the option's value */
      continue;
    }
    img->path = argv[i];
    break;
  }
  img->width = width;
  img->height = height;
  img->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  img->buffer = (unsigned char*)calloc((size_t)width * height * 4, 1);
  if (!img->ctx || !img->buffer ||
      !OSMesaMakeCurrent(img->ctx, img->buffer, GL_UNSIGNED_BYTE, width, height)) {
    fprintf(stderr, "cannot create an OSMesa context\n");
    return 0;
  }
  glViewport(0, 0, width, height);
  return 1;
}

int lecture_end(LectureImage* img) {
  glFinish();
  GLenum error = glGetError();
  int rc = 0;
  if (error != GL_NO_ERROR) {
    fprintf(stderr, "GL error 0x%04x\n", (unsigned)error);
    rc = 3;
  }
  stbi_flip_vertically_on_write(1);
  if (!stbi_write_png(img->path, img->width, img->height, 4, img->buffer, img->width * 4)) {
    fprintf(stderr, "cannot write %s\n", img->path);
    rc = 2;
  } else {
    printf("wrote %s (%dx%d)\n", img->path, img->width, img->height);
  }
  OSMesaDestroyContext(img->ctx);
  free(img->buffer);
  return rc;
}

const char* lecture_option(int argc, char** argv, const char* name) {
  for (int i = 1; i + 1 < argc; ++i)
    if (strcmp(argv[i], name) == 0) return argv[i + 1];
  return NULL;
}

void lecture_perspective(double fovy_degrees, double aspect, double z_near, double z_far) {
  double top = z_near * tan(fovy_degrees * 3.14159265358979323846 / 360.0);
  glFrustum(-top * aspect, top * aspect, -top, top, z_near, z_far);
}

double lecture_panel(const LectureImage* img, int index, int count, int row, int rows) {
  int w = img->width / count, h = img->height / rows;
  glViewport(index * w, img->height - (row + 1) * h, w, h);
  return (double)w / h;
}

void lecture_lit_view(double aspect) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  lecture_perspective(40.0, aspect, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  /* The direction of the white light source is (1, 1, 1), given in eye space. */
  GLfloat light_position[] = {1., 1., 1., 0.};
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
}

void lecture_teapot_view(double aspect) {
  lecture_lit_view(aspect);
  glTranslatef(0.0f, 0.0f, -6.0f);
  glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(-20.0f, 0.0f, 1.0f, 0.0f);
}

void lecture_teapot_panel(const LectureImage* img, int index, int count) {
  lecture_teapot_view(lecture_panel(img, index, count, 0, 1));
}

void wall(int n) {
  glNormal3f(0., 0., 1.);
  glBegin(GL_QUADS);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      float x0 = -4. + 8. * i / n, x1 = -4. + 8. * (i + 1) / n;
      float y0 = -4. + 8. * j / n, y1 = -4. + 8. * (j + 1) / n;
      glVertex3f(x0, y0, 0.);
      glVertex3f(x1, y0, 0.);
      glVertex3f(x1, y1, 0.);
      glVertex3f(x0, y1, 0.);
    }
  }
  glEnd();
}
