// Texturing on the fast pipeline's SIMD path against the reference (texture-inl.h against
// texture.cpp): textures of up to 256 x 256 texels with every filter pair, wrap mode (mirrored
// repeat and clamp to border too), base format and environment mode, 1D, 2D, 3D (up to
// 32^3, r varying over the triangles), cube maps (directions crossing the faces' edges) and depth
// textures (compared with r by every function, or not, in every depth texture mode), mipmapped or not, with base and maximum levels, LOD clamps and biases (the texture's and the unit's), on floors and walls seen in
// perspective (every mipmap level in one picture), orthographically, and with projective
// coordinates, in framebuffers of even and odd heights (llvmpipe's quads then lie across the
// fast path's blocks), on every SIMD target. Where the texel is the colour (GL_REPLACE of an
// RGBA texture, unlit, opaque) the pictures must be identical: the samplers must pick and
// filter the same texels in the same arithmetic (llvmpipe's 8-bit filter for repeat and clamp
// to edge, float for the other wrap modes). Otherwise colours within 1/255, as for every
// other state. One unit's draws take the textured kernel, two units' and GL_COMBINE's the
// general block: both are drawn, and the kernel is chosen for the state it implements only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <sstream>

#include "differential.hpp"
#include "fast/simd_targets.hpp"

