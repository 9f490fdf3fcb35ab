/* The benchmark corpus: OpenGL 1.1 programs written the way classic GLUT examples are written
 * (state set once, the display function redrawn every frame), one scene each, built twice from
 * this source: against Mesa's libOSMesa (bench_corpus_mesa; llvmpipe by GALLIUM_DRIVER) and
 * against libshadelab-gl (bench_corpus_shadelab). A frame is the display function and glFinish.
 * Prints one line:
 *   RESULT scene=NAME size=WxH frames=F median_ms=M min_ms=A max_ms=B
 *
 *   bench_corpus_* SCENE [--size WxH] [--frames F] [--warmup W] [--png FILE] [--no-stencil]
 *   bench_corpus_* --list        the scene names, one a line
 *
 * --no-stencil asks for a context without a stencil buffer (scenes that use it need one). */
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

static int width = 1920, height = 1080;

/* ---- helpers ------------------------------------------------------------------------------ */

static void perspective(double fovy, double aspect, double znear, double zfar) {
  double h = znear * tan(fovy * M_PI / 360.0);
  glFrustum(-h * aspect, h * aspect, -h, h, znear, zfar);
}

static void projection_perspective(double fovy, double znear, double zfar) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  perspective(fovy, (double)width / height, znear, zfar);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void projection_ortho(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -2.0, 2.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void light_white(void) {
  GLfloat pos[] = {1.0f, 1.0f, 1.0f, 0.0f}, white[] = {1.0f, 1.0f, 1.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
}

/* A size x size RGBA checkerboard of `squares` squares a side, as the Red Book's checker.c. */
static GLubyte* checker_image(int size, int squares, int alpha) {
  GLubyte* p = malloc((size_t)size * size * 4);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      int on = ((i * squares / size) + (j * squares / size)) & 1;
      GLubyte* t = p + ((size_t)j * size + i) * 4;
      t[0] = on ? 255 : 40;
      t[1] = on ? 255 : (GLubyte)(40 + 200 * i / size);
      t[2] = on ? 255 : (GLubyte)(40 + 200 * j / size);
      t[3] = alpha ? (GLubyte)(on ? 255 : 64) : 255;
    }
  return p;
}

/* A texture object with the image and every mipmap level (2x2 box filter) when `mipmaps`. */
static GLuint make_texture(int size, int squares, int alpha, int mipmaps, GLenum min_filter, GLenum mag_filter) {
  GLuint name;
  glGenTextures(1, &name);
  glBindTexture(GL_TEXTURE_2D, name);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  GLubyte* image = checker_image(size, squares, alpha);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
  for (int level = 1, s = size / 2; mipmaps && s >= 1; ++level, s /= 2) {
    GLubyte* next = malloc((size_t)s * s * 4);
    for (int j = 0; j < s; ++j)
      for (int i = 0; i < s; ++i)
        for (int c = 0; c < 4; ++c) {
          const int w = 2 * s;
          int sum = image[((2 * j) * w + 2 * i) * 4 + c] + image[((2 * j) * w + 2 * i + 1) * 4 + c] +
                    image[((2 * j + 1) * w + 2 * i) * 4 + c] + image[((2 * j + 1) * w + 2 * i + 1) * 4 + c];
          next[((size_t)j * s + i) * 4 + c] = (GLubyte)((sum + 2) / 4);
        }
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, next);
    free(image);
    image = next;
  }
  free(image);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)min_filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)mag_filter);
  return name;
}

static void textured_quad(float x0, float y0, float x1, float y1, float z, float s0, float t0, float s1, float t1) {
  glBegin(GL_QUADS);
  glTexCoord2f(s0, t0), glVertex3f(x0, y0, z);
  glTexCoord2f(s1, t0), glVertex3f(x1, y0, z);
  glTexCoord2f(s1, t1), glVertex3f(x1, y1, z);
  glTexCoord2f(s0, t1), glVertex3f(x0, y1, z);
  glEnd();
}

/* A UV sphere of radius 1, `stacks` x 2 `stacks` quads as triangles, for arrays and lists. */
typedef struct {
  GLfloat* positions;
  GLuint* indices;
  int vertex_count, index_count;
} Mesh;

