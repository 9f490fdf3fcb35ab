/* libshadelab-glut's shapes against freeglut's, both drawn on Mesa: every GLUT shape function,
   wire and solid, lit and unlit, drawn once by Debian's freeglut (libglut) and once by the
   function of the same name in libshadelab-glut, which is linked into this program with its
   glut* symbols renamed shadelab_glut* (objcopy, tests/platform/rename_glut.cmake). Each case
   has a cell of its own; the program prints per case the share of the cell's pixels within
   2/255 of freeglut's and the same share of the pixels that either drew, writes both images
   and a difference image (PPM) and exits 1 when a case is below the conformance bar (99.5 %)
   in either. Run under with_xvfb.sh with __GLX_VENDOR_LIBRARY_NAME=mesa, so that GLVND sends both
   to Mesa's llvmpipe.

     glut_shapes_vs_freeglut OUT_DIR */
#define _GNU_SOURCE /* dladdr, RTLD_DEFAULT */
#include <GL/freeglut.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* libshadelab-glut's functions, renamed (the signatures of <GL/shadelab_glut.h>). */
void shadelab_glutWireSphere(double radius, GLint slices, GLint stacks);
void shadelab_glutSolidSphere(double radius, GLint slices, GLint stacks);
void shadelab_glutWireCube(double size);
void shadelab_glutSolidCube(double size);
void shadelab_glutWireTorus(double inner, double outer, GLint sides, GLint rings);
void shadelab_glutSolidTorus(double inner, double outer, GLint sides, GLint rings);
void shadelab_glutWireCone(double base, double height, GLint slices, GLint stacks);
void shadelab_glutSolidCone(double base, double height, GLint slices, GLint stacks);
void shadelab_glutWireTeapot(double size);
void shadelab_glutSolidTeapot(double size);
void shadelab_glutWireTetrahedron(void);
void shadelab_glutSolidTetrahedron(void);
void shadelab_glutWireOctahedron(void);
void shadelab_glutSolidOctahedron(void);
void shadelab_glutWireDodecahedron(void);
void shadelab_glutSolidDodecahedron(void);
void shadelab_glutWireIcosahedron(void);
void shadelab_glutSolidIcosahedron(void);
void shadelab_glutWireRhombicDodecahedron(void);
void shadelab_glutSolidRhombicDodecahedron(void);

enum { kCols = 6, kRows = 6, kCell = 128, kTolerance = 2 };
static const double kMinPercent = 99.5;

static int use_shadelab = 0; /* which library the cases call */
#define CALL(fn, args) (use_shadelab ? shadelab_##fn args : fn args)

/* How a case is drawn, besides its shape. */
enum {
  kLit = 1,        /* GL_LIGHTING with a directional light */
  kFlat = 2,       /* glShadeModel(GL_FLAT) */
  kStipple = 4,    /* glLineStipple(2, 0x33F3) */
  kWide = 8,       /* glLineWidth(2) */
  kCullBack = 16,  /* GL_CULL_FACE, back faces */
  kTwoSided = 32,  /* GL_LIGHT_MODEL_TWO_SIDE with a blue back material */
  kPointLight = 64 /* a positional light near the shape instead of the directional one */
};

typedef struct {
  const char* name;   /* freeglut's function, checked to come from libglut */
  const char* label;  /* what the report calls the case */
  void (*draw)(void); /* calls `name` through CALL */
  int style;
  float extent; /* half the view's height at the origin, over the default's 4/3 */
} Case;

static void wire_sphere(void) { CALL(glutWireSphere, (1.0, 16, 10)); }
static void wire_sphere_coarse(void) { CALL(glutWireSphere, (0.9, 7, 5)); }
static void solid_sphere(void) { CALL(glutSolidSphere, (1.0, 24, 12)); }
static void solid_sphere_coarse(void) { CALL(glutSolidSphere, (1.0, 12, 8)); }
static void wire_cube(void) { CALL(glutWireCube, (1.3)); }
static void solid_cube(void) { CALL(glutSolidCube, (1.3)); }
static void wire_torus(void) { CALL(glutWireTorus, (0.3, 0.8, 10, 20)); }
static void solid_torus(void) { CALL(glutSolidTorus, (0.3, 0.85, 12, 24)); }
static void upright(void) { /* GLUT's cone points along +z */
  glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
  glTranslatef(0.0f, 0.0f, -0.8f);
}
static void wire_cone(void) {
  upright();
  CALL(glutWireCone, (0.8, 1.6, 12, 4));
}
static void solid_cone(void) {
  upright();
  CALL(glutSolidCone, (0.9, 1.6, 16, 3));
}
static void wire_teapot(void) { CALL(glutWireTeapot, (0.8)); }
static void solid_teapot(void) { CALL(glutSolidTeapot, (0.8)); }
static void wire_tetrahedron(void) { CALL(glutWireTetrahedron, ()); }
static void solid_tetrahedron(void) { CALL(glutSolidTetrahedron, ()); }
static void wire_octahedron(void) { CALL(glutWireOctahedron, ()); }
static void solid_octahedron(void) { CALL(glutSolidOctahedron, ()); }
static void wire_dodecahedron(void) { CALL(glutWireDodecahedron, ()); }
static void solid_dodecahedron(void) { CALL(glutSolidDodecahedron, ()); }
static void wire_icosahedron(void) { CALL(glutWireIcosahedron, ()); }
static void solid_icosahedron(void) { CALL(glutSolidIcosahedron, ()); }
static void wire_rhombic(void) { CALL(glutWireRhombicDodecahedron, ()); }
static void solid_rhombic(void) { CALL(glutSolidRhombicDodecahedron, ()); }

