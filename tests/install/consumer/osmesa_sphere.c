/* An OSMesa program built against the installed libshadelab-gl (through pkg-config or the CMake
 * package): a red sphere of libshadelab-glut, lit head-on by a white directional light, on a
 * blue background. Its centre is the material's diffuse red (N.L = 1), a corner the clear
 * colour. Prints the renderer and "ok", or what differs (exit status 1). */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <GL/shadelab_glut.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { kSize = 64 };

static int expect_pixel(const GLubyte* rgba, int x, int y, int r, int g, int b) {
  const GLubyte* p = rgba + (y * kSize + x) * 4;
  if (abs(p[0] - r) <= 2 && abs(p[1] - g) <= 2 && abs(p[2] - b) <= 2) return 1;
  printf("pixel (%d, %d) is (%d, %d, %d), expected (%d, %d, %d)\n", x, y, p[0], p[1], p[2], r, g, b);
  return 0;
}

int main(void) {
  static GLubyte buffer[kSize * kSize * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, kSize, kSize)) {
    printf("cannot create or bind an OSMesa context\n");
    return 1;
  }
  printf("GL_RENDERER: %s\n", (const char*)glGetString(GL_RENDERER));
  const GLfloat light_dir[] = {0, 0, 1, 0};
  const GLfloat black[] = {0, 0, 0, 1};
  const GLfloat red[] = {1, 0, 0, 1};
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
  glLightfv(GL_LIGHT0, GL_POSITION, light_dir);
  glMaterialfv(GL_FRONT, GL_AMBIENT, black);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1, 1, -1, 1, -2, 2);
  glMatrixMode(GL_MODELVIEW);
  glutSolidSphere(0.8, 48, 24);
  glFinish();
  int ok = strstr((const char*)glGetString(GL_RENDERER), "shadelab") != NULL;
  ok &= expect_pixel(buffer, kSize / 2, kSize / 2, 255, 0, 0);
  ok &= expect_pixel(buffer, 0, 0, 0, 0, 255);
  ok &= glGetError() == GL_NO_ERROR;
  OSMesaDestroyContext(ctx);
  printf("%s\n", ok ? "ok" : "FAIL");
  return ok ? 0 : 1;
}