static Mesh sphere_mesh(int stacks) {
  Mesh m;
  int slices = 2 * stacks;
  m.vertex_count = (slices + 1) * (stacks + 1);
  m.index_count = 6 * slices * stacks;
  m.positions = malloc(sizeof(GLfloat) * 3 * (size_t)m.vertex_count);
  m.indices = malloc(sizeof(GLuint) * (size_t)m.index_count);
  int v = 0, k = 0;
  for (int j = 0; j <= stacks; ++j)
    for (int i = 0; i <= slices; ++i, ++v) {
      double phi = M_PI * j / stacks, theta = 2.0 * M_PI * i / slices;
      m.positions[3 * v] = (GLfloat)(sin(phi) * cos(theta));
      m.positions[3 * v + 1] = (GLfloat)cos(phi);
      m.positions[3 * v + 2] = (GLfloat)(-sin(phi) * sin(theta));
    }
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      GLuint a = (GLuint)(j * (slices + 1) + i), b = a + 1, c = a + (GLuint)(slices + 1), d = c + 1;
      GLuint tri[6] = {a, c, b, b, c, d};
      memcpy(&m.indices[k], tri, sizeof tri);
      k += 6;
    }
  return m;
}

static Mesh mesh;

static void sphere_material(void) {
  GLfloat dif[] = {0.6f, 0.5f, 0.3f, 1.0f}, spec[] = {0.5f, 0.5f, 0.5f, 1.0f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, dif);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
}

/* ---- scenes ------------------------------------------------------------------------------- */

/* empty: a clear and nothing else (the fixed cost of a frame). */
static void empty_init(void) { glEnable(GL_DEPTH_TEST); }
static void empty_display(void) { glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT); }

/* triangle: one smooth-shaded triangle (the Red Book's smooth.c). */
static void triangle_init(void) {
  projection_ortho();
  glShadeModel(GL_SMOOTH);
}
static void triangle_display(void) {
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.0f, 0.0f), glVertex2f(-0.9f, -0.9f);
  glColor3f(0.0f, 1.0f, 0.0f), glVertex2f(0.9f, -0.9f);
  glColor3f(0.0f, 0.0f, 1.0f), glVertex2f(0.0f, 0.9f);
  glEnd();
}

/* checker: a 64x64 checkerboard, GL_NEAREST, GL_DECAL, on two quads in perspective, one facing
 * the viewer and one turned away (the Red Book's checker.c). */
static void checker_setup(GLenum filter, GLenum env) {
  glEnable(GL_DEPTH_TEST);
  make_texture(64, 8, 0, 0, filter, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env);
  glEnable(GL_TEXTURE_2D);
  projection_perspective(60.0, 1.0, 30.0);
  glTranslatef(0.0f, 0.0f, -3.6f);
}
static void checker_init(void) { checker_setup(GL_NEAREST, GL_DECAL); }
static void checker_linear_init(void) { checker_setup(GL_LINEAR, GL_MODULATE); }
static void checker_display(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(0.9f, 0.8f, 0.7f);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f), glVertex3f(-2.0f, -1.0f, 0.0f);
  glTexCoord2f(0.0f, 1.0f), glVertex3f(-2.0f, 1.0f, 0.0f);
  glTexCoord2f(1.0f, 1.0f), glVertex3f(0.0f, 1.0f, 0.0f);
  glTexCoord2f(1.0f, 0.0f), glVertex3f(0.0f, -1.0f, 0.0f);
  glTexCoord2f(0.0f, 0.0f), glVertex3f(1.0f, -1.0f, 0.0f);
  glTexCoord2f(0.0f, 1.0f), glVertex3f(1.0f, 1.0f, 0.0f);
  glTexCoord2f(1.0f, 1.0f), glVertex3f(2.41421f, 1.0f, -1.41421f);
  glTexCoord2f(1.0f, 0.0f), glVertex3f(2.41421f, -1.0f, -1.41421f);
  glEnd();
}

/* floor_*: a long floor receding to the horizon under a 256x256 mipmapped texture repeated 40
 * times, with each minification filter (the Red Book's mipmap.c, in perspective). */
