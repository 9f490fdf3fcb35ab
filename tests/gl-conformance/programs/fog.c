/* Fog (GL 1.1 section 3.9). Rows: GL_LINEAR (start 2, end 14), GL_EXP (density 0.16) and
 * GL_EXP2 (density 0.11). Columns, each with another GL_FOG_HINT: lit spheres receding in
 * perspective (GL_DONT_CARE); a textured floor and back wall in perspective, modulated and
 * replaced (GL_NICEST); an orthographic wall sloping away in depth with smooth colours and a
 * fog colour with alpha 0.3 (GL_FASTEST: alpha is kept, and stored); translucent quads blended
 * in front of and behind a lit sphere with a separate specular colour (GL_DONT_CARE). Last
 * column: a flat-shaded sphere under fog start == end (GL_LINEAR), vertices with w = 2 and fog
 * coordinates past the far end (top); lit, textured spheres (GL_NICEST). */
#include "conf.h"

static GLuint make_texture(void) {
  static unsigned char texels[16 * 16 * 4];
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      unsigned char* t = &texels[(y * 16 + x) * 4];
      int on = ((x / 4) + (y / 4)) % 2;
      t[0] = (unsigned char)(on ? 230 : 40);
      t[1] = (unsigned char)(on ? 190 : 80 + 8 * y);
      t[2] = (unsigned char)(on ? 70 : 210);
      t[3] = 255;
    }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  return tex;
}

