// Entry point of the shadelab command: parses the command line with CLI11 and runs the chosen
// subcommand. Usage errors exit with status 2.
#include <iostream>
#include <vector>

#include "commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"shadelab: the OpenGL lighting, shading and materials system on the CPU"};
  app.require_subcommand(1);
  app.footer(
      "Examples:\n"
      "  shadelab render scenes/teapot.json -o teapot.png\n"
      "  shadelab render scenes/teapot.json --shading flat --size 800x600 -o flat.png\n"
      "  shadelab render scenes/teapot.json --set lights[0].spot.cutoff=30 --stats -o spot.png\n"
      "Run 'shadelab COMMAND --help' for a command's options.");
  std::vector<std::pair<CLI::App*, shadelab::cli::Action>> actions;
  shadelab::cli::Action render = shadelab::cli::add_render_command(app);
  actions.emplace_back(app.get_subcommand("render"), render);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return shadelab::cli::kExitBadInput;
  }
  for (auto& [sub, action] : actions) {
    if (sub->parsed()) return action();
  }
  return shadelab::cli::kExitBadInput;
}
