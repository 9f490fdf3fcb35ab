// draw_fragments: GL's per-fragment operations on a rectangle of window-space fragments that
// no primitive made (glDrawPixels, glCopyPixels and glBitmap's fragments, GL 1.1 sections
// 3.6.4, 3.6.5 and 3.7): texturing, fog, scissor, alpha test, stencil, depth, blending or
// logic op, colour mask. The reference's operations, fragment by fragment; no rasterizing.
#include <algorithm>
#include <atomic>
#include <cstdint>

#include "pipeline/fragment_ops.hpp"
#include "pipeline/stages.hpp"

namespace shadelab {

namespace {

using detail::Fragment;

struct RectJob {
  Framebuffer* fb;
  const FragmentState* fragment;
  const ShadeState* shade;  // lighting off, an incomplete texture dropped
  const FragmentRect* rect;
  int x0, x1;  // the columns inside the framebuffer
};

// The fragment at pixel (x, y), rectangle index i, as the rasterizer would hand it over.
Fragment make_fragment(const FragmentRect& r, int x, int y, std::size_t i) {
  Fragment f;
  f.x = x;
  f.y = y;
  const float z = r.depths.empty() ? r.depth : r.depths[i];
  f.z = z > 0.0f ? (z < 1.0f ? z : 1.0f) : 0.0f;  // window depth clamped (NaN to 0)
  f.attr.fill(0.0f);
  const glm::vec4 c = r.colors.size() == 1 ? r.colors[0] : r.colors[i];
  for (int k = 0; k < 4; ++k) f.attr[detail::kFrontColor + k] = f.attr[detail::kBackColor + k] = c[k];
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    for (int k = 0; k < 4; ++k) f.attr[std::size_t(detail::kTexCoord + 4 * u + k)] = r.texcoords[std::size_t(u)][k];
  }
  f.attr[detail::kFogCoord] = r.fog_coord;
  return f;  // texture derivatives zero: the magnification filter
}

// One fragment through the operations, in draw.cpp's order. Returns whether it was written.
bool fragment_ops(const RectJob& job, const Fragment& f, std::uint64_t& fragments) {
  const FragmentState& fs = *job.fragment;
  if (!detail::pixel_kept(fs, f.x, f.y, false)) return false;
  ++fragments;
  const glm::vec4 color = detail::shade_fragment(*job.shade, f, true);
  if (fs.alpha_test.enabled && !detail::alpha_test(fs.alpha_test, color.a)) return false;
  Framebuffer& fb = *job.fb;
  const std::size_t px = std::size_t(f.y) * std::size_t(fb.width) + std::size_t(f.x);
  if (!detail::depth_stencil_test(fb, px, f.z, fs)) return false;
  if (FragmentCapture* cap = fs.capture) {
    if (cap->count >= cap->limit) {
      ++cap->dropped;
      return false;
    }
    cap->pixels[px].push_back({f.z, color, fs.blend});
    ++cap->count;
    return true;
  }
  detail::write_color(fb, px, color, fs);
  return true;
}

// Rows [begin, end) of the framebuffer (inside the rectangle), counted into `stats`.
void draw_rows(const RectJob& job, int begin, int end, RenderStats& stats) {
  const FragmentRect& r = *job.rect;
  std::uint64_t fragments = 0, written = 0;
  for (int y = begin; y < end; ++y) {
    for (int x = job.x0; x < job.x1; ++x) {
      const std::size_t i = std::size_t(y - r.y) * std::size_t(r.width) + std::size_t(x - r.x);
      if (!r.mask.empty() && !r.mask[i]) continue;
      written += fragment_ops(job, make_fragment(r, x, y, i), fragments);
    }
  }
  std::atomic_ref<std::uint64_t>(stats.fragments).fetch_add(fragments);
  std::atomic_ref<std::uint64_t>(stats.pixels_shaded).fetch_add(written);
}

bool valid(const Framebuffer& fb, const FragmentRect& r) {
  const std::size_t n = std::size_t(std::max(r.width, 0)) * std::size_t(std::max(r.height, 0));
  return r.width > 0 && r.height > 0 && fb.width > 0 && fb.height > 0 &&
         (r.colors.size() == 1 || r.colors.size() == n) && (r.depths.empty() || r.depths.size() == n) &&
         (r.mask.empty() || r.mask.size() == n);
}

}  // namespace

void draw_fragments(Framebuffer& fb, const FragmentState& fragment, const ShadeState& shade,
                    const FragmentRect& rect, RenderStats* stats_out, PipelineContext* fast) {
  if (fast) fast->apply_pending_clears(fb);
  if (!valid(fb, rect)) return;
  ShadeState s = shade;
  s.lighting = false;
  s.drop_incomplete_textures();  // GL 1.1 section 3.8.9
  const long x0 = std::max<long>(rect.x, 0), x1 = std::min<long>(long(rect.x) + rect.width, fb.width);
  const long y0 = std::max<long>(rect.y, 0), y1 = std::min<long>(long(rect.y) + rect.height, fb.height);
  if (x0 >= x1 || y0 >= y1) return;
  const RectJob job{&fb, &fragment, &s, &rect, int(x0), int(x1)};
  RenderStats local;
  RenderStats& stats = stats_out ? *stats_out : local;
  // Rows are disjoint pixels; a capture's counters are shared, so it is filled on one thread.
  if (!fast || fragment.capture || (y1 - y0) * (x1 - x0) < 4096) {
    draw_rows(job, int(y0), int(y1), stats);
    return;
  }
  fast->parallel_for(std::size_t(y1 - y0), 8, [&](std::size_t b, std::size_t e) {
    draw_rows(job, int(y0 + long(b)), int(y0 + long(e)), stats);
  });
}

}  // namespace shadelab
