// Random draws for the fast pipeline's differential tests: meshes (soups of tiny to huge
// triangles, shared-vertex spheres and walls, clipped and degenerate ones), lights, materials,
// textures, shadow maps, projections, viewports and fragment states, all from one seed.
#pragma once

#include <memory>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "shadelab/pipeline.hpp"
#include "support/sanitizers.hpp"

namespace shadelab::test {

/// How many of a differential test's `n` random cases run: all of them, but a quarter in the
/// ThreadSanitizer build. That run is there for the threads' synchronization, which the first
/// cases exercise as well as the rest, at some twenty times the cost of a plain run; every
/// case still runs in the plain and the AddressSanitizer builds.
constexpr unsigned random_cases(unsigned n) { return kThreadSanitizer ? (n + 3) / 4 : n; }

/// One draw_triangles call and everything its spans point into.
struct RandomDraw {
  std::vector<glm::vec4> positions, colors, back_colors;
  std::vector<glm::vec3> normals, secondary, back_secondary;
  std::vector<glm::vec4> texcoords;  // (s, t, r, q); q != 1 in some draws (projective)
  // A second texture unit's coordinates and texture (multitexture), at unit `second_unit`.
  std::vector<glm::vec4> texcoords2;
  std::vector<float> fog_coords;
  std::vector<Triangle> triangles;
  std::vector<std::uint8_t> triangle_flags;
  std::vector<LineSegment> lines;
  std::vector<std::uint32_t> points;
  std::vector<Light> lights;
  std::vector<ShadowMap> shadow_maps;
  std::shared_ptr<Texture> texture, texture2;
  int second_unit = 1;
  glm::vec4 constant_color{1.0f};
  glm::mat4 projection{1.0f};
  Viewport viewport;
  FragmentState frag;
  ShadeState shade;
  bool capture = false;

  VertexInput input() const {
    VertexInput in;
    in.positions = positions;
    in.normals = normals;
    in.colors = colors;
    in.back_colors = back_colors;
    in.secondary_colors = secondary;
    in.back_secondary_colors = back_secondary;
    in.texcoords[0] = texcoords;
    in.texcoords[std::size_t(second_unit)] = texcoords2;
    in.fog_coords = fog_coords;
    in.constant_color = constant_color;
    in.triangles = triangles;
    in.triangle_flags = triangle_flags;
    in.lines = lines;
    in.points = points;
    return in;
  }
};

class RandomDraws {
 public:
  // The projective q, r and 1D/border choices of textures come from a second stream, so that
  // adding them left every other choice of a seed's scene as it was.
  explicit RandomDraws(unsigned seed) : rng_(seed), texture_rng_(seed ^ 0x5eedu) {}

  float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool chance(double p) { return std::bernoulli_distribution(p)(rng_); }
  glm::vec4 color(float alpha_lo = 1.0f) {
    return {uniform(0, 1), uniform(0, 1), uniform(0, 1), uniform(alpha_lo, 1)};
  }
  glm::vec3 unit() {
    glm::vec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    float l = glm::length(v);
    return l > 1e-3f ? v / l : glm::vec3(0, 0, 1);
  }

  /// A framebuffer size: mostly small and odd, sometimes a few hundred pixels.
  glm::ivec2 size() {
    if (chance(0.15)) return {integer(1, 9), integer(1, 9)};
    if (chance(0.2)) return {integer(100, 400), integer(80, 300)};
    return {integer(10, 140), integer(10, 110)};
  }

  /// A framebuffer with random colours, depths and stencil values.
  Framebuffer framebuffer(glm::ivec2 s) {
    Framebuffer fb;
    fb.resize(s.x, s.y);
    fb.clear_color(color(0.0f));
    bool noisy = chance(0.3);
    for (float& d : fb.depth) d = noisy ? uniform(0.3f, 1.0f) : 1.0f;
    for (std::uint8_t& v : fb.stencil) v = std::uint8_t(integer(0, 3));
    if (chance(0.3)) {
      for (std::uint8_t& c : fb.color) c = std::uint8_t(integer(0, 255));
    }
    return fb;
  }

