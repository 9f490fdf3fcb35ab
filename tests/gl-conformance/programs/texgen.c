/* Texture coordinate generation (OpenGL 1.1 section 2.10.4) with the texture matrix and
 * projective texture coordinates (section 3.8: s/q and t/q per fragment): object-linear and
 * eye-linear stripes on GLUT's teapot and a torus, sphere mapping on a sphere and the teapot,
 * s, t, r and q all generated and transformed by a texture matrix with a perspective part,
 * the classic projected light (eye-linear planes set under the camera, a light's projection
 * in the texture matrix, projected onto a lit floor and wall), and the same generation
 * through glDrawArrays and glDrawElements. The generation state (planes through the
 * modelview, modes, enables) is recorded with conf_value. */
#include <math.h>
#include <stdio.h>

#include <GL/shadelab_glut.h>

#include "conf.h"

static void perspective_cell(const ConfContext* c, int col, int row) {
  conf_panel(c, col, row, 4, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -4.5f);
}

static void lights_on(void) {
  const GLfloat light[4] = {1.0f, 2.0f, 3.0f, 0.0f}, white[4] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
}

static void gen(GLenum coord, GLenum mode, const GLfloat* plane) {
  glTexGeni(coord, GL_TEXTURE_GEN_MODE, (GLint)mode);
  if (plane) glTexGenfv(coord, mode == GL_OBJECT_LINEAR ? GL_OBJECT_PLANE : GL_EYE_PLANE, plane);
}

static void enable_gen(int s, int t, int r, int q) {
  (s ? glEnable : glDisable)(GL_TEXTURE_GEN_S);
  (t ? glEnable : glDisable)(GL_TEXTURE_GEN_T);
  (r ? glEnable : glDisable)(GL_TEXTURE_GEN_R);
  (q ? glEnable : glDisable)(GL_TEXTURE_GEN_Q);
}

/* A 1D stripe texture (8 texels: one dark, seven light) for contour lines. */
static GLuint stripe_texture(void) {
  static unsigned char texels[8 * 3];
  for (int i = 0; i < 8; ++i) {
    texels[i * 3 + 0] = i == 0 ? 40 : 250;
    texels[i * 3 + 1] = i == 0 ? 40 : 200;
    texels[i * 3 + 2] = i == 0 ? 160 : 120;
  }
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_1D, t);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return t;
}

/* A 64x64 environment: sky gradient, a bright sun, a ground checker, rings. */
static GLuint environment_texture(void) {
  static unsigned char texels[64 * 64 * 3];
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      unsigned char* p = &texels[(y * 64 + x) * 3];
      double dx = x - 40.0, dy = y - 44.0, r = sqrt((x - 32.0) * (x - 32.0) + (y - 32.0) * (y - 32.0));
      int sun = dx * dx + dy * dy < 36.0, ring = ((int)r / 4) % 2;
      if (y < 28) {
        int on = (x / 8 + y / 8) % 2;
        p[0] = (unsigned char)(on ? 120 : 70), p[1] = (unsigned char)(on ? 90 : 140), p[2] = 50;
      } else {
        p[0] = (unsigned char)(60 + y * 2), p[1] = (unsigned char)(100 + y), p[2] = 230;
      }
      if (ring) p[1] = (unsigned char)(p[1] / 2);
      if (sun) p[0] = p[1] = 255, p[2] = 200;
    }
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return t;
}

/* A 32x32 spotlight: bright in a disc fading out, a dark cross, black outside (clamped
 * with a black border colour). */
static GLuint spot_texture(void) {
  static unsigned char texels[32 * 32 * 3];
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      unsigned char* p = &texels[(y * 32 + x) * 3];
      double r = sqrt((x - 15.5) * (x - 15.5) + (y - 15.5) * (y - 15.5)) / 15.5;
      double k = r < 1.0 ? 1.0 - r * r : 0.0;
      int cross = (x >= 14 && x <= 17) || (y >= 14 && y <= 17);
      if (cross) k *= 0.3;
      p[0] = (unsigned char)(255 * k), p[1] = (unsigned char)(230 * k), p[2] = (unsigned char)(120 * k);
    }
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 32, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
  return t;
}

