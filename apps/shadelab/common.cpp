// Helpers shared by the subcommands: --size parsing, the default font and the progress bar.
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <iostream>

#include "commands.hpp"

namespace shadelab::cli {

namespace {

// 1 to 9 decimal digits.
bool is_count(const std::string& s) {
  if (s.empty() || s.size() > 9) return false;
  for (char c : s) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  }
  return true;
}

}  // namespace

bool add_size_overrides(const std::string& size, const char* command,
                        std::vector<std::string>& overrides) {
  std::size_t x = size.find('x');
  std::string width = size.substr(0, x), height = x == std::string::npos ? "" : size.substr(x + 1);
  if (!is_count(width) || !is_count(height)) {
    std::cerr << "shadelab " << command << ": --size: expected WIDTHxHEIGHT (e.g. 1920x1080), got \""
              << size << "\"\n";
    return false;
  }
  overrides.push_back("image.width=" + width);
  overrides.push_back("image.height=" + height);
  return true;
}

std::unique_ptr<Font> load_default_font(const char* command) {
  std::string error;
  std::unique_ptr<Font> font = Font::load(Font::kDefaultPath, &error);
  if (!font) std::cerr << "shadelab " << command << ": " << error << "\n";
  return font;
}

void progress_bar(int done, int total, const std::string& label) {
  if (!isatty(STDERR_FILENO)) return;
  const int width = 30;
  int filled = total > 0 ? done * width / total : width;
  std::fprintf(stderr, "\r[%s%s] %d/%d %-40.40s", std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), done, total, label.c_str());
  if (done == total) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

}  // namespace shadelab::cli