  /// Adds GL's other per-fragment state to a draw: fog (any mode, sometimes with given fog
  /// coordinates), a scissor box, the alpha test, a logic op and a polygon stipple, each
  /// sometimes. Logic ops that mix source and destination bits turn a colour one step off
  /// into bytes far apart, and the fast pipeline's per-pixel lighting and fog are within a
  /// step of the reference's, not equal: those ops come without them.
  void fragment_extras(RandomDraw& d, glm::ivec2 fb_size) {
    FogState& fog = d.shade.fog;
    fog.enabled = chance(0.5);
    fog.mode = FogMode(integer(0, 2));
    fog.color = glm::vec3(color());
    fog.start = uniform(-2, 8);
    fog.end = chance(0.05) ? fog.start : uniform(0, 30);
    fog.density = chance(0.05) ? 0.0f : uniform(0, 0.6f);
    if (chance(0.2)) for (std::size_t i = 0; i < d.positions.size(); ++i) d.fog_coords.push_back(uniform(-5, 40));
    FragmentState& f = d.frag;
    if (chance(0.4)) {
      int x = integer(-8, fb_size.x), y = integer(-8, fb_size.y);
      f.scissor = {true, x, y, integer(0, fb_size.x + 8), integer(0, fb_size.y + 8)};
      if (chance(0.1)) f.scissor = {true, 0, 0, fb_size.x, fb_size.y};
    }
    if (chance(0.4)) f.alpha_test = {true, compare_func(), chance(0.2) ? float(integer(0, 4)) / 4.0f : uniform(-0.2f, 1.2f)};
    if (chance(0.3)) {
      f.logic_op = {true, LogicOp(integer(0, 15))};
      const LogicOp op = f.logic_op.op;
      const bool mixes = !(op == LogicOp::kClear || op == LogicOp::kCopy || op == LogicOp::kNoop ||
                           op == LogicOp::kInvert || op == LogicOp::kCopyInverted || op == LogicOp::kSet);
      if (mixes) {
        fog.enabled = false;
        if (d.shade.lighting && d.shade.shading == ShadingMode::kPhong) d.shade.shading = ShadingMode::kGouraud;
      }
    }
    if (chance(0.3)) {
      f.stipple.enabled = true;
      for (std::uint32_t& row : f.stipple.rows) row = std::uint32_t(rng_()) & (chance(0.3) ? ~0u : std::uint32_t(rng_()));
    }
  }

  /// Adds GL 1.4's blending and stencil state to a draw: any equation, factors (the constant
  /// colour's too) chosen apart for alpha or not, a constant colour (sometimes 0 or 1 exactly),
  /// and the wrapping stencil operations among the others, sometimes with the stencil test
  /// turned on for them.
  void blend_extras(RandomDraw& d) {
    BlendState& b = d.frag.blend;
    b.enabled = chance(0.85);
    b.equation = BlendEquation(integer(0, 4));
    b.src = any_blend_factor();
    b.dst = any_blend_factor();
    b.src_alpha = chance(0.3) ? b.src : any_blend_factor();
    b.dst_alpha = chance(0.3) ? b.dst : any_blend_factor();
    b.color = chance(0.1) ? glm::vec4(float(integer(0, 1)), float(integer(0, 1)), 0.0f, 1.0f) : color(0.0f);
    StencilState& s = d.frag.stencil;
    if (!s.enabled && chance(0.3)) {
      s = {true, compare_func(), std::uint8_t(integer(0, 3)), std::uint8_t(integer(0, 255)),
           std::uint8_t(integer(0, 255)), StencilOp::kKeep, StencilOp::kKeep, StencilOp::kKeep};
      if (chance(0.5)) s.value_mask = s.write_mask = 0xff;
    }
    if (s.enabled) {
      for (StencilOp* op : {&s.fail, &s.depth_fail, &s.pass}) {
        *op = chance(0.6) ? (chance(0.5) ? StencilOp::kIncrWrap : StencilOp::kDecrWrap) : StencilOp(integer(0, 7));
      }
    }
  }

  BlendFactor any_blend_factor() { return BlendFactor(integer(0, 14)); }

