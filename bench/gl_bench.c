/* The benchmark scenes as one OpenGL 1.1 + OSMesa program, built twice from this source:
 * against Mesa's libOSMesa (bench_gl_mesa; llvmpipe or softpipe by GALLIUM_DRIVER) and against
 * libshadelab-gl (bench_gl_shadelab). Each frame: clear, draw, glFinish. Prints one line:
 *   RESULT scene=NAME size=WxH triangles=N frames=F median_ms=M min_ms=A max_ms=B
 *
 *   bench_gl_* SCENE [--size WxH] [--triangles N] [--frames F] [--warmup W] [--png FILE]
 *
 * Scenes:
 *   sphere  a sphere of about N triangles (default 1,000,000) lit by 8 attenuated point
 *           lights, Gouraud, drawn with glDrawElements from float arrays;
 *   teapot  the lecture's shiny red teapot (glutSolidTeapot, one white directional light);
 *   fill    a full-screen 100 x 100 wall under a spot light, with two transparent layers
 *           (blended, src alpha / one minus src alpha) over it: fill-bound;
 *   list    the sphere scene's mesh as a display list, compiled once (glBegin(GL_TRIANGLES),
 *           glNormal3fv and glVertex3fv per index, as programs build lists) and called each
 *           frame: to compare with the sphere's glDrawElements. */
#define _DEFAULT_SOURCE 1
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <GL/gl.h>
#include <GL/osmesa.h>
#include <GL/shadelab_glut.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

typedef struct {
  GLfloat* positions;
  GLfloat* normals;
  GLuint* indices;
  int vertex_count, index_count;
} Mesh;

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

static int compare_doubles(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

/* A UV sphere of radius 1 with about `triangles` triangles (2 * slices * stacks). */
static Mesh make_sphere(long triangles) {
  Mesh m;
  int stacks = (int)sqrt(triangles / 4.0);
  if (stacks < 2) stacks = 2;
  int slices = 2 * stacks;
  m.vertex_count = (slices + 1) * (stacks + 1);
  m.index_count = 6 * slices * stacks;
  m.positions = malloc(sizeof(GLfloat) * 3 * (size_t)m.vertex_count);
  m.normals = malloc(sizeof(GLfloat) * 3 * (size_t)m.vertex_count);
  m.indices = malloc(sizeof(GLuint) * (size_t)m.index_count);
  int v = 0;
  for (int j = 0; j <= stacks; ++j) {
    double phi = M_PI * j / stacks;
    for (int i = 0; i <= slices; ++i, ++v) {
      double theta = 2.0 * M_PI * i / slices;
      GLfloat n[3] = {(GLfloat)(sin(phi) * cos(theta)), (GLfloat)cos(phi), (GLfloat)(-sin(phi) * sin(theta))};
      memcpy(&m.positions[3 * v], n, sizeof n);
      memcpy(&m.normals[3 * v], n, sizeof n);
    }
  }
  int k = 0;
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      GLuint a = (GLuint)(j * (slices + 1) + i), b = a + 1, c = a + (GLuint)(slices + 1), d = c + 1;
      GLuint tri[6] = {a, c, b, b, c, d};
      memcpy(&m.indices[k], tri, sizeof tri);
      k += 6;
    }
  return m;
}

static void perspective(double fovy, double aspect, double znear, double zfar) {
  double h = znear * tan(fovy * M_PI / 360.0);
  glFrustum(-h * aspect, h * aspect, -h, h, znear, zfar);
}

static void setup_sphere(int width, int height) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  perspective(30.0, (double)width / height, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -5.0f);
  glEnable(GL_LIGHTING);
  GLfloat amb[] = {0.05f, 0.05f, 0.05f, 1.0f};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
  for (int i = 0; i < 8; ++i) {
    double a = 2.0 * M_PI * i / 8.0;
    GLfloat pos[] = {(GLfloat)(3.0 * cos(a)), (GLfloat)(1.5 * sin(2.0 * a)), (GLfloat)(2.5 + sin(a)), 1.0f};
    GLfloat col[] = {0.3f + 0.7f * (i & 1), 0.3f + 0.7f * ((i >> 1) & 1), 0.3f + 0.7f * ((i >> 2) & 1), 1.0f};
    glLightfv(GL_LIGHT0 + i, GL_POSITION, pos);
    glLightfv(GL_LIGHT0 + i, GL_DIFFUSE, col);
    glLightfv(GL_LIGHT0 + i, GL_SPECULAR, col);
    glLightf(GL_LIGHT0 + i, GL_CONSTANT_ATTENUATION, 0.5f);
    glLightf(GL_LIGHT0 + i, GL_LINEAR_ATTENUATION, 0.1f);
    glLightf(GL_LIGHT0 + i, GL_QUADRATIC_ATTENUATION, 0.02f);
    glEnable(GL_LIGHT0 + i);
  }
  GLfloat dif[] = {0.6f, 0.6f, 0.6f, 1.0f}, spec[] = {0.5f, 0.5f, 0.5f, 1.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, dif);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
}

static void draw_sphere(const Mesh* m) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, m->positions);
  glNormalPointer(GL_FLOAT, 0, m->normals);
  glDrawElements(GL_TRIANGLES, m->index_count, GL_UNSIGNED_INT, m->indices);
}

/* The sphere's triangles, vertex by vertex, into list 1. */
static void compile_sphere_list(const Mesh* m) {
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  for (int k = 0; k < m->index_count; ++k) {
    const GLuint i = m->indices[k];
    glNormal3fv(&m->normals[3 * i]);
    glVertex3fv(&m->positions[3 * i]);
  }
  glEnd();
  glEndList();
}

