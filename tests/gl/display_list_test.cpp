// Display lists' geometry compiled once (gl/src/dlist_geometry.cpp): which primitives become
// meshes, that a mesh replaces its commands, that the vertex-array path draws the same pixels
// as the commands drawn immediately, when the path is left for vertex-by-vertex drawing, and
// the current values a list leaves. Through the GL API on an OSMesa context; the list's
// internals read through the library's private headers.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <vector>

#include "gl/src/context.hpp"
#include "gl/src/osmesa_context.hpp"

namespace {

constexpr int kSize = 64;

class DisplayListTest : public ::testing::Test {
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
  // The test's own context, not current_context(): gcc's UBSan null check of a thread-local
  // address reads the flags of an add that the linker relaxes into a lea in executables
  // (initial-exec to local-exec), and reports a null pointer that is not there.
  shadelab::gl::GlContext& gl() { return *ctx_; }
  const shadelab::gl::DisplayList& list(GLuint name) {
    return *gl().lists.names->lists.at(name);
  }
  std::vector<unsigned char> frame(const std::function<void()>& draw) {
    glClear(GL_COLOR_BUFFER_BIT);
    draw();
    glFinish();
    return pixels_;
  }
  static int max_difference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
    int worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
    return worst;
  }

  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> pixels_ = std::vector<unsigned char>(kSize * kSize * 4);
};

// A lit strip of 2 x 8 vertices, each vertex given twice as a triangle list would.
void lit_triangles() {
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 7; ++i) {
    const float x0 = -0.9f + 0.25f * float(i), x1 = x0 + 0.25f;
    const float quad[6][2] = {{x0, -0.5f}, {x1, -0.5f}, {x1, 0.5f}, {x0, -0.5f}, {x1, 0.5f}, {x0, 0.5f}};
    for (const auto& v : quad) {
      glNormal3f(v[0] * 0.5f, v[1], 1.0f);
      glVertex2f(v[0], v[1]);
    }
  }
  glEnd();
}

void setup_light() {
  const GLfloat pos[] = {0.3f, 0.5f, 1.0f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
}

TEST_F(DisplayListTest, BeginEndOfVerticesBecomesOneMeshOfDistinctVertices) {
  glNewList(1, GL_COMPILE);
  lit_triangles();
  glEndList();
  const shadelab::gl::DisplayList& l = list(1);
  ASSERT_EQ(l.meshes.size(), 1u);
  const shadelab::gl::ListMesh& m = l.meshes[0];
  EXPECT_EQ(m.mode, GLenum(GL_TRIANGLES));
  EXPECT_EQ(m.indices.size(), 42u);    // 7 quads of 2 triangles
  EXPECT_EQ(m.positions.size(), 16u);  // 8 columns of 2 vertices
  EXPECT_EQ(m.normals.size(), 16u);
  EXPECT_TRUE(m.colors.empty());  // never set: the colour current at glCallList
  EXPECT_EQ(l.code.size(), 2u);   // the Mesh command (header and index) replaced the 86 commands
}

TEST_F(DisplayListTest, AttributeFirstSetAfterTheFirstVertexKeepsTheCommands) {
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glColor3f(1, 0, 0);
  glVertex2f(1, 0);
  glVertex2f(0, 1);
  glEnd();
  glEndList();
  EXPECT_TRUE(list(1).meshes.empty());
}

TEST_F(DisplayListTest, MeshDrawsWhatTheCommandsDrawThroughTheArrayPath) {
  setup_light();
  glNewList(1, GL_COMPILE);
  lit_triangles();
  glEndList();
  const auto immediate = frame(lit_triangles);
  const auto fast_before = gl().lists.meshes_fast;
  const auto listed = frame([] { glCallList(1); });
  EXPECT_EQ(gl().lists.meshes_fast, fast_before + 1);
  EXPECT_LE(max_difference(immediate, listed), 1);
}

TEST_F(DisplayListTest, ColourMaterialWithPerVertexColoursGoesVertexByVertex) {
  setup_light();
  glEnable(GL_COLOR_MATERIAL);
  auto coloured = [] {
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i < 8; ++i) {
      glColor3f(float(i) / 7.0f, 1.0f - float(i) / 7.0f, 0.5f);
      glNormal3f(0.0f, 0.2f * float(i % 2), 1.0f);
      glVertex2f(-0.9f + 0.25f * float(i / 2), i % 2 ? 0.6f : -0.6f);
    }
    glEnd();
  };
  glNewList(1, GL_COMPILE);
  coloured();
  glEndList();
  const auto immediate = frame(coloured);
  const auto by_vertex_before = gl().lists.meshes_by_vertex;
  const auto listed = frame([] { glCallList(1); });
  EXPECT_EQ(gl().lists.meshes_by_vertex, by_vertex_before + 1);
  EXPECT_LE(max_difference(immediate, listed), 1);
  GLfloat diffuse[4];
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);  // the material followed the last colour
  EXPECT_FLOAT_EQ(diffuse[0], 1.0f);
  EXPECT_FLOAT_EQ(diffuse[1], 0.0f);
}

TEST_F(DisplayListTest, ListLeavesTheAttributesItSetLastCurrent) {
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glColor3f(0.25f, 0.5f, 0.75f);
  glTexCoord2f(0.5f, 0.25f);
  glVertex2f(0, 0), glVertex2f(1, 0), glVertex2f(0, 1);
  glEnd();
  glEndList();
  glNormal3f(0.0f, 1.0f, 0.0f);
  glCallList(1);
  GLfloat v[4];
  glGetFloatv(GL_CURRENT_COLOR, v);
  EXPECT_FLOAT_EQ(v[2], 0.75f);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, v);
  EXPECT_FLOAT_EQ(v[0], 0.5f);
  EXPECT_FLOAT_EQ(v[1], 0.25f);
  glGetFloatv(GL_CURRENT_NORMAL, v);  // not set by the list: unchanged
  EXPECT_FLOAT_EQ(v[1], 1.0f);
}

// As if its commands were called there (GL 1.1 section 5.4; Mesa instead records the error and
// drops the list's vertices, docs/gl-conformance.md).
TEST_F(DisplayListTest, ListPrimitiveCalledInsideAPrimitiveAddsItsVerticesToIt) {
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glVertex2f(1.0f, -1.0f), glVertex2f(1.0f, 1.0f);
  glEnd();
  glEndList();
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1.0f, -1.0f);
  glCallList(1);  // its glBegin: GL_INVALID_OPERATION; its vertices complete this triangle; its glEnd ends it
  EXPECT_FALSE(gl().prim.active);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glFinish();
  const unsigned char* p = &pixels_[(16 * kSize + 48) * 4];  // inside the triangle
  EXPECT_EQ(p[0], 255);
  EXPECT_EQ(gl().lists.meshes_by_vertex, 1u);
}

TEST_F(DisplayListTest, DrawElementsInAListSharesItsVertices) {
  const GLfloat pos[4][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  const GLuint idx[6] = {0, 1, 2, 0, 2, 3};
  glVertexPointer(3, GL_FLOAT, 0, pos);
  glEnableClientState(GL_VERTEX_ARRAY);
  glNewList(1, GL_COMPILE);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, idx);
  glEndList();
  glDisableClientState(GL_VERTEX_ARRAY);
  ASSERT_EQ(list(1).meshes.size(), 1u);
  EXPECT_EQ(list(1).meshes[0].positions.size(), 4u);
  EXPECT_TRUE(list(1).meshes[0].array_draw);
}

}  // namespace
