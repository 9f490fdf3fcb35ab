// Sweep logic: parsing --vary expressions, validating each value through the scene reader,
// rendering every combination and laying the pictures out with labels.
#include "sweep.hpp"

#include "shadelab/scene_io.hpp"

namespace shadelab::cli {

namespace {

// The request's scene with `options`: from its file, or from its text.
LoadResult load(const SweepRequest& r, const LoadOptions& options) {
  return r.scene_text ? parse_scene(*r.scene_text, r.scene, r.base_dir, options) : load_scene_file(r.scene, options);
}

std::vector<std::string> split_top_level(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (in_string) {
      if (c == '\\' && i + 1 < s.size()) cur += s[i++];
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (c == ']' || c == '}') {
      --depth;
    } else if (c == ',' && depth == 0) {
      out.push_back(cur);
      cur.clear();
      continue;
    }
    cur += c;
  }
  out.push_back(cur);
  return out;
}

std::optional<ShadingMode> shading_from(const std::string& v) {
  if (v == "flat") return ShadingMode::kFlat;
  if (v == "gouraud") return ShadingMode::kGouraud;
  if (v == "phong") return ShadingMode::kPhong;
  return std::nullopt;
}

// Diagnostics from overrides report file "--set"; those caused by a --vary value say so.
void relabel(Diagnostics& from, Diagnostics& to, const std::string& label) {
  for (Diagnostic d : from.items()) {
    if (d.location.file == "--set") d.location.file = label;
    to.error(d.location, d.key_path, d.message);
  }
}


// Checks the scene with the shared options first (errors against the file or --set), then each
// key/value alone so an error names the --vary value at fault.
bool validate(const SweepRequest& r, Diagnostics& diags) {
  LoadOptions base;
  base.overrides = r.overrides;
  if (r.samples) base.overrides.push_back("image.samples=" + std::to_string(*r.samples));
  LoadResult plain = load(r, base);
  if (!plain.scene) {
    diags.append(plain.diagnostics);
    return false;
  }
  for (const Variation& v : r.vary) {
    for (const std::string& value : v.values) {
      if (v.key == "shading") {
        if (!shading_from(value)) {
          diags.error({"--vary", 0, 0}, "shading",
                      "expected one of \"flat\", \"gouraud\", \"phong\", got \"" + value + "\"");
        }
        continue;
      }
      LoadOptions opts;
      opts.overrides = r.overrides;
      opts.overrides.push_back(v.key + "=" + value);
      if (r.samples) opts.overrides.push_back("image.samples=" + std::to_string(*r.samples));
      LoadResult res = load(r, opts);
      if (!res.scene) relabel(res.diagnostics, diags, "--vary");
      if (!diags.empty()) return false;  // one bad key gives the same error for every value
    }
  }
  return diags.empty();
}

void add_assignment(SweepCell& c, const std::string& key, const std::string& value) {
  if (key == "shading") c.shading = shading_from(value);
  else c.overrides.push_back(key + "=" + value);
  c.label += (c.label.empty() ? "" : ", ") + short_key(key) + " = " + value;
}

// Row-major cells: the first key varies along a row, the second (if any) down the columns.
std::vector<SweepCell> combinations(const SweepRequest& r) {
  std::vector<SweepCell> cells;
  if (r.vary.empty()) return {SweepCell{}};
  const Variation& across = r.vary[0];
  std::vector<std::string> down = r.vary.size() > 1 ? r.vary[1].values : std::vector<std::string>{""};
  for (const std::string& row_value : down) {
    for (const std::string& value : across.values) {
      SweepCell c;
      add_assignment(c, across.key, value);
      if (r.vary.size() > 1) add_assignment(c, r.vary[1].key, row_value);
      cells.push_back(c);
    }
  }
  return cells;
}

}  // namespace

std::string short_key(const std::string& key) {
  std::size_t dot = key.find_last_of('.');
  return dot == std::string::npos ? key : key.substr(dot + 1);
}

bool parse_variation(const std::string& text, Variation& out, std::string* error) {
  std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
    if (error) *error = "--vary: expected KEY=V1,V2,..., got \"" + text + "\"";
    return false;
  }
  out.key = text.substr(0, eq);
  out.values = split_top_level(text.substr(eq + 1));
  for (const std::string& v : out.values) {
    if (v.empty()) {
      if (error) *error = "--vary: " + out.key + ": empty value in \"" + text.substr(eq + 1) + "\"";
      return false;
    }
  }
  return true;
}

std::optional<std::vector<SweepCell>> sweep_cells(const SweepRequest& r, Diagnostics& diags) {
  if (!validate(r, diags)) return std::nullopt;
  std::vector<SweepCell> cells = combinations(r);
  if (r.labels.size() == cells.size()) {
    for (std::size_t i = 0; i < cells.size(); ++i) cells[i].label = r.labels[i];
  }
  return cells;
}

std::optional<Image> render_sweep_cell(const SweepRequest& r, const SweepCell& c, Diagnostics& diags) {
  LoadOptions opts;
  opts.overrides = r.overrides;
  opts.overrides.insert(opts.overrides.end(), c.overrides.begin(), c.overrides.end());
  // Through the reader, so samples are checked (square numbers, pixel limit) like any value.
  if (r.samples) opts.overrides.push_back("image.samples=" + std::to_string(*r.samples));
  LoadResult res = load(r, opts);
  if (!res.scene) {
    relabel(res.diagnostics, diags, "--vary");
    return std::nullopt;
  }
  RenderOptions ro;
  ro.shading = c.shading ? c.shading : r.shading;
  return render_scene(*res.scene, ro);
}

Image sweep_sheet(const SweepRequest& r, const std::vector<SweepCell>& cells, std::vector<Image> pictures,
                  const Font& font) {
  std::vector<SheetCell> sheet;
  for (std::size_t i = 0; i < cells.size() && i < pictures.size(); ++i) {
    sheet.push_back({std::move(pictures[i]), cells[i].label});
  }
  int columns = r.columns > 0 ? r.columns : int(r.vary.empty() ? 1 : r.vary[0].values.size());
  return make_contact_sheet(sheet, columns, font, r.title);
}

std::optional<Image> run_sweep(const SweepRequest& r, const Font& font, Diagnostics& diags,
                               const std::function<void(int, int, const std::string&)>& progress,
                               std::vector<Image>* pictures_out) {
  std::optional<std::vector<SweepCell>> cells = sweep_cells(r, diags);
  if (!cells) return std::nullopt;
  std::vector<Image> pictures;
  for (const SweepCell& c : *cells) {
    std::optional<Image> picture = render_sweep_cell(r, c, diags);
    if (!picture) return std::nullopt;
    pictures.push_back(std::move(*picture));
    if (progress) progress(int(pictures.size()), int(cells->size()), c.label);
  }
  if (pictures_out) *pictures_out = pictures;
  return sweep_sheet(r, *cells, std::move(pictures), font);
}

}  // namespace shadelab::cli
