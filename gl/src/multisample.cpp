// Multisampling (GL 1.3; GL 1.5 sections 3.2.1, 3.3.3-3.5.6 and 4.1.3, 4.1.10): glSampleCoverage
// and the multisample buffer of a visual with samples (GLX and EGL configurations with
// GLX_SAMPLES / EGL_SAMPLES 4).
//
// Each drawing is drawn once per sample into that sample's colour, depth and stencil (the
// pass exchanges them into the framebuffer, enter_sample), its geometry shifted so that the
// sample's position in every pixel lies on the pixel's centre: the pipeline then decides
// coverage, depth and stencil at the sample's position, as section 3.2.1 asks, and evaluates
// colour and texture coordinates there too (allowed: "at any location within the pixel",
// section 3.5.6). Pixel rectangles (glDrawPixels, glBitmap, glCopyPixels) and glAccum's
// GL_RETURN write every sample of the pixels they cover, unshifted; glClear clears every
// sample. The colour buffer holds the resolved colour, the mean of the samples' colours
// (section 4.1.10), brought up to date, tile by tile, for the tiles drawn since, before
// anything reads it.
//
// With GL_MULTISAMPLE off, every sample of a pixel takes the pixel's own fragment (section
// 3.2.1: single-sample rasterization, full coverage). With it on, points are discs of their
// size (squares as sprites) and lines rectangles of their width, whatever GL_POINT_SMOOTH and
// GL_LINE_SMOOTH say (sections 3.3.3, 3.4.4; the core's multisample point and line), points
// below GL_POINT_FADE_THRESHOLD_SIZE fade, GL_SAMPLE_COVERAGE leaves out the samples
// glSampleCoverage's mask clears, GL_SAMPLE_ALPHA_TO_COVERAGE covers a sample only where the
// fragment's alpha exceeds the sample's threshold ((k + 0.5) / samples), and
// GL_SAMPLE_ALPHA_TO_ONE makes the alpha 1 (sample_fragment_state).
// The enables are glEnable capabilities (state.cpp); GL_MULTISAMPLE_BIT is attrib.cpp's.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {
namespace {

// The sample positions within a pixel, GL window coordinates (y up): the usual four
// (Direct3D's, and llvmpipe's for the framebuffers it does multisample), whose y those measure
// from the top.
constexpr std::array<glm::vec2, 4> kPositions4{{{0.375f, 0.875f}, {0.875f, 0.625f}, {0.125f, 0.375f}, {0.625f, 0.125f}}};

// Whether the alpha test passes an alpha of 1 (compared as the pipeline compares, in 8 bits).
bool passes_at_one(const AlphaTestState& a) {
  const long ref = std::lround(std::clamp(a.ref, 0.0f, 1.0f) * 255.0f);
  switch (a.func) {
    case CompareFunc::kNever: return false;
    case CompareFunc::kLess: return 255 < ref;
    case CompareFunc::kEqual: return ref == 255;
    case CompareFunc::kLequal: return 255 <= ref;
    case CompareFunc::kGreater: return 255 > ref;
    case CompareFunc::kNotequal: return ref != 255;
    case CompareFunc::kGequal: case CompareFunc::kAlways: return true;
  }
  return true;
}

// Makes the buffers for the framebuffer's size when they are missing or of another size,
// holding what the framebuffer holds: every sample the pixel's colour, depth and stencil.
void make_sample_buffers(GlContext& c) {
  SampleBuffers& s = c.ms;
  if (s.width == c.fb.width && s.height == c.fb.height && s.color.size() == std::size_t(s.count)) return;
  s.width = c.fb.width, s.height = c.fb.height;
  s.color.assign(std::size_t(s.count), c.fb.color);
  s.depth.assign(std::size_t(s.count - 1), c.fb.depth);
  s.stencil.assign(std::size_t(s.count - 1), c.fb.stencil);
  s.unresolved.assign(c.tiles.flags.size(), 0);
  s.any_unresolved = false;
}

// Exchanges sample k's buffers with the framebuffer's (the same call puts them back).
void exchange_sample(GlContext& c, int k) {
  SampleBuffers& s = c.ms;
  std::swap(c.fb.color, s.color[std::size_t(k)]);
  if (k == 0) return;
  c.fb.depth.swap(s.depth[std::size_t(k - 1)]);
  c.fb.stencil.swap(s.stencil[std::size_t(k - 1)]);
}

// The waiting draws rasterized and the pending clears applied, into the buffers in fb now.
void finish_pass(GlContext& c) {
  if (c.pipeline) c.pipeline->apply_pending_clears(c.fb);
}

}  // namespace

void enter_sample(GlContext& c, int k) {
  finish_pass(c);
  make_sample_buffers(c);
  exchange_sample(c, k);
  c.ms.active = k;
  c.ms.shift = glm::vec2(0.0f);
  if (c.multisample.enabled) c.ms.shift = glm::vec2(0.5f) - kPositions4[std::size_t(k)];
}

