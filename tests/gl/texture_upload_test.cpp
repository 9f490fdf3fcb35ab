// Texture uploads of 8-bit RGB(A) and BGR(A) images into levels of 8-bit components are copied byte
// for byte (gl/src/teximage.cpp's store_bytes); every other upload goes through floats and the
// pixel transfer. Both must store the same texels: each image here is uploaded once on the
// copying path and once with identity colour maps on (GL_MAP_COLOR), which forces the general
// path, under unpack alignments, row lengths and skips, with borders, sub-images and 3D images, and the
// two textures are read back and compared. Through the GL API on an OSMesa context.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace {

class TextureUploadTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    ASSERT_NE(ctx_, nullptr);
    ASSERT_TRUE(OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, 4, 4));
    std::vector<GLfloat> identity(256);
    for (int i = 0; i < 256; ++i) identity[std::size_t(i)] = float(i) / 255.0f;
    for (GLenum map : {GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_G_TO_G, GL_PIXEL_MAP_B_TO_B, GL_PIXEL_MAP_A_TO_A})
      glPixelMapfv(map, 256, identity.data());
  }
  void TearDown() override {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
  }

  // Level 0 of the bound texture of `target` as RGBA bytes.
  static std::vector<std::uint8_t> read_back(GLenum target, int w, int h, int d) {
    std::vector<std::uint8_t> out(std::size_t(w) * std::size_t(h) * std::size_t(d) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    return out;
  }

  // `upload` run twice, on the copying path and on the general one; the texels must agree.
  template <class Upload>
  void expect_same(const Upload& upload, int w, int h, const char* what, GLenum target = GL_TEXTURE_2D, int d = 1) {
    GLuint tex[2];
    glGenTextures(2, tex);
    std::vector<std::uint8_t> got[2];
    for (int k = 0; k < 2; ++k) {
      glPixelTransferi(GL_MAP_COLOR, k == 1 ? GL_TRUE : GL_FALSE);
      glBindTexture(target, tex[k]);
      upload();
      glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
      got[k] = read_back(target, w, h, d);
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << what;
    EXPECT_EQ(got[0], got[1]) << what;
    glDeleteTextures(2, tex);
  }

  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> pixels_ = std::vector<unsigned char>(4 * 4 * 4);
};

TEST_F(TextureUploadTest, CopiedBytesAreTheTexelsOfTheGeneralPath) {
  std::mt19937 rng(7);
  std::vector<std::uint8_t> image(64 * 64 * 4 + 4096);
  for (std::uint8_t& b : image) b = std::uint8_t(rng());
  struct Unpack {
    int alignment, row_length, skip_pixels, skip_rows;
  };
  for (const Unpack& u : {Unpack{4, 0, 0, 0}, Unpack{1, 0, 0, 0}, Unpack{8, 23, 3, 2}, Unpack{2, 40, 5, 7}}) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, u.alignment);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, u.row_length);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, u.skip_pixels);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, u.skip_rows);
    for (GLenum format : {GL_RGBA, GL_RGB, GL_BGRA, GL_BGR}) {
      for (GLint internal : {GL_RGBA, GL_RGBA8, GL_RGB, GL_RGB8, 4, 3, GL_LUMINANCE8, GL_INTENSITY8, GL_ALPHA8,
                             GL_LUMINANCE8_ALPHA8, 1, 2}) {
        const std::string what = "format " + std::to_string(format) + " internal " + std::to_string(internal) +
                                 " alignment " + std::to_string(u.alignment) + " row length " +
                                 std::to_string(u.row_length);
        // A 13 x 9 image, odd sizes so that rows are padded.
        expect_same([&] { glTexImage2D(GL_TEXTURE_2D, 0, internal, 13, 9, 0, format, GL_UNSIGNED_BYTE, image.data()); },
                    13, 9, what.c_str());
        // A sub-image into a level defined first.
        expect_same(
            [&] {
              glTexImage2D(GL_TEXTURE_2D, 0, internal, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.data() + 100);
              glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 5, 11, 7, format, GL_UNSIGNED_BYTE, image.data());
            },
            16, 16, (what + " (sub-image)").c_str());
        // A border, stripped when stored (14 x 10 with the border: 12 x 8 texels).
        expect_same([&] { glTexImage2D(GL_TEXTURE_2D, 0, internal, 14, 10, 1, format, GL_UNSIGNED_BYTE, image.data()); },
                    12, 8, (what + " (border)").c_str());
        // A 3D image (images of 6 rows, two skipped), and a sub-image of it.
        glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 6);
        glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
        expect_same(
            [&] {
              glTexImage3D(GL_TEXTURE_3D, 0, internal, 5, 4, 3, 0, format, GL_UNSIGNED_BYTE, image.data());
              glTexSubImage3D(GL_TEXTURE_3D, 0, 1, 1, 1, 3, 2, 2, format, GL_UNSIGNED_BYTE, image.data() + 7);
            },
            5, 4, (what + " (3D)").c_str(), GL_TEXTURE_3D, 3);
        glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
        glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
      }
    }
  }
}

// Images of many rows go through floats band by band, the bands on the pipeline's threads
// (teximage.cpp's store_client_image): a 300-row float image, with a border and under unpack
// skips, into 16-bit and 8-bit levels, must store what the same rows store uploaded one at a
// time (one band each, on the calling thread).
TEST_F(TextureUploadTest, ManyRowsInBandsStoreWhatSingleRowsStore) {
  constexpr int kW = 37, kH = 300;
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(-0.1f, 1.1f);
  std::vector<float> image(std::size_t(kW + 3) * std::size_t(kH + 4) * 4);
  for (float& v : image) v = unit(random);
  for (GLint internal : {GL_RGBA16, GL_RGBA8, GL_LUMINANCE12_ALPHA4}) {
    GLuint tex[2];
    glGenTextures(2, tex);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, kW + 3);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, internal, kW, kH, 1, GL_RGBA, GL_FLOAT, image.data());
    const std::vector<std::uint8_t> banded = read_back(GL_TEXTURE_2D, kW - 2, kH - 2, 1);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, internal, kW - 2, kH - 2, 0, GL_RGBA, GL_FLOAT, nullptr);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);  // the border's column skipped by hand
    for (int y = 0; y < kH - 2; ++y) {
      glPixelStorei(GL_UNPACK_SKIP_ROWS, 3 + y);  // and its row
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, y, kW - 2, 1, GL_RGBA, GL_FLOAT, image.data());
    }
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    const std::vector<std::uint8_t> rows = read_back(GL_TEXTURE_2D, kW - 2, kH - 2, 1);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << internal;
    EXPECT_EQ(banded, rows) << internal;
    std::vector<std::uint16_t> wide[2];
    for (int k = 0; k < 2; ++k) {  // the 16-bit values too
      glBindTexture(GL_TEXTURE_2D, tex[k]);
      wide[k].resize(std::size_t(kW - 2) * std::size_t(kH - 2) * 4);
      glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT, wide[k].data());
    }
    EXPECT_EQ(wide[0], wide[1]) << internal;
    glDeleteTextures(2, tex);
  }
}

}  // namespace
