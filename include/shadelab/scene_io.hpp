// Reading scene files (JSON, format in docs/scene-format.md) into a validated Scene, with
// errors that name file, line, column and key path. Never prints, never exits, never throws
// on bad input.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadelab/diagnostics.hpp"
#include "shadelab/scene.hpp"

namespace shadelab {

struct LoadOptions {
  /// "key.path=value" overrides applied before validation (the CLI's --set), e.g.
  /// "lights[0].spot.cutoff=30". The value is JSON, or a bare word taken as a string.
  std::vector<std::string> overrides;
  /// Limits against hostile input.
  long long max_pixels = 16384LL * 16384LL;
  long long max_triangles = 20'000'000;
  int max_lights = 1024;
  /// Longest side of a texture image, checked from its header before it is decoded.
  int max_texture_side = 8192;
  /// Mesh and texture files must lie inside the scene's folder (after symbolic links are
  /// followed): for scenes from untrusted sources, such as the lab's requests.
  bool confine_files = false;
};

struct LoadResult {
  std::optional<Scene> scene;  ///< set only when there are no diagnostics
  Diagnostics diagnostics;
};

/// Reads and validates the scene file at `path`; relative mesh paths are resolved against the
/// file's folder.
LoadResult load_scene_file(const std::string& path, const LoadOptions& options = {});

/// Same, from text in memory; `filename` is used in messages, `base_dir` to resolve mesh paths.
LoadResult parse_scene(std::string_view text, const std::string& filename,
                       const std::string& base_dir, const LoadOptions& options = {});

}  // namespace shadelab