static GLenum floor_filter;
static void floor_init(void) {
  glEnable(GL_DEPTH_TEST);
  make_texture(256, 16, 0, 1, floor_filter, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  projection_perspective(60.0, 0.5, 200.0);
  glTranslatef(0.0f, -1.0f, 0.0f);
}
static void floor_nn_init(void) { floor_filter = GL_NEAREST_MIPMAP_NEAREST, floor_init(); }
static void floor_ln_init(void) { floor_filter = GL_LINEAR_MIPMAP_NEAREST, floor_init(); }
static void floor_nl_init(void) { floor_filter = GL_NEAREST_MIPMAP_LINEAR, floor_init(); }
static void floor_ll_init(void) { floor_filter = GL_LINEAR_MIPMAP_LINEAR, floor_init(); }
static void floor_display(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBegin(GL_QUADS);
  glTexCoord2f(0.0f, 0.0f), glVertex3f(-40.0f, 0.0f, -1.0f);
  glTexCoord2f(40.0f, 0.0f), glVertex3f(40.0f, 0.0f, -1.0f);
  glTexCoord2f(40.0f, 40.0f), glVertex3f(40.0f, 0.0f, -160.0f);
  glTexCoord2f(0.0f, 40.0f), glVertex3f(-40.0f, 0.0f, -160.0f);
  glEnd();
}

/* wrap: four quads filling the screen with coordinates from -1 to 2, GL_REPEAT and GL_CLAMP
 * in each combination (the Red Book's wrap.c), linear filtering, a border colour. */
static GLuint wrap_textures[4];
static void wrap_init(void) {
  projection_ortho();
  GLfloat border[] = {0.2f, 0.6f, 0.9f, 1.0f};
  for (int k = 0; k < 4; ++k) {
    wrap_textures[k] = make_texture(32, 4, 0, 0, GL_LINEAR, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (k & 1) ? GL_CLAMP : GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (k & 2) ? GL_CLAMP : GL_REPEAT);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  }
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
}
static void wrap_display(void) {
  glClear(GL_COLOR_BUFFER_BIT);
  for (int k = 0; k < 4; ++k) {
    glBindTexture(GL_TEXTURE_2D, wrap_textures[k]);
    float x = (k & 1) ? 0.0f : -1.0f, y = (k & 2) ? 0.0f : -1.0f;
    textured_quad(x, y, x + 1.0f, y + 1.0f, 0.0f, -1.0f, -1.0f, 2.0f, 2.0f);
  }
}

/* texenv: the four environment modes side by side on smooth-coloured quads, an RGBA texture
 * with alpha, blended over a background. */
static void texenv_init(void) {
  projection_ortho();
  make_texture(128, 8, 1, 0, GL_LINEAR, GL_LINEAR);
  GLfloat env[] = {0.9f, 0.3f, 0.1f, 0.5f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
}
static void texenv_display(void) {
  static const GLenum modes[4] = {GL_DECAL, GL_MODULATE, GL_BLEND, GL_REPLACE};
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_BLEND);
  glBegin(GL_QUADS);
  glColor3f(0.2f, 0.2f, 0.3f), glVertex2f(-1.0f, -1.0f), glVertex2f(1.0f, -1.0f);
  glColor3f(0.6f, 0.6f, 0.4f), glVertex2f(1.0f, 1.0f), glVertex2f(-1.0f, 1.0f);
  glEnd();
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_BLEND);
  for (int k = 0; k < 4; ++k) {
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)modes[k]);
    float x = -1.0f + 0.5f * k;
    glBegin(GL_QUADS);
    glColor4f(1.0f, 0.2f, 0.2f, 0.8f), glTexCoord2f(0.0f, 0.0f), glVertex2f(x, -1.0f);
    glColor4f(0.2f, 1.0f, 0.2f, 0.8f), glTexCoord2f(2.0f, 0.0f), glVertex2f(x + 0.5f, -1.0f);
    glColor4f(0.2f, 0.2f, 1.0f, 0.6f), glTexCoord2f(2.0f, 4.0f), glVertex2f(x + 0.5f, 1.0f);
    glColor4f(1.0f, 1.0f, 0.2f, 0.9f), glTexCoord2f(0.0f, 4.0f), glVertex2f(x, 1.0f);
    glEnd();
  }
}