static const Case kCases[] = {
    {"glutWireSphere", "wire sphere, lit", wire_sphere, kLit, 1.0f},
    {"glutWireSphere", "wire sphere, stippled", wire_sphere_coarse, kStipple, 1.0f},
    {"glutSolidSphere", "solid sphere", solid_sphere, kLit, 1.0f},
    {"glutSolidSphere", "solid sphere, flat", solid_sphere_coarse, kLit | kFlat, 1.0f},
    {"glutWireCube", "wire cube, lit", wire_cube, kLit, 1.0f},
    {"glutWireCube", "wire cube, wide", wire_cube, kWide, 1.0f},
    {"glutSolidCube", "solid cube", solid_cube, kLit, 1.0f},
    {"glutSolidCube", "solid cube, point light", solid_cube, kLit | kPointLight, 1.0f},
    {"glutWireTorus", "wire torus, lit", wire_torus, kLit, 1.0f},
    {"glutWireTorus", "wire torus, stippled", wire_torus, kStipple, 1.0f},
    {"glutSolidTorus", "solid torus", solid_torus, kLit, 1.0f},
    {"glutSolidTorus", "solid torus, flat", solid_torus, kLit | kFlat, 1.0f},
    {"glutWireCone", "wire cone, lit", wire_cone, kLit, 1.0f},
    {"glutWireCone", "wire cone, stippled", wire_cone, kStipple, 1.0f},
    {"glutSolidCone", "solid cone", solid_cone, kLit, 1.0f},
    {"glutSolidCone", "solid cone, flat", solid_cone, kLit | kFlat, 1.0f},
    {"glutWireTeapot", "wire teapot, lit", wire_teapot, kLit, 1.0f},
    {"glutWireTeapot", "wire teapot, stippled", wire_teapot, kStipple, 1.0f},
    {"glutSolidTeapot", "solid teapot", solid_teapot, kLit, 1.0f},
    {"glutSolidTeapot", "solid teapot, flat", solid_teapot, kLit | kFlat, 1.0f},
    {"glutSolidTeapot", "solid teapot, back faces culled", solid_teapot, kLit | kCullBack, 1.0f},
    {"glutSolidTeapot", "solid teapot, two-sided", solid_teapot, kLit | kTwoSided, 1.0f},
    {"glutWireTetrahedron", "wire tetrahedron, lit", wire_tetrahedron, kLit | kPointLight, 1.0f},
    {"glutSolidTetrahedron", "solid tetrahedron", solid_tetrahedron, kLit | kPointLight, 1.0f},
    {"glutWireOctahedron", "wire octahedron, lit", wire_octahedron, kLit, 1.0f},
    {"glutSolidOctahedron", "solid octahedron", solid_octahedron, kLit | kPointLight, 1.0f},
    {"glutWireDodecahedron", "wire dodecahedron, lit", wire_dodecahedron, kLit, 1.5f},
    {"glutWireDodecahedron", "wire dodecahedron, stippled", wire_dodecahedron, kStipple, 1.5f},
    {"glutSolidDodecahedron", "solid dodecahedron", solid_dodecahedron, kLit, 1.5f},
    {"glutSolidDodecahedron", "solid dodecahedron, point light", solid_dodecahedron,
     kLit | kPointLight | kFlat, 1.5f},
    {"glutWireIcosahedron", "wire icosahedron, lit", wire_icosahedron, kLit, 1.0f},
    {"glutWireIcosahedron", "wire icosahedron, stippled", wire_icosahedron, kStipple, 1.0f},
    {"glutSolidIcosahedron", "solid icosahedron", solid_icosahedron, kLit | kPointLight, 1.0f},
    {"glutWireRhombicDodecahedron", "wire rhombic dodecahedron, lit", wire_rhombic, kLit, 1.0f},
    {"glutSolidRhombicDodecahedron", "solid rhombic dodecahedron", solid_rhombic, kLit, 1.0f},
    {"glutSolidRhombicDodecahedron", "solid rhombic dodecahedron, point light", solid_rhombic,
     kLit | kPointLight | kCullBack, 1.0f},
};
enum { kCaseCount = sizeof kCases / sizeof kCases[0] };

