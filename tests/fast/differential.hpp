// Helpers of the fast pipeline's differential tests: a list of random draws rendered with
// or without a PipelineContext, and the comparison of two results (coverage, depth and stencil
// identical, colours within 1/255).
#pragma once

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "fast/plan.hpp"
#include "random_draws.hpp"
#include "shadelab/pipeline.hpp"

namespace shadelab::test {

/// The plan make_plan makes for a triangle draw with this state (8 x 8 pixels).
inline fast::DrawPlan planned(const FragmentState& frag, const ShadeState& shade) {
  Framebuffer fb;
  fb.resize(8, 8);
  VertexInput in;
  fast::DrawJob job;
  job.fb = &fb;
  job.frag = &frag;
  job.shade = &shade;
  job.in = &in;
  fast::make_plan(job);
  return job.plan;
}

/// The block kernel make_plan chooses for a triangle draw with this state.
inline fast::BlockKernel planned_kernel(const FragmentState& frag, const ShadeState& shade) {
  return planned(frag, shade).kernel;
}

struct Result {
  Framebuffer fb;
  FragmentCapture capture;
  RenderStats stats;
};

// Draws every draw into a copy of `initial`; with `context`, through the fast pipeline.
inline Result render(const Framebuffer& initial, const std::vector<RandomDraw>& draws,
              PipelineContext* context) {
  Result r;
  r.fb = initial;
  r.capture.pixels.resize(std::size_t(initial.width) * std::size_t(initial.height));
  for (const RandomDraw& d : draws) {
    FragmentState frag = d.frag;
    if (d.capture) frag.capture = &r.capture;
    VertexInput in = d.input();
    draw_triangles(r.fb, d.projection, d.viewport, frag, d.shade, in, &r.stats, context);
  }
  return r;
}

// Draws every draw into a copy of `initial` through `context` with `clears` pending, then
// applies what is still pending: the fast pipeline's image of a frame begun with a clear.
inline Framebuffer render_cleared_later(const Framebuffer& initial, const std::vector<RandomDraw>& draws,
                                        PipelineContext& context, const PipelineContext::PendingClears& clears) {
  Framebuffer fb = initial;
  context.pending_clears() = clears;
  for (const RandomDraw& d : draws) {
    VertexInput in = d.input();
    draw_triangles(fb, d.projection, d.viewport, d.frag, d.shade, in, nullptr, &context);
  }
  context.apply_pending_clears(fb);
  return fb;
}

inline std::string compare_buffers(const Framebuffer& fast, const Framebuffer& ref) {
  std::ostringstream out;
  int shown = 0;
  for (int y = 0; y < ref.height; ++y) {
    for (int x = 0; x < ref.width; ++x) {
      std::size_t i = std::size_t(y) * ref.width + x;
      bool depth_same = std::memcmp(&fast.depth[i], &ref.depth[i], sizeof(float)) == 0;
      int worst = 0;
      for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(fast.color[i * 4 + c] - ref.color[i * 4 + c]));
      if (depth_same && fast.stencil[i] == ref.stencil[i] && worst <= 1) continue;
      if (shown++ < 4) {
        out << "(" << x << "," << y << ") depth " << fast.depth[i] << " vs " << ref.depth[i] << ", stencil "
            << int(fast.stencil[i]) << " vs " << int(ref.stencil[i]) << ", colour off by " << worst << "\n";
      }
    }
  }
  if (shown) out << shown << " pixels differ";
  return out.str();
}

inline std::string compare_captures(const FragmentCapture& fast, const FragmentCapture& ref) {
  for (std::size_t i = 0; i < ref.pixels.size(); ++i) {
    const auto &a = fast.pixels[i], &b = ref.pixels[i];
    if (a.size() != b.size()) return "capture sizes differ at pixel " + std::to_string(i);
    for (std::size_t k = 0; k < a.size(); ++k) {
      bool close = glm::all(glm::lessThanEqual(glm::abs(a[k].color - b[k].color), glm::vec4(1.0f / 255.0f)));
      if (a[k].depth != b[k].depth || !close) return "captured fragment differs at pixel " + std::to_string(i);
    }
  }
  return "";
}

