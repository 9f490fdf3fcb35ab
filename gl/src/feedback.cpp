// Selection and feedback (GL 1.1 sections 5.2 and 5.3): glRenderMode, glSelectBuffer, the name
// stack (glInitNames, glLoadName, glPushName, glPopName), glFeedbackBuffer and glPassThrough,
// and the observer that turns the primitives of a draw made in either mode into hit records or
// feedback tokens. The primitives come from the core pipeline (FragmentState::observer): each
// after clipping, culling and the polygon modes, as Mesa's draw module hands them to its
// selection and feedback stages, so that the values are Mesa's (docs/gl.md, "Selection and
// feedback"). Nothing here touches the framebuffer.
#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {

namespace {

// A value of a hit record; counted past the end of the buffer (overflow).
void write_record(SelectionState& s, GLuint value) {
  if (s.count < std::uint64_t(s.size)) s.buffer[s.count] = value;
  ++s.count;
}

// A depth in [0, 1] as a hit record's unsigned integer: times 2^32 - 1 in float, as Mesa
// computes it. The float product of 1.0 is 2^32, which Mesa's conversion on x86-64 (through a
// 64-bit integer) wraps to 0; the same here, without the undefined conversion.
GLuint hit_depth(float z) {
  if (!(z >= 0.0f)) z = 0.0f;  // never below 0 (nor NaN) after clipping; kept defined anyway
  return GLuint(std::uint64_t(std::int64_t(float(0xffffffffu) * std::min(z, 2.0f))));
}

void reset_hit(SelectionState& s) {
  s.hit = false;
  s.min_z = 1.0f;
  s.max_z = -1.0f;
}

// The hit record of the name stack as it is, when something was hit since the last one.
void write_hit_record(SelectionState& s) {
  if (!s.hit) return;
  write_record(s, GLuint(s.depth));
  write_record(s, hit_depth(s.min_z));
  write_record(s, hit_depth(s.max_z));
  for (int i = 0; i < s.depth; ++i) write_record(s, s.names[std::size_t(i)]);
  ++s.hits;
  reset_hit(s);
}

void hit(SelectionState& s, float z) {
  s.hit = true;
  s.min_z = std::min(s.min_z, z);
  s.max_z = std::max(s.max_z, z);
}

void token(FeedbackState& f, GLfloat value) {
  if (f.count < std::uint64_t(f.size)) f.buffer[f.count] = value;
  ++f.count;
}

// A vertex as glFeedbackBuffer's type asks (GL 1.1 table 5.2): x, y, then z, w, the colour
// and the texture coordinates as the type has them.
void feedback_vertex(FeedbackState& f, const glm::vec4& window, const glm::vec4& color, const glm::vec4& texcoord) {
  token(f, window.x);
  token(f, window.y);
  if (f.type == GL_2D) return;
  token(f, window.z);
  if (f.type == GL_4D_COLOR_TEXTURE) token(f, window.w);
  if (f.type == GL_3D) return;
  for (int i = 0; i < 4; ++i) token(f, color[i]);
  if (f.type == GL_3D_COLOR) return;
  for (int i = 0; i < 4; ++i) token(f, texcoord[i]);
}

void feedback_vertex(FeedbackState& f, const ObservedVertex& v) { feedback_vertex(f, v.window, v.color, v.texcoord); }

bool is_feedback_type(GLenum type) {
  return type == GL_2D || type == GL_3D || type == GL_3D_COLOR || type == GL_3D_COLOR_TEXTURE ||
         type == GL_4D_COLOR_TEXTURE;
}

}  // namespace

void RenderModeObserver::point(const ObservedVertex& v) {
  if (c_.render_mode == GL_SELECT) return hit(c_.selection, v.window.z);
  token(c_.feedback, GLfloat(GL_POINT_TOKEN));
  feedback_vertex(c_.feedback, v);
}

void RenderModeObserver::line(const ObservedVertex& a, const ObservedVertex& b) {
  if (c_.render_mode == GL_SELECT) {
    hit(c_.selection, a.window.z);
    return hit(c_.selection, b.window.z);
  }
  FeedbackState& f = c_.feedback;
  token(f, GLfloat(f.reset_pending ? GL_LINE_RESET_TOKEN : GL_LINE_TOKEN));
  f.reset_pending = false;
  feedback_vertex(f, a);
  feedback_vertex(f, b);
}

// Mesa reports every polygon as the triangles its draw module makes of it (GL_POLYGON_TOKEN 3),
// where the specification allows the whole polygon in one.
void RenderModeObserver::triangle(const ObservedVertex& a, const ObservedVertex& b, const ObservedVertex& c) {
  if (c_.render_mode == GL_SELECT) {
    hit(c_.selection, a.window.z);
    hit(c_.selection, b.window.z);
    return hit(c_.selection, c.window.z);
  }
  token(c_.feedback, GLfloat(GL_POLYGON_TOKEN));
  token(c_.feedback, 3.0f);
  feedback_vertex(c_.feedback, a);
  feedback_vertex(c_.feedback, b);
  feedback_vertex(c_.feedback, c);
}