  /// A draw of lines, points or polygons in GL_LINE / GL_POINT mode (or a mix), with random
  /// widths, sizes, stipple, smoothing, polygon modes and offsets, edge flags and clip planes.
  RandomDraw prim_draw(glm::ivec2 fb_size) {
    RandomDraw d;
    const int kind = integer(0, 3);  // lines, points, unfilled polygons, all three
    const bool pixel_exact = chance(0.3);
    prim_mesh(d, kind, pixel_exact ? fb_size : glm::ivec2(0));
    attributes(d);
    d.projection = pixel_exact ? glm::ortho(0.0f, float(fb_size.x), 0.0f, float(fb_size.y), -1.0f, 1.0f)
                               : projection(float(fb_size.x) / float(fb_size.y));
    d.viewport = pixel_exact ? Viewport{0, 0, fb_size.x, fb_size.y} : viewport(fb_size);
    fragment_state(d);
    prim_state(d, kind >= 2);
    shade_state(d);
    return d;
  }

  /// User clip planes in eye space, some enabled.
  void clip_planes(FragmentState& f) {
    for (glm::vec4& p : f.clip.eye) {
      glm::vec3 n = unit();
      p = glm::vec4(n, -glm::dot(n, somewhere()) * uniform(0.0f, 1.0f));
    }
    f.clip.enabled = std::uint8_t(integer(0, 255) & integer(0, 255));
  }

  RandomDraw draw(glm::ivec2 fb_size) {
    RandomDraw d;
    mesh(d);
    attributes(d);
    d.projection = projection(float(fb_size.x) / float(fb_size.y));
    d.viewport = viewport(fb_size);
    fragment_state(d);
    shade_state(d);
    return d;
  }

 private:
  void add_triangle(RandomDraw& d, glm::vec3 centre, float size) {
    auto base = std::uint32_t(d.positions.size());
    for (int k = 0; k < 3; ++k) d.positions.push_back(glm::vec4(centre + unit() * size, 1.0f));
    d.triangles.push_back({base, base + 1, base + 2});
  }

  glm::vec3 somewhere() { return {uniform(-3, 3), uniform(-2.5f, 2.5f), uniform(-14, 0.5f)}; }

  void soup(RandomDraw& d) {
    int n = integer(1, 60);
    const float sizes[] = {0.002f, 0.02f, 0.2f, 1.0f, 8.0f};
    for (int i = 0; i < n; ++i) add_triangle(d, somewhere(), sizes[integer(0, 4)] * uniform(0.3f, 1));
    if (chance(0.3)) {  // degenerate: repeated and collinear vertices
      auto base = std::uint32_t(d.positions.size());
      glm::vec3 p = somewhere(), q = somewhere();
      d.positions.push_back(glm::vec4(p, 1));
      d.positions.push_back(glm::vec4(q, 1));
      d.positions.push_back(glm::vec4(0.5f * (p + q), 1));
      d.triangles.push_back({base, base + 1, base + 2});
      d.triangles.push_back({base, base, base + 1});
    }
  }

