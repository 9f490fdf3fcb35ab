// The image decoders behind read_image (read_image.cpp): PNG through libpng, JPEG through
// libjpeg-turbo, each into 8-bit RGBA, top row first. They report failures as text (without
// the file's name: read_image adds it) and never print, exit, throw or abort: the libraries'
// error callbacks jump back to the decoder, which cleans up and returns false.
#pragma once

#include <cstdint>
#include <cstdio>
#include <new>
#include <string>

#include "shadelab/image.hpp"

namespace shadelab::detail {

/// Reserves the memory of `bytes` bytes of pixels in `out` without touching it: the decoders
/// fill it row by row as the file's data arrives, so that a small file declaring a large
/// image fails at its end before it costs memory. False when the allocator refuses.
inline bool reserve_pixels(Image& out, std::size_t bytes) noexcept {
  try {
    out.rgba.reserve(bytes);
    return true;
  } catch (const std::bad_alloc&) {
    return false;
  }
}

/// The width and height in a PNG's IHDR chunk, read from the file's first 24 bytes (the
/// signature, then IHDR: the PNG specification, section 5.6, puts it first). False when those
/// bytes are not an IHDR declaring sides of 1..2^31-1 pixels (libpng then says what is wrong).
bool png_header_size(const std::uint8_t (&first)[24], std::uint32_t& width, std::uint32_t& height);

/// Decodes the PNG `file` (read from its start) into `out`. libpng's own limits refuse a side
/// longer than `max_side` (read_image checks the header first, with a clearer message).
bool decode_png(std::FILE* file, int max_side, Image& out, std::string& error);

/// The width and height of the JPEG `file`'s frame (read from its start), from its markers up
/// to the first scan; nothing of the image is decoded.
bool jpeg_header_size(std::FILE* file, std::uint32_t& width, std::uint32_t& height,
                      std::string& error);

/// Decodes the JPEG `file` (read from its start) into `out`, refusing a side longer than
/// `max_side`. Greyscale, YCbCr and RGB frames are converted by libjpeg-turbo; CMYK and YCCK
/// (as Adobe's programs write them: inverted) become R = C K / 255, G = M K / 255, B = Y K / 255.
bool decode_jpeg(std::FILE* file, int max_side, Image& out, std::string& error);

}  // namespace shadelab::detail
