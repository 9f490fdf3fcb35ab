// The shadelab command as a user runs it: exit statuses, exact error texts, overrides, the
// --size/--shading/--stats options, and no partial output after a failure.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "shadelab/image.hpp"
#include "support/test_support.hpp"

namespace shadelab {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

std::string write_file(const std::string& name, const std::string& text) {
  fs::path p = fs::path(test::output_dir()) / name;
  std::ofstream(p) << text;
  return p.string();
}

std::string fresh_output(const std::string& name) {
  fs::path p = fs::path(test::output_dir()) / name;
  fs::remove(p);
  return p.string();
}

TEST(Cli, RendersTheTeapotAtTheRequestedSize) {
  std::string out = fresh_output("cli_teapot.png");
  auto r = run_cli("render scenes/teapot.json --size 64x48 -o '" + out + "'");
  ASSERT_EQ(r.exit_status, 0) << r.err;
  Image img;
  std::string error;
  ASSERT_TRUE(read_image(out, img, &error)) << error;
  EXPECT_EQ(img.width, 64);
  EXPECT_EQ(img.height, 48);
}

TEST(Cli, StatsReportsCountsAndTimes) {
  auto r = run_cli("render scenes/teapot.json --size 64x48 --stats -o '" +
                   fresh_output("cli_stats.png") + "'");
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.out.find("triangles"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("total"), std::string::npos) << r.out;
}

TEST(Cli, BadSceneGivesLocatedErrorStatus2AndNoOutput) {
  std::string scene = write_file("cli_bad_spot.json",
                                 "{\n"
                                 "  \"lights\": [\n"
                                 "    {\"spot\": {\"cutoff\": 120}}\n"
                                 "  ]\n"
                                 "}\n");
  std::string out = fresh_output("cli_bad_spot.png");
  auto r = run_cli("render '" + scene + "' -o '" + out + "'");
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(r.err, scene + ":3:25: lights[0].spot.cutoff: 120 is out of range (0..90, or 180)\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, MissingSceneFile) {
  auto r = run_cli("render does/not/exist.json -o '" + fresh_output("cli_missing.png") + "'");
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(r.err, "does/not/exist.json: cannot open scene file: No such file or directory\n");
}

TEST(Cli, BadOverrideValueIsReportedAgainstSet) {
  auto r = run_cli("render scenes/teapot.json --set lights[0].spot.cutoff=200 -o '" +
                   fresh_output("cli_set.png") + "'");
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(r.err, "--set: lights[0].spot.cutoff: 200 is out of range (0..90, or 180)\n");
}

// The limits against hostile input are the user's to change, and say what was exceeded.
TEST(Cli, LimitsCanBeLoweredAndAreReportedWithTheirValue) {
  std::string out = fresh_output("cli_limits.png");
  auto r = run_cli("render scenes/teapot.json --max-triangles 1000 -o '" + out + "'");
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(r.err, "scenes/teapot.json:19:16: objects[0].shape: the scene would have 9216 triangles, "
                   "more than the limit of 1000\n");
  r = run_cli("render scenes/teapot.json --max-pixels 1000 -o '" + out + "'");
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(r.err, "scenes/teapot.json:3:12: image: 640 x 480 = 307200 pixels, more than the limit of 1000\n");
  r = run_cli("render scenes/teapot.json --max-lights 0 -o '" + out + "'");
  EXPECT_EQ(r.exit_status, 2);  // out of the option's range
  EXPECT_FALSE(fs::exists(out));
  r = run_cli("render scenes/teapot.json --size 64x48 --max-triangles 10000 -o '" + out + "'");
  EXPECT_EQ(r.exit_status, 0) << r.err;
}

// Texture size is checked from the file's header before decoding; the limit is the user's.
TEST(Cli, TextureSizeLimitIsChecked) {
  std::string out = fresh_output("cli_texture_limit.png");
  auto r = run_cli("render scenes/lecture/14-emission-night.json --size 32x24 --max-texture-size 32 -o '" +
                   out + "'");
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.err.find("objects[0].texture.file: the texture is 64 x 64, more than the limit of 32 x 32 "
                       "(--max-texture-size)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out));
  r = run_cli("render scenes/lecture/14-emission-night.json --size 32x24 --max-texture-size 64 -o '" + out + "'");
  EXPECT_EQ(r.exit_status, 0) << r.err;
}

// Exact transparency's fragment lists have a memory limit; over it the picture is still
// written and the warning says what was left out and which option raises the limit.
TEST(Cli, FragmentMemoryLimitWarns) {
  std::string out = fresh_output("cli_fragment_limit.png");
  auto r = run_cli("render scenes/shadows-and-glass.json --size 64x48 --max-fragment-memory 1 -o '" + out + "'");
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(fs::exists(out));
  EXPECT_EQ(r.err, "");  // 64 x 48 pixels' lists fit in a MiB
  r = run_cli("render scenes/shadows-and-glass.json --size 1024x1024 --max-fragment-memory 1 -o '" + out + "'");
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: exact transparency: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("fragments were not blended; their lists need more than the limit of 1 MiB "
                       "(--max-fragment-memory)"),
            std::string::npos)
      << r.err;
}

TEST(Cli, OverrideChangesTheImage) {
  std::string a = fresh_output("cli_set_a.png"), b = fresh_output("cli_set_b.png");
  ASSERT_EQ(run_cli("render scenes/teapot.json --size 48x36 -o '" + a + "'").exit_status, 0);
  auto r = run_cli("render scenes/teapot.json --size 48x36 --set 'lights[0].diffuse=[0,0,1]' -o '" +
                   b + "'");
  ASSERT_EQ(r.exit_status, 0) << r.err;
  Image ia, ib;
  std::string e;
  ASSERT_TRUE(read_image(a, ia, &e) && read_image(b, ib, &e)) << e;
  EXPECT_NE(ia.rgba, ib.rgba);
}

TEST(Cli, BadSizeAndShading) {
  auto r = run_cli("render scenes/teapot.json --size 64by48");
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(r.err, "shadelab render: --size: expected WIDTHxHEIGHT (e.g. 1920x1080), got \"64by48\"\n");
  auto s = run_cli("render scenes/teapot.json --size 0x48");
  EXPECT_EQ(s.exit_status, 2);
  EXPECT_EQ(s.err, "--set: image.width: 0 is out of range (1..16384)\n");
  auto t = run_cli("render scenes/teapot.json --shading toon");
  EXPECT_EQ(t.exit_status, 2);
  EXPECT_NE(t.err.find("--shading"), std::string::npos) << t.err;
}

TEST(Cli, RefusesToOverwriteTheInput) {
  std::string scene = write_file("cli_self.json", "{}");
  auto r = run_cli("render '" + scene + "' -o '" + scene + "'");
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_EQ(r.err, "shadelab render: refusing to overwrite the input file " + scene + "\n");
}

TEST(Cli, UnwritableOutputIsStatus1) {
  auto r = run_cli("render scenes/teapot.json --size 8x8 -o /nonexistent-dir/x.png");
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_EQ(r.err, "shadelab render: cannot write /nonexistent-dir/x.png: No such file or directory\n");
}

TEST(Cli, UsageErrorsAndHelp) {
  EXPECT_EQ(run_cli("").exit_status, 2);
  EXPECT_EQ(run_cli("frobnicate").exit_status, 2);
  auto h = run_cli("render --help");
  EXPECT_EQ(h.exit_status, 0);
  EXPECT_NE(h.out.find("Examples"), std::string::npos);
}

}  // namespace
}  // namespace shadelab
