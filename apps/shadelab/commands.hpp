// The shadelab command's subcommands. Each registers itself on the CLI11 app and returns the
// process exit status when run: 0 success, 1 failure while working, 2 bad input or usage.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "shadelab/contact_sheet.hpp"

namespace shadelab::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

/// A subcommand's action, run after parsing succeeded.
using Action = std::function<int()>;

/// Turns --size "WIDTHxHEIGHT" into image.width/height overrides (validated by the scene
/// reader like any value). Prints the error for `command` and returns false when malformed.
bool add_size_overrides(const std::string& size, const char* command,
                        std::vector<std::string>& overrides);

/// Loads the default TrueType font, printing the error for `command` on failure.
std::unique_ptr<Font> load_default_font(const char* command);

/// A progress bar on standard error when it is a terminal: `done` of `total`, and `label`.
void progress_bar(int done, int total, const std::string& label);

Action add_render_command(CLI::App& app);
Action add_sweep_command(CLI::App& app);
Action add_materials_command(CLI::App& app);
Action add_gallery_command(CLI::App& app);
Action add_shadow_matrix_command(CLI::App& app);
Action add_serve_command(CLI::App& app);
Action add_run_command(CLI::App& app);
Action add_animate_command(CLI::App& app);
Action add_merge_command(CLI::App& app);

/// Assembling a sharded batch (`shadelab merge`): each command's half, from its manifest.
int merge_sweep(const nlohmann::json& manifest, const std::string& output);
int merge_animate(const nlohmann::json& manifest, const std::string& output);
int merge_gallery(const nlohmann::json& manifest, const std::string& output);

}  // namespace shadelab::cli
