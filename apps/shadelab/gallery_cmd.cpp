// `shadelab gallery OUTDIR`: renders every figure scene in scenes/lecture and every row
// experiment listed in scenes/lecture/rows.json (its contact sheet, and an animation of its
// pictures), and writes OUTDIR/index.html showing each picture with its caption, its
// parameters and the command that reproduces it. With --shard I/N it renders its share of the
// pictures into OUTDIR.parts/ for `shadelab merge OUTDIR` (shard.hpp).
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"
#include "shard.hpp"
#include "sweep.hpp"
#include "text_file.hpp"

namespace shadelab::cli {

namespace {

namespace fs = std::filesystem;

struct GalleryArgs {
  std::string outdir, shard;
  std::string scenes = "scenes/lecture";
  int samples = 4;
};

struct Entry {
  std::string title, image, animation, caption, parameters, command;  // animation: "" for none
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

std::string read_text(const fs::path& p) { return read_text_file(p.string()).value_or(""); }

// One picture of the gallery (a figure, or a row with its animation): its entry in the page
// and how to render its files into a folder.
struct Item {
  Entry entry;
  std::function<bool(const fs::path& dir, Diagnostics& diags)> render;
};

bool figure_item(const fs::path& scene, const GalleryArgs& a, std::vector<Item>& items, Diagnostics& diags) {
  LoadOptions opts;
  opts.overrides.push_back("image.samples=" + std::to_string(a.samples));  // checked by the reader
  LoadResult r = load_scene_file(scene.string(), opts);
  if (!r.scene) {
    diags.append(r.diagnostics);
    return false;
  }
  const std::string png = scene.stem().string() + ".png";
  Item item;
  item.entry = {scene.stem().string(), png, "", r.scene->caption, read_text(scene),
                "shadelab render " + scene.string() + " --samples " + std::to_string(a.samples) + " -o " + png};
  item.render = [scene = std::make_shared<Scene>(std::move(*r.scene)), png](const fs::path& dir, Diagnostics& d) {
    std::string error;
    if (!write_png(render_scene(*scene), (dir / png).string(), &error)) {
      d.error({}, "", error);
      return false;
    }
    return true;
  };
  items.push_back(std::move(item));
  return true;
}

// rows.json: [{"name", "title", "scene", "vary": ["KEY=V1,V2", ...], "set": [...], "caption"}].
// A row is its contact sheet and an animation of its pictures, one a second (a row of one
// picture, an empty `vary`, has no animation).
bool row_items(const fs::path& manifest, const GalleryArgs& a, const Font& font, std::vector<Item>& items,
               Diagnostics& diags) {
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
    const std::string name = row.value("name", "row");
    const std::string png = name + ".png";
    const std::string animation = r.vary.empty() ? "" : name + "-animation.png";  // a single picture is not animated
    command += " --samples " + std::to_string(a.samples) + " -o " + png;
    Item item;
    item.entry = {r.title, png, animation, row.value("caption", ""), read_text(r.scene), command};
    item.render = [r, png, animation, &font](const fs::path& dir, Diagnostics& d) {
      std::vector<Image> pictures;
      std::optional<Image> sheet = run_sweep(r, font, d, nullptr, &pictures);
      std::string error;
      if (!sheet || !write_png(*sheet, (dir / png).string(), &error) ||
          (!animation.empty() && !write_apng(pictures, (dir / animation).string(), 1, 1, &error))) {
        if (!error.empty()) d.error({}, "", error);
        return false;
      }
      return true;
    };
    items.push_back(std::move(item));
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
         << "\">\n";
    if (!e.animation.empty()) {
      html << "<p>As an animation, one picture a second:</p>\n<img src=\"" << html_escape(e.animation)
           << "\" alt=\"" << html_escape(e.title) << " (animated)\">\n";
    }
    html << "<figcaption><p>" << html_escape(e.caption) << "</p>\n<p><code>"
         << html_escape(e.command) << "</code></p>\n<details><summary>parameters</summary><pre>"
         << html_escape(e.parameters) << "</pre></details></figcaption>\n</figure>\n";
  }
  html << "</body></html>\n";
}

// Every item of the gallery, in the page's order: the figures, then the rows. Prints errors.
std::optional<std::vector<Item>> gallery_items(const GalleryArgs& a, const Font& font) {
  std::error_code ec;
  std::vector<fs::path> scenes;
  for (const auto& f : fs::directory_iterator(a.scenes, ec)) {
    if (f.path().extension() == ".json" && f.path().filename() != "rows.json") scenes.push_back(f.path());
  }
  if (ec || scenes.empty()) {
    std::cerr << "shadelab gallery: no scene files in " << a.scenes << "\n";
    return std::nullopt;
  }
  std::sort(scenes.begin(), scenes.end());
  std::vector<Item> items;
  Diagnostics diags;
  for (const fs::path& s : scenes) {
    if (!figure_item(s, a, items, diags)) break;
  }
  fs::path rows = fs::path(a.scenes) / "rows.json";
  if (diags.empty() && fs::exists(rows)) {
    try {
      row_items(rows, a, font, items, diags);
    } catch (const nlohmann::json::exception& e) {  // a value of the wrong type in rows.json
      diags.error({rows.string(), 0, 0}, "", e.what());
    }
  }
  if (!diags.empty()) {
    std::cerr << diags.to_string();
    return std::nullopt;
  }
  return items;
}

// The item's part: a folder of its files, made under another name and renamed when complete.
fs::path part_folder(const GalleryArgs& a, std::size_t k) { return part_path(a.outdir, k, ""); }

nlohmann::json manifest_of(const GalleryArgs& a, std::size_t parts) {
  return {{"command", "gallery"}, {"parts", parts}, {"scenes", a.scenes}, {"samples", a.samples}};
}

int run_shard(const GalleryArgs& a, const std::vector<Item>& items, const Shard& shard) {
  std::string error;
  if (!write_manifest(a.outdir, manifest_of(a, items.size()), &error)) {
    std::cerr << "shadelab gallery: " << error << "\n";
    return kExitFailure;
  }
  for (std::size_t k = 0; k < items.size(); ++k) {
    std::error_code ec;
    if (!shard.owns(k) || fs::is_directory(part_folder(a, k), ec)) continue;
    const fs::path tmp = part_folder(a, k).string() + ".tmp" + std::to_string(getpid());
    fs::remove_all(tmp, ec);
    fs::create_directories(tmp, ec);
    Diagnostics diags;
    if (ec || !items[k].render(tmp, diags)) {
      std::cerr << (ec ? "shadelab gallery: cannot create " + tmp.string() + "\n" : diags.to_string());
      return kExitFailure;
    }
    fs::rename(tmp, part_folder(a, k), ec);
    if (ec) {
      std::cerr << "shadelab gallery: cannot write " << part_folder(a, k).string() << ": " << ec.message() << "\n";
      return kExitFailure;
    }
    std::cerr << "gallery: " << items[k].entry.image << "\n";
  }
  return kExitOk;
}

int run(const GalleryArgs& a) {
  Shard shard;
  std::string error;
  if (!a.shard.empty() && !parse_shard(a.shard, shard, &error)) {
    std::cerr << error << "\n";
    return kExitBadInput;
  }
  std::error_code ec;
  fs::create_directories(a.outdir, ec);
  if (ec) {
    std::cerr << "shadelab gallery: cannot create " << a.outdir << ": " << ec.message() << "\n";
    return kExitFailure;
  }
  std::unique_ptr<Font> font = load_default_font("gallery");
  if (!font) return kExitFailure;
  std::optional<std::vector<Item>> items = gallery_items(a, *font);
  if (!items) return kExitBadInput;
  if (shard.active()) return run_shard(a, *items, shard);
  std::vector<Entry> entries;
  for (const Item& item : *items) {
    Diagnostics diags;
    if (!item.render(a.outdir, diags)) {
      std::cerr << diags.to_string();
      return kExitBadInput;
    }
    entries.push_back(item.entry);
    std::cerr << "gallery: " << item.entry.image << "\n";
  }
  write_index(a, entries);
  std::cout << "gallery: " << entries.size() << " pictures, open "
            << (fs::path(a.outdir) / "index.html").string() << "\n";
  return kExitOk;
}

}  // namespace

int merge_gallery(const nlohmann::json& m, const std::string& output) {
  GalleryArgs a;
  a.outdir = output;
  a.scenes = m.value("scenes", a.scenes);
  a.samples = m.value("samples", a.samples);
  std::unique_ptr<Font> font = load_default_font("merge");
  if (!font) return kExitFailure;
  std::optional<std::vector<Item>> items = gallery_items(a, *font);
  if (!items) return kExitBadInput;
  std::error_code ec;
  for (std::size_t k = 0; k < items->size(); ++k) {
    if (!fs::is_directory(part_folder(a, k), ec)) {
      std::cerr << "shadelab merge: " << part_folder(a, k).string() << " (" << (*items)[k].entry.image
                << ") is not there yet; run the missing shards (they skip the parts already there)\n";
      return kExitFailure;
    }
  }
  fs::create_directories(a.outdir, ec);
  std::vector<Entry> entries;
  for (std::size_t k = 0; k < items->size(); ++k) {
    for (const auto& f : fs::directory_iterator(part_folder(a, k), ec)) {
      fs::copy_file(f.path(), fs::path(a.outdir) / f.path().filename(), fs::copy_options::overwrite_existing, ec);
      if (ec) {
        std::cerr << "shadelab merge: cannot copy " << f.path().string() << ": " << ec.message() << "\n";
        return kExitFailure;
      }
    }
    entries.push_back((*items)[k].entry);
  }
  write_index(a, entries);
  return kExitOk;
}

Action add_gallery_command(CLI::App& app) {
  auto a = std::make_shared<GalleryArgs>();
  CLI::App* cmd = app.add_subcommand("gallery", "Render every figure of the lecture into a web page");
  cmd->add_option("outdir", a->outdir, "Output folder (created if needed)")->required();
  cmd->add_option("--scenes", a->scenes, "Folder of figure scenes and rows.json")
      ->capture_default_str();
  cmd->add_option("--samples", a->samples, "Anti-aliasing samples per pixel")
      ->check(CLI::Range(1, 64))->capture_default_str();
  cmd->add_option("--shard", a->shard,
                  "I/N: render only the I-th of N shares of the pictures into OUTDIR.parts/ (then shadelab merge OUTDIR)");
  cmd->footer("Example:\n  shadelab gallery out/gallery    (then open out/gallery/index.html)");
  return [a] { return run(*a); };
}

}  // namespace shadelab::cli