static void record_gen(ConfContext* c, const char* what) {
  static const GLenum coords[4] = {GL_S, GL_T, GL_R, GL_Q};
  char key[96];
  for (int i = 0; i < 4; ++i) {
    GLfloat eye[4], object[4];
    GLint mode;
    glGetTexGenfv(coords[i], GL_EYE_PLANE, eye);
    glGetTexGenfv(coords[i], GL_OBJECT_PLANE, object);
    glGetTexGeniv(coords[i], GL_TEXTURE_GEN_MODE, &mode);
    snprintf(key, sizeof key, "%s coord %d eye plane", what, i);
    conf_values(c, key, (double[]){eye[0], eye[1], eye[2], eye[3]}, 4);
    snprintf(key, sizeof key, "%s coord %d object plane", what, i);
    conf_values(c, key, (double[]){object[0], object[1], object[2], object[3]}, 4);
    snprintf(key, sizeof key, "%s coord %d mode", what, i);
    conf_value(c, key, mode);
    snprintf(key, sizeof key, "%s coord %d enabled", what, i);
    conf_value(c, key, glIsEnabled(GL_TEXTURE_GEN_S + (GLenum)i));
  }
  conf_error(c, what);
}

/* Contours: object-linear stripes on the teapot, eye-linear ones on a torus. */
static void contours(const ConfContext* c) {
  GLuint stripes = stripe_texture();
  glEnable(GL_TEXTURE_1D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  const GLfloat object_plane[4] = {0.0f, 2.5f, 0.5f, 0.1f};
  gen(GL_S, GL_OBJECT_LINEAR, object_plane);
  enable_gen(1, 0, 0, 0);
  perspective_cell(c, 0, 0);
  glRotatef(25.0f, 1, 0, 0);
  glRotatef(-30.0f, 0, 1, 0);
  glFrontFace(GL_CW);
  glutSolidTeapot(1.0);
  glFrontFace(GL_CCW);
  perspective_cell(c, 1, 0);
  const GLfloat eye_plane[4] = {1.5f, 1.5f, 0.0f, 0.0f};
  gen(GL_S, GL_EYE_LINEAR, eye_plane);
  glRotatef(50.0f, 1, 0, 0);
  glutSolidTorus(0.35, 1.0, 16, 32);
  enable_gen(0, 0, 0, 0);
  glDisable(GL_TEXTURE_1D);
  glDeleteTextures(1, &stripes);
}

/* Sphere maps: a sphere and the teapot reflecting the environment texture. */
static void sphere_maps(const ConfContext* c) {
  GLuint env = environment_texture();
  glEnable(GL_TEXTURE_2D);
  gen(GL_S, GL_SPHERE_MAP, NULL);
  gen(GL_T, GL_SPHERE_MAP, NULL);
  enable_gen(1, 1, 0, 0);
  perspective_cell(c, 2, 0);
  glEnable(GL_NORMALIZE);
  glScalef(1.3f, 1.3f, 1.3f);
  conf_sphere(1.0f, 32, 16);
  glDisable(GL_NORMALIZE);
  perspective_cell(c, 3, 0);
  glRotatef(20.0f, 1, 0, 0);
  glRotatef(40.0f, 0, 1, 0);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glFrontFace(GL_CW);
  glutSolidTeapot(1.0);
  glFrontFace(GL_CCW);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  enable_gen(0, 0, 0, 0);
  glDeleteTextures(1, &env);
}

/* s, t, r, q generated (object linear from x, y, z and a plane making q vary) and a texture
 * matrix with rotation, scale and a perspective row. */
static void four_coordinates(ConfContext* c, GLuint checker) {
  glBindTexture(GL_TEXTURE_2D, checker);
  const GLfloat ps[4] = {1, 0, 0, 0}, pt[4] = {0, 1, 0, 0}, pr[4] = {0, 0, 1, 0}, pq[4] = {0.25f, 0.1f, 0.3f, 1.0f};
  gen(GL_S, GL_OBJECT_LINEAR, ps);
  gen(GL_T, GL_OBJECT_LINEAR, pt);
  gen(GL_R, GL_OBJECT_LINEAR, pr);
  gen(GL_Q, GL_OBJECT_LINEAR, pq);
  enable_gen(1, 1, 1, 1);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0.0f);
  glRotatef(15.0f, 0, 0, 1);
  glScalef(0.6f, 0.9f, 1.0f);
  const GLfloat perspective[16] = {1, 0, 0, 0.2f, 0, 1, 0, -0.15f, 0, 0, 1, 0, 0, 0, 0, 1};
  glMultMatrixf(perspective);
  perspective_cell(c, 0, 1);
  glRotatef(30.0f, 1, 1, 0);
  conf_sphere(1.3f, 32, 16);
  perspective_cell(c, 1, 1);
  glRotatef(-40.0f, 1, 0, 0);
  conf_wall(3.0f, 3.0f, 6);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  record_gen(c, "four coordinates");
  enable_gen(0, 0, 0, 0);
}

