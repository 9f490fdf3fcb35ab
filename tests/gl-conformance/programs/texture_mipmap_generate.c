/* Automatic mipmap generation of OpenGL 1.4 (OpenGL 1.5 section 3.8.8, GL_GENERATE_MIPMAP):
 * levels made from the base level by glTexImage2D, again after glTexSubImage2D,
 * glCopyTexImage2D and glCopyTexSubImage2D change it; a base level of 1 (level 0 left alone)
 * and a maximum level of 2 (no level made past it); non-power-of-two images (12x5); 1D
 * textures; internal formats of fewer and of more than 8 bits a component, luminance-alpha;
 * generation turned off again (a changed base level leaves the others). Each generated level
 * is drawn alone (base level = maximum level = that level, nearest filters) so that its texels
 * show one by one, beside trilinear floors through every level. The generated levels' sizes
 * and internal formats and a sample of their texels (glGetTexImage) are recorded with
 * conf_value. */
#include <math.h>
#include <stdio.h>

#include "conf.h"

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 6, 6);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* The whole level, shifted a little so that no texel edge falls on a pixel centre (a 32-texel
 * level over 48 pixels would have some there, where a float's rounding picks the texel). */
static void quad(void) {
  glBegin(GL_QUADS);
  glTexCoord2f(0.004f, 0.006f);
  glVertex2f(-1, -1);
  glTexCoord2f(1.004f, 0.006f);
  glVertex2f(1, -1);
  glTexCoord2f(1.004f, 1.006f);
  glVertex2f(1, 1);
  glTexCoord2f(0.004f, 1.006f);
  glVertex2f(-1, 1);
  glEnd();
}

/* Level `level` of the bound 2D texture alone, nearest, filling cell (col, row). */
static void show_level(const ConfContext* c, int level, int col, int row) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, level);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, level);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  cell(c, col, row);
  quad();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
}

static void floor_cell(const ConfContext* c, int col, int row) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  conf_panel(c, col, row, 6, 6);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, -0.7f, 0.0f);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex3f(-2, 0, -1.1f);
  glTexCoord2f(3, 0);
  glVertex3f(2, 0, -1.1f);
  glTexCoord2f(3, 18);
  glVertex3f(2, 0, -35);
  glTexCoord2f(0, 18);
  glVertex3f(-2, 0, -35);
  glEnd();
}

/* A w x h RGBA image: smooth gradients, a sharp diagonal, odd values everywhere (so that the
 * rounding of every average shows). */
static void pattern(unsigned char* img, int w, int h, int seed) {
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      unsigned char* p = &img[(y * w + x) * 4];
      p[0] = (unsigned char)((x * 37 + y * 11 + seed * 13) % 256);
      p[1] = (unsigned char)(127 + 120 * sin(0.7 * x + 0.3 * seed) * cos(0.5 * y));
      p[2] = (unsigned char)(x > y ? 230 - 3 * x : 25 + 5 * y);
      p[3] = (unsigned char)(255 - ((x ^ y) * 7 + seed) % 120);
    }
}

