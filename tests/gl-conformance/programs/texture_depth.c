/* Depth textures and shadow comparison of OpenGL 1.4 (ARB_depth_texture, ARB_shadow,
 * EXT_shadow_funcs; OpenGL 1.5 sections 3.8.1, 3.8.4, 3.8.14): GL_DEPTH_COMPONENT images from
 * client floats and unsigned shorts and copied from the depth buffer, drawn as luminance,
 * intensity and alpha (GL_DEPTH_TEXTURE_MODE), nearest and linear; GL_COMPARE_R_TO_TEXTURE
 * with each of the eight functions over quads whose r crosses the texels' depths, nearest and
 * linear (the comparison per texel, then filtered), r outside [0, 1]; a shadow map: a scene's
 * depth from the light copied into a texture and projected back by eye-linear generation and
 * the texture matrix. Values: the depth sizes and formats of every depth internal format,
 * texels read back as floats, the parameters' defaults and queries, and the errors. */
#include <stdio.h>
#include <string.h>

#include "conf.h"

static void cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 4);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* A quad over the cell: s, t from 0 to 1 (slightly inside), r from r0 (left) to r1 (right). */
static void quad_r(float r0, float r1) {
  glBegin(GL_QUADS);
  glTexCoord3f(0.02f, 0.03f, r0);
  glVertex2f(-1, -1);
  glTexCoord3f(0.98f, 0.03f, r1);
  glVertex2f(1, -1);
  glTexCoord3f(0.98f, 0.97f, r1);
  glVertex2f(1, 1);
  glTexCoord3f(0.02f, 0.97f, r0);
  glVertex2f(-1, 1);
  glEnd();
}

static void filter(GLenum f) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)f);
}

