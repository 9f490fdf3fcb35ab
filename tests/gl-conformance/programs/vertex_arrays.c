/* Vertex arrays: glDrawArrays on an interleaved array (position, normal, RGBA unsigned-byte
 * colour, with a stride) under lighting and colour material; glDrawElements with
 * GL_UNSIGNED_INT and GL_UNSIGNED_SHORT indices on separate float arrays (a shared-vertex
 * sphere in three draws: 32-bit indices from vertex 0, which shadelab reads in place, 32-bit
 * indices from further on, 16-bit indices); glDrawElements
 * with GL_UNSIGNED_BYTE (GL_QUADS) and GL_UNSIGNED_INT (GL_TRIANGLE_FAN) indices and RGB float
 * colours; glArrayElement between glBegin/glEnd with a texture-coordinate array. */
#include <math.h>
#include <string.h>

#include "conf.h"

typedef struct Vertex {
  GLfloat pos[3];
  GLfloat normal[3];
  GLubyte colour[4];
} Vertex;

enum { kSlices = 24, kStacks = 12 };
static Vertex tri_soup[kSlices * kStacks * 6];
static GLfloat grid_pos[(kSlices + 1) * (kStacks + 1)][3];
static GLfloat grid_nrm[(kSlices + 1) * (kStacks + 1)][3];
static GLushort grid_idx[kSlices * kStacks * 6];
static GLuint grid_idx32[kSlices * kStacks * 6];

static void unit_point(int i, int j, GLfloat out[3]) {
  double t = 2.0 * CONF_PI * i / kSlices, p = CONF_PI * j / kStacks;
  out[0] = (GLfloat)(sin(p) * sin(t));
  out[1] = (GLfloat)cos(p);
  out[2] = (GLfloat)(sin(p) * cos(t));
}

static void build(void) {
  int n = 0, m = 0;
  const int di[6] = {0, 0, 1, 0, 1, 1}, dj[6] = {0, 1, 1, 0, 1, 0};
  for (int j = 0; j < kStacks; ++j)
    for (int i = 0; i < kSlices; ++i)
      for (int k = 0; k < 6; ++k) {
        Vertex* v = &tri_soup[n++];
        unit_point(i + di[k], j + dj[k], v->normal);
        memcpy(v->pos, v->normal, sizeof v->pos);
        v->colour[0] = (GLubyte)(40 + 200 * (i % 2));
        v->colour[1] = (GLubyte)(60 + 12 * j);
        v->colour[2] = (GLubyte)(250 - 9 * i);
        v->colour[3] = 255;
        grid_idx32[m] = (GLuint)((j + dj[k]) * (kSlices + 1) + i + di[k]), grid_idx[m] = (GLushort)grid_idx32[m], ++m;
      }
  for (int j = 0; j <= kStacks; ++j)
    for (int i = 0; i <= kSlices; ++i) {
      unit_point(i, j, grid_nrm[j * (kSlices + 1) + i]);
      memcpy(grid_pos[j * (kSlices + 1) + i], grid_nrm[j * (kSlices + 1) + i], 3 * sizeof(GLfloat));
    }
}

static void panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 2, 2);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.2, 1.2, -1.2, 1.2, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void flat_shapes(void) {
  /* The quad is a parallelogram with affine colours, so that any split of it looks the same. */
  static const GLfloat pos[9][2] = {{-1.0f, 0.1f}, {-0.1f, 0.15f}, {-0.15f, 1.0f}, {-1.05f, 0.95f},
                                    {0.55f, 0.5f}, {0.95f, 0.45f}, {0.8f, 0.95f}, {0.3f, 0.92f},
                                    {0.15f, 0.3f}};
  static const GLfloat col[9][3] = {{1, 0.2f, 0}, {0.2f, 1, 0}, {0.2f, 1, 1}, {1, 0.2f, 1}, {1, 1, 1},
                                    {1, 0, 1}, {0, 1, 1}, {1, 0.5f, 0}, {0.5f, 0, 1}};
  static const GLubyte quad_idx[4] = {0, 1, 2, 3};
  static const GLuint fan_idx[5] = {4, 8, 5, 6, 7};
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glColorPointer(3, GL_FLOAT, 0, col);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, quad_idx);
  glDrawElements(GL_TRIANGLE_FAN, 5, GL_UNSIGNED_INT, fan_idx);
  glDisableClientState(GL_COLOR_ARRAY);
}

