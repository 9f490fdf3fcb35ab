// glClear seen in order by everything that reads the framebuffer: pixels read back after
// clears that no draw follows, a clear through a colour mask after a full clear, a depth-only
// clear between two draws, OSMesaGetDepthBuffer, and the caller's buffer after glFinish.
// (A front end that defers clears to the next draw, as llvmpipe does, must keep these.)
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cstdint>
#include <cstdio>
#include <vector>

#include "expect_pixel.hpp"

namespace {

constexpr int kW = 150, kH = 90;  // partial tiles on two sides
using steady::expect_pixel;
using steady::failures;

void quad(float z) {
  glBegin(GL_QUADS);
  glVertex3f(-0.5f, -0.5f, z), glVertex3f(0.5f, -0.5f, z), glVertex3f(0.5f, 0.5f, z), glVertex3f(-0.5f, 0.5f, z);
  glEnd();
}

}  // namespace

int main() {
  std::vector<unsigned char> buffer(std::size_t(kW) * kH * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kW, kH)) return 2;
  glViewport(0, 0, kW, kH);
  const std::uint8_t red[4] = {255, 0, 0, 255}, blue[4] = {0, 0, 255, 255}, green[4] = {0, 255, 0, 255};

  // A clear that no draw follows, read back (the far corner: a partial tile).
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  expect_pixel(kW - 1, kH - 1, red, "clear, then glReadPixels");

  // A full clear, then a clear through a colour mask: both, in order.
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
  glClearColor(1.0f, 1.0f, 1.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const std::uint8_t magenta[4] = {255, 0, 255, 255};
  expect_pixel(3, 3, magenta, "full clear, then a masked clear");

  // Clear, draw a green quad in the middle: cleared outside, green inside.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(0.0f, 1.0f, 0.0f);
  quad(0.0f);
  expect_pixel(kW / 2, kH / 2, green, "clear, then a draw (inside)");
  expect_pixel(1, kH - 2, blue, "clear, then a draw (outside)");

  // A depth-only clear to 0 between two draws: a red quad then fails GL_LESS everywhere.
  glClearDepth(0.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glColor3f(1.0f, 0.0f, 0.0f);
  quad(-0.5f);
  expect_pixel(kW / 2, kH / 2, green, "depth clear to 0, then a draw that fails the test");

  // A depth clear seen by OSMesaGetDepthBuffer (24-bit depth in the low bits).
  glClearDepth(0.5);
  glClear(GL_DEPTH_BUFFER_BIT);
  GLint w = 0, h = 0, bytes = 0;
  void* depth = nullptr;
  if (!OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &depth) || bytes != 4 || !depth) {
    std::printf("FAIL OSMesaGetDepthBuffer\n");
    ++failures;
  } else {
    const std::uint32_t d = static_cast<const std::uint32_t*>(depth)[std::size_t(w) * std::size_t(h) - 1] & 0xffffffu;
    if (d < 0x7fff00u || d > 0x800100u) {
      std::printf("FAIL depth clear to 0.5 read as %u of 16777215\n", unsigned(d));
      ++failures;
    }
  }

  // glFinish copies a clear into the caller's buffer.
  glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  const unsigned char* last = &buffer[(std::size_t(kW) * kH - 1) * 4];
  if (last[0] != 0 || last[1] != 255 || last[2] != 0) {
    std::printf("FAIL clear, then glFinish: the caller's buffer has %d %d %d\n", last[0], last[1], last[2]);
    ++failures;
  }
  OSMesaDestroyContext(ctx);
  std::printf("%s\n", failures ? "FAILED" : "all clears seen in order");
  return failures ? 1 : 0;
}
