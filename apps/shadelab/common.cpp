// Helpers shared by the subcommands: --size parsing and the default font.
#include <iostream>
#include <regex>

#include "commands.hpp"

namespace shadelab::cli {

bool add_size_overrides(const std::string& size, const char* command,
                        std::vector<std::string>& overrides) {
  std::smatch m;
  if (!std::regex_match(size, m, std::regex(R"((\d{1,9})x(\d{1,9}))"))) {
    std::cerr << "shadelab " << command << ": --size: expected WIDTHxHEIGHT (e.g. 1920x1080), got \""
              << size << "\"\n";
    return false;
  }
  overrides.push_back("image.width=" + m[1].str());
  overrides.push_back("image.height=" + m[2].str());
  return true;
}

std::unique_ptr<Font> load_default_font(const char* command) {
  std::string error;
  std::unique_ptr<Font> font = Font::load(Font::kDefaultPath, &error);
  if (!font) std::cerr << "shadelab " << command << ": " << error << "\n";
  return font;
}

}  // namespace shadelab::cli