static void perspective(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.6, 0.6, 1.0, 40.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void material(float r, float g, float b, float a) {
  const GLfloat diffuse[4] = {r, g, b, a}, ambient[4] = {0.2f * r, 0.2f * g, 0.2f * b, a};
  const GLfloat specular[4] = {0.8f, 0.8f, 0.8f, 1.0f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
}

static void lights_on(void) {
  const GLfloat dir[4] = {0.4f, 0.7f, 0.6f, 0.0f};
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
}

static void spheres(void) {
  perspective();
  lights_on();
  const float zs[5] = {-3.0f, -5.5f, -8.5f, -12.5f, -19.0f};
  const float xs[5] = {-1.1f, 1.3f, -0.4f, 3.2f, -4.2f};
  for (int i = 0; i < 5; ++i) {
    material(i % 2 ? 0.9f : 0.3f, 0.5f, i % 3 ? 0.2f : 0.9f, 1.0f);
    glPushMatrix();
    glTranslatef(xs[i], 0.5f * (float)i - 1.0f, zs[i]);
    conf_sphere(0.9f, 20, 12);
    glPopMatrix();
  }
  glDisable(GL_LIGHTING);
}

static void floor_and_wall(GLuint tex) {
  perspective();
  glBindTexture(GL_TEXTURE_2D, tex);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBegin(GL_TRIANGLES); /* a floor from z = -1 to z = -30, colours fading */
  for (int j = 0; j < 6; ++j) {
    float z0 = -1.0f - 5.0f * (float)j, z1 = z0 - 5.0f, t0 = (float)j, t1 = t0 + 1.0f;
    glColor3f(1.0f, 1.0f - 0.1f * (float)j, 0.8f);
    glTexCoord2f(0, t0); glVertex3f(-3.0f, -1.0f, z0);
    glTexCoord2f(2, t0); glVertex3f(3.0f, -1.0f, z0);
    glTexCoord2f(2, t1); glVertex3f(3.0f, -1.0f, z1);
    glTexCoord2f(0, t0); glVertex3f(-3.0f, -1.0f, z0);
    glTexCoord2f(2, t1); glVertex3f(3.0f, -1.0f, z1);
    glTexCoord2f(0, t1); glVertex3f(-3.0f, -1.0f, z1);
  }
  glEnd();
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glPushMatrix(); /* a back wall, turned so that its depth changes across it */
  glTranslatef(0.5f, 2.0f, -15.0f);
  glRotatef(35.0f, 0, 1, 0);
  conf_wall(14.0f, 8.0f, 6);
  glPopMatrix();
  glDisable(GL_TEXTURE_2D);
}

static void sloping_wall(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, 0.0, 30.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat fog_color[4] = {0.7f, 0.75f, 0.85f, 0.3f};
  glFogfv(GL_FOG_COLOR, fog_color);
  glBegin(GL_QUADS);
  glColor4f(1.0f, 0.2f, 0.1f, 1.0f);
  glVertex3f(-1.0f, -1.0f, -0.5f);
  glColor4f(0.1f, 0.9f, 0.2f, 0.6f);
  glVertex3f(1.0f, -1.0f, -25.0f);
  glColor4f(0.2f, 0.3f, 1.0f, 0.9f);
  glVertex3f(1.0f, 1.0f, -25.0f);
  glColor4f(1.0f, 1.0f, 0.3f, 0.2f);
  glVertex3f(-1.0f, 1.0f, -0.5f);
  glEnd();
  const GLfloat grey[4] = {0.5f, 0.5f, 0.55f, 1.0f};
  glFogfv(GL_FOG_COLOR, grey);
}

static void translucent_quad(float z, float r, float g, float b) {
  glColor4f(r, g, b, 0.5f);
  glBegin(GL_QUADS);
  glVertex3f(-0.5f * -z * 0.5f, -0.35f * -z * 0.5f, z);
  glVertex3f(0.15f * -z * 0.5f, -0.35f * -z * 0.5f, z);
  glVertex3f(0.15f * -z * 0.5f, 0.4f * -z * 0.5f, z);
  glVertex3f(-0.5f * -z * 0.5f, 0.4f * -z * 0.5f, z);
  glEnd();
}

static void blended(void) {
  perspective();
  lights_on();
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  material(0.2f, 0.4f, 0.9f, 1.0f);
  glPushMatrix();
  glTranslatef(0.3f, 0.0f, -9.0f);
  conf_sphere(2.2f, 24, 16);
  glPopMatrix();
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glDisable(GL_LIGHTING);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  translucent_quad(-16.0f, 1.0f, 0.9f, 0.2f); /* behind the sphere: depth-tested away in part */
  translucent_quad(-4.0f, 0.9f, 0.2f, 0.6f);
  glDisable(GL_BLEND);
}

static void corner_cases(void) {
  perspective();
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 7.0f);
  glFogf(GL_FOG_END, 7.0f); /* Mesa's scale 1: nearer than 7 fully fogged */
  glShadeModel(GL_FLAT);
  lights_on();
  material(0.9f, 0.6f, 0.2f, 1.0f);
  glPushMatrix();
  glTranslatef(-0.6f, 0.6f, -7.0f);
  conf_sphere(1.6f, 16, 10);
  glPopMatrix();
  glDisable(GL_LIGHTING);
  glShadeModel(GL_SMOOTH);
  glFogf(GL_FOG_START, 1.0f);
  glFogf(GL_FOG_END, 10.0f);
  glBegin(GL_TRIANGLES); /* w = 2: the fog coordinate is |z_eye| = 8 to 30, not z / w */
  glColor3f(0.1f, 1.0f, 0.3f);
  glVertex4f(-2.0f, -3.0f, -8.0f, 2.0f);
  glColor3f(1.0f, 0.1f, 0.3f);
  glVertex4f(8.0f, -10.0f, -30.0f, 2.0f);
  glColor3f(0.2f, 0.3f, 1.0f);
  glVertex4f(2.0f, 3.0f, -12.0f, 2.0f);
  glEnd();
}

static void textured_spheres(GLuint tex) {
  perspective();
  lights_on();
  material(1.0f, 1.0f, 1.0f, 1.0f);
  glBindTexture(GL_TEXTURE_2D, tex);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  for (int i = 0; i < 3; ++i) {
    glPushMatrix();
    glTranslatef(-1.0f + 1.2f * (float)i, 0.5f - 0.6f * (float)i, -3.5f - 5.0f * (float)i);
    glRotatef(30.0f * (float)i, 0, 1, 0);
    conf_sphere(1.1f, 24, 14);
    glPopMatrix();
  }
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_LIGHTING);
}

static void set_mode(int row) {
  if (row == 0) {
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 2.0f);
    glFogf(GL_FOG_END, 14.0f);
  } else {
    glFogi(GL_FOG_MODE, row == 1 ? GL_EXP : GL_EXP2);
    glFogf(GL_FOG_DENSITY, row == 1 ? 0.16f : 0.11f);
  }
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 500, 300)) return 1;
  GLuint tex = make_texture();
  glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const GLfloat grey[4] = {0.5f, 0.5f, 0.55f, 1.0f};
  glFogfv(GL_FOG_COLOR, grey);
  glEnable(GL_FOG);
  const GLenum hints[5] = {GL_DONT_CARE, GL_NICEST, GL_FASTEST, GL_DONT_CARE, GL_NICEST};
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 5; ++col) {
      set_mode(row);
      glHint(GL_FOG_HINT, hints[col]);
      conf_panel(&c, col, row, 5, 3);
      if (col == 0) spheres();
      if (col == 1) floor_and_wall(tex);
      if (col == 2) sloping_wall();
      if (col == 3) blended();
      if (col == 4 && row == 0) corner_cases();
      if (col == 4 && row > 0) textured_spheres(tex);
    }
  }
  glDisable(GL_FOG);
  return conf_finish(&c);
}