void RenderModeObserver::restart_stipple() {
  if (c_.render_mode == GL_FEEDBACK) c_.feedback.reset_pending = true;
}

void feedback_raster_position(GlContext& c, GLenum which) {
  const RasterPosition& r = c.raster_pos;
  if (c.render_mode != GL_FEEDBACK || !r.valid) return;
  token(c.feedback, GLfloat(which));
  feedback_vertex(c.feedback, r.window, r.color, r.texcoords[0]);  // unit 0's (GL 1.3 section 5.3)
}

void select_raster_position(GlContext& c) {
  if (c.render_mode == GL_SELECT && c.raster_pos.valid) hit(c.selection, c.raster_pos.window.z);
}

// Leaving a mode answers for it: the hit records (selection, the last one written now) or the
// feedback values, -1 when they did not fit the buffer; 0 leaving GL_RENDER. As Mesa, the mode
// left is answered and reset before the new one is checked: an unknown mode is
// GL_INVALID_ENUM, 0 and the mode unchanged, and a selection or feedback mode whose buffer was
// never given (size 0) is GL_INVALID_OPERATION but entered all the same.
GLint exec::RenderMode(GlContext& c, GLenum mode) {
  GLint result = 0;
  if (c.render_mode == GL_SELECT) {
    SelectionState& s = c.selection;
    write_hit_record(s);
    result = s.count > std::uint64_t(s.size) ? -1 : s.hits;
    s.count = 0;
    s.hits = 0;
    s.depth = 0;
    reset_hit(s);
  } else if (c.render_mode == GL_FEEDBACK) {
    FeedbackState& f = c.feedback;
    result = f.count > std::uint64_t(f.size) ? -1 : GLint(f.count);
    f.count = 0;
  }
  switch (mode) {
    case GL_RENDER: break;
    case GL_SELECT:
      if (c.selection.size == 0) c.set_error(GL_INVALID_OPERATION);
      break;
    case GL_FEEDBACK:
      if (c.feedback.size == 0) c.set_error(GL_INVALID_OPERATION);
      break;
    default: c.set_error(GL_INVALID_ENUM); return 0;
  }
  c.render_mode = mode;
  return result;
}

void exec::SelectBuffer(GlContext& c, GLsizei size, GLuint* buffer) {
  if (size < 0) return c.set_error(GL_INVALID_VALUE);
  if (c.render_mode == GL_SELECT) return c.set_error(GL_INVALID_OPERATION);
  SelectionState& s = c.selection;
  s.buffer = buffer;
  s.size = size;
  s.count = 0;
  reset_hit(s);
}

// Outside GL_SELECT mode the name stack commands are ignored (GL 1.1 section 5.2). Each
// writes the hit record of the stack as it was, if there was a hit, before changing it (and
// before checking it: glPushName on a full stack still writes the record, as Mesa 22 does).
void exec::InitNames(GlContext& c) {
  if (c.render_mode != GL_SELECT) return;
  write_hit_record(c.selection);
  c.selection.depth = 0;
  reset_hit(c.selection);
}

void exec::LoadName(GlContext& c, GLuint name) {
  SelectionState& s = c.selection;
  if (c.render_mode != GL_SELECT) return;
  if (s.depth == 0) return c.set_error(GL_INVALID_OPERATION);
  write_hit_record(s);
  s.names[std::size_t(s.depth - 1)] = name;
}

void exec::PushName(GlContext& c, GLuint name) {
  SelectionState& s = c.selection;
  if (c.render_mode != GL_SELECT) return;
  write_hit_record(s);
  if (s.depth >= kMaxNameStackDepth) return c.set_error(GL_STACK_OVERFLOW);
  s.names[std::size_t(s.depth++)] = name;
}

void exec::PopName(GlContext& c) {
  SelectionState& s = c.selection;
  if (c.render_mode != GL_SELECT) return;
  write_hit_record(s);
  if (s.depth == 0) return c.set_error(GL_STACK_UNDERFLOW);
  --s.depth;
}

// Errors in Mesa's order: the mode, the size, a null buffer for a non-empty one (which also
// forgets the buffer given before), the type.
void exec::FeedbackBuffer(GlContext& c, GLsizei size, GLenum type, GLfloat* buffer) {
  FeedbackState& f = c.feedback;
  if (c.render_mode == GL_FEEDBACK) return c.set_error(GL_INVALID_OPERATION);
  if (size < 0) return c.set_error(GL_INVALID_VALUE);
  if (!buffer && size > 0) {
    f.size = 0;
    return c.set_error(GL_INVALID_VALUE);
  }
  if (!is_feedback_type(type)) return c.set_error(GL_INVALID_ENUM);
  f.type = type;
  f.size = size;
  f.buffer = buffer;
}

void exec::PassThrough(GlContext& c, GLfloat value) {
  if (c.render_mode != GL_FEEDBACK) return;
  token(c.feedback, GLfloat(GL_PASS_THROUGH_TOKEN));
  token(c.feedback, value);
}

}  // namespace shadelab::gl
