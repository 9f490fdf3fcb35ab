// PNG encoding through libpng and atomic file writes (reading is read_image.cpp's; animated
// PNG is write_apng.cpp's).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>

#include <png.h>

#include "shadelab/image.hpp"

namespace shadelab {

namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + length);
}

void no_flush(png_structp) {}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  std::vector<std::uint8_t> out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return out;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, info ? &info : nullptr);
    out.clear();
    return out;
  }
  png_set_write_fn(png, &out, append_bytes, no_flush);
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, 6);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, const_cast<png_bytep>(image.pixel(0, y)));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

bool write_file_atomically(const std::vector<std::uint8_t>& bytes, const std::string& path, std::string* error) {
  // Write beside the target, then rename over it: readers never see a partial file.
  std::string tmp = path + ".tmp" + std::to_string(std::random_device{}() & 0xffffff);
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) {
      if (error) *error = "cannot write " + path + ": " + std::strerror(errno);
      return false;
    }
    f.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    f.close();
    if (!f) {
      if (error) *error = "cannot write " + path + ": " + std::strerror(errno);
      std::remove(tmp.c_str());
      return false;
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    if (error) *error = "cannot write " + path + ": " + std::strerror(errno);
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

bool write_png(const Image& image, const std::string& path, std::string* error) {
  if (image.width <= 0 || image.height <= 0) {
    if (error) *error = "cannot write an empty image";
    return false;
  }
  std::vector<std::uint8_t> bytes = encode_png(image);
  if (bytes.empty()) {
    if (error) *error = "PNG encoding failed";
    return false;
  }
  return write_file_atomically(bytes, path, error);
}

}  // namespace shadelab
