// The shadelab command's subcommands. Each registers itself on the CLI11 app and returns the
// process exit status when run: 0 success, 1 failure while working, 2 bad input or usage.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace shadelab::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

/// A subcommand's action, run after parsing succeeded.
using Action = std::function<int()>;

Action add_render_command(CLI::App& app);
Action add_sweep_command(CLI::App& app);
Action add_materials_command(CLI::App& app);
Action add_gallery_command(CLI::App& app);
Action add_shadow_matrix_command(CLI::App& app);

}  // namespace shadelab::cli