/* textures8: an 8 x 8 wall of tiles, each with one of eight texture objects bound in turn. */
static GLuint tile_textures[8];
static void textures8_init(void) {
  projection_ortho();
  for (int k = 0; k < 8; ++k) tile_textures[k] = make_texture(64 << (k & 1), 2 + k, 0, 1, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
}
static void textures8_display(void) {
  glClear(GL_COLOR_BUFFER_BIT);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      glBindTexture(GL_TEXTURE_2D, tile_textures[(i + j) & 7]);
      glColor3f(0.5f + 0.06f * i, 0.5f + 0.06f * j, 0.8f);
      float x = -1.0f + 0.25f * i, y = -1.0f + 0.25f * j;
      textured_quad(x, y, x + 0.25f, y + 0.25f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f);
    }
}

/* teapot_textured: the lit teapot, a mipmapped texture modulating it. */
static void teapot_textured_init(void) {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);
  light_white();
  GLfloat white[] = {1.0f, 1.0f, 1.0f, 1.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, white);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 60.0f);
  make_texture(256, 16, 0, 1, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  projection_perspective(30.0, 1.0, 20.0);
  glTranslatef(0.0f, -0.15f, -5.5f);
  glRotatef(15.0f, 1.0f, 0.0f, 0.0f);
}
static void teapot_display(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glutSolidTeapot(1.0);
}

/* teapot: the lecture's shiny red teapot, untextured. */
static void teapot_init(void) {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);
  light_white();
  GLfloat red[] = {0.41f, 0.135f, 0.067f, 1.0f}, white[] = {1.0f, 1.0f, 1.0f, 1.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 125.0f);
  projection_perspective(30.0, 1.0, 20.0);
  glTranslatef(0.0f, -0.15f, -5.5f);
  glRotatef(15.0f, 1.0f, 0.0f, 0.0f);
}

/* stencil: a disc written into the stencil buffer, then the teapot drawn only inside it and a
 * full-screen layer only outside it (a window / mask effect). */
static void stencil_init(void) {
  teapot_init();
  glClearStencil(0);
}
static void stencil_display(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glDisable(GL_LIGHTING);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glBegin(GL_TRIANGLE_FAN);
  glVertex2f(0.0f, 0.0f);
  for (int k = 0; k <= 64; ++k) glVertex2f(0.6f * (float)cos(k * M_PI / 32) * height / width, 0.6f * (float)sin(k * M_PI / 32));
  glEnd();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glStencilFunc(GL_NOTEQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColor3f(0.3f, 0.5f, 0.7f);
  glRectf(-1.0f, -1.0f, 1.0f, 1.0f);
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_LIGHTING);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glClear(GL_DEPTH_BUFFER_BIT);
  glutSolidTeapot(1.0);
  glDisable(GL_STENCIL_TEST);
}

/* spheres_*: 200 x 400 quads of a sphere lit by two lights, drawn four ways: immediate mode
 * with float calls, with double calls, glDrawElements from arrays, and a display list; and
 * with and without back-face culling. */
static void spheres_init(void) {
  glEnable(GL_DEPTH_TEST);
  GLfloat pos2[] = {-1.0f, 0.5f, 0.5f, 0.0f}, blue[] = {0.3f, 0.4f, 0.9f, 1.0f};
  light_white();
  glLightfv(GL_LIGHT1, GL_POSITION, pos2);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, blue);
  glEnable(GL_LIGHT1);
  sphere_material();
  mesh = sphere_mesh(200);
  projection_perspective(30.0, 1.0, 20.0);
  glTranslatef(0.0f, 0.0f, -4.0f);
}
static void spheres_cull_init(void) {
  spheres_init();
  glEnable(GL_CULL_FACE);
}
static void sphere_immediate_float(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  for (int k = 0; k < mesh.index_count; ++k) {
    const GLfloat* p = &mesh.positions[3 * mesh.indices[k]];
    glNormal3f(p[0], p[1], p[2]);
    glVertex3f(p[0], p[1], p[2]);
  }
  glEnd();
}
static void sphere_immediate_double(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  for (int k = 0; k < mesh.index_count; ++k) {
    const GLfloat* p = &mesh.positions[3 * mesh.indices[k]];
    glNormal3d(p[0], p[1], p[2]);
    glVertex3d(p[0], p[1], p[2]);
  }
  glEnd();
}
static void sphere_arrays(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, mesh.positions);
  glNormalPointer(GL_FLOAT, 0, mesh.positions);
  glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, mesh.indices);
}
static void spheres_list_init(void) {
  spheres_init();
  glNewList(1, GL_COMPILE);
  sphere_immediate_float();
  glEndList();
}
static void sphere_list(void) {
  glCallList(1);  /* its glClear is in the list */
}

