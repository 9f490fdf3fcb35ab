/* glReadPixels with GL_RGBA and GL_RGB (GL_UNSIGNED_BYTE): a scene is drawn into the left half;
 * its lower quarter is read back as RGBA and its upper quarter, from an odd x with an odd width,
 * as RGB with the default GL_PACK_ALIGNMENT of 4 (rows padded to 384 bytes). The PNG is a
 * composite made on the CPU: the left half as rendered, the RGBA read-back pasted into the lower
 * right quarter and the RGB read-back into the upper right one. The program also reads the whole
 * window back as RGBA and checks it byte for byte against the OSMesa buffer. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "conf.h"

enum { kW = 256, kH = 256 };

static void scene(void) {
  glViewport(0, 0, kW / 2, kH);
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1.0, 1.0, -2.0, 2.0, -2.0, 2.0);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat dir[] = {-0.5f, 0.6f, 1, 0}, dif[] = {0.8f, 0.5f, 0.2f, 0.6f};
  const GLfloat spec[] = {1, 1, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, dif); /* alpha 0.6 lands in the framebuffer */
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
  glPushMatrix();
  glTranslatef(0.0f, 1.0f, 0.0f);
  conf_sphere(0.85f, 32, 16);
  glPopMatrix();
  glDisable(GL_LIGHTING);
  glBegin(GL_TRIANGLES);
  glColor4f(1, 0, 0, 1);
  glVertex2f(-0.9f, -1.9f);
  glColor4f(0, 1, 0, 0.5f);
  glVertex2f(0.9f, -1.6f);
  glColor4f(0, 0, 1, 0.1f);
  glVertex2f(-0.2f, -0.1f);
  glEnd();
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, kW, kH)) return 1;
  glClearColor(0.2f, 0.25f, 0.3f, 0.75f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  scene();
  glFinish();

  const int rgb_x = 1, rgb_w = 127, rgb_stride = (rgb_w * 3 + 3) / 4 * 4;
  unsigned char* rgba = malloc((size_t)kW / 2 * kH / 2 * 4);
  unsigned char* rgb = malloc((size_t)rgb_stride * kH / 2);
  unsigned char* whole = malloc((size_t)kW * kH * 4);
  unsigned char* out = malloc((size_t)kW * kH * 4);
  memset(rgb, 0xee, (size_t)rgb_stride * kH / 2);
  glReadPixels(0, 0, kW / 2, kH / 2, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glReadPixels(rgb_x, kH / 2, rgb_w, kH / 2, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, whole);
  int rc = conf_check_error("glReadPixels") ? 3 : 0;
  long mismatches = 0;
  for (long i = 0; i < (long)kW * kH * 4; ++i) mismatches += whole[i] != c.buffer[i];
  if (mismatches) {
    fprintf(stderr, "glReadPixels(GL_RGBA) differs from the OSMesa buffer in %ld bytes\n",
            mismatches);
    rc = 4;
  }

  /* The composite, bottom row first like the OSMesa buffer. */
  memcpy(out, c.buffer, (size_t)kW * kH * 4);
  for (int y = 0; y < kH / 2; ++y) {
    memcpy(out + ((size_t)y * kW + kW / 2) * 4, rgba + (size_t)y * (kW / 2) * 4, (size_t)kW / 2 * 4);
    for (int x = 0; x < kW / 2; ++x) {
      unsigned char* o = out + ((size_t)(y + kH / 2) * kW + kW / 2 + x) * 4;
      if (x < rgb_w) {
        memcpy(o, rgb + (size_t)y * rgb_stride + (size_t)x * 3, 3);
        o[3] = 255;
      } else {
        o[0] = o[1] = o[2] = 0, o[3] = 255;
      }
    }
  }
  if (!conf_write_png(c.out_path, out, kW, kH)) rc = 2;
  OSMesaDestroyContext(c.ctx);
  free(c.buffer);
  free(rgba);
  free(rgb);
  free(whole);
  free(out);
  return rc;
}
