// Whole scenes through render_scene with the reference pipeline and with the fast one (1, 2
// and 3 threads): every scene file in the repository, in every shading mode. Colours must agree
// within 1/255 on every pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <optional>
#include <sstream>

#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"

#include "random_draws.hpp"

namespace shadelab {
namespace {

std::vector<std::filesystem::path> scene_files() {
  std::vector<std::filesystem::path> files;
  for (const char* dir : {"/scenes", "/scenes/lecture"}) {
    for (const auto& f : std::filesystem::directory_iterator(std::string(SHADELAB_SOURCE_DIR) + dir)) {
      if (f.path().extension() == ".json" && f.path().filename() != "rows.json") files.push_back(f.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// "" when every channel of every pixel is within 1, else the first differences.
std::string compare_images(const Image& fast, const Image& reference) {
  if (fast.width != reference.width || fast.height != reference.height) return "size differs";
  std::ostringstream out;
  int bad = 0;
  for (int y = 0; y < fast.height; ++y) {
    for (int x = 0; x < fast.width; ++x) {
      const std::uint8_t* a = fast.pixel(x, y);
      const std::uint8_t* b = reference.pixel(x, y);
      for (int c = 0; c < 4; ++c) {
        if (std::abs(int(a[c]) - int(b[c])) <= 1) continue;
        if (bad++ < 5) {
          out << "(" << x << "," << y << ") channel " << c << ": fast " << int(a[c])
              << " reference " << int(b[c]) << "\n";
        }
        break;
      }
    }
  }
  if (bad) out << bad << " pixels differ by more than 1/255";
  return out.str();
}

TEST(FastScenes, EverySceneFileMatchesTheReference) {
  PipelineContext one(1), two(2), three(3);
  for (const auto& file : scene_files()) {
    LoadOptions opts;
    opts.overrides = {"image.width=200", "image.height=150"};
    LoadResult r = load_scene_file(file.string(), opts);
    ASSERT_TRUE(r.scene) << r.diagnostics.to_string();
    // The scene's own shading, then each mode for every object (the scene's own alone in the
    // ThreadSanitizer build: random_cases).
    const std::array<std::optional<ShadingMode>, 4> modes = {std::nullopt, ShadingMode::kFlat, ShadingMode::kGouraud,
                                                             ShadingMode::kPhong};
    for (std::size_t m = 0; m < test::random_cases(unsigned(modes.size())); ++m) {
      const std::optional<ShadingMode> mode = modes[m];
      RenderOptions ref;
      ref.shading = mode;
      ref.reference = true;
      RenderStats ref_stats;
      Image expected = render_scene(*r.scene, ref, &ref_stats);
      for (PipelineContext* ctx : {&one, &two, &three}) {
        RenderOptions fast;
        fast.shading = mode;
        fast.context = ctx;
        RenderStats stats;
        Image actual = render_scene(*r.scene, fast, &stats);
        SCOPED_TRACE(file.filename().string() + " mode " + std::to_string(mode ? int(*mode) : -1) +
                     " threads " + std::to_string(ctx->threads()));
        EXPECT_EQ(compare_images(actual, expected), "");
        EXPECT_EQ(stats.fragments, ref_stats.fragments);
        EXPECT_EQ(stats.pixels_shaded, ref_stats.pixels_shaded);
        EXPECT_EQ(stats.triangles_rasterized, ref_stats.triangles_rasterized);
      }
    }
  }
}

TEST(FastScenes, DefaultIsTheFastPipelineAndReferenceIsSelectable) {
  LoadResult r = load_scene_file(std::string(SHADELAB_SOURCE_DIR) + "/scenes/teapot.json");
  ASSERT_TRUE(r.scene);
  RenderOptions opts;
  opts.threads = 2;
  Image fast = render_scene(*r.scene, opts);
  opts.reference = true;
  Image reference = render_scene(*r.scene, opts);
  EXPECT_EQ(compare_images(fast, reference), "");
}

}  // namespace
}  // namespace shadelab
