// The scene front end: camera and lights into eye space, each object's vertices into eye
// space, opaque objects first and blended ones after, back to front, through draw_triangles.
#include <algorithm>
#include <chrono>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "shadelab/render.hpp"
#include "pipeline/shadow_maps.hpp"
#include "shadelab/shadow.hpp"

namespace shadelab {

namespace {

// GL_POSITION and GL_SPOT_DIRECTION are transformed by the modelview in force at glLight
// (GL 1.5 section 2.14.2); for world-space scene lights that is the camera's view matrix.
std::vector<Light> lights_in_eye_space(const Scene& scene, const glm::mat4& view) {
  std::vector<Light> out;
  for (const SceneLight& sl : scene.lights) {
    Light l = sl.light;
    if (!sl.eye_space) {
      l.position = view * l.position;
      l.spot_direction = glm::mat3(view) * l.spot_direction;
    }
    out.push_back(l);
  }
  return out;
}

struct EyeMesh {
  std::vector<glm::vec4> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec4> texcoords;  ///< scaled by the object's texture_repeat; q = 1
};

EyeMesh to_eye_space(const Mesh& mesh, const glm::mat4& modelview) {
  EyeMesh eye;
  eye.positions.reserve(mesh.positions.size());
  for (const glm::vec3& p : mesh.positions) eye.positions.push_back(modelview * glm::vec4(p, 1.0f));
  // Normals by the inverse transpose, then normalized (as with GL_NORMALIZE).
  glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(modelview)));
  eye.normals.reserve(mesh.normals.size());
  for (const glm::vec3& n : mesh.normals) {
    glm::vec3 e = normal_matrix * n;
    float len = glm::length(e);
    eye.normals.push_back(len > 0.0f ? e / len : glm::vec3(0.0f, 0.0f, 1.0f));
  }
  return eye;
}

