// Multisampling (GL 1.5 sections 3.2.1 and 4.1.3, gl/src/multisample.cpp) on an OSMesa
// context with shadelab's OSMESA_SAMPLES_SHADELAB attribute, on the fast pipeline and on the
// reference one (SHADELAB_REFERENCE): a white shape over black leaves 255 * covered / 4 in an
// edge pixel, the samples at x 0.125, 0.375, 0.625, 0.875 and y 0.125 ... 0.875 of the pixel.
// Coverage, depth and stencil per sample, GL_MULTISAMPLE off, smooth lines ignored, sample
// coverage, alpha to coverage and to one, pixel rectangles, clears, the accumulation buffer,
// occlusion queries counting samples, and the caller's buffer holding the resolved colours.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <vector>

namespace {

constexpr int kSize = 16;

OSMesaContext make_context(int samples, int accum = 0) {
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_ACCUM_BITS, accum, OSMESA_SAMPLES_SHADELAB, samples, 0};
  return OSMesaCreateContextAttribs(attributes, nullptr);
}

class MultisampleTest : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    if (GetParam()) setenv("SHADELAB_REFERENCE", "1", 1);
    ctx_ = make_context(4, 16);
    unsetenv("SHADELAB_REFERENCE");
    ASSERT_NE(ctx_, nullptr);
    ASSERT_TRUE(OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, kSize, kSize));
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, kSize, 0, kSize, -1, 1);  // window pixels, z 1 nearest (depth 0)
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glColor3f(1, 1, 1);
  }
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
  }
  static void rect(float x0, float y0, float x1, float y1, float z = 0.0f) {
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z), glVertex3f(x1, y0, z), glVertex3f(x1, y1, z), glVertex3f(x0, y1, z);
    glEnd();
  }
  static std::array<int, 4> rgba(int x, int y) {
    GLubyte p[4] = {};
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    return {p[0], p[1], p[2], p[3]};
  }
  static int red(int x, int y) { return rgba(x, y)[0]; }

  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> pixels_ = std::vector<unsigned char>(kSize * kSize * 4);
};

TEST(MultisampleContextTest, SamplesAskedForGiveFourAndNoneWithoutTheAttribute) {
  std::vector<unsigned char> pixels(kSize * kSize * 4);
  for (int asked : {0, 1, 2, 4}) {
    OSMesaContext c = make_context(asked);
    ASSERT_NE(c, nullptr) << asked;
    ASSERT_TRUE(OSMesaMakeCurrent(c, pixels.data(), GL_UNSIGNED_BYTE, kSize, kSize));
    GLint buffers = -1, samples = -1;
    glGetIntegerv(GL_SAMPLE_BUFFERS, &buffers);
    glGetIntegerv(GL_SAMPLES, &samples);
    EXPECT_EQ(buffers, asked > 0 ? 1 : 0) << asked;
    EXPECT_EQ(samples, asked > 0 ? 4 : 0) << asked;
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(c);
  }
  EXPECT_EQ(make_context(5), nullptr);
  EXPECT_EQ(make_context(-1), nullptr);
}

TEST_P(MultisampleTest, EdgePixelsHoldTheShareOfSamplesCovered) {
  rect(0, 0, 8.5f, 4);     // two of the four sample columns of pixel 8
  rect(0, 4, 8.25f, 6);    // one
  rect(0, 6, 8.75f, 8);    // three
  rect(10, 0, 16, 10.5f);  // two sample rows of row 10
  rect(10, 12, 16, 13.25f);
  EXPECT_EQ(red(7, 2), 255);
  EXPECT_EQ(red(8, 2), 128);
  EXPECT_EQ(red(9, 2), 0);
  EXPECT_EQ(red(8, 5), 64);
  EXPECT_EQ(red(8, 7), 191);
  EXPECT_EQ(red(12, 10), 128);
  EXPECT_EQ(red(12, 11), 0);
  EXPECT_EQ(red(12, 13), 64);
  EXPECT_EQ(rgba(8, 2)[3], 128);  // alpha resolved as the other channels
  glFinish();  // the caller's buffer holds the resolved colours
  EXPECT_EQ(pixels_[(2 * kSize + 8) * 4], 128);
  EXPECT_EQ(pixels_[(2 * kSize + 7) * 4], 255);
}

TEST_P(MultisampleTest, DepthAndStencilAreTestedPerSample) {
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 0, 0);
  rect(0, 0, 16, 4, -0.5f);  // far
  glColor3f(0, 1, 0);
  rect(0, 0, 8.5f, 4, 0.5f);  // near, half of pixel 8
  glColor3f(0, 0, 1);
  rect(0, 0, 16, 4, 0.0f);  // between: where the far one is only
  glDisable(GL_DEPTH_TEST);
  EXPECT_EQ(rgba(8, 2), (std::array<int, 4>{0, 128, 128, 255}));
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  rect(0, 8, 8.25f, 12);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColor3f(1, 1, 1);
  rect(0, 8, 16, 12);
  glDisable(GL_STENCIL_TEST);
  EXPECT_EQ(red(7, 10), 255);
  EXPECT_EQ(red(8, 10), 64);
  EXPECT_EQ(red(9, 10), 0);
}

