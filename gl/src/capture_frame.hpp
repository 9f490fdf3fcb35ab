// The frame being captured (capture.hpp), shared by the recording (capture.cpp) and the
// writing of its scene and OBJ files (capture_scene.cpp). Private to the GL library.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/src/context.hpp"

namespace shadelab::gl {

enum class Blend { kNone, kAlpha, kAdditive };

// What makes triangles one object: every key of a scene object they need.
struct ObjectKey {
  bool lit = true;
  bool flat = false;
  CullMode cull = CullMode::kNone;
  Blend blend = Blend::kNone;
  Material front, back;
  int texture = -1;  // FrameCapture::textures index of texture unit 0's texture, -1: none
  TextureEnvMode env = TextureEnvMode::kModulate;

  bool operator==(const ObjectKey& o) const {
    return lit == o.lit && flat == o.flat && cull == o.cull && blend == o.blend && texture == o.texture &&
           (texture < 0 || env == o.env) && (!lit || (same(front, o.front) && same(back, o.back)));
  }
  static bool same(const Material& a, const Material& b) {
    return a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular &&
           a.emission == b.emission && a.shininess == b.shininess;
  }
};

struct Object {
  ObjectKey key;
  int first_draw = 0;
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec4> colors;  // unlit objects
  std::vector<glm::vec2> texcoords;  // textured objects: (s / q, t / q) of unit 0
  std::vector<Triangle> triangles;
  // Per vertex of the draw being added: its index here, or UINT32_MAX (reset at the first
  // triangle of each draw that reaches this object, `remap_draw`).
  std::vector<std::uint32_t> remap;
  int remap_draw = -1;
};

// What a scene file cannot hold, counted for the caption.
struct Omitted {
  std::size_t lines = 0, points = 0, unfilled = 0, textured = 0, fogged = 0, pixels = 0;
  std::size_t no_depth_test = 0, over_limit = 0, behind_eye = 0, mixed = 0, blend_other = 0;
  std::size_t clamped = 0, lights_differ = 0, views_differ = 0, merged = 0;
  std::size_t more_units = 0;  // draws textured by units past the first: unit 0's kept
  std::size_t texture_settings = 0;  // textures whose settings the scene approximates
};

// A 2D texture a captured draw read: its base level as it was then, and its parameters.
struct CapturedTexture {
  const Texture* source = nullptr;
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // rows from t = 0
  TextureWrap wrap_s = TextureWrap::kRepeat, wrap_t = TextureWrap::kRepeat;
  TextureFilter min_filter = TextureFilter::kNearestMipmapLinear, mag_filter = TextureFilter::kLinear;
  glm::vec4 border{0.0f};  // GL_TEXTURE_BORDER_COLOR (the scene's GL_CLAMP blends with black)
};


struct FrameCapture {
  std::string path;
  int frame = 1;        // the chosen frame, from 1
  int ended = 0;        // frames ended so far
  bool written = false;
  int draws = 0;        // draws recorded in this frame
  std::vector<Object> objects;
  std::vector<CapturedTexture> textures;
  std::size_t triangles = 0;
  // Fixed by the frame's first draw.
  bool have_view = false;
  glm::mat4 projection{1.0f};
  Viewport viewport;
  bool have_lights = false;
  std::array<Light, kMaxLights> lights;
  LightModel model;
  glm::vec4 background{0.0f};
  Omitted omitted;

  void restart() {
    draws = 0;
    objects.clear();
    textures.clear();
    triangles = 0;
    have_view = have_lights = false;
    omitted = {};
  }
};

/// Writes the frame as its scene file and OBJ files (`ended`: the frame was shown; else the
/// program stopped while drawing it) and marks it written. Nothing is printed: a file that
/// cannot be written is missing, which `shadelab run` reports.
void write_scene(FrameCapture& f, bool ended);

}  // namespace shadelab::gl
