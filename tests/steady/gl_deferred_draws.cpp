// libshadelab-gl draws deferred (PipelineContext::set_deferred): a frame's draws are set up
// when made and rasterized tile by tile when something reads the framebuffer. What a
// program sees must not change: client arrays rewritten right after glDrawElements, a
// stencil clear between stencil draws, more draws than the queue holds, depth read back
// before glFinish, draws with and without a texture interleaved, and textures and the
// texture environment changed or deleted while textured draws wait.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cstdint>
#include <cstdio>
#include <vector>

#include "expect_pixel.hpp"

namespace {

constexpr int kW = 200, kH = 140;  // several tiles, partial ones on two sides
using steady::expect_pixel;
using steady::failures;

void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z), glVertex3f(x1, y0, z), glVertex3f(x1, y1, z), glVertex3f(x0, y1, z);
  glEnd();
}

}  // namespace

int main() {
  std::vector<unsigned char> buffer(std::size_t(kW) * kH * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kW, kH)) return 2;
  glViewport(0, 0, kW, kH);
  const std::uint8_t black[4] = {0, 0, 0, 255}, red[4] = {255, 0, 0, 255}, green[4] = {0, 255, 0, 255},
                     blue[4] = {0, 0, 255, 255};
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);

  // Client arrays and indices rewritten right after glDrawElements, before anything reads
  // the framebuffer: the draw keeps what they held when it was made.
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  {
    GLfloat positions[] = {-1.0f, -1.0f, 0.0f, 0.0f, -1.0f, 0.0f, 0.0f, 1.0f, 0.0f, -1.0f, 1.0f, 0.0f};
    GLfloat colors[] = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
    GLuint indices[] = {0, 1, 2, 0, 2, 3};
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glColorPointer(4, GL_FLOAT, 0, colors);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, indices);  // the left half, red
    for (GLfloat& c : colors) c = 0.0f;
    for (GLuint& i : indices) i = 0;
    for (int v = 0; v < 4; ++v) positions[v * 3] += 1.0f;  // now the right half, black
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
  }
  expect_pixel(kW / 4, kH / 2, red, "glDrawElements, then its arrays rewritten (left half)");
  expect_pixel(3 * kW / 4, kH / 2, black, "glDrawElements, then its arrays rewritten (right half)");

  // A stencil clear between a draw that writes the stencil and one that tests it.
  glEnable(GL_STENCIL_TEST);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColor3f(0.0f, 0.0f, 1.0f);
  quad(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f);  // blue everywhere, stencil 1
  glClear(GL_STENCIL_BUFFER_BIT);        // stencil 0 again
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glColor3f(1.0f, 0.0f, 0.0f);
  quad(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f);  // passes nowhere
  glDisable(GL_STENCIL_TEST);
  expect_pixel(kW / 2, kH / 2, blue, "a stencil clear between two stencil draws");

  // More draws than wait at once: 300 overlapping quads, each a shade of its own; the last
  // one drawn shows where all overlap.
  glClear(GL_COLOR_BUFFER_BIT);
  for (int i = 0; i < 300; ++i) {
    glColor3ub(GLubyte(i % 256), GLubyte(i / 256 * 100), 7);
    const float s = 0.2f + 0.002f * float(i);
    quad(-s, -s, s, s, 0.0f);
  }
  const std::uint8_t last[4] = {GLubyte(299 % 256), GLubyte(299 / 256 * 100), 7, 255};
  expect_pixel(kW / 2, kH / 2, last, "300 overlapping draws");
  const std::uint8_t edge[4] = {GLubyte(299 % 256), GLubyte(299 / 256 * 100), 7, 255};
  expect_pixel(int(kW * 0.5f * (1.0f + 0.79f)), kH / 2, edge, "300 overlapping draws (the largest)");

  // Depth read back before glFinish: the draw's depth, not the clear's.
  glEnable(GL_DEPTH_TEST);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(0.0f, 1.0f, 0.0f);
  quad(-0.5f, -0.5f, 0.5f, 0.5f, 0.0f);  // window depth 0.5
  GLfloat depth = -1.0f;
  glReadPixels(kW / 2, kH / 2, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  if (!(depth > 0.49f && depth < 0.51f)) {
    std::printf("FAIL depth read back after a draw: %g, expected 0.5\n", double(depth));
    ++failures;
  }

  // A textured draw (drawn at once) between two deferred ones, then its texture replaced:
  // each draw in its order, with the texture it was drawn with.
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  const GLubyte white_texel[4] = {255, 255, 255, 255}, black_texel[4] = {0, 0, 0, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white_texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glColor3f(1.0f, 0.0f, 0.0f);
  quad(-1.0f, -1.0f, 0.0f, 1.0f, 0.0f);  // left: red
  glEnable(GL_TEXTURE_2D);
  glColor3f(0.0f, 1.0f, 0.0f);
  glBegin(GL_QUADS);  // middle: green modulated by white
  glTexCoord2f(0.5f, 0.5f);
  glVertex3f(-0.5f, -1.0f, 0.0f), glVertex3f(0.5f, -1.0f, 0.0f), glVertex3f(0.5f, 1.0f, 0.0f), glVertex3f(-0.5f, 1.0f, 0.0f);
  glEnd();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, black_texel);
  glDisable(GL_TEXTURE_2D);
  glColor3f(0.0f, 0.0f, 1.0f);
  quad(0.25f, -1.0f, 1.0f, 1.0f, 0.0f);  // right: blue
  glFinish();
  const unsigned char* row = &buffer[std::size_t(kH / 2) * kW * 4];
  const std::uint8_t* want[3] = {red, green, blue};
  const int xs[3] = {kW / 8, int(kW * 0.6f), 7 * kW / 8};
  for (int k = 0; k < 3; ++k) {
    const unsigned char* p = row + std::size_t(xs[k]) * 4;
    if (p[0] != want[k][0] || p[1] != want[k][1] || p[2] != want[k][2]) {
      std::printf("FAIL draws around a textured one: the caller's buffer has %d %d %d at x = %d\n", p[0], p[1], p[2], xs[k]);
      ++failures;
    }
  }
  // Textured draws wait too (their textures are kept): a texture changed after a draw
  // (glTexSubImage2D, glTexParameter, a new image), the environment colour changed, and the
  // texture deleted, each before anything reads the framebuffer: every draw with what it was
  // drawn with.
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_TEXTURE_2D);
  GLuint kept = 0;
  glGenTextures(1, &kept);
  glBindTexture(GL_TEXTURE_2D, kept);
  const GLubyte two_texels[8] = {0, 0, 255, 255, 255, 255, 0, 255};  // blue, yellow
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, two_texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  auto textured_column = [](float x0, float x1, float s) {
    glBegin(GL_QUADS);
    glTexCoord2f(s, 0.5f);
    glVertex2f(x0, -1.0f), glVertex2f(x1, -1.0f), glVertex2f(x1, 1.0f), glVertex2f(x0, 1.0f);
    glEnd();
  };
  textured_column(-1.0f, -0.6f, 0.25f);  // blue (texel 0)
  const GLubyte red_texel[4] = {255, 0, 0, 255};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red_texel);
  textured_column(-0.6f, -0.2f, 0.25f);  // red (texel 0 replaced)
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
  textured_column(-0.2f, 0.2f, 0.5f);  // halfway between red and yellow
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
  const GLfloat env_green[4] = {0.0f, 1.0f, 0.0f, 1.0f}, env_black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_green);
  glColor3f(0.0f, 0.0f, 0.0f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  textured_column(0.2f, 0.6f, 0.75f);  // black fragment blended toward green by yellow: (0, 1, 0)
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_black);
  glDeleteTextures(1, &kept);  // the default texture (no image) is bound now
  glDisable(GL_TEXTURE_2D);
  glColor3f(1.0f, 1.0f, 1.0f);
  quad(0.6f, -1.0f, 1.0f, 1.0f, 0.0f);  // white
  const std::uint8_t half[4] = {255, 128, 0, 255}, white[4] = {255, 255, 255, 255};
  const std::uint8_t* kept_want[5] = {blue, red, half, green, white};
  for (int k = 0; k < 5; ++k) {
    const int x = int(kW * (0.1f + 0.2f * float(k)));
    const char* what[5] = {"a textured draw before glTexSubImage2D", "after glTexSubImage2D",
                           "after glTexParameter", "GL_BLEND before the environment colour changed",
                           "an untextured draw after glDeleteTextures"};
    expect_pixel(x, kH / 2, kept_want[k], what[k]);
  }

  OSMesaDestroyContext(ctx);
  std::printf("%s\n", failures ? "FAILED" : "deferred draws seen in order");
  return failures ? 1 : 0;
}