TEST_P(MultisampleTest, MultisampleOffSamplesThePixelCentre) {
  glDisable(GL_MULTISAMPLE);
  rect(0, 0, 8.4f, 4);
  rect(0, 4, 8.6f, 8);
  glEnable(GL_MULTISAMPLE);
  EXPECT_EQ(red(8, 2), 0);
  EXPECT_EQ(red(8, 6), 255);
  rect(0, 8, 8.4f, 12);
  EXPECT_EQ(red(8, 10), 128);
}

// Sections 3.3.3 and 3.4.4: a point is a disc of its size, a line the rectangle of its width,
// smooth or not; a point below the fade threshold fades.
TEST_P(MultisampleTest, SmoothLinesAndPointsAreMultisampledInstead) {
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBegin(GL_LINES);
  glVertex2f(2, 4.5f), glVertex2f(14, 4.5f);
  glEnd();
  glPointSize(3.0f);
  glBegin(GL_POINTS);
  glVertex2f(8.5f, 12.5f);  // the disc of radius 1.5 on pixel (8, 12)
  glEnd();
  glPointSize(0.5f);  // below the fade threshold (1): drawn at size 1, alpha times 1/4
  glBegin(GL_POINTS);
  glVertex2f(4.5f, 14.5f);
  glEnd();
  glPointSize(1.0f);
  glDisable(GL_BLEND);
  EXPECT_EQ(red(8, 4), 255);  // every sample's line is row 4: no smoothed fringe
  EXPECT_EQ(red(8, 3), 0);
  EXPECT_EQ(red(8, 5), 0);
  for (int x = 7; x <= 9; ++x) EXPECT_EQ(red(x, 12), 255) << x;  // whole, no smoothed rim
  EXPECT_EQ(red(7, 11), 128);  // a disc: two samples of the corner pixel
  EXPECT_EQ(red(4, 14), 64);
  EXPECT_EQ(red(6, 12), 0);
  EXPECT_EQ(red(10, 12), 0);
  EXPECT_EQ(red(8, 10), 0);
  EXPECT_EQ(red(8, 14), 0);
}

TEST_P(MultisampleTest, WideLinesAreRectanglesOfTheirWidth) {
  glLineWidth(2.0f);
  glBegin(GL_LINES);
  glVertex2f(2, 2), glVertex2f(14, 14);  // samples within 1 of the diagonal y = x
  glEnd();
  glLineWidth(1.0f);
  EXPECT_EQ(red(8, 8), 255);
  EXPECT_EQ(red(9, 8), 191);  // three samples of four within the rectangle
  EXPECT_EQ(red(9, 7), 0);
  EXPECT_EQ(red(15, 15), 0);  // it ends at the endpoints
}

TEST_P(MultisampleTest, SampleCoverageKeepsTheFirstSamplesOrTheOthers) {
  glEnable(GL_SAMPLE_COVERAGE);
  glSampleCoverage(0.5f, GL_FALSE);
  rect(0, 0, 16, 8);
  glSampleCoverage(0.5f, GL_TRUE);
  glColor3f(0, 0, 1);
  rect(0, 0, 16, 4);
  glSampleCoverage(0.3f, GL_FALSE);  // one sample (truncated)
  rect(0, 8, 16, 12);
  glSampleCoverage(0.0f, GL_FALSE);  // none
  rect(0, 12, 16, 16);
  glDisable(GL_SAMPLE_COVERAGE);
  EXPECT_EQ(rgba(3, 6), (std::array<int, 4>{128, 128, 128, 128}));
  EXPECT_EQ(rgba(3, 2), (std::array<int, 4>{128, 128, 255, 255}));
  EXPECT_EQ(rgba(3, 10), (std::array<int, 4>{0, 0, 64, 64}));
  EXPECT_EQ(rgba(3, 14), (std::array<int, 4>{0, 0, 0, 0}));
}

