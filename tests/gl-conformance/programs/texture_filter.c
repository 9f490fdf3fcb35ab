/* Texture images and filters: glTexImage2D with a full mipmap chain (16x16 down to 1x1, RGB
 * rows padded to the default GL_UNPACK_ALIGNMENT of 4, each level a different colour so that
 * the chosen level shows); magnification GL_NEAREST and GL_LINEAR; GL_REPEAT; GL_CLAMP (which
 * with GL_LINEAR blends in the border colour outside [0, 1]); all six minification filters on a
 * frontal quad at a fixed level of detail (lambda = 1.3: level 1 for *_MIPMAP_NEAREST; 1.5:
 * levels 1 and 2 half and half for *_MIPMAP_LINEAR); a receding floor (perspective-correct
 * texture coordinates) with GL_LINEAR_MIPMAP_LINEAR on a smooth texture with box-filtered
 * levels; and a mipmap filter on a texture with only level 0,
 * which is incomplete, so texturing is as if disabled (OpenGL 1.1 section 3.8.9). */
#include <math.h>

#include "conf.h"

static const unsigned char kLevelColour[5][3] = {
    {220, 40, 40}, {40, 200, 60}, {50, 80, 230}, {230, 220, 40}, {220, 60, 220}};

/* Level `level` of the coloured chain: a checker of (2 >> level)-texel blocks (1 at least). */
static void coloured_level(int level, int size) {
  static unsigned char data[16 * 16 * 4];
  int stride = (size * 3 + 3) / 4 * 4, block = level == 0 ? 2 : 1;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      unsigned char* t = &data[y * stride + x * 3];
      int on = ((x / block) + (y / block)) % 2;
      for (int k = 0; k < 3; ++k) t[k] = on ? kLevelColour[level][k] : 235;
    }
  glTexImage2D(GL_TEXTURE_2D, level, GL_RGB, size, size, 0, GL_RGB, GL_UNSIGNED_BYTE, data);
}

static GLuint coloured_chain(void) {
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  for (int level = 0, size = 16; size >= 1; ++level, size /= 2) coloured_level(level, size);
  return tex;
}

/* A smooth 32x32 RGBA pattern (low contrast between levels, so that small differences in the
 * level of detail stay small) with box-filtered levels down to 1x1 (internal format 4, GL 1.0
 * style). */
static GLuint natural_chain(void) {
  static unsigned char levels[6][32 * 32 * 4];
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      unsigned char* t = &levels[0][(y * 32 + x) * 4];
      double a = 2.0 * CONF_PI * x / 16.0, b = 2.0 * CONF_PI * y / 32.0;
      t[0] = (unsigned char)(150 + 45 * sin(a));
      t[1] = (unsigned char)(120 + 45 * cos(b));
      t[2] = (unsigned char)(110 + 30 * sin(a + b));
      t[3] = 255;
    }
  for (int l = 1, size = 16; size >= 1; ++l, size /= 2)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        for (int k = 0; k < 4; ++k) {
          const unsigned char* p = levels[l - 1];
          int s = size * 2, sum = p[((2 * y) * s + 2 * x) * 4 + k] + p[((2 * y) * s + 2 * x + 1) * 4 + k] +
                          p[((2 * y + 1) * s + 2 * x) * 4 + k] + p[((2 * y + 1) * s + 2 * x + 1) * 4 + k];
          levels[l][(y * size + x) * 4 + k] = (unsigned char)((sum + 2) / 4);
        }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  for (int l = 0, size = 32; size >= 1; ++l, size /= 2)
    glTexImage2D(GL_TEXTURE_2D, l, 4, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, levels[l]);
  return tex;
}

static void quad(float s0, float t0, float s1, float t1) {
  glBegin(GL_QUADS);
  glTexCoord2f(s0, t0);
  glVertex2f(-1, -1);
  glTexCoord2f(s1, t0);
  glVertex2f(1, -1);
  glTexCoord2f(s1, t1);
  glVertex2f(1, 1);
  glTexCoord2f(s0, t1);
  glVertex2f(-1, 1);
  glEnd();
}

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void filters(GLenum min, GLenum mag) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag);
}