static const char* out_dir = ".";
static unsigned char* images[2]; /* RGB, bottom row first: freeglut's, libshadelab-glut's */

/* Cell `i` (row 0 at the top) with a perspective view of the unit box, turned a little. */
static void cell(int i, float extent) {
  const int col = i % kCols, row = i / kCols;
  glViewport(col * kCell, (kRows - 1 - row) * kCell, kCell, kCell);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5 * extent, 0.5 * extent, -0.5 * extent, 0.5 * extent, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.0f);
  glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(-30.0f, 0.0f, 1.0f, 0.0f);
}

/* The state a case's style asks for, set before the shape is drawn and undone after. No
   GL_NORMALIZE: lighting sees the normals as each library gives them. */
static void begin_style(int i, int style) {
  static const float colours[5][3] = {{0.9f, 0.4f, 0.3f},
                                      {0.4f, 0.9f, 0.5f},
                                      {0.3f, 0.6f, 1.0f},
                                      {1.0f, 0.9f, 0.3f},
                                      {0.8f, 0.5f, 0.9f}};
  const float* c = colours[i % 5];
  const GLfloat directional[] = {1.0f, 1.0f, 1.0f, 0.0f}, point[] = {1.2f, 1.6f, 2.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, style & kPointLight ? point : directional);
  if (style & kLit) {
    GLfloat diffuse[] = {c[0], c[1], c[2], 1.0f},
            ambient[] = {c[0] * 0.3f, c[1] * 0.3f, c[2] * 0.3f, 1.0f};
    const GLfloat specular[] = {0.8f, 0.8f, 0.8f, 1.0f}, back[] = {0.2f, 0.3f, 0.9f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
    if (style & kTwoSided) glMaterialfv(GL_BACK, GL_DIFFUSE, back);
    glEnable(GL_LIGHTING);
  } else {
    glColor3f(c[0], c[1], c[2]);
  }
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, style & kTwoSided ? GL_TRUE : GL_FALSE);
  if (style & kFlat) glShadeModel(GL_FLAT);
  if (style & kStipple) glEnable(GL_LINE_STIPPLE), glLineStipple(2, 0x33F3);
  if (style & kWide) glLineWidth(2.0f);
  if (style & kCullBack) glEnable(GL_CULL_FACE);
}

static void end_style(void) {
  glDisable(GL_LIGHTING);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  glShadeModel(GL_SMOOTH);
  glDisable(GL_LINE_STIPPLE);
  glLineWidth(1.0f);
  glDisable(GL_CULL_FACE);
}

