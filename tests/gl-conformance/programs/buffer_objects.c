/* GL 1.5's buffer objects (section 2.9): every array kind drawn from buffers (vertex, normal,
 * colour, texture coordinates, edge flags with polygon lines, the index array), interleaved
 * arrays in a buffer, indices from GL_ELEMENT_ARRAY_BUFFER for glDrawElements,
 * glDrawRangeElements and glMultiDrawElements, glArrayElement, glMultiDrawArrays, buffers
 * updated by glBufferSubData and through glMapBuffer between draws, display lists (which read
 * the buffers at compile time), the client attribute stack, a buffer shared with a second
 * context, deleting bound buffers; then the queries (bindings per array, buffer parameters,
 * pointers) and the errors, compared value by value with Mesa's. */
#define GL_GLEXT_PROTOTYPES
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "conf.h"

typedef struct Vertex {
  GLfloat pos[3];
  GLfloat normal[3];
  GLubyte color[4];
  GLfloat tex[2];
} Vertex;

enum { kSlices = 16, kStacks = 8, kGrid = (kSlices + 1) * (kStacks + 1), kIndices = kSlices * kStacks * 6 };
static Vertex verts[kGrid];
static GLushort indices16[kIndices];
static GLuint indices32[kIndices];

static void build(void) {
  for (int j = 0; j <= kStacks; ++j)
    for (int i = 0; i <= kSlices; ++i) {
      Vertex* v = &verts[j * (kSlices + 1) + i];
      const double t = 2.0 * CONF_PI * i / kSlices, p = CONF_PI * j / kStacks;
      v->normal[0] = (GLfloat)(sin(p) * sin(t)), v->normal[1] = (GLfloat)cos(p), v->normal[2] = (GLfloat)(sin(p) * cos(t));
      memcpy(v->pos, v->normal, sizeof v->pos);
      v->color[0] = (GLubyte)(40 + 200 * (i % 2)), v->color[1] = (GLubyte)(60 + 20 * j), v->color[2] = (GLubyte)(250 - 12 * i);
      v->color[3] = 255;
      v->tex[0] = (GLfloat)i / kSlices * 2.0f, v->tex[1] = (GLfloat)j / kStacks;
    }
  const int di[6] = {0, 0, 1, 0, 1, 1}, dj[6] = {0, 1, 1, 0, 1, 0};
  int m = 0;
  for (int j = 0; j < kStacks; ++j)
    for (int i = 0; i < kSlices; ++i)
      for (int k = 0; k < 6; ++k) indices32[m] = (GLuint)((j + dj[k]) * (kSlices + 1) + i + di[k]), indices16[m] = (GLushort)indices32[m], ++m;
}

static void panel(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.2, 1.2, -1.2, 1.2, -5.0, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
}

#define OFFSET(field) ((const GLvoid*)offsetof(Vertex, field))

/* Every array from the vertex buffer, at offsets, with the stride of the struct. */
static void bind_arrays(GLuint vbo) {
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glVertexPointer(3, GL_FLOAT, sizeof(Vertex), OFFSET(pos));
  glNormalPointer(GL_FLOAT, sizeof(Vertex), OFFSET(normal));
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), OFFSET(color));
  glTexCoordPointer(2, GL_FLOAT, sizeof(Vertex), OFFSET(tex));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

static void enable_arrays(int on) {
  const GLenum arrays[4] = {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_TEXTURE_COORD_ARRAY};
  for (int k = 0; k < 4; ++k) on ? glEnableClientState(arrays[k]) : glDisableClientState(arrays[k]);
}

static void lit(int on) {
  const GLfloat light[4] = {0.3f, 0.5f, 1.0f, 0.0f};
  if (!on) {
    glDisable(GL_LIGHTING), glDisable(GL_COLOR_MATERIAL), glDisable(GL_DEPTH_TEST);
    return;
  }
  glEnable(GL_LIGHTING), glEnable(GL_LIGHT0), glEnable(GL_COLOR_MATERIAL), glEnable(GL_DEPTH_TEST);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
}