namespace shadelab {
namespace {

// A 3D chain below level 0: each level halves every side, texels random around the level's
// own shade.
void random_levels_3d(std::mt19937& rng, Texture& t) {
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  while (t.levels.back().width > 1 || t.levels.back().height > 1 || t.levels.back().depth > 1) {
    const TextureLevel& src = t.levels.back();
    TextureLevel dst;
    dst.width = std::max(1, src.width / 2), dst.height = std::max(1, src.height / 2), dst.depth = std::max(1, src.depth / 2);
    const int shade = pick(0, 200);
    for (int i = 0; i < dst.width * dst.height * dst.depth * 4; ++i) dst.rgba.push_back(std::uint8_t(shade + pick(0, 55)));
    t.levels.push_back(std::move(dst));
  }
}

// A cube map's chain below level 0: each level halves the faces' side, six faces of random
// texels around the level's own shade.
void random_levels_cube(std::mt19937& rng, Texture& t) {
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  while (t.levels.back().width > 1) {
    TextureLevel dst;
    dst.width = dst.height = t.levels.back().width / 2, dst.depth = 6;
    const int shade = pick(0, 200);
    for (int i = 0; i < dst.width * dst.height * 6 * 4; ++i) dst.rgba.push_back(std::uint8_t(shade + pick(0, 55)));
    t.levels.push_back(std::move(dst));
  }
}

// A texture of random size (1 to 256 a side, any aspect, some sides not powers of two; 3D: up
// to 32^3; cube maps: six square faces up to 64), noisy checkerboard texels, every parameter random; mipmapped when
// the filter needs it (and sometimes otherwise).
std::shared_ptr<Texture> random_texture(std::mt19937& rng, bool one_d, bool three_d = false, bool cube = false) {
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  auto t = std::make_shared<Texture>();
  TextureLevel level;
  t->dimensions = one_d ? 1 : three_d ? 3 : 2;
  t->cube_map = cube;
  // A quarter of 1D and 2D textures have sides that are not powers of two (GL 2.0's; repeat
  // wraps them otherwise in llvmpipe's 8-bit filter).
  auto side = [&](int log2_max) { return !three_d && !cube && pick(0, 3) == 0 ? pick(3, 100) : 1 << pick(0, log2_max); };
  level.width = side(three_d ? 5 : cube ? 6 : 8);
  level.height = one_d ? 1 : cube ? level.width : side(three_d ? 5 : 8);
  level.depth = three_d ? 1 << pick(0, 5) : cube ? 6 : 1;
  const int squares = 1 << pick(0, 4);
  for (int k = 0; k < level.depth; ++k) {
    for (int j = 0; j < level.height; ++j) {
      for (int i = 0; i < level.width; ++i) {
        const bool on = ((i * squares / level.width) + (j * squares / level.height) + (k * squares / level.depth)) & 1;
        for (int c = 0; c < 4; ++c) level.rgba.push_back(std::uint8_t(on ? pick(150, 255) : pick(0, 100)));
      }
    }
  }
  t->levels.push_back(level);
  t->min_filter = TextureFilter(pick(0, 5));
  t->mag_filter = pick(0, 1) ? TextureFilter::kNearest : TextureFilter::kLinear;
  const bool mipmapped = t->min_filter != TextureFilter::kNearest && t->min_filter != TextureFilter::kLinear;
  if (mipmapped || pick(0, 3) == 0) {
    if (three_d) random_levels_3d(rng, *t);
    else if (cube) random_levels_cube(rng, *t);
    else generate_mipmaps(*t);
  }
  t->wrap_r = TextureWrap(pick(0, 4));
  t->wrap_s = TextureWrap(pick(0, 4));
  t->wrap_t = TextureWrap(pick(0, 4));
  t->format = TextureFormat(pick(0, 5));
  if (pick(0, 1)) {  // GL 1.2-1.4 level-of-detail state
    auto real = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
    const int levels = int(t->levels.size());
    if (pick(0, 2) == 0) t->base_level = pick(0, levels - 1);
    if (pick(0, 2) == 0) t->max_level = t->base_level + pick(0, 3);
    if (pick(0, 2) == 0) t->min_lod = pick(0, 1) ? real(-2.0f, 4.0f) : float(pick(0, 3));
    if (pick(0, 2) == 0) t->max_lod = pick(0, 1) ? real(-1.0f, 6.0f) : float(pick(0, 5));
    if (pick(0, 2) == 0) t->lod_bias = pick(0, 1) ? real(-4.0f, 4.0f) : float(pick(-2, 2));
  }
  t->border_color = {pick(0, 255) / 255.0f, pick(0, 255) / 255.0f, pick(0, 255) / 255.0f, pick(0, 255) / 255.0f};
  return t;
}

// A 1D or 2D depth texture: random depths in steps of 1/64 (so that r meets some exactly),
// compared or not, by any function, read as luminance, intensity or alpha.
std::shared_ptr<Texture> random_depth_texture(std::mt19937& rng, bool one_d) {
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::shared_ptr<Texture> t = random_texture(rng, one_d);
  t->depth = true;
  for (TextureLevel& l : t->levels) {
    l.depth_values.clear();
    for (int i = 0; i < l.width * l.height; ++i) l.depth_values.push_back(float(pick(0, 64)) / 64.0f);
  }
  t->compare = pick(0, 3) != 0;
  t->compare_func = TextureCompare(pick(0, 7));
  const TextureFormat modes[3] = {TextureFormat::kLuminance, TextureFormat::kIntensity, TextureFormat::kAlpha};
  t->format = modes[pick(0, 2)];
  return t;
}

struct TexturedScene {
  Framebuffer initial;
  std::vector<test::RandomDraw> draws;
  bool exact = false;  // the texel is the colour: pictures must be identical
};

// A GL_COMBINE environment of random functions, sources (the crossbar's other units too),
// operands and scales.
template <class Pick>
TextureCombine random_combine(Pick& pick) {
  TextureCombine c;
  c.rgb = CombineFunction(pick(0, 7));
  c.alpha = CombineFunction(pick(0, 5));
  for (int i = 0; i < 3; ++i) {
    c.rgb_source[i] = CombineSource(pick(0, 7));
    c.alpha_source[i] = CombineSource(pick(0, 7));
    c.rgb_operand[i] = CombineOperand(pick(0, 3));
    c.alpha_operand[i] = CombineOperand(pick(2, 3));
  }
  const float scales[3] = {1.0f, 2.0f, 4.0f};
  c.rgb_scale = scales[pick(0, 2)];
  c.alpha_scale = scales[pick(0, 2)];
  return c;
}

// A floor receding to the horizon, a wall turned away, or a face-on quad, with texture
// coordinates repeated up to 64 times (or a few texels magnified), projective sometimes.
TexturedScene textured_scene(unsigned seed) {
  std::mt19937 rng(seed);
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  auto real = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
  TexturedScene scene;
  const int width = pick(0, 3) == 0 ? pick(1, 40) : pick(40, 300);
  const int height = pick(0, 3) == 0 ? pick(1, 40) : pick(40, 220);
  scene.initial.resize(width, height);
  scene.initial.clear_color({0.1f, 0.2f, 0.3f, 1.0f});
  scene.initial.clear_depth(1.0f);
  const int count = pick(1, 3);
  scene.exact = pick(0, 2) == 0;
  for (int k = 0; k < count; ++k) {
    test::RandomDraw d;
    const int kind = pick(0, 7);  // 1D, 2D, 3D, a cube map or a depth texture
    d.texture = kind == 7 ? random_depth_texture(rng, pick(0, 3) == 0) : random_texture(rng, kind == 0, kind == 5, kind == 6);
    const int shape = pick(0, 2);
    const float repeat = pick(0, 2) == 0 ? real(0.05f, 1.5f) : real(1.0f, 64.0f);
    const float s0 = real(-2.0f, 2.0f), t0 = real(-2.0f, 2.0f);
    const float aspect = float(width) / float(height);
    if (shape == 2) {
      d.projection = glm::ortho(-aspect, aspect, -1.0f, 1.0f, -2.0f, 2.0f);
      const float x0 = real(-1.5f, 0.5f), y0 = real(-1.5f, 0.5f), x1 = x0 + real(0.3f, 2.5f), y1 = y0 + real(0.3f, 2.5f);
      d.positions = {{x0, y0, 0, 1}, {x1, y0, 0, 1}, {x1, y1, 0, 1}, {x0, y1, 0, 1}};
    } else {
      d.projection = glm::perspective(glm::radians(real(30.0f, 90.0f)), aspect, 0.1f, 200.0f);
      const float far = -real(5.0f, 150.0f);
      if (shape == 0) {  // floor
        const float y = -real(0.3f, 2.0f);
        d.positions = {{-20, y, -0.5f, 1}, {20, y, -0.5f, 1}, {20, y, far, 1}, {-20, y, far, 1}};
      } else {  // wall turned away
        const float x = real(-1.0f, 1.0f);
        d.positions = {{x - 1, -1, -2, 1}, {x + 1, -1, -2, 1}, {x + 20, 1.5f, far, 1}, {x - 1, 1.5f, -2, 1}};
      }
    }
    const bool projective = pick(0, 3) == 0;
    const glm::vec2 st[4] = {{s0, t0}, {s0 + repeat, t0}, {s0 + repeat, t0 + repeat}, {s0, t0 + repeat}};
    for (int i = 0; i < 4; ++i) {
      const float q = projective ? real(0.3f, 3.0f) : 1.0f;
      const float r = kind == 5 ? real(-1.5f, 2.5f) : kind == 6 ? real(-3.0f, 3.0f) : kind == 7 ? real(-0.3f, 1.3f) : 0.0f;
      d.texcoords.push_back({st[i].x * q, st[i].y * q, r * q, q});
      d.colors.push_back({real(0, 1), real(0, 1), real(0, 1), real(0.2f, 1)});
    }
    d.triangles = {{0, 1, 2}, {0, 2, 3}};
    if (pick(0, 1)) d.triangles = {{1, 2, 3}, {1, 3, 0}};
    d.viewport = {0, 0, width, height, 0.0f, 1.0f};
    d.shade.lighting = false;
    TextureUnit& unit = d.shade.textures[0];
    unit.texture = d.texture.get();
    unit.env_color = {pick(0, 255) / 255.0f, pick(0, 255) / 255.0f, pick(0, 255) / 255.0f, pick(0, 255) / 255.0f};
    if (pick(0, 3) == 0) unit.lod_bias = real(-3.0f, 3.0f);
    d.frag.depth_test = pick(0, 1);
    if (scene.exact) {
      // The texel is the whole colour: RGBA, or a depth texture read as intensity.
      d.texture->format = d.texture->depth ? TextureFormat::kIntensity : TextureFormat::kRgba;
      unit.env = TextureEnvMode::kReplace;
      if (pick(0, 2) == 0) d.frag.alpha_test = {true, CompareFunc(pick(0, 7)), real(0.0f, 1.0f)};
    } else {
      unit.env = TextureEnvMode(pick(0, 5));
      if (unit.env == TextureEnvMode::kCombine) unit.combine = random_combine(pick);
      if (pick(0, 2) == 0) {  // a second unit (multitexture) over the first, at unit 1 to 3
        d.second_unit = pick(1, kMaxTextureUnits - 1);
        const int kind2 = pick(0, 5);
        d.texture2 = random_texture(rng, kind2 == 0, kind2 == 5);
        const float scale = real(0.2f, 6.0f), shift = real(-1.0f, 1.0f);
        for (const glm::vec4& tc : d.texcoords) {
          const float r2 = kind2 == 5 ? real(-1.5f, 2.5f) * tc.w : tc.z;
          d.texcoords2.push_back({tc.y * scale + shift * tc.w, tc.x * scale, r2, tc.w});
        }
        TextureUnit& second = d.shade.textures[std::size_t(d.second_unit)];
        second.texture = d.texture2.get();
        second.env = TextureEnvMode(pick(0, 5));
        if (second.env == TextureEnvMode::kCombine) second.combine = random_combine(pick);
        second.env_color = {pick(0, 255) / 255.0f, pick(0, 255) / 255.0f, pick(0, 255) / 255.0f, pick(0, 255) / 255.0f};
        if (pick(0, 3) == 0) second.lod_bias = real(-3.0f, 3.0f);
      }
      d.shade.shading = pick(0, 3) == 0 ? ShadingMode::kFlat : ShadingMode::kGouraud;
      if (pick(0, 2) == 0) d.frag.blend = {true, BlendFactor::kSrcAlpha, BlendFactor::kOneMinusSrcAlpha};
      if (pick(0, 3) == 0) d.frag.alpha_test = {true, CompareFunc::kGreater, real(0.2f, 0.8f)};
      if (pick(0, 3) == 0) {  // fog, after the environments
        FogState& fog = d.shade.fog;
        fog.enabled = true;
        fog.mode = FogMode(pick(0, 2));
        fog.color = {pick(0, 255) / 255.0f, pick(0, 255) / 255.0f, pick(0, 255) / 255.0f};
        fog.start = real(-1.0f, 3.0f), fog.end = real(3.0f, 12.0f), fog.density = real(0.05f, 0.6f);
      }
    }
    scene.draws.push_back(std::move(d));
  }
  return scene;
}

std::string identical(const Framebuffer& fast, const Framebuffer& ref) {
  std::ostringstream out;
  int shown = 0;
  for (int y = 0; y < ref.height; ++y) {
    for (int x = 0; x < ref.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(ref.width) + std::size_t(x);
      if (std::memcmp(&fast.color[i * 4], &ref.color[i * 4], 4) == 0 &&
          std::memcmp(&fast.depth[i], &ref.depth[i], 4) == 0) {
        continue;
      }
      if (shown++ < 4) {
        out << "(" << x << "," << y << ") ";
        for (int c = 0; c < 4; ++c) out << int(fast.color[i * 4 + c]) << "/" << int(ref.color[i * 4 + c]) << " ";
        out << "\n";
      }
    }
  }
  if (shown) out << shown << " pixels differ";
  return out.str();
}

void check_scenes(unsigned first, unsigned last, PipelineContext& context, const std::string& target) {
  const unsigned requested = last - first;
  last = first + test::random_cases(requested);
  int exact_scenes = 0, fogged_kernel = 0;  // fogged draws through the textured kernel
  for (unsigned seed = first; seed < last; ++seed) {
    const TexturedScene scene = textured_scene(seed);
    for (const test::RandomDraw& d : scene.draws) {
      fogged_kernel += d.shade.fog.enabled && fast::kernel_textured(test::planned_kernel(d.frag, d.shade));
    }
    const test::Result ref = test::render(scene.initial, scene.draws, nullptr);
    const test::Result fast = test::render(scene.initial, scene.draws, &context);
    const std::string diff = scene.exact ? identical(fast.fb, ref.fb) : test::compare_buffers(fast.fb, ref.fb);
    ASSERT_EQ(diff, "") << "seed " << seed << " (" << scene.initial.width << "x" << scene.initial.height << ", "
                        << (scene.exact ? "identical" : "within 1/255") << "), target " << target;
    exact_scenes += scene.exact;
  }
  // Over a fifth of the scenes are drawn exactly; of the fewer scenes a ThreadSanitizer build
  // draws, a tenth (a small sample's share varies).
  EXPECT_GT(exact_scenes, int(last - first) / (last - first == requested ? 5 : 10));
  EXPECT_GT(fogged_kernel, int(last - first) / 20);
}

TEST(TextureDifferential, TexturedScenesMatchTheReference) {
  PipelineContext one(1), two(2);
  check_scenes(1, 250, one, "best");
  check_scenes(250, 400, two, "best");
}

TEST(TextureDifferential, EverySimdTargetSamplesAsTheReference) {
  PipelineContext two(2);
  for (const std::string& target : fast::available_simd_targets()) {
    ASSERT_TRUE(fast::force_simd_target(target));
    check_scenes(1000, 1100, two, target);
    if (HasFatalFailure()) break;
  }
  fast::force_simd_target("");
}

// The scenes above must reach what they are for: minified and magnified pixels, several
// mipmap levels in one picture, quads across odd-height blocks. A floor of a 256 x 256
// mipmapped texture in a 64 x 63 framebuffer shows all of it; the fast path's picture must
// equal the reference's there too, with each minification filter.
TEST(TextureDifferential, FloorThroughEveryLevelOnAnOddHeight) {
  PipelineContext two(2);
  for (int filter = 2; filter <= 5; ++filter) {
    test::RandomDraw d;
    d.texture = std::make_shared<Texture>();
    TextureLevel level;
    level.width = level.height = 256;
    for (int j = 0; j < 256; ++j) {
      for (int i = 0; i < 256; ++i) {
        const std::uint8_t v = ((i / 16 + j / 16) & 1) ? 230 : 20;
        level.rgba.insert(level.rgba.end(), {v, std::uint8_t(i), std::uint8_t(j), 255});
      }
    }
    d.texture->levels.push_back(level);
    generate_mipmaps(*d.texture);
    d.texture->min_filter = TextureFilter(filter);
    d.shade.textures[0].texture = d.texture.get();
    d.shade.textures[0].env = TextureEnvMode::kReplace;
    d.shade.lighting = false;
    d.projection = glm::perspective(glm::radians(60.0f), 64.0f / 63.0f, 0.1f, 200.0f);
    d.positions = {{-40, -1, -0.5f, 1}, {40, -1, -0.5f, 1}, {40, -1, -160, 1}, {-40, -1, -160, 1}};
    d.texcoords = {{0, 0, 0, 1}, {40, 0, 0, 1}, {40, 40, 0, 1}, {0, 40, 0, 1}};
    d.triangles = {{0, 1, 2}, {0, 2, 3}};
    d.viewport = {0, 0, 64, 63, 0.0f, 1.0f};
    Framebuffer initial;
    initial.resize(64, 63);
    const std::vector<test::RandomDraw> draws = {d};
    const test::Result ref = test::render(initial, draws, nullptr);
    const test::Result fast = test::render(initial, draws, &two);
    EXPECT_EQ(identical(fast.fb, ref.fb), "") << "filter " << filter;
    // Distinct colours in the picture: texels from several levels (a single level's nearest
    // texels would give the checkerboard's two).
    std::vector<std::uint32_t> colours;
    for (std::size_t i = 0; i < ref.fb.color.size(); i += 4) {
      std::uint32_t c;
      std::memcpy(&c, &ref.fb.color[i], 4);
      colours.push_back(c);
    }
    std::sort(colours.begin(), colours.end());
    EXPECT_GT(std::unique(colours.begin(), colours.end()) - colours.begin(), 40) << "filter " << filter;
  }
}

// Affine triangles whose coordinates change by less than a base-level texel a pixel sample
// the base level with the magnification filter without a level of detail per quad
// (magnified_everywhere); the others compute it. Quads turned at any angle, a 64 x 64
// mipmapped texture spread over 50 to 80 pixels a side (from 1.28 texels a pixel to 0.8),
// filters that tell minification from magnification (a linear one and a nearest one), in
// framebuffers of even and odd heights: identical to the reference on every target.
TEST(TextureDifferential, MagnifiedTrianglesSampleTheBaseLevel) {
  std::mt19937 rng(2026);
  auto real = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  auto texture = std::make_shared<Texture>();
  TextureLevel level;
  level.width = level.height = 64;
  for (int k = 0; k < 64 * 64; ++k) {
    for (int c = 0; c < 4; ++c) level.rgba.push_back(std::uint8_t(pick(0, 255)));
  }
  texture->levels.push_back(level);
  generate_mipmaps(*texture);
  PipelineContext two(2);
  for (const std::string& target : fast::available_simd_targets()) {
    ASSERT_TRUE(fast::force_simd_target(target));
    for (int scene = 0; scene < 24; ++scene) {
      const int width = 160, height = scene % 2 ? 129 : 128;
      std::vector<test::RandomDraw> draws;
      for (int k = 0; k < 4; ++k) {
        test::RandomDraw d;
        auto t = std::make_shared<Texture>(*texture);
        const bool linear_min = pick(0, 1);
        t->min_filter = linear_min ? (pick(0, 1) ? TextureFilter::kLinearMipmapNearest : TextureFilter::kLinearMipmapLinear)
                                   : (pick(0, 1) ? TextureFilter::kNearestMipmapNearest : TextureFilter::kNearestMipmapLinear);
        t->mag_filter = linear_min ? TextureFilter::kNearest : TextureFilter::kLinear;
        d.texture = t;
        d.projection = glm::ortho(0.0f, float(width), 0.0f, float(height), -1.0f, 1.0f);
        const float angle = real(0.0f, 6.2832f), side_s = real(50.0f, 80.0f), side_t = real(50.0f, 80.0f);
        const glm::vec2 centre{real(40.0f, 120.0f), real(40.0f, 90.0f)};
        const glm::vec2 across{std::cos(angle), std::sin(angle)}, down{-std::sin(angle), std::cos(angle)};
        const glm::vec2 corner[4] = {-0.5f * side_s * across - 0.5f * side_t * down, 0.5f * side_s * across - 0.5f * side_t * down,
                                     0.5f * side_s * across + 0.5f * side_t * down, -0.5f * side_s * across + 0.5f * side_t * down};
        const float s0 = real(-1.0f, 1.0f), t0 = real(-1.0f, 1.0f);
        const glm::vec2 st[4] = {{s0, t0}, {s0 + 1, t0}, {s0 + 1, t0 + 1}, {s0, t0 + 1}};
        for (int i = 0; i < 4; ++i) {
          d.positions.push_back({centre + corner[i], 0.0f, 1.0f});
          d.texcoords.push_back({st[i], 0.0f, 1.0f});
          d.colors.push_back({1, 1, 1, 1});
        }
        d.triangles = pick(0, 1) ? std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}} : std::vector<Triangle>{{1, 2, 3}, {1, 3, 0}};
        d.viewport = {0, 0, width, height, 0.0f, 1.0f};
        d.shade.lighting = false;
        d.shade.textures[0].texture = t.get();
        d.shade.textures[0].env = TextureEnvMode::kReplace;
        d.frag.depth_test = false;
        draws.push_back(std::move(d));
      }
      Framebuffer initial;
      initial.resize(width, height);
      const test::Result ref = test::render(initial, draws, nullptr);
      const test::Result fast = test::render(initial, draws, &two);
      ASSERT_EQ(identical(fast.fb, ref.fb), "") << "scene " << scene << ", target " << target;
    }
  }
  fast::force_simd_target("");
}

