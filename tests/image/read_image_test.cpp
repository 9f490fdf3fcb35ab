// Reading images: only PNG, JPEG and binary PPM, and a size declared in the header is checked
// before anything is decoded. The inputs are the fuzzers' findings (fuzz/regressions/png/).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "shadelab/image.hpp"
#include "support/test_support.hpp"

namespace shadelab {
namespace {

// 23 bytes that stb_image takes for a TGA header declaring 8066 x 39688 pixels: decoding it
// wanted more than 2 GB (found by fuzz_png). Not a PNG, JPEG or PPM, so refused at once.
TEST(ReadImage, RefusesFormatsOtherThanPngJpegAndPpm) {
  Image img;
  std::string error;
  EXPECT_FALSE(read_image("fuzz/regressions/png/oom-huge-header.bin", img, &error));
  EXPECT_EQ(error, "cannot read image fuzz/regressions/png/oom-huge-header.bin: not a PNG, JPEG or PPM file");
  EXPECT_EQ(img.width, 0);
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

// Binary PPM, as Mesa's GLSL benchmark writes it (bench/run.sh compares it with gl_compare).
TEST(ReadImage, ReadsBinaryPpm) {
  std::string path = test::output_dir() + "/two.ppm";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_TRUE(f);
  const unsigned char pixels[6] = {255, 0, 0, 0, 0, 255};
  std::fprintf(f, "P6\n2 1\n255\n");
  std::fwrite(pixels, 1, 6, f);
  std::fclose(f);
  Image img;
  std::string error;
  ASSERT_TRUE(read_image(path, img, &error)) << error;
  EXPECT_EQ(img.width, 2);
  EXPECT_EQ(img.pixel(1, 0)[2], 255);
  EXPECT_EQ(img.pixel(1, 0)[3], 255);
}

// A PPM header with a zero size (found by fuzz_png): stb_image decodes it as an image without
// pixels; it is refused.
TEST(ReadImage, RefusesAnImageWithoutPixels) {
  Image img;
  std::string error;
  EXPECT_FALSE(read_image("fuzz/regressions/png/ppm-zero-size.bin", img, &error));
  EXPECT_EQ(error, "cannot read image fuzz/regressions/png/ppm-zero-size.bin: it has no pixels");
  EXPECT_EQ(img.width, 0);
}

TEST(ReadImage, MissingFileSaysWhy) {
  Image img;
  std::string error;
  EXPECT_FALSE(read_image("no/such/file.png", img, &error));
  EXPECT_EQ(error, "cannot read image no/such/file.png: No such file or directory");
}

}  // namespace
}  // namespace shadelab
