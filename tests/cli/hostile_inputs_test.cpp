// The hardening task's hostile set, through the command as a user runs it: truncated and
// deeply nested JSON, 1e308 and NaN everywhere, a 100000 x 100000 image, a million lights, OBJ
// files with out-of-range indices, a PNG texture that declares gigapixels. Each gets exit
// status 2 and an error naming file, line and column, never a crash (a signal), a hang or an
// out-of-memory kill, and no output file is left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/test_support.hpp"

namespace shadelab {
namespace {

namespace fs = std::filesystem;

struct Hostile {
  const char* name;
  std::string text;
  const char* expected;  ///< a part of the error message
};

std::string repeat(const std::string& s, int n) {
  std::string out;
  out.reserve(s.size() * std::size_t(n));
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

std::string write(const fs::path& dir, const std::string& name, const std::string& text) {
  fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

TEST(HostileInputs, EveryOneGetsAnErrorNeverACrash) {
  fs::path dir = fs::path(test::output_dir()) / "hostile";
  fs::create_directories(dir);
  const std::string teapot = R"({"objects": [{"shape": "teapot"}]})";
  const std::string lights = "{\"lights\": [" + repeat("{},", 999999) + "{}]}";
  // The same key everywhere a number goes, with a value JSON cannot hold or a scene refuses.
  const std::string every_number_huge =
      R"({"image": {"width": 1e308, "height": 1e308}, "camera": {"eye": [1e308, 1e308, 1e308], "fovy": 1e308},
          "lights": [{"position": [1e308, -1e308, 1e308, 1], "constant_attenuation": 1e308}],
          "objects": [{"shape": {"type": "sphere", "slices": 1e308}, "transform": {"scale": 1e308}}]})";
  write(dir, "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\nf -7 1 2\nf 1 2 3\n");
  const Hostile inputs[] = {
      {"truncated.json", teapot.substr(0, teapot.size() / 2), ":1:"},
      {"nested.json", repeat("[", 100000) + repeat("]", 100000), "nesting"},
      {"nested_objects.json", repeat("{\"a\":", 5000) + "1" + repeat("}", 5000), "nesting"},
      {"huge_numbers.json", every_number_huge, "out of range"},
      {"nan.json", R"({"camera": {"eye": [NaN, 0, 0]}, "lights": [{"diffuse": [nan, Infinity, -Infinity]}]})",
       ":1:"},
      {"huge_image.json", R"({"image": {"width": 100000, "height": 100000}})", "image.width"},
      {"million_lights.json", lights, "more than 262144 values"},
      {"many_lights.json", "{\"lights\": [" + repeat("{},", 99999) + "{}]}",
       "lights: 100000 lights, more than the limit of 1024"},
      {"bad_indices.json", R"({"objects": [{"shape": {"type": "mesh", "file": "bad.obj"}}]})", "bad.obj"},
      {"gigapixel_texture.json",
       R"({"objects": [{"shape": "cube", "texture": {"file": ")" + std::string(SHADELAB_SOURCE_DIR) +
           R"(/fuzz/regressions/png/huge-ihdr.png"}}]})",
       "the texture is 17000 x 10000, more than the limit of 8192 x 8192"},
  };
  for (const Hostile& h : inputs) {
    SCOPED_TRACE(h.name);
    std::string scene = write(dir, h.name, h.text);
    std::string out = (dir / (std::string(h.name) + ".png")).string();
    fs::remove(out);
    test::CommandResult r = test::run_cli("render '" + scene + "' -o '" + out + "'");
    EXPECT_EQ(r.exit_status, 2) << r.err;  // -1 would be a signal
    EXPECT_NE(r.err.find(h.name), std::string::npos) << r.err;  // the message names the file
    EXPECT_NE(r.err.find(h.expected), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

}  // namespace
}  // namespace shadelab