void leave_sample(GlContext& c) {
  finish_pass(c);
  exchange_sample(c, c.ms.active);
  c.ms.active = -1;
  c.ms.shift = glm::vec2(0.0f);
}

unsigned sample_mask(const GlContext& c) {
  const unsigned all = (1u << c.ms.count) - 1u;
  const MultisampleState& m = c.multisample;
  if (!m.enabled || !m.coverage) return all;
  // Section 4.1.3 leaves the mask to the implementation: as Mesa makes it, value * samples
  // bits (truncated), the first samples; inverted with `invert`.
  const int n = std::clamp(int(m.coverage_value * float(c.ms.count)), 0, c.ms.count);
  const unsigned mask = (1u << n) - 1u;
  return m.coverage_invert ? ~mask & all : mask;
}

void sample_fragment_state(const GlContext& c, FragmentState& f) {
  // Sections 3.3.3 and 3.4.4: points are discs (squares as sprites), lines rectangles, their
  // smooth enables ignored; points below the fade threshold drawn at its size, faded.
  f.line.smooth = false;
  f.point.smooth = false;
  f.line.multisample = true;
  f.point.multisample = true;
  f.point.fade_threshold = c.prims.point_fade;
  AlphaTestState& a = f.alpha_test;
  if (c.multisample.alpha_to_one) {
    // Section 4.1.3: the alpha is 1 after the coverage is taken from it, so the alpha test
    // (section 4.1.4) compares 1 with its reference: it passes every fragment or none.
    f.alpha_one = true;
    if (a.enabled) a = AlphaTestState{!passes_at_one(a), CompareFunc::kNever, 0.0f};
  }
  if (!c.multisample.alpha_to_coverage) return;
  // Section 4.1.3: the fragment's alpha becomes a coverage mask; here sample k is covered
  // where alpha > (k + 0.5) / samples (alpha 1 covers them all, alpha 0 none), checked with
  // the alpha test (section 4.1.4, after it) on the same alpha.
  if (!a.enabled) a = AlphaTestState{true, CompareFunc::kAlways, 0.0f};
  a.floor = (float(c.ms.active) + 0.5f) / float(c.ms.count);
}

glm::mat4 sample_projection(const GlContext& c, const glm::mat4& projection) {
  const Viewport& vp = c.raster.viewport;
  if (c.ms.active < 0 || c.ms.shift == glm::vec2(0.0f) || vp.width <= 0 || vp.height <= 0) return projection;
  // A window-space shift d is a shift of 2 d / size in normalized device coordinates, which
  // is w times that in clip coordinates.
  glm::mat4 shift(1.0f);
  shift[3][0] = 2.0f * c.ms.shift.x / float(vp.width);
  shift[3][1] = 2.0f * c.ms.shift.y / float(vp.height);
  return shift * projection;
}

void resolve_samples(GlContext& c) {
  SampleBuffers& s = c.ms;
  if (!s.any_unresolved || s.active >= 0) return;
  s.any_unresolved = false;
  finish_pass(c);
  if (s.width != c.fb.width || s.height != c.fb.height || s.unresolved.size() != c.tiles.flags.size()) return;
  std::swap(c.tiles.list, s.list);
  c.tiles.list.clear();
  for (std::size_t t = 0; t < s.unresolved.size(); ++t) {
    if (s.unresolved[t]) c.tiles.list.push_back(int(t)), s.unresolved[t] = 0;
  }
  const std::size_t width = std::size_t(c.fb.width);
  const std::uint8_t *a = s.color[0].data(), *b = s.color[1].data(), *d = s.color[2].data(), *e = s.color[3].data();
  for_listed_tiles(c, [&](int x0, int y0, int x1, int y1) {
    std::uint8_t* out = c.fb.color.data();
    for (int y = y0; y < y1; ++y) {
      const std::size_t begin = (std::size_t(y) * width + std::size_t(x0)) * 4, end = (std::size_t(y) * width + std::size_t(x1)) * 4;
      // The four samples' mean, rounded to the nearest, in a loop the compiler vectorizes.
      for (std::size_t i = begin; i < end; ++i) out[i] = std::uint8_t((unsigned(a[i]) + b[i] + d[i] + e[i] + 2u) >> 2);
    }
  });
  std::swap(c.tiles.list, s.list);
}

void resolve_into_both_buffers(GlContext& c) {
  SampleBuffers& s = c.ms;
  std::vector<std::uint8_t> drawn = s.unresolved;
  const bool any = s.any_unresolved;
  resolve_samples(c);
  exchange_color_buffers(c);
  s.unresolved.swap(drawn);
  s.any_unresolved = any;
  resolve_samples(c);
  exchange_color_buffers(c);
}

// The value is clamped to [0, 1] (a NaN becomes 0, as Mesa's CLAMP makes it).
void exec::SampleCoverage(GlContext& c, GLfloat value, GLboolean invert) {
  c.multisample.coverage_value = value > 0.0f ? std::min(value, 1.0f) : 0.0f;
  c.multisample.coverage_invert = invert != GL_FALSE;
}

}  // namespace shadelab::gl
