// Evaluators (GL 1.1 section 5.1): glMap1/glMap2 (every target; control points copied as
// floats), glGetMap, glMapGrid, glEvalCoord, glEvalPoint and glEvalMesh, with GL_AUTO_NORMAL
// and the GL_MAPn_* enables (their flags are capability_flag's, gl/src/state.cpp). An
// evaluated vertex is specified as glVertex specifies one, with the enabled maps' colour,
// normal and texture coordinates in place of the current ones, which stay unchanged (Mesa 22.3
// leaves stale values in them: docs/gl-conformance.md, "Evaluators"). Errors and their order
// are Mesa's (src/mesa/main/eval.c); what is evaluated and in which order of operations too
// (gl/src/eval_math.cpp). The colour-index maps are stored and queried but evaluate nothing,
// as in Mesa's RGBA contexts. Points and lines of glEvalMesh go through glBegin as the
// specification writes them. Must not print, exit or keep pointers to the caller's arrays.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/geometric.hpp>

#include "gl/generated/exec.hpp"
#include "gl/generated/run.hpp"
#include "gl/generated/save.hpp"
#include "gl/src/context.hpp"
#include "gl/src/draw.hpp"
#include "gl/src/eval_math.hpp"

namespace shadelab::gl {

EvalState::EvalState() {
  // Every map starts as order 1 with the attribute's initial value (table 6.20).
  const float vertex[4] = {0, 0, 0, 1}, normal[3] = {0, 0, 1}, index[1] = {1};
  const float color[4] = {1, 1, 1, 1}, texcoord[4] = {0, 0, 0, 1};
  const float* initial[kEvalTargets] = {color,    index,    normal, texcoord, texcoord,
                                        texcoord, texcoord, vertex, vertex};
  for (int t = 0; t < kEvalTargets; ++t) {
    const int n = eval_components(GLenum(GL_MAP1_COLOR_4 + t));
    map1[t].points.assign(initial[t], initial[t] + n);
    map2[t].points.assign(initial[t], initial[t] + n);
  }
}

int eval_components(GLenum target) {
  static constexpr int kComponents[kEvalTargets] = {4, 1, 3, 1, 2, 3, 4, 3, 4};
  if (target >= GL_MAP1_COLOR_4 && target <= GL_MAP1_VERTEX_4)
    return kComponents[target - GL_MAP1_COLOR_4];
  if (target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4)
    return kComponents[target - GL_MAP2_COLOR_4];
  return 0;
}

bool* eval_capability_flag(GlContext& c, GLenum cap) {
  EvalAttribs& a = c.eval.attribs;
  if (cap >= GL_MAP1_COLOR_4 && cap <= GL_MAP1_VERTEX_4)
    return &a.map1_enabled[cap - GL_MAP1_COLOR_4];
  if (cap >= GL_MAP2_COLOR_4 && cap <= GL_MAP2_VERTEX_4)
    return &a.map2_enabled[cap - GL_MAP2_COLOR_4];
  if (cap == GL_AUTO_NORMAL) return &a.auto_normal;
  return nullptr;
}

namespace {

constexpr int kColor = 0, kNormal = 2, kTexCoord1 = 3, kVertex3 = 7, kVertex4 = 8;

// Control points from the caller's array, `stride` values apart, as floats.
template <class T>
std::vector<float> copy_points1(const T* points, int stride, int order, int k) {
  std::vector<float> out(std::size_t(order * k));
  for (int i = 0; i < order; ++i)
    for (int j = 0; j < k; ++j)
      out[std::size_t(i * k + j)] = float(points[std::ptrdiff_t(i) * stride + j]);
  return out;
}

template <class T>
std::vector<float> copy_points2(const T* points, int ustride, int uorder, int vstride, int vorder,
                                int k) {
  std::vector<float> out(std::size_t(uorder * vorder * k));
  for (int i = 0; i < uorder; ++i)
    for (int j = 0; j < vorder; ++j)
      for (int m = 0; m < k; ++m) {
        const std::ptrdiff_t at = std::ptrdiff_t(i) * ustride + std::ptrdiff_t(j) * vstride + m;
        out[std::size_t((i * vorder + j) * k + m)] = float(points[at]);
      }
  return out;
}

bool is_map1(GLenum target) { return target >= GL_MAP1_COLOR_4 && target <= GL_MAP1_VERTEX_4; }
bool is_map2(GLenum target) { return target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4; }

// glMap1's checks, in Mesa's order.
template <class T>
void map1(GlContext& c, GLenum target, float u1, float u2, GLint stride, GLint order,
          const T* points) {
  if (u1 == u2) return c.set_error(GL_INVALID_VALUE);
  if (order < 1 || order > kMaxEvalOrder) return c.set_error(GL_INVALID_VALUE);
  if (!points) return c.set_error(GL_INVALID_VALUE);
  const int k = eval_components(target);
  if (k == 0) return c.set_error(GL_INVALID_ENUM);
  if (stride < k) return c.set_error(GL_INVALID_VALUE);
  if (!is_map1(target)) return c.set_error(GL_INVALID_ENUM);
  EvalMap1& m = c.eval.map1[target - GL_MAP1_COLOR_4];
  m.points = copy_points1(points, stride, order, k);
  m.order = order, m.u1 = u1, m.u2 = u2, m.du = 1.0f / (u2 - u1);
}

template <class T>
void map2(GlContext& c, GLenum target, float u1, float u2, GLint ustride, GLint uorder, float v1,
          float v2, GLint vstride, GLint vorder, const T* points) {
  if (u1 == u2 || v1 == v2) return c.set_error(GL_INVALID_VALUE);
  if (uorder < 1 || uorder > kMaxEvalOrder || vorder < 1 || vorder > kMaxEvalOrder) {
    return c.set_error(GL_INVALID_VALUE);
  }
  const int k = eval_components(target);
  if (k == 0) return c.set_error(GL_INVALID_ENUM);
  if (ustride < k || vstride < k) return c.set_error(GL_INVALID_VALUE);
  if (!is_map2(target)) return c.set_error(GL_INVALID_ENUM);
  if (!points) return c.set_error(GL_INVALID_VALUE);  // Mesa would keep a map without points
  EvalMap2& m = c.eval.map2[target - GL_MAP2_COLOR_4];
  m.points = copy_points2(points, ustride, uorder, vstride, vorder, k);
  m.uorder = uorder, m.vorder = vorder;
  m.u1 = u1, m.u2 = u2, m.du = 1.0f / (u2 - u1);
  m.v1 = v1, m.v2 = v2, m.dv = 1.0f / (v2 - v1);
}

// glGetMap: the values as floats, or false for a query it rejects.
bool map_values(const GlContext& c, GLenum target, GLenum query, std::vector<float>& out) {
  const bool one = is_map1(target);
  const EvalMap1* m1 = one ? &c.eval.map1[target - GL_MAP1_COLOR_4] : nullptr;
  const EvalMap2* m2 = one ? nullptr : &c.eval.map2[target - GL_MAP2_COLOR_4];
  switch (query) {
    case GL_COEFF:
      out = one ? m1->points : m2->points;
      return true;
    case GL_ORDER:
      out = one ? std::vector<float>{float(m1->order)}
                : std::vector<float>{float(m2->uorder), float(m2->vorder)};
      return true;
    case GL_DOMAIN:
      out = one ? std::vector<float>{m1->u1, m1->u2}
                : std::vector<float>{m2->u1, m2->u2, m2->v1, m2->v2};
      return true;
    default:
      return false;
  }
}

template <class T>
void get_map(GlContext& c, GLenum target, GLenum query, T* v) {
  if (eval_components(target) == 0) return c.set_error(GL_INVALID_ENUM);
  std::vector<float> values;
  if (!map_values(c, target, query, values)) return c.set_error(GL_INVALID_ENUM);
  if (!v) return c.set_error(GL_INVALID_VALUE);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if constexpr (std::is_same_v<T, GLint>) {
      // Orders are integers already; coefficients and domains rounded (Mesa's lroundf).
      v[i] = GLint(std::lround(values[i]));
    } else {
      v[i] = T(values[i]);
    }
  }
}

// The highest enabled texture-coordinate map of a dimension (a 4-component one wins), or -1.
int texcoord_map(const std::array<bool, kEvalTargets>& enabled) {
  for (int t = kTexCoord1 + 3; t >= kTexCoord1; --t)
    if (enabled[t]) return t;
  return -1;
}

int vertex_map(const std::array<bool, kEvalTargets>& enabled) {
  return enabled[kVertex4] ? kVertex4 : enabled[kVertex3] ? kVertex3 : -1;
}

// The evaluated attributes become the vertex's, the vertex is specified, and the current
// attributes are put back (section 5.1: evaluation does not change them). Under colour
// material the material follows the evaluated colour for this vertex, then the current one
// again (apply_color_material settles lighting deferred with the other).
template <class Eval>
void evaluated_vertex(GlContext& c, const std::array<bool, kEvalTargets>& enabled, const Eval& eval,
                      const glm::vec4& position, const glm::vec3* auto_normal) {
  const CurrentAttribs saved = c.current;
  if (enabled[kNormal]) {
    float n[4] = {0, 0, 0, 1};
    eval(kNormal, n);
    c.current.normal = glm::vec3(n[0], n[1], n[2]);
  }
  if (auto_normal) c.current.normal = *auto_normal;
  const bool colored = enabled[kColor];
  if (colored) {
    float v[4] = {0, 0, 0, 1};
    eval(kColor, v);
    c.current.color = glm::vec4(v[0], v[1], v[2], v[3]);
    apply_color_material(c);
  }
  if (const int t = texcoord_map(enabled); t >= 0) {
    float v[4] = {0, 0, 0, 1};
    eval(t, v);
    c.current.texcoords[0] = glm::vec4(v[0], v[1], v[2], v[3]);  // unit 0's, as glTexCoord
  }
  if (c.prim.active) emit_vertex(c, position);
  c.current = saved;
  if (colored) apply_color_material(c);
}

// A primitive holding an evaluation is drawn as one begun outside any list, even when a list
// runs it: Mesa compiles glEvalCoord/glEvalPoint inside glBegin/glEnd as commands
// (vbo_save_api.c's dlist_fallback) and replays the whole primitive through its immediate
// path, where llvmpipe splits quads from their first vertex (docs/gl-conformance.md).
void leave_list_split(GlContext& c) {
  if (c.prim.active) c.prim.in_list = false;
}

void eval_coord1(GlContext& c, float u) {
  leave_list_split(c);
  const EvalAttribs& a = c.eval.attribs;
  const int vm = vertex_map(a.map1_enabled);
  if (vm < 0) return;  // no vertex map: no vertex, nothing else (Mesa)
  auto eval = [&](int t, float* out) {
    const EvalMap1& m = c.eval.map1[t];
    const int k = eval_components(GLenum(GL_MAP1_COLOR_4 + t));
    bezier_curve(m.points.data(), k, k, m.order, (u - m.u1) * m.du, out);
  };
  float p[4] = {0, 0, 0, 1};
  eval(vm, p);
  evaluated_vertex(c, a.map1_enabled, eval,
                   glm::vec4(p[0], p[1], p[2], vm == kVertex4 ? p[3] : 1.0f), nullptr);
}

void eval_coord2(GlContext& c, float u, float v) {
  leave_list_split(c);
  const EvalAttribs& a = c.eval.attribs;
  const int vm = vertex_map(a.map2_enabled);
  if (vm < 0) return;
  auto eval = [&](int t, float* out) {
    const EvalMap2& m = c.eval.map2[t];
    const int k = eval_components(GLenum(GL_MAP2_COLOR_4 + t));
    bezier_surface(m.points.data(), k, m.uorder, m.vorder, (u - m.u1) * m.du, (v - m.v1) * m.dv,
                   out);
  };
  const EvalMap2& m = c.eval.map2[vm];
  const int k = vm == kVertex4 ? 4 : 3;
  const float uu = (u - m.u1) * m.du, vv = (v - m.v1) * m.dv;
  float p[4] = {0, 0, 0, 1};
  if (!a.auto_normal) {
    bezier_surface(m.points.data(), k, m.uorder, m.vorder, uu, vv, p);
    return evaluated_vertex(c, a.map2_enabled, eval,
                            glm::vec4(p[0], p[1], p[2], k == 4 ? p[3] : 1.0f), nullptr);
  }
  // GL_AUTO_NORMAL (equation 5.4): the cross product of the partial derivatives, of the
  // projected surface x / w for a 4-component map.
  float du[4] = {0, 0, 0, 0}, dv[4] = {0, 0, 0, 0};
  bezier_surface_tangents(m.points.data(), k, m.uorder, m.vorder, uu, vv, p, du, dv);
  if (k == 4) {
    for (int i = 0; i < 3; ++i) du[i] = du[i] * p[3] - du[3] * p[i];
    for (int i = 0; i < 3; ++i) dv[i] = dv[i] * p[3] - dv[3] * p[i];
  }
  glm::vec3 n(du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2],
              du[0] * dv[1] - du[1] * dv[0]);
  const float len2 = n.x * n.x + n.y * n.y + n.z * n.z;
  if (len2 != 0.0f) n *= 1.0f / std::sqrt(len2);
  evaluated_vertex(c, a.map2_enabled, eval, glm::vec4(p[0], p[1], p[2], k == 4 ? p[3] : 1.0f), &n);
}

}  // namespace