static void draw_all(void) {
  glClearColor(0.1f, 0.1f, 0.14f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (int i = 0; i < kCaseCount; ++i) {
    cell(i, kCases[i].extent);
    begin_style(i, kCases[i].style);
    kCases[i].draw();
    end_style();
  }
}

static unsigned char* read_window(void) {
  unsigned char* pixels = malloc((size_t)kCols * kCell * kRows * kCell * 3);
  if (!pixels) exit(1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, kCols * kCell, kRows * kCell, GL_RGB, GL_UNSIGNED_BYTE, pixels);
  return pixels;
}

static int write_ppm(const char* name, const unsigned char* rgb) {
  char path[4096];
  snprintf(path, sizeof path, "%s/%s", out_dir, name);
  FILE* f = fopen(path, "wb");
  if (!f) {
    fprintf(stderr, "glut_shapes_vs_freeglut: cannot write %s\n", path);
    return 0;
  }
  const int w = kCols * kCell, h = kRows * kCell;
  fprintf(f, "P6\n%d %d\n255\n", w, h);
  for (int y = h - 1; y >= 0; --y) fwrite(rgb + (size_t)y * w * 3, 1, (size_t)w * 3, f);
  return fclose(f) == 0;
}

static int channel_gap(const unsigned char* a, const unsigned char* b) {
  int gap = 0;
  for (int k = 0; k < 3; ++k) {
    int d = abs((int)a[k] - (int)b[k]);
    if (d > gap) gap = d;
  }
  return gap;
}

/* Compares the two images cell by cell; fills `diff` (grey where within the tolerance, red
   where not). Returns the number of cases below the bar. */
static int compare(unsigned char* diff) {
  const int w = kCols * kCell;
  const unsigned char background[3] = {26, 26, 36}; /* (0.1, 0.1, 0.14) */
  int failures = 0;
  printf("%-44s %9s %22s %6s\n", "case (libshadelab-glut vs freeglut)", "cell", "drawn pixels",
         "worst");
  for (int i = 0; i < kCaseCount; ++i) {
    const int x0 = (i % kCols) * kCell, y0 = (kRows - 1 - i / kCols) * kCell;
    long good = 0, drawn = 0, drawn_good = 0;
    int worst = 0;
    for (int y = y0; y < y0 + kCell; ++y) {
      for (int x = x0; x < x0 + kCell; ++x) {
        const size_t o = ((size_t)y * w + x) * 3;
        const unsigned char *a = images[0] + o, *b = images[1] + o;
        const int gap = channel_gap(a, b);
        const int ok = gap <= kTolerance;
        const int is_drawn =
            channel_gap(a, background) > kTolerance || channel_gap(b, background) > kTolerance;
        good += ok, drawn += is_drawn, drawn_good += ok && is_drawn;
        if (gap > worst) worst = gap;
        for (int k = 0; k < 3; ++k)
          diff[o + k] = ok ? (unsigned char)(a[k] / 3) : (k == 0 ? 255 : 0);
      }
    }
    const double percent = 100.0 * good / (kCell * kCell);
    const double drawn_percent = drawn ? 100.0 * drawn_good / drawn : 100.0;
    const int pass = percent >= kMinPercent && drawn_percent >= kMinPercent && drawn > 0;
    failures += !pass;
    printf("%-44s %8.3f%% %8.3f%% of %6ld %6d%s\n", kCases[i].label, percent, drawn_percent, drawn,
           worst, pass ? "" : "   FAIL");
  }
  return failures;
}

/* Each freeglut function a case calls must be libglut's: were one of libshadelab-glut's
   functions left unrenamed, it would stand in for freeglut's and the comparison would be void. */
static int check_freeglut_symbols(void) {
  for (int i = 0; i < kCaseCount; ++i) {
    void* f = dlsym(RTLD_DEFAULT, kCases[i].name);
    Dl_info info;
    if (!f || !dladdr(f, &info) || !info.dli_fname || !strstr(info.dli_fname, "libglut")) {
      fprintf(stderr, "glut_shapes_vs_freeglut: %s does not come from freeglut's libglut (%s)\n",
              kCases[i].name, f && info.dli_fname ? info.dli_fname : "not found");
      return 0;
    }
  }
  return 1;
}

static void display(void) {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHT0);
  for (use_shadelab = 0; use_shadelab < 2; ++use_shadelab) {
    draw_all();
    glFinish();
    images[use_shadelab] = read_window();
  }
  if (glGetError() != GL_NO_ERROR) {
    fprintf(stderr, "glut_shapes_vs_freeglut: a GL error was raised\n");
    exit(1);
  }
  unsigned char* diff = malloc((size_t)kCols * kCell * kRows * kCell * 3);
  if (!diff) exit(1);
  const int failures = compare(diff);
  int written = write_ppm("freeglut.ppm", images[0]) && write_ppm("shadelab.ppm", images[1]) &&
                write_ppm("diff.ppm", diff);
  printf(
      "%d of %d cases within %d/255 on at least %.1f %% of their cell's pixels and of the drawn "
      "ones\n",
      kCaseCount - failures, kCaseCount, kTolerance, kMinPercent);
  exit(failures == 0 && written ? 0 : 1);
}

/* mkdir -p */
static int make_directories(char* path) {
  for (char* p = path + 1; *p; ++p) {
    if (*p != '/') continue;
    *p = '\0';
    mkdir(path, 0777);
    *p = '/';
  }
  struct stat st;
  return mkdir(path, 0777) == 0 || (stat(path, &st) == 0 && S_ISDIR(st.st_mode));
}

int main(int argc, char** argv) {
  glutInit(&argc, argv);
  if (argc != 2) {
    fprintf(stderr, "usage: glut_shapes_vs_freeglut OUT_DIR\n");
    return 2;
  }
  out_dir = argv[1];
  if (!make_directories(argv[1])) {
    fprintf(stderr, "glut_shapes_vs_freeglut: cannot create %s\n", argv[1]);
    return 1;
  }
  if (!check_freeglut_symbols()) return 1;
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
  glutInitWindowSize(kCols * kCell, kRows * kCell);
  glutCreateWindow("shadelab platform test: libshadelab-glut against freeglut");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
