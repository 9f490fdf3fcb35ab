/* Cube map textures of OpenGL 1.3 (OpenGL 1.5 sections 2.10.4, 3.8.1, 3.8.6, 3.8.10, 3.8.15):
 * six faces given by glTexImage2D, glTexSubImage2D, glCopyTexImage2D and glCopyTexSubImage2D of
 * the face targets, sampled by direction (the major axis picks the face) from glTexCoord3f,
 * from GL_NORMAL_MAP and GL_REFLECTION_MAP texture generation on spheres (lit and unlit, under
 * a texture matrix), nearest and linear, every wrap mode on the faces, mipmaps given and
 * generated (GL_GENERATE_MIPMAP) on receding planes, the cube map over 2D and an incomplete
 * cube map (a missing face, faces of two sizes) giving way, face images in a display list, the
 * binding and enable through glPushAttrib. GL_CLAMP on the faces draws as GL_CLAMP_TO_EDGE
 * (llvmpipe samples every cube map so, as Direct3D does). Values: GL_MAX_CUBE_MAP_TEXTURE_SIZE, bindings, enables, each
 * face's level parameters, proxies, texels read back by glGetTexImage of faces, the texture
 * generation modes and the errors of wrong targets, non-square faces and modes. */
#include <stdio.h>
#include <string.h>

#include "conf.h"

static const GLenum kFaces[6] = {GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_CUBE_MAP_NEGATIVE_X,
                                 GL_TEXTURE_CUBE_MAP_POSITIVE_Y, GL_TEXTURE_CUBE_MAP_NEGATIVE_Y,
                                 GL_TEXTURE_CUBE_MAP_POSITIVE_Z, GL_TEXTURE_CUBE_MAP_NEGATIVE_Z};

/* A face of n x n texels: its own base colour, a gradient along s and t and a darker checker,
 * a bright texel at (0, 0) so that the orientation shows. */
static void face_image(unsigned char* p, int n, int face, int level) {
  static const unsigned char base[6][3] = {{230, 60, 50}, {60, 200, 70}, {60, 90, 230},
                                           {220, 210, 60}, {210, 70, 210}, {60, 210, 210}};
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      unsigned char* t = &p[(y * n + x) * 4];
      const int dark = ((x / 2 + y / 2) % 2) ? 50 : 0;
      for (int k = 0; k < 3; ++k) {
        int v = base[face][k] - dark + (k == 0 ? 40 * x / n : k == 1 ? 40 * y / n : 0) - 30 * level;
        t[k] = (unsigned char)(v < 0 ? 0 : v > 255 ? 255 : v);
      }
      t[3] = (unsigned char)(200 + 55 * ((x + y) % 2));
      if (x == 0 && y == 0) t[0] = t[1] = t[2] = 255;
    }
}

static void load_cube(int n, int levels) {
  static unsigned char img[64 * 64 * 4];
  for (int f = 0; f < 6; ++f)
    for (int l = 0; l < levels; ++l) {
      const int size = n >> l > 0 ? n >> l : 1;
      face_image(img, size, f, l);
      glTexImage2D(kFaces[f], l, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    }
}

static void filter(GLenum min, GLenum mag) {
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, (GLint)min);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, (GLint)mag);
}

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 4);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void texgen(GLenum mode, int on) {
  const GLenum coords[3] = {GL_S, GL_T, GL_R};
  const GLenum caps[3] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R};
  for (int i = 0; i < 3; ++i) {
    glTexGeni(coords[i], GL_TEXTURE_GEN_MODE, (GLint)mode);
    if (on) glEnable(caps[i]);
    else glDisable(caps[i]);
  }
}

/* A quad whose corners point in the directions d[0..3] (glTexCoord3f), filling the cell. */
static void direction_quad(const float d[4][3]) {
  const float v[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) {
    glTexCoord3f(d[i][0], d[i][1], d[i][2]);
    glVertex2f(v[i][0], v[i][1]);
  }
  glEnd();
}

static void record_face(ConfContext* c, GLenum target, int level, const char* what) {
  static const GLenum pnames[] = {GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_BORDER, GL_TEXTURE_INTERNAL_FORMAT,
                                  GL_TEXTURE_RED_SIZE, GL_TEXTURE_ALPHA_SIZE};
  double v[6];
  for (int i = 0; i < 6; ++i) {
    GLint n = -1;
    glGetTexLevelParameteriv(target, level, pnames[i], &n);
    v[i] = n;
  }
  char key[96];
  snprintf(key, sizeof key, "%s 0x%x level %d width height border format red alpha", what, target, level);
  conf_values(c, key, v, 6);
}

