/* The current raster position (GL 1.1 section 2.12), seen through solid 6 x 6 bitmaps drawn at
 * it: positions through ortho and perspective projections, modelview transforms, w != 1,
 * viewports with offsets and depth ranges (the raster depth against a depth buffer), every
 * glRasterPos variant; positions outside the view volume (nothing drawn, the next glBitmap does
 * not move); the raster colour unlit (current colour) and lit (directional and positional
 * lights, local viewer, spot, colour material), raster texture coordinates (a textured bitmap;
 * through the texture matrix in the queries). The top rows hold the glGet results of the raster state encoded
 * as pixels (position, colour, texture coordinates, distance, valid bit).
 *
 * Left out, where Mesa departs from the specification: lighting with a positional light or a
 * local viewer under a non-identity modelview (Mesa lights the object-space position with
 * eye-space lights), glGetIntegerv of raster colours outside [-1, 1] (Mesa overflows), bitmaps
 * textured under a texture matrix (Mesa samples them at other coordinates). */
#include <math.h>
#include <string.h>

#include "conf.h"

enum { kW = 256, kH = 256 };

static const GLubyte kSolid[6] = {0xfc, 0xfc, 0xfc, 0xfc, 0xfc, 0xfc};

static void marker(void) { glBitmap(6, 6, 0.0f, 0.0f, 7.0f, 0.0f, kSolid); }