static void record_state(ConfContext* c, const char* when) {
  static const GLenum names[] = {GL_ARRAY_BUFFER_BINDING, GL_ELEMENT_ARRAY_BUFFER_BINDING,
                                 GL_VERTEX_ARRAY_BUFFER_BINDING, GL_NORMAL_ARRAY_BUFFER_BINDING,
                                 GL_COLOR_ARRAY_BUFFER_BINDING, GL_INDEX_ARRAY_BUFFER_BINDING,
                                 GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, GL_EDGE_FLAG_ARRAY_BUFFER_BINDING};
  char label[160];
  for (unsigned k = 0; k < sizeof names / sizeof names[0]; ++k) {
    GLint i = -1;
    GLfloat f = -1;
    GLboolean b = 7;
    glGetIntegerv(names[k], &i);
    glGetFloatv(names[k], &f);
    glGetBooleanv(names[k], &b);
    snprintf(label, sizeof label, "%s binding 0x%x", when, names[k]);
    const double v[3] = {i, f, b};
    conf_values(c, label, v, 3);
  }
  GLvoid* p = (GLvoid*)1;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  snprintf(label, sizeof label, "%s vertex pointer", when);
  conf_value(c, label, (double)(size_t)p);
  glGetPointerv(GL_COLOR_ARRAY_POINTER, &p);
  snprintf(label, sizeof label, "%s color pointer", when);
  conf_value(c, label, (double)(size_t)p);
  snprintf(label, sizeof label, "%s error", when);
  conf_error(c, label);
}

static void record_buffer(ConfContext* c, GLenum target, const char* when) {
  static const GLenum pnames[] = {GL_BUFFER_SIZE, GL_BUFFER_USAGE, GL_BUFFER_ACCESS, GL_BUFFER_MAPPED};
  char label[160];
  for (int k = 0; k < 4; ++k) {
    GLint v = -1;
    glGetBufferParameteriv(target, pnames[k], &v);
    snprintf(label, sizeof label, "%s parameter 0x%x", when, pnames[k]);
    conf_value(c, label, v);
    conf_error(c, label);
  }
  GLvoid* p = (GLvoid*)1;
  glGetBufferPointerv(target, GL_BUFFER_MAP_POINTER, &p);
  snprintf(label, sizeof label, "%s map pointer null", when);
  conf_value(c, label, p == NULL);
  conf_error(c, label);
}