// A complete 2 x 2 grey RGBA texture, linear without mipmaps.
Texture grey_2x2() {
  Texture texture;
  TextureLevel level;
  level.width = level.height = 2;
  level.rgba.assign(16, 128);
  texture.levels.push_back(level);
  texture.min_filter = TextureFilter::kLinear;
  return texture;
}

// The kernel make_plan chooses for a textured draw: a textured kernel for one unit whose
// environment is not GL_COMBINE, with or without the depth test, alpha test, fog and blend
// (the scenes above draw through both on every target), kTextured2D for a 2D colour texture
// and kTextured for the other shapes; the general path with a second unit, GL_COMBINE, the
// stencil test or a logic op.
TEST(TextureDifferential, TheTexturedKernelOnlyForOneUnitWithoutOtherState) {
  Texture texture = grey_2x2();
  auto kernel = [&](auto&& change) {
    FragmentState frag;
    ShadeState shade;
    shade.lighting = false;
    shade.textures[0].texture = &texture;
    change(frag, shade);
    return test::planned_kernel(frag, shade);
  };
  using fast::BlockKernel;
  EXPECT_EQ(kernel([](FragmentState&, ShadeState&) {}), BlockKernel::kTextured2D);
  EXPECT_EQ(kernel([](FragmentState& f, ShadeState&) {
              f.depth_test = false;
              f.alpha_test = {true, CompareFunc::kGreater, 0.5f};
              f.blend = {true, BlendFactor::kOne, BlendFactor::kOne};
            }),
            BlockKernel::kTextured2D);
  EXPECT_EQ(kernel([&](FragmentState&, ShadeState& s) { s.textures[2].texture = &texture; }), BlockKernel::kGeneral);
  EXPECT_EQ(kernel([](FragmentState&, ShadeState& s) { s.textures[0].env = TextureEnvMode::kCombine; }),
            BlockKernel::kGeneral);
  EXPECT_EQ(kernel([](FragmentState&, ShadeState& s) { s.fog.enabled = true; }), BlockKernel::kTextured2D);
  EXPECT_EQ(kernel([](FragmentState& f, ShadeState&) { f.stencil.enabled = true; }), BlockKernel::kGeneral);
  EXPECT_EQ(kernel([](FragmentState& f, ShadeState&) { f.logic_op.enabled = true; }), BlockKernel::kGeneral);
  EXPECT_EQ(kernel([](FragmentState& f, ShadeState&) { f.color_mask[1] = false; }), BlockKernel::kGeneral);
  // Every other shape: kTextured, whose sampler reads the shape from the plan.
  for (int shape = 0; shape < 4; ++shape) {
    Texture other = texture;
    if (shape == 0) other.dimensions = 1;
    if (shape == 1) other.dimensions = 3;
    if (shape == 2) other.cube_map = true;
    if (shape == 3) other.depth = true;
    EXPECT_EQ(kernel([&](FragmentState&, ShadeState& s) { s.textures[0].texture = &other; }), BlockKernel::kTextured)
        << "shape " << shape;
  }
}

