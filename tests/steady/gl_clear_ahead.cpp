// glClear has the tiles that no draw reached since the clear before cleared on a worker
// thread while the program goes on (PipelineContext::clear_ahead), when the caller's buffer
// is the colour buffer. Every frame must come out exactly as where nothing is cleared ahead
// (one thread): a sequence of frames whose drawn parts move (tiles cleared ahead that a draw
// then reaches, tiles drawn before and now left), frames that draw nothing, a new clear
// colour, pixels the caller writes into its buffer between frames, glReadPixels between the
// clear and the draws, a clear through a colour mask, and draws of every size (those of many
// vertices go through the pipeline's threads while the clear may still run).
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

namespace {

constexpr int kW = 333, kH = 217;  // 6 x 4 tiles of 64 pixels, partial ones on two sides
constexpr int kFrames = 24;

void rect(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z), glVertex3f(x1, y0, z), glVertex3f(x1, y1, z), glVertex3f(x0, y1, z);
  glEnd();
}

// A fan of many thin triangles around (cx, cy): a draw of many vertices.
void fan(float cx, float cy, float radius, int n) {
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < n; ++i) {
    const float a0 = 6.2831853f * float(i) / float(n), a1 = 6.2831853f * float(i + 1) / float(n);
    glColor3f(float(i % 7) / 6.0f, float(i % 3) / 2.0f, 0.5f);
    glVertex3f(cx, cy, 0.2f);
    glVertex3f(cx + radius * __builtin_cosf(a0), cy + radius * __builtin_sinf(a0), 0.2f);
    glVertex3f(cx + radius * __builtin_cosf(a1), cy + radius * __builtin_sinf(a1), 0.2f);
  }
  glEnd();
}

// Renders the frames into a context whose pipeline has `threads` threads; returns the
// caller's buffer after each glFinish (and the pixels read back mid-frame).
std::vector<std::vector<std::uint8_t>> render(const char* threads) {
  setenv("SHADELAB_THREADS", threads, 1);  // read when the context's pipeline is made
  std::vector<std::vector<std::uint8_t>> out;
  std::vector<std::uint8_t> buffer(std::size_t(kW) * kH * 4, 7);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kW, kH)) std::exit(2);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0.0, kW, 0.0, kH, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_DEPTH_TEST);
  std::mt19937 rng(12345);
  auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
  for (int frame = 0; frame < kFrames; ++frame) {
    const int kind = frame % 6;
    if (kind == 3) glClearColor(uniform(0, 1), uniform(0, 1), uniform(0, 1), 1.0f);
    if (kind == 5) {  // a masked clear first, then the full one
      glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
      glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    }
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (kind == 2) {  // read back between the clear and the draws
      std::vector<std::uint8_t> read(std::size_t(kW) * kH * 4);
      glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, read.data());
      out.push_back(read);
    }
    if (kind != 4) {  // kind 4 draws nothing
      const int rects = 1 + int(rng() % 3);
      for (int r = 0; r < rects; ++r) {
        const float x = uniform(-20, kW), y = uniform(-20, kH);
        glColor3f(uniform(0, 1), uniform(0, 1), uniform(0, 1));
        rect(x, y, x + uniform(5, 140), y + uniform(5, 100), uniform(-0.9f, 0.9f));
      }
      if (frame % 2) fan(uniform(0, kW), uniform(0, kH), uniform(10, 120), 4000);
    }
    glFinish();
    out.push_back(buffer);
    // The caller writes into its buffer between frames: a row and a column of pixels.
    const int wy = int(rng() % kH), wx = int(rng() % kW);
    std::memset(&buffer[std::size_t(wy) * kW * 4], 200, std::size_t(kW) * 4);
    for (int y = 0; y < kH; ++y) std::memset(&buffer[(std::size_t(y) * kW + std::size_t(wx)) * 4], 90, 4);
  }
  OSMesaDestroyContext(ctx);
  return out;
}

}  // namespace

int main() {
  const std::vector<std::vector<std::uint8_t>> ahead = render("3"), plain = render("1");
  int failures = 0;
  if (ahead.size() != plain.size()) return 2;
  for (std::size_t f = 0; f < ahead.size(); ++f) {
    for (std::size_t i = 0; i < ahead[f].size(); ++i) {
      if (ahead[f][i] != plain[f][i]) {
        const std::size_t px = i / 4;
        std::printf("FAIL picture %zu: byte %zu of pixel (%zu, %zu) is %d with clears ahead, %d without\n", f, i % 4,
                    px % kW, px / kW, ahead[f][i], plain[f][i]);
        ++failures;
        break;
      }
    }
  }
  std::printf("%s\n", failures ? "FAILED" : "every frame as where nothing is cleared ahead");
  return failures ? 1 : 0;
}
