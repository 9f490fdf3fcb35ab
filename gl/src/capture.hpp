// A frame of a GL program kept as a scene file (docs/platform.md, "A frame as a scene"): with
// SHADELAB_CAPTURE_SCENE=FILE (what `shadelab run --capture-scene FILE` sets), the triangles a
// chosen frame draws are recorded with what lit them (eye-space positions and normals, the
// lights, the light model, each triangle's materials, the shading model, culling and blending)
// and written when the frame ends as FILE, a scene file (docs/scene-format.md), beside which each
// object's triangles go into an OBJ file. The lab opens it and explains its pixels; the scene
// renders the frame's lit triangles as the program drew them.
//
// Frames: a swap of a double-buffered window, or a glFlush / glFinish of anything else
// (single-buffered windows, pbuffers, OSMesa buffers), counted from 1 as `shadelab run`
// counts them; SHADELAB_CAPTURE_FRAME=N picks one (1 by default). A colour clear of the whole
// viewport starts the frame's picture again. What a scene file cannot hold is counted and
// named in the scene's caption: lines and points, polygons drawn as lines or points, textures,
// fog, pixel rectangles (glDrawPixels, glBitmap), disabled depth testing.
//
// The library writes these files only when the variable asks for them; it prints nothing.
#pragma once

#include <GL/gl.h>

#include <span>

#include "shadelab/material.hpp"

namespace shadelab {
struct ShadeState;
struct VertexInput;
}  // namespace shadelab

namespace shadelab::gl {

struct GlContext;

inline constexpr const char* kCaptureSceneVariable = "SHADELAB_CAPTURE_SCENE";  ///< the scene file
inline constexpr const char* kCaptureFrameVariable = "SHADELAB_CAPTURE_FRAME";  ///< its frame, from 1

/// The materials a vertex was lit with (they may change between glBegin and glEnd).
struct VertexMaterials {
  Material front, back;
};

/// Reads the variables when a context is made: nothing happens without them.
void capture_init(GlContext& c);

/// Whether the frame being drawn is recorded (the draw paths keep what it needs then).
bool capture_recording(const GlContext& c);

/// Records a draw of triangles, lines or points as draw_triangles receives it. `lit`: lighting
/// was on. `vertex_materials`: per vertex of `in`, when the draw's colours were lit vertex by
/// vertex; empty when `shade` lights them (its front and back materials).
void capture_draw(GlContext& c, const ShadeState& shade, const VertexInput& in, bool lit,
                  std::span<const VertexMaterials> vertex_materials);

/// A pixel rectangle drawn (glDrawPixels, glBitmap, glCopyPixels): counted, not captured.
void capture_pixels(GlContext& c);

/// glClear: a colour clear of the whole viewport forgets what the frame drew before it.
void capture_clear(GlContext& c, GLbitfield mask, bool scissored);

/// A frame ended (shown): when it was the chosen one, the scene is written.
void capture_frame_end(GlContext& c);

/// The context is being destroyed: a chosen frame that was drawn but never ended is written.
void capture_context_end(GlContext& c);

}  // namespace shadelab::gl
