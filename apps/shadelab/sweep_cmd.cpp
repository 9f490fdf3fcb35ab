// `shadelab sweep SCENE --vary KEY=V1,V2,... -o SHEET.png`: a contact sheet of one scene
// rendered once per value (a grid for two keys), with a progress bar on a terminal.
#include <cstdio>
#include <iostream>
#include <memory>
#include <unistd.h>

#include "commands.hpp"
#include "sweep.hpp"

namespace shadelab::cli {

namespace {

struct SweepArgs {
  std::string scene, output, shading, title, size;
  std::vector<std::string> vary, overrides;
  int samples = 0, columns = 0;
};

void progress_bar(int done, int total, const std::string& label) {
  if (!isatty(STDERR_FILENO)) return;
  const int width = 30;
  int filled = total > 0 ? done * width / total : width;
  std::fprintf(stderr, "\r[%s%s] %d/%d %-40.40s", std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), done, total, label.c_str());
  if (done == total) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

int run(const SweepArgs& a) {
  SweepRequest r;
  r.scene = a.scene;
  r.overrides = a.overrides;
  if (!a.size.empty() && !add_size_overrides(a.size, "sweep", r.overrides)) return kExitBadInput;
  r.columns = a.columns;
  r.title = a.title;
  if (a.samples > 0) r.samples = a.samples;
  if (a.shading == "flat") r.shading = ShadingMode::kFlat;
  if (a.shading == "gouraud") r.shading = ShadingMode::kGouraud;
  if (a.shading == "phong") r.shading = ShadingMode::kPhong;
  if (a.vary.empty() || a.vary.size() > 2) {
    std::cerr << "shadelab sweep: give one or two --vary KEY=V1,V2,...\n";
    return kExitBadInput;
  }
  for (const std::string& text : a.vary) {
    Variation v;
    std::string error;
    if (!parse_variation(text, v, &error)) {
      std::cerr << error << "\n";
      return kExitBadInput;
    }
    r.vary.push_back(v);
  }
  std::unique_ptr<Font> font = load_default_font("sweep");
  if (!font) return kExitFailure;
  std::string error;
  Diagnostics diags;
  std::optional<Image> sheet = run_sweep(r, *font, diags, progress_bar);
  if (!sheet) {
    std::cerr << diags.to_string();
    return kExitBadInput;
  }
  if (!write_png(*sheet, a.output, &error)) {
    std::cerr << "shadelab sweep: " << error << "\n";
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

Action add_sweep_command(CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand("sweep", "Render a scene once per value and make a contact sheet");
  cmd->add_option("scene", a->scene, "Scene file")->required();
  cmd->add_option("--vary", a->vary,
                  "KEY=V1,V2,... : a key path and its values (once or twice; 'shading' varies "
                  "the shading mode)")->required();
  cmd->add_option("-o,--output", a->output, "Output PNG")->required();
  cmd->add_option("--set", a->overrides, "Override a scene value for every picture (repeatable)");
  cmd->add_option("--size", a->size, "Size of each picture, WIDTHxHEIGHT");
  cmd->add_option("--shading", a->shading, "Shading mode for every object")
      ->check(CLI::IsMember({"flat", "gouraud", "phong"}));
  cmd->add_option("--samples", a->samples, "Anti-aliasing samples per pixel (1, 4, 9 ... 64)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--columns", a->columns, "Pictures per row (default: one row per value of the second key)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--title", a->title, "Title printed above the sheet");
  cmd->footer(
      "Examples:\n"
      "  shadelab sweep scenes/lecture/10-spot-cutoff.json --vary 'lights[0].spot.cutoff=50,40,30,20' -o cutoff.png\n"
      "  shadelab sweep scenes/lecture/07-mesh-size.json --vary objects[0].shape.nx=1,2,4,10,20 \\\n"
      "      --vary shading=gouraud,phong -o mesh.png\n"
      "Exit status: 0 success, 1 output could not be written, 2 bad scene, key or value.");
  return [a] { return run(*a); };
}

}  // namespace shadelab::cli
