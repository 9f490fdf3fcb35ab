// Sharded batches' parts and manifests (shard.hpp).
#include "shard.hpp"

#include <cstdio>
#include <filesystem>

#include "text_file.hpp"

namespace shadelab::cli {

namespace fs = std::filesystem;

bool parse_shard(const std::string& text, Shard& out, std::string* error) {
  int i = 0, n = 0;
  char slash = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &i, &slash, &n, &extra) != 3 || slash != '/' || n < 1 || n > 100000 ||
      i < 1 || i > n) {
    if (error) *error = "--shard: expected I/N with 1 <= I <= N (the I-th of N parts), got \"" + text + "\"";
    return false;
  }
  out.index = i;
  out.count = n;
  return true;
}

std::string parts_dir(const std::string& output) {
  std::string o = output;
  while (o.size() > 1 && o.back() == '/') o.pop_back();
  return o + ".parts";
}

std::string part_path(const std::string& output, std::size_t part, const std::string& extension) {
  char name[32];
  std::snprintf(name, sizeof name, "part-%05zu", part);
  return (fs::path(parts_dir(output)) / (name + extension)).string();
}

bool write_manifest(const std::string& output, const nlohmann::json& manifest, std::string* error) {
  std::error_code ec;
  fs::create_directories(parts_dir(output), ec);
  if (ec) {
    if (error) *error = "cannot create " + parts_dir(output) + ": " + ec.message();
    return false;
  }
  const std::string text = manifest.dump(2) + "\n";
  return write_file_atomically(std::vector<std::uint8_t>(text.begin(), text.end()),
                               (fs::path(parts_dir(output)) / "manifest.json").string(), error);
}

std::optional<nlohmann::json> read_manifest(const std::string& output, std::string* error) {
  const fs::path path = fs::path(parts_dir(output)) / "manifest.json";
  const std::optional<std::string> text = read_text_file(path.string());
  if (!text) {
    if (error) *error = "no " + path.string() + ": run the command with --shard I/N first";
    return std::nullopt;
  }
  nlohmann::json m = nlohmann::json::parse(*text, nullptr, false);
  if (!m.is_object() || !m.contains("command") || !m["command"].is_string() || !m.contains("parts") ||
      !m["parts"].is_number_unsigned()) {
    if (error) *error = path.string() + ": not a shadelab batch manifest";
    return std::nullopt;
  }
  return m;
}

std::vector<std::size_t> missing_parts(const std::string& output, std::size_t count, const std::string& extension) {
  std::vector<std::size_t> missing;
  for (std::size_t k = 0; k < count; ++k) {
    std::error_code ec;
    if (!fs::is_regular_file(part_path(output, k, extension), ec)) missing.push_back(k);
  }
  return missing;
}

bool read_part(const std::string& output, std::size_t part, Image& image, std::string* error) {
  return read_image(part_path(output, part), image, error, 1 << 15);
}

bool write_part(const std::string& output, std::size_t part, const Image& image, std::string* error) {
  return write_png(image, part_path(output, part), error);
}

}  // namespace shadelab::cli
