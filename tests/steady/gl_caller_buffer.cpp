// The caller's buffer as the colour buffer (gl/src/present.cpp). In the framebuffer's own
// layout (RGBA bytes, rows from the bottom, no padding) the GL library draws into that buffer
// itself, as classic OSMesa does: what was drawn is there after glFinish, what the caller
// writes into it is what blending and glReadPixels read, a clear left pending reaches it at
// the flush, and depth is kept. Changing the layout with OSMesaPixelStore rewrites the buffer
// in the new one (copied out from then on) and back; rebinding to another buffer makes that
// one the colour buffer; a BGRA context is copied out in its own byte order.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cstdint>
#include <cstdio>
#include <vector>

#include "expect_pixel.hpp"

namespace {

constexpr int kW = 200, kH = 130;  // 4 x 3 tiles of 64 pixels, partial ones on two sides

using Px = std::uint8_t[4];
constexpr Px kBlue{0, 0, 255, 255}, kGreen{0, 255, 0, 255}, kRed{255, 0, 0, 255}, kWhite{255, 255, 255, 255};

// Byte c of pixel (x, y) of a buffer of rows `row_length` pixels long, row 0 at the bottom
// (`y_up`) or at the top.
std::uint8_t* at(std::vector<std::uint8_t>& b, int x, int y, int row_length = kW, bool y_up = true) {
  const int row = y_up ? y : kH - 1 - y;
  return &b[(std::size_t(row) * std::size_t(row_length) + std::size_t(x)) * 4];
}

// The caller's pixel (x, y) in the buffer's layout; `order` names where R, G, B, A lie.
void expect_user(std::vector<std::uint8_t>& b, int x, int y, const Px want, const char* what, int row_length = kW,
                 bool y_up = true, const int order[4] = nullptr) {
  static constexpr int kRgba[4] = {0, 1, 2, 3};
  if (!order) order = kRgba;
  const std::uint8_t* p = at(b, x, y, row_length, y_up);
  for (int c = 0; c < 4; ++c) {
    if (p[order[c]] != want[c]) {
      std::printf("FAIL %s: the caller's pixel (%d, %d) is %d %d %d %d in its byte order, expected %d %d %d %d\n",
                  what, x, y, p[0], p[1], p[2], p[3], want[order[0]], want[order[1]], want[order[2]],
                  want[order[3]]);
      ++steady::failures;
      return;
    }
  }
}

// A quad over pixels [x0, x1) x [y0, y1) at window depth (1 - z) / 2 (glOrtho below).
void rect(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z), glVertex3f(x1, y0, z), glVertex3f(x1, y1, z), glVertex3f(x0, y1, z);
  glEnd();
}

void set_up_view() {
  glViewport(0, 0, kW, kH);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, kW, 0.0, kH, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
}

}  // namespace

