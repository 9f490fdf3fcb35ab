// What an OSMesaContext handle points to: a GlContext (the handle type is declared by
// <GL/osmesa.h> as `struct osmesa_context*`). Private to libshadelab-gl. It adds no state of
// its own to the GlContext and no window-system code: OSMesa is only a caller's buffer.
#pragma once

#include "gl/src/context.hpp"

struct osmesa_context : shadelab::gl::GlContext {
  using GlContext::GlContext;
};

namespace shadelab::gl {

/// Makes the caller's buffer the framebuffer's colour: the buffer itself when it has the
/// framebuffer's layout (lends_color), else its pixels read in (present.cpp).
void import_user_buffer(GlContext& c);
/// Whether the caller's buffer has the framebuffer's colour layout and size.
bool lends_color(const GlContext& c);

}  // namespace shadelab::gl