/* gluLookAt's matrix (eye, centre, up = y) multiplied onto the current matrix. */
static void look_at(float ex, float ey, float ez, float cx, float cy, float cz) {
  float f[3] = {cx - ex, cy - ey, cz - ez}, up[3] = {0, 1, 0}, s[3], u[3];
  float n = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  for (int i = 0; i < 3; ++i) f[i] /= n;
  s[0] = f[1] * up[2] - f[2] * up[1], s[1] = f[2] * up[0] - f[0] * up[2], s[2] = f[0] * up[1] - f[1] * up[0];
  n = sqrtf(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  for (int i = 0; i < 3; ++i) s[i] /= n;
  u[0] = s[1] * f[2] - s[2] * f[1], u[1] = s[2] * f[0] - s[0] * f[2], u[2] = s[0] * f[1] - s[1] * f[0];
  const GLfloat m[16] = {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, 0, 0, 0, 1};
  glMultMatrixf(m);
  glTranslatef(-ex, -ey, -ez);
}

/* The projected light: planes set to the identity while the modelview is the camera's, so
 * that (s, t, r, q) are eye coordinates; the texture matrix takes them back to the world and
 * into the light's clip space, biased to [0, 1]. */
static void projected_light(ConfContext* c, GLuint spot) {
  glViewport(c->width / 2, 0, c->width / 2, 2 * (c->height / 3));
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, -1.0f, -6.0f);
  glRotatef(25.0f, 1, 0, 0);
  glRotatef(-20.0f, 0, 1, 0);
  const GLfloat ps[4] = {1, 0, 0, 0}, pt[4] = {0, 1, 0, 0}, pr[4] = {0, 0, 1, 0}, pq[4] = {0, 0, 0, 1};
  GLfloat camera[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, camera);
  glPushMatrix();
  glLoadIdentity();
  gen(GL_S, GL_EYE_LINEAR, ps);
  gen(GL_T, GL_EYE_LINEAR, pt);
  gen(GL_R, GL_EYE_LINEAR, pr);
  gen(GL_Q, GL_EYE_LINEAR, pq);
  glPopMatrix();
  record_gen(c, "projected light");
  enable_gen(1, 1, 1, 1);
  /* Texture matrix: bias * light frustum * light view * inverse(camera). */
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0.5f);
  glScalef(0.5f, 0.5f, 0.5f);
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  look_at(-1.5f, 4.5f, 2.5f, 0.2f, 0.6f, -1.5f);
  /* inverse of the camera: a rigid motion, so its transpose rotation and negated translation */
  GLfloat inverse[16] = {camera[0], camera[4], camera[8], 0, camera[1], camera[5], camera[9], 0,
                         camera[2], camera[6], camera[10], 0, 0, 0, 0, 1};
  for (int i = 0; i < 3; ++i)
    inverse[12 + i] = -(inverse[i] * camera[12] + inverse[4 + i] * camera[13] + inverse[8 + i] * camera[14]);
  glMultMatrixf(inverse);
  glMatrixMode(GL_MODELVIEW);
  glBindTexture(GL_TEXTURE_2D, spot);
  const GLfloat black[4] = {0, 0, 0, 1};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, black);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  const GLfloat grey[4] = {0.9f, 0.9f, 0.9f, 1}, ambient[4] = {0.6f, 0.6f, 0.6f, 1};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glNormal3f(0, 1, 0);
  glBegin(GL_QUADS); /* floor */
  glVertex3f(-4, 0, 4);
  glVertex3f(4, 0, 4);
  glVertex3f(4, 0, -4);
  glVertex3f(-4, 0, -4);
  glEnd();
  glNormal3f(0, 0, 1);
  glBegin(GL_QUADS); /* wall */
  glVertex3f(-4, 0, -4);
  glVertex3f(4, 0, -4);
  glVertex3f(4, 4, -4);
  glVertex3f(-4, 4, -4);
  glEnd();
  glPushMatrix();
  glTranslatef(0.5f, 0.8f, 0.5f);
  conf_sphere(0.8f, 24, 12);
  glPopMatrix();
  const GLfloat dark[4] = {0.2f, 0.2f, 0.2f, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, dark);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  enable_gen(0, 0, 0, 0);
}

