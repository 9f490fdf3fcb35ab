// Benchmark scene (d), shadelab's side: per-pixel Phong (Blinn-Phong, the GL lighting
// equation evaluated at every pixel) with 8 attenuated point lights on a sphere filling a
// 1920x1080 frame, through the core library's draw_triangles with a persistent
// PipelineContext and framebuffer. Mesa's side is phong_glsl.c (the same scene as a GLSL
// shader); the lights, material and camera match it.
//   bench_phong_shadelab [--size WxH] [--frames F] [--warmup W] [--png FILE]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "shadelab/image.hpp"
#include "shadelab/light.hpp"
#include "shadelab/material.hpp"
#include "shadelab/pipeline.hpp"
#include "shadelab/shapes.hpp"

using namespace shadelab;

int main(int argc, char** argv) {
  int width = 1920, height = 1080, frames = 10, warmup = 2;
  const char* png = nullptr;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--size") && std::sscanf(argv[i + 1], "%dx%d", &width, &height) == 2) continue;
    if (!std::strcmp(argv[i], "--frames")) frames = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--warmup")) warmup = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--png")) png = argv[i + 1];
    else return std::fprintf(stderr, "unknown option %s\n", argv[i]), 2;
  }
  if (frames < 1 || width < 1 || height < 1) return 2;

  // Sphere of radius 1.9 at z = -5 under a 30-degree vertical field of view: it fills the
  // frame's height and more.
  Mesh sphere = make_sphere({1.9f, 96, 48});
  glm::mat4 modelview = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -5));
  std::vector<glm::vec4> positions;
  std::vector<glm::vec3> normals;
  for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
    positions.push_back(modelview * glm::vec4(sphere.positions[i], 1.0f));
    normals.push_back(sphere.normals[i]);
  }
  std::vector<Light> lights(8);
  for (int i = 0; i < 8; ++i) {
    double a = 2.0 * M_PI * i / 8.0;
    Light& l = lights[std::size_t(i)];
    l.position = {float(3.0 * std::cos(a)), float(1.5 * std::sin(2.0 * a)), float(2.5 + std::sin(a)) - 5.0f, 1.0f};
    glm::vec4 col{0.12f + 0.28f * float(i & 1), 0.12f + 0.28f * float((i >> 1) & 1), 0.12f + 0.28f * float((i >> 2) & 1), 1.0f};
    l.ambient = {0, 0, 0, 1};
    l.diffuse = l.specular = col;
    l.constant_attenuation = 0.5f;
    l.linear_attenuation = 0.1f;
    l.quadratic_attenuation = 0.02f;
    l.enabled = true;
  }
  ShadeState shade;
  shade.lighting = true;
  shade.shading = ShadingMode::kPhong;
  shade.model.ambient = {0.05f, 0.05f, 0.05f, 1.0f};
  shade.lights = lights;
  shade.front.ambient = shade.front.diffuse = {0.6f, 0.6f, 0.6f, 1.0f};
  shade.front.specular = {0.5f, 0.5f, 0.5f, 1.0f};
  shade.front.shininess = 40.0f;
  shade.back = shade.front;
  VertexInput in;
  in.positions = positions;
  in.normals = normals;
  in.triangles = sphere.triangles;
  double h = 1.0 * std::tan(30.0 * M_PI / 360.0), aspect = double(width) / height;
  glm::mat4 projection = glm::frustum(float(-h * aspect), float(h * aspect), float(-h), float(h), 1.0f, 20.0f);
  Viewport vp{0, 0, width, height, 0.0f, 1.0f};
  FragmentState frag;
  frag.cull = CullMode::kBack;
  Framebuffer fb;
  fb.resize(width, height);
  PipelineContext context;

  std::vector<double> times;
  for (int f = -warmup; f < frames; ++f) {
    auto t0 = std::chrono::steady_clock::now();
    // Cleared as the GL library clears (glClear): each tile by the draw into it, while it is
    // in the cache; the tiles the sphere leaves are cleared at the end.
    context.clear_later(fb, PipelineContext::PendingClears::kColor | PipelineContext::PendingClears::kDepth,
                        {0.1f, 0.1f, 0.12f, 1.0f}, 1.0f);
    draw_triangles(fb, projection, vp, frag, shade, in, nullptr, &context);
    context.apply_pending_clears(fb);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (f >= 0) times.push_back(ms);
  }
  std::sort(times.begin(), times.end());
  std::size_t n = times.size();
  double median = n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
  std::printf("RESULT scene=phong size=%dx%d triangles=%zu frames=%d median_ms=%.3f min_ms=%.3f max_ms=%.3f\n",
              width, height, sphere.triangles.size(), frames, median, times.front(), times.back());
  if (png) {
    std::string error;
    if (!write_png(fb.to_image(), png, &error)) return std::fprintf(stderr, "%s\n", error.c_str()), 1;
  }
  return 0;
}
