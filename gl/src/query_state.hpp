// The state of occlusion queries (GL 1.5 section 4.1.6, table 6.37): the context's query
// objects and the one active GL_SAMPLES_PASSED query, whose count the draws made while it is
// active add to. The commands are in queryobj.cpp. Plain data: nothing here draws.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <unordered_map>

#include "shadelab/pipeline.hpp"

namespace shadelab::gl {

/// GL_QUERY_COUNTER_BITS of GL_SAMPLES_PASSED (Mesa's, for llvmpipe).
inline constexpr int kQueryCounterBits = 64;

/// One query object: a name glGenQueries returned has one that was never begun (glIsQuery is
/// false, and its result cannot be asked for), as in Mesa.
struct QueryObject {
  bool ever_begun = false;
  std::uint64_t result = 0;  ///< samples passed between its last glBeginQuery and glEndQuery
};

/// Query objects belong to their context (they are not shared).
struct QueryState {
  std::unordered_map<GLuint, QueryObject> objects;
  GLuint next_name = 1;  ///< above every name ever used, as Mesa's hash picks new names
  GLuint active = 0;     ///< the active query's name (GL_CURRENT_QUERY), 0: none
  /// The draws' counts while a query is active: their pixels_shaded are the samples that
  /// passed the depth and stencil tests (and every test before them).
  RenderStats counts;
};

struct GlContext;
/// What a draw passes to the core as its RenderStats: the active query's counts, or null when
/// no query is active (then drawing costs nothing more, and may wait to be drawn).
RenderStats* query_counts(GlContext& c);

}  // namespace shadelab::gl