// Leaves a random draw only state the fast pipeline's SIMD path draws alone and that the draw
// does not hold on to: no texture, capture, stencil or shadow maps.
inline void simd_only(RandomDraw& d) {
  for (TextureUnit& u : d.shade.textures) u.texture = nullptr;
  d.frag.capture = nullptr;
  d.frag.stencil.enabled = false;
  d.capture = false;
  d.shadow_maps.clear();
  d.shade.shadow_maps = {};
}

/// A framebuffer size of a random number of tiles across and down (within the given ranges)
/// and up to 40 pixels more each way: the last tiles and blocks end inside the framebuffer.
inline glm::ivec2 tiles_and_more(RandomDraws& random, glm::ivec2 columns, glm::ivec2 rows) {
  glm::ivec2 size;
  size.x = random.integer(columns.x, columns.y) * PipelineContext::kTileSize;
  size.x += random.integer(0, 40);
  size.y = random.integer(rows.x, rows.y) * PipelineContext::kTileSize;
  size.y += random.integer(0, 40);
  return size;
}

/// Gives a draw a random 4 x 4 RGBA texture on unit 0, nearest or linear (complete without
/// mipmaps).
inline void bind_random_texture(RandomDraws& random, RandomDraw& d) {
  d.texture = std::make_shared<Texture>();
  TextureLevel level;
  level.width = level.height = 4;
  for (int k = 0; k < 64; ++k) level.rgba.push_back(std::uint8_t(random.integer(0, 255)));
  d.texture->levels.push_back(level);
  d.texture->min_filter = d.texture->mag_filter = random.chance(0.5) ? TextureFilter::kNearest : TextureFilter::kLinear;
  d.shade.textures[0].texture = d.texture.get();
}

/// Renders `draws` into copies of `initial` with the reference and with each context;
/// returns "" when every context agrees with the reference (`where` names the scene).
inline std::string compare_scene(const std::string& where_prefix, const Framebuffer& initial,
                                 const std::vector<RandomDraw>& draws, const std::vector<PipelineContext*>& contexts) {
  Result ref = render(initial, draws, nullptr);
  for (PipelineContext* ctx : contexts) {
    Result fast = render(initial, draws, ctx);
    std::string where = where_prefix + " threads " + std::to_string(ctx->threads()) + ": ";
    const RenderStats &a = fast.stats, &b = ref.stats;
    if (a.fragments != b.fragments || a.pixels_shaded != b.pixels_shaded ||
        a.triangles_rasterized != b.triangles_rasterized || a.triangles_culled != b.triangles_culled ||
        a.triangles_clipped != b.triangles_clipped || a.vertices_lit != b.vertices_lit) {
      return where + "counts differ: fragments " + std::to_string(a.fragments) + " vs " +
             std::to_string(b.fragments) + ", shaded " + std::to_string(a.pixels_shaded) + " vs " +
             std::to_string(b.pixels_shaded);
    }
    std::string diff = compare_buffers(fast.fb, ref.fb) + compare_captures(fast.capture, ref.capture);
    if (!diff.empty()) return where + diff;
    // Resolve copies of the reference: the next context compares with the unresolved one.
    Framebuffer ref_fb = ref.fb;
    FragmentCapture ref_capture = ref.capture;
    resolve_fragments(fast.fb, fast.capture);
    resolve_fragments(ref_fb, ref_capture);
    diff = compare_buffers(fast.fb, ref_fb);
    if (!diff.empty()) return where + "after resolve: " + diff;
  }
  return "";
}

// Compares one random scene (seed) on every given context; returns "" when all agree. With
// `extras`, the draws also use fog, scissor, alpha test, logic op and polygon stipple
// (RandomDraws::fragment_extras).
inline std::string check_seed(unsigned seed, const std::vector<PipelineContext*>& contexts, bool extras = false) {
  RandomDraws random(seed);
  glm::ivec2 size = random.size();
  Framebuffer initial = random.framebuffer(size);
  std::vector<RandomDraw> draws;
  for (int i = random.integer(1, 4); i > 0; --i) {
    draws.push_back(random.draw(size));
    if (extras) random.fragment_extras(draws.back(), size);
  }
  return compare_scene("seed " + std::to_string(seed), initial, draws, contexts);
}

}  // namespace shadelab::test
