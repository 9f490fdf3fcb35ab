// `shadelab merge OUTPUT`: assembles the parts that `sweep`, `animate` or `gallery` runs with
// --shard I/N wrote into OUTPUT.parts/ into OUTPUT, as one run of the command would have
// written it (shard.hpp). It renders nothing but a gallery's page.
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "shard.hpp"

namespace shadelab::cli {

namespace {

struct MergeArgs {
  std::string output;
  bool remove_parts = false;
};

int run(const MergeArgs& a) {
  std::string error;
  std::optional<nlohmann::json> m = read_manifest(a.output, &error);
  if (!m) {
    std::cerr << "shadelab merge: " << error << "\n";
    return kExitBadInput;
  }
  const std::string command = (*m)["command"].get<std::string>();
  const std::size_t parts = (*m)["parts"].get<std::size_t>();
  const std::string extension = command == "gallery" ? "" : ".png";
  if (command != "gallery") {
    const std::vector<std::size_t> missing = missing_parts(a.output, parts, extension);
    if (!missing.empty()) {
      std::cerr << "shadelab merge: " << missing.size() << " of " << parts << " parts are not in "
                << parts_dir(a.output) << " yet (the first: " << part_path(a.output, missing[0], extension)
                << "); run the missing shards (they skip the parts already there)\n";
      return kExitFailure;
    }
  }
  int status = kExitBadInput;
  if (command == "sweep") status = merge_sweep(*m, a.output);
  else if (command == "animate") status = merge_animate(*m, a.output);
  else if (command == "gallery") status = merge_gallery(*m, a.output);
  else std::cerr << "shadelab merge: " << parts_dir(a.output) << "/manifest.json: unknown command \"" << command << "\"\n";
  if (status == kExitOk && a.remove_parts) {
    std::error_code ec;
    std::filesystem::remove_all(parts_dir(a.output), ec);
  }
  if (status == kExitOk) std::cout << "merge: " << parts << " parts into " << a.output << "\n";
  return status;
}

}  // namespace

Action add_merge_command(CLI::App& app) {
  auto a = std::make_shared<MergeArgs>();
  CLI::App* cmd = app.add_subcommand("merge", "Assemble the parts of a batch run with --shard I/N");
  cmd->add_option("output", a->output, "The output the sharded command was given (-o FILE, or the gallery's folder)")
      ->required();
  cmd->add_flag("--remove-parts", a->remove_parts, "Delete OUTPUT.parts/ once OUTPUT is written");
  cmd->footer(
      "Example:\n"
      "  for i in 1 2 3 4; do shadelab animate scene.json --orbit --shard $i/4 -o orbit.png & done; wait\n"
      "  shadelab merge orbit.png\n"
      "Exit status: 0 success, 1 parts missing or output not written, 2 no or bad manifest.");
  return [a] { return run(*a); };
}

}  // namespace shadelab::cli
