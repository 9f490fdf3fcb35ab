// Reading images: only PNG and JPEG, and a size declared in the header is checked
// before anything is decoded. The inputs are the fuzzers' findings (fuzz/regressions/png/).
#include <gtest/gtest.h>

#include <string>

#include "shadelab/image.hpp"

namespace shadelab {
namespace {

// 23 bytes that stb_image takes for a TGA header declaring 8066 x 39688 pixels: decoding it
// wanted more than 2 GB (found by fuzz_png). Not a PNG or JPEG, so refused at once. So are
// PNM files (fuzz_png found stb_image's PNM reader reading past the end of a short 16-bit
// PGM, and taking a zero-size PPM as an image).
TEST(ReadImage, RefusesFormatsOtherThanPngAndJpeg) {
  Image img;
  std::string error;
  EXPECT_FALSE(read_image("fuzz/regressions/png/oom-huge-header.bin", img, &error));
  EXPECT_EQ(error, "cannot read image fuzz/regressions/png/oom-huge-header.bin: not a PNG or JPEG file");
  EXPECT_EQ(img.width, 0);
  for (const char* path : {"fuzz/regressions/png/pgm-short-16bit.bin", "fuzz/regressions/png/ppm-zero-size.bin"}) {
    EXPECT_FALSE(read_image(path, img, &error));
    EXPECT_EQ(error, "cannot read image " + std::string(path) + ": not a PNG or JPEG file");
  }
}

// A 69-byte PNG whose header says 17000 x 10000 (680 MB of pixels): refused from the header.
TEST(ReadImage, ChecksTheDeclaredSizeBeforeDecoding) {
  Image img;
  std::string error;
  EXPECT_FALSE(read_image("fuzz/regressions/png/huge-ihdr.png", img, &error));
  EXPECT_EQ(error, "the image fuzz/regressions/png/huge-ihdr.png is 17000 x 10000, more than the limit "
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
}

}  // namespace
}  // namespace shadelab
