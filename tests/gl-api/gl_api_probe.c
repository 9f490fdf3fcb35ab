/* What libshadelab-gl answers about its own API, for gl/api/generate.py check-api (the test
 * gl_api_exports): `gl_api_probe version` prints glGetString(GL_VERSION) of a new OSMesa
 * context; `gl_api_probe procs` reads names from stdin, one a line, and prints each with
 * "same" when OSMesaGetProcAddress returns the function the dynamic linker finds by that
 * name, "null" when both find none, and "differs" otherwise. */
#define _GNU_SOURCE 1
#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

#include <GL/gl.h>
#include <GL/osmesa.h>

static int print_version(void) {
  static unsigned char buffer[4 * 4 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 4, 4)) {
    fprintf(stderr, "gl_api_probe: no OSMesa context\n");
    return 1;
  }
  const char* version = (const char*)glGetString(GL_VERSION);
  printf("%s\n", version ? version : "(null)");
  OSMesaDestroyContext(ctx);
  return version ? 0 : 1;
}

static int print_procs(void) {
  char name[256];
  while (fgets(name, sizeof name, stdin)) {
    name[strcspn(name, "\r\n")] = '\0';
    if (!name[0]) continue;
    void* linked = dlsym(RTLD_DEFAULT, name);
    OSMESAproc found = OSMesaGetProcAddress(name);
    const char* verdict = "differs";
    if (!linked && !found) verdict = "null";
    else if (linked && found && (void*)found == linked) verdict = "same";
    printf("%s %s\n", name, verdict);
  }
  return 0;
}

int main(int argc, char** argv) {
  if (argc == 2 && strcmp(argv[1], "version") == 0) return print_version();
  if (argc == 2 && strcmp(argv[1], "procs") == 0) return print_procs();
  fprintf(stderr, "usage: gl_api_probe version|procs\n");
  return 2;
}