void exec::Map1f(GlContext& c, GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order,
                 const GLfloat* points) {
  map1(c, target, u1, u2, stride, order, points);
}
void exec::Map1d(GlContext& c, GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
                 const GLdouble* points) {
  map1(c, target, float(u1), float(u2), stride, order, points);
}
void exec::Map2f(GlContext& c, GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder,
                 GLfloat v1, GLfloat v2, GLint vstride, GLint vorder, const GLfloat* points) {
  map2(c, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}
void exec::Map2d(GlContext& c, GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder,
                 GLdouble v1, GLdouble v2, GLint vstride, GLint vorder, const GLdouble* points) {
  map2(c, target, float(u1), float(u2), ustride, uorder, float(v1), float(v2), vstride, vorder,
       points);
}

void exec::GetMapfv(GlContext& c, GLenum target, GLenum query, GLfloat* v) {
  get_map(c, target, query, v);
}
void exec::GetMapdv(GlContext& c, GLenum target, GLenum query, GLdouble* v) {
  get_map(c, target, query, v);
}
void exec::GetMapiv(GlContext& c, GLenum target, GLenum query, GLint* v) {
  get_map(c, target, query, v);
}

void exec::EvalCoord1f(GlContext& c, GLfloat u) { eval_coord1(c, u); }
void exec::EvalCoord1d(GlContext& c, GLdouble u) { eval_coord1(c, float(u)); }
void exec::EvalCoord1fv(GlContext& c, const GLfloat* u) {
  if (!u) return c.set_error(GL_INVALID_VALUE);
  eval_coord1(c, u[0]);
}
void exec::EvalCoord1dv(GlContext& c, const GLdouble* u) {
  if (!u) return c.set_error(GL_INVALID_VALUE);
  eval_coord1(c, float(u[0]));
}
void exec::EvalCoord2f(GlContext& c, GLfloat u, GLfloat v) { eval_coord2(c, u, v); }
void exec::EvalCoord2d(GlContext& c, GLdouble u, GLdouble v) { eval_coord2(c, float(u), float(v)); }
void exec::EvalCoord2fv(GlContext& c, const GLfloat* u) {
  if (!u) return c.set_error(GL_INVALID_VALUE);
  eval_coord2(c, u[0], u[1]);
}
void exec::EvalCoord2dv(GlContext& c, const GLdouble* u) {
  if (!u) return c.set_error(GL_INVALID_VALUE);
  eval_coord2(c, float(u[0]), float(u[1]));
}

// glMapGrid (section 5.1): the step is kept as Mesa keeps it, (u2 - u1) / n in floats.
void exec::MapGrid1f(GlContext& c, GLint un, GLfloat u1, GLfloat u2) {
  if (un < 1) return c.set_error(GL_INVALID_VALUE);
  EvalAttribs& a = c.eval.attribs;
  a.grid1_un = un, a.grid1_u1 = u1, a.grid1_u2 = u2, a.grid1_du = (u2 - u1) / float(un);
}
void exec::MapGrid1d(GlContext& c, GLint un, GLdouble u1, GLdouble u2) {
  exec::MapGrid1f(c, un, float(u1), float(u2));
}
void exec::MapGrid2f(GlContext& c, GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1,
                     GLfloat v2) {
  if (un < 1 || vn < 1) return c.set_error(GL_INVALID_VALUE);
  EvalAttribs& a = c.eval.attribs;
  a.grid2_un = un, a.grid2_u1 = u1, a.grid2_u2 = u2, a.grid2_du = (u2 - u1) / float(un);
  a.grid2_vn = vn, a.grid2_v1 = v1, a.grid2_v2 = v2, a.grid2_dv = (v2 - v1) / float(vn);
}
void exec::MapGrid2d(GlContext& c, GLint un, GLdouble u1, GLdouble u2, GLint vn, GLdouble v1,
                     GLdouble v2) {
  exec::MapGrid2f(c, un, float(u1), float(u2), vn, float(v1), float(v2));
}

void exec::EvalPoint1(GlContext& c, GLint i) {
  const EvalAttribs& a = c.eval.attribs;
  const float du = (a.grid1_u2 - a.grid1_u1) / float(a.grid1_un);
  eval_coord1(c, float(i) * du + a.grid1_u1);
}
void exec::EvalPoint2(GlContext& c, GLint i, GLint j) {
  const EvalAttribs& a = c.eval.attribs;
  const float du = (a.grid2_u2 - a.grid2_u1) / float(a.grid2_un);
  const float dv = (a.grid2_v2 - a.grid2_v1) / float(a.grid2_vn);
  eval_coord2(c, float(i) * du + a.grid2_u1, float(j) * dv + a.grid2_v1);
}

// glEvalMesh1 (equation 5.5): the grid points i1..i2 as points or one line strip; the
// parameter advances by repeated addition of the step, as Mesa's loop does (a 64-bit counter:
// i2 may be INT_MAX).
void exec::EvalMesh1(GlContext& c, GLenum mode, GLint i1, GLint i2) {
  GLenum prim;
  if (mode == GL_POINT)
    prim = GL_POINTS;
  else if (mode == GL_LINE)
    prim = GL_LINE_STRIP;
  else
    return c.set_error(GL_INVALID_ENUM);
  const EvalAttribs& a = c.eval.attribs;
  if (vertex_map(a.map1_enabled) < 0) return;
  const float du = a.grid1_du;
  float u = a.grid1_u1 + float(i1) * du;
  run::Begin(c, prim);
  for (std::int64_t i = i1; i <= i2; ++i, u += du) eval_coord1(c, u);
  run::End(c);
}

// glEvalMesh2 (equation 5.6): points, a line strip along each grid row then each column, or
// a triangle strip per pair of rows (v then v + dv at each u).
void exec::EvalMesh2(GlContext& c, GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2) {
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) return c.set_error(GL_INVALID_ENUM);
  const EvalAttribs& a = c.eval.attribs;
  if (vertex_map(a.map2_enabled) < 0) return;
  const float du = a.grid2_du, dv = a.grid2_dv;
  const float v1 = a.grid2_v1 + float(j1) * dv, u1 = a.grid2_u1 + float(i1) * du;
  float u, v;
  std::int64_t i, j;  // 64 bits: a range ending at INT_MAX must not overflow the counter
  switch (mode) {
    case GL_POINT:
      run::Begin(c, GL_POINTS);
      for (v = v1, j = j1; j <= j2; ++j, v += dv)
        for (u = u1, i = i1; i <= i2; ++i, u += du) eval_coord2(c, u, v);
      run::End(c);
      break;
    case GL_LINE:
      for (v = v1, j = j1; j <= j2; ++j, v += dv) {
        run::Begin(c, GL_LINE_STRIP);
        for (u = u1, i = i1; i <= i2; ++i, u += du) eval_coord2(c, u, v);
        run::End(c);
      }
      for (u = u1, i = i1; i <= i2; ++i, u += du) {
        run::Begin(c, GL_LINE_STRIP);
        for (v = v1, j = j1; j <= j2; ++j, v += dv) eval_coord2(c, u, v);
        run::End(c);
      }
      break;
    default:
      for (v = v1, j = j1; j < j2; ++j, v += dv) {
        run::Begin(c, GL_TRIANGLE_STRIP);
        for (u = u1, i = i1; i <= i2; ++i, u += du) {
          eval_coord2(c, u, v);
          eval_coord2(c, u, v + dv);
        }
        run::End(c);
      }
  }
}

