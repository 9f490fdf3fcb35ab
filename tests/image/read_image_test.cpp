// Reading images: only PNG and JPEG, a size declared in the header is checked before anything
// is decoded, and every error names the file and says what is wrong. The inputs are the
// fuzzers' findings (fuzz/regressions/png/) and files made here, broken on purpose.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "shadelab/image.hpp"
#include "support/image_files.hpp"
#include "support/sanitizers.hpp"

namespace shadelab {
namespace {

using test::Bytes;

Bytes big_endian(std::uint32_t v) {
  return {std::uint8_t(v >> 24), std::uint8_t(v >> 16), std::uint8_t(v >> 8), std::uint8_t(v)};
}

// A PNG chunk: length, type, data, CRC of type and data (PNG specification, section 5.3).
Bytes chunk(const char (&type)[5], const Bytes& data, std::uint32_t declared_length) {
  Bytes c = big_endian(declared_length);
  for (int i = 0; i < 4; ++i) c.push_back(std::uint8_t(type[i]));
  c.insert(c.end(), data.begin(), data.end());
  uLong crc = crc32(0, c.data() + 4, uInt(c.size() - 4));
  for (int shift = 24; shift >= 0; shift -= 8) c.push_back(std::uint8_t(crc >> shift));
  return c;
}
Bytes chunk(const char (&type)[5], const Bytes& data) {
  return chunk(type, data, std::uint32_t(data.size()));
}

// The signature and IHDR of an 8-bit RGBA image of `width` x `height`.
Bytes rgba_png_header(std::uint32_t width, std::uint32_t height) {
  Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  Bytes ihdr = big_endian(width);
  const Bytes h = big_endian(height);
  ihdr.insert(ihdr.end(), h.begin(), h.end());
  ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});
  const Bytes c = chunk("IHDR", ihdr);
  png.insert(png.end(), c.begin(), c.end());
  return png;
}

// An 8 x 8 RGB PNG written by libpng.
Bytes small_png() {
  test::PngSpec s;
  s.width = s.height = 8;
  s.color_type = 2;  // RGB
  for (int y = 0; y < 8; ++y) {
    test::Bytes row;
    for (int x = 0; x < 8; ++x)
      row.insert(row.end(), {std::uint8_t(x * 30), std::uint8_t(y * 30), 7});
    s.rows.push_back(row);
  }
  return test::encode_png_file(s);
}

// Where a baseline JPEG's frame header starts (SOF0: FF C0, length, precision, height, width).
std::size_t sof0(const Bytes& jpeg) {
  static const std::uint8_t kSof0[2] = {0xff, 0xc0};
  auto at = std::search(jpeg.begin(), jpeg.end(), kSof0, kSof0 + 2);
  EXPECT_NE(at, jpeg.end());
  return std::size_t(at - jpeg.begin());
}

// The most memory the process has held so far, in bytes.
long peak_memory() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss * 1024L;
}

std::string read_error(const std::string& path, int max_side = 16384) {
  Image img;
  std::string error;
  EXPECT_FALSE(read_image(path, img, &error, max_side)) << path;
  EXPECT_TRUE(img.rgba.empty()) << path;
  return error;
}

// 23 bytes that stb_image takes for a TGA header declaring 8066 x 39688 pixels: decoding it
// wanted more than 2 GB (found by fuzz_png). Not a PNG or JPEG, so refused at once. So are
// PNM files (fuzz_png found stb_image's PNM reader reading past the end of a short 16-bit
// PGM, and taking a zero-size PPM as an image).
TEST(ReadImage, RefusesFormatsOtherThanPngAndJpeg) {
  Image img;
  std::string error;
  EXPECT_FALSE(read_image("fuzz/regressions/png/oom-huge-header.bin", img, &error));
  EXPECT_EQ(error,
            "cannot read image fuzz/regressions/png/oom-huge-header.bin: not a PNG or JPEG file");
  EXPECT_EQ(img.width, 0);
  for (const char* path :
       {"fuzz/regressions/png/pgm-short-16bit.bin", "fuzz/regressions/png/ppm-zero-size.bin"}) {
    EXPECT_FALSE(read_image(path, img, &error));
    EXPECT_EQ(error, "cannot read image " + std::string(path) + ": not a PNG or JPEG file");
  }
}

