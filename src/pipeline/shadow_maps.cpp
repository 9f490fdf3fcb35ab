// Building shadow maps for a scene: for each light with "shadow", a depth picture of the
// opaque objects from the light (an orthographic box fitted around the scene for directional
// lights, a perspective cone for spots, a cube of six 90-degree views for point lights),
// drawn with the same pipeline, colour writes off.
#include "pipeline/shadow_maps.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace shadelab::detail {

namespace {

struct Bounds {
  glm::vec3 centre{0.0f};
  float radius = 1.0f;
};

Bounds scene_bounds(const Scene& scene) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const SceneObject& o : scene.objects) {
    if (!o.mesh) continue;
    for (const glm::vec3& p : o.mesh->positions) {
      glm::vec3 w(o.model * glm::vec4(p, 1.0f));
      lo = glm::min(lo, w);
      hi = glm::max(hi, w);
    }
  }
  if (lo.x > hi.x) return {};
  return {0.5f * (lo + hi), std::max(0.5f * glm::length(hi - lo), 1e-3f)};
}

glm::vec3 some_up(const glm::vec3& dir) {
  return std::abs(dir.y) > 0.9f * glm::length(dir) ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
}

// One face: the depth of every opaque object seen through light_view and light_proj.
ShadowMap::Face render_face(const Scene& scene, const glm::mat4& light_view, const glm::mat4& light_proj,
                            const glm::mat4& camera_view, int size) {
  Framebuffer fb;
  fb.resize(size, size);
  FragmentState frag;
  for (bool& c : frag.color_mask) c = false;
  ShadeState shade;
  shade.lighting = false;
  for (const SceneObject& o : scene.objects) {
    if (!o.mesh || o.blend.enabled) continue;  // transparent objects cast no shadow
    std::vector<glm::vec4> pos;
    pos.reserve(o.mesh->positions.size());
    glm::mat4 mv = light_view * o.model;
    for (const glm::vec3& p : o.mesh->positions) pos.push_back(mv * glm::vec4(p, 1.0f));
    VertexInput in;
    in.positions = pos;
    in.triangles = o.mesh->triangles;
    draw_triangles(fb, light_proj, Viewport{0, 0, size, size}, frag, shade, in);
  }
  return {light_proj * light_view * glm::inverse(camera_view), std::move(fb.depth)};
}

}  // namespace

std::vector<ShadowMap> build_shadow_maps(const Scene& scene, const glm::mat4& view) {
  std::vector<ShadowMap> maps(scene.lights.size());
  bool any = false;
  Bounds b = scene_bounds(scene);
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const SceneLight& sl = scene.lights[i];
    if (!sl.shadow || !sl.light.enabled) continue;
    any = true;
    ShadowMap& m = maps[i];
    m.size = sl.shadow_map_size;
    m.bias = sl.shadow_bias;
    m.pcf = sl.shadow_pcf;
    glm::vec4 pos = sl.eye_space ? glm::inverse(view) * sl.light.position : sl.light.position;
    if (pos.w == 0.0f) {  // directional: an orthographic box around the scene
      glm::vec3 dir = glm::normalize(glm::vec3(pos));
      glm::mat4 lv = glm::lookAt(b.centre + dir * (2.0f * b.radius), b.centre, some_up(dir));
      glm::mat4 lp = glm::ortho(-b.radius, b.radius, -b.radius, b.radius, 0.5f * b.radius, 3.5f * b.radius);
      m.faces.push_back(render_face(scene, lv, lp, view, m.size));
      m.texel_at_unit = 2.0f * b.radius / float(m.size);
      continue;
    }
    glm::vec3 l = glm::vec3(pos) / pos.w;
    float far = glm::length(l - b.centre) + b.radius + 1.0f;
    float near = std::max(far * 1e-4f, 0.01f);
    m.perspective = true;
    m.light_eye = glm::vec3(view * glm::vec4(l, 1.0f));
    glm::vec3 spot = sl.eye_space ? glm::vec3(glm::inverse(view) * glm::vec4(sl.light.spot_direction, 0.0f))
                                  : sl.light.spot_direction;
    if (sl.light.spot_cutoff < 89.0f && glm::length(spot) > 0.0f) {  // spot: one cone
      float fov = 2.0f * sl.light.spot_cutoff + 4.0f;
      glm::mat4 lv = glm::lookAt(l, l + spot, some_up(spot));
      m.faces.push_back(render_face(scene, lv, glm::perspective(glm::radians(fov), 1.0f, near, far), view, m.size));
      m.texel_at_unit = 2.0f * std::tan(glm::radians(0.5f * fov)) / float(m.size);
      continue;
    }
    const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    glm::mat4 lp = glm::perspective(glm::radians(90.0f), 1.0f, near, far);
    for (const glm::vec3& a : axes) m.faces.push_back(render_face(scene, glm::lookAt(l, l + a, some_up(a)), lp, view, m.size));
    m.texel_at_unit = 2.0f / float(m.size);
  }
  if (!any) maps.clear();
  return maps;
}

}  // namespace shadelab::detail