// Eye-space depth of the centre of an object's bounding box, for back-to-front ordering.
float eye_depth(const SceneObject& obj, const glm::mat4& view) {
  if (!obj.mesh || obj.mesh->positions.empty()) return 0.0f;
  glm::vec3 lo = obj.mesh->positions[0], hi = lo;
  for (const glm::vec3& p : obj.mesh->positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return (view * obj.model * glm::vec4(0.5f * (lo + hi), 1.0f)).z;
}

// Opaque objects in file order, then blended ones from far to near (SPEC section 5).
std::vector<const SceneObject*> draw_order(const Scene& scene, const glm::mat4& view) {
  std::vector<const SceneObject*> opaque, blended;
  for (const SceneObject& o : scene.objects) (o.blend.enabled ? blended : opaque).push_back(&o);
  std::stable_sort(blended.begin(), blended.end(), [&](const SceneObject* a, const SceneObject* b) {
    return eye_depth(*a, view) < eye_depth(*b, view);  // more negative z is farther
  });
  opaque.insert(opaque.end(), blended.begin(), blended.end());
  return opaque;
}

// One draw of an object: its model matrix and fragment state, and for shadows the single
// unlit colour that replaces its material, vertex colours and texture.
struct ObjectPass {
  glm::mat4 model;
  FragmentState frag;
  std::optional<glm::vec4> shadow_color;
};

FragmentState object_state(const SceneObject& obj) {
  FragmentState frag;
  frag.blend = obj.blend;
  // Blended objects show both faces (SPEC section 5), whatever their cull setting.
  frag.cull = obj.blend.enabled ? CullMode::kNone : obj.cull;
  return frag;
}

void draw_object(Framebuffer& fb, const Scene& scene, const SceneObject& obj,
                 const glm::mat4& view, const glm::mat4& projection,
                 std::span<const Light> lights, const RenderOptions& options,
                 const ObjectPass& pass, RenderStats* stats,
                 std::span<const ShadowMap> shadow_maps = {}) {
  if (!obj.mesh) return;
  EyeMesh eye = to_eye_space(*obj.mesh, view * pass.model);
  bool shadow = pass.shadow_color.has_value();
  ShadeState shade;
  shade.lighting = obj.lighting && !shadow;
  shade.shading = options.shading.value_or(obj.shading);
  shade.model = scene.light_model;
  shade.lights = lights;
  shade.front = obj.front;
  shade.back = obj.back.value_or(obj.front);
  shade.textures[0].texture = shadow ? nullptr : obj.texture.get();
  shade.shadow_maps = shadow_maps;
  shade.textures[0].env = obj.texture_env;
  VertexInput in;
  in.positions = eye.positions;
  in.normals = eye.normals;
  if (!shadow) in.colors = obj.mesh->colors;
  if (shade.textures[0].texture) {
    for (const glm::vec2& t : obj.mesh->texcoords) eye.texcoords.emplace_back(t * obj.texture_repeat, 0.0f, 1.0f);
    in.texcoords[0] = eye.texcoords;
  }
  in.constant_color = shadow ? *pass.shadow_color : obj.color;
  in.triangles = obj.mesh->triangles;
  Viewport vp{0, 0, fb.width, fb.height, 0.0f, 1.0f};
  draw_triangles(fb, projection, vp, pass.frag, shade, in, stats, options.context);
}

// The stencil value marking a shadow's receiver: 1 + the index of the first shadow naming it.
std::uint8_t receiver_mark(const Scene& scene, const SceneObject& obj) {
  for (std::size_t i = 0; i < scene.shadows.size(); ++i) {
    if (scene.shadows[i].receiver == obj.name) return static_cast<std::uint8_t>(i + 1);
  }
  return 0;
}

// The projection that flattens world space onto the shadow's plane from its light, or nothing
// when the light is below the plane (the receiver's upper side is then unlit).
std::optional<glm::mat4> shadow_matrix(const Scene& scene, const PlanarShadow& sh, const glm::mat4& view) {
  if (sh.light < 0 || std::size_t(sh.light) >= scene.lights.size()) return std::nullopt;
  const SceneLight& sl = scene.lights[std::size_t(sh.light)];
  glm::vec4 pos = sl.eye_space ? glm::inverse(view) * sl.light.position : sl.light.position;
  glm::vec3 n(sh.plane);
  if (pos.w == 0.0f) {
    glm::vec3 dir(pos);
    if (glm::dot(n, dir) <= 0.0f) return std::nullopt;
    return directional_light_shadow(dir, sh.plane);
  }
  glm::vec3 l = glm::vec3(pos) / pos.w;
  if (glm::dot(n, l) + sh.plane.w <= 0.0f) return std::nullopt;
  return point_light_shadow(l, sh.plane);
}

// Every object but the receiver, flattened onto the plane, only where the receiver's mark is
// in the stencil; the mark is cleared as the shadow is drawn, so overlapping shadow triangles
// darken a pixel once. The polygon offset pulls the shadow in front of the receiving plane.
void draw_shadow(Framebuffer& fb, const Scene& scene, std::size_t index, const glm::mat4& view,
                 const glm::mat4& projection, std::span<const Light> lights,
                 const RenderOptions& options, RenderStats* stats) {
  const PlanarShadow& sh = scene.shadows[index];
  std::optional<glm::mat4> m = shadow_matrix(scene, sh, view);
  if (!m) return;
  std::uint8_t mark = 0;
  for (const SceneObject& o : scene.objects) {
    if (o.name == sh.receiver) mark = receiver_mark(scene, o);
  }
  ObjectPass pass;
  pass.shadow_color = sh.color;
  pass.frag.depth_func = CompareFunc::kLequal;
  pass.frag.depth_write = false;
  pass.frag.polygon_offset = true;
  pass.frag.offset_factor = -1.0f;
  pass.frag.offset_units = -4.0f;
  pass.frag.blend = {sh.color.a < 1.0f, BlendFactor::kSrcAlpha, BlendFactor::kOneMinusSrcAlpha};
  pass.frag.stencil = {true, CompareFunc::kEqual, mark, 0xff, 0xff,
                       StencilOp::kKeep, StencilOp::kKeep, StencilOp::kZero};
  for (const SceneObject& o : scene.objects) {
    if (o.name == sh.receiver) continue;
    pass.model = *m * o.model;
    draw_object(fb, scene, o, view, projection, lights, options, pass, stats);
  }
}

// Averages each n x n block of `big` into one pixel (ordered-grid supersampling resolve).
Image downsample(const Image& big, int n) {
  Image out;
  out.width = big.width / n;
  out.height = big.height / n;
  out.rgba.resize(std::size_t(out.width) * out.height * 4);
  int count = n * n;
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      for (int c = 0; c < 4; ++c) {
        int sum = 0;
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) sum += big.pixel(x * n + i, y * n + j)[c];
        out.pixel(x, y)[c] = static_cast<std::uint8_t>((sum + count / 2) / count);
      }
    }
  }
  return out;
}

