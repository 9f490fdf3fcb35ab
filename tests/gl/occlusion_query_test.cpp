// Occlusion queries (GL 1.5 section 4.1.6, gl/src/queryobj.cpp) counted by hand, on the fast
// pipeline and on the reference one (SHADELAB_REFERENCE): whole and hidden quads, the draws
// made before glBeginQuery (left waiting by the fast pipeline) not counted, glBitmap's set
// bits, glDrawPixels' pixels, points, the alpha test, and the same counts from both. Through
// the GL API on an OSMesa context.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

namespace {

constexpr int kSize = 16;

class OcclusionQueryTest : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    if (GetParam()) setenv("SHADELAB_REFERENCE", "1", 1);
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    unsetenv("SHADELAB_REFERENCE");
    ASSERT_NE(ctx_, nullptr);
    ASSERT_TRUE(OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, kSize, kSize));
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, kSize, 0, kSize, -1, 1);  // window pixels, z 1 nearest (depth 0)
    glMatrixMode(GL_MODELVIEW);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glGenQueries(1, &query_);
  }
  void TearDown() override {
    glDeleteQueries(1, &query_);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
  }
  // The samples `draw` makes pass, through a query.
  template <class Draw>
  GLuint count(Draw draw) {
    glBeginQuery(GL_SAMPLES_PASSED, query_);
    draw();
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint n = ~0u;
    glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &n);
    GLuint available = 0;
    glGetQueryObjectuiv(query_, GL_QUERY_RESULT_AVAILABLE, &available);
    EXPECT_EQ(available, GLuint(GL_TRUE));
    return n;
  }
  static void rect(float x0, float y0, float x1, float y1, float z) {
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z), glVertex3f(x1, y0, z), glVertex3f(x1, y1, z), glVertex3f(x0, y1, z);
    glEnd();
  }

  OSMesaContext ctx_ = nullptr;
  GLuint query_ = 0;
  std::vector<unsigned char> pixels_ = std::vector<unsigned char>(kSize * kSize * 4);
};

TEST_P(OcclusionQueryTest, QuadsCountTheirPassingPixels) {
  EXPECT_EQ(count([] { rect(0, 0, kSize, kSize, 0); }), GLuint(kSize * kSize));
  glEnable(GL_DEPTH_TEST);
  rect(0, 0, kSize, kSize, 0.5f);  // depth 0.25 everywhere
  EXPECT_EQ(count([] { rect(0, 0, kSize, kSize, 0.0f); }), 0u);           // behind
  EXPECT_EQ(count([] { rect(2, 3, 10, 7, 0.9f); }), GLuint(8 * 4));        // in front
  EXPECT_EQ(count([] {}), 0u);                                             // no draw
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);                     // still counted
  glDepthMask(GL_FALSE);
  EXPECT_EQ(count([] { rect(0, 0, 4, 4, 1.0f); }), 16u);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
}

TEST_P(OcclusionQueryTest, DrawsMadeBeforeTheQueryAreNotCounted) {
  for (int i = 0; i < 20; ++i) rect(0, 0, kSize, kSize, 0);  // waiting on the fast pipeline
  EXPECT_EQ(count([] { rect(0, 0, 5, 5, 0); }), 25u);
  rect(0, 0, kSize, kSize, 0);  // after the query: not in the next one either
  EXPECT_EQ(count([] { rect(0, 0, 1, 3, 0); }), 3u);
}

TEST_P(OcclusionQueryTest, BitmapsAndPixelsCountTheirFragments) {
  static const GLubyte bits[8] = {0xff, 0x81, 0x81, 0x00, 0x0f, 0x00, 0x01, 0x80};  // 8+2+2+4+1+1 bits
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(3, 3);
  EXPECT_EQ(count([] { glBitmap(8, 8, 0, 0, 0, 0, bits); }), 18u);
  std::vector<GLubyte> image(5 * 4 * 4, 200);
  glRasterPos2i(1, 1);
  EXPECT_EQ(count([&] { glDrawPixels(5, 4, GL_RGBA, GL_UNSIGNED_BYTE, image.data()); }), 20u);
  glPixelZoom(2.0f, 3.0f);
  EXPECT_EQ(count([&] { glDrawPixels(5, 4, GL_RGBA, GL_UNSIGNED_BYTE, image.data()); }), 120u);
  glPixelZoom(1.0f, 1.0f);
  glRasterPos2i(kSize - 2, kSize - 2);  // partly outside the window: only the pixels inside
  EXPECT_EQ(count([&] { glDrawPixels(5, 4, GL_RGBA, GL_UNSIGNED_BYTE, image.data()); }), 4u);
}

TEST_P(OcclusionQueryTest, PointsAndTheAlphaTest) {
  EXPECT_EQ(count([] {
              glBegin(GL_POINTS);
              for (int i = 0; i < 5; ++i) glVertex2f(1.5f + 2.0f * float(i), 4.5f);
              glEnd();
            }),
            5u);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  EXPECT_EQ(count([] {
              glColor4f(1, 1, 1, 0.25f);
              rect(0, 0, 8, 8, 0);
              glColor4f(1, 1, 1, 0.75f);
              rect(8, 0, 16, 2, 0);
            }),
            16u);
  glDisable(GL_ALPHA_TEST);
}

INSTANTIATE_TEST_SUITE_P(Pipelines, OcclusionQueryTest, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Reference" : "Fast"; });

}  // namespace
