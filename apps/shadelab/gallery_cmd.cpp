// `shadelab gallery OUTDIR`: renders every figure scene in scenes/lecture and every row
// experiment listed in scenes/lecture/rows.json, and writes OUTDIR/index.html showing each
// picture with its caption, its parameters and the command that reproduces it.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "shadelab/scene_io.hpp"
#include "sweep.hpp"

namespace shadelab::cli {

namespace {

namespace fs = std::filesystem;

struct GalleryArgs {
  std::string outdir;
  std::string scenes = "scenes/lecture";
  int samples = 4;
};

struct Entry {
  std::string title, image, caption, parameters, command;
};

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string read_text(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

bool render_figure(const fs::path& scene, const GalleryArgs& a, std::vector<Entry>& entries,
                   Diagnostics& diags) {
  LoadOptions opts;
  opts.overrides.push_back("image.samples=" + std::to_string(a.samples));  // checked by the reader
  LoadResult r = load_scene_file(scene.string(), opts);
  if (!r.scene) {
    diags.append(r.diagnostics);
    return false;
  }
  std::string png = scene.stem().string() + ".png";
  std::string error;
  if (!write_png(render_scene(*r.scene), (fs::path(a.outdir) / png).string(), &error)) {
    diags.error({}, "", error);
    return false;
  }
  entries.push_back({scene.stem().string(), png, r.scene->caption, read_text(scene),
                     "shadelab render " + scene.string() + " --samples " +
                         std::to_string(a.samples) + " -o " + png});
  return true;
}

// rows.json: [{"name", "title", "scene", "vary": ["KEY=V1,V2", ...], "set": [...], "caption"}]
bool render_rows(const fs::path& manifest, const GalleryArgs& a, const Font& font,
                 std::vector<Entry>& entries, Diagnostics& diags) {
  nlohmann::json rows = nlohmann::json::parse(read_text(manifest), nullptr, false);
  if (!rows.is_array()) {
    diags.error({manifest.string(), 0, 0}, "", "expected a JSON array of rows");
    return false;
  }
  for (const auto& row : rows) {
    SweepRequest r;
    r.scene = (manifest.parent_path() / row.value("scene", "")).string();
    r.title = row.value("title", "");
    r.samples = a.samples;
    std::string command = "shadelab sweep " + r.scene;
    for (const auto& v : row.value("vary", nlohmann::json::array())) {
      Variation var;
      std::string error;
      if (!v.is_string() || !parse_variation(v.get<std::string>(), var, &error)) {
        diags.error({manifest.string(), 0, 0}, "", error.empty() ? "vary entries are strings" : error);
        return false;
      }
      r.vary.push_back(var);
      command += " --vary '" + v.get<std::string>() + "'";
    }
    for (const auto& l : row.value("labels", nlohmann::json::array())) {
      if (l.is_string()) r.labels.push_back(l.get<std::string>());
    }
    for (const auto& s : row.value("set", nlohmann::json::array())) {
      r.overrides.push_back(s.get<std::string>());
      command += " --set '" + s.get<std::string>() + "'";
    }
    std::string png = row.value("name", "row") + ".png";
    std::optional<Image> sheet = run_sweep(r, font, diags, nullptr);
    std::string error;
    if (!sheet || !write_png(*sheet, (fs::path(a.outdir) / png).string(), &error)) {
      if (!error.empty()) diags.error({}, "", error);
      return false;
    }
    command += " --samples " + std::to_string(a.samples) + " -o " + png;
    entries.push_back({r.title, png, row.value("caption", ""), read_text(r.scene), command});
  }
  return true;
}

void write_index(const GalleryArgs& a, const std::vector<Entry>& entries) {
  std::ofstream html(fs::path(a.outdir) / "index.html");
  html << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
          "<title>shadelab: Lighting, Shading and Materials</title>\n<style>\n"
          "body{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#222}\n"
          "figure{margin:2em 0;border-top:1px solid #ccc;padding-top:1em}\n"
          "img{max-width:100%;border:1px solid #999}\n"
          "code{background:#f3f3f3;padding:.2em .4em}\n"
          "details pre{background:#f7f7f7;padding:.6em;overflow:auto;font-size:85%}\n"
          "</style></head><body>\n<h1>Lecture 14: Lighting, Shading and Materials</h1>\n"
          "<p>Every figure of the lecture, rendered by shadelab. Each picture shows its caption, "
          "the command that reproduces it and the scene file it comes from.</p>\n";
  for (const Entry& e : entries) {
    html << "<figure id=\"" << html_escape(e.title) << "\">\n<h2>" << html_escape(e.title)
         << "</h2>\n<img src=\"" << html_escape(e.image) << "\" alt=\"" << html_escape(e.title)
         << "\">\n<figcaption><p>" << html_escape(e.caption) << "</p>\n<p><code>"
         << html_escape(e.command) << "</code></p>\n<details><summary>parameters</summary><pre>"
         << html_escape(e.parameters) << "</pre></details></figcaption>\n</figure>\n";
  }
  html << "</body></html>\n";
}

int run(const GalleryArgs& a) {
  std::error_code ec;
  fs::create_directories(a.outdir, ec);
  if (ec) {
    std::cerr << "shadelab gallery: cannot create " << a.outdir << ": " << ec.message() << "\n";
    return kExitFailure;
  }
  std::vector<fs::path> scenes;
  for (const auto& f : fs::directory_iterator(a.scenes, ec)) {
    if (f.path().extension() == ".json" && f.path().filename() != "rows.json") scenes.push_back(f.path());
  }
  if (ec || scenes.empty()) {
    std::cerr << "shadelab gallery: no scene files in " << a.scenes << "\n";
    return kExitBadInput;
  }
  std::sort(scenes.begin(), scenes.end());
  std::unique_ptr<Font> font = load_default_font("gallery");
  if (!font) return kExitFailure;
  std::vector<Entry> entries;
  Diagnostics diags;
  for (const fs::path& s : scenes) {
    if (!render_figure(s, a, entries, diags)) break;
    std::cerr << "gallery: " << entries.back().image << "\n";
  }
  fs::path rows = fs::path(a.scenes) / "rows.json";
  if (diags.empty() && fs::exists(rows)) {
    try {
      render_rows(rows, a, *font, entries, diags);
    } catch (const nlohmann::json::exception& e) {  // a value of the wrong type in rows.json
      diags.error({rows.string(), 0, 0}, "", e.what());
    }
  }
  if (!diags.empty()) {
    std::cerr << diags.to_string();
    return kExitBadInput;
  }
  write_index(a, entries);
  std::cout << "gallery: " << entries.size() << " pictures, open "
            << (fs::path(a.outdir) / "index.html").string() << "\n";
  return kExitOk;
}

}  // namespace

Action add_gallery_command(CLI::App& app) {
  auto a = std::make_shared<GalleryArgs>();
  CLI::App* cmd = app.add_subcommand("gallery", "Render every figure of the lecture into a web page");
  cmd->add_option("outdir", a->outdir, "Output folder (created if needed)")->required();
  cmd->add_option("--scenes", a->scenes, "Folder of figure scenes and rows.json")
      ->capture_default_str();
  cmd->add_option("--samples", a->samples, "Anti-aliasing samples per pixel")
      ->check(CLI::Range(1, 64))->capture_default_str();
  cmd->footer("Example:\n  shadelab gallery out/gallery    (then open out/gallery/index.html)");
  return [a] { return run(*a); };
}

}  // namespace shadelab::cli
