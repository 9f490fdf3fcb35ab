/* Benchmark scene (d), Mesa's side: per-pixel Blinn-Phong with 8 attenuated point lights on a
 * sphere filling a 1920x1080 frame, as a GLSL 3.30 shader in an OSMesa core-profile context
 * (llvmpipe compiles it with LLVM). The fragment shader evaluates OpenGL's lighting equation
 * (emission 0, global ambient, per light ambient 0 + diffuse + Blinn specular, attenuation,
 * clamped) exactly as shadelab's Phong mode does; scene, lights and material match
 * phong_shadelab.cpp.
 *   bench_phong_glsl [--size WxH] [--frames F] [--warmup W] [--png FILE]  */
#define _DEFAULT_SOURCE 1
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stb_image_write.h>

static const char* kVertex =
    "#version 330 core\n"
    "layout(location = 0) in vec3 position;\n"
    "layout(location = 1) in vec3 normal;\n"
    "uniform mat4 projection;\n"
    "out vec3 eye_position;\n"
    "out vec3 eye_normal;\n"
    "void main() {\n"
    "  eye_position = position + vec3(0.0, 0.0, -5.0);\n"
    "  eye_normal = normal;\n"
    "  gl_Position = projection * vec4(eye_position, 1.0);\n"
    "}\n";

static const char* kFragment =
    "#version 330 core\n"
    "in vec3 eye_position;\n"
    "in vec3 eye_normal;\n"
    "uniform vec3 light_position[8];\n"
    "uniform vec3 light_color[8];\n"
    "out vec4 color;\n"
    "void main() {\n"
    "  vec3 n = normalize(eye_normal);\n"
    "  vec3 v = vec3(0.0, 0.0, 1.0);\n"
    "  vec3 diffuse_colour = vec3(0.6), specular_colour = vec3(0.5);\n"
    "  vec3 sum = diffuse_colour * vec3(0.05);\n"
    "  for (int i = 0; i < 8; ++i) {\n"
    "    vec3 d = light_position[i] - eye_position;\n"
    "    float dist = length(d);\n"
    "    vec3 l = d / dist;\n"
    "    float att = 1.0 / (0.5 + 0.1 * dist + 0.02 * dist * dist);\n"
    "    float ndl = dot(n, l);\n"
    "    if (ndl > 0.0) {\n"
    "      vec3 h = normalize(l + v);\n"
    "      float s = max(dot(n, h), 0.0);\n"
    "      sum += att * (ndl * diffuse_colour + pow(s, 40.0) * specular_colour) * light_color[i];\n"
    "    }\n"
    "  }\n"
    "  color = vec4(clamp(sum, 0.0, 1.0), 1.0);\n"
    "}\n";

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

static int compare_doubles(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

static GLuint compile(GLenum kind, const char* source) {
  GLuint s = glCreateShader(kind);
  glShaderSource(s, 1, &source, NULL);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(s, sizeof log, NULL, log);
    fprintf(stderr, "shader: %s\n", log);
    exit(1);
  }
  return s;
}