/* small: 10,000 triangles of 1 to 4 pixels scattered over the screen, flat colours. */
static GLfloat* small_vertices;
static GLubyte* small_colors;
enum { kSmall = 10000 };
static void small_init(void) {
  projection_ortho();
  glEnable(GL_DEPTH_TEST);
  small_vertices = malloc(sizeof(GLfloat) * 9 * kSmall);
  small_colors = malloc(3 * 3 * kSmall);
  unsigned seed = 12345;
  for (int k = 0; k < kSmall; ++k) {
    seed = seed * 1103515245u + 12345u;
    float x = -1.0f + 2.0f * (float)((seed >> 8) % 10000) / 10000.0f;
    seed = seed * 1103515245u + 12345u;
    float y = -1.0f + 2.0f * (float)((seed >> 8) % 10000) / 10000.0f;
    float sx = 3.0f * 2.0f / width, sy = 3.0f * 2.0f / height, z = (float)(k % 100) / 100.0f;
    GLfloat tri[9] = {x, y, z, x + sx, y, z, x, y + sy, z};
    memcpy(&small_vertices[9 * k], tri, sizeof tri);
    for (int c = 0; c < 9; ++c) small_colors[9 * k + c] = (GLubyte)(seed >> (c * 3));
  }
}
static void small_display(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, small_vertices);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, small_colors);
  glDrawArrays(GL_TRIANGLES, 0, 3 * kSmall);
}

/* blend: five full-screen layers blended over a smooth background (fill-bound). */
static void blend_init(void) {
  projection_ortho();
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
}
static void blend_display(void) {
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_BLEND);
  triangle_display();
  glEnable(GL_BLEND);
  for (int k = 0; k < 5; ++k) {
    glColor4f(0.2f * k, 1.0f - 0.2f * k, 0.5f, 0.2f);
    glRectf(-1.0f, -1.0f, 1.0f, 1.0f);
  }
}

/* wire: the sphere as lines (glPolygonMode GL_LINE), lit, 50 x 100 quads. */
static void wire_init(void) {
  spheres_init();
  free(mesh.positions), free(mesh.indices);
  mesh = sphere_mesh(50);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
}

/* lines: a grid of 400 horizontal and 400 vertical lines, 2 pixels wide, and a stippled
 * diagonal fan (axes and grids, as programs draw them). */
static void lines_init(void) {
  projection_ortho();
  glLineWidth(2.0f);
}
static void lines_display(void) {
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(0.6f, 0.6f, 0.6f);
  glBegin(GL_LINES);
  for (int k = 0; k < 400; ++k) {
    float v = -1.0f + 2.0f * (k + 0.5f) / 400.0f;
    glVertex2f(-1.0f, v), glVertex2f(1.0f, v);
    glVertex2f(v, -1.0f), glVertex2f(v, 1.0f);
  }
  glEnd();
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x0F0F);
  glColor3f(1.0f, 0.8f, 0.2f);
  glBegin(GL_LINES);
  for (int k = 0; k < 100; ++k) {
    double a = 2.0 * M_PI * k / 100.0;
    glVertex2f(0.0f, 0.0f), glVertex2f((float)cos(a), (float)sin(a));
  }
  glEnd();
  glDisable(GL_LINE_STIPPLE);
}

