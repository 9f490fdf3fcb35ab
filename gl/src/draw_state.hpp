// The core pipeline's per-draw state made from a context's GL state (draw_state.cpp): the
// FragmentState of every draw (and of the fragments glDrawPixels, glCopyPixels and glBitmap
// make), its FogState, and the ShadeState of those rectangles of fragments. Translation (it
// changes no GL state), and the one call that draws those rectangles.
#pragma once

#include "gl/src/context.hpp"

namespace shadelab::gl {

/// The core's per-fragment state from GL's. Without a depth (stencil) buffer the depth
/// (stencil) test behaves as if disabled (GL 1.1 sections 4.1.5, 4.1.6).
FragmentState fragment_state(const GlContext& c);

/// The core's fog from GL's (GL 1.1 section 3.9).
shadelab::FogState fog_state(const GlContext& c);

/// A width or size as Mesa's state tracker hands it to llvmpipe: clamped to [least, the
/// maximum] (line widths from 1, point sizes from 0: glLineWidth and glPointSize keep any
/// positive value, and a NaN, for glGet; a NaN draws as 1 here).
float raster_size(float v, float least, float max);

/// The per-fragment state of every fragment the context draws (the fragments of glDrawPixels,
/// glCopyPixels and glBitmap use it with draw_fragments, GL 1.1 sections 3.6.4, 3.7).
FragmentState rectangle_fragment_state(const GlContext& c);
/// How those fragments are coloured: the active texture and its environment (and every
/// per-fragment colour operation a primitive's fragments get after texturing); no lighting.
ShadeState rectangle_shade_state(GlContext& c);
/// Draws a rectangle of fragments with those states into each colour buffer GL_DRAW_BUFFER
/// names, and marks its tiles changed.
void draw_rectangle(GlContext& c, const FragmentRect& rect);

}  // namespace shadelab::gl
