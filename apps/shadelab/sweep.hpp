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

/// One picture of a sweep: the overrides and shading of its values, and its label.
struct SweepCell {
  std::vector<std::string> overrides;
  std::optional<ShadingMode> shading;
  std::string label;
};

/// Checks the request (the scene, then each key and value alone) and lists its pictures in
/// the sheet's order: the first key along a row, the second down the columns. Problems go to
/// `diags` (with file "--vary" for a bad key or value).
std::optional<std::vector<SweepCell>> sweep_cells(const SweepRequest& request, Diagnostics& diags);

/// One picture of the sweep.
std::optional<Image> render_sweep_cell(const SweepRequest& request, const SweepCell& cell, Diagnostics& diags);

/// The contact sheet of the pictures, one per cell, in order (the parts of a sharded sweep
/// give the same sheet as one run).
Image sweep_sheet(const SweepRequest& request, const std::vector<SweepCell>& cells, std::vector<Image> pictures,
                  const Font& font);

/// Renders every combination and makes the sheet. Problems go to `diags`;
/// `progress(done, total, label)` is called after each picture; `pictures`, when given,
/// receives the pictures themselves.
std::optional<Image> run_sweep(const SweepRequest& request, const Font& font, Diagnostics& diags,
                               const std::function<void(int, int, const std::string&)>& progress,
                               std::vector<Image>* pictures = nullptr);

/// "lights[0].spot.cutoff" -> "cutoff"; the pseudo-key "shading" stays "shading".
std::string short_key(const std::string& key);

}  // namespace shadelab::cli
