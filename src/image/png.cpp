// PNG encoding through libpng, atomic file writes, and image reading through stb_image.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include <png.h>
#include <stb_image.h>

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

bool read_image(const std::string& path, Image& out, std::string* error, int max_side) {
  // Only PNG and JPEG: stb_image would also take headerless formats (TGA) from almost any
  // bytes, and its PNM reader reads past the end of short files.
  unsigned char magic[8] = {};
  {
    std::ifstream f(path, std::ios::binary);
    if (!f) {
      if (error) *error = "cannot read image " + path + ": " + std::strerror(errno);
      return false;
    }
    f.read(reinterpret_cast<char*>(magic), sizeof magic);
  }
  static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  bool png = std::memcmp(magic, kPng, 8) == 0;
  bool jpeg = magic[0] == 0xff && magic[1] == 0xd8 && magic[2] == 0xff;
  if (!png && !jpeg) {
    if (error) *error = "cannot read image " + path + ": not a PNG or JPEG file";
    return false;
  }
  int w = 0, h = 0, channels = 0;
  if (stbi_info(path.c_str(), &w, &h, &channels) && (w > max_side || h > max_side)) {
    if (error) {
      *error = "the image " + path + " is " + std::to_string(w) + " x " + std::to_string(h) +
               ", more than the limit of " + std::to_string(max_side) + " x " + std::to_string(max_side);
    }
    return false;
  }
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (!data) {
    if (error) *error = "cannot read image " + path + ": " + stbi_failure_reason();
    return false;
  }
  if (w <= 0 || h <= 0) {  // never an image without pixels
    stbi_image_free(data);
    if (error) *error = "cannot read image " + path + ": it has no pixels";
    return false;
  }
  out.width = w;
  out.height = h;
  out.rgba.assign(data, data + std::size_t(w) * std::size_t(h) * 4);
  stbi_image_free(data);
  return true;
}

}  // namespace shadelab