/* points: 100,000 points of size 1 and 10,000 of size 5, smooth-coloured. */
static void points_init(void) { projection_ortho(); }
static void points_display(void) {
  glClear(GL_COLOR_BUFFER_BIT);
  unsigned seed = 777;
  for (int pass = 0; pass < 2; ++pass) {
    int n = pass ? 10000 : 100000;
    glPointSize(pass ? 5.0f : 1.0f);
    glBegin(GL_POINTS);
    for (int k = 0; k < n; ++k) {
      seed = seed * 1103515245u + 12345u;
      float x = -1.0f + 2.0f * (float)((seed >> 8) & 0xffff) / 65536.0f;
      seed = seed * 1103515245u + 12345u;
      float y = -1.0f + 2.0f * (float)((seed >> 8) & 0xffff) / 65536.0f;
      glColor3f(0.5f + 0.5f * x, 0.5f + 0.5f * y, 0.5f);
      glVertex2f(x, y);
    }
    glEnd();
  }
}

/* fog: rows of lit spheres receding into GL_EXP fog (the Red Book's fog.c). */
static void fog_init(void) {
  spheres_init();
  GLfloat fog[] = {0.5f, 0.5f, 0.5f, 1.0f};
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_EXP);
  glFogfv(GL_FOG_COLOR, fog);
  glFogf(GL_FOG_DENSITY, 0.15f);
  glClearColor(0.5f, 0.5f, 0.5f, 1.0f);
  glLoadIdentity();
}
static void fog_display(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (int k = 0; k < 5; ++k) {
    glPushMatrix();
    glTranslatef(-2.0f + k, -0.5f, -3.0f - 3.0f * k);
    glutSolidSphere(0.6, 40, 20);
    glPopMatrix();
  }
}

/* alpha: 200 textured billboards (an RGBA checkerboard, transparent squares cut out by the
 * alpha test), depth-tested, as trees and fences are drawn. */
static void alpha_init(void) {
  glEnable(GL_DEPTH_TEST);
  make_texture(64, 8, 1, 0, GL_NEAREST, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  projection_perspective(50.0, 0.5, 50.0);
}
static void alpha_display(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (int k = 0; k < 200; ++k) {
    float x = -6.0f + (float)(k % 20) * 0.6f, z = -2.0f - (float)(k / 20) * 1.5f;
    textured_quad(x, -1.0f, x + 1.0f, 1.0f, z, 0.0f, 0.0f, 1.0f, 1.0f);
  }
}

typedef struct {
  const char* name;
  void (*init)(void);
  void (*display)(void);
  int stencil;  /* needs a stencil buffer */
} Scene;

/* teapot-readback: the teapot, then the frame read back as RGB bytes each frame, as programs that
 * save or check their frames do (glReadPixels in the display callback). */
static unsigned char* readback;
static void readback_init(void) {
  teapot_init();
  readback = malloc((size_t)width * height * 3);
}
static void readback_display(void) {
  teapot_display();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, readback);
}

/* image: a full-window RGBA image drawn with glDrawPixels each frame (an image viewer, a video
 * player, a software renderer showing its output). */
static GLubyte* image_pixels;
static void image_init(void) {
  projection_ortho();
  image_pixels = malloc((size_t)width * height * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      GLubyte* p = image_pixels + ((size_t)y * width + x) * 4;
      p[0] = (GLubyte)(x * 255 / width), p[1] = (GLubyte)(y * 255 / height), p[2] = (GLubyte)((x ^ y) & 255), p[3] = 255;
    }
}
static void image_display(void) {
  glClear(GL_COLOR_BUFFER_BIT);
  glRasterPos2f(-1.0f, -1.0f);
  glDrawPixels(width, height, GL_RGBA, GL_UNSIGNED_BYTE, image_pixels);
}

