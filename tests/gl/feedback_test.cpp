// Selection and feedback (gl/src/feedback.cpp) where shadelab follows the specification and
// Mesa 22 does not, so the conformance program select_feedback cannot compare them: edge
// flags of polygons drawn as lines, texture coordinates generated and transformed with no
// texture enabled; and what no Mesa comparison shows: nothing is drawn in either mode, on the
// fast pipeline's deferred draws too. Through the GL API on an OSMesa context.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <vector>

namespace {

constexpr int kSize = 32;

class FeedbackTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    ASSERT_NE(ctx_, nullptr);
    ASSERT_TRUE(OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  }
  void TearDown() override {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
  }
  std::vector<GLfloat> feedback(GLenum type, void (*draw)()) {
    std::vector<GLfloat> buffer(4096, -99.0f);
    glFeedbackBuffer(GLsizei(buffer.size()), type, buffer.data());
    glRenderMode(GL_FEEDBACK);
    draw();
    const GLint n = glRenderMode(GL_RENDER);
    EXPECT_GE(n, 0);
    buffer.resize(std::size_t(n < 0 ? 0 : n));
    return buffer;
  }

  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> pixels_ = std::vector<unsigned char>(kSize * kSize * 4);
};

// GL 1.1 section 2.6.2: an edge is drawn (and fed back) when its first vertex's flag is set.
TEST_F(FeedbackTest, PolygonEdgesInLineModeFollowTheEdgeFlags) {
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  const std::vector<GLfloat> fb = feedback(GL_2D, [] {
    glBegin(GL_POLYGON);
    glEdgeFlag(GL_TRUE);
    glVertex2f(-0.5f, -0.5f);  // window (8, 8): edge to (24, 8) drawn
    glEdgeFlag(GL_FALSE);
    glVertex2f(0.5f, -0.5f);  // (24, 8): edge to (24, 24) not drawn
    glEdgeFlag(GL_TRUE);
    glVertex2f(0.5f, 0.5f);  // (24, 24): edge to (8, 24) drawn
    glVertex2f(-0.5f, 0.5f);  // (8, 24): edge back to (8, 8) drawn
    glEnd();
  });
  // Three lines of 5 values each; the first restarts the stipple (the polygon's first triangle).
  const std::vector<GLfloat> expected = {GL_LINE_RESET_TOKEN, 8, 8, 24, 8, GL_LINE_TOKEN, 24, 24, 8, 24,
                                         GL_LINE_TOKEN, 8, 24, 8, 8};
  EXPECT_EQ(fb, expected);
}

// Sections 2.10.2 and 5.3: the fed-back texture coordinates are those after generation and the
// texture matrix, whether or not a texture is enabled.
TEST_F(FeedbackTest, TextureCoordinatesAreGeneratedAndTransformedWithoutATexture) {
  static const GLfloat plane[4] = {1.0f, 0.0f, 0.0f, 0.5f};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  glEnable(GL_TEXTURE_GEN_S);
  glMatrixMode(GL_TEXTURE);
  glScalef(2.0f, 3.0f, 1.0f);
  glMatrixMode(GL_MODELVIEW);
  glTexCoord4f(7.0f, 0.25f, 0.5f, 1.0f);
  const std::vector<GLfloat> fb = feedback(GL_3D_COLOR_TEXTURE, [] {
    glBegin(GL_POINTS);
    glVertex2f(0.25f, 0.0f);
    glEnd();
  });
  ASSERT_EQ(fb.size(), 1u + 3 + 4 + 4);
  EXPECT_EQ(fb[0], GLfloat(GL_POINT_TOKEN));
  EXPECT_FLOAT_EQ(fb[8], 2.0f * (0.25f + 0.5f));  // s generated, then scaled
  EXPECT_FLOAT_EQ(fb[9], 3.0f * 0.25f);           // t given, then scaled
  EXPECT_FLOAT_EQ(fb[10], 0.5f);
  EXPECT_FLOAT_EQ(fb[11], 1.0f);
}

// Draws, clears and pixel copies in either mode leave the framebuffer alone; the deferred draw
// made before the mode change is still drawn.
TEST_F(FeedbackTest, NothingIsDrawnInSelectionOrFeedbackMode) {
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1.0f, 0.0f, 0.0f);
  glRectf(-1.0f, -1.0f, 0.0f, 1.0f);  // left half red, deferred
  GLfloat fbuf[256];
  GLuint sbuf[64];
  glFeedbackBuffer(256, GL_2D, fbuf);
  glSelectBuffer(64, sbuf);
  for (GLenum mode : {GLenum(GL_FEEDBACK), GLenum(GL_SELECT)}) {
    glRenderMode(mode);
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0.0f, 1.0f, 0.0f);
    glRectf(-1.0f, -1.0f, 1.0f, 1.0f);
    glRasterPos2f(-1.0f, -1.0f);
    glCopyPixels(0, 0, kSize / 2, kSize, GL_COLOR);
    EXPECT_GT(glRenderMode(GL_RENDER), 0);
  }
  glFinish();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const unsigned char* p = &pixels_[std::size_t(4 * (y * kSize + x))];
      const bool left = x < kSize / 2;
      ASSERT_EQ(p[0], left ? 255 : 0) << x << ", " << y;
      ASSERT_EQ(p[1], 0) << x << ", " << y;
      ASSERT_EQ(p[2], left ? 0 : 255) << x << ", " << y;
    }
  }
}

}  // namespace
