// Drawing allocates nothing once a program's buffers have grown: a few frames of the
// benchmark's kinds of drawing (vertex arrays lit by 8 lights, a glBegin/glEnd wall under a
// spot light, blended rectangles, clears and glFinish) through libshadelab-gl, and per-pixel
// Phong through the core library's fast pipeline, are drawn once to warm up, then again
// while every operator new in the process is counted. Exit status 0 when none was made.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <vector>

#include <glm/ext/matrix_clip_space.hpp>

#include "shadelab/pipeline.hpp"

namespace {

std::atomic<bool> counting{false};
std::atomic<long> allocations{0};

void* allocate(std::size_t n) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}

}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace {

constexpr int kSize = 256;

struct Sphere {
  std::vector<GLfloat> points;  // positions, which are also the normals
  std::vector<GLuint> indices;
};

Sphere make_sphere(int stacks, int slices) {
  Sphere s;
  for (int j = 0; j <= stacks; ++j) {
    double phi = M_PI * j / stacks;
    for (int i = 0; i <= slices; ++i) {
      double theta = 2.0 * M_PI * i / slices;
      s.points.push_back(GLfloat(std::sin(phi) * std::cos(theta)));
      s.points.push_back(GLfloat(std::cos(phi)));
      s.points.push_back(GLfloat(-std::sin(phi) * std::sin(theta)));
    }
  }
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      GLuint a = GLuint(j * (slices + 1) + i), b = a + 1, c = a + GLuint(slices + 1), d = c + 1;
      for (GLuint v : {a, c, b, b, c, d}) s.indices.push_back(v);
    }
  }
  return s;
}

void set_up_lights() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.3, 0.3, -0.3, 0.3, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -5.0f);
  for (int i = 0; i < 8; ++i) {
    GLfloat pos[] = {GLfloat(3.0 * std::cos(i)), GLfloat(std::sin(2.0 * i)), 2.5f, 1.0f};
    glLightfv(GL_LIGHT0 + GLenum(i), GL_POSITION, pos);
    glLightf(GL_LIGHT0 + GLenum(i), GL_LINEAR_ATTENUATION, 0.1f);
    glEnable(GL_LIGHT0 + GLenum(i));
  }
  glEnable(GL_DEPTH_TEST);
}

// One frame of every kind of drawing the benchmarks do.
void frame(const Sphere& sphere) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glDisable(GL_BLEND);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, sphere.points.data());
  glNormalPointer(GL_FLOAT, 0, sphere.points.data());
  glDrawElements(GL_TRIANGLES, GLsizei(sphere.indices.size()), GL_UNSIGNED_INT, sphere.indices.data());
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glBegin(GL_QUADS);  // a wall of 40 x 40 quads, long enough for the threaded path
  for (int j = 0; j < 40; ++j) {
    for (int i = 0; i < 40; ++i) {
      float x0 = -1.0f + 0.05f * i, y0 = -1.0f + 0.05f * j, x1 = x0 + 0.05f, y1 = y0 + 0.05f;
      glVertex3f(x0, y0, -1.0f), glVertex3f(x1, y0, -1.0f), glVertex3f(x1, y1, -1.0f), glVertex3f(x0, y1, -1.0f);
    }
  }
  glEnd();
  glDisable(GL_LIGHTING);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(0.2f, 0.4f, 1.0f, 0.3f);
  glRectf(-1.0f, -1.0f, 1.0f, 1.0f);
  glFinish();
}

// Per-pixel Phong through the core library's fast pipeline, 8 lights, on the same sphere.
struct PhongDraw {
  shadelab::Framebuffer fb;
  shadelab::PipelineContext context{2};
  std::vector<glm::vec4> positions;
  std::vector<glm::vec3> normals;
  std::vector<shadelab::Triangle> triangles;
  std::vector<shadelab::Light> lights;
  shadelab::ShadeState shade;
  shadelab::FragmentState fragments;

  explicit PhongDraw(const Sphere& s) {
    fb.resize(kSize, kSize);
    for (std::size_t i = 0; i + 2 < s.points.size(); i += 3) {
      glm::vec3 n(s.points[i], s.points[i + 1], s.points[i + 2]);
      positions.emplace_back(n.x, n.y, n.z - 5.0f, 1.0f);
      normals.push_back(n);
    }
    for (std::size_t i = 0; i + 2 < s.indices.size(); i += 3) {
      triangles.push_back({s.indices[i], s.indices[i + 1], s.indices[i + 2]});
    }
    for (int i = 0; i < 8; ++i) {
      shadelab::Light l;
      l.diffuse = l.specular = glm::vec4(0.6f, 0.6f, 0.6f, 1.0f);
      l.position = glm::vec4(3.0f * std::cos(float(i)), std::sin(2.0f * float(i)), -2.0f, 1.0f);
      lights.push_back(l);
    }
    shade.lighting = true;
    shade.shading = shadelab::ShadingMode::kPhong;
    shade.lights = lights;
  }

  void draw() {
    fb.clear_color({0.1f, 0.1f, 0.1f, 1.0f});
    fb.clear_depth(1.0f);
    const glm::mat4 projection = glm::frustum(-0.3f, 0.3f, -0.3f, 0.3f, 1.0f, 20.0f);
    shadelab::Viewport viewport;
    viewport.width = kSize;
    viewport.height = kSize;
    shadelab::VertexInput in;
    in.positions = positions;
    in.normals = normals;
    in.triangles = triangles;
    shadelab::draw_triangles(fb, projection, viewport, fragments, shade, in, nullptr, &context);
  }
};

}  // namespace

int main() {
  std::vector<unsigned char> buffer(std::size_t(kSize) * kSize * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kSize, kSize)) {
    std::fprintf(stderr, "no context\n");
    return 1;
  }
  glViewport(0, 0, kSize, kSize);
  set_up_lights();
  const Sphere sphere = make_sphere(60, 120);  // 14,400 triangles: the threaded array path
  PhongDraw phong(sphere);
  for (int i = 0; i < 3; ++i) frame(sphere), phong.draw();  // buffers grow to their sizes
  counting = true;
  for (int i = 0; i < 5; ++i) frame(sphere);
  const long gl = allocations.exchange(0);
  for (int i = 0; i < 5; ++i) phong.draw();
  counting = false;
  const long core = allocations.load();
  OSMesaDestroyContext(ctx);
  std::printf("allocations in 5 steady frames: libshadelab-gl %ld, core fast pipeline (Phong) %ld\n", gl, core);
  return gl == 0 && core == 0 ? 0 : 1;
}
