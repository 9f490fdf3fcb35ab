// Implementation of the shared test helpers (see test_support.hpp).
#include "support/test_support.hpp"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace shadelab::test {

namespace fs = std::filesystem;

std::string output_dir() {
  fs::path dir = SHADELAB_TEST_OUTPUT;
  fs::create_directories(dir);
  return dir.string();
}

namespace {
std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}
}  // namespace

CommandResult run_cli(const std::string& args) {
  static int counter = 0;
  fs::path dir = output_dir();
  std::string tag = std::to_string(::getpid()) + "_" + std::to_string(counter++);
  fs::path out = dir / ("cli_" + tag + ".out"), err = dir / ("cli_" + tag + ".err");
  std::string cmd = std::string("cd '") + SHADELAB_SOURCE_DIR + "' && '" + SHADELAB_CLI + "' " +
                    args + " >'" + out.string() + "' 2>'" + err.string() + "' </dev/null";
  int status = std::system(cmd.c_str());
  CommandResult r;
  r.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

std::string compare_golden(const Image& actual, const std::string& name, int max_channel_diff,
                           double allowed_fraction) {
  fs::path golden = fs::path(SHADELAB_SOURCE_DIR) / "tests" / "golden" / (name + ".png");
  const char* update = std::getenv("SHADELAB_UPDATE_GOLDEN");
  std::string error;
  if (update && std::string(update) == "1") {
    fs::create_directories(golden.parent_path());
    if (!write_png(actual, golden.string(), &error)) return error;
    return "";
  }
  fs::path actual_path = fs::path(output_dir()) / (name + ".actual.png");
  Image expected;
  if (!read_image(golden.string(), expected, &error)) {
    write_png(actual, actual_path.string(), &error);
    return "missing golden image " + golden.string() + " (actual written to " +
           actual_path.string() + "; review it and rerun with SHADELAB_UPDATE_GOLDEN=1)";
  }
  if (expected.width != actual.width || expected.height != actual.height) {
    write_png(actual, actual_path.string(), &error);
    return "size differs from golden: " + std::to_string(actual.width) + "x" +
           std::to_string(actual.height) + " vs " + std::to_string(expected.width) + "x" +
           std::to_string(expected.height);
  }
  Image diff = actual;
  std::size_t bad = 0, pixels = std::size_t(actual.width) * actual.height;
  int worst = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    int d = 0;
    for (int c = 0; c < 4; ++c) {
      d = std::max(d, std::abs(int(actual.rgba[i * 4 + c]) - int(expected.rgba[i * 4 + c])));
    }
    worst = std::max(worst, d);
    bad += d > max_channel_diff;
    // Difference image: grey where equal, red scaled by the difference elsewhere.
    std::uint8_t v = static_cast<std::uint8_t>(std::min(255, d * 16));
    std::array<std::uint8_t, 4> px = d > max_channel_diff ? std::array<std::uint8_t, 4>{255, 0, 0, 255}
                                     : d > 0 ? std::array<std::uint8_t, 4>{v, v, 0, 255}
                                             : std::array<std::uint8_t, 4>{40, 40, 40, 255};
    std::copy(px.begin(), px.end(), &diff.rgba[i * 4]);
  }
  if (double(bad) <= allowed_fraction * double(pixels)) return "";
  fs::path diff_path = fs::path(output_dir()) / (name + ".diff.png");
  write_png(actual, actual_path.string(), &error);
  write_png(diff, diff_path.string(), &error);
  return std::to_string(bad) + " of " + std::to_string(pixels) + " pixels differ by more than " +
         std::to_string(max_channel_diff) + "/255 (worst " + std::to_string(worst) +
         "); actual: " + actual_path.string() + ", difference: " + diff_path.string();
}

}  // namespace shadelab::test
