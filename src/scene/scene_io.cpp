// The scene reader's entry points: read the file (bounded), parse JSON with positions, apply
// --set overrides, validate into a Scene, and hand back every problem in file order.
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "scene/overrides.hpp"
#include "scene/scene_reader.hpp"
#include "shadelab/scene_io.hpp"

namespace shadelab {

namespace {

// Problems in the order of the text (overrides, with no line, last), so that they read top down.
Diagnostics in_file_order(const Diagnostics& diags) {
  std::vector<Diagnostic> items = diags.items();
  auto key = [](const Diagnostic& d) {
    return std::pair(d.location.line > 0 ? d.location.line : INT_MAX, d.location.column);
  };
  std::stable_sort(items.begin(), items.end(),
                   [&](const Diagnostic& a, const Diagnostic& b) { return key(a) < key(b); });
  Diagnostics sorted;
  for (Diagnostic& d : items) sorted.error(std::move(d.location), std::move(d.key_path), std::move(d.message));
  return sorted;
}

LoadResult file_error(const std::string& path, const std::string& message) {
  LoadResult r;
  r.diagnostics.error({path, 0, 0}, "", message);
  return r;
}

}  // namespace

LoadResult parse_scene(std::string_view text, const std::string& filename, const std::string& base_dir,
                       const LoadOptions& options) {
  LoadResult result;
  detail::JsonValue root;
  if (!detail::parse_json(text, filename, root, result.diagnostics)) return result;
  for (const std::string& o : options.overrides) detail::apply_override(root, o, result.diagnostics);
  if (!result.diagnostics.empty()) return result;
  Scene scene;
  detail::SceneReader(filename, base_dir, options, result.diagnostics).read(root, scene);
  if (result.diagnostics.empty()) {
    result.scene = std::move(scene);
  } else {
    result.diagnostics = in_file_order(result.diagnostics);
  }
  return result;
}

LoadResult load_scene_file(const std::string& path, const LoadOptions& options) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return file_error(path, "cannot open scene file: Is a directory");
  std::ifstream f(path, std::ios::binary);
  if (!f) return file_error(path, std::string("cannot open scene file: ") + std::strerror(errno));
  // Read in chunks up to the limit: special files (/dev/zero) never end.
  std::string text;
  char chunk[1 << 16];
  while (f.read(chunk, sizeof chunk) || f.gcount() > 0) {
    text.append(chunk, std::size_t(f.gcount()));
    if (text.size() > detail::kMaxJsonBytes) {
      return file_error(path, "the file is longer than " + std::to_string(detail::kMaxJsonBytes) +
                                  " bytes, the limit for a scene");
    }
  }
  std::string base = std::filesystem::path(path).parent_path().string();
  return parse_scene(text, path, base.empty() ? "." : base, options);
}

}  // namespace shadelab