// A 69-byte PNG whose header says 17000 x 10000 (680 MB of pixels): refused from the header.
TEST(ReadImage, ChecksTheDeclaredSizeBeforeDecoding) {
  Image img;
  std::string error;
  EXPECT_FALSE(read_image("fuzz/regressions/png/huge-ihdr.png", img, &error));
  EXPECT_EQ(error,
            "the image fuzz/regressions/png/huge-ihdr.png is 17000 x 10000, more than the limit "
            "of 16384 x 16384");
  EXPECT_FALSE(read_image("scenes/textures/bricks.png", img, &error, 63));
  EXPECT_NE(error.find("is 64 x 64, more than the limit of 63 x 63"), std::string::npos) << error;
  EXPECT_TRUE(read_image("scenes/textures/bricks.png", img, &error, 64)) << error;
  EXPECT_EQ(img.width, 64);
  EXPECT_EQ(img.rgba.size(), 64u * 64u * 4u);
}

TEST(ReadImage, MissingFileSaysWhy) {
  Image img;
  std::string error;
  EXPECT_FALSE(read_image("no/such/file.png", img, &error));
  EXPECT_EQ(error, "cannot read image no/such/file.png: No such file or directory");
  EXPECT_EQ(read_error("scenes"), "cannot read image scenes: Is a directory");
}

TEST(ReadImage, NonImageFilesAreRefused) {
  EXPECT_EQ(read_error("scenes/teapot.json"),
            "cannot read image scenes/teapot.json: not a PNG or JPEG file");
  const std::string empty = test::write_test_file("empty.png", {});
  EXPECT_EQ(read_error(empty), "cannot read image " + empty + ": not a PNG or JPEG file");
  // The PNG signature alone is not enough: what follows is read as chunks and found wanting
  // (libpng names the chunk, its type's bytes as it read them: "o wo").
  const std::string text = test::write_test_file(
      "signature_then_text.png",
      {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 'h', 'e', 'l', 'l', 'o', ' ', 'w', 'o',
       'r',  'l', 'd', ' ', 'h',  'e',  'l',  'l',  'o', ' ', 'w', 'o', 'r', 'l', 'd'});
  EXPECT_EQ(read_error(text),
            "cannot read image " + text + ": invalid PNG: o[20]wo: invalid chunk type");
}

// fuzz_png's finding: a 2 x 2 PNG whose second IDAT chunk declares 0x7fffff00 bytes and holds
// a few. stb_image grew its buffer of IDAT data to 2 GiB to hold it before reading it; libpng
// reads IDAT data a few kilobytes at a time as it inflates it, and finds the file's end.
TEST(ReadImage, IdatDeclaringGigabytesCostsNoMemory) {
  const long before = peak_memory();
  EXPECT_EQ(
      read_error("fuzz/regressions/png/idat-declares-2gib.png"),
      "cannot read image fuzz/regressions/png/idat-declares-2gib.png: the PNG file is truncated");
  EXPECT_LT(peak_memory() - before, 64L << 20);
}

// A 100000 x 100000 image (40 GB of pixels) declared in 45 bytes is refused from its header:
// nothing is decoded or allocated. read_image_size reports what the header says.
TEST(ReadImage, HugeDeclaredSizeFailsFast) {
  Bytes png = rgba_png_header(100000, 100000);
  const Bytes idat = chunk("IDAT", {0x78, 0x9c, 0x63, 0x00, 0x00});
  png.insert(png.end(), idat.begin(), idat.end());
  const std::string path = test::write_test_file("100000x100000.png", png);
  const long before = peak_memory();
  EXPECT_EQ(read_error(path),
            "the image " + path + " is 100000 x 100000, more than the limit of 16384 x 16384");
  EXPECT_LT(peak_memory() - before, 16L << 20);
  int w = 0, h = 0;
  std::string error;
  EXPECT_TRUE(read_image_size(path, w, h, &error)) << error;
  EXPECT_EQ(w, 100000);
  EXPECT_EQ(h, 100000);

  // A JPEG's frame header patched to 60000 x 50000.
  Bytes jpeg = test::encode_jpeg_file(8, 8, 1, Bytes(64, 100));
  const std::size_t at = sof0(jpeg);
  jpeg[at + 5] = 50000 >> 8, jpeg[at + 6] = 50000 & 0xff, jpeg[at + 7] = 60000 >> 8,
            jpeg[at + 8] = 60000 & 0xff;
  const std::string jpeg_path = test::write_test_file("60000x50000.jpg", jpeg);
  EXPECT_EQ(read_error(jpeg_path),
            "the image " + jpeg_path + " is 60000 x 50000, more than the limit of 16384 x 16384");
  EXPECT_LT(peak_memory() - before, 16L << 20);
}