  // A closed sphere or a flat grid with shared vertices (shared edges, no cracks allowed).
  void shared_mesh(RandomDraw& d) {
    glm::vec3 c = somewhere();
    float r = uniform(0.05f, 3.0f);
    int cols = integer(3, 24), rows = integer(2, 16);
    bool sphere = chance(0.6);
    auto base = std::uint32_t(d.positions.size());
    for (int j = 0; j <= rows; ++j) {
      for (int i = 0; i <= cols; ++i) {
        float u = float(i) / cols, v = float(j) / rows;
        glm::vec3 p = sphere ? glm::vec3(std::sin(v * 3.14159f) * std::cos(u * 6.28318f), std::cos(v * 3.14159f),
                                         std::sin(v * 3.14159f) * std::sin(u * 6.28318f))
                             : glm::vec3(u * 2 - 1 + uniform(-0.01f, 0.01f), v * 2 - 1, 0.0f);
        d.positions.push_back(glm::vec4(c + p * r, 1.0f));
      }
    }
    auto at = [&](int i, int j) { return base + std::uint32_t(j * (cols + 1) + i); };
    for (int j = 0; j < rows; ++j) {
      for (int i = 0; i < cols; ++i) {
        d.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        d.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }

  void mesh(RandomDraw& d) {
    int parts = integer(1, 3);
    for (int i = 0; i < parts; ++i) chance(0.5) ? soup(d) : shared_mesh(d);
    if (chance(0.15)) {  // homogeneous positions: the same points with w != 1
      for (glm::vec4& p : d.positions) p *= uniform(0.5f, 2.0f);
    }
    if (chance(0.05)) d.triangles.push_back({0, 0, std::uint32_t(d.positions.size() + 5)});
  }

  glm::vec4 pixel_point(glm::ivec2 s) {
    float x = uniform(-3, float(s.x) + 3), y = uniform(-3, float(s.y) + 3);
    if (chance(0.4)) x = std::floor(x), y = std::floor(y);
    else if (chance(0.4)) x = std::floor(x) + 0.5f, y = std::floor(y) + 0.5f;
    return {x, y, uniform(-0.9f, 0.9f), 1.0f};
  }

  // Vertices and the primitives over them; with `pixels`, window positions of a pixel-exact
  // orthographic view (ends on pixel centres and corners).
  void prim_mesh(RandomDraw& d, int kind, glm::ivec2 pixels) {
    if (kind >= 2) {
      mesh(d);
      if (pixels.x) {
        for (glm::vec4& p : d.positions) p = pixel_point(pixels);
      }
      for (std::size_t i = 0; i < d.triangles.size(); ++i) {
        d.triangle_flags.push_back(std::uint8_t(chance(0.7) ? kTriangleEdges : integer(0, 7)) |
                                   (chance(0.5) ? kTriangleRestartStipple : 0));
      }
    }
    const int n = integer(2, 60);
    const auto base = std::uint32_t(d.positions.size());
    for (int i = 0; i < n; ++i) {
      glm::vec4 p = pixels.x ? pixel_point(pixels) : glm::vec4(somewhere(), 1.0f);
      if (!pixels.x && chance(0.1)) p *= uniform(0.5f, 2.0f);  // w != 1
      d.positions.push_back(p);
    }
    if (kind == 0 || kind == 3) {
      for (int i = 0; i + 1 < n; ++i) {
        const bool strip = chance(0.5);
        d.lines.push_back({{base + std::uint32_t(i), base + std::uint32_t(strip ? i + 1 : integer(0, n - 1))},
                           chance(0.3) ? LineSegment::kRestartStipple : 0u});
      }
      if (chance(0.05)) d.lines.push_back({{0, std::uint32_t(d.positions.size() + 3)}});
    }
    if (kind == 1 || kind == 3) {
      for (int i = 0; i < n; ++i) d.points.push_back(base + std::uint32_t(integer(0, n - 1)));
    }
  }

  float prim_size() {
    if (chance(0.3)) return 1.0f;
    if (chance(0.1)) return uniform(0.1f, 0.99f);
    if (chance(0.05)) return uniform(20, 300);
    return chance(0.5) ? float(integer(1, 8)) : uniform(1, 9);
  }

  void prim_state(RandomDraw& d, bool unfilled) {
    FragmentState& f = d.frag;
    f.line = {prim_size(), chance(0.2), chance(0.3), std::uint16_t(integer(0, 0xffff)), std::uint16_t(integer(1, 4))};
    f.point = {prim_size(), chance(0.2)};
    if (chance(0.3)) {  // GL 1.4's distance attenuation: a size per point from its eye distance
      f.point.attenuation = {uniform(0.0f, 2.0f), chance(0.5) ? uniform(0.0f, 0.5f) : 0.0f, uniform(0.0f, 0.3f)};
      if (chance(0.1)) f.point.attenuation = {0.0f, 0.0f, 0.0f};  // infinite sizes, clamped
      f.point.size = uniform(1, 40);
      f.point.min_size = chance(0.5) ? 1.0f : uniform(0.0f, 6.0f);
      f.point.max_size = chance(0.5) ? 255.0f : uniform(2.0f, 30.0f);
    }
    if (unfilled) {
      f.front_mode = PolygonMode(integer(0, 2));
      f.back_mode = PolygonMode(integer(0, 2));
      if (f.front_mode == PolygonMode::kFill && f.back_mode == PolygonMode::kFill) f.back_mode = PolygonMode::kLine;
    }
    if (chance(0.2)) {
      f.offset_line = chance(0.5);
      f.offset_point = chance(0.5);
      f.offset_factor = uniform(-2, 2);
      f.offset_units = uniform(-8, 8);
    }
    if (chance(0.25)) clip_planes(f);
  }

  void attributes(RandomDraw& d) {
    std::size_t n = d.positions.size();
    bool unit_normals = chance(0.8);
    for (std::size_t i = 0; i < n; ++i) d.normals.push_back(unit() * (unit_normals ? 1.0f : uniform(0, 2)));
    if (chance(0.1)) d.normals.clear();
    if (chance(0.5)) for (std::size_t i = 0; i < n; ++i) d.colors.push_back(color(0.1f));
    if (chance(0.2)) for (std::size_t i = 0; i < n; ++i) d.back_colors.push_back(color(0.1f));
    if (chance(0.2)) for (std::size_t i = 0; i < n; ++i) d.secondary.push_back(glm::vec3(color()));
    if (chance(0.1)) for (std::size_t i = 0; i < n; ++i) d.back_secondary.push_back(glm::vec3(color()));
    if (chance(0.8)) {
      const bool projective = texture_chance(0.3);
      for (std::size_t i = 0; i < n; ++i) {
        const float s = uniform(-2, 3), t = uniform(-2, 3);
        const float q = projective ? texture_uniform(0.25f, 3.0f) : 1.0f;
        d.texcoords.push_back({s * q, t * q, texture_uniform(-1, 1), q});
      }
    }
    d.constant_color = color(0.1f);
  }

  glm::mat4 projection(float aspect) {
    if (chance(0.25)) {
      float h = uniform(1, 6);
      return glm::ortho(-h * aspect, h * aspect, -h, h, uniform(-1, 1), uniform(5, 20));
    }
    return glm::perspective(glm::radians(uniform(15, 100)), aspect, uniform(0.05f, 1.5f), uniform(8, 100));
  }

  Viewport viewport(glm::ivec2 s) {
    Viewport vp{0, 0, s.x, s.y, 0.0f, 1.0f};
    if (chance(0.25)) {
      vp = {integer(-s.x / 2, s.x / 2), integer(-s.y / 2, s.y / 2), integer(1, 2 * s.x), integer(1, 2 * s.y)};
    }
    if (chance(0.2)) {
      vp.near_depth = uniform(0, 1);
      vp.far_depth = uniform(0, 1);
    }
    return vp;
  }

  CompareFunc compare_func() { return CompareFunc(integer(0, 7)); }

  BlendFactor blend_factor() {
    if (chance(0.5)) return chance(0.5) ? BlendFactor::kSrcAlpha : BlendFactor::kOneMinusSrcAlpha;
    return BlendFactor(integer(0, 10));
  }

  void fragment_state(RandomDraw& d) {
    FragmentState& f = d.frag;
    f.cull = CullMode(integer(0, 2));
    f.front_ccw = chance(0.8);
    f.depth_test = chance(0.85);
    f.depth_func = chance(0.6) ? CompareFunc::kLess : compare_func();
    f.depth_write = chance(0.85);
    f.blend = {chance(0.3), blend_factor(), blend_factor()};
    if (chance(0.1)) for (bool& m : f.color_mask) m = chance(0.5);
    if (chance(0.15)) {
      f.stencil = {true, compare_func(), std::uint8_t(integer(0, 3)), std::uint8_t(integer(0, 255)),
                   std::uint8_t(integer(0, 255)), StencilOp(integer(0, 5)), StencilOp(integer(0, 5)),
                   StencilOp(integer(0, 5))};
    }
    if (chance(0.1)) {
      f.polygon_offset = true;
      f.offset_factor = uniform(-2, 2);
      f.offset_units = uniform(-8, 8);
    }
    d.capture = chance(0.05);
  }

  Light light() {
    Light l;
    l.ambient = color() * uniform(0, 0.4f);
    l.diffuse = color();
    l.specular = color();
    glm::vec3 p = glm::vec3(uniform(-6, 6), uniform(-6, 6), uniform(-12, 6));
    int kind = integer(0, 2);  // directional, point, spot
    l.position = kind == 0 ? glm::vec4(unit(), 0.0f) : glm::vec4(p, 1.0f) * (chance(0.2) ? 2.0f : 1.0f);
    if (kind == 2 || chance(0.05)) {
      l.spot_direction = chance(0.05) ? glm::vec3(0.0f) : unit() * uniform(0.5f, 2);
      l.spot_cutoff = uniform(5, 90);
      l.spot_exponent = chance(0.3) ? 0.0f : uniform(0, 128);
    }
    if (kind != 0 && chance(0.7)) {
      l.constant_attenuation = chance(0.05) ? 0.0f : uniform(0, 2);
      l.linear_attenuation = uniform(0, 0.5f);
      l.quadratic_attenuation = uniform(0, 0.2f);
    }
    l.enabled = chance(0.9);
    return l;
  }

  Material material() {
    Material m;
    m.ambient = color();
    m.diffuse = color(chance(0.5) ? 1.0f : 0.1f);
    m.specular = color();
    m.emission = chance(0.3) ? color() * 0.3f : glm::vec4(0, 0, 0, 1);
    m.shininess = chance(0.1) ? 0.0f : uniform(0, 128);
    m.specular_model = chance(0.3) ? SpecularModel::kPhong : SpecularModel::kBlinn;
    if (chance(0.15)) {
      m.diffuse_model = DiffuseModel::kOrenNayar;
      m.roughness = chance(0.3) ? 0.0f : uniform(0, 1);
    }
    return m;
  }

  std::shared_ptr<Texture> texture() {
    auto t = std::make_shared<Texture>();
    TextureLevel level;
    t->dimensions = texture_chance(0.2) ? 1 : 2;
    level.width = 1 << integer(0, 4);
    level.height = t->dimensions == 1 ? 1 : 1 << integer(0, 4);
    for (int i = 0; i < level.width * level.height * 4; ++i) level.rgba.push_back(std::uint8_t(integer(0, 255)));
    t->levels.push_back(level);
    if (chance(0.7)) generate_mipmaps(*t);
    t->format = TextureFormat(integer(0, 5));
    t->wrap_s = TextureWrap(integer(0, 2));
    t->wrap_t = TextureWrap(integer(0, 2));
    t->min_filter = TextureFilter(integer(0, 5));
    t->mag_filter = chance(0.5) ? TextureFilter::kNearest : TextureFilter::kLinear;
    env_color_ = color();  // ShadeState's, given with the texture
    t->border_color = {texture_uniform(0, 1), texture_uniform(0, 1), texture_uniform(0, 1), texture_uniform(0, 1)};
    // GL 1.3's and 1.4's wrap modes (the second stream's): the border alone outside the texture
    // (GL_CLAMP_TO_BORDER, whose blocks wholly in the border the SIMD sampler draws without
    // reading texels) and mirrored repeats.
    for (TextureWrap* wrap : {&t->wrap_s, &t->wrap_t}) {
      if (texture_chance(0.25)) *wrap = texture_chance(0.5) ? TextureWrap::kClampToBorder : TextureWrap::kMirroredRepeat;
    }
    return t;
  }

  // A small hand-made shadow map seen through the draw's own projection.
  ShadowMap shadow_map(const glm::mat4& projection) {
    ShadowMap m;
    m.size = 4;
    m.faces.push_back({projection, {}});
    for (int i = 0; i < 16; ++i) m.faces[0].depth.push_back(uniform(0.2f, 1.0f));
    m.texel_at_unit = 0.05f;
    m.bias = chance(0.5) ? -1.0f : 0.001f;
    m.pcf = integer(0, 1);
    return m;
  }

  void shade_state(RandomDraw& d) {
    ShadeState& s = d.shade;
    s.lighting = chance(0.75);
    s.shading = ShadingMode(integer(0, 2));
    s.model.ambient = color() * 0.3f;
    s.model.local_viewer = chance(0.3);
    s.model.two_side = chance(0.3);
    s.model.separate_specular = chance(0.3);
    int n = chance(0.1) ? 0 : integer(1, 8);
    for (int i = 0; i < n; ++i) d.lights.push_back(light());
    s.lights = d.lights;
    s.front = material();
    s.back = material();
    if (!d.texcoords.empty() && chance(0.25)) {
      d.texture = texture();
      s.textures[0].env_color = env_color_;
    }
    s.textures[0].texture = d.texture.get();
    s.textures[0].env = TextureEnvMode(integer(0, 4));
    if (chance(0.1)) {
      for (std::size_t i = 0; i < d.lights.size(); ++i) d.shadow_maps.push_back(shadow_map(d.projection));
      s.shadow_maps = d.shadow_maps;
    }
  }

  std::mt19937 rng_;
  glm::vec4 env_color_{0.0f};
  std::mt19937 texture_rng_;

  float texture_uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(texture_rng_); }
  bool texture_chance(double p) { return std::bernoulli_distribution(p)(texture_rng_); }
};

}  // namespace shadelab::test