static const Scene kScenes[] = {
  {"empty", empty_init, empty_display, 0},
  {"triangle", triangle_init, triangle_display, 0},
  {"teapot", teapot_init, teapot_display, 0},
  {"checker", checker_init, checker_display, 0},
  {"checker-linear", checker_linear_init, checker_display, 0},
  {"floor-nearest-mipmap-nearest", floor_nn_init, floor_display, 0},
  {"floor-linear-mipmap-nearest", floor_ln_init, floor_display, 0},
  {"floor-nearest-mipmap-linear", floor_nl_init, floor_display, 0},
  {"floor-linear-mipmap-linear", floor_ll_init, floor_display, 0},
  {"wrap", wrap_init, wrap_display, 0},
  {"texenv", texenv_init, texenv_display, 0},
  {"textures8", textures8_init, textures8_display, 0},
  {"teapot-textured", teapot_textured_init, teapot_display, 0},
  {"stencil", stencil_init, stencil_display, 1},
  {"sphere-immediate-float", spheres_init, sphere_immediate_float, 0},
  {"sphere-immediate-double", spheres_init, sphere_immediate_double, 0},
  {"sphere-arrays", spheres_init, sphere_arrays, 0},
  {"sphere-arrays-culled", spheres_cull_init, sphere_arrays, 0},
  {"sphere-list", spheres_list_init, sphere_list, 0},
  {"small-triangles", small_init, small_display, 0},
  {"blend-5-layers", blend_init, blend_display, 0},
  {"wire-sphere", wire_init, sphere_arrays, 0},
  {"lines", lines_init, lines_display, 0},
  {"points", points_init, points_display, 0},
  {"fog", fog_init, fog_display, 0},
  {"alpha-test", alpha_init, alpha_display, 0},
  {"teapot-readback", readback_init, readback_display, 0},
  {"image", image_init, image_display, 0},
};
enum { kSceneCount = sizeof kScenes / sizeof kScenes[0] };

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

static int compare_doubles(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

int main(int argc, char** argv) {
  if (argc >= 2 && !strcmp(argv[1], "--list")) {
    for (int k = 0; k < kSceneCount; ++k) printf("%s\n", kScenes[k].name);
    return 0;
  }
  if (argc < 2) {
    fprintf(stderr, "usage: %s SCENE [--size WxH] [--frames F] [--warmup W] [--png FILE] [--no-stencil] | --list\n", argv[0]);
    return 2;
  }
  const Scene* scene = NULL;
  for (int k = 0; k < kSceneCount; ++k)
    if (!strcmp(argv[1], kScenes[k].name)) scene = &kScenes[k];
  if (!scene) {
    fprintf(stderr, "unknown scene %s (--list names them)\n", argv[1]);
    return 2;
  }
  int frames = 10, warmup = 2, stencil = 8;
  const char* png = NULL;
  for (int i = 2; i < argc; ++i) {
    if (!strcmp(argv[i], "--no-stencil")) {
      stencil = 0;
      continue;
    }
    if (i + 1 >= argc) {
      fprintf(stderr, "%s needs a value\n", argv[i]);
      return 2;
    }
    if (!strcmp(argv[i], "--size") && sscanf(argv[i + 1], "%dx%d", &width, &height) == 2) ++i;
    else if (!strcmp(argv[i], "--frames")) frames = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--warmup")) warmup = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--png")) png = argv[++i];
    else {
      fprintf(stderr, "unknown option %s\n", argv[i]);
      return 2;
    }
  }
  if (frames < 1 || width < 1 || height < 1 || (scene->stencil && !stencil)) return 2;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, stencil, 0, NULL);
  unsigned char* buffer = malloc((size_t)width * height * 4);
  if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, width, height)) {
    fprintf(stderr, "no OSMesa context\n");
    return 1;
  }
  glViewport(0, 0, width, height);
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  scene->init();
  double* times = malloc(sizeof(double) * (size_t)frames);
  for (int f = -warmup; f < frames; ++f) {
    double t0 = now_ms();
    scene->display();
    glFinish();
    if (f >= 0) times[f] = now_ms() - t0;
  }
  if (glGetError() != GL_NO_ERROR) fprintf(stderr, "%s: a GL error was raised\n", scene->name);
  qsort(times, (size_t)frames, sizeof(double), compare_doubles);
  double median = frames % 2 ? times[frames / 2] : 0.5 * (times[frames / 2 - 1] + times[frames / 2]);
  printf("RESULT scene=%s size=%dx%d frames=%d median_ms=%.3f min_ms=%.3f max_ms=%.3f\n", scene->name, width,
         height, frames, median, times[0], times[frames - 1]);
  if (png) {
    stbi_flip_vertically_on_write(1);
    if (!stbi_write_png(png, width, height, 4, buffer, width * 4)) return 1;
  }
  OSMesaDestroyContext(ctx);
  free(buffer);
  free(times);
  return 0;
}