int grid_size(int samples) {
  int n = 1;
  while ((n + 1) * (n + 1) <= samples) ++n;
  return n;
}

}  // namespace

Image render_scene(const Scene& scene, const RenderOptions& requested, RenderStats* stats) {
  auto start = std::chrono::steady_clock::now();
  RenderOptions options = requested;  // the fast pipeline unless `reference` (src/fast/)
  std::optional<PipelineContext> own_context;
  if (options.reference) options.context = nullptr;
  else if (!options.context) options.context = &own_context.emplace(options.threads);
  int n = grid_size(options.samples.value_or(scene.samples));
  Framebuffer fb;
  fb.resize(scene.width * n, scene.height * n);
  fb.clear_color(scene.background, options.context);
  glm::mat4 view = scene.camera.view_matrix();
  glm::mat4 projection =
      scene.camera.projection_matrix(float(scene.width) / float(std::max(scene.height, 1)));
  std::vector<Light> lights = lights_in_eye_space(scene, view);
  std::vector<ShadowMap> shadow_maps = detail::build_shadow_maps(scene, view);
  fb.clear_stencil(0);
  bool exact = scene.transparency == Scene::Transparency::kExact;
  FragmentCapture capture;
  bool shadows_drawn = false;
  for (const SceneObject* obj : draw_order(scene, view)) {
    if (options.deadline && std::chrono::steady_clock::now() > *options.deadline) {
      if (stats) stats->interrupted = true;
      break;
    }
    // Shadows go on the opaque picture, before anything blended is drawn over it.
    if (obj->blend.enabled && !shadows_drawn) {
      for (std::size_t i = 0; i < scene.shadows.size(); ++i) draw_shadow(fb, scene, i, view, projection, lights, options, stats);
      shadows_drawn = true;
      if (exact) {
        std::size_t pixels = std::size_t(fb.width) * std::size_t(fb.height);
        // The lists themselves, then entries; a list's growth by doubling can hold up to twice
        // its entries, so each entry is counted twice and the total stays within the budget.
        std::size_t lists = pixels * sizeof(capture.pixels[0]);
        capture.limit = options.max_fragment_memory > lists
                            ? (options.max_fragment_memory - lists) / (2 * sizeof(FragmentCapture::Entry))
                            : 0;
        capture.pixels.resize(pixels);
      }
    }
    ObjectPass pass{obj->model, object_state(*obj), std::nullopt};
    if (std::uint8_t mark = receiver_mark(scene, *obj)) {
      pass.frag.stencil = {true, CompareFunc::kAlways, mark, 0xff, 0xff,
                           StencilOp::kKeep, StencilOp::kKeep, StencilOp::kReplace};
    }
    if (exact && obj->blend.enabled) {
      pass.frag.capture = &capture;  // tested against the opaque depth, composited below
      pass.frag.depth_write = false;
    }
    draw_object(fb, scene, *obj, view, projection, lights, options, pass, stats, shadow_maps);
  }
  if (!shadows_drawn) {
    for (std::size_t i = 0; i < scene.shadows.size(); ++i) draw_shadow(fb, scene, i, view, projection, lights, options, stats);
  }
  if (exact) {
    if (stats) stats->fragments_dropped += capture.dropped;
    resolve_fragments(fb, capture);
  }
  Image image = fb.to_image();
  if (n > 1) {
    auto t = std::chrono::steady_clock::now();
    image = downsample(image, n);
    if (stats) {
      stats->ms_resolve +=
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
    }
  }
  if (stats) {
    stats->ms_total +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  return image;
}

}  // namespace shadelab