TEST_P(MultisampleTest, AlphaToCoverageAndAlphaToOne) {
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  for (int i = 0; i <= 4; ++i) {  // alphas 0, 0.2 ... 0.8: 0, 1, 2, 2, 3 samples
    glColor4f(1, 1, 1, 0.2f * float(i));
    rect(float(3 * i), 0, float(3 * i + 3), 4);
  }
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.7f);  // a larger lower bound stands: 0.6 fails, 0.9 covers 4
  glColor4f(1, 1, 1, 0.6f);
  rect(0, 4, 8, 8);
  glColor4f(1, 1, 1, 0.9f);
  rect(8, 4, 16, 8);
  glAlphaFunc(GL_LESS, 0.5f);  // an upper bound too: 0.4 keeps its two samples, 0.6 none
  glColor4f(1, 1, 1, 0.4f);
  rect(0, 14, 8, 16);
  glColor4f(1, 1, 1, 0.6f);
  rect(8, 14, 16, 16);
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  EXPECT_EQ(red(1, 2), 0);
  EXPECT_EQ(red(4, 2), 64);
  EXPECT_EQ(red(7, 2), 128);
  EXPECT_EQ(red(10, 2), 128);
  EXPECT_EQ(red(13, 2), 191);
  EXPECT_EQ(red(4, 6), 0);
  EXPECT_EQ(red(12, 6), 255);
  EXPECT_EQ(red(4, 15), 128);
  EXPECT_EQ(red(12, 15), 0);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  glColor4f(1, 1, 1, 0.25f);
  rect(0, 8, 16, 10);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_LESS, 0.5f);  // compares the alpha 1: nothing passes
  rect(0, 10, 16, 12);
  glDisable(GL_ALPHA_TEST);
  glDisable(GL_SAMPLE_ALPHA_TO_ONE);
  rect(0, 12, 16, 14);
  glDisable(GL_BLEND);
  EXPECT_EQ(rgba(4, 9), (std::array<int, 4>{255, 255, 255, 255}));
  EXPECT_EQ(red(4, 11), 0);
  EXPECT_EQ(red(4, 13), 64);
}

TEST_P(MultisampleTest, PixelRectanglesClearsAndTheAccumulationBufferReachEverySample) {
  rect(0, 0, 8.5f, 4);  // pixel 8: 128
  glRasterPos2i(0, 8);
  glCopyPixels(6, 0, 4, 4, GL_COLOR);  // the resolved colours, onto every sample
  EXPECT_EQ(red(2, 10), 128);
  EXPECT_EQ(red(1, 10), 255);
  const std::array<GLubyte, 16> white{255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255};
  glRasterPos2i(12, 12);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, white.data());
  EXPECT_EQ(red(12, 12), 255);
  EXPECT_EQ(red(13, 13), 255);
  EXPECT_EQ(red(14, 14), 0);
  rect(12, 12, 14, 14);  // drawn again over every sample: still 255
  EXPECT_EQ(red(13, 13), 255);
  glAccum(GL_LOAD, 0.5f);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_NEAR(red(8, 2), 64, 1);
  EXPECT_NEAR(red(7, 2), 128, 1);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 8, 16);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  EXPECT_EQ(rgba(7, 2), (std::array<int, 4>{0, 255, 0, 255}));
  EXPECT_NEAR(red(8, 2), 64, 1);
  rect(8, 0, 8.5f, 4);  // half of pixel 8 again: its other samples stay as they were
  EXPECT_NEAR(red(8, 2), 160, 1);  // (255 + 255 + 64 + 64) / 4, rounded
  glClearDepth(0.25);
  glClear(GL_DEPTH_BUFFER_BIT);
  GLfloat depth = 0;
  glReadPixels(3, 3, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  EXPECT_NEAR(depth, 0.25f, 1e-6f);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  rect(0, 8, 16, 16, 0.49f);  // depth 0.255: behind the cleared depth in every sample
  glDisable(GL_DEPTH_TEST);
  EXPECT_EQ(red(3, 12), 0);
}

TEST_P(MultisampleTest, OcclusionQueriesCountSamples) {
  GLuint query = 0;
  glGenQueries(1, &query);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  rect(0, 0, 4, 4);        // 16 pixels, 64 samples
  rect(8, 0, 8.5f, 1);     // 2 samples
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint n = 0;
  glGetQueryObjectuiv(query, GL_QUERY_RESULT, &n);
  EXPECT_EQ(n, 66u);
  glDeleteQueries(1, &query);
}

TEST_P(MultisampleTest, ANewBufferSizeStartsFromItsPixels) {
  rect(0, 0, 8.5f, 4);
  std::vector<unsigned char> other(8 * 8 * 4, 0);
  for (std::size_t i = 0; i < other.size(); i += 4) other[i] = 200, other[i + 3] = 255;
  ASSERT_TRUE(OSMesaMakeCurrent(ctx_, other.data(), GL_UNSIGNED_BYTE, 8, 8));
  glViewport(0, 0, 8, 8);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 8, 0, 8, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glColor3f(0, 0, 0);
  rect(0, 0, 4.5f, 8);  // over the caller's pixels: pixel 4 keeps half of its 200
  EXPECT_EQ(red(4, 3), 100);
  EXPECT_EQ(red(5, 3), 200);
  EXPECT_EQ(red(3, 3), 0);
}

INSTANTIATE_TEST_SUITE_P(Pipelines, MultisampleTest, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "Reference" : "Fast"; });

}  // namespace
