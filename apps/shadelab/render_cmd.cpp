// `shadelab render SCENE -o OUT.png`: one scene file to one PNG, with overrides and statistics.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "shadelab/image.hpp"
#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"

namespace shadelab::cli {

namespace {

struct RenderArgs {
  std::string scene;
  std::string output;
  std::string size;
  std::string shading;
  std::vector<std::string> overrides;
  int samples = 0;
  bool stats = false;
  bool reference = false;
  int threads = 0;
  LoadOptions limits;  // only the max_* fields
  std::size_t max_fragment_mib = 1024;
};

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  return std::filesystem::exists(b, ec) && std::filesystem::equivalent(a, b, ec);
}

void print_stats(const RenderStats& s, const Scene& scene) {
  std::printf("image            %d x %d\n", scene.width, scene.height);
  std::printf("triangles        %llu in, %llu culled, %llu clipped, %llu rasterized\n",
              (unsigned long long)s.triangles_in, (unsigned long long)s.triangles_culled,
              (unsigned long long)s.triangles_clipped, (unsigned long long)s.triangles_rasterized);
  std::printf("vertices lit     %llu\n", (unsigned long long)s.vertices_lit);
  std::printf("fragments        %llu (%llu written)\n", (unsigned long long)s.fragments,
              (unsigned long long)s.pixels_shaded);
  std::printf("vertex stage     %.2f ms\n", s.ms_vertex);
  std::printf("raster + shade   %.2f ms\n", s.ms_raster);
  std::printf("total            %.2f ms\n", s.ms_total);
}

int run_render(const RenderArgs& args) {
  LoadOptions options = args.limits;
  options.overrides = args.overrides;
  // Through the scene's own validation, so limits and messages are the same.
  if (!args.size.empty() && !add_size_overrides(args.size, "render", options.overrides)) {
    return kExitBadInput;
  }
  // Through the scene's validation too (square numbers only, size limits).
  if (args.samples > 0) options.overrides.push_back("image.samples=" + std::to_string(args.samples));
  RenderOptions render_options;
  if (args.shading == "flat") render_options.shading = ShadingMode::kFlat;
  if (args.shading == "gouraud") render_options.shading = ShadingMode::kGouraud;
  if (args.shading == "phong") render_options.shading = ShadingMode::kPhong;
  render_options.reference = args.reference;
  render_options.threads = args.threads;
  render_options.max_fragment_memory = args.max_fragment_mib << 20;

  std::string output = args.output;
  if (output.empty()) output = std::filesystem::path(args.scene).stem().string() + ".png";
  if (same_file(args.scene, output)) {
    std::cerr << "shadelab render: refusing to overwrite the input file " << args.scene << "\n";
    return kExitBadInput;
  }
  LoadResult loaded = load_scene_file(args.scene, options);
  if (!loaded.scene) {
    std::cerr << loaded.diagnostics.to_string();
    return kExitBadInput;
  }
  RenderStats stats;
  Image image = render_scene(*loaded.scene, render_options, &stats);
  std::string error;
  if (!write_png(image, output, &error)) {
    std::cerr << "shadelab render: " << error << "\n";
    return kExitFailure;
  }
  if (stats.fragments_dropped > 0) {
    std::cerr << "shadelab render: warning: exact transparency: " << stats.fragments_dropped
              << " fragments were not blended; their lists need more than the limit of "
              << args.max_fragment_mib << " MiB (--max-fragment-memory)\n";
  }
  if (args.stats) print_stats(stats, *loaded.scene);
  return kExitOk;
}

}  // namespace

Action add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene file to a PNG image");
  cmd->add_option("scene", args->scene, "Scene file (JSON, see docs/scene-format.md)")->required();
  cmd->add_option("-o,--output", args->output, "Output PNG (default: the scene's name + .png)");
  cmd->add_option("--size", args->size, "Image size WIDTHxHEIGHT, overrides image.width/height");
  cmd->add_option("--shading", args->shading, "Shading mode for every object")
      ->check(CLI::IsMember({"flat", "gouraud", "phong"}));
  cmd->add_option("--set", args->overrides,
                  "Override a scene value by key path, e.g. lights[0].spot.cutoff=30 (repeatable)");
  cmd->add_option("--samples", args->samples,
                  "Anti-aliasing: samples per pixel, 1, 4, 9, 16 ... 64 (supersampling)")
      ->check(CLI::Range(1, 64));
  cmd->add_flag("--stats", args->stats, "Print triangle and pixel counts and time per stage");
  cmd->add_flag("--reference", args->reference, "Draw with the simple reference pipeline");
  cmd->add_option("--max-pixels", args->limits.max_pixels,
                  "Limit on width x height x samples (default 268435456)")
      ->check(CLI::Range(1LL, 1LL << 32));
  cmd->add_option("--max-triangles", args->limits.max_triangles,
                  "Limit on triangles after tessellation (default 20000000)")
      ->check(CLI::Range(1LL, 1LL << 31));
  cmd->add_option("--max-lights", args->limits.max_lights, "Limit on lights (default 1024)")
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--max-texture-size", args->limits.max_texture_side,
                  "Limit on a texture image's width and height (default 8192)")
      ->check(CLI::Range(1, 1 << 16));
  cmd->add_option("--max-fragment-memory", args->max_fragment_mib,
                  "Memory for exact transparency's per-pixel fragment lists, MiB (default 1024)")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 20));
  cmd->add_option("--threads", args->threads,
                  "Fast pipeline threads (default: $SHADELAB_THREADS, else all cores)")
      ->check(CLI::Range(1, 256));
  cmd->footer(
      "Examples:\n"
      "  shadelab render scenes/teapot.json -o teapot.png\n"
      "  shadelab render scenes/teapot.json --size 1920x1080 --shading phong --stats\n"
      "  shadelab render scenes/teapot.json --set 'materials.shiny_red.shininess=20' -o dull.png\n"
      "Exit status: 0 success, 1 output could not be written, 2 bad scene or arguments.");
  return [args] { return run_render(*args); };
}

}  // namespace shadelab::cli
