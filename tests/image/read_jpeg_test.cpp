// JPEG reading (libjpeg-turbo) into 8-bit RGBA: baseline and progressive, RGB (YCbCr in the
// file), greyscale and Adobe's CMYK and YCCK. The files are written at test time at quality 100
// without chroma subsampling, from 8 x 8 blocks of one colour each: a block's only coefficient
// is its mean, so the colours come back within the rounding of the YCbCr conversion.
#include <gtest/gtest.h>

#include <cstdlib>

#include "shadelab/image.hpp"
#include "support/image_files.hpp"

namespace shadelab {
namespace {

using test::Bytes;

// 16 x 16 pixels, four 8 x 8 blocks: top left, top right, bottom left, bottom right.
const std::uint8_t kBlocks[4][3] = {{200, 30, 40}, {20, 180, 60}, {10, 20, 220}, {128, 128, 128}};

Bytes four_blocks() {
  Bytes rgb;
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const std::uint8_t* c = kBlocks[(y / 8) * 2 + x / 8];
      rgb.insert(rgb.end(), c, c + 3);
    }
  }
  return rgb;
}

Image read_jpeg(const std::string& name, const Bytes& file) {
  EXPECT_FALSE(file.empty()) << name << ": libjpeg did not write the test image";
  Image img;
  std::string error;
  EXPECT_TRUE(read_image(test::write_test_file(name, file), img, &error)) << error;
  return img;
}

// Every pixel within `tolerance` of `expected(x, y)` in red, green and blue, alpha 255.
template <typename Expected>
void expect_pixels(const Image& img, int width, int height, int tolerance, Expected expected) {
  ASSERT_EQ(img.width, width);
  ASSERT_EQ(img.height, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::uint8_t* want = expected(x, y);
      const std::uint8_t* got = img.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        EXPECT_LE(std::abs(got[c] - want[c]), tolerance)
            << "pixel " << x << ", " << y << " channel " << c;
      }
      EXPECT_EQ(got[3], 255);
    }
  }
}

TEST(ReadJpeg, BaselineAndProgressiveRgb) {
  const Image baseline =
      read_jpeg("baseline.jpg", test::encode_jpeg_file(16, 16, 3, four_blocks()));
  expect_pixels(baseline, 16, 16, 2, [](int x, int y) { return kBlocks[(y / 8) * 2 + x / 8]; });
  // The same coefficients sent in libjpeg's ten progressive scans decode to the same bytes.
  const Image progressive =
      read_jpeg("progressive.jpg", test::encode_jpeg_file(16, 16, 3, four_blocks(), true));
  EXPECT_EQ(progressive.width, 16);
  EXPECT_EQ(progressive.rgba, baseline.rgba);
}

TEST(ReadJpeg, GreyBecomesRgb) {
  Bytes grey(16 * 8);
  for (int i = 0; i < 16 * 8; ++i) grey[std::size_t(i)] = i % 16 < 8 ? 50 : 200;
  static const std::uint8_t kGrey[2][3] = {{50, 50, 50}, {200, 200, 200}};
  // No colour conversion at all: exact.
  expect_pixels(read_jpeg("grey.jpg", test::encode_jpeg_file(16, 8, 1, grey)), 16, 8, 0,
                [](int x, int) { return kGrey[x / 8]; });
  expect_pixels(read_jpeg("grey_progressive.jpg", test::encode_jpeg_file(16, 8, 1, grey, true)), 16,
                8, 0, [](int x, int) { return kGrey[x / 8]; });
}

// libjpeg writes CMYK as given, with Adobe's marker; Adobe's programs store the inks inverted
// (255: none), which is how this reader (as stb_image before it) takes them: R = C K / 255.
// C, M, Y, K = 200, 100, 50, 150: R = 117.6, G = 58.8, B = 29.4.
TEST(ReadJpeg, AdobeCmykAndYcck) {
  const Bytes cmyk = [] {
    Bytes b;
    for (int i = 0; i < 64; ++i) b.insert(b.end(), {200, 100, 50, 150});
    return b;
  }();
  static const std::uint8_t kRgb[3] = {118, 59, 29};
  expect_pixels(read_jpeg("cmyk.jpg", test::encode_jpeg_file(8, 8, 4, cmyk)), 8, 8, 1,
                [](int, int) { return kRgb; });
  expect_pixels(read_jpeg("ycck.jpg", test::encode_jpeg_file(8, 8, 4, cmyk, false, true)), 8, 8, 2,
                [](int, int) { return kRgb; });
}

// A progressive JPEG may refine its coefficients in any number of scans, each a pass over the
// whole image: a small file of many scans can keep a decoder busy for a long time. Past 500
// (libjpeg-turbo's own limit in its TurboJPEG API) decoding stops.
TEST(ReadJpeg, AtMost500Scans) {
  const std::string path =
      test::write_test_file("631_scans.jpg", test::encode_many_scans_jpeg_file());
  Image img;
  std::string error;
  EXPECT_FALSE(read_image(path, img, &error));
  EXPECT_EQ(error,
            "cannot read image " + path + ": the JPEG file has more than 500 scans, the most read");
}

}  // namespace
}  // namespace shadelab
