// The reference pipeline's per-draw context and its fragment path, shared by its triangles
// (draw.cpp) and its lines, points and unfilled polygons (draw_prims.cpp). Private. The
// context only points at the draw's arguments: nothing is kept from one draw to the next.
#pragma once

#include <vector>

#include "pipeline/stages.hpp"
#include "raster/prims.hpp"

namespace shadelab::detail {

struct ReferenceDraw {
  Framebuffer* fb;
  const FragmentState* fragment;
  const ShadeState* shade;
  const Viewport* viewport;
  RenderStats* stats;
};

/// One rasterized fragment through the per-fragment operations: the polygon stipple (when
/// `polygon`) and the scissor, shading (`front`: front colours and material) with the
/// coverage of a smooth line or point (null: none) times alpha, the alpha test, depth (offset
/// by `offset`, clamped) and stencil tests, then capture or blending (or the logic op) and the
/// colour write.
void reference_fragment(const ReferenceDraw& ctx, const Fragment& f, bool front, float offset,
                        const Coverage* coverage, bool polygon);

/// Draws the draw's lines and points, and its triangles when some face is in GL_LINE or
/// GL_POINT mode, from the vertex stage's clip-space vertices.
void draw_prims_reference(const ReferenceDraw& ctx, const glm::mat4& projection, const VertexInput& in,
                          const std::vector<ClipVertex>& verts);

}  // namespace shadelab::detail