static GLuint checker_texture(void) {
  static GLubyte texels[8 * 8 * 4];
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      GLubyte* t = &texels[(y * 8 + x) * 4];
      int on = (x + y) % 2;
      t[0] = on ? 250 : 30, t[1] = on ? 220 : 60, t[2] = on ? 40 : 200, t[3] = 255;
    }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return tex;
}

static void array_element_strip(void) {
  static const GLfloat pos[8][2] = {{-1.0f, -1.0f}, {-1.0f, -0.2f}, {-0.35f, -0.95f},
                                    {-0.3f, -0.25f}, {0.35f, -1.0f}, {0.3f, -0.2f},
                                    {1.0f, -0.9f},   {0.95f, -0.1f}};
  static const GLfloat uv[8][2] = {{0, 0}, {0, 1}, {0.33f, 0}, {0.33f, 1},
                                   {0.66f, 0}, {0.66f, 1}, {1, 0}, {1, 1}};
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glTexCoordPointer(2, GL_FLOAT, 0, uv);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glEnable(GL_TEXTURE_2D);
  glColor3f(1, 1, 1);
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 8; ++i) glArrayElement(i);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  build();
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const GLfloat dir[] = {-0.4f, 0.5f, 1.0f, 0.0f}, spec[] = {0.5f, 0.5f, 0.5f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glEnable(GL_LIGHT0);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 16.0f);

  panel(&c, 0, 0); /* interleaved, glDrawArrays, colour material */
  glEnable(GL_LIGHTING);
  glEnable(GL_COLOR_MATERIAL);
  glVertexPointer(3, GL_FLOAT, sizeof(Vertex), tri_soup[0].pos);
  glNormalPointer(GL_FLOAT, sizeof(Vertex), tri_soup[0].normal);
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), tri_soup[0].colour);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glRotatef(20.0f, 1, 0, 0);
  glDrawArrays(GL_TRIANGLES, 0, kSlices * kStacks * 6);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisable(GL_COLOR_MATERIAL);

  panel(&c, 1, 0); /* separate arrays, glDrawElements GL_UNSIGNED_SHORT */
  const GLfloat dif[] = {0.9f, 0.4f, 0.2f, 1};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
  glVertexPointer(3, GL_FLOAT, 0, grid_pos);
  glNormalPointer(GL_FLOAT, 0, grid_nrm);
  glRotatef(-30.0f, 0, 0, 1);
  glScalef(1.0f, 0.7f, 1.0f);
  glEnable(GL_NORMALIZE);
  /* In three draws: GLuint indices from vertex 0, GLuint indices from further on, GLushort. */
  const int third = kSlices * kStacks * 2;
  glDrawElements(GL_TRIANGLES, third, GL_UNSIGNED_INT, grid_idx32);
  glDrawElements(GL_TRIANGLES, third, GL_UNSIGNED_INT, grid_idx32 + third);
  glDrawElements(GL_TRIANGLES, third, GL_UNSIGNED_SHORT, grid_idx + 2 * third);
  glDisable(GL_NORMALIZE);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisable(GL_LIGHTING);

  panel(&c, 0, 1); /* glDrawElements GL_UNSIGNED_BYTE quads and GL_UNSIGNED_INT fan, unlit */
  glDisable(GL_DEPTH_TEST);
  GLuint tex = checker_texture();
  flat_shapes();
  array_element_strip(); /* the bottom half: glArrayElement, textured */

  panel(&c, 1, 1); /* glArrayElement again, then glDrawArrays on a textured, repeated quad */
  array_element_strip();
  glScalef(1.0f, -1.0f, 1.0f);
  /* A parallelogram: texture coordinates are affine over it whichever way it is split. */
  static const GLfloat quad[4][2] = {{-0.9f, -0.95f}, {0.9f, -0.9f}, {0.85f, -0.1f}, {-0.95f, -0.15f}};
  static const GLfloat quad_uv[4][2] = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  glVertexPointer(2, GL_FLOAT, 0, quad);
  glTexCoordPointer(2, GL_FLOAT, 0, quad_uv);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glEnable(GL_TEXTURE_2D);
  glDrawArrays(GL_QUADS, 0, 4);
  glDeleteTextures(1, &tex);
  return conf_finish(&c);
}
