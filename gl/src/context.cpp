// GlContext construction with OpenGL 1.1's initial state, the thread's current context, and
// colour-material tracking. Entry points live in the other files; nothing here draws.
#include "gl/src/context.hpp"

#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "gl/src/capture.hpp"
#include "gl/src/texture.hpp"

namespace shadelab::gl {

GlContext::GlContext(GLenum format, int depth, int stencil, const GlContext* share)
    : buffer_format(format), depth_bits(depth), stencil_bits(stencil) {
  for (int i = 0; i < kMaxLights; ++i) {
    lighting.lights[std::size_t(i)] = default_light(i);
    lighting.lights[std::size_t(i)].enabled = false;  // every GL_LIGHTi starts disabled
  }
  // GL's default back material equals the front one; both are Material's defaults.
  // Each target's default texture (name 0), with the target's dimensions: one object the
  // texture units share.
  for (GLenum target : {GLenum(GL_TEXTURE_1D), GLenum(GL_TEXTURE_2D), GLenum(GL_TEXTURE_3D), GLenum(GL_TEXTURE_CUBE_MAP), kTextureRectangle}) {
    auto object = std::make_shared<TextureObject>();
    set_texture_target(*object, target);
    for (TextureUnitState& unit : textures.units) {
      TextureBinding& b = unit.binding(target);
      b.default_object = b.object = object;
    }
  }
  textures.names = share ? share->textures.names : std::make_shared<TextureNames>();
  lists.names = share ? share->lists.names : std::make_shared<ListNames>();
  buffer_names = share ? share->buffer_names : std::make_shared<BufferNames>();
  // glTexGen's initial planes: s = x, t = y, r = q = 0 (GL 1.1 section 2.10.4).
  for (TextureUnitState& unit : textures.units) {
    unit.gen[0].object_plane = unit.gen[0].eye_plane = glm::vec4(1, 0, 0, 0);
    unit.gen[1].object_plane = unit.gen[1].eye_plane = glm::vec4(0, 1, 0, 0);
  }
  const char* reference = std::getenv("SHADELAB_REFERENCE");
  use_reference = reference && *reference && std::string_view(reference) != "0";
  if (const char* stats = std::getenv("SHADELAB_STATS")) stats_path = stats;
  capture_init(*this);
}

// With SHADELAB_STATS, one line of counts for the context's life (nothing when the file cannot
// be opened: the library reports nothing of its own accord).
GlContext::~GlContext() {
  capture_context_end(*this);
  if (!pipeline || stats_path.empty()) return;
  pipeline->finish_draws();
  const RenderStats n = pipeline->take_counts();
  if (std::FILE* f = std::fopen(stats_path.c_str(), "a")) {
    std::fprintf(f, "shadelab-stats target=%s draws=%llu deferred=%llu triangles=%llu fragments=%llu simd=%llu reference=%llu shaded=%llu\n",
                 PipelineContext::simd_target().c_str(), (unsigned long long)n.draws, (unsigned long long)n.draws_deferred,
                 (unsigned long long)n.triangles_in, (unsigned long long)n.fragments,
                 (unsigned long long)(n.fragments - n.fragments_reference),
                 (unsigned long long)n.fragments_reference, (unsigned long long)n.pixels_shaded);
    std::fclose(f);
  }
}

MatrixStack& GlContext::current_stack() {
  switch (matrix_mode) {
    case GL_PROJECTION: return projection;
    case GL_TEXTURE: return texture_matrix();
    default: return modelview;
  }
}

void set_initial_window_state(GlContext& c, int width, int height) {
  c.raster.viewport.width = width;
  c.raster.viewport.height = height;
  c.raster.scissor_width = width;
  c.raster.scissor_height = height;
  c.ever_current = true;
}

namespace {

void track(Material& m, GLenum mode, const glm::vec4& color) {
  switch (mode) {
    case GL_AMBIENT: m.ambient = color; break;
    case GL_DIFFUSE: m.diffuse = color; break;
    case GL_SPECULAR: m.specular = color; break;
    case GL_EMISSION: m.emission = color; break;
    case GL_AMBIENT_AND_DIFFUSE: m.ambient = m.diffuse = color; break;
    default: break;
  }
}

}  // namespace

void apply_color_material(GlContext& c) {
  LightingState& l = c.lighting;
  if (!l.color_material) return;
  if (c.prim.active && c.prim.deferred_lighting) {
    Material front = l.front, back = l.back;
    if (l.color_material_face != GL_BACK) track(front, l.color_material_mode, c.current.color);
    if (l.color_material_face != GL_FRONT) track(back, l.color_material_mode, c.current.color);
    auto same = [](const Material& a, const Material& b) {
      return a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular &&
             a.emission == b.emission && a.shininess == b.shininess;
    };
    if (!same(front, l.front) || !same(back, l.back)) settle_lighting(c);
  }
  if (l.color_material_face != GL_BACK) track(l.front, l.color_material_mode, c.current.color);
  if (l.color_material_face != GL_FRONT) track(l.back, l.color_material_mode, c.current.color);
}

}  // namespace shadelab::gl
