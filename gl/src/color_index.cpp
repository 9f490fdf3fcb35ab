// Colour-index framebuffer controls in an RGBA context (GL 1.1 sections 4.2.2 and 4.2.3):
// glIndexMask and glClearIndex are accepted and their values kept and reported, as Mesa
// does; an RGBA buffer has no index to mask or clear, so they change no pixel. The current
// index (glIndex*) is in current.cpp.
#include <cmath>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {

void exec::IndexMask(GlContext& c, GLuint mask) { c.raster.index_mask = mask; }

// Kept as an unsigned integer, as Mesa keeps it (the fraction is dropped); negative or
// non-finite values, which an index buffer could not hold either, become 0.
void exec::ClearIndex(GlContext& c, GLfloat index) {
  c.raster.clear_index = std::isfinite(index) && index > 0.0f && index < 4294967296.0f ? GLuint(index) : 0u;
}

}  // namespace shadelab::gl