// The textured kernel writes the filtered bytes as the colours (DrawPlan::texel_bytes) for
// GL_REPLACE of an RGBA texture the 8-bit sampler filters, without blending, alpha-tested or
// not: the exact scenes above (GL_REPLACE of RGBA texels, compared bit for bit) and the floor
// draw through it; not for another environment or format, a texture filtered in floats
// (GL_CLAMP) or blending.
TEST(TextureDifferential, TexelBytesOnlyForReplacingRgbaFilteredInBytes) {
  Texture texture = grey_2x2();
  auto bytes = [&](auto&& change) {
    Texture t = texture;
    FragmentState frag;
    ShadeState shade;
    shade.lighting = false;
    shade.textures[0].texture = &t;
    shade.textures[0].env = TextureEnvMode::kReplace;
    change(frag, shade, t);
    return test::planned(frag, shade).texel_bytes;
  };
  EXPECT_TRUE(bytes([](FragmentState&, ShadeState&, Texture&) {}));
  EXPECT_TRUE(bytes([](FragmentState& f, ShadeState&, Texture& t) {
    f.depth_test = false;
    t.wrap_s = TextureWrap::kClampToEdge;
    t.min_filter = TextureFilter::kNearest;
  }));
  EXPECT_FALSE(bytes([](FragmentState&, ShadeState& s, Texture&) { s.textures[0].env = TextureEnvMode::kModulate; }));
  EXPECT_FALSE(bytes([](FragmentState&, ShadeState&, Texture& t) { t.format = TextureFormat::kRgb; }));
  EXPECT_FALSE(bytes([](FragmentState&, ShadeState&, Texture& t) { t.wrap_t = TextureWrap::kClamp; }));
  EXPECT_TRUE(bytes([](FragmentState& f, ShadeState&, Texture&) { f.alpha_test = {true, CompareFunc::kGreater, 0.5f}; }));
  EXPECT_FALSE(bytes([](FragmentState& f, ShadeState&, Texture&) { f.blend.enabled = true; }));
  EXPECT_FALSE(bytes([](FragmentState&, ShadeState& s, Texture&) { s.fog.enabled = true; }));
}

}  // namespace
}  // namespace shadelab