/* Generation through vertex arrays: eye-linear s and t on a grid drawn with glDrawArrays
 * (triangle strips) and glDrawElements (triangles). */
static void arrays(const ConfContext* c, GLuint checker) {
  static GLfloat vertices[11 * 11 * 3], normals[11 * 11 * 3], strip_vertices[10 * 22 * 3];
  static GLushort triangles[10 * 10 * 6];
  for (int j = 0, k = 0; j <= 10; ++j)
    for (int i = 0; i <= 10; ++i, ++k) {
      float x = -1.0f + 0.2f * (float)i, y = -1.0f + 0.2f * (float)j, z = 0.25f * sinf(3.0f * x) * cosf(2.0f * y);
      vertices[k * 3] = x, vertices[k * 3 + 1] = y, vertices[k * 3 + 2] = z;
      normals[k * 3] = 0, normals[k * 3 + 1] = 0, normals[k * 3 + 2] = 1;
    }
  for (int j = 0, n = 0; j < 10; ++j)
    for (int i = 0; i < 10; ++i) {
      GLushort a = (GLushort)(j * 11 + i), b = (GLushort)(a + 1), d = (GLushort)(a + 11), e = (GLushort)(d + 1);
      triangles[n++] = a, triangles[n++] = b, triangles[n++] = e;
      triangles[n++] = a, triangles[n++] = e, triangles[n++] = d;
    }
  /* Row j as a strip: (j + 1, i), (j, i) for each i (counter-clockwise). */
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i <= 10; ++i)
      for (int k = 0; k < 3; ++k) {
        strip_vertices[((j * 22) + 2 * i) * 3 + k] = vertices[((j + 1) * 11 + i) * 3 + k];
        strip_vertices[((j * 22) + 2 * i + 1) * 3 + k] = vertices[(j * 11 + i) * 3 + k];
      }
  glBindTexture(GL_TEXTURE_2D, checker);
  const GLfloat ps[4] = {1.2f, 0.3f, 0.0f, 0.5f}, pt[4] = {-0.3f, 1.2f, 0.8f, 0.5f};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, vertices);
  glNormalPointer(GL_FLOAT, 0, normals);
  enable_gen(1, 1, 0, 0);
  for (int pass = 0; pass < 2; ++pass) {
    conf_panel(c, pass, 2, 4, 3);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1.5, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gen(GL_S, GL_EYE_LINEAR, ps);
    gen(GL_T, GL_EYE_LINEAR, pt);
    glTranslatef(0, 0, -3.5f);
    glRotatef(-35.0f, 1, 0, 0);
    glRotatef(20.0f * (float)pass, 0, 0, 1);
    if (pass == 0) {
      for (int j = 0; j < 10; ++j) glDrawElements(GL_TRIANGLES, 60, GL_UNSIGNED_SHORT, triangles + j * 60);
    } else {
      gen(GL_S, GL_OBJECT_LINEAR, ps);
      gen(GL_T, GL_OBJECT_LINEAR, pt);
      glVertexPointer(3, GL_FLOAT, 0, strip_vertices);
      glDisableClientState(GL_NORMAL_ARRAY);
      for (int j = 0; j < 10; ++j) glDrawArrays(GL_TRIANGLE_STRIP, j * 22, 22);
    }
  }
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  enable_gen(0, 0, 0, 0);
}

static GLuint checker_texture(void) {
  static unsigned char texels[16 * 16 * 3];
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      unsigned char* p = &texels[(y * 16 + x) * 3];
      int on = (x / 2 + y / 2) % 2;
      p[0] = (unsigned char)(on ? 240 : 30 + 10 * x);
      p[1] = (unsigned char)(on ? 210 : 60);
      p[2] = (unsigned char)(on ? 90 : 120 + 8 * y);
    }
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return t;
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 320, 240)) return 1;
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  record_gen(&c, "initial");
  lights_on();
  contours(&c);
  sphere_maps(&c);
  GLuint checker = checker_texture();
  glEnable(GL_TEXTURE_2D);
  four_coordinates(&c, checker);
  GLuint spot = spot_texture();
  projected_light(&c, spot);
  arrays(&c, checker);
  glDeleteTextures(1, &checker);
  glDeleteTextures(1, &spot);
  return conf_finish(&c);
}
