// Helpers shared by the fuzz targets: a private scratch folder and writing an input there
// (for the readers that take a path).
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace shadelab::fuzz {

/// A folder of this process's own under the system's temporary folder.
inline const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() / ("shadelab-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

/// Writes the input to `name` in the scratch folder and returns the path.
inline std::string write_input(const char* name, const std::uint8_t* data, std::size_t size) {
  std::string path = (scratch() / name).string();
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

}  // namespace shadelab::fuzz
