// `shadelab sweep SCENE --vary KEY=V1,V2,... -o SHEET.png`: a contact sheet of one scene
// rendered once per value (a grid for two keys), with a progress bar on a terminal; with
// --shard I/N, its share of the pictures into OUTPUT.parts/ for `shadelab merge` (shard.hpp).
#include <cstdio>
#include <iostream>
#include <memory>
#include <unistd.h>

#include "commands.hpp"
#include "shard.hpp"
#include "sweep.hpp"

namespace shadelab::cli {

namespace {

struct SweepArgs {
  std::string scene, output, shading, title, size, shard;
  std::vector<std::string> vary, overrides;
  int samples = 0, columns = 0;
};

// The request the arguments stand for; prints what is wrong.
std::optional<SweepRequest> request_of(const SweepArgs& a) {
  SweepRequest r;
  r.scene = a.scene;
  r.overrides = a.overrides;
  if (!a.size.empty() && !add_size_overrides(a.size, "sweep", r.overrides)) return std::nullopt;
  r.columns = a.columns;
  r.title = a.title;
  if (a.samples > 0) r.samples = a.samples;
  if (a.shading == "flat") r.shading = ShadingMode::kFlat;
  if (a.shading == "gouraud") r.shading = ShadingMode::kGouraud;
  if (a.shading == "phong") r.shading = ShadingMode::kPhong;
  if (a.vary.empty() || a.vary.size() > 2) {
    std::cerr << "shadelab sweep: give one or two --vary KEY=V1,V2,...\n";
    return std::nullopt;
  }
  for (const std::string& text : a.vary) {
    Variation v;
    std::string error;
    if (!parse_variation(text, v, &error)) {
      std::cerr << error << "\n";
      return std::nullopt;
    }
    r.vary.push_back(v);
  }
  return r;
}

nlohmann::json manifest_of(const SweepArgs& a, std::size_t parts) {
  return {{"command", "sweep"}, {"parts", parts},      {"scene", a.scene},     {"vary", a.vary},
          {"set", a.overrides}, {"size", a.size},      {"shading", a.shading}, {"samples", a.samples},
          {"columns", a.columns}, {"title", a.title}};
}

// This shard's pictures, each written as a part (those already there are kept).
int run_shard(const SweepArgs& a, const SweepRequest& r, const Shard& shard) {
  Diagnostics diags;
  std::optional<std::vector<SweepCell>> cells = sweep_cells(r, diags);
  if (!cells) {
    std::cerr << diags.to_string();
    return kExitBadInput;
  }
  std::string error;
  if (!write_manifest(a.output, manifest_of(a, cells->size()), &error)) {
    std::cerr << "shadelab sweep: " << error << "\n";
    return kExitFailure;
  }
  std::vector<std::size_t> mine;
  for (std::size_t k : missing_parts(a.output, cells->size())) {
    if (shard.owns(k)) mine.push_back(k);
  }
  int done = 0;
  for (std::size_t k : mine) {
    std::optional<Image> picture = render_sweep_cell(r, (*cells)[k], diags);
    if (!picture) {
      std::cerr << diags.to_string();
      return kExitBadInput;
    }
    if (!write_part(a.output, k, *picture, &error)) {
      std::cerr << "shadelab sweep: " << error << "\n";
      return kExitFailure;
    }
    progress_bar(++done, int(mine.size()), (*cells)[k].label);
  }
  return kExitOk;
}

int run(const SweepArgs& a) {
  Shard shard;
  std::string error;
  if (!a.shard.empty() && !parse_shard(a.shard, shard, &error)) {
    std::cerr << error << "\n";
    return kExitBadInput;
  }
  std::optional<SweepRequest> r = request_of(a);
  if (!r) return kExitBadInput;
  if (shard.active()) return run_shard(a, *r, shard);
  std::unique_ptr<Font> font = load_default_font("sweep");
  if (!font) return kExitFailure;
  Diagnostics diags;
  std::optional<Image> sheet = run_sweep(*r, *font, diags, progress_bar);
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

int merge_sweep(const nlohmann::json& m, const std::string& output) {
  SweepArgs a;
  try {
    a.scene = m.at("scene").get<std::string>();
    a.vary = m.at("vary").get<std::vector<std::string>>();
    a.overrides = m.at("set").get<std::vector<std::string>>();
    a.size = m.at("size").get<std::string>();
    a.shading = m.at("shading").get<std::string>();
    a.samples = m.at("samples").get<int>();
    a.columns = m.at("columns").get<int>();
    a.title = m.at("title").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    std::cerr << "shadelab merge: " << parts_dir(output) << "/manifest.json: " << e.what() << "\n";
    return kExitBadInput;
  }
  std::optional<SweepRequest> r = request_of(a);
  if (!r) return kExitBadInput;
  Diagnostics diags;
  std::optional<std::vector<SweepCell>> cells = sweep_cells(*r, diags);
  if (!cells) {
    std::cerr << diags.to_string();
    return kExitBadInput;
  }
  std::vector<Image> pictures(cells->size());
  std::string error;
  for (std::size_t k = 0; k < pictures.size(); ++k) {
    if (!read_part(output, k, pictures[k], &error)) {
      std::cerr << "shadelab merge: " << error << "\n";
      return kExitFailure;
    }
  }
  std::unique_ptr<Font> font = load_default_font("merge");
  if (!font) return kExitFailure;
  if (!write_png(sweep_sheet(*r, *cells, std::move(pictures), *font), output, &error)) {
    std::cerr << "shadelab merge: " << error << "\n";
    return kExitFailure;
  }
  return kExitOk;
}

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
  cmd->add_option("--shard", a->shard,
                  "I/N: render only the I-th of N shares of the pictures into OUTPUT.parts/ (then shadelab merge OUTPUT)");
  cmd->footer(
      "Examples:\n"
      "  shadelab sweep scenes/lecture/10-spot-cutoff.json --vary 'lights[0].spot.cutoff=50,40,30,20' -o cutoff.png\n"
      "  shadelab sweep scenes/lecture/07-mesh-size.json --vary objects[0].shape.nx=1,2,4,10,20 \\\n"
      "      --vary shading=gouraud,phong -o mesh.png\n"
      "Exit status: 0 success, 1 output could not be written, 2 bad scene, key or value.");
  return [a] { return run(*a); };
}

}  // namespace shadelab::cli
