// Sweeps: one scene rendered once per value of one or two keys, laid out as a contact sheet.
// Shared by `shadelab sweep` and `shadelab gallery`.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "shadelab/contact_sheet.hpp"
#include "shadelab/diagnostics.hpp"
#include "shadelab/render.hpp"

namespace shadelab::cli {

/// One `--vary KEY=V1,V2,...`: the key path and its values (JSON texts or bare words).
struct Variation {
  std::string key;
  std::vector<std::string> values;
};

/// Parses "KEY=V1,V2,..." (commas inside [], {} or quotes do not split). False + error text
/// on a malformed expression.
bool parse_variation(const std::string& text, Variation& out, std::string* error);

struct SweepRequest {
  std::string scene;                    ///< the scene file (or, with `scene_text`, its name in messages)
  /// The scene's JSON itself, when it is not read from the file `scene` (the Python module's
  /// scenes made from dicts); mesh and texture paths are then resolved against `base_dir`.
  std::optional<std::string> scene_text;
  std::string base_dir = ".";
  std::vector<Variation> vary;          ///< one or two keys
  std::vector<std::string> overrides;   ///< --set, applied to every picture
  std::optional<ShadingMode> shading;   ///< --shading
  std::optional<int> samples;
  int columns = 0;                      ///< 0: one row per value of the second key
  std::string title;
  std::vector<std::string> labels;      ///< replace the "key = value" labels, in cell order
};

/// Renders every combination and makes the sheet. Problems go to `diags` (with file "--vary"
/// for a bad key or value); `progress(done, total, label)` is called after each picture.
std::optional<Image> run_sweep(const SweepRequest& request, const Font& font, Diagnostics& diags,
                               const std::function<void(int, int, const std::string&)>& progress);

/// "lights[0].spot.cutoff" -> "cutoff"; the pseudo-key "shading" stays "shading".
std::string short_key(const std::string& key);

}  // namespace shadelab::cli
