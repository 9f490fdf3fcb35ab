// Entry point of the shadelab command: parses the command line with CLI11 and runs the chosen
// subcommand. Usage errors exit with status 2.
#include <utility>
#include <vector>

#include "commands.hpp"

namespace {

struct Command {
  const char* name;
  shadelab::cli::Action (*add)(CLI::App&);
};

constexpr Command kCommands[] = {
    {"render", shadelab::cli::add_render_command},
    {"sweep", shadelab::cli::add_sweep_command},
    {"animate", shadelab::cli::add_animate_command},
    {"materials", shadelab::cli::add_materials_command},
    {"gallery", shadelab::cli::add_gallery_command},
    {"merge", shadelab::cli::add_merge_command},
    {"shadow-matrix", shadelab::cli::add_shadow_matrix_command},
    {"serve", shadelab::cli::add_serve_command},
    {"run", shadelab::cli::add_run_command},
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"shadelab: the OpenGL lighting, shading and materials system on the CPU"};
  app.require_subcommand(1);
  app.footer(
      "Examples:\n"
      "  shadelab render scenes/teapot.json -o teapot.png\n"
      "  shadelab render scenes/teapot.json --shading flat --size 800x600 -o flat.png\n"
      "  shadelab sweep scenes/teapot.json --vary shading=flat,gouraud,phong -o modes.png\n"
      "  shadelab animate scenes/lecture/10-spot-cutoff.json --vary 'lights[0].spot.cutoff=5:60' -o cutoff.png\n"
      "  shadelab materials --sheet materials.png\n"
      "  shadelab run --xvfb --frames 1 --capture 'out/frame%04d.png' -- ./glut_program\n"
      "Run 'shadelab COMMAND --help' for a command's options.");
  std::vector<std::pair<const char*, shadelab::cli::Action>> actions;
  for (const Command& c : kCommands) actions.emplace_back(c.name, c.add(app));
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
  for (auto& [name, action] : actions) {
    if (app.get_subcommand(name)->parsed()) return action();
  }
  return shadelab::cli::kExitBadInput;
}