static void record_level(ConfContext* c, const char* what) {
  static const GLenum pnames[] = {GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_INTERNAL_FORMAT,
                                  GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_RED_SIZE};
  double v[6];
  for (int i = 0; i < 6; ++i) {
    GLint n = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, pnames[i], &n);
    v[i] = n;
  }
  char key[96];
  snprintf(key, sizeof key, "%s width height format depth luminance red", what);
  conf_values(c, key, v, 6);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 256)) return 1;
  glClearColor(0.15f, 0.1f, 0.3f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

  /* An 8 x 8 depth image: a ramp along s, a step along t, and a few spikes. */
  static float depth[8 * 8];
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) depth[y * 8 + x] = 0.1f + 0.1f * (float)x + (y >= 4 ? 0.05f : 0.0f);
  depth[2 * 8 + 5] = 1.0f;
  depth[6 * 8 + 1] = 0.0f;

  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  GLint n = -1;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, &n);
  conf_value(&c, "default depth texture mode", n);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, &n);
  conf_value(&c, "default compare mode", n);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, &n);
  conf_value(&c, "default compare func", n);
  const GLenum formats[4] = {GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32};
  for (int i = 0; i < 4; ++i) {
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)formats[i], 8, 8, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    conf_error(&c, "TexImage2D depth");
    char what[32];
    snprintf(what, sizeof what, "format 0x%x", formats[i]);
    record_level(&c, what);
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 8, 8, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  float back[64];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
  conf_values(&c, "texels read back", (double[]){back[0], back[13], back[21], back[49], back[63]}, 5);
  glEnable(GL_TEXTURE_2D);
  glColor4f(1.0f, 0.9f, 0.8f, 1.0f);

  /* Row 0: luminance nearest and linear, intensity blended, alpha blended. */
  filter(GL_NEAREST);
  cell(&c, 0, 0);
  quad_r(0, 0);
  filter(GL_LINEAR);
  cell(&c, 1, 0);
  quad_r(0, 0);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
  cell(&c, 2, 0);
  quad_r(0, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, &n);
  conf_value(&c, "depth texture mode", n);
  cell(&c, 3, 0);
  quad_r(0, 0);
  glDisable(GL_BLEND);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);

  /* Rows 1 and 2: comparison with each function, r from 0 to 1 across the cell; nearest in
   * row 1, linear (percentage closer) in row 2. */
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  const GLenum funcs[8] = {GL_LEQUAL, GL_GEQUAL, GL_LESS, GL_GREATER, GL_EQUAL, GL_NOTEQUAL, GL_NEVER, GL_ALWAYS};
  for (int i = 0; i < 8; ++i) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, (GLint)funcs[i]);
    conf_error(&c, "compare func");
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, &n);
    conf_value(&c, "compare func", n);
    filter(i < 4 ? GL_NEAREST : GL_LINEAR);
    cell(&c, i % 4, 1 + i / 4);
    glScalef(1.0f, i < 6 ? 1.0f : 0.5f, 1.0f);
    quad_r(0.0f, 1.0f);
  }
  /* Linear PCF for LEQUAL and GEQUAL in the lower halves of the last two cells, over r
   * outside [0, 1]. */
  filter(GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  cell(&c, 2, 2);
  glTranslatef(0.0f, -0.5f, 0.0f);
  glScalef(1.0f, 0.5f, 1.0f);
  quad_r(0.3f, 1.4f); /* r > 1 against the texel of depth 1 */
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
  cell(&c, 3, 2);
  glTranslatef(0.0f, -0.5f, 0.0f);
  glScalef(1.0f, 0.5f, 1.0f);
  quad_r(-0.4f, 0.7f); /* r < 0 against the texel of depth 0 */

  /* Row 3: a shadow map. A sphere over a floor drawn from the light (an orthographic view from
   * above), its depth copied into a 64 x 64 depth texture; then the floor drawn from the eye
   * with the texture coordinates of the light's view (eye-linear generation under the light's
   * matrices, with bias). */
  glDisable(GL_TEXTURE_2D);
  glViewport(0, 0, 64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.5, 1.5, -1.5, 1.5, 0.5, 5.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(90.0f, 1, 0, 0); /* looking down -y */
  glTranslatef(0.0f, -3.0f, 0.0f);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glPushMatrix();
  glTranslatef(0.2f, 0.5f, 0.1f);
  conf_sphere(0.6f, 24, 16);
  glPopMatrix();
  glBegin(GL_QUADS);
  glVertex3f(-1.5f, -0.5f, -1.5f);
  glVertex3f(-1.5f, -0.5f, 1.5f);
  glVertex3f(1.5f, -0.5f, 1.5f);
  glVertex3f(1.5f, -0.5f, -1.5f);
  glEnd();
  GLuint shadow;
  glGenTextures(1, &shadow);
  glBindTexture(GL_TEXTURE_2D, shadow);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, 64, 64, 0);
  conf_error(&c, "CopyTexImage2D depth");
  record_level(&c, "copied");
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 16, 16);
  conf_error(&c, "CopyTexSubImage2D depth");
  static float copied[64 * 64];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, copied);
  /* To 1e-4: the depths the two rasterizers interpolate differ in their last 24-bit steps. */
  for (int i = 0; i < 3; ++i) {
    const int at[3] = {0, 32 * 64 + 40, 10 * 64 + 50};
    char key[48];
    snprintf(key, sizeof key, "copied depth %d to 1e-4", at[i]);
    conf_value(&c, key, (double)(long)(copied[at[i]] * 10000.0f + 0.5f) / 10000.0);
  }
  filter(GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glEnable(GL_SCISSOR_TEST); /* the bottom row, where the light's view was drawn, cleared */
  glScissor(0, 0, 256, 64);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  for (int panel = 0; panel < 2; ++panel) {
    conf_panel(&c, panel, 3, 2, 4);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.3, 0.3, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, -0.3f, -4.0f);
    glRotatef(30.0f + 40.0f * (float)panel, 1, 0, 0);
    /* Eye planes given under the identity: object coordinates of the world (the modelview
     * below is the world's), into the light's clip space, then [0, 1]. */
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.5f, 0.5f, 0.5f);
    glScalef(0.5f, 0.5f, 0.5f);
    glOrtho(-1.5, 1.5, -1.5, 1.5, 0.5, 5.0);
    glRotatef(90.0f, 1, 0, 0);
    glTranslatef(0.0f, -3.0f, 0.0f);
    glMatrixMode(GL_MODELVIEW);
    const GLfloat ps[4] = {1, 0, 0, 0}, pt[4] = {0, 1, 0, 0}, pr[4] = {0, 0, 1, 0}, pq[4] = {0, 0, 0, 1};
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, ps);
    glTexGenfv(GL_T, GL_OBJECT_PLANE, pt);
    glTexGenfv(GL_R, GL_OBJECT_PLANE, pr);
    glTexGenfv(GL_Q, GL_OBJECT_PLANE, pq);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    glEnable(GL_TEXTURE_GEN_Q);
    glEnable(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, panel ? GL_INTENSITY : GL_LUMINANCE);
    glColor3f(0.9f, 0.8f, 0.5f);
    /* The floor, a little above the depth the map holds for it (a bias against acne). */
    glBegin(GL_QUADS);
    glVertex3f(-1.5f, -0.49f, -1.5f);
    glVertex3f(-1.5f, -0.49f, 1.5f);
    glVertex3f(1.5f, -0.49f, 1.5f);
    glVertex3f(1.5f, -0.49f, -1.5f);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_GEN_R);
    glDisable(GL_TEXTURE_GEN_Q);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glColor3f(0.3f, 0.6f, 0.9f);
    glTranslatef(0.2f, 0.5f, 0.1f);
    conf_sphere(0.6f, 24, 16);
  }
  glDisable(GL_DEPTH_TEST);

  /* Errors. */
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 8, 8, 0, GL_RGBA, GL_FLOAT, depth);
  conf_error(&c, "depth format from RGBA");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  conf_error(&c, "RGBA format from depth");
  glTexImage3D(GL_TEXTURE_3D, 0, GL_DEPTH_COMPONENT, 2, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  conf_error(&c, "3D depth");
  glTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT16, 8, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  conf_error(&c, "1D depth");
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, back);
  conf_error(&c, "GetTexImage RGBA of depth");
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_FLOAT, depth);
  conf_error(&c, "TexSubImage2D RGBA into depth");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  conf_error(&c, "TexSubImage2D depth");
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_RGBA);
  conf_error(&c, "depth texture mode RGBA");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_LESS);
  conf_error(&c, "compare mode LESS");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_RGBA);
  conf_error(&c, "compare func RGBA");
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, &n);
  conf_value(&c, "compare mode", n);
  GLuint color;
  glGenTextures(1, &color);
  glBindTexture(GL_TEXTURE_2D, color);
  static unsigned char rgba[4 * 4 * 4];
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, back);
  conf_error(&c, "GetTexImage depth of RGBA");
  return conf_finish(&c);
}
