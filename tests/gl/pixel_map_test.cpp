// Pixel maps (GL 1.1 section 3.6.3, gl/src/pixel_transfer.cpp) given values no conversion can
// hold: NaN, infinities and values past every integer type, then read back as floats, unsigned
// ints and unsigned shorts, and used by glDrawPixels of stencil indices. The answers are
// defined (NaN reads 0, the rest clamp), never an undefined float-to-integer conversion (the
// sanitized build checks every conversion). Through the GL API on an OSMesa context.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace {

constexpr int kSize = 8;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

class PixelMapTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    ASSERT_NE(ctx_, nullptr);
    ASSERT_TRUE(OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  }
  void TearDown() override {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
  }

  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> pixels_ = std::vector<unsigned char>(kSize * kSize * 4);
};

constexpr std::array<float, 8> kExtremes = {kNaN, kInf, -kInf, 1e30f, -1e30f, 3e9f, -3e9f, 2.5f};

TEST_F(PixelMapTest, IndexMapsOfExtremeValuesReadBackClamped) {
  glPixelMapfv(GL_PIXEL_MAP_I_TO_I, GLsizei(kExtremes.size()), kExtremes.data());
  std::array<GLfloat, 8> f{};
  std::array<GLuint, 8> ui{};
  std::array<GLushort, 8> us{};
  glGetPixelMapfv(GL_PIXEL_MAP_I_TO_I, f.data());
  glGetPixelMapuiv(GL_PIXEL_MAP_I_TO_I, ui.data());
  glGetPixelMapusv(GL_PIXEL_MAP_I_TO_I, us.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_TRUE(std::isnan(f[0]));  // I_TO_I keeps what it was given
  EXPECT_EQ(f[1], kInf);
  // As unsigned ints: NaN 0, the rest clamped to [INT_MIN, UINT_MAX] and truncated.
  EXPECT_EQ(ui[0], 0u);
  EXPECT_EQ(ui[1], 4294967295u);
  EXPECT_EQ(ui[2], GLuint(0x80000000u));
  EXPECT_EQ(ui[3], 4294967295u);
  EXPECT_EQ(ui[4], GLuint(0x80000000u));
  EXPECT_EQ(ui[5], 3000000000u);
  EXPECT_EQ(ui[6], GLuint(0x80000000u));
  EXPECT_EQ(ui[7], 2u);
  // As unsigned shorts: NaN 0, clamped to [0, 65535].
  const std::array<GLushort, 8> want_us = {0, 65535, 0, 65535, 0, 65535, 0, 2};
  EXPECT_EQ(us, want_us);
}

TEST_F(PixelMapTest, ColourMapsOfExtremeValuesReadBackClamped) {
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, GLsizei(kExtremes.size()), kExtremes.data());
  std::array<GLfloat, 8> f{};
  std::array<GLuint, 8> ui{};
  std::array<GLushort, 8> us{};
  glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, f.data());
  glGetPixelMapuiv(GL_PIXEL_MAP_R_TO_R, ui.data());
  glGetPixelMapusv(GL_PIXEL_MAP_R_TO_R, us.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const std::array<GLfloat, 8> want_f = {0, 1, 0, 1, 0, 1, 0, 1};  // stored clamped to [0, 1]
  EXPECT_EQ(f, want_f);
  const std::array<GLuint, 8> want_ui = {0, 4294967295u, 0, 4294967295u, 0, 4294967295u, 0, 4294967295u};
  EXPECT_EQ(ui, want_ui);
  const std::array<GLushort, 8> want_us = {0, 65535, 0, 65535, 0, 65535, 0, 65535};
  EXPECT_EQ(us, want_us);
}

// S_TO_S values are stored as integers in GLint's range (Mesa's); a huge one used by
// glDrawPixels(GL_STENCIL_INDEX) under GL_MAP_STENCIL writes its low 8 bits.
TEST_F(PixelMapTest, StencilMapOfHugeValuesIsUsable) {
  std::array<float, 2> map = {1e30f, kNaN};
  glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 2, map.data());
  std::array<GLfloat, 2> f{};
  glGetPixelMapfv(GL_PIXEL_MAP_S_TO_S, f.data());
  EXPECT_EQ(f[0], 2147483520.0f);
  EXPECT_EQ(f[1], 0.0f);
  glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows of 2 bytes, unpadded
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  const std::array<GLubyte, 4> indices = {0, 1, 2, 3};
  glRasterPos2f(-1.0f, -1.0f);
  glDrawPixels(2, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, indices.data());
  std::array<GLubyte, 4> stencil{};
  glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);  // read back as stored (reading maps too)
  glReadPixels(0, 0, 2, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // Indices 0 and 2 map through entry 0 (2147483520: low byte 0x80), 1 and 3 through entry 1.
  const std::array<GLubyte, 4> want = {0x80, 0, 0x80, 0};
  EXPECT_EQ(stencil, want);
}

}  // namespace
