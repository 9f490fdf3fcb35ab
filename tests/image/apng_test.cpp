// Animated PNG (encode_apng): the chunks the APNG specification asks for, in order, with
// consecutive sequence numbers and valid CRCs; the first frame is the still image that PNG
// readers see; bad input gives nothing. (ffprobe decodes every frame in tests/scaleout.)
#include <zlib.h>

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "shadelab/image.hpp"
#include "support/image_files.hpp"

namespace shadelab {
namespace {

Image solid(int w, int h, std::uint8_t r) {
  Image img{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4, 255)};
  for (std::size_t i = 0; i < img.rgba.size(); i += 4) img.rgba[i] = r, img.rgba[i + 1] = std::uint8_t(i % 251);
  return img;
}

std::uint32_t be32(const std::uint8_t* p) { return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3]; }

struct Chunk {
  std::string type;
  std::vector<std::uint8_t> body;
};

std::vector<Chunk> chunks(const std::vector<std::uint8_t>& png) {
  std::vector<Chunk> out;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t n = be32(&png[at]);
    EXPECT_LE(at + 12 + n, png.size());
    if (at + 12 + n > png.size()) break;
    const std::uint32_t crc = std::uint32_t(crc32(0, &png[at + 4], uInt(n + 4)));
    EXPECT_EQ(crc, be32(&png[at + 8 + n])) << "chunk at " << at;
    out.push_back({std::string(reinterpret_cast<const char*>(&png[at + 4]), 4),
                   std::vector<std::uint8_t>(&png[at + 8], &png[at + 8 + n])});
    at += 12 + n;
  }
  return out;
}

TEST(Apng, ChunksFollowTheSpecification) {
  const std::vector<Image> frames = {solid(9, 7, 10), solid(9, 7, 120), solid(9, 7, 250)};
  const std::vector<std::uint8_t> apng = encode_apng(frames, 1, 24);
  ASSERT_GT(apng.size(), 8u);
  const std::vector<Chunk> c = chunks(apng);
  ASSERT_GE(c.size(), 8u);
  EXPECT_EQ(c[0].type, "IHDR");
  ASSERT_EQ(c[1].type, "acTL");
  EXPECT_EQ(be32(&c[1].body[0]), 3u);  // frames
  EXPECT_EQ(be32(&c[1].body[4]), 0u);  // plays for ever
  EXPECT_EQ(c.back().type, "IEND");
  std::uint32_t sequence = 0;
  int controls = 0, idat = 0, fdat = 0;
  for (const Chunk& k : c) {
    if (k.type == "fcTL") {
      ASSERT_EQ(k.body.size(), 26u);
      EXPECT_EQ(be32(&k.body[0]), sequence++);
      EXPECT_EQ(be32(&k.body[4]), 9u);
      EXPECT_EQ(be32(&k.body[8]), 7u);
      EXPECT_EQ(k.body[20] << 8 | k.body[21], 1);   // delay 1/24 s
      EXPECT_EQ(k.body[22] << 8 | k.body[23], 24);
      ++controls;
    } else if (k.type == "fdAT") {
      EXPECT_EQ(be32(&k.body[0]), sequence++);
      EXPECT_GT(idat, 0);  // the default image comes first
      ++fdat;
    } else if (k.type == "IDAT") {
      EXPECT_EQ(controls, 1);  // the first frame's control precedes it: the still is frame 0
      ++idat;
    }
  }
  EXPECT_EQ(controls, 3);
  EXPECT_GE(fdat, 2);
  // Deterministic: the same frames, the same bytes.
  EXPECT_EQ(encode_apng(frames, 1, 24), apng);
}

TEST(Apng, PngReadersSeeTheFirstFrame) {
  const std::vector<Image> frames = {solid(5, 4, 200), solid(5, 4, 3)};
  const std::string path = test::write_test_file("apng_first.png", {});
  std::string error;
  ASSERT_TRUE(write_apng(frames, path, 1, 2, &error)) << error;
  Image back;
  ASSERT_TRUE(read_image(path, back, &error)) << error;
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.rgba, frames[0].rgba);
}

TEST(Apng, BadInputGivesNothing) {
  EXPECT_TRUE(encode_apng({}, 1, 24).empty());
  EXPECT_TRUE(encode_apng({solid(4, 4, 1), solid(5, 4, 1)}, 1, 24).empty());  // sizes differ
  EXPECT_TRUE(encode_apng({solid(4, 4, 1)}, 70000, 24).empty());              // delay past 16 bits
  EXPECT_TRUE(encode_apng({Image{}}, 1, 24).empty());
  std::string error;
  EXPECT_FALSE(write_apng({}, test::write_test_file("apng_none.png", {}), 1, 24, &error));
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace shadelab
