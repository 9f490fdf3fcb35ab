// Shared test helpers: running the shadelab command, comparing images with golden references
// (writing actual and difference images on failure), and small scene builders.
#pragma once

#include <string>

#include "shadelab/image.hpp"

namespace shadelab::test {

struct CommandResult {
  int exit_status = -1;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

/// Runs the shadelab program with `args` (a shell-quoted argument string) from the source dir.
CommandResult run_cli(const std::string& args);

/// Folder for files tests write (created on demand).
std::string output_dir();

/// Compares `actual` with tests/golden/<name>.png: passes when every channel is within
/// `max_channel_diff` on all but `allowed_fraction` of pixels. A missing golden fails. With
/// SHADELAB_UPDATE_GOLDEN=1 the golden is (re)written instead. On failure, writes
/// <output_dir>/<name>.actual.png and <name>.diff.png and returns a message; "" on success.
std::string compare_golden(const Image& actual, const std::string& name,
                           int max_channel_diff = 1, double allowed_fraction = 0.001);

}  // namespace shadelab::test
