// Multisampling (GL 1.3; GL 1.5 section 3.2.1): glSampleCoverage and the state it sets. The
// visuals have no multisample buffer (GL_SAMPLE_BUFFERS is 0), so, as the section says, the
// multisample enables and the coverage values are kept and reported and change no fragment.
// The enables are glEnable capabilities (state.cpp); GL_MULTISAMPLE_BIT is attrib.cpp's.
#include <algorithm>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {

// The value is clamped to [0, 1] (a NaN becomes 0, as Mesa's CLAMP makes it).
void exec::SampleCoverage(GlContext& c, GLfloat value, GLboolean invert) {
  c.multisample.coverage_value = value > 0.0f ? std::min(value, 1.0f) : 0.0f;
  c.multisample.coverage_invert = invert != GL_FALSE;
}

}  // namespace shadelab::gl
