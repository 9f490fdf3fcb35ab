// Micro-benchmarks of the fast pipeline's stages, one number per stage, so that a regression
// in one stage shows up on its own line (items/s):
//   BM_VertexLighting  vertices lit, projected and mapped to window space (vertex stage only)
//   BM_TriangleSetup   small triangles through setup and binning (setup stage only)
//   BM_Fill/*          pixels of a full-HD frame through draw_triangles (all stages; the
//                      2-triangle frame makes it all raster/fragment work)
// Every benchmark keeps one PipelineContext alive and draws once before timing, so the timed
// loop allocates nothing. Geometry is in "pixel" eye space: an orthographic projection maps
// eye (x, y) in [0, 1920] x [0, 1080] to the same window coordinates.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "fast/context.hpp"
#include "fast/plan.hpp"
#include "fast/setup.hpp"
#include "fast/simd_targets.hpp"
#include "fast/vertex_stage.hpp"
#include "shadelab/pipeline.hpp"

namespace {

using namespace shadelab;

constexpr int kWidth = 1920, kHeight = 1080;

glm::mat4 screen_projection() { return glm::ortho(0.0f, float(kWidth), 0.0f, float(kHeight), -1.0f, 1.0f); }

Viewport screen_viewport() {
  Viewport v;
  v.width = kWidth;
  v.height = kHeight;
  return v;
}

// `count` white positional lights hovering over the screen, with attenuation: the most
// expensive common light (direction, distance and half vector per point).
std::vector<Light> make_lights(int count) {
  std::vector<Light> lights;
  for (int i = 0; i < count; ++i) {
    Light l;
    float a = 6.2831853f * float(i) / float(count);
    l.position = {kWidth * (0.5f + 0.3f * std::cos(a)), kHeight * (0.5f + 0.3f * std::sin(a)), 800.0f, 1.0f};
    l.ambient = {0.05f, 0.05f, 0.05f, 1.0f};
    l.diffuse = l.specular = {0.6f, 0.6f, 0.6f, 1.0f};
    l.linear_attenuation = 1e-4f;
    lights.push_back(l);
  }
  return lights;
}

Material shiny_material() {
  Material m;
  m.diffuse = {0.8f, 0.2f, 0.2f, 1.0f};
  m.specular = {1.0f, 1.0f, 1.0f, 1.0f};
  m.shininess = 32.0f;  // Blinn specular: a pow (log + exp) per light per point
  return m;
}

// Mesh data owning the arrays a VertexInput points into.
struct Mesh {
  std::vector<glm::vec4> positions, colors;
  std::vector<glm::vec3> normals;
  std::vector<Triangle> triangles;
  void add(float x, float y) {
    positions.emplace_back(x, y, 0.0f, 1.0f);
    // Normals tilted by position (all facing the viewer) so every lane does real work.
    normals.push_back(glm::normalize(glm::vec3(x / kWidth - 0.5f, y / kHeight - 0.5f, 1.0f)));
    colors.emplace_back(x / kWidth, y / kHeight, 0.5f, 0.5f);
  }
  VertexInput input() const {
    VertexInput in;
    in.positions = positions;
    in.normals = normals;
    in.colors = colors;
    in.triangles = triangles;
    return in;
  }
};

// Fills the context's first job for one draw as draw_fast.cpp does, and sizes the vertex outputs.
fast::DrawJob& prepare_job(PipelineContext& ctx, Framebuffer& fb, const FragmentState& frag,
                           const ShadeState& shade, const VertexInput& in) {
  std::vector<std::unique_ptr<fast::DrawJob>>& jobs = ctx.impl().jobs;
  if (jobs.empty()) jobs.push_back(std::make_unique<fast::DrawJob>());
  fast::DrawJob& job = *jobs[0];
  job.fb = &fb;
  job.fb_width = fb.width;
  job.fb_height = fb.height;
  job.triangles = in.triangles;
  job.frag = &frag;
  job.shade = &shade;
  job.in = &in;
  job.projection = screen_projection();
  job.viewport = screen_viewport();
  fast::make_plan(job);
  const std::size_t n = in.positions.size();
  job.vertices.resize(n);
  job.outcodes.resize(n);
  job.varyings.resize(n * std::size_t(job.plan.layout.count));
  return job;
}

// 1. Vertex stage, one thread: 64k vertices (a 256 x 256 grid over the screen), Gouraud
// lighting with N positional lights, Blinn specular, through run_vertex_range directly.
// Estimated FLOPs per lit vertex per light (lighting-inl.h): direction + normalize 12,
// attenuation 6, n.l 5, ambient + diffuse 19, half vector + normalize + n.h 17, specular 10,
// pow (log + exp) ~35: about 105 (2 sqrt, 7 div). Per vertex besides: projection 28,
// outcodes 7, viewport + snapping ~20, clamps: about 55. So ~160 FLOPs per vertex with 1
// light, ~900 with 8.
void BM_VertexLighting(benchmark::State& state) {
  Mesh mesh;
  for (int j = 0; j < 256; ++j) {
    for (int i = 0; i < 256; ++i) mesh.add((i + 0.5f) * kWidth / 256.0f, (j + 0.5f) * kHeight / 256.0f);
  }
  const std::vector<Light> lights = make_lights(int(state.range(0)));
  ShadeState shade;
  shade.lighting = true;
  shade.shading = ShadingMode::kGouraud;
  shade.lights = lights;
  shade.front = shade.back = shiny_material();
  FragmentState frag;
  Framebuffer fb;
  fb.resize(kWidth, kHeight);
  const VertexInput in = mesh.input();
  PipelineContext ctx(1);
  fast::DrawJob& job = prepare_job(ctx, fb, frag, shade, in);
  if (!job.plan.simd_vertex_lighting) state.SkipWithError("vertex lighting is not on the SIMD path");
  fast::WorkerScratch& ws = ctx.impl().workers[0];
  const std::size_t n = in.positions.size();
  for (auto _ : state) {
    fast::run_vertex_range(job, 0, n, ws);
    benchmark::DoNotOptimize(job.varyings.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(n));
  job.shade = nullptr;
}
BENCHMARK(BM_VertexLighting)->ArgName("lights")->Arg(1)->Arg(8)->Unit(benchmark::kMicrosecond);

// 2. Setup and binning, one thread: 200k right triangles of 2 pixels' area (legs of 2 pixels,
// one per 3 x 3 pixel cell over 640 x 313 cells), all inside the view volume and front-facing,
// through reset_chunk + setup_range. The vertex stage runs once, before timing. Per triangle:
// 3 outcode loads, the double signed area (6 FLOPs), the integer snapped area and pixel box,
// and one push_back into the (usually single) 64 x 64 tile it touches.
void BM_TriangleSetup(benchmark::State& state) {
  constexpr std::size_t kTriangles = 200000;
  Mesh mesh;
  for (std::size_t t = 0; t < kTriangles; ++t) {
    float x = float(t % 640) * 3.0f + 0.25f, y = float(t / 640) * 3.0f + 0.25f;
    std::uint32_t v = std::uint32_t(mesh.positions.size());
    mesh.add(x, y);
    mesh.add(x + 2.0f, y);
    mesh.add(x, y + 2.0f);
    mesh.triangles.push_back({v, v + 1, v + 2});
  }
  ShadeState shade;
  shade.lighting = false;
  FragmentState frag;
  Framebuffer fb;
  fb.resize(kWidth, kHeight);
  const VertexInput in = mesh.input();
  PipelineContext ctx(1);
  fast::DrawJob& job = prepare_job(ctx, fb, frag, shade, in);
  fast::run_vertex_range(job, 0, in.positions.size(), ctx.impl().workers[0]);
  job.tiles_x = (kWidth + fast::kTileSize - 1) / fast::kTileSize;
  job.tiles_y = (kHeight + fast::kTileSize - 1) / fast::kTileSize;
  job.chunk_count = 1;
  job.chunks.resize(1);
  fast::SetupChunk& chunk = job.chunks[0];
  const std::size_t tiles = std::size_t(job.tiles_x) * std::size_t(job.tiles_y);
  fast::reset_chunk(chunk, tiles);  // warm-up: grows the bins once
  fast::setup_range(job, chunk, 0, kTriangles);
  if (chunk.stats.triangles_rasterized != kTriangles) state.SkipWithError("triangles were culled or clipped");
  for (auto _ : state) {
    fast::reset_chunk(chunk, tiles);
    fast::setup_range(job, chunk, 0, kTriangles);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(kTriangles));
  job.shade = nullptr;
}
BENCHMARK(BM_TriangleSetup)->Unit(benchmark::kMicrosecond);

// 3. Pixel fill: the whole 1920 x 1080 framebuffer covered by two triangles, drawn with
// draw_triangles and a PipelineContext of 1 or 2 threads (the vertex and setup stages are
// negligible here). Depth test with GL_LEQUAL at a constant depth, so every pixel passes and
// writes in every iteration without clearing. Per pixel (SIMD lanes of doubles): coverage
// (3 compares, 3 adds), barycentrics and depth ~10 FLOPs, perspective weights 9, then
//   kUnlit:  Gouraud vertex colours, 4 varyings x 5 = 20 FLOPs, then RGBA8 conversion.
//   kPhong1 / kPhong8: interpolated position (2 varying) and normal (3), renormalized
//            (9), then the lighting equation per pixel: ~105 FLOPs per light (see above).
//   kBlend:  kUnlit plus src-alpha / one-minus-src-alpha blending (colour read, ~12 FLOPs);
//            depth tested but not written.
enum class Fill { kUnlit, kPhong1, kPhong8, kBlend };

void BM_Fill(benchmark::State& state, Fill mode) {
  Mesh mesh;
  mesh.add(0, 0);
  mesh.add(kWidth, 0);
  mesh.add(kWidth, kHeight);
  mesh.add(0, kHeight);
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  const std::vector<Light> lights = make_lights(mode == Fill::kPhong8 ? 8 : 1);
  ShadeState shade;
  shade.lighting = mode == Fill::kPhong1 || mode == Fill::kPhong8;
  shade.shading = shade.lighting ? ShadingMode::kPhong : ShadingMode::kGouraud;
  shade.lights = lights;
  shade.front = shade.back = shiny_material();
  FragmentState frag;
  frag.depth_func = CompareFunc::kLequal;
  if (mode == Fill::kBlend) {
    frag.blend = {true, BlendFactor::kSrcAlpha, BlendFactor::kOneMinusSrcAlpha};
    frag.depth_write = false;
  }
  Framebuffer fb;
  fb.resize(kWidth, kHeight);
  fb.clear_color({0.1f, 0.2f, 0.3f, 1.0f});
  fb.clear_depth(1.0f);
  fb.clear_stencil(0);
  const VertexInput in = mesh.input();
  const glm::mat4 projection = screen_projection();
  const Viewport viewport = screen_viewport();
  PipelineContext ctx(int(state.range(0)));
  RenderStats stats;  // warm-up draw: sizes the context's buffers, checks every pixel is drawn
  draw_triangles(fb, projection, viewport, frag, shade, in, &stats, &ctx);
  if (stats.pixels_shaded != std::uint64_t(kWidth) * kHeight) state.SkipWithError("not every pixel was drawn");
  if (ctx.impl().jobs[0]->plan.scalar_fragments) state.SkipWithError("fragments took the scalar path");
  for (auto _ : state) {
    draw_triangles(fb, projection, viewport, frag, shade, in, nullptr, &ctx);
    benchmark::DoNotOptimize(fb.color.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(kWidth) * kHeight);
}
BENCHMARK_CAPTURE(BM_Fill, gouraud_unlit_depth, Fill::kUnlit)
    ->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Fill, phong_1_light, Fill::kPhong1)
    ->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Fill, phong_8_lights, Fill::kPhong8)
    ->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Fill, blend_src_alpha, Fill::kBlend)
    ->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  // Results depend on the SIMD target the dispatcher picked (AVX3, AVX2, SSE4 ...).
  benchmark::AddCustomContext("simd_target", shadelab::fast::current_simd_target());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