static void perspective(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 4);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* A floor receding from the viewer whose texture coordinates are directions (x, 1, z) over it:
 * the +Y face seen ever smaller. */
static void receding_floor(float spread) {
  glBegin(GL_QUADS);
  glTexCoord3f(-spread, 1.0f, 0.3f);
  glVertex3f(-1.5f, -0.5f, -1.1f);
  glTexCoord3f(spread, 1.0f, 0.3f);
  glVertex3f(1.5f, -0.5f, -1.1f);
  glTexCoord3f(spread, 1.0f, -spread * 3.0f);
  glVertex3f(1.5f, -0.5f, -30.0f);
  glTexCoord3f(-spread, 1.0f, -spread * 3.0f);
  glVertex3f(-1.5f, -0.5f, -30.0f);
  glEnd();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 384, 384)) return 1;
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  GLint n = -1;
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &n);
  conf_value(&c, "max cube map texture size", n);
  conf_value(&c, "enabled at first", glIsEnabled(GL_TEXTURE_CUBE_MAP));

  GLuint cube;
  glGenTextures(1, &cube);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &n);
  conf_value(&c, "binding", n == (GLint)cube);
  load_cube(8, 1);
  conf_error(&c, "six faces");
  for (int f = 0; f < 6; ++f) record_face(&c, kFaces[f], 0, "face");
  filter(GL_NEAREST, GL_NEAREST);
  glEnable(GL_TEXTURE_CUBE_MAP);
  conf_value(&c, "enabled", glIsEnabled(GL_TEXTURE_CUBE_MAP));

  /* Row 0: the six faces seen through direction quads (nearest): +Z straight on, a quad
   * sweeping over the edge between +X and +Z, one around the -Y corner; linear on the same. */
  static const float front[4][3] = {{-0.9f, -0.9f, 1}, {0.9f, -0.9f, 1}, {0.9f, 0.9f, 1}, {-0.9f, 0.9f, 1}};
  static const float across[4][3] = {{0.3f, -0.7f, 1}, {1, -0.7f, -0.6f}, {1, 0.8f, -0.6f}, {0.3f, 0.8f, 1}};
  static const float corner[4][3] = {{-1, -1, -1}, {1, -1, -0.7f}, {0.8f, -0.9f, 1}, {-1, -0.8f, 1}};
  cell(&c, 0, 0);
  direction_quad(front);
  cell(&c, 1, 0);
  direction_quad(across);
  cell(&c, 2, 0);
  direction_quad(corner);
  filter(GL_LINEAR, GL_LINEAR);
  cell(&c, 3, 0);
  direction_quad(across);

  /* Row 1: normal-map and reflection-map generation on spheres (nearest, then linear), the
   * reflection map under a rotating texture matrix, and on a lit sphere modulated. */
  filter(GL_NEAREST, GL_NEAREST);
  texgen(GL_NORMAL_MAP, 1);
  cell(&c, 0, 1);
  glRotatef(30.0f, 1, 1, 0);
  conf_sphere(0.9f, 28, 20);
  texgen(GL_REFLECTION_MAP, 1);
  filter(GL_LINEAR, GL_LINEAR);
  cell(&c, 1, 1);
  glRotatef(-20.0f, 0, 1, 0);
  conf_sphere(0.9f, 28, 20);
  glMatrixMode(GL_TEXTURE);
  glRotatef(70.0f, 0, 1, 0);
  glMatrixMode(GL_MODELVIEW);
  cell(&c, 2, 1);
  conf_sphere(0.9f, 28, 20);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  const GLfloat light[4] = {0.4f, 0.7f, 1.0f, 0.0f};
  cell(&c, 3, 1);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glScalef(1.0f, 0.8f, 1.0f);
  conf_sphere(0.9f, 28, 20);
  glDisable(GL_LIGHTING);
  glDisable(GL_NORMALIZE);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  texgen(GL_REFLECTION_MAP, 0);
  GLint modes[3];
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &modes[0]);
  glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, &modes[1]);
  glGetTexGeniv(GL_R, GL_TEXTURE_GEN_MODE, &modes[2]);
  conf_value(&c, "texgen mode s", modes[0]);
  conf_value(&c, "texgen mode r", modes[2]);

  /* Row 2: wrap modes on a 4x4 face magnified linearly (directions reaching past the face's
   * edges only by the face coordinates, so every lookup stays on +Z); mipmaps given, then
   * generated, on receding floors. */
  GLuint small;
  glGenTextures(1, &small);
  glBindTexture(GL_TEXTURE_CUBE_MAP, small);
  load_cube(4, 1);
  filter(GL_LINEAR, GL_LINEAR);
  const GLfloat border[4] = {1.0f, 1.0f, 0.2f, 1.0f};
  glTexParameterfv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BORDER_COLOR, border);
  const GLenum wraps[2] = {GL_CLAMP, GL_CLAMP_TO_EDGE};
  static const float zoom[4][3] = {{-0.97f, -0.97f, 1}, {0.97f, -0.97f, 1}, {0.97f, 0.97f, 1}, {-0.97f, 0.97f, 1}};
  for (int i = 0; i < 2; ++i) {
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, (GLint)wraps[i]);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, (GLint)wraps[1 - i]);
    cell(&c, i, 2);
    direction_quad(zoom);
  }
  GLuint mip;
  glGenTextures(1, &mip);
  glBindTexture(GL_TEXTURE_CUBE_MAP, mip);
  load_cube(32, 6);
  filter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  perspective(&c, 2, 2);
  receding_floor(1.0f);
  GLuint gen;
  glGenTextures(1, &gen);
  glBindTexture(GL_TEXTURE_CUBE_MAP, gen);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_GENERATE_MIPMAP, GL_TRUE);
  load_cube(32, 1);
  for (int l = 1; l <= 5; ++l) record_face(&c, GL_TEXTURE_CUBE_MAP_POSITIVE_Y, l, "generated");
  filter(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
  perspective(&c, 3, 2);
  receding_floor(0.8f);

  /* Row 3: a cube map over 2D; one face missing then faces of two sizes (incomplete: the 2D
   * texture instead); faces copied from the framebuffer and a sub-image, in a display list;
   * glPushAttrib / glPopAttrib of the enable and binding. */
  GLuint flat;
  glGenTextures(1, &flat);
  glBindTexture(GL_TEXTURE_2D, flat);
  static unsigned char img[64 * 64 * 4];
  face_image(img, 8, 3, 2);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  static const float half[4][3] = {{-0.9f, -0.9f, 1}, {0.9f, -0.9f, 1}, {0.9f, 0.9f, 1}, {-0.9f, 0.9f, 1}};
  cell(&c, 0, 3);
  glBegin(GL_QUADS); /* left half: cube map (s, t, r); the 2D texture reads (s, t) */
  glTexCoord3f(half[0][0], half[0][1], 1);
  glVertex2f(-1, -1);
  glTexCoord3f(0, -0.9f, 1);
  glVertex2f(0, -1);
  glTexCoord3f(0, 0.9f, 1);
  glVertex2f(0, 1);
  glTexCoord3f(half[3][0], half[3][1], 1);
  glVertex2f(-1, 1);
  glEnd();
  GLuint partial;
  glGenTextures(1, &partial);
  glBindTexture(GL_TEXTURE_CUBE_MAP, partial);
  for (int f = 0; f < 5; ++f) {
    face_image(img, 8, f, 0);
    glTexImage2D(kFaces[f], 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  }
  filter(GL_NEAREST, GL_NEAREST);
  glBegin(GL_QUADS); /* right half: five faces only, the 2D texture */
  glTexCoord3f(0.05f, 0.05f, 1);
  glVertex2f(0, -1);
  glTexCoord3f(0.95f, 0.05f, 1);
  glVertex2f(1, -1);
  glTexCoord3f(0.95f, 0.95f, 1);
  glVertex2f(1, 0);
  glTexCoord3f(0.05f, 0.95f, 1);
  glVertex2f(0, 0);
  glEnd();
  face_image(img, 4, 5, 0);
  glTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glBegin(GL_QUADS); /* six faces, one of another size: still the 2D texture */
  glTexCoord3f(0.05f, 0.05f, 1);
  glVertex2f(0, 0);
  glTexCoord3f(0.95f, 0.05f, 1);
  glVertex2f(1, 0);
  glTexCoord3f(0.95f, 0.95f, 1);
  glVertex2f(1, 1);
  glTexCoord3f(0.05f, 0.95f, 1);
  glVertex2f(0, 1);
  glEnd();
  glDisable(GL_TEXTURE_2D);

  /* Faces copied from what row 0 drew, one through a list. */
  glFinish();
  GLuint copied;
  glGenTextures(1, &copied);
  glBindTexture(GL_TEXTURE_CUBE_MAP, copied);
  for (int f = 0; f < 6; ++f) glCopyTexImage2D(kFaces[f], 0, GL_RGB, 10 + 20 * f, 300, 16, 16, 0);
  conf_error(&c, "CopyTexImage2D faces");
  face_image(img, 8, 0, 1);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Z, 0, 4, 4, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glCopyTexSubImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_X, 0, 0, 0, 200, 330, 8, 8);
  glEndList();
  memset(img, 0, sizeof img);
  glCallList(list);
  conf_error(&c, "list of face images");
  filter(GL_NEAREST, GL_NEAREST);
  cell(&c, 1, 3);
  direction_quad(front);
  cell(&c, 2, 3);
  static const float back[4][3] = {{-1, -0.9f, 0.9f}, {-1, -0.9f, -0.9f}, {-1, 0.9f, -0.9f}, {-1, 0.9f, 0.9f}};
  direction_quad(back);
  unsigned char read[16 * 16 * 4];
  glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_Z, 0, GL_RGBA, GL_UNSIGNED_BYTE, read);
  double sum = 0;
  for (int i = 0; i < 16 * 16 * 4; ++i) sum += read[i] * (1 + i % 7);
  conf_value(&c, "+Z texels read back", sum);
  glGetTexImage(GL_TEXTURE_CUBE_MAP_NEGATIVE_X, 0, GL_RGB, GL_UNSIGNED_BYTE, read);
  sum = 0;
  for (int i = 0; i < 16 * 16 * 3; ++i) sum += read[i] * (1 + i % 5);
  conf_value(&c, "-X texels read back", sum);
  record_face(&c, GL_TEXTURE_CUBE_MAP_NEGATIVE_X, 0, "copied");

  glPushAttrib(GL_ENABLE_BIT | GL_TEXTURE_BIT);
  glDisable(GL_TEXTURE_CUBE_MAP);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  glPopAttrib();
  conf_value(&c, "enable after pop", glIsEnabled(GL_TEXTURE_CUBE_MAP));
  glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &n);
  conf_value(&c, "binding after pop", n == (GLint)copied);
  cell(&c, 3, 3);
  texgen(GL_NORMAL_MAP, 1);
  glRotatef(200.0f, 0.2f, 1, 0);
  conf_sphere(0.8f, 20, 14);
  /* The coordinates generated at a raster position (normal map: the current normal). Not
   * drawn: Mesa 22 textures a glDrawPixels with the coordinates of its own image rather than
   * the raster position's. */
  glNormal3f(0.3f, 0.0f, 1.0f);
  glLoadIdentity();
  glRasterPos2f(0.55f, 0.55f);
  GLfloat raster[4];
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, raster);
  conf_values(&c, "raster texture coordinates from texgen", (double[]){raster[0], raster[1], raster[2], raster[3]}, 4);
  texgen(GL_NORMAL_MAP, 0);

  /* Proxies and errors. */
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_error(&c, "proxy square");
  record_face(&c, GL_PROXY_TEXTURE_CUBE_MAP, 0, "proxy");
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 64, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_error(&c, "proxy not square");
  record_face(&c, GL_PROXY_TEXTURE_CUBE_MAP, 0, "proxy");
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 1, GL_RGBA, 8192, 8192, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  record_face(&c, GL_PROXY_TEXTURE_CUBE_MAP, 1, "proxy large");
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 16, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  conf_error(&c, "face not square");
  glTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  conf_error(&c, "TexImage2D cube map target");
  glTexImage1D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  conf_error(&c, "TexImage1D face");
  glTexSubImage2D(GL_TEXTURE_CUBE_MAP, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
  conf_error(&c, "TexSubImage2D cube map target");
  glCopyTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, GL_RGBA, 0, 0, 16, 8, 0);
  conf_error(&c, "CopyTexImage2D not square");
  glCopyTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 0, 0, 16, 16, 0);
  conf_error(&c, "CopyTexImage2D cube map target");
  glGetTexImage(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, GL_UNSIGNED_BYTE, read);
  conf_error(&c, "GetTexImage cube map target");
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &n);
  conf_error(&c, "GetTexLevelParameteriv cube map target");
  glTexParameteri(GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  conf_error(&c, "TexParameteri face");
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  conf_error(&c, "TexParameteri wrap r");
  glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, &n);
  conf_value(&c, "wrap r", n);
  glBindTexture(GL_TEXTURE_2D, copied);
  conf_error(&c, "BindTexture cube map as 2D");
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  conf_error(&c, "TexGen q normal map");
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  conf_error(&c, "TexGen q reflection map");
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  conf_error(&c, "TexGen r sphere map");
  glTexGenf(GL_T, GL_TEXTURE_GEN_MODE, (GLfloat)GL_REFLECTION_MAP);
  conf_error(&c, "TexGenf t reflection map");
  glCopyTexSubImage3D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, 0, 0, 0, 0, 0, 1, 1);
  conf_error(&c, "CopyTexSubImage3D face");
  glDeleteTextures(1, &copied);
  glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &n);
  conf_value(&c, "binding after delete", n);
  return conf_finish(&c);
}
