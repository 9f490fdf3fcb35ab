// Frames that clear the whole buffer and draw into a part of it, as most programs do. The GL
// library leaves alone the tiles that still hold the last clear's value and copies into the
// caller's buffer only what changed (gl/src/context.hpp, TileMap); every frame must still
// come out as if everything had been cleared and copied: parts drawn in the frame before are
// cleared again (colour and depth), pixels the caller wrote into its own buffer are cleared
// (in Mesa, glClear writes that buffer), a new clear colour reaches every pixel, a clear
// through a colour mask is followed by a full clear that writes every pixel again, and a
// depth clear left to the next draw (PipelineContext::PendingClears) survives binding the
// context to another buffer.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

namespace {

constexpr int kW = 300, kH = 200;  // 5 x 4 tiles of 64 pixels, partial ones on two sides
int failures = 0;
std::vector<unsigned char> buffer(std::size_t(kW) * kH * 4);

struct Rgb {
  int r, g, b;
};
constexpr Rgb kBlue{0, 0, 255}, kGreen{0, 255, 0}, kRed{255, 0, 0}, kYellow{255, 255, 0};

// The caller's buffer after glFinish (row 0 is the bottom row, OSMesa's default).
void expect_user(int x, int y, Rgb want, const char* what) {
  const unsigned char* p = &buffer[(std::size_t(y) * kW + std::size_t(x)) * 4];
  if (p[0] != want.r || p[1] != want.g || p[2] != want.b) {
    std::printf("FAIL %s: the caller's pixel (%d, %d) is %d %d %d, expected %d %d %d\n", what, x, y, p[0], p[1],
                p[2], want.r, want.g, want.b);
    ++failures;
  }
}

void expect_depth(int x, int y, float want, const char* what) {
  float got = -1.0f;
  glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &got);
  if (got < want - 1e-6f || got > want + 1e-6f) {
    std::printf("FAIL %s: depth at (%d, %d) is %g, expected %g\n", what, x, y, double(got), double(want));
    ++failures;
  }
}

// A quad over pixels [x0, x1) x [y0, y1) at window depth (1 - z) / 2 (glOrtho below).
void rect(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z), glVertex3f(x1, y0, z), glVertex3f(x1, y1, z), glVertex3f(x0, y1, z);
  glEnd();
}

void clear(float r, float g, float b) {
  glClearColor(r, g, b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

}  // namespace

int main() {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kW, kH)) return 2;
  glViewport(0, 0, kW, kH);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0.0, kW, 0.0, kH, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClearDepth(1.0);

  // Frame 1: a green square on the left.
  clear(0.0f, 0.0f, 1.0f);
  glColor3f(0.0f, 1.0f, 0.0f);
  rect(10, 10, 60, 60, 0.0f);
  glFinish();
  expect_user(30, 30, kGreen, "frame 1, inside the square");
  expect_user(250, 150, kBlue, "frame 1, outside it");

  // The caller writes into its buffer between frames, where no frame draws.
  std::memset(&buffer[(std::size_t(190) * kW + 290) * 4], 255, 4);

  // Frame 2: the same clear, a green square on the right only.
  clear(0.0f, 0.0f, 1.0f);
  rect(200, 120, 260, 180, 0.0f);
  glFinish();
  expect_user(30, 30, kBlue, "frame 2, where frame 1 drew");
  expect_user(230, 150, kGreen, "frame 2, its own square");
  expect_user(290, 190, kBlue, "frame 2, the pixel the caller wrote");
  expect_depth(30, 30, 1.0f, "frame 2, where frame 1 drew");
  expect_depth(230, 150, 0.5f, "frame 2, its own square");

  // Depth cleared again where frame 2 wrote it: a red square behind the green one passes
  // GL_LESS in a new frame.
  clear(0.0f, 0.0f, 1.0f);
  glColor3f(1.0f, 0.0f, 0.0f);
  rect(200, 120, 260, 180, -0.5f);
  glFinish();
  expect_user(230, 150, kRed, "frame 3, a square where depth was written before");

  // A new clear colour reaches every pixel.
  clear(1.0f, 1.0f, 0.0f);
  glFinish();
  expect_user(0, 0, kYellow, "new clear colour, first pixel");
  expect_user(kW - 1, kH - 1, kYellow, "new clear colour, last pixel");
  expect_user(230, 150, kYellow, "new clear colour, where frame 3 drew");

  // A clear through a colour mask, then a full clear with the colour before it.
  clear(0.0f, 0.0f, 1.0f);
  glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glFinish();
  expect_user(100, 100, Rgb{255, 0, 255}, "a clear through a colour mask");
  clear(0.0f, 0.0f, 1.0f);
  glFinish();
  expect_user(100, 100, kBlue, "a full clear after a masked one");
  expect_user(kW - 1, 0, kBlue, "a full clear after a masked one, a partial tile");

  // A depth clear, then the context bound to another buffer of the same size (depth is
  // kept): a square behind one drawn before the clear passes GL_LESS.
  clear(0.0f, 0.0f, 1.0f);
  glColor3f(0.0f, 1.0f, 0.0f);
  rect(100, 50, 160, 110, 0.0f);
  glFinish();
  glClear(GL_DEPTH_BUFFER_BIT);
  std::vector<unsigned char> other(buffer.size());
  if (!OSMesaMakeCurrent(ctx, other.data(), GL_UNSIGNED_BYTE, kW, kH)) return 2;
  glColor3f(1.0f, 0.0f, 0.0f);
  rect(100, 50, 160, 110, -0.5f);
  glFinish();
  const unsigned char* p = &other[(std::size_t(80) * kW + 130) * 4];
  if (p[0] != 255 || p[1] != 0 || p[2] != 0) {
    std::printf("FAIL a depth clear before rebinding: pixel (130, 80) is %d %d %d, expected 255 0 0\n", p[0], p[1], p[2]);
    ++failures;
  }

  OSMesaDestroyContext(ctx);
  std::printf("%s\n", failures ? "FAILED" : "every frame as if wholly cleared and copied");
  return failures ? 1 : 0;
}
