// Reading PNG and JPEG files: the format from the file's first bytes, the size its header
// declares checked against the caller's limit before anything is decoded, then libpng or
// libjpeg-turbo (decoders.hpp). Every error names the file.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "image/decoders.hpp"
#include "shadelab/image.hpp"

namespace shadelab {

namespace {

struct CloseFile {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, CloseFile>;

enum class Format { kPng, kJpeg };

// An image file opened and sniffed; the size is known when its header could be read.
struct Opened {
  File file;
  Format format = Format::kPng;
  bool size_known = false;
  std::uint32_t width = 0, height = 0;
};

std::string cannot_read(const std::string& path, const std::string& why) {
  return "cannot read image " + path + ": " + why;
}

// Only PNG and JPEG, told by their signatures (PNG specification section 5.2; JPEG's SOI
// marker and the next marker's 0xff). Other formats are refused before any decoder sees them.
bool open_image(const std::string& path, Opened& f, std::string& error) {
  f.file.reset(std::fopen(path.c_str(), "rb"));
  if (!f.file) {
    error = cannot_read(path, std::strerror(errno));
    return false;
  }
  std::uint8_t first[24] = {};
  const std::size_t got = std::fread(first, 1, sizeof first, f.file.get());
  if (std::ferror(f.file.get())) {  // a folder, for one
    error = cannot_read(path, std::strerror(errno));
    return false;
  }
  static const std::uint8_t kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (got >= 8 && std::memcmp(first, kPng, 8) == 0) {
    f.format = Format::kPng;
    // Short or odd headers are left to libpng, whose error says what is wrong.
    f.size_known = got == sizeof first && detail::png_header_size(first, f.width, f.height);
    return true;
  }
  if (got >= 3 && first[0] == 0xff && first[1] == 0xd8 && first[2] == 0xff) {
    f.format = Format::kJpeg;
    std::rewind(f.file.get());
    std::string why;
    if (!detail::jpeg_header_size(f.file.get(), f.width, f.height, why)) {
      error = cannot_read(path, why);
      return false;
    }
    f.size_known = true;
    return true;
  }
  error = cannot_read(path, "not a PNG or JPEG file");
  return false;
}

}  // namespace

bool read_image_size(const std::string& path, int& width, int& height, std::string* error) {
  Opened f;
  std::string why;
  if (!open_image(path, f, why)) {
    if (error) *error = why;
    return false;
  }
  if (!f.size_known) {
    if (error) *error = cannot_read(path, "invalid PNG: no valid IHDR chunk after the signature");
    return false;
  }
  // A PNG's sides are at most 2^31 - 1 (png_header_size), a JPEG's 65535: both fit an int.
  width = int(f.width);
  height = int(f.height);
  return true;
}

bool read_image(const std::string& path, Image& out, std::string* error, int max_side) {
  Opened f;
  std::string why;
  if (!open_image(path, f, why)) {
    if (error) *error = why;
    return false;
  }
  const auto limit = std::uint32_t(max_side < 1 ? 1 : max_side);
  if (f.size_known && (f.width > limit || f.height > limit)) {
    if (error) {
      *error = "the image " + path + " is " + std::to_string(f.width) + " x " +
               std::to_string(f.height) + ", more than the limit of " + std::to_string(limit) +
               " x " + std::to_string(limit);
    }
    return false;
  }
  std::rewind(f.file.get());
  const bool ok = f.format == Format::kPng ? detail::decode_png(f.file.get(), max_side, out, why)
                                           : detail::decode_jpeg(f.file.get(), max_side, out, why);
  if (!ok && error) *error = cannot_read(path, why);
  return ok;
}

}  // namespace shadelab