int main() {
  std::vector<std::uint8_t> buffer(std::size_t(kW) * kH * 4, 7);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kW, kH)) return 2;
  set_up_view();

  // What the buffer held when bound is the colour buffer's content.
  const Px kSeven{7, 7, 7, 7};
  steady::expect_pixel(150, 100, kSeven, "the buffer's content when bound");

  // A frame: a clear left pending, a green square, a flush.
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(0.0f, 1.0f, 0.0f);
  rect(20, 20, 120, 100, 0.0f);
  glFinish();
  expect_user(buffer, 50, 50, kGreen, "a square drawn");
  expect_user(buffer, kW - 1, kH - 1, kBlue, "the clear, in a tile nothing was drawn into");
  expect_user(buffer, 10, 10, kBlue, "the clear, beside the square");

  // The caller writes into its buffer: glReadPixels and blending read what it wrote.
  std::uint8_t* p = at(buffer, 60, 60);
  p[0] = 255, p[1] = 255, p[2] = 255, p[3] = 255;
  steady::expect_pixel(60, 60, kWhite, "a pixel the caller wrote, read back");
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glColor4f(1.0f, 0.0f, 0.0f, 1.0f);
  rect(55, 55, 65, 65, 0.5f);  // in front: passes GL_LESS
  glDisable(GL_BLEND);
  glFinish();
  const Px kYellow{255, 255, 0, 255};
  expect_user(buffer, 60, 60, kWhite, "red added to the pixel the caller wrote");
  expect_user(buffer, 58, 58, kYellow, "red added to the green square");

  // A clear with nothing drawn after it reaches the buffer at the flush; depth is kept
  // (a square behind the first fails GL_LESS).
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  expect_user(buffer, 50, 50, kBlue, "a colour clear alone");
  glColor3f(1.0f, 0.0f, 0.0f);
  rect(20, 20, 120, 100, -0.5f);
  glFinish();
  expect_user(buffer, 50, 50, kBlue, "a square behind depth kept over a colour clear");

  // Rows from the top: the buffer is rewritten in that layout, and drawing reaches it there.
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(0.0f, 1.0f, 0.0f);
  rect(10, 10, 40, 30, 0.0f);
  glFinish();
  OSMesaPixelStore(OSMESA_Y_UP, 0);
  expect_user(buffer, 20, 20, kGreen, "a square, rows from the top", kW, false);
  expect_user(buffer, 20, kH - 1 - 20, kBlue, "the clear, rows from the top", kW, false);
  glColor3f(1.0f, 0.0f, 0.0f);
  rect(150, 100, 190, 120, 0.0f);
  glFinish();
  expect_user(buffer, 160, 110, kRed, "drawn with rows from the top", kW, false);
  steady::expect_pixel(160, 110, kRed, "drawn with rows from the top, read back");
  steady::expect_pixel(20, 20, kGreen, "drawn before rows from the top, read back");
  OSMesaPixelStore(OSMESA_Y_UP, 1);
  expect_user(buffer, 160, 110, kRed, "rows from the bottom again", kW, true);
  expect_user(buffer, 20, 20, kGreen, "rows from the bottom again, the first square", kW, true);
  glColor3f(1.0f, 1.0f, 1.0f);
  rect(100, 10, 110, 20, 0.0f);
  glFinish();
  expect_user(buffer, 105, 15, kWhite, "drawn with rows from the bottom again");

  // Longer rows: the same buffer seen with 256 pixels a row (the caller's buffer must hold
  // them: rebound to a larger one).
  std::vector<std::uint8_t> wide(std::size_t(256) * kH * 4, 0);
  if (!OSMesaMakeCurrent(ctx, wide.data(), GL_UNSIGNED_BYTE, kW, kH)) return 2;
  OSMesaPixelStore(OSMESA_ROW_LENGTH, 256);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(1.0f, 0.0f, 0.0f);
  rect(180, 100, 200, 130, 0.0f);
  glFinish();
  expect_user(wide, 190, 120, kRed, "rows of 256 pixels", 256);
  expect_user(wide, 10, 120, kBlue, "rows of 256 pixels, the clear", 256);
  const std::uint8_t* pad = &wide[(std::size_t(120) * 256 + 230) * 4];
  if (pad[0] != 0 || pad[1] != 0 || pad[2] != 0 || pad[3] != 0) {
    std::printf("FAIL rows of 256 pixels: the padding after a row was written\n");
    ++steady::failures;
  }
  OSMesaPixelStore(OSMESA_ROW_LENGTH, 0);

  // Bound to another buffer of the same size: that one is the colour buffer now; the first
  // keeps what it had.
  std::vector<std::uint8_t> other(buffer.size(), 0);
  if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kW, kH)) return 2;
  if (!OSMesaMakeCurrent(ctx, other.data(), GL_UNSIGNED_BYTE, kW, kH)) return 2;
  const Px kNothing{0, 0, 0, 0};
  steady::expect_pixel(105, 15, kNothing, "another buffer bound");
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(0.0f, 1.0f, 0.0f);
  rect(0, 0, kW, kH, 0.0f);
  glFinish();
  expect_user(other, 105, 15, kGreen, "drawn into another buffer");
  expect_user(buffer, 105, 15, kWhite, "the first buffer, after another was bound");
  OSMesaDestroyContext(ctx);

  // A BGRA buffer is copied out in its byte order.
  std::vector<std::uint8_t> bgra(buffer.size(), 0);
  OSMesaContext bgra_ctx = OSMesaCreateContextExt(OSMESA_BGRA, 24, 8, 0, nullptr);
  if (!bgra_ctx || !OSMesaMakeCurrent(bgra_ctx, bgra.data(), GL_UNSIGNED_BYTE, kW, kH)) return 2;
  set_up_view();
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(1.0f, 0.0f, 0.0f);
  rect(20, 20, 120, 100, 0.0f);
  glFinish();
  static constexpr int kBgra[4] = {2, 1, 0, 3};
  expect_user(bgra, 50, 50, kRed, "a BGRA buffer, the square", kW, true, kBgra);
  expect_user(bgra, 150, 110, kBlue, "a BGRA buffer, the clear", kW, true, kBgra);
  OSMesaDestroyContext(bgra_ctx);

  std::printf("%s\n", steady::failures ? "FAILED" : "the caller's buffer is the colour buffer");
  return steady::failures ? 1 : 0;
}
