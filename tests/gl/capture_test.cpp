// A frame kept as a scene file (gl/src/capture.hpp, SHADELAB_CAPTURE_SCENE): programs drawn
// through the GL API on an OSMesa context, their frame captured at glFinish, the scene read back
// by the scene reader and rendered by render_scene: it must draw what the program drew, and say
// in its caption what it could not keep.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <GL/shadelab_glut.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"

namespace {

using namespace shadelab;
namespace fs = std::filesystem;
constexpr int kWidth = 96, kHeight = 72;

class CaptureTest : public ::testing::Test {
 protected:
  // The variables are read when the context is made.
  void start(int frame = 1) {
    dir_ = fs::path(SHADELAB_TEST_OUTPUT) / "capture" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    scene_ = (dir_ / "frame.json").string();
    setenv("SHADELAB_CAPTURE_SCENE", scene_.c_str(), 1);
    setenv("SHADELAB_CAPTURE_FRAME", std::to_string(frame).c_str(), 1);
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    unsetenv("SHADELAB_CAPTURE_SCENE");
    unsetenv("SHADELAB_CAPTURE_FRAME");
    ASSERT_NE(ctx_, nullptr);
    ASSERT_TRUE(OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, kWidth, kHeight));
    glEnable(GL_DEPTH_TEST);
  }
  void TearDown() override {
    if (!ctx_) return;
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
  }
  Scene load() {
    LoadResult r = load_scene_file(scene_);
    EXPECT_TRUE(r.scene.has_value()) << r.diagnostics.to_string();
    return r.scene ? *r.scene : Scene{};
  }
  // The share of pixels where the scene's render is within 2/255 of the program's frame.
  double agreement(const Scene& scene) {
    const Image image = render_scene(scene);
    EXPECT_EQ(image.width, kWidth);
    EXPECT_EQ(image.height, kHeight);
    if (image.width != kWidth || image.height != kHeight) return 0.0;
    int close = 0;
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const unsigned char* a = &pixels_[std::size_t((kHeight - 1 - y) * kWidth + x) * 4];  // OSMesa: bottom row first
        const unsigned char* b = &image.rgba[std::size_t(y * kWidth + x) * 4];
        bool ok = true;
        for (int k = 0; k < 3; ++k) ok = ok && std::abs(int(a[k]) - int(b[k])) <= 2;
        close += ok;
      }
    }
    return double(close) / (kWidth * kHeight);
  }
  static void material(float r, float g, float b, float shininess) {
    const GLfloat diffuse[] = {r, g, b, 1}, ambient[] = {r / 4, g / 4, b / 4, 1}, specular[] = {0.6f, 0.6f, 0.6f, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
  }

  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> pixels_ = std::vector<unsigned char>(kWidth * kHeight * 4);
  fs::path dir_;
  std::string scene_;
};

// Two lights (a spot and a directional one), a clockwise teapot with back faces culled, a
// flat-shaded cube and a sphere, seen through a symmetric frustum.
TEST_F(CaptureTest, LitFrameRendersAsTheProgramDrewIt) {
  start();
  glMatrixMode(GL_PROJECTION);
  glFrustum(-0.5 * kWidth / kHeight, 0.5 * kWidth / kHeight, -0.5, 0.5, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(0, 0, -6);
  glEnable(GL_LIGHTING);
  const GLfloat spot_pos[] = {-2, 3, 3, 1}, spot_dir[] = {0.5f, -0.8f, -0.8f}, sun[] = {1, 1, 1, 0};
  const GLfloat blue[] = {0.3f, 0.4f, 1, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, spot_pos);
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, spot_dir);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 40);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 4);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.1f);
  glLightfv(GL_LIGHT2, GL_POSITION, sun);
  glLightfv(GL_LIGHT2, GL_DIFFUSE, blue);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT2);
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  material(0.8f, 0.2f, 0.1f, 50);
  glEnable(GL_CULL_FACE);
  glFrontFace(GL_CW);
  glutSolidTeapot(0.8);
  glFrontFace(GL_CCW);
  glDisable(GL_CULL_FACE);
  glPushMatrix();
  glTranslatef(-1.7f, 0.2f, 0);
  glRotatef(30, 1, 1, 0);
  material(0.2f, 0.8f, 0.3f, 10);
  glShadeModel(GL_FLAT);
  glutSolidCube(0.9);
  glShadeModel(GL_SMOOTH);
  glPopMatrix();
  glTranslatef(1.7f, 0, 0);
  material(0.9f, 0.8f, 0.2f, 90);
  glutSolidSphere(0.6, 24, 12);
  glFinish();

  const Scene s = load();
  ASSERT_EQ(s.objects.size(), 3u);
  ASSERT_EQ(s.lights.size(), 3u);  // GL_LIGHT0 .. GL_LIGHT2, light 1 off
  EXPECT_TRUE(s.lights[0].light.enabled && !s.lights[1].light.enabled && s.lights[2].light.enabled);
  EXPECT_TRUE(s.lights[0].eye_space);
  EXPECT_FLOAT_EQ(s.lights[0].light.spot_cutoff, 40);
  EXPECT_FLOAT_EQ(s.lights[0].light.linear_attenuation, 0.1f);
  EXPECT_FALSE(s.camera.matrix.has_value()) << "a symmetric frustum is a field of view";
  EXPECT_EQ(s.objects[0].cull, CullMode::kBack);
  EXPECT_EQ(s.objects[1].shading, ShadingMode::kFlat);
  EXPECT_NEAR(s.objects[2].front.shininess, 90, 1e-4);
  EXPECT_NE(s.caption.find("captured by shadelab"), std::string::npos);
  EXPECT_GE(agreement(s), 0.99);
}

