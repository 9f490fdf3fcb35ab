// What an OSMesaContext handle points to: a GlContext (the handle type is declared by
// <GL/osmesa.h> as `struct osmesa_context*`). Private to libshadelab-gl.
#pragma once

#include "gl/src/context.hpp"

struct osmesa_context : shadelab::gl::GlContext {
  using GlContext::GlContext;
};

namespace shadelab::gl {

/// Reads the caller's buffer into the framebuffer (present.cpp).
void import_user_buffer(GlContext& c);

}  // namespace shadelab::gl
