// 8-bit RGBA images: PNG and animated PNG encoding, and reading PNG and JPEG files. The top
// row comes first.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes, top row first

  std::uint8_t* pixel(int x, int y) { return &rgba[(std::size_t(y) * width + x) * 4]; }
  const std::uint8_t* pixel(int x, int y) const {
    return &rgba[(std::size_t(y) * width + x) * 4];
  }
};

/// PNG bytes of `image` (RGBA, 8 bits per channel).
std::vector<std::uint8_t> encode_png(const Image& image);

/// Writes `image` as PNG to `path` atomically (a temporary file beside it, then a rename), so a
/// failed write never leaves a partial file. Returns false and sets `error` on failure.
bool write_png(const Image& image, const std::string& path, std::string* error);

/// Writes `bytes` to `path` atomically, as write_png does. Returns false and sets `error` on
/// failure.
bool write_file_atomically(const std::vector<std::uint8_t>& bytes, const std::string& path, std::string* error);

/// An animated PNG (APNG) of `frames`, all of one size, each shown for delay_num / delay_den
/// seconds, played `plays` times (0: for ever). Every frame is a whole picture (no blending
/// with the previous one); the first is also the still image that viewers without APNG
/// support show. Each frame is compressed by libpng exactly as encode_png compresses it, so
/// the same frames always give the same bytes. Empty on bad input (no frames, sizes differ,
/// a delay out of 16-bit range).
std::vector<std::uint8_t> encode_apng(const std::vector<Image>& frames, int delay_num, int delay_den,
                                      int plays = 0);

/// encode_apng written atomically to `path`. Returns false and sets `error` on failure.
bool write_apng(const std::vector<Image>& frames, const std::string& path, int delay_num, int delay_den,
                std::string* error);

/// Reads a PNG (libpng) or JPEG (libjpeg-turbo) file as RGBA, top row first: grey, grey with
/// alpha, RGB, RGBA and palette PNGs of any bit depth (16-bit samples keep their high byte, tRNS
/// becomes alpha), interlaced or not; baseline and progressive JPEGs in grey, YCbCr, RGB or
/// Adobe CMYK. Other formats are refused. Returns false and sets `error` (naming the file and
/// saying what is wrong) on failure, and, without decoding anything, when the file's header
/// declares a side longer than `max_side` pixels (a small file can declare a huge image;
/// decoding it would take gigabytes). A truncated file is an error.
bool read_image(const std::string& path, Image& out, std::string* error, int max_side = 16384);

/// The width and height in pixels that a PNG or JPEG file's header declares, read without
/// decoding the image (for checking against a limit). Returns false and sets `error` when the
/// file cannot be read, is neither PNG nor JPEG, or its header is invalid.
bool read_image_size(const std::string& path, int& width, int& height, std::string* error);

}  // namespace shadelab
