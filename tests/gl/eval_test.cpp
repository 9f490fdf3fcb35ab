// Evaluators (GL 1.1 section 5.1, gl/src/eval.cpp): what the conformance program evaluators
// cannot compare with Mesa. Evaluation leaves the current colour, normal and texture
// coordinates unchanged (Mesa 22.3 leaves stale values there, docs/gl-conformance.md); a
// surface's point computed with GL_AUTO_NORMAL (de Casteljau) equals the one computed without
// (Horner); glEvalCoord inside glBegin/glEnd in a list replays once per call. Through the GL
// API on an OSMesa context.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "gl/src/eval_math.hpp"

namespace {

constexpr int kSize = 64;

// The Red Book's bezsurf control points: 4 x 4 x 3.
constexpr float kPatch[4][4][3] = {
    {{-1.5f, -1.5f, 4.0f}, {-0.5f, -1.5f, 2.0f}, {0.5f, -1.5f, -1.0f}, {1.5f, -1.5f, 2.0f}},
    {{-1.5f, -0.5f, 1.0f}, {-0.5f, -0.5f, 3.0f}, {0.5f, -0.5f, 0.0f}, {1.5f, -0.5f, -1.0f}},
    {{-1.5f, 0.5f, 4.0f}, {-0.5f, 0.5f, 0.0f}, {0.5f, 0.5f, 3.0f}, {1.5f, 0.5f, 4.0f}},
    {{-1.5f, 1.5f, -2.0f}, {-0.5f, 1.5f, -2.0f}, {0.5f, 1.5f, 0.0f}, {1.5f, 1.5f, -1.0f}}};

class EvalTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    ASSERT_NE(ctx_, nullptr);
    ASSERT_TRUE(OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, kSize, kSize));
    glMatrixMode(GL_PROJECTION);
    glOrtho(-4.5, 4.5, -4.5, 4.5, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
  }
  void TearDown() override {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
  }
  int drawn() const {
    int n = 0;
    for (int i = 0; i < kSize * kSize; ++i) n += pixels_[std::size_t(i) * 4 + 3] != 0;
    return n;
  }

  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> pixels_ = std::vector<unsigned char>(kSize * kSize * 4);
};

TEST_F(EvalTest, EvaluationLeavesTheCurrentValues) {
  const float colours[2][2][4] = {{{1, 0, 0, 1}, {0, 1, 0, 1}}, {{0, 0, 1, 1}, {1, 1, 0, 1}}};
  const float tex[2][2][2] = {{{0, 0}, {0, 1}}, {{1, 0}, {1, 1}}};
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
  glNormal3f(0.0f, 0.6f, 0.8f);
  glTexCoord4f(0.125f, 0.375f, 0.5f, 2.0f);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &kPatch[0][0][0]);
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, &colours[0][0][0]);
  glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 2, 2, 0, 1, 4, 2, &tex[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3), glEnable(GL_MAP2_COLOR_4), glEnable(GL_MAP2_TEXTURE_COORD_2);
  glEnable(GL_AUTO_NORMAL), glEnable(GL_LIGHTING), glEnable(GL_LIGHT0);
  glMapGrid2f(4, 0.0f, 1.0f, 4, 0.0f, 1.0f);
  glEvalMesh2(GL_FILL, 0, 4, 0, 4);
  glBegin(GL_TRIANGLES);
  glEvalCoord2f(0.2f, 0.3f), glEvalPoint2(1, 2), glEvalCoord2f(0.7f, 0.1f);
  glEnd();
  std::array<float, 4> c{}, t{};
  std::array<float, 3> n{};
  glGetFloatv(GL_CURRENT_COLOR, c.data());
  glGetFloatv(GL_CURRENT_NORMAL, n.data());
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, t.data());
  EXPECT_EQ(c, (std::array<float, 4>{0.25f, 0.5f, 0.75f, 1.0f}));
  EXPECT_EQ(n, (std::array<float, 3>{0.0f, 0.6f, 0.8f}));
  EXPECT_EQ(t, (std::array<float, 4>{0.125f, 0.375f, 0.5f, 2.0f}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// De Casteljau's point (with the tangents) is Horner's point, for equal and unequal orders.
TEST(EvalMath, TangentPathGivesTheSamePoint) {
  std::vector<float> net;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j)
      net.insert(net.end(), {float(i), float(j * j) * 0.5f, float((i * 7 + j * 3) % 5)});
  const int orders[][2] = {{4, 4}, {2, 5}, {6, 3}, {3, 3}, {2, 2}, {5, 4}};
  for (const auto& o : orders) {
    for (float u : {0.0f, 0.25f, 0.5f, 1.0f}) {
      for (float v : {0.0f, 0.4f, 1.0f}) {
        float a[3], b[3], du[3], dv[3];
        shadelab::gl::bezier_surface(net.data(), 3, o[0], o[1], u, v, a);
        shadelab::gl::bezier_surface_tangents(net.data(), 3, o[0], o[1], u, v, b, du, dv);
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(a[k], b[k], 1e-4f)
              << "orders " << o[0] << " x " << o[1] << " at " << u << ", " << v;
        }
      }
    }
  }
}

// glBegin/glEvalCoord2/glEnd compiled with GL_COMPILE_AND_EXECUTE draws, and the list draws the
// same again (Mesa 22.3 compiles the executed evaluation's vertices too: each replays twice).
TEST_F(EvalTest, EvalCoordInAListReplaysOnce) {
  const float square[2][2][3] = {{{-4, -4, 0}, {4, -4, 0}}, {{-4, 4, 0}, {4, 4, 0}}};
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, &square[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glNewList(1, GL_COMPILE_AND_EXECUTE);
  glBegin(GL_QUADS);
  glEvalCoord2f(0.5f, 0.5f), glEvalCoord2f(1.0f, 0.5f), glEvalCoord2f(1.0f, 1.0f),
      glEvalCoord2f(0.5f, 1.0f);
  glEnd();
  glEndList();
  glFinish();
  const int executed = drawn();
  EXPECT_GT(executed, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glCallList(1);
  glFinish();
  EXPECT_EQ(drawn(), executed);
}

}  // namespace
