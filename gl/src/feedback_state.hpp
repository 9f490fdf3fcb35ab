// The state of GL's selection and feedback modes (GL 1.1 sections 5.2, 5.3, table 6.31): the
// render mode, the selection buffer with its hit and name stack, the feedback buffer, and the
// observer through which the core pipeline reports a draw's primitives in either mode
// (shadelab::PrimitiveObserver). The commands are in feedback.cpp. Plain data and
// declarations: nothing here draws or writes the caller's buffers.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>

#include <glm/vec4.hpp>

#include "shadelab/pipeline.hpp"

namespace shadelab::gl {

inline constexpr int kMaxNameStackDepth = 64;  // as Mesa's MAX_NAME_STACK_DEPTH

struct SelectionState {
  GLuint* buffer = nullptr;
  GLsizei size = 0;
  // Values written so far, counting those past the end (the overflow glRenderMode reports).
  std::uint64_t count = 0;
  GLint hits = 0;
  bool hit = false;  // a primitive or raster position was hit since the last hit record
  float min_z = 1.0f, max_z = -1.0f;
  int depth = 0;
  std::array<GLuint, kMaxNameStackDepth> names{};
};

struct FeedbackState {
  GLfloat* buffer = nullptr;
  GLsizei size = 0;
  GLenum type = GL_2D;
  std::uint64_t count = 0;  // values written so far, counting those past the end
  // A polygon drawn as lines restarted its stipple: the next line is a GL_LINE_RESET_TOKEN
  // (kept across draws and render modes, as Mesa's feedback stage keeps it).
  bool reset_pending = false;
};

struct GlContext;

/// Takes the primitives of draws made in GL_SELECT or GL_FEEDBACK mode (draw.cpp sets it as
/// FragmentState::observer): hits for selection, tokens for feedback.
class RenderModeObserver final : public PrimitiveObserver {
 public:
  explicit RenderModeObserver(GlContext& c) : c_(c) {}
  void point(const ObservedVertex& v) override;
  void line(const ObservedVertex& a, const ObservedVertex& b) override;
  void triangle(const ObservedVertex& a, const ObservedVertex& b, const ObservedVertex& c) override;
  void restart_stipple() override;

 private:
  GlContext& c_;
};

/// glBitmap, glDrawPixels and glCopyPixels in GL_FEEDBACK mode, with a valid raster position
/// (GL 1.1 section 5.3): `token` and the raster position's vertex. (In GL_SELECT mode they do
/// nothing: no hit, as Mesa, following the specification's appendix B, corollary 6.)
void feedback_raster_position(GlContext& c, GLenum token);

/// glRasterPos in GL_SELECT mode: a valid raster position is a hit at its depth (as Mesa).
void select_raster_position(GlContext& c);

}  // namespace shadelab::gl