static void ortho_window(void) {
  glViewport(0, 0, kW, kH);
  glDepthRange(0.0, 1.0);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* Row 1: positions in window coordinates, fractions around the pixel edges, every variant. */
static void positions(void) {
  ortho_window();
  glColor3f(1.0f, 1.0f, 1.0f);
  glRasterPos2i(4, 200);
  marker();
  glRasterPos2f(16.4999f, 200.5f);
  marker();
  glRasterPos2d(28.9999, 201.0001);
  marker();
  glRasterPos2s(40, 202);
  marker();
  const GLint iv[3] = {52, 203, 0};
  glRasterPos3iv(iv);
  marker();
  const GLfloat fv[4] = {128.0f, 400.0f, 0.0f, 2.0f}; /* w = 2: (64, 200) */
  glRasterPos4fv(fv);
  marker();
  const GLdouble dv[3] = {76.75, 199.25, 0.5};
  glRasterPos3dv(dv);
  marker();
  const GLshort sv[4] = {88, 201, 0, 1};
  glRasterPos4sv(sv);
  marker();
  glRasterPos4d(200.0, 402.0, 0.0, 2.0);
  marker();
  glRasterPos3s(112, 200, 0);
  marker();
  const GLint iv4[4] = {124, 200, 0, 1};
  glRasterPos4iv(iv4);
  marker();
  glRasterPos2i(136, 200);
  marker(); /* two markers: glBitmap moved the position by 7 */
  marker();
  /* Outside the view volume: invalid, nothing drawn, no move; valid again after. */
  glRasterPos2i(-1, 200);
  marker();
  glRasterPos3f(160, 200, 2.0f);
  marker();
  glRasterPos2i(kW, 200); /* x = w on the right plane: inside */
  marker();
  glRasterPos2i(170, 200);
  marker();
  /* A position moved past the window by glBitmap stays valid (and draws nothing there). */
  glRasterPos2i(240, 200);
  marker();
  marker();
  marker();
  glBitmap(0, 0, 0, 0, -30.0f, -10.0f, NULL);
  marker();
}

/* Row 2: transforms. */
static void transforms(void) {
  ortho_window();
  glColor3f(1.0f, 0.6f, 0.2f);
  glTranslatef(10.0f, 170.0f, 0.0f);
  glRasterPos2f(0.0f, 0.0f);
  marker();
  glRotatef(30.0f, 0, 0, 1);
  glRasterPos2f(20.0f, 0.0f);
  marker();
  glScalef(2.0f, 3.0f, 1.0f);
  glRasterPos2f(15.0f, 2.0f);
  marker();
  glLoadIdentity();
  glViewport(100, 150, 64, 48); /* a viewport with an offset */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glRasterPos3f(0.3f, 0.2f, -2.0f);
  marker();
  glRasterPos3f(-0.9f, -0.5f, -1.5f);
  marker();
  glRasterPos3f(0.0f, 0.0f, -0.5f); /* in front of the near plane */
  marker();
  glRasterPos4f(0.5f, 0.5f, -2.0f, 2.0f);
  marker();
  glRasterPos3f(3.0f, 0.0f, -2.0f); /* beside the frustum */
  marker();
}

/* Row 3: the raster depth against a depth buffer. A wall at depth 0.5 hides markers whose
 * window depth (through glDepthRange) is farther. */
static void depths(void) {
  ortho_window();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glColor3f(0.2f, 0.2f, 0.5f);
  glBegin(GL_TRIANGLES);
  glVertex3f(0, 130, 0);
  glVertex3f(kW, 130, 0);
  glVertex3f(kW, 150, 0);
  glVertex3f(0, 130, 0);
  glVertex3f(kW, 150, 0);
  glVertex3f(0, 150, 0);
  glEnd();
  glColor3f(0.9f, 0.9f, 0.3f);
  const float z[6] = {0.5f, -0.5f, 0.2f, -0.2f, 0.9f, -0.9f};
  for (int i = 0; i < 6; ++i) {
    glRasterPos3f(8.0f + 12.0f * i, 137.0f, z[i]);
    marker();
  }
  glDepthRange(0.6, 1.0); /* every marker farther than the wall */
  for (int i = 0; i < 6; ++i) {
    glRasterPos3f(88.0f + 12.0f * i, 137.0f, z[i]);
    marker();
  }
  glDepthRange(0.0, 0.4);
  for (int i = 0; i < 6; ++i) {
    glRasterPos3f(168.0f + 12.0f * i, 137.0f, z[i]);
    marker();
  }
  glDepthRange(0.0, 1.0);
  glFlush(); /* Mesa 22.3 draws bitmaps it keeps for later with the state at that time */
  glDisable(GL_DEPTH_TEST);
}

static void light(GLenum l, float x, float y, float z, float w) {
  const GLfloat pos[4] = {x, y, z, w}, white[4] = {1, 1, 1, 1};
  glLightfv(l, GL_POSITION, pos);
  glLightfv(l, GL_DIFFUSE, white);
  glLightfv(l, GL_SPECULAR, white);
  glEnable(l);
}

/* Row 4: the raster colour, lit. Normals and positions vary per marker. */
static void lit_colors(void) {
  ortho_window();
  glEnable(GL_LIGHTING);
  const GLfloat diffuse[4] = {0.8f, 0.5f, 0.3f, 1.0f}, spec[4] = {0.6f, 0.6f, 0.6f, 1.0f};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
  light(GL_LIGHT0, 0.3f, 0.5f, 1.0f, 0.0f);
  for (int i = 0; i < 8; ++i) {
    float a = (float)i / 8.0f * 2.0f * (float)CONF_PI;
    glNormal3f((float)cos(a), (float)sin(a) * 0.5f, 0.7f);
    glRasterPos2f(8.0f + 12.0f * i, 110.0f);
    marker();
  }
  /* Positional light with attenuation, identity modelview. */
  light(GL_LIGHT1, 150.0f, 120.0f, 40.0f, 1.0f);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.01f);
  glDisable(GL_LIGHT0);
  glNormal3f(0.0f, 0.0f, 1.0f);
  for (int i = 0; i < 8; ++i) {
    glRasterPos2f(104.0f + 12.0f * i, 110.0f);
    marker();
  }
  /* Local viewer, a spot light, two-sided model (the raster colour is the front one). */
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  light(GL_LIGHT2, 230.0f, 120.0f, 30.0f, 1.0f);
  const GLfloat dir[3] = {0.0f, 0.0f, -1.0f};
  glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, dir);
  glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 45.0f);
  glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 4.0f);
  glDisable(GL_LIGHT1);
  for (int i = 0; i < 5; ++i) {
    glNormal3f(i == 4 ? 0.0f : 0.2f, 0.0f, i == 4 ? -1.0f : 1.0f);
    glRasterPos2f(200.0f + 12.0f * (i % 4), i == 4 ? 98.0f : 110.0f);
    marker();
  }
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  glDisable(GL_LIGHT2);
  /* Colour material: the current colour becomes the diffuse material. */
  light(GL_LIGHT0, 0.0f, 0.0f, 1.0f, 0.0f);
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  for (int i = 0; i < 6; ++i) {
    glColor3f(0.2f * i, 1.0f - 0.15f * i, 0.5f);
    glRasterPos2f(8.0f + 12.0f * i, 90.0f);
    marker();
  }
  glDisable(GL_COLOR_MATERIAL);
  /* Directional light under a rotated modelview. */
  glRotatef(40.0f, 0.0f, 1.0f, 0.0f);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glRasterPos2f(90.0f, 90.0f);
  marker();
  glLoadIdentity();
  glDisable(GL_LIGHT0);
  glDisable(GL_LIGHTING);
}

/* Row 5: raster texture coordinates: a 4 x 4 texture of distinct colours, sampled at the raster
 * position's coordinates (the texture matrix is checked by the queries: Mesa samples bitmaps
 * and images elsewhere when it is not the identity). */
