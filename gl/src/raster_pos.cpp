// The current raster position (GL 1.1 section 2.12): glRasterPos{2,3,4}{s,i,f,d}[v]. The
// position goes through the modelview and projection like a vertex, is clipped (a point
// outside the view volume makes the raster position invalid and changes nothing else), is
// mapped to window coordinates, and takes the vertex's data: the colour lit with the front
// material by the core's light_point (section 2.13; no copy of the equation here) or the
// current colour, texture coordinates through the texture matrix, and the eye-space distance
// for fog. glWindowPos (GL 1.4; GL 1.5 section 2.12) sets it directly in window coordinates.
// Only state; glBitmap, glDrawPixels and glCopyPixels draw at it.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"
#include "gl/src/convert.hpp"
#include "gl/src/texgen.hpp"
#include "shadelab/lighting.hpp"

namespace shadelab::gl {
namespace {

// m * v summed in Mesa's order (m0 x + m1 y + m2 z + m3 w, left to right), so that window
// coordinates come out as Mesa's to the last bit (glDrawPixels rounds them).
glm::vec4 transform(const glm::mat4& m, const glm::vec4& v) {
  glm::vec4 r;
  for (int i = 0; i < 4; ++i) r[i] = m[0][i] * v.x + m[1][i] * v.y + m[2][i] * v.z + m[3][i] * v.w;
  return r;
}

// Section 2.12: inside the view volume, -w <= x, y, z <= w. Coordinates that are not finite
// make no raster position (Mesa would keep NaN ones, which no later command can use).
bool inside_view_volume(const glm::vec4& clip) {
  if (!std::isfinite(clip.x) || !std::isfinite(clip.y) || !std::isfinite(clip.z) || !std::isfinite(clip.w)) {
    return false;
  }
  return !(clip.z < -clip.w || clip.z > clip.w || clip.x > clip.w || clip.x < -clip.w ||
           clip.y > clip.w || clip.y < -clip.w);
}

// Window coordinates (section 2.10.1) in single precision, as Mesa computes them.
glm::vec3 window_of(const Viewport& vp, const glm::vec4& clip) {
  const float d = clip.w == 0.0f ? 1.0f : 1.0f / clip.w;
  const float sx = float(vp.width) / 2.0f, tx = sx + float(vp.x);
  const float sy = float(vp.height) / 2.0f, ty = sy + float(vp.y);
  const float sz = 0.5f * (vp.far_depth - vp.near_depth), tz = 0.5f * (vp.near_depth + vp.far_depth);
  return {clip.x * d * sx + tx, clip.y * d * sy + ty, clip.z * d * sz + tz};
}

// The eye-space normal a vertex is lit with: the inverse transpose of the modelview, then
// GL_NORMALIZE or GL_RESCALE_NORMAL (sections 2.10.3, 2.13).
glm::vec3 eye_normal(const GlContext& c, const glm::mat4& modelview) {
  const glm::mat3 inv = glm::inverse(glm::mat3(modelview));
  glm::vec3 n = glm::transpose(inv) * c.current.normal;
  if (c.lighting.normalize) {
    const float len = glm::length(n);
    return len > 0.0f ? n / len : n;
  }
  if (c.lighting.rescale_normal) {
    n /= std::sqrt(inv[0][2] * inv[0][2] + inv[1][2] * inv[1][2] + inv[2][2] * inv[2][2]);
  }
  return n;
}

// The raster colour: lit as a vertex with the front material and colour clamped (section
// 2.13.6), or the current colour as it is, as Mesa keeps it.
void set_color(GlContext& c, const glm::vec4& eye, const glm::mat4& modelview) {
  RasterPosition& r = c.raster_pos;
  if (!c.lighting.enabled) {  // the current colours as they are (GL 1.4: the secondary too)
    r.color = c.current.color;
    r.secondary = c.current.secondary;
    return;
  }
  std::vector<Light> lights;
  for (const Light& l : c.lighting.lights) {
    if (l.enabled) lights.push_back(l);
  }
  const glm::vec3 pos = eye.w != 0.0f ? glm::vec3(eye) / eye.w : glm::vec3(eye);
  const LitColor lit = light_point(c.lighting.model, lights, c.lighting.front, {pos, eye_normal(c, modelview), nullptr});
  r.color = glm::clamp(glm::vec4(finite_or_zero(lit.primary.r), finite_or_zero(lit.primary.g),
                                 finite_or_zero(lit.primary.b), finite_or_zero(lit.primary.a)),
                       glm::vec4(0.0f), glm::vec4(1.0f));
  const glm::vec3 s = glm::clamp(lit.secondary, glm::vec3(0.0f), glm::vec3(1.0f));
  r.secondary = glm::vec4(finite_or_zero(s.r), finite_or_zero(s.g), finite_or_zero(s.b), 0.0f);
}

void raster_pos(GlContext& c, double x, double y, double z, double w) {
  const glm::vec4 object{float(x), float(y), float(z), float(w)};
  const glm::mat4& modelview = c.modelview.top();
  const glm::vec4 eye = transform(modelview, object);
  const glm::vec4 clip = transform(c.projection.top(), eye);
  RasterPosition& r = c.raster_pos;
  if (!inside_view_volume(clip)) {
    r.valid = false;
    return;
  }
  r.valid = true;
  r.window = glm::vec4(window_of(c.raster.viewport, clip), clip.w);
  // GL 1.4 section 2.12: the fog coordinate, or the eye distance (Mesa's choice of distance).
  r.distance = c.fog.coord_source == GL_FOG_COORDINATE ? c.current.fog_coord
                                                        : std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
  set_color(c, eye, modelview);
  // Every unit's texture coordinates, generated as a vertex's (section 2.12; GL 1.3's cube-map
  // modes too), through the unit's texture matrix.
  for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {
    const TextureUnitState& unit = c.textures.units[u];
    glm::vec4 tc = c.current.texcoords[u];
    if (unit.any_texgen()) {
      const glm::vec3 n = texgen_needs_normal(unit) ? eye_normal(c, modelview) : glm::vec3(0.0f);
      tc = generate_texcoords(unit, tc, object, eye, n);
    }
    r.texcoords[u] = transform(c.texture_matrices[u].top(), tc);
  }
  select_raster_position(c);
}

template <class T>
void raster_pos_v(GlContext& c, const T* v, int n) {
  if (!v) return c.set_error(GL_INVALID_VALUE);
  raster_pos(c, double(v[0]), double(v[1]), n > 2 ? double(v[2]) : 0.0, n > 3 ? double(v[3]) : 1.0);
}

// GL 1.5 section 2.12, glWindowPos: x and y are the window coordinates, z in [0, 1] is mapped
// into the depth range (in single precision, as Mesa computes it), w is 1. Nothing is
// transformed, lit or clipped: the position is valid, the colours are the current colour and
// secondary colour (clamped, as Mesa clamps them), the texture coordinates are the current
// ones (no texture matrix), the distance is the current fog coordinate when that is the fog
// source, else 0.
void window_pos(GlContext& c, double x, double y, double z) {
  RasterPosition& r = c.raster_pos;
  const Viewport& vp = c.raster.viewport;
  const float zc = std::clamp(float(z), 0.0f, 1.0f);
  r.valid = true;
  r.window = glm::vec4(float(x), float(y), zc * (vp.far_depth - vp.near_depth) + vp.near_depth, 1.0f);
  r.color = glm::clamp(c.current.color, glm::vec4(0.0f), glm::vec4(1.0f));
  r.secondary = glm::clamp(c.current.secondary, glm::vec4(0.0f), glm::vec4(1.0f));
  r.distance = c.fog.coord_source == GL_FOG_COORDINATE ? c.current.fog_coord : 0.0f;
  r.texcoords = c.current.texcoords;
  select_raster_position(c);
}

template <class T>
void window_pos_v(GlContext& c, const T* v, int n) {
  if (!v) return c.set_error(GL_INVALID_VALUE);
  window_pos(c, double(v[0]), double(v[1]), n > 2 ? double(v[2]) : 0.0);
}

}  // namespace

void exec::RasterPos2d(GlContext& c, GLdouble x, GLdouble y) { raster_pos(c, x, y, 0.0, 1.0); }
void exec::RasterPos2f(GlContext& c, GLfloat x, GLfloat y) { raster_pos(c, x, y, 0.0, 1.0); }
void exec::RasterPos2i(GlContext& c, GLint x, GLint y) { raster_pos(c, x, y, 0.0, 1.0); }
void exec::RasterPos2s(GlContext& c, GLshort x, GLshort y) { raster_pos(c, x, y, 0.0, 1.0); }
void exec::RasterPos3d(GlContext& c, GLdouble x, GLdouble y, GLdouble z) { raster_pos(c, x, y, z, 1.0); }
void exec::RasterPos3f(GlContext& c, GLfloat x, GLfloat y, GLfloat z) { raster_pos(c, x, y, z, 1.0); }
void exec::RasterPos3i(GlContext& c, GLint x, GLint y, GLint z) { raster_pos(c, x, y, z, 1.0); }
void exec::RasterPos3s(GlContext& c, GLshort x, GLshort y, GLshort z) { raster_pos(c, x, y, z, 1.0); }
void exec::RasterPos4d(GlContext& c, GLdouble x, GLdouble y, GLdouble z, GLdouble w) { raster_pos(c, x, y, z, w); }
void exec::RasterPos4f(GlContext& c, GLfloat x, GLfloat y, GLfloat z, GLfloat w) { raster_pos(c, x, y, z, w); }
void exec::RasterPos4i(GlContext& c, GLint x, GLint y, GLint z, GLint w) { raster_pos(c, x, y, z, w); }
void exec::RasterPos4s(GlContext& c, GLshort x, GLshort y, GLshort z, GLshort w) { raster_pos(c, x, y, z, w); }
void exec::RasterPos2dv(GlContext& c, const GLdouble* v) { raster_pos_v(c, v, 2); }
void exec::RasterPos2fv(GlContext& c, const GLfloat* v) { raster_pos_v(c, v, 2); }
void exec::RasterPos2iv(GlContext& c, const GLint* v) { raster_pos_v(c, v, 2); }
void exec::RasterPos2sv(GlContext& c, const GLshort* v) { raster_pos_v(c, v, 2); }
void exec::RasterPos3dv(GlContext& c, const GLdouble* v) { raster_pos_v(c, v, 3); }
void exec::RasterPos3fv(GlContext& c, const GLfloat* v) { raster_pos_v(c, v, 3); }
void exec::RasterPos3iv(GlContext& c, const GLint* v) { raster_pos_v(c, v, 3); }
void exec::RasterPos3sv(GlContext& c, const GLshort* v) { raster_pos_v(c, v, 3); }
void exec::RasterPos4dv(GlContext& c, const GLdouble* v) { raster_pos_v(c, v, 4); }
void exec::RasterPos4fv(GlContext& c, const GLfloat* v) { raster_pos_v(c, v, 4); }
void exec::RasterPos4iv(GlContext& c, const GLint* v) { raster_pos_v(c, v, 4); }
void exec::RasterPos4sv(GlContext& c, const GLshort* v) { raster_pos_v(c, v, 4); }


void exec::WindowPos2d(GlContext& c, GLdouble x, GLdouble y) { window_pos(c, x, y, 0.0); }
void exec::WindowPos2f(GlContext& c, GLfloat x, GLfloat y) { window_pos(c, x, y, 0.0); }
void exec::WindowPos2i(GlContext& c, GLint x, GLint y) { window_pos(c, x, y, 0.0); }
void exec::WindowPos2s(GlContext& c, GLshort x, GLshort y) { window_pos(c, x, y, 0.0); }
void exec::WindowPos3d(GlContext& c, GLdouble x, GLdouble y, GLdouble z) { window_pos(c, x, y, z); }
void exec::WindowPos3f(GlContext& c, GLfloat x, GLfloat y, GLfloat z) { window_pos(c, x, y, z); }
void exec::WindowPos3i(GlContext& c, GLint x, GLint y, GLint z) { window_pos(c, x, y, z); }
void exec::WindowPos3s(GlContext& c, GLshort x, GLshort y, GLshort z) { window_pos(c, x, y, z); }
void exec::WindowPos2dv(GlContext& c, const GLdouble* v) { window_pos_v(c, v, 2); }
void exec::WindowPos2fv(GlContext& c, const GLfloat* v) { window_pos_v(c, v, 2); }
void exec::WindowPos2iv(GlContext& c, const GLint* v) { window_pos_v(c, v, 2); }
void exec::WindowPos2sv(GlContext& c, const GLshort* v) { window_pos_v(c, v, 2); }
void exec::WindowPos3dv(GlContext& c, const GLdouble* v) { window_pos_v(c, v, 3); }
void exec::WindowPos3fv(GlContext& c, const GLfloat* v) { window_pos_v(c, v, 3); }
void exec::WindowPos3iv(GlContext& c, const GLint* v) { window_pos_v(c, v, 3); }
void exec::WindowPos3sv(GlContext& c, const GLshort* v) { window_pos_v(c, v, 3); }

}  // namespace shadelab::gl