// Display lists (section 5.4): the control points are copied now, tightly (stride = the
// target's components), and the command replays with them. Mesa records the same way,
// with the errors raised when the list runs: a target it does not know leaves no points
// (GL_INVALID_VALUE then, after the domain and order checks).
template <class T>
void save_map1(GlContext& c, GLenum target, T u1, T u2, GLint stride, GLint order, const T* points,
               void (*record)(GlContext&, GLenum, T, T, GLint, GLint, const T*, std::size_t)) {
  const int k = eval_components(target);
  std::vector<T> packed;
  if (points && k > 0 && order >= 1 && order <= kMaxEvalOrder) {
    for (int i = 0; i < order; ++i)
      for (int j = 0; j < k; ++j) packed.push_back(points[std::ptrdiff_t(i) * stride + j]);
  }
  record(c, target, u1, u2, k, order, packed.empty() ? nullptr : packed.data(), packed.size());
}

template <class T>
void save_map2(GlContext& c, GLenum target, T u1, T u2, GLint ustride, GLint uorder, T v1, T v2,
               GLint vstride, GLint vorder, const T* points,
               void (*record)(GlContext&, GLenum, T, T, GLint, GLint, T, T, GLint, GLint, const T*,
                              std::size_t)) {
  const int k = eval_components(target);
  std::vector<T> packed;
  if (points && k > 0 && uorder >= 1 && uorder <= kMaxEvalOrder && vorder >= 1 &&
      vorder <= kMaxEvalOrder) {
    for (int i = 0; i < uorder; ++i)
      for (int j = 0; j < vorder; ++j)
        for (int m = 0; m < k; ++m)
          packed.push_back(points[std::ptrdiff_t(i) * ustride + std::ptrdiff_t(j) * vstride + m]);
  }
  record(c, target, u1, u2, vorder * k, uorder, v1, v2, k, vorder,
         packed.empty() ? nullptr : packed.data(), packed.size());
}

void save::Map1f(GlContext& c, GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order,
                 const GLfloat* points) {
  save_map1<GLfloat>(c, target, u1, u2, stride, order, points, record::Map1f);
}
void save::Map1d(GlContext& c, GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
                 const GLdouble* points) {
  save_map1<GLdouble>(c, target, u1, u2, stride, order, points, record::Map1d);
}
void save::Map2f(GlContext& c, GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder,
                 GLfloat v1, GLfloat v2, GLint vstride, GLint vorder, const GLfloat* points) {
  save_map2<GLfloat>(c, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points,
                     record::Map2f);
}
void save::Map2d(GlContext& c, GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder,
                 GLdouble v1, GLdouble v2, GLint vstride, GLint vorder, const GLdouble* points) {
  save_map2<GLdouble>(c, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points,
                      record::Map2d);
}

}  // namespace shadelab::gl