static void textured(void) {
  ortho_window();
  GLubyte tex[4 * 4 * 4];
  for (int i = 0; i < 16; ++i) {
    tex[i * 4] = (GLubyte)(i * 16), tex[i * 4 + 1] = (GLubyte)(255 - i * 12), tex[i * 4 + 2] = (GLubyte)(i * 7 + 60);
    tex[i * 4 + 3] = 255;
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glColor3f(1.0f, 1.0f, 1.0f);
  for (int i = 0; i < 8; ++i) {
    glTexCoord2f(0.125f + 0.25f * (i % 4), 0.125f + 0.25f * (i / 4));
    glRasterPos2f(8.0f + 12.0f * i, 70.0f);
    marker();
    glFlush(); /* Mesa 22.3 keeps bitmaps of one colour for later, whatever their coordinates */
  }
  glFlush(); /* Mesa 22.3 crashes in a later glDrawPixels when its cached bitmaps wait for a flush
              * past the texture's disabling */
  glDisable(GL_TEXTURE_2D);
}

static GLubyte to_byte(float v) { return (GLubyte)(v < 0 ? 0 : v > 1 ? 255 : v * 255.0f + 0.5f); }
/* The low byte of v truncated to an integer (0 for what no int holds): values past 255 wrap
 * rather than being converted to GLubyte directly, which C leaves undefined. */
static GLubyte low_byte(float v) { return (GLubyte)(v > -2e9f && v < 2e9f ? (unsigned)(int)v & 0xffu : 0u); }

/* The top rows: the raster state of several positions from glGet, as pixels. */
static void queries(void) {
  static GLubyte row[kW * 4];
  int n = 0;
  memset(row, 0, sizeof row);
  GLfloat pos[4], col[4], tc[4], dist;
  GLint ipos[4], valid;
  for (int k = 0; k < 6; ++k) {
    glViewport(0, 0, kW, kH);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (k < 3) glOrtho(0, kW, 0, kH, -1, 1);
    else glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor4f(0.1f * k, 0.9f - 0.1f * k, 0.5f, 0.25f * k);
    glTexCoord2f(0.3f * k, 1.0f - 0.2f * k);
    if (k == 1) glTranslatef(3.5f, -2.25f, 0.5f);
    if (k == 4) glDepthRange(0.25, 0.75);
    if (k == 3) {
      glMatrixMode(GL_TEXTURE);
      glTranslatef(0.5f, 0.25f, 0.0f);
      glScalef(0.5f, 2.0f, 1.0f);
      glMatrixMode(GL_MODELVIEW);
    }
    if (k == 5) {
      glEnable(GL_LIGHTING);
      light(GL_LIGHT0, 0.0f, 1.0f, 1.0f, 0.0f);
      glNormal3f(0.0f, 0.6f, 0.8f);
    }
    glRasterPos4f(k < 3 ? 30.5f * k + 7.25f : 0.1f * k, k < 3 ? 100.75f : -0.2f, k < 3 ? 0.3f : -3.0f + 0.3f * k,
                  k == 2 ? 2.0f : 1.0f);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
    glGetIntegerv(GL_CURRENT_RASTER_POSITION, ipos);
    glGetFloatv(GL_CURRENT_RASTER_COLOR, col);
    glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, tc);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &dist);
    glGetIntegerv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    const GLubyte px[6][4] = {
        {(GLubyte)ipos[0], (GLubyte)ipos[1], to_byte(pos[2]), low_byte(pos[3] * 50.0f)},
        {low_byte(pos[0] * 4.0f), low_byte(pos[1] * 4.0f), (GLubyte)(valid * 255), 255},
        {to_byte(col[0]), to_byte(col[1]), to_byte(col[2]), to_byte(col[3])},
        {to_byte(tc[0]), to_byte(tc[1]), to_byte(tc[2]), to_byte(tc[3])},
        {low_byte(dist * 2.0f), low_byte(dist * 50.0f), 0, 255},
        {0, 0, 0, 255},
    };
    for (int i = 0; i < 6; ++i, ++n) memcpy(row + n * 4, px[i], 4);
    glDepthRange(0.0, 1.0);
    glDisable(GL_LIGHTING);
    glDisable(GL_LIGHT0);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
  }
  ortho_window();
  for (int y = 0; y < 4; ++y) {
    glRasterPos2i(0, kH - 4 + y);
    glDrawPixels(n, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
  }
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, kW, kH)) return 1;
  glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  positions();
  transforms();
  depths();
  lit_colors();
  textured();
  queries();
  return conf_finish(&c);
}
