// Occlusion queries (GL 1.5 sections 4.1.6 and 6.1.12): glGenQueries, glDeleteQueries,
// glIsQuery, glBeginQuery, glEndQuery, glGetQueryiv, glGetQueryObjectiv/uiv with
// GL_SAMPLES_PASSED. While a query is active, every draw hands the core its RenderStats
// (query_counts), whose pixels_shaded count the fragments that passed every test up to and
// including the depth test, whichever pipeline draws them; such draws are rasterized at once,
// so a result is known, and available, at glEndQuery. Errors and names as Mesa's queryobj.c
// gives them in a compatibility context (a name never generated may be begun).
#include <climits>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {
namespace {

// An object that glGetQueryObject may read: begun at least once and not active.
const QueryObject* finished_query(const GlContext& c, GLuint id) {
  const auto it = id ? c.queries.objects.find(id) : c.queries.objects.end();
  if (it == c.queries.objects.end() || !it->second.ever_begun || c.queries.active == id) return nullptr;
  return &it->second;
}

// glGetQueryObject's value of `pname`; false (GL_INVALID_ENUM) for another pname.
bool query_object_value(const QueryObject& q, GLenum pname, std::uint64_t& value) {
  switch (pname) {
    case GL_QUERY_RESULT: value = q.result; return true;
    case GL_QUERY_RESULT_AVAILABLE: value = GL_TRUE; return true;  // counted by glEndQuery
    default: return false;
  }
}

// The name after `name` that glGenQueries may take next (Mesa's names only grow).
void note_name(QueryState& q, GLuint name) {
  if (name >= q.next_name) q.next_name = name + 1;
}

}  // namespace

RenderStats* query_counts(GlContext& c) { return c.queries.active ? &c.queries.counts : nullptr; }

void exec::GenQueries(GlContext& c, GLsizei n, GLuint* ids) {
  if (n < 0 || (n > 0 && !ids)) return c.set_error(GL_INVALID_VALUE);
  QueryState& q = c.queries;
  for (GLsizei i = 0; i < n; ++i) {
    while (q.next_name == 0 || q.objects.count(q.next_name)) ++q.next_name;
    ids[i] = q.next_name;
    q.objects[ids[i]] = QueryObject{};
    note_name(q, ids[i]);
  }
}

// Deleting the active query ends it (as Mesa does); names that are not queries are ignored.
void exec::DeleteQueries(GlContext& c, GLsizei n, const GLuint* ids) {
  if (n < 0 || (n > 0 && !ids)) return c.set_error(GL_INVALID_VALUE);
  QueryState& q = c.queries;
  for (GLsizei i = 0; i < n; ++i) {
    if (ids[i] == 0 || !q.objects.erase(ids[i])) continue;
    if (q.active == ids[i]) q.active = 0;
  }
}

GLboolean exec::IsQuery(GlContext& c, GLuint id) {
  const auto it = c.queries.objects.find(id);
  return id != 0 && it != c.queries.objects.end() && it->second.ever_begun ? GL_TRUE : GL_FALSE;
}

// Section 4.1.6: GL_INVALID_OPERATION while a query is active and for the name 0; a name
// never generated becomes a query object (GL 1.5; Mesa's compatibility contexts too).
void exec::BeginQuery(GlContext& c, GLenum target, GLuint id) {
  if (target != GL_SAMPLES_PASSED) return c.set_error(GL_INVALID_ENUM);
  QueryState& q = c.queries;
  if (q.active != 0 || id == 0) return c.set_error(GL_INVALID_OPERATION);
  QueryObject& object = q.objects[id];
  note_name(q, id);
  object.ever_begun = true;
  object.result = 0;
  q.active = id;
  q.counts = RenderStats{};
}

void exec::EndQuery(GlContext& c, GLenum target) {
  if (target != GL_SAMPLES_PASSED) return c.set_error(GL_INVALID_ENUM);
  QueryState& q = c.queries;
  if (q.active == 0) return c.set_error(GL_INVALID_OPERATION);
  q.objects[q.active].result = q.counts.pixels_shaded;
  q.active = 0;
  q.counts = RenderStats{};
}

void exec::GetQueryiv(GlContext& c, GLenum target, GLenum pname, GLint* params) {
  if (target != GL_SAMPLES_PASSED) return c.set_error(GL_INVALID_ENUM);
  GLint value;
  switch (pname) {
    case GL_QUERY_COUNTER_BITS: value = kQueryCounterBits; break;
    case GL_CURRENT_QUERY: value = GLint(c.queries.active); break;
    default: return c.set_error(GL_INVALID_ENUM);
  }
  if (params) *params = value;
}

// A count past the type's range is clamped to its largest value, as Mesa does.
void exec::GetQueryObjectiv(GlContext& c, GLuint id, GLenum pname, GLint* params) {
  const QueryObject* q = finished_query(c, id);
  if (!q) return c.set_error(GL_INVALID_OPERATION);
  std::uint64_t value = 0;
  if (!query_object_value(*q, pname, value)) return c.set_error(GL_INVALID_ENUM);
  if (params) *params = value > std::uint64_t(INT_MAX) ? INT_MAX : GLint(value);
}

void exec::GetQueryObjectuiv(GlContext& c, GLuint id, GLenum pname, GLuint* params) {
  const QueryObject* q = finished_query(c, id);
  if (!q) return c.set_error(GL_INVALID_OPERATION);
  std::uint64_t value = 0;
  if (!query_object_value(*q, pname, value)) return c.set_error(GL_INVALID_ENUM);
  if (params) *params = value > std::uint64_t(UINT_MAX) ? UINT_MAX : GLuint(value);
}

}  // namespace shadelab::gl