static void wrap(GLenum s, GLenum t) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, s);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, t);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 255)) return 1;
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_TEXTURE_2D);
  glColor3f(1, 1, 1);
  GLuint chain = coloured_chain();

  /* Top row: magnification (about 4 pixels per texel; the quad is rotated a little so that
   * texel edges do not fall on pixel centres), GL_REPEAT, GL_CLAMP. */
  cell(&c, 0, 0);
  glRotatef(3.0f, 0, 0, 1);
  filters(GL_NEAREST, GL_NEAREST);
  quad(0.1f, 0.1f, 0.9f, 0.9f);
  cell(&c, 1, 0);
  glRotatef(3.0f, 0, 0, 1);
  filters(GL_NEAREST, GL_LINEAR);
  quad(0.1f, 0.1f, 0.9f, 0.9f);
  cell(&c, 2, 0);
  filters(GL_LINEAR, GL_LINEAR);
  wrap(GL_REPEAT, GL_REPEAT);
  quad(-1.03f, -0.98f, 1.97f, 2.02f);
  cell(&c, 3, 0);
  wrap(GL_CLAMP, GL_CLAMP);
  quad(-0.52f, -0.47f, 1.48f, 1.53f);
  wrap(GL_REPEAT, GL_REPEAT);

  /* Middle row and the first two of the bottom row: minification on a frontal quad. A 64-pixel
   * cell shows 64 * 2^lambda / 16 texture repeats across (85 pixels: the same density upward).
   * Non-mipmapped and *_MIPMAP_NEAREST filters at lambda = 1.3 (level 1, far from the rounding
   * point at 1.5); *_MIPMAP_LINEAR at lambda = 1.5 (levels 1 and 2, half and half): llvmpipe's
   * level of detail is a piecewise-linear log2 that is exact at whole and half levels only (at
   * 1.3 it weighs level 2 by 0.26, not 0.3), and softpipe's is exact, so these are the levels
   * where both agree. */
  static const GLenum mins[6] = {GL_NEAREST,
                                 GL_LINEAR,
                                 GL_NEAREST_MIPMAP_NEAREST,
                                 GL_LINEAR_MIPMAP_NEAREST,
                                 GL_NEAREST_MIPMAP_LINEAR,
                                 GL_LINEAR_MIPMAP_LINEAR};
  for (int i = 0; i < 6; ++i) {
    float density = i < 4 ? 2.4622888f : 2.8284271f; /* 2^1.3, 2^1.5 */
    float reps_s = 64.0f * density / 16.0f, reps_t = 85.0f * density / 16.0f;
    cell(&c, i % 4, 1 + i / 4);
    filters(mins[i], GL_LINEAR);
    quad(0.013f, 0.021f, 0.013f + reps_s, 0.021f + reps_t);
  }

  /* A floor from near to far, trilinear, on box-filtered levels. */
  GLuint natural = natural_chain();
  filters(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  conf_panel(&c, 2, 2, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.4, 0.4, -0.5, 0.5, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, -1.0f, 0.0f);
  glRotatef(5.0f, 0, 1, 0);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex3f(-3, 0, -1);
  glTexCoord2f(6, 0);
  glVertex3f(3, 0, -1);
  glTexCoord2f(6, 30);
  glVertex3f(3, 0, -31);
  glTexCoord2f(0, 30);
  glVertex3f(-3, 0, -31);
  glEnd();

  /* Only level 0 given, a mipmap filter: incomplete, the quad keeps its plain colour. */
  GLuint lonely;
  glGenTextures(1, &lonely);
  glBindTexture(GL_TEXTURE_2D, lonely);
  coloured_level(0, 16);
  filters(GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR);
  cell(&c, 3, 2);
  glColor3f(0.4f, 0.7f, 0.9f);
  quad(0.0f, 0.0f, 1.0f, 1.0f);

  glDeleteTextures(1, &chain);
  glDeleteTextures(1, &natural);
  glDeleteTextures(1, &lonely);
  return conf_finish(&c);
}
