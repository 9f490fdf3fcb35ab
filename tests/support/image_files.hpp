// Image files for the readers' tests, made at test time: PNGs of every colour type, bit depth
// and interlace method (libpng's writer) and JPEGs (libjpeg-turbo's compressor), as bytes to
// be cut, patched and written where a test wants them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadelab::test {

using Bytes = std::vector<std::uint8_t>;

/// A PNG to encode: `rows` holds each row's samples as the PNG stores them (packed below 8
/// bits, most significant bits first; 16-bit samples big-endian), top row first.
struct PngSpec {
  int width = 1, height = 1;
  int color_type = 0;  ///< PNG_COLOR_TYPE_*
  int bit_depth = 8;
  bool interlaced = false;  ///< Adam7
  std::vector<Bytes> rows;
  std::vector<std::uint8_t> palette;                ///< r, g, b per entry (PLTE)
  std::vector<std::uint8_t> palette_alpha;          ///< tRNS of a palette image
  std::optional<std::uint16_t> transparent_grey;    ///< tRNS of a grey image
  std::optional<std::uint16_t> transparent_rgb[3];  ///< tRNS of an RGB image
};

/// The PNG file of `spec` (libpng, default compression); empty if libpng refuses it.
Bytes encode_png_file(const PngSpec& spec);

/// A JPEG of `width` x `height` pixels from `samples` (`components` bytes a pixel: 1 grey,
/// 3 RGB, 4 CMYK), at quality 100 and without chroma subsampling. `ycck` stores CMYK as YCCK;
/// `progressive` writes libjpeg's simple progression of scans instead of one baseline scan.
Bytes encode_jpeg_file(int width, int height, int components, const Bytes& samples,
                       bool progressive = false, bool ycck = false);

/// An 8 x 8 grey progressive JPEG of 631 scans, all valid: the DC coefficient, then each of
/// the 63 AC coefficients in a band of its own, sent from bit 9 down to bit 0 (ten scans).
Bytes encode_many_scans_jpeg_file();

/// Writes `bytes` to `name` in the tests' output folder and returns its path.
std::string write_test_file(const std::string& name, const Bytes& bytes);

}  // namespace shadelab::test