// Colour material with a colour per triangle: one object per colour; an unlit triangle keeps
// its vertex colours; an asymmetric frustum is kept as the matrix.
TEST_F(CaptureTest, ColourMaterialUnlitColoursAndAnAsymmetricFrustum) {
  start();
  glMatrixMode(GL_PROJECTION);
  glFrustum(-0.4, 1.0, -0.5, 0.5, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glNormal3f(0, 0, 1);
  glColor3f(1, 0, 0);
  glVertex3f(-1, -1, -3), glVertex3f(0, -1, -3), glVertex3f(-0.5f, 0, -3);
  glColor3f(0, 1, 0);
  glNormal3f(0.3f, 0, 1);
  glVertex3f(0, -1, -3), glVertex3f(1, -1, -3), glVertex3f(0.5f, 0, -3);
  glEnd();
  glDisable(GL_LIGHTING);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 1, 0), glVertex3f(-1, 0.2f, -4);
  glColor3f(0, 1, 1), glVertex3f(1, 0.2f, -4);
  glColor3f(1, 0, 1), glVertex3f(0, 1.2f, -4);
  glEnd();
  glBegin(GL_LINES);  // not a scene's: counted in the caption
  glVertex3f(-1, 1, -3), glVertex3f(1, 1, -3);
  glEnd();
  glFinish();

  const Scene s = load();
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_NEAR(s.objects[0].front.diffuse.r, 1, 1e-6);
  EXPECT_NEAR(s.objects[1].front.diffuse.g, 1, 1e-6);
  EXPECT_FALSE(s.objects[2].lighting);
  ASSERT_EQ(s.objects[2].mesh->colors.size(), 3u);
  EXPECT_TRUE(s.camera.matrix.has_value()) << "an asymmetric frustum is kept as its matrix";
  EXPECT_NE(s.caption.find("1 line segment"), std::string::npos) << s.caption;
  EXPECT_GE(agreement(s), 0.99);
}

// Textured draws: unit 0's texture is written as a PNG beside the scene, with the draw's
// texture coordinates, filter and environment (a lit, modulated quad and an unlit, replaced one).
TEST_F(CaptureTest, TexturedDrawsKeepTheirTexture) {
  start();
  std::vector<GLubyte> checker(16 * 8 * 4);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) {
      GLubyte* p = &checker[std::size_t(y * 16 + x) * 4];
      const bool on = ((x / 2) + (y / 2)) % 2 == 0;
      p[0] = on ? 250 : 30, p[1] = GLubyte(x * 16), p[2] = GLubyte(y * 32), p[3] = 255;
    }
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker.data());
  glEnable(GL_TEXTURE_2D);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-0.5 * kWidth / kHeight, 0.5 * kWidth / kHeight, -0.5, 0.5, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBegin(GL_QUADS);  // lit, the texture repeated twice across
  glNormal3f(0, 0, 1);
  glTexCoord2f(0, 0), glVertex3f(-1.4f, -1, -3);
  glTexCoord2f(2, 0), glVertex3f(-0.1f, -1, -3);
  glTexCoord2f(2, 2), glVertex3f(-0.1f, 1, -3);
  glTexCoord2f(0, 2), glVertex3f(-1.4f, 1, -3);
  glEnd();
  glDisable(GL_LIGHTING);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glRectf(0.1f, -0.3f, 0.9f, 0.3f);  // glRect: texture coordinates (0, 0) everywhere
  glBegin(GL_TRIANGLES);
  glTexCoord2f(0, 0), glVertex3f(0.1f, 0.4f, -2.5f);
  glTexCoord2f(1, 0), glVertex3f(1.0f, 0.4f, -2.5f);
  glTexCoord2f(0.5f, 1), glVertex3f(0.5f, 1.0f, -2.5f);
  glEnd();
  glFinish();

  const Scene s = load();
  ASSERT_EQ(s.objects.size(), 2u);
  for (const SceneObject& o : s.objects) {
    ASSERT_TRUE(o.texture) << o.name;
    EXPECT_EQ(o.texture->levels[0].width, 16);
    EXPECT_EQ(o.texture->levels[0].height, 8);
  }
  EXPECT_EQ(s.objects[0].texture_env, TextureEnvMode::kModulate);
  EXPECT_EQ(s.objects[1].texture_env, TextureEnvMode::kReplace);
  EXPECT_TRUE(fs::exists(dir_ / "frame-texture-1.png"));
  EXPECT_GE(agreement(s), 0.99);
}

// SHADELAB_CAPTURE_FRAME=2: the second glFinish's frame, from its last full colour clear.
TEST_F(CaptureTest, TheChosenFrameFromItsLastClear) {
  start(2);
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1, 1, -1, 1, -1, 1);  // near -1: no scene camera has it, so the matrix
  glMatrixMode(GL_MODELVIEW);
  auto quad = [](float r, float g, float b) {
    glColor3f(r, g, b);
    glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
  };
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  quad(1, 0, 0);
  glFinish();  // frame 1: red
  EXPECT_FALSE(fs::exists(scene_));
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  quad(0, 0, 1);
  glClearColor(0, 0.5f, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);  // what was drawn before is gone
  quad(0, 1, 0);
  glFinish();  // frame 2: green on dark green

  const Scene s = load();
  EXPECT_TRUE(s.camera.matrix.has_value());
  ASSERT_EQ(s.objects.size(), 1u);
  ASSERT_FALSE(s.objects[0].mesh->colors.empty());
  EXPECT_EQ(s.objects[0].mesh->colors[0], glm::vec4(0, 1, 0, 1));
  EXPECT_NEAR(s.background.g, 0.5f, 1e-6);
  EXPECT_NE(s.caption.find("Frame 2 of"), std::string::npos);
  EXPECT_GE(agreement(s), 0.99);
}

}  // namespace
