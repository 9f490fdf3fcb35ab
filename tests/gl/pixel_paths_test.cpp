// glReadPixels and glDrawPixels of unsigned-byte RGB(A) and BGR(A) images take a copying path
// (gl/src/readpix.cpp's read_bytes, drawpix.cpp's draw_bytes) when nothing transforms the
// pixels; otherwise the general one, through floats and the per-fragment operations. Both must
// give the same bytes: each case here runs once on each path (the general one forced by state
// that changes nothing: identity colour maps for reads, an alpha test that always passes for
// draws), under pack and unpack alignments, row lengths and skips, rectangles partly outside
// the window and a scissor box. Through the GL API on an OSMesa context.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace {

constexpr int kWidth = 37, kHeight = 29;

class PixelPathsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    ASSERT_NE(ctx_, nullptr);
    ASSERT_TRUE(OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, kWidth, kHeight));
    std::vector<GLfloat> identity(256);
    for (int i = 0; i < 256; ++i) identity[std::size_t(i)] = float(i) / 255.0f;
    for (GLenum map : {GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_G_TO_G, GL_PIXEL_MAP_B_TO_B, GL_PIXEL_MAP_A_TO_A})
      glPixelMapfv(map, 256, identity.data());
    std::mt19937 rng(11);
    image_.resize(64 * 64 * 4);
    for (std::uint8_t& b : image_) b = std::uint8_t(rng());
  }
  void TearDown() override {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
  }

  // The whole window as RGBA bytes, read on the general path.
  std::vector<std::uint8_t> window() {
    std::vector<std::uint8_t> out(kWidth * kHeight * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
    return out;
  }

  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> buffer_ = std::vector<unsigned char>(kWidth * kHeight * 4);
  std::vector<std::uint8_t> image_;
};

TEST_F(PixelPathsTest, DrawnBytesAreTheFragmentsOfTheGeneralPath) {
  struct Case {
    int alignment, row_length, skip_pixels, skip_rows, x, y, w, h;
    bool scissor;
  };
  const Case cases[] = {{4, 0, 0, 0, 0, 0, 37, 29, false}, {1, 0, 0, 0, 5, 3, 13, 9, false},
                        {8, 23, 3, 2, -4, -3, 19, 11, false}, {2, 40, 5, 7, 30, 20, 17, 15, true}};
  for (const Case& k : cases) {
    for (GLenum format : {GL_RGBA, GL_RGB, GL_BGRA, GL_BGR}) {
      const std::string what = "format " + std::to_string(format) + " at " + std::to_string(k.x) + "," + std::to_string(k.y);
      glPixelStorei(GL_UNPACK_ALIGNMENT, k.alignment);
      glPixelStorei(GL_UNPACK_ROW_LENGTH, k.row_length);
      glPixelStorei(GL_UNPACK_SKIP_PIXELS, k.skip_pixels);
      glPixelStorei(GL_UNPACK_SKIP_ROWS, k.skip_rows);
      if (k.scissor) glEnable(GL_SCISSOR_TEST), glScissor(8, 6, 25, 20);
      std::vector<std::uint8_t> got[2];
      for (int general = 0; general < 2; ++general) {
        glDisable(GL_SCISSOR_TEST);
        glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
        glClear(GL_COLOR_BUFFER_BIT);
        if (k.scissor) glEnable(GL_SCISSOR_TEST);
        if (general) glEnable(GL_ALPHA_TEST), glAlphaFunc(GL_ALWAYS, 0.0f);
        glWindowPos2i(k.x, k.y);
        glDrawPixels(k.w, k.h, format, GL_UNSIGNED_BYTE, image_.data());
        glDisable(GL_ALPHA_TEST);
        glDisable(GL_SCISSOR_TEST);
        got[general] = window();
      }
      EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << what;
      EXPECT_EQ(got[0], got[1]) << what;
    }
  }
}

TEST_F(PixelPathsTest, ReadBytesAreThoseOfTheGeneralPath) {
  glWindowPos2i(0, 0);
  glDrawPixels(kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, image_.data());
  struct Case {
    int alignment, row_length, skip_pixels, skip_rows, x, y, w, h;
  };
  const Case cases[] = {{4, 0, 0, 0, 0, 0, 37, 29}, {1, 0, 0, 0, 5, 3, 13, 9}, {8, 23, 3, 2, -4, -3, 19, 11},
                        {2, 40, 5, 7, 30, 20, 17, 15}, {4, 0, 0, 0, 40, 2, 5, 5}};
  for (const Case& k : cases) {
    for (GLenum format : {GL_RGBA, GL_RGB, GL_BGRA, GL_BGR}) {
      const std::string what = "format " + std::to_string(format) + " at " + std::to_string(k.x) + "," + std::to_string(k.y);
      glPixelStorei(GL_PACK_ALIGNMENT, k.alignment);
      glPixelStorei(GL_PACK_ROW_LENGTH, k.row_length);
      glPixelStorei(GL_PACK_SKIP_PIXELS, k.skip_pixels);
      glPixelStorei(GL_PACK_SKIP_ROWS, k.skip_rows);
      std::vector<std::uint8_t> got[2];
      for (int general = 0; general < 2; ++general) {
        got[general].assign(64 * 64 * 4, 0xa5);  // what the read does not reach stays
        glPixelTransferi(GL_MAP_COLOR, general ? GL_TRUE : GL_FALSE);
        glReadPixels(k.x, k.y, k.w, k.h, format, GL_UNSIGNED_BYTE, got[general].data());
        glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
      }
      EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << what;
      EXPECT_EQ(got[0], got[1]) << what;
    }
  }
}

}  // namespace
