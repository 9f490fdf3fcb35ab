// The drawing pipeline shared by both front ends (scene files and the GL library):
// eye-space vertices in, pixels in a framebuffer out. Vertex lighting, clipping, triangle
// setup, rasterization, per-pixel shading and blending happen here. It keeps no state
// between calls besides the framebuffer it is given.
// Its types are in framebuffer.hpp, fragment_state.hpp, shade_state.hpp, vertex_input.hpp and
// pipeline_context.hpp, included here for every user of the pipeline; here are the draws.
#pragma once

#include <cstdint>
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "shadelab/fragment_state.hpp"
#include "shadelab/framebuffer.hpp"
#include "shadelab/pipeline_context.hpp"
#include "shadelab/shade_state.hpp"
#include "shadelab/vertex_input.hpp"

namespace shadelab {

/// Sorts every pixel's captured fragments far to near and blends them over the framebuffer with
/// each fragment's own blend state, then empties the capture.
void resolve_fragments(Framebuffer& fb, FragmentCapture& capture);

/// Draws the triangles, lines and points of `vertices` into `fb`: vertex lighting
/// (flat/Gouraud), projection, homogeneous clipping against the view volume and the user clip
/// planes, viewport mapping, facing, culling and the polygon modes, rasterization (triangles
/// with the top-left fill rule at pixel centres; lines and points by llvmpipe's rules,
/// docs/rasterization.md), depth/stencil tests, per-pixel lighting (Phong), blending.
/// `projection` maps eye space to clip space. With `fast`, the tiled, multithreaded SIMD
/// pipeline draws instead of the reference path: the same coverage and depth, colours within
/// 1/255.
void draw_triangles(Framebuffer& fb, const glm::mat4& projection, const Viewport& viewport,
                    const FragmentState& fragment, const ShadeState& shade,
                    const VertexInput& vertices, RenderStats* stats = nullptr,
                    PipelineContext* fast = nullptr);

/// A rectangle of window-space fragments that no primitive made: what glDrawPixels,
/// glCopyPixels and glBitmap produce (GL 1.1 sections 3.6.4, 3.6.5, 3.7). Fragment (i, j) of
/// the rectangle is at window pixel (x + i, y + j); arrays are indexed by j * width + i
/// (row 0 the bottom row).
struct FragmentRect {
  int x = 0, y = 0;
  int width = 0, height = 0;  ///< >= 0
  /// The fragments' colours, unclamped: width * height of them, or one for every fragment
  /// (glBitmap's raster colour).
  std::span<const glm::vec4> colors;
  float depth = 0.0f;                ///< window depth of every fragment (the raster position's)
  std::span<const float> depths;     ///< or one per fragment (glDrawPixels of depth values)
  std::span<const std::uint8_t> mask;  ///< empty, or width * height: 0 makes no fragment (glBitmap)
  /// (s, t, r, q) of every fragment for each texture unit (the raster position's), for
  /// texturing (s / q, t / q).
  std::array<glm::vec4, kMaxTextureUnits> texcoords = filled_texcoords();
  static constexpr std::array<glm::vec4, kMaxTextureUnits> filled_texcoords() {
    std::array<glm::vec4, kMaxTextureUnits> t;
    for (glm::vec4& v : t) v = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    return t;
  }
  float fog_coord = 0.0f;    ///< the raster position's fog coordinate
};

/// Runs GL's per-fragment operations on the fragments of `rect`, as on a primitive's: their
/// colours textured with `shade`'s texture units at `texcoords` (their magnification filter: the
/// coordinates do not change across the rectangle) and fogged with `shade.fog` at `fog_coord`
/// (lighting and shading are not used), then `fragment`'s scissor, alpha test, stencil and
/// depth tests, blending or logic op and colour mask. Fragments outside the framebuffer are
/// dropped (pixel ownership); polygon stipple, culling and polygon offset do not apply.
/// With `fast`, its waiting draws and pending clears are applied first and the fragments are
/// written at once, rows split over its threads (a simple loop over the reference's
/// operations: not a hot path); the caller marks what it knows of the rectangle's tiles.
void draw_fragments(Framebuffer& fb, const FragmentState& fragment, const ShadeState& shade,
                    const FragmentRect& rect, RenderStats* stats = nullptr,
                    PipelineContext* fast = nullptr);

}  // namespace shadelab