// What a sanitizer's shadow of a reserved but untouched allocation of `bytes` costs:
// AddressSanitizer's is an eighth of it; ThreadSanitizer writes the shadow of a new allocation
// as if the program had written it, half its size (537 MB for the gigabyte below, measured in
// the ThreadSanitizer build scripts/test.sh makes).
long reserved_shadow(long bytes) {
  return test::kThreadSanitizer ? bytes / 2 : test::kAddressSanitizer ? bytes / 8 : 0;
}

// Within the limit, a file declaring 16384 x 16384 (1 GiB of RGBA) with only a few bytes of
// data fails when its data ends; the pixels' memory is filled as rows arrive, not before.
// Filling the pixels would cost the whole gigabyte (and its shadow) in every build.
TEST(ReadImage, DeclaredSizeCostsMemoryOnlyAsDataArrives) {
  Bytes png = rgba_png_header(16384, 16384);
  const Bytes idat = chunk("IDAT", {0x78, 0x9c, 0x63, 0x60, 0x60});  // the zlib stream goes on
  png.insert(png.end(), idat.begin(), idat.end());
  const std::string path = test::write_test_file("16384x16384_no_data.png", png);
  const long before = peak_memory();
  EXPECT_EQ(read_error(path), "cannot read image " + path + ": the PNG file is truncated");
  EXPECT_LT(peak_memory() - before, reserved_shadow(1L << 30) + (128L << 20));
}

TEST(ReadImage, TruncatedFilesAreErrors) {
  const Bytes png = small_png();
  for (std::size_t keep :
       {std::size_t(30), png.size() / 2, png.size() - 12}) {  // the last: no IEND
    const std::string path = test::write_test_file("truncated_" + std::to_string(keep) + ".png",
                                                   Bytes(png.begin(), png.begin() + long(keep)));
    EXPECT_EQ(read_error(path), "cannot read image " + path + ": the PNG file is truncated");
  }
  Bytes rgb(16 * 16 * 3, 90);
  for (bool progressive : {false, true}) {
    const Bytes jpeg = test::encode_jpeg_file(16, 16, 3, rgb, progressive);
    for (std::size_t keep :
         {std::size_t(10), jpeg.size() / 2, jpeg.size() - 2}) {  // the last: no EOI
      const std::string path = test::write_test_file(
          "truncated_" + std::to_string(keep) + (progressive ? "_progressive" : "") + ".jpg",
          Bytes(jpeg.begin(), jpeg.begin() + long(keep)));
      EXPECT_EQ(read_error(path), "cannot read image " + path + ": the JPEG file is truncated");
    }
  }
}

// libpng's and libjpeg's own words after the file's name.
TEST(ReadImage, CorruptFilesSayWhatIsWrong) {
  Bytes png = small_png();
  png[29] ^= 1;  // a bit of IHDR's CRC
  std::string path = test::write_test_file("bad_crc.png", png);
  EXPECT_EQ(read_error(path), "cannot read image " + path + ": invalid PNG: IHDR: CRC error");

  Bytes jpeg = test::encode_jpeg_file(8, 8, 1, Bytes(64, 100));
  jpeg[sof0(jpeg) + 4] =
      12;  // 12-bit samples, which neither libjpeg's 8-bit API nor stb_image reads
  path = test::write_test_file("12bit.jpg", jpeg);
  EXPECT_EQ(read_error(path),
            "cannot read image " + path + ": invalid JPEG: Unsupported JPEG data precision 12");
}

}  // namespace
}  // namespace shadelab
