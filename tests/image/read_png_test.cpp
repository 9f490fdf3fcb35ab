// PNG reading (libpng) into 8-bit RGBA: every colour type at every bit depth the PNG
// specification allows (section 11.2.2), with and without tRNS, and Adam7 interlacing. The
// files are written at test time with libpng; the expected bytes are worked out by hand:
// grey g becomes (g, g, g), samples below 8 bits are scaled to 0..255 (1 bit: x 255, 2 bits:
// x 0x55, 4 bits: x 0x11), 16-bit samples keep their high byte, alpha is 255 unless the image
// has an alpha channel or a tRNS entry says otherwise.
#include <gtest/gtest.h>
#include <png.h>

#include "shadelab/image.hpp"
#include "support/image_files.hpp"

namespace shadelab {
namespace {

using test::Bytes;
using test::PngSpec;

PngSpec one_row(int width, int color_type, int bit_depth, Bytes row) {
  PngSpec s;
  s.width = width;
  s.color_type = color_type;
  s.bit_depth = bit_depth;
  s.rows = {std::move(row)};
  return s;
}

// The RGBA bytes read_image gives for `spec`, written to `name`.
Bytes read_back(const std::string& name, const PngSpec& spec) {
  const Bytes file = test::encode_png_file(spec);
  EXPECT_FALSE(file.empty()) << name << ": libpng did not write the test image";
  Image img;
  std::string error;
  EXPECT_TRUE(read_image(test::write_test_file(name, file), img, &error)) << error;
  EXPECT_EQ(img.width, spec.width) << name;
  EXPECT_EQ(img.height, spec.height) << name;
  return img.rgba;
}

TEST(ReadPng, GreyAtEveryBitDepth) {
  EXPECT_EQ(read_back("grey1.png", one_row(4, PNG_COLOR_TYPE_GRAY, 1, {0b1010'0000})),
            (Bytes{255, 255, 255, 255, 0, 0, 0, 255, 255, 255, 255, 255, 0, 0, 0, 255}));
  EXPECT_EQ(
      read_back("grey2.png", one_row(4, PNG_COLOR_TYPE_GRAY, 2, {0b00'01'10'11})),
      (Bytes{0, 0, 0, 255, 0x55, 0x55, 0x55, 255, 0xaa, 0xaa, 0xaa, 255, 0xff, 0xff, 0xff, 255}));
  EXPECT_EQ(read_back("grey4.png", one_row(2, PNG_COLOR_TYPE_GRAY, 4, {0x3c})),
            (Bytes{0x33, 0x33, 0x33, 255, 0xcc, 0xcc, 0xcc, 255}));
  EXPECT_EQ(read_back("grey8.png", one_row(2, PNG_COLOR_TYPE_GRAY, 8, {0x00, 0x80})),
            (Bytes{0, 0, 0, 255, 0x80, 0x80, 0x80, 255}));
  EXPECT_EQ(read_back("grey16.png", one_row(2, PNG_COLOR_TYPE_GRAY, 16, {0x12, 0x34, 0xfe, 0xdc})),
            (Bytes{0x12, 0x12, 0x12, 255, 0xfe, 0xfe, 0xfe, 255}));
}

// tRNS names one grey value (at the image's bit depth) that is fully transparent; a 16-bit
// value is compared whole, before the low byte is dropped.
TEST(ReadPng, GreyWithTransparentValue) {
  PngSpec s = one_row(2, PNG_COLOR_TYPE_GRAY, 4, {0x3c});
  s.transparent_grey = 0xc;
  EXPECT_EQ(read_back("grey4_trns.png", s), (Bytes{0x33, 0x33, 0x33, 255, 0xcc, 0xcc, 0xcc, 0}));
  s = one_row(2, PNG_COLOR_TYPE_GRAY, 8, {0x80, 0x81});
  s.transparent_grey = 0x80;
  EXPECT_EQ(read_back("grey8_trns.png", s), (Bytes{0x80, 0x80, 0x80, 0, 0x81, 0x81, 0x81, 255}));
  s = one_row(2, PNG_COLOR_TYPE_GRAY, 16, {0x12, 0x34, 0x12, 0x35});
  s.transparent_grey = 0x1234;
  EXPECT_EQ(read_back("grey16_trns.png", s), (Bytes{0x12, 0x12, 0x12, 0, 0x12, 0x12, 0x12, 255}));
}

TEST(ReadPng, GreyWithAlpha) {
  EXPECT_EQ(read_back("grey_alpha8.png", one_row(1, PNG_COLOR_TYPE_GRAY_ALPHA, 8, {0x40, 0x80})),
            (Bytes{0x40, 0x40, 0x40, 0x80}));
  EXPECT_EQ(read_back("grey_alpha16.png",
                      one_row(1, PNG_COLOR_TYPE_GRAY_ALPHA, 16, {0x40, 0x11, 0x80, 0xff})),
            (Bytes{0x40, 0x40, 0x40, 0x80}));
}

TEST(ReadPng, Rgb) {
  EXPECT_EQ(read_back("rgb8.png", one_row(2, PNG_COLOR_TYPE_RGB, 8, {1, 2, 3, 250, 251, 252})),
            (Bytes{1, 2, 3, 255, 250, 251, 252, 255}));
  PngSpec s = one_row(2, PNG_COLOR_TYPE_RGB, 8, {1, 2, 3, 250, 251, 252});
  s.transparent_rgb[0] = 1, s.transparent_rgb[1] = 2, s.transparent_rgb[2] = 3;
  EXPECT_EQ(read_back("rgb8_trns.png", s), (Bytes{1, 2, 3, 0, 250, 251, 252, 255}));
  // The second pixel differs from the transparent colour in a low byte only: it stays opaque.
  s = one_row(2, PNG_COLOR_TYPE_RGB, 16, {1, 2, 3, 4, 5, 6, 1, 3, 3, 4, 5, 6});
  s.transparent_rgb[0] = 0x0102, s.transparent_rgb[1] = 0x0304, s.transparent_rgb[2] = 0x0506;
  EXPECT_EQ(read_back("rgb16_trns.png", s), (Bytes{1, 3, 5, 0, 1, 3, 5, 255}));
}

TEST(ReadPng, Rgba) {
  EXPECT_EQ(read_back("rgba8.png", one_row(1, PNG_COLOR_TYPE_RGBA, 8, {1, 2, 3, 4})),
            (Bytes{1, 2, 3, 4}));
  EXPECT_EQ(read_back("rgba16.png",
                      one_row(1, PNG_COLOR_TYPE_RGBA, 16, {1, 0xff, 2, 0xff, 3, 0xff, 4, 0xff})),
            (Bytes{1, 2, 3, 4}));
}

// Palette entry i is (10 i, 200 - 10 i, i).
PngSpec palette_row(int width, int bit_depth, int entries, Bytes row) {
  PngSpec s = one_row(width, PNG_COLOR_TYPE_PALETTE, bit_depth, std::move(row));
  for (int i = 0; i < entries; ++i) {
    s.palette.insert(s.palette.end(),
                     {std::uint8_t(10 * i), std::uint8_t(200 - 10 * i), std::uint8_t(i)});
  }
  return s;
}

TEST(ReadPng, PaletteAtEveryBitDepth) {
  EXPECT_EQ(read_back("palette1.png", palette_row(3, 1, 2, {0b010'00000})),
            (Bytes{0, 200, 0, 255, 10, 190, 1, 255, 0, 200, 0, 255}));
  EXPECT_EQ(read_back("palette2.png", palette_row(4, 2, 4, {0b11'10'01'00})),
            (Bytes{30, 170, 3, 255, 20, 180, 2, 255, 10, 190, 1, 255, 0, 200, 0, 255}));
  EXPECT_EQ(read_back("palette4.png", palette_row(2, 4, 16, {0x5a})),
            (Bytes{50, 150, 5, 255, 100, 100, 10, 255}));
  EXPECT_EQ(read_back("palette8.png", palette_row(2, 8, 20, {19, 7})),
            (Bytes{190, 10, 19, 255, 70, 130, 7, 255}));
}

// tRNS gives the alpha of the first entries; the others are opaque.
TEST(ReadPng, PaletteWithAlpha) {
  PngSpec s = palette_row(3, 8, 3, {0, 1, 2});
  s.palette_alpha = {0, 128};
  EXPECT_EQ(read_back("palette8_trns.png", s),
            (Bytes{0, 200, 0, 0, 10, 190, 1, 128, 20, 180, 2, 255}));
}

// Adam7 sends the pixels in seven passes (PNG specification, section 8.2); the image read is
// the same as the one written without interlacing. 8 x 8 covers every pass; 5 x 3 leaves some
// passes empty and packs 2-bit palette indices into partial bytes.
TEST(ReadPng, InterlacedImagesComeOutWhole) {
  PngSpec rgb;
  rgb.width = rgb.height = 8;
  rgb.color_type = PNG_COLOR_TYPE_RGB;
  Bytes expected;
  for (int y = 0; y < 8; ++y) {
    Bytes row;
    for (int x = 0; x < 8; ++x) {
      const Bytes pixel = {std::uint8_t(30 * x), std::uint8_t(30 * y), std::uint8_t(8 * x + y)};
      row.insert(row.end(), pixel.begin(), pixel.end());
      expected.insert(expected.end(), pixel.begin(), pixel.end());
      expected.push_back(255);
    }
    rgb.rows.push_back(row);
  }
  rgb.interlaced = true;
  EXPECT_EQ(read_back("rgb8_adam7.png", rgb), expected);

  PngSpec small = palette_row(5, 2, 4, {});
  small.height = 3;
  // Indices (x + y) % 4, four to a byte: rows 0 1 2 3 0 | 1 2 3 0 1 | 2 3 0 1 2.
  small.rows = {
      {0b00'01'10'11, 0b00'000000}, {0b01'10'11'00, 0b01'000000}, {0b10'11'00'01, 0b10'000000}};
  const Bytes flat = read_back("palette2_flat.png", small);
  small.interlaced = true;
  const Bytes adam7 = read_back("palette2_adam7.png", small);
  EXPECT_EQ(adam7, flat);
  ASSERT_EQ(adam7.size(), 5u * 3u * 4u);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) {
      const int i = (x + y) % 4;
      const std::uint8_t* p = &adam7[std::size_t(y * 5 + x) * 4];
      EXPECT_EQ(Bytes(p, p + 4),
                (Bytes{std::uint8_t(10 * i), std::uint8_t(200 - 10 * i), std::uint8_t(i), 255}))
          << x << ", " << y;
    }
  }
}

}  // namespace
}  // namespace shadelab