static void errors(ConfContext* c, GLuint vbo, GLuint ibo) {
  unsigned char bytes[64];
  GLuint names[3] = {0, 0, 0};
  glGenBuffers(-1, names), conf_error(c, "GenBuffers -1");
  glDeleteBuffers(-1, names), conf_error(c, "DeleteBuffers -1");
  glBindBuffer(GL_TEXTURE_2D, vbo), conf_error(c, "BindBuffer target");
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBufferData(GL_ARRAY_BUFFER, 16, NULL, GL_STATIC_DRAW), conf_error(c, "BufferData no buffer");
  glBufferSubData(GL_ARRAY_BUFFER, 0, 4, bytes), conf_error(c, "BufferSubData no buffer");
  (void)glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY), conf_error(c, "MapBuffer no buffer");
  (void)glUnmapBuffer(GL_ARRAY_BUFFER), conf_error(c, "UnmapBuffer no buffer");
  GLint v;
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v), conf_error(c, "GetBufferParameteriv no buffer");
  GLvoid* p;
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &p), conf_error(c, "GetBufferPointerv no buffer");
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, bytes), conf_error(c, "GetBufferSubData no buffer");
  glBufferData(GL_TEXTURE_2D, 16, NULL, GL_STATIC_DRAW), conf_error(c, "BufferData target");
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, -1, NULL, GL_STATIC_DRAW), conf_error(c, "BufferData size -1");
  glBufferData(GL_ARRAY_BUFFER, 16, NULL, GL_RGBA), conf_error(c, "BufferData usage");
  glBufferData(GL_ARRAY_BUFFER, -1, NULL, GL_RGBA), conf_error(c, "BufferData size usage");
  glBufferSubData(GL_ARRAY_BUFFER, -1, 4, bytes), conf_error(c, "BufferSubData offset -1");
  glBufferSubData(GL_ARRAY_BUFFER, 0, -4, bytes), conf_error(c, "BufferSubData size -4");
  glBufferSubData(GL_ARRAY_BUFFER, sizeof verts - 2, 4, bytes), conf_error(c, "BufferSubData past the end");
  glBufferSubData(GL_ARRAY_BUFFER, sizeof verts, 0, bytes), conf_error(c, "BufferSubData empty at the end");
  glGetBufferSubData(GL_ARRAY_BUFFER, sizeof verts - 2, 4, bytes), conf_error(c, "GetBufferSubData past the end");
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_TEXTURE_2D, &v), conf_error(c, "GetBufferParameteriv pname");
  glGetBufferParameteriv(GL_TEXTURE_2D, GL_BUFFER_SIZE, &v), conf_error(c, "GetBufferParameteriv target");
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &p), conf_error(c, "GetBufferPointerv pname");
  (void)glMapBuffer(GL_ARRAY_BUFFER, GL_RGBA), conf_error(c, "MapBuffer access");
  (void)glMapBuffer(GL_TEXTURE_2D, GL_READ_ONLY), conf_error(c, "MapBuffer target");
  (void)glUnmapBuffer(GL_ARRAY_BUFFER), conf_error(c, "UnmapBuffer not mapped");
  conf_value(c, "MapBuffer pointer", glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY) != NULL);
  conf_error(c, "MapBuffer");
  record_buffer(c, GL_ARRAY_BUFFER, "mapped read only");
  (void)glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY), conf_error(c, "MapBuffer mapped");
  glBufferSubData(GL_ARRAY_BUFFER, 0, 4, bytes), conf_error(c, "BufferSubData mapped");
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, bytes), conf_error(c, "GetBufferSubData mapped");
  bind_arrays(vbo);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 3), conf_error(c, "DrawArrays mapped");
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, indices16), conf_error(c, "DrawElements mapped");
  glDisableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 3), conf_error(c, "DrawArrays mapped but disabled");
  conf_value(c, "UnmapBuffer", glUnmapBuffer(GL_ARRAY_BUFFER));
  conf_error(c, "UnmapBuffer");
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  (void)glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_WRITE_ONLY);
  record_buffer(c, GL_ELEMENT_ARRAY_BUFFER, "element mapped write only");
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, 0), conf_error(c, "DrawElements index buffer mapped");
  glDrawArrays(GL_TRIANGLES, 0, 3), conf_error(c, "DrawArrays index buffer mapped");
  glDisableClientState(GL_VERTEX_ARRAY);
  glBegin(GL_POINTS);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glEnd();
  conf_error(c, "BindBuffer in glBegin");
  (void)glUnmapBuffer(GL_ELEMENT_ARRAY_BUFFER);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  /* A zero-sized buffer mapped. */
  glGenBuffers(1, names);
  glBindBuffer(GL_ARRAY_BUFFER, names[0]);
  (void)glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE), conf_error(c, "MapBuffer of an empty buffer");
  record_buffer(c, GL_ARRAY_BUFFER, "empty buffer");
  glDeleteBuffers(1, names);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  conf_error(c, "errors done");
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 512, 384)) return 1;
  build();
  GLuint bufs[4] = {0, 0, 0, 0};
  conf_value(&c, "IsBuffer 0 before", glIsBuffer(0));
  glGenBuffers(4, bufs);
  const GLuint vbo = bufs[0], ibo = bufs[1], vbo2 = bufs[2], ibo2 = bufs[3];
  conf_values(&c, "GenBuffers", (const double[]){bufs[0], bufs[1], bufs[2], bufs[3]}, 4);
  conf_value(&c, "IsBuffer generated", glIsBuffer(vbo));
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  conf_value(&c, "IsBuffer bound", glIsBuffer(vbo));
  record_buffer(&c, GL_ARRAY_BUFFER, "new buffer");
  glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
  record_buffer(&c, GL_ARRAY_BUFFER, "vbo");
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof indices16, indices16, GL_DYNAMIC_DRAW);
  record_buffer(&c, GL_ELEMENT_ARRAY_BUFFER, "ibo");
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  record_state(&c, "initial");

  glClearColor(0.08f, 0.08f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  /* 0: glDrawElements with client indices, arrays from the buffer, lit. */
  panel(&c, 0, 0), lit(1);
  bind_arrays(vbo);
  record_state(&c, "arrays bound");
  enable_arrays(1);
  glDrawElements(GL_TRIANGLES, kIndices, GL_UNSIGNED_INT, indices32);
  lit(0);
  conf_check_error("panel 0");

  /* 1: indices from the element buffer, three ways. */
  panel(&c, 1, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glDrawElements(GL_TRIANGLES, kIndices / 3, GL_UNSIGNED_SHORT, (const GLvoid*)0);
  glDrawRangeElements(GL_TRIANGLES, 0, kGrid - 1, kIndices / 3, GL_UNSIGNED_SHORT,
                      (const GLvoid*)(kIndices / 3 * sizeof(GLushort)));
  {
    const GLsizei counts[2] = {kIndices / 6, kIndices / 6};
    const GLvoid* offsets[2] = {(const GLvoid*)(2 * kIndices / 3 * sizeof(GLushort)),
                                (const GLvoid*)(5 * kIndices / 6 * sizeof(GLushort))};
    glMultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_SHORT, offsets, 2);
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  conf_check_error("panel 1");

  /* 2: glDrawArrays / glMultiDrawArrays of strips, glArrayElement, from the buffer. */
  panel(&c, 2, 0);
  glDisableClientState(GL_NORMAL_ARRAY);
  {
    const GLint first[3] = {0, (kSlices + 1) * 3, (kSlices + 1) * 6};
    const GLsizei count[3] = {kSlices + 1, kSlices + 1, kSlices + 1};
    glPointSize(3.0f);
    glMultiDrawArrays(GL_POINTS, first, count, 3);
    glDrawArrays(GL_LINE_STRIP, (kSlices + 1) * 4, kSlices + 1);
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i <= kSlices; ++i) glArrayElement((kSlices + 1) * 2 + i), glArrayElement((kSlices + 1) * 3 + i);
    glEnd();
    glPointSize(1.0f);
  }
  glEnableClientState(GL_NORMAL_ARRAY);
  conf_check_error("panel 2");

  /* 3: textured from the buffer's texture coordinates, the vertices rewritten by
   * glBufferSubData (squashed), then through glMapBuffer (shifted). */
  panel(&c, 3, 0);
  {
    GLubyte texels[4][4][4];
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x)
        texels[y][x][0] = (GLubyte)(255 * ((x + y) % 2)), texels[y][x][1] = 200, texels[y][x][2] = (GLubyte)(60 * y), texels[y][x][3] = 255;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glEnable(GL_TEXTURE_2D);
    Vertex squashed[kGrid];
    memcpy(squashed, verts, sizeof verts);
    for (int k = 0; k < kGrid; ++k) squashed[k].pos[1] *= 0.5f, squashed[k].pos[0] *= 0.5f;
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof squashed, squashed);
    glTranslatef(-0.5f, 0.4f, 0.0f);
    glDrawElements(GL_TRIANGLES, kIndices, GL_UNSIGNED_SHORT, indices16);
    Vertex* mapped = (Vertex*)glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
    if (mapped)
      for (int k = 0; k < kGrid; ++k) mapped[k].pos[0] += 1.0f, mapped[k].pos[1] -= 0.8f;
    glUnmapBuffer(GL_ARRAY_BUFFER);
    glDrawElements(GL_TRIANGLES, kIndices, GL_UNSIGNED_SHORT, indices16);
    glDisable(GL_TEXTURE_2D);
    glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STREAM_DRAW);  /* back to the sphere */
    glBindBuffer(GL_ARRAY_BUFFER, 0);
  }
  conf_check_error("panel 3");

  /* 4: glInterleavedArrays in a buffer (GL_C4UB_V3F and GL_T2F_N3F_V3F at an offset). */
  panel(&c, 0, 1);
  enable_arrays(0);
  {
    struct { GLubyte c[4]; GLfloat v[3]; } cv[kGrid];
    struct { GLfloat t[2]; GLfloat n[3]; GLfloat v[3]; } tnv[kGrid];
    for (int k = 0; k < kGrid; ++k) {
      memcpy(cv[k].c, verts[k].color, 4);
      cv[k].v[0] = verts[k].pos[0] * 0.5f - 0.5f, cv[k].v[1] = verts[k].pos[1] * 0.5f + 0.5f, cv[k].v[2] = verts[k].pos[2] * 0.5f;
      memcpy(tnv[k].t, verts[k].tex, sizeof tnv[k].t);
      memcpy(tnv[k].n, verts[k].normal, sizeof tnv[k].n);
      tnv[k].v[0] = verts[k].pos[0] * 0.5f + 0.5f, tnv[k].v[1] = verts[k].pos[1] * 0.5f - 0.5f, tnv[k].v[2] = verts[k].pos[2] * 0.5f;
    }
    glBindBuffer(GL_ARRAY_BUFFER, vbo2);
    glBufferData(GL_ARRAY_BUFFER, 64 + sizeof cv + sizeof tnv, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof cv, cv);
    glBufferSubData(GL_ARRAY_BUFFER, 64 + sizeof cv, sizeof tnv, tnv);
    glInterleavedArrays(GL_C4UB_V3F, 0, (const GLvoid*)0);
    glDrawElements(GL_TRIANGLES, kIndices, GL_UNSIGNED_INT, indices32);
    record_state(&c, "interleaved C4UB_V3F");
    glInterleavedArrays(GL_T2F_N3F_V3F, 0, (const GLvoid*)(64 + sizeof cv));
    lit(1);
    glColor3f(0.9f, 0.6f, 0.3f);
    glDrawElements(GL_TRIANGLES, kIndices, GL_UNSIGNED_INT, indices32);
    lit(0);
    record_state(&c, "interleaved T2F_N3F_V3F");
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glInterleavedArrays(GL_V3F, 0, verts);  /* client memory again */
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  }
  conf_check_error("panel 4");

  /* 5: edge flags and the index array from a buffer, polygons drawn as lines. */
  panel(&c, 1, 1);
  {
    static const GLfloat quad_pos[8][2] = {{-1, -1}, {0, -1}, {0, 0}, {-1, 0}, {0.1f, 0.1f}, {1, 0.1f}, {1, 1}, {0.1f, 1}};
    static const GLboolean flags[8] = {1, 0, 1, 0, 0, 1, 1, 1};
    static const GLfloat index_values[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    glBindBuffer(GL_ARRAY_BUFFER, vbo2);
    glBufferData(GL_ARRAY_BUFFER, sizeof quad_pos + sizeof flags + sizeof index_values, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof quad_pos, quad_pos);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof quad_pos, sizeof index_values, index_values);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof quad_pos + sizeof index_values, sizeof flags, flags);
    glVertexPointer(2, GL_FLOAT, 0, (const GLvoid*)0);
    glIndexPointer(GL_FLOAT, 0, (const GLvoid*)sizeof quad_pos);
    glEdgeFlagPointer(0, (const GLvoid*)(sizeof quad_pos + sizeof index_values));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    record_state(&c, "edge flags and indices");
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glEnableClientState(GL_INDEX_ARRAY);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(1.0f, 1.0f, 0.3f);
    glLineWidth(2.0f);
    glDrawArrays(GL_TRIANGLES, 0, 3);  /* (edge flags of fans and strips: not compared) */
    glDrawArrays(GL_POLYGON, 4, 4);
    glLineWidth(1.0f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    GLfloat index = -1;
    glArrayElement(5);
    glDisableClientState(GL_INDEX_ARRAY);
    glGetFloatv(GL_CURRENT_INDEX, &index);
    conf_value(&c, "current index after glArrayElement", index);
  }
  conf_check_error("panel 5");

  /* 6: a display list compiled from the buffers; the buffers change before it runs. */
  panel(&c, 2, 1);
  GLuint list = glGenLists(1);
  {
    bind_arrays(vbo);
    enable_arrays(1);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
    glNewList(list, GL_COMPILE);
    lit(1);
    glDrawElements(GL_TRIANGLES, kIndices / 2, GL_UNSIGNED_SHORT, (const GLvoid*)0);
    glDrawRangeElements(GL_TRIANGLES, 0, kGrid - 1, kIndices / 2, GL_UNSIGNED_SHORT, (const GLvoid*)(kIndices / 2 * sizeof(GLushort)));
    lit(0);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i <= kSlices; ++i) glArrayElement((kSlices + 1) * 4 + i);
    glEnd();
    glEndList();
    Vertex moved[kGrid];
    memcpy(moved, verts, sizeof verts);
    for (int k = 0; k < kGrid; ++k) moved[k].pos[0] = moved[k].pos[0] * 0.2f + 0.8f;
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof moved, moved);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    GLushort reversed[kIndices];
    for (int k = 0; k < kIndices; ++k) reversed[k] = indices16[kIndices - 1 - k];
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, sizeof reversed / 4, reversed);
    glCallList(list);
    glDrawElements(GL_LINES, kIndices / 4, GL_UNSIGNED_SHORT, (const GLvoid*)0);  /* the changed data */
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof verts, verts);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
  }
  conf_check_error("panel 6");

  /* 7: the client attribute stack saves the bindings. */
  panel(&c, 3, 1);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glBindBuffer(GL_ARRAY_BUFFER, vbo2);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glVertexPointer(2, GL_FLOAT, 0, (const GLvoid*)0);
  record_state(&c, "pushed and changed");
  glPopClientAttrib();
  record_state(&c, "popped");
  lit(1);
  glDrawElements(GL_TRIANGLES, kIndices, GL_UNSIGNED_INT, indices32);
  lit(0);
  conf_check_error("panel 7");

  /* 8: a second context sharing the first's lists and buffers draws from the same buffer. */
  {
    static unsigned char other[64 * 64 * 4];
    OSMesaContext shared = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, c.ctx);
    OSMesaMakeCurrent(shared, other, GL_UNSIGNED_BYTE, 64, 64);
    conf_value(&c, "shared IsBuffer", glIsBuffer(vbo));
    GLint binding = -1;
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &binding);
    conf_value(&c, "shared context binding", binding);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    GLint size = -1;
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
    conf_value(&c, "shared buffer size", size);
    GLfloat first[3] = {0, 0, 0};
    glGetBufferSubData(GL_ARRAY_BUFFER, sizeof(Vertex), sizeof first, first);
    conf_values(&c, "shared buffer data", (const double[]){first[0], first[1], first[2]}, 3);
    /* A buffer made here, deleted in the first context below. */
    glBindBuffer(GL_ARRAY_BUFFER, ibo2);
    glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
    glFinish();
    OSMesaMakeCurrent(c.ctx, c.buffer, GL_UNSIGNED_BYTE, c.width, c.height);
    conf_value(&c, "IsBuffer made in the shared context", glIsBuffer(ibo2));
    OSMesaDestroyContext(shared);
    conf_value(&c, "IsBuffer after the shared context went", glIsBuffer(ibo2));
  }
  panel(&c, 0, 2);
  bind_arrays(ibo2);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDrawElements(GL_TRIANGLES, kIndices, GL_UNSIGNED_SHORT, indices16);
  conf_check_error("panel 8");

  /* 9: deleting bound buffers unbinds them. */
  panel(&c, 1, 2);
  glBindBuffer(GL_ARRAY_BUFFER, ibo2);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  record_state(&c, "before delete");
  glDeleteBuffers(1, &ibo2);
  record_state(&c, "after deleting the array buffer");
  conf_value(&c, "IsBuffer deleted", glIsBuffer(ibo2));
  glDeleteBuffers(1, &ibo);
  record_state(&c, "after deleting the element buffer");
  bind_arrays(vbo);
  glDrawArrays(GL_TRIANGLE_STRIP, (kSlices + 1) * 3, 2 * (kSlices + 1));
  GLuint again[2] = {0, 0};
  glGenBuffers(2, again);
  conf_values(&c, "GenBuffers after delete", (const double[]){again[0], again[1]}, 2);
  enable_arrays(0);
  conf_check_error("panel 9");

  panel(&c, 2, 2);
  errors(&c, vbo, vbo2);
  return conf_finish(&c);
}