int main(int argc, char** argv) {
  int width = 1920, height = 1080, frames = 10, warmup = 2;
  const char* png = NULL;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--size") && sscanf(argv[i + 1], "%dx%d", &width, &height) == 2) continue;
    if (!strcmp(argv[i], "--frames")) frames = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--warmup")) warmup = atoi(argv[i + 1]);
    else if (!strcmp(argv[i], "--png")) png = argv[i + 1];
    else return fprintf(stderr, "unknown option %s\n", argv[i]), 2;
  }
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE,
                         OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                         OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, NULL);
  unsigned char* buffer = malloc((size_t)width * height * 4);
  if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, width, height)) {
    fprintf(stderr, "no OSMesa core-profile context\n");
    return 1;
  }
  /* The sphere: radius 1.9, 96 slices x 48 stacks (as shadelab's make_sphere; 9,216 triangles). */
  const int slices = 96, stacks = 48;
  int nv = (slices + 1) * (stacks + 1), ni = 6 * slices * stacks;
  float* verts = malloc(sizeof(float) * 6 * (size_t)nv);
  GLuint* idx = malloc(sizeof(GLuint) * (size_t)ni);
  for (int j = 0, v = 0; j <= stacks; ++j)
    for (int i = 0; i <= slices; ++i, ++v) {
      double phi = M_PI * j / stacks, theta = 2.0 * M_PI * i / slices;
      float n[3] = {(float)(sin(phi) * cos(theta)), (float)cos(phi), (float)(-sin(phi) * sin(theta))};
      for (int k = 0; k < 3; ++k) verts[6 * v + k] = 1.9f * n[k], verts[6 * v + 3 + k] = n[k];
    }
  for (int j = 0, k = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i, k += 6) {
      GLuint a = (GLuint)(j * (slices + 1) + i), b = a + 1, c = a + (GLuint)(slices + 1), d = c + 1;
      GLuint t[6] = {a, c, b, b, c, d};
      memcpy(&idx[k], t, sizeof t);
    }
  GLuint vao, vbo, ibo;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(float) * 6 * (size_t)nv), verts, GL_STATIC_DRAW);
  glGenBuffers(1, &ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(sizeof(GLuint) * (size_t)ni), idx, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)(3 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  GLuint program = glCreateProgram();
  glAttachShader(program, compile(GL_VERTEX_SHADER, kVertex));
  glAttachShader(program, compile(GL_FRAGMENT_SHADER, kFragment));
  glLinkProgram(program);
  glUseProgram(program);
  double h = tan(30.0 * M_PI / 360.0), aspect = (double)width / height;
  float proj[16] = {0};
  proj[0] = (float)(1.0 / (h * aspect)), proj[5] = (float)(1.0 / h);
  proj[10] = -21.0f / 19.0f, proj[11] = -1.0f, proj[14] = -40.0f / 19.0f; /* frustum near 1, far 20 */
  glUniformMatrix4fv(glGetUniformLocation(program, "projection"), 1, GL_FALSE, proj);
  float lp[24], lc[24];
  for (int i = 0; i < 8; ++i) {
    double a = 2.0 * M_PI * i / 8.0;
    lp[3 * i] = (float)(3.0 * cos(a)), lp[3 * i + 1] = (float)(1.5 * sin(2.0 * a)), lp[3 * i + 2] = (float)(2.5 + sin(a)) - 5.0f;
    lc[3 * i] = 0.12f + 0.28f * (i & 1), lc[3 * i + 1] = 0.12f + 0.28f * ((i >> 1) & 1), lc[3 * i + 2] = 0.12f + 0.28f * ((i >> 2) & 1);
  }
  glUniform3fv(glGetUniformLocation(program, "light_position"), 8, lp);
  glUniform3fv(glGetUniformLocation(program, "light_color"), 8, lc);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  double* times = malloc(sizeof(double) * (size_t)frames);
  for (int f = -warmup; f < frames; ++f) {
    double t0 = now_ms();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, ni, GL_UNSIGNED_INT, 0);
    glFinish();
    if (f >= 0) times[f] = now_ms() - t0;
  }
  qsort(times, (size_t)frames, sizeof(double), compare_doubles);
  double median = frames % 2 ? times[frames / 2] : 0.5 * (times[frames / 2 - 1] + times[frames / 2]);
  printf("RESULT scene=phong size=%dx%d triangles=%d frames=%d median_ms=%.3f min_ms=%.3f max_ms=%.3f\n",
         width, height, ni / 3, frames, median, times[0], times[frames - 1]);
  if (png) {
    /* RGB, top row first (OpenGL's rows run bottom up). */
    unsigned char* rgb = malloc((size_t)width * height * 3);
    if (!rgb) return 1;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        memcpy(&rgb[((size_t)y * width + x) * 3], &buffer[((size_t)(height - 1 - y) * width + x) * 4], 3);
    int ok = stbi_write_png(png, width, height, 3, rgb, width * 3);
    free(rgb);
    if (!ok) return 1;
  }
  OSMesaDestroyContext(ctx);
  return 0;
}