static void setup_teapot(int width, int height) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  perspective(30.0, (double)width / height, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, -0.15f, -5.5f);
  glRotatef(15.0f, 1.0f, 0.0f, 0.0f);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  GLfloat dir[] = {1.0f, 1.0f, 1.0f, 0.0f}, white[] = {1.0f, 1.0f, 1.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  GLfloat red[] = {0.41f, 0.135f, 0.067f, 1.0f}; /* the lecture's shiny red */
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 125.0f);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);
}

static void setup_fill(int width, int height) {
  (void)width, (void)height;
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -2.0, 2.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  GLfloat pos[] = {0.0f, 0.0f, 1.5f, 1.0f}, down[] = {0.0f, 0.0f, -1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, down);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 40.0f);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 4.0f);
  glEnable(GL_LIGHT0);
}

static void draw_fill(void) {
  /* The wall: 100 x 100 quads filling the view, lit per vertex by the spot. */
  glEnable(GL_LIGHTING);
  glDisable(GL_BLEND);
  GLfloat grey[] = {0.8f, 0.8f, 0.8f, 1.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glBegin(GL_QUADS);
  for (int j = 0; j < 100; ++j)
    for (int i = 0; i < 100; ++i) {
      float x0 = -1.0f + 0.02f * i, y0 = -1.0f + 0.02f * j, x1 = x0 + 0.02f, y1 = y0 + 0.02f;
      glVertex3f(x0, y0, 0.0f), glVertex3f(x1, y0, 0.0f), glVertex3f(x1, y1, 0.0f), glVertex3f(x0, y1, 0.0f);
    }
  glEnd();
  /* Two transparent full-screen layers in front of it. */
  glDisable(GL_LIGHTING);
  glEnable(GL_BLEND);
  glColor4f(0.2f, 0.4f, 1.0f, 0.3f);
  glRectf(-1.0f, -1.0f, 1.0f, 1.0f);
  glColor4f(1.0f, 0.5f, 0.1f, 0.25f);
  glBegin(GL_QUADS);
  glVertex3f(-1.0f, -1.0f, 0.5f), glVertex3f(1.0f, -1.0f, 0.5f), glVertex3f(1.0f, 1.0f, 0.5f), glVertex3f(-1.0f, 1.0f, 0.5f);
  glEnd();
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s sphere|teapot|fill|list [--size WxH] [--triangles N] [--frames F] [--warmup W] [--png FILE]\n", argv[0]);
    return 2;
  }
  const char* scene = argv[1];
  int width = 1920, height = 1080, frames = 10, warmup = 2;
  long triangles = 1000000;
  const char* png = NULL;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--size") && sscanf(argv[i + 1], "%dx%d", &width, &height) == 2) continue;
    if (!strcmp(argv[i], "--triangles")) triangles = atol(argv[i + 1]);
    else if (!strcmp(argv[i], "--frames")) frames = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--warmup")) warmup = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--png")) png = argv[i + 1];
    else {
      fprintf(stderr, "unknown option %s\n", argv[i]);
      return 2;
    }
  }
  if (frames < 1 || width < 1 || height < 1 || triangles < 8) return 2;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  unsigned char* buffer = malloc((size_t)width * height * 4);
  if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, width, height)) {
    fprintf(stderr, "no OSMesa context\n");
    return 1;
  }
  glViewport(0, 0, width, height);
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  Mesh mesh = {0};
  int kind = !strcmp(scene, "sphere") ? 0 : !strcmp(scene, "teapot") ? 1 : !strcmp(scene, "fill") ? 2
             : !strcmp(scene, "list") ? 3 : -1;
  if (kind < 0) {
    fprintf(stderr, "unknown scene %s\n", scene);
    return 2;
  }
  if (kind == 0 || kind == 3) {
    mesh = make_sphere(triangles);
    triangles = mesh.index_count / 3;
    setup_sphere(width, height);
    if (kind == 3) compile_sphere_list(&mesh);
  } else if (kind == 1) {
    triangles = 0; /* glutSolidTeapot's own tessellation (printed as 0: not counted here) */
    setup_teapot(width, height);
  } else {
    triangles = 2 * 100 * 100 + 4;
    setup_fill(width, height);
  }
  double* times = malloc(sizeof(double) * (size_t)frames);
  for (int f = -warmup; f < frames; ++f) {
    double t0 = now_ms();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (kind == 0) draw_sphere(&mesh);
    else if (kind == 1) glutSolidTeapot(1.0);
    else if (kind == 3) glCallList(1);
    else draw_fill();
    glFinish();
    if (f >= 0) times[f] = now_ms() - t0;
  }
  qsort(times, (size_t)frames, sizeof(double), compare_doubles);
  double median = frames % 2 ? times[frames / 2] : 0.5 * (times[frames / 2 - 1] + times[frames / 2]);
  printf("RESULT scene=%s size=%dx%d triangles=%ld frames=%d median_ms=%.3f min_ms=%.3f max_ms=%.3f\n",
         scene, width, height, triangles, frames, median, times[0], times[frames - 1]);
  if (png) {
    stbi_flip_vertically_on_write(1);
    if (!stbi_write_png(png, width, height, 4, buffer, width * 4)) return 1;
  }
  OSMesaDestroyContext(ctx);
  free(buffer);
  free(times);
  return 0;
}