static void record_levels(ConfContext* c, GLenum target, const char* what, int first, int last) {
  static unsigned char back[32 * 32 * 4];
  char key[96];
  for (int l = first; l <= last; ++l) {
    GLint w = -1, h = -1, f = -1;
    glGetTexLevelParameteriv(target, l, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(target, l, GL_TEXTURE_HEIGHT, &h);
    glGetTexLevelParameteriv(target, l, GL_TEXTURE_INTERNAL_FORMAT, &f);
    snprintf(key, sizeof key, "%s level %d width height format", what, l);
    conf_values(c, key, (double[]){w, h, f}, 3);
    if (w <= 0 || h <= 0 || w * h > 32 * 32) continue;
    glGetTexImage(target, l, GL_RGBA, GL_UNSIGNED_BYTE, back);
    for (int i = 0; i < w * h; i += 1 + w * h / 6) {
      snprintf(key, sizeof key, "%s level %d texel %d", what, l, i);
      conf_values(c, key, (double[]){back[i * 4], back[i * 4 + 1], back[i * 4 + 2], back[i * 4 + 3]}, 4);
    }
  }
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 288, 288)) return 1;
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  static unsigned char img[32 * 32 * 4];

  /* Row 0: a 32x32 RGBA image's generated levels 1 to 4, and a trilinear floor. */
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  GLint generate = -1;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, &generate);
  conf_value(&c, "generate default", generate);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, &generate);
  conf_value(&c, "generate on", generate);
  pattern(img, 32, 32, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  conf_error(&c, "TexImage2D with generation");
  record_levels(&c, GL_TEXTURE_2D, "rgba", 1, 6);
  for (int l = 1; l <= 4; ++l) show_level(&c, l, l - 1, 0);
  floor_cell(&c, 4, 0);

  /* glTexSubImage2D on the base level: levels made again (levels 1 and 2 shown). A
   * sub-image of another level changes that level only (level 3 shown). */
  static unsigned char block[12 * 12 * 4];
  for (int i = 0; i < 12 * 12; ++i) block[i * 4] = 250, block[i * 4 + 1] = 250, block[i * 4 + 2] = 20, block[i * 4 + 3] = 255;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 5, 9, 12, 12, GL_RGBA, GL_UNSIGNED_BYTE, block);
  glTexSubImage2D(GL_TEXTURE_2D, 3, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, block);
  record_levels(&c, GL_TEXTURE_2D, "after sub-image", 1, 3);
  show_level(&c, 1, 5, 0);
  show_level(&c, 2, 0, 1);
  show_level(&c, 3, 1, 1);

  /* A 12x5 RGB image (levels 6x2, 3x1, 1x1), an RGBA4 image, a luminance-alpha image and an
   * RGBA16 image (more than 8 bits a component), level 2 of each, and level 1 of the first. */
  GLuint npot;
  glGenTextures(1, &npot);
  glBindTexture(GL_TEXTURE_2D, npot);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  pattern(img, 12, 5, 2);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 12, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  record_levels(&c, GL_TEXTURE_2D, "12x5", 1, 4);
  show_level(&c, 1, 2, 1);
  show_level(&c, 2, 3, 1);
  const GLint formats[3] = {GL_RGBA4, GL_LUMINANCE8_ALPHA8, GL_RGBA16};
  GLuint formatted[3];
  glGenTextures(3, formatted);
  for (int i = 0; i < 3; ++i) {
    glBindTexture(GL_TEXTURE_2D, formatted[i]);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    pattern(img, 16, 16, 3 + i);
    glTexImage2D(GL_TEXTURE_2D, 0, formats[i], 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    char what[32];
    snprintf(what, sizeof what, "format %d", i);
    record_levels(&c, GL_TEXTURE_2D, what, 1, 2);
    show_level(&c, 2, 4 + i % 2, 1 + i / 2);
  }

  /* Row 2: copies from the framebuffer into the base level (glCopyTexImage2D of row 0's
   * cells, then glCopyTexSubImage2D over a part; cells of nearest texels, whose pixels are the
   * same in both libraries), levels 1 and 2 of each. */
  glFinish();
  GLuint copied;
  glGenTextures(1, &copied);
  glBindTexture(GL_TEXTURE_2D, copied);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 10, 250, 32, 32, 0);
  record_levels(&c, GL_TEXTURE_2D, "copy", 1, 2);
  show_level(&c, 1, 0, 2);
  show_level(&c, 2, 1, 2);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 8, 8, 60, 250, 16, 16); /* level 2's texels, exact */
  record_levels(&c, GL_TEXTURE_2D, "copy sub-image", 1, 2);
  show_level(&c, 1, 2, 2);
  show_level(&c, 2, 3, 2);

  /* Row 3: base level 1 (level 0 keeps its own image; levels 2 on made from level 1), a
   * maximum level of 2 (levels 3 on are not made), generation turned off (a new base image
   * leaves the old levels), a 1D texture. */
  GLuint based;
  glGenTextures(1, &based);
  glBindTexture(GL_TEXTURE_2D, based);
  pattern(img, 32, 32, 6);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  pattern(img, 16, 16, 7);
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  record_levels(&c, GL_TEXTURE_2D, "base 1", 0, 5);
  show_level(&c, 0, 4, 2);
  show_level(&c, 2, 5, 2);

  GLuint capped;
  glGenTextures(1, &capped);
  glBindTexture(GL_TEXTURE_2D, capped);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 2);
  pattern(img, 16, 16, 8);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  record_levels(&c, GL_TEXTURE_2D, "max level 2", 1, 4);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_FALSE);
  pattern(img, 16, 16, 9);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  record_levels(&c, GL_TEXTURE_2D, "generation off", 1, 2);
  show_level(&c, 2, 0, 3);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 2);
  floor_cell(&c, 1, 3);

  GLuint one_d;
  glGenTextures(1, &one_d);
  glBindTexture(GL_TEXTURE_1D, one_d);
  glTexParameteri(GL_TEXTURE_1D, GL_GENERATE_MIPMAP, GL_TRUE);
  pattern(img, 32, 1, 10);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  record_levels(&c, GL_TEXTURE_1D, "1D", 1, 5);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_BASE_LEVEL, 2);
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_1D);
  cell(&c, 2, 3);
  quad();
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  conf_panel(&c, 3, 3, 6, 6);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(-80.0f, 0, 1, 0);
  glBegin(GL_QUADS);
  glTexCoord1f(0);
  glVertex3f(-1, -1, -2);
  glTexCoord1f(20);
  glVertex3f(-1, -1, -30);
  glTexCoord1f(20);
  glVertex3f(-1, 1, -30);
  glTexCoord1f(0);
  glVertex3f(-1, 1, -2);
  glEnd();
  glDisable(GL_TEXTURE_1D);
  glEnable(GL_TEXTURE_2D);

  /* Row 4: the trilinear floors of the 12x5 image and the RGBA16 one. */
  glBindTexture(GL_TEXTURE_2D, npot);
  floor_cell(&c, 0, 4);
  glBindTexture(GL_TEXTURE_2D, formatted[2]);
  floor_cell(&c, 1, 4);
  glBindTexture(GL_TEXTURE_2D, formatted[0]);
  floor_cell(&c, 2, 4);
  conf_error(&c, "end");

  GLuint names[6] = {tex, npot, copied, based, capped, one_d};
  glDeleteTextures(6, names);
  glDeleteTextures(3, formatted);
  return conf_finish(&c);
}
