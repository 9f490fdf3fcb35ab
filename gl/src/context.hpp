// GlContext: all the state of one OpenGL 1.1 context (the GL 1.1 specification's state
// tables, chapter 6), its framebuffer and the caller's OSMesa buffer. Plain data plus the error
// rule; the exec:: functions of the GL commands change it, draw.cpp hands primitives to the
// core pipeline. The larger features keep their state in their own headers, included here
// (texture_state.hpp, vertex_state.hpp, pixel_state.hpp, dlist_state.hpp, eval_state.hpp,
// feedback_state.hpp, query_state.hpp, and the client state in client_state.hpp).
// No global state except the thread's current-context pointer (as OSMesaMakeCurrent needs).
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/src/buffer_state.hpp"
#include "gl/src/client_state.hpp"
#include "gl/src/dlist_state.hpp"
#include "gl/src/eval_state.hpp"
#include "gl/src/feedback_state.hpp"
#include "gl/src/pixel_state.hpp"
#include "gl/src/query_state.hpp"
#include "gl/src/texture_state.hpp"
#include "gl/src/vertex_state.hpp"
#include "shadelab/detail/default_init.hpp"
#include "shadelab/light.hpp"
#include "shadelab/material.hpp"
#include "shadelab/pipeline.hpp"
#include "shadelab/texture.hpp"

namespace shadelab::gl {

// Implementation limits, reported through glGet. Stack depths are Mesa's; lights are more
// than Mesa's 8 because the lecture's night scene uses 16 spot lights.
inline constexpr int kMaxLights = 32;
inline constexpr int kMaxModelviewDepth = 32;
inline constexpr int kMaxProjectionDepth = 32;
inline constexpr int kMaxTextureStackDepth = 10;
inline constexpr int kMaxTextureSize = 16384;  // as llvmpipe's
inline constexpr int kMaxTextureLevels = 15;    // levels 0 .. log2(kMaxTextureSize)
inline constexpr int kMax3dTextureSize = 2048;  // GL_MAX_3D_TEXTURE_SIZE, as llvmpipe's
inline constexpr int kMax3dTextureLevels = 12;  // levels 0 .. log2(kMax3dTextureSize)
inline constexpr int kMaxViewportDim = 16384;
inline constexpr int kMaxBufferDim = 16384;  // OSMESA_MAX_WIDTH / OSMESA_MAX_HEIGHT

struct MatrixStack {
  std::vector<glm::mat4> entries{glm::mat4(1.0f)};
  std::size_t max_depth = 32;
  glm::mat4& top() { return entries.back(); }
  const glm::mat4& top() const { return entries.back(); }
};

/// Lighting state (GL 1.1 section 2.13). Lights are stored in eye space, as glLight left
/// them; Light::enabled is GL_LIGHTi.
struct LightingState {
  bool enabled = false;  // GL_LIGHTING
  std::array<Light, kMaxLights> lights;
  LightModel model;
  Material front, back;
  bool color_material = false;
  GLenum color_material_face = GL_FRONT_AND_BACK;
  GLenum color_material_mode = GL_AMBIENT_AND_DIFFUSE;
  bool normalize = false;
  bool rescale_normal = false;
  GLenum shade_model = GL_SMOOTH;
};

/// The current vertex attributes (GL 1.1 section 2.7), in object space.
struct CurrentAttribs {
  glm::vec4 color{1.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  // Per texture unit (GL 1.3 section 2.7): glTexCoord sets unit 0's, glMultiTexCoord any.
  std::array<glm::vec4, kMaxTextureUnits> texcoords = FragmentRect::filled_texcoords();
  float index = 1.0f;      // GL_CURRENT_INDEX: kept, colours nothing in an RGBA context
  float edge_flag = 1.0f;  // GL_EDGE_FLAG as given (GL_TRUE only when exactly 1, as Mesa's)
  // GL 1.4 section 2.7: GL_CURRENT_SECONDARY_COLOR (glSecondaryColor3* sets red, green and
  // blue; alpha stays 1, as Mesa's) and GL_CURRENT_FOG_COORDINATE.
  glm::vec4 secondary{0.0f, 0.0f, 0.0f, 1.0f};
  float fog_coord = 0.0f;
};

/// Per-fragment operations and the framebuffer controls, kept as GL enums (what glGet
/// returns); draw_state.cpp translates them into the core's FragmentState.
struct RasterState {
  Viewport viewport;
  bool depth_test = false;
  GLenum depth_func = GL_LESS;
  bool depth_mask = true;
  bool blend = false;
  GLenum blend_src = GL_ONE, blend_dst = GL_ZERO;  // the colour factors (GL_BLEND_SRC_RGB, ...)
  // GL 1.4 (section 4.1.7): glBlendFuncSeparate's alpha factors, glBlendEquation (the colour's
  // and alpha's, apart with EXT_blend_equation_separate), and glBlendColor's constant, clamped
  // to [0, 1] when given.
  GLenum blend_src_alpha = GL_ONE, blend_dst_alpha = GL_ZERO;
  GLenum blend_equation = GL_FUNC_ADD, blend_equation_alpha = GL_FUNC_ADD;
  glm::vec4 blend_color{0.0f};
  bool cull = false;
  GLenum cull_mode = GL_BACK;
  GLenum front_face = GL_CCW;
  std::array<bool, 4> color_mask{true, true, true, true};
  // glClearIndex and glIndexMask (GL 1.1 sections 4.2.3, 4.2.2): kept and reported; they
  // apply to colour-index buffers only.
  GLuint clear_index = 0, index_mask = ~0u;
  bool stencil_test = false;
  GLenum stencil_func = GL_ALWAYS;
  GLint stencil_ref = 0;
  GLuint stencil_value_mask = 0xff, stencil_write_mask = 0xff;
  GLenum stencil_fail = GL_KEEP, stencil_zfail = GL_KEEP, stencil_zpass = GL_KEEP;
  bool polygon_offset_fill = false;
  float offset_factor = 0.0f, offset_units = 0.0f;
  glm::vec4 clear_color{0.0f};
  double clear_depth = 1.0;
  GLint clear_stencil = 0;
  bool dither = true;  // accepted and reported; shadelab never dithers (nor does llvmpipe)
  // glScissor (GL 1.1 section 4.1.2): the box as given; the first binding to a drawable sets
  // it to the drawable's size (set_initial_window_state).
  bool scissor_test = false;
  GLint scissor_x = 0, scissor_y = 0;
  GLsizei scissor_width = 0, scissor_height = 0;
  // glAlphaFunc (4.1.3): the reference clamped to [0, 1].
  bool alpha_test = false;
  GLenum alpha_func = GL_ALWAYS;
  float alpha_ref = 0.0f;
  // glLogicOp (4.1.7). GL 1.1's GL_LOGIC_OP is GL_INDEX_LOGIC_OP: accepted, no effect on
  // RGBA buffers (as in Mesa); GL_COLOR_LOGIC_OP is the one that applies.
  bool color_logic_op = false, index_logic_op = false;
  GLenum logic_op = GL_COPY;
  // glPolygonStipple (3.5.2): rows[y] bit x is pixel (x, y) of the pattern (bit 0 leftmost,
  // the core's PolygonStipple layout); initially all ones.
  bool polygon_stipple = false;
  std::array<std::uint32_t, 32> stipple = filled_stipple();

  static std::array<std::uint32_t, 32> filled_stipple() {
    std::array<std::uint32_t, 32> rows;
    rows.fill(~0u);
    return rows;
  }
};

/// Fog (GL 1.1 section 3.9), as glFog sets it and glGet reports it.
struct FogSettings {
  bool enabled = false;  // GL_FOG
  GLenum mode = GL_EXP;
  glm::vec4 color{0.0f};  // clamped to [0, 1]
  float density = 1.0f, start = 0.0f, end = 1.0f;
  float index = 0.0f;  // GL_FOG_INDEX: stored and reported (colour-index mode only)
  // GL 1.4: GL_FOG_COORDINATE_SOURCE (section 3.10: the per-vertex fog coordinate or the
  // fragment's eye distance) and GL_COLOR_SUM (section 3.9: the secondary colour added to
  // the primary when lighting is off), both in the fog attribute group.
  GLenum coord_source = GL_FRAGMENT_DEPTH;
  bool color_sum = false;
  /// Whether fragments are fogged by the vertices' fog coordinates (GL_FOG_COORDINATE source).
  bool by_coordinates() const { return enabled && coord_source == GL_FOG_COORDINATE; }
};

// Mesa's limits for points and lines (glGet GL_POINT_SIZE_RANGE, GL_LINE_WIDTH_RANGE and
// their granularity) and its number of user clip planes.
inline constexpr float kMaxPointSize = 255.0f, kMaxLineWidth = 255.0f, kSizeGranularity = 0.1f;
// The least derived size of an attenuated point (Mesa's MinPointSize: the vertex program's clamp).
inline constexpr float kMinPointSize = 1.0f;
inline constexpr int kMaxClipPlanes = 8;

/// Points, lines, the polygon modes and the user clip planes (GL 1.1 sections 2.11, 3.3-3.5).
struct PrimState {
  GLfloat point_size = 1.0f;
  bool point_smooth = false;
  // glPointParameter (GL 1.4 section 3.3): the derived size's clamps, the fade threshold
  // (stored and reported) and the distance attenuation coefficients (a, b, c).
  GLfloat point_min = 0.0f, point_max = kMaxPointSize, point_fade = 1.0f;
  glm::vec3 point_attenuation{1.0f, 0.0f, 0.0f};
  // ARB_point_sprite: the enable, and each texture unit's GL_COORD_REPLACE_ARB (a bit per unit;
  // both in the point attribute group, the enable in the enable group too).
  bool point_sprite = false;
  std::uint8_t coord_replace = 0;
  GLfloat line_width = 1.0f;
  bool line_smooth = false, line_stipple = false;
  GLushort stipple_pattern = 0xffff;
  GLint stipple_repeat = 1;
  GLenum front_mode = GL_FILL, back_mode = GL_FILL;
  bool offset_point = false, offset_line = false;
  bool polygon_smooth = false;  // llvmpipe draws polygons unsmoothed whatever it says
  std::array<glm::vec4, kMaxClipPlanes> clip_planes{};  // eye space, as glGetClipPlane returns them
  std::array<bool, kMaxClipPlanes> clip_enabled{};
  bool unfilled() const { return front_mode != GL_FILL || back_mode != GL_FILL; }
};

/// Multisampling (GL 1.3; GL 1.5 section 3.2.1): the enables and glSampleCoverage's values.
/// They change pixels only in a context whose visual has a multisample buffer (SampleBuffers).
struct MultisampleState {
  bool enabled = true;  // GL_MULTISAMPLE
  bool alpha_to_coverage = false, alpha_to_one = false, coverage = false;
  float coverage_value = 1.0f;  // clamped to [0, 1]
  bool coverage_invert = false;
};

/// The multisample buffer of a visual with samples (GL 1.5 sections 3.2.1 and 4.1.10;
/// multisample.cpp): a colour, depth and stencil value per sample. Sample 0's depth and
/// stencil are the framebuffer's own (what glReadPixels reads); every sample's colour, and the
/// other samples' depth and stencil, are here. Drawing draws each sample in turn: its buffers
/// are exchanged into `fb` (`active`) and the primitive is drawn with its geometry shifted so
/// that the sample's position in each pixel falls on the pixel's centre; the colour buffer
/// (fb.color) holds the resolved colours, the samples' mean, brought up to date for the tiles
/// drawn since (`unresolved`) before anything reads it (settle_clears, present).
struct SampleBuffers {
  int count = 0;  ///< GL_SAMPLES of the visual: 4, or 0 without a multisample buffer
  int width = 0, height = 0;  ///< the framebuffer size the buffers were made for
  std::vector<ColorBuffer> color;                  ///< per sample
  std::vector<std::vector<float>> depth;           ///< samples 1 to count - 1
  std::vector<std::vector<std::uint8_t>> stencil;  ///< samples 1 to count - 1
  std::vector<std::uint8_t> unresolved;            ///< per tile of the tile map
  bool any_unresolved = false;
  int active = -1;  ///< the sample whose buffers are in fb, -1 for none
  glm::vec2 shift{0.0f};  ///< the window-space shift of the active sample's geometry
  std::vector<int> list;  ///< scratch: the tiles a resolve visits
};

/// The caller's colour buffer (OSMesaMakeCurrent) and how it is laid out.
struct UserBuffer {
  void* data = nullptr;
  int width = 0, height = 0;
  int row_length = 0;  // pixels per row; 0: width
  bool y_up = true;    // row 0 is the bottom row
  GLenum format = GL_RGBA;
};

/// What the GL layer knows of each tile of the framebuffer (the fast pipeline's squares of
/// PipelineContext::kTileSize pixels, present.cpp): whether it changed since its last copy
/// into the caller's buffer, and whether it holds nothing but the colour or depth of the last
/// glClear, which a glClear with the same value can then leave as it is. Most frames clear
/// the whole buffer and draw into a part of it: the rest is neither cleared again nor copied.
struct TileMap {
  static constexpr std::uint8_t kChanged = 1, kColorClear = 2, kDepthClear = 4;
  int columns = 0;
  std::vector<std::uint8_t> flags;  // per tile, row by row from pixel (0, 0)
  std::uint32_t clear_color = 0;    // the pixel of kColorClear tiles (RGBA8 bytes)
  float clear_depth = 0.0f;         // the depth of kDepthClear tiles
  std::vector<int> list;            // scratch: the tiles an operation visits
  std::vector<int> ahead;           // the tiles glClear clears ahead (clear_ahead)
  std::vector<int> runs;            // scratch: for_listed_tiles' runs of neighbouring tiles
  std::vector<unsigned char> clear_row;  // scratch: a row of the clear colour, caller's format
};

/// One glPushAttrib entry (GL 1.1 section 6.1.14): the mask and a copy of the structs that
/// hold the attribute groups' state, whatever the mask (pushes are rare); glPopAttrib
/// (attrib.cpp) restores the groups the mask names, in Mesa's order.
///
/// NEW STATE MUST JOIN ITS ATTRIBUTE GROUP. Whoever adds server state to GlContext (a member
/// here or a field of the structs below) looks up its group in the "Attribute" column of GL
/// 1.1's state tables (chapter 6, tables 6.5-6.25) and makes attrib.cpp's restore of that
/// group (restore_current, restore_color_buffer, ...) copy it back; a struct not copied here
/// yet is added as a member. Capabilities need nothing more: the enable group goes through
/// capability_flag and exec::Enable for every GL 1.1 capability (attrib.cpp's kCapabilities).
/// Client state (pixel store, vertex arrays) goes the same way through ClientAttribRecord.
struct AttribRecord {
  GLbitfield mask = 0;
  CurrentAttribs current;
  LightingState lighting;
  RasterState raster;
  PrimState prims;
  FogSettings fog;
  TextureState textures;  // environment; the bindings are restored through exec::BindTexture
  // Every accepted capability; a texture unit's (GL_TEXTURE_2D, GL_TEXTURE_GEN_S...) once per
  // unit.
  struct Enable {
    GLenum cap;
    std::size_t unit;  // the texture unit active when it is restored
    bool on;
  };
  std::vector<Enable> enables;
  // Per texture unit and target: the bound name and the parameters of the bound and default
  // objects.
  struct TextureTarget {
    std::size_t unit = 0;
    GLenum target = 0;
    GLuint name = 0;
    std::array<float, 19> bound{}, defaults{};  // attrib.cpp's kTextureParameters
  };
  std::vector<TextureTarget> texture_targets;
  std::array<GLenum, 7> hints{};
  GLenum matrix_mode = GL_MODELVIEW;
  GLuint list_base = 0;
  RasterPosition raster_pos;  // current group (table 6.5)
  PixelTransfer pixel;        // pixel group (table 6.17): all but the maps, which no group holds
  GLenum draw_buffer = GL_FRONT, read_buffer = GL_FRONT;  // colour-buffer and pixel groups
  glm::vec4 accum_clear{0.0f};                             // accum-buffer group
  EvalAttribs eval;
  MultisampleState multisample;  // multisample group (GL 1.3)
};

/// GL_MAX_ATTRIB_STACK_DEPTH and GL_MAX_CLIENT_ATTRIB_STACK_DEPTH (Mesa's).
inline constexpr int kMaxAttribStackDepth = 16;
inline constexpr int kMaxClientAttribStackDepth = 16;

/// The window-system drawable a context draws into (gl/src/platform: GLX windows, pixmaps and
/// pbuffers), told of what the GL does that concerns it: a flush (glFlush / glFinish: the
/// drawable presents into its image what it shows, a single-buffered window its buffer, a
/// double-buffered one what was drawn into its front buffer) and glViewport (where llvmpipe checks a window's size, since GLUT programs set the
/// viewport when resized). OSMesa buffers have none.
class SurfaceHooks {
 public:
  virtual void flushed(struct GlContext& c) = 0;
  virtual void viewport_set(struct GlContext& c) = 0;

 protected:
  ~SurfaceHooks() = default;
};

struct FrameCapture;  // capture.cpp
struct FrameCaptureDeleter {
  void operator()(FrameCapture* f) const;
};

struct GlContext {
  // Creation parameters
  GLenum buffer_format = GL_RGBA;
  int depth_bits = 24, stencil_bits = 8;

  GLenum error = GL_NO_ERROR;
  LightingState lighting;
  CurrentAttribs current;
  RasterState raster;
  PrimState prims;
  FogSettings fog;
  MultisampleState multisample;  // glSampleCoverage and the multisample enables
  TextureState textures;
  PixelStore pack, unpack;
  PixelTransfer pixel;         // glPixelTransfer, glPixelMap, glPixelZoom
  RasterPosition raster_pos;   // glRasterPos
  BufferState buffers;         // glDrawBuffer, glReadBuffer, the accumulation buffer
  ClientArrays arrays;
  std::shared_ptr<BufferNames> buffer_names;  // GL 1.5 buffer objects (bufferobj.cpp)
  ListState lists;
  EvalState eval;
  GLenum render_mode = GL_RENDER;  // glRenderMode (feedback.cpp)
  SelectionState selection;
  FeedbackState feedback;
  QueryState queries;  // glBeginQuery (queryobj.cpp)
  RenderModeObserver render_mode_observer{*this};
  std::vector<AttribRecord> attrib_stack;              // glPushAttrib
  std::vector<ClientAttribRecord> client_attrib_stack;  // glPushClientAttrib
  Primitive prim;
  ArrayScratch array_scratch;
  ImmediateScratch immediate_scratch;
  // glHint, by state.cpp's hint_slot: the GL 1.1 hints, then GL_GENERATE_MIPMAP_HINT (1.4) and
  // GL 1.3's GL_TEXTURE_COMPRESSION_HINT (accepted, no compression either way).
  std::array<GLenum, 7> hints{GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE,
                              GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE};

  GLenum matrix_mode = GL_MODELVIEW;
  MatrixStack modelview{{glm::mat4(1.0f)}, kMaxModelviewDepth};
  MatrixStack projection{{glm::mat4(1.0f)}, kMaxProjectionDepth};
  // One texture matrix stack per texture unit (GL 1.3 section 2.10.2).
  std::array<MatrixStack, kMaxTextureUnits> texture_matrices{
      MatrixStack{{glm::mat4(1.0f)}, kMaxTextureStackDepth}, MatrixStack{{glm::mat4(1.0f)}, kMaxTextureStackDepth},
      MatrixStack{{glm::mat4(1.0f)}, kMaxTextureStackDepth}, MatrixStack{{glm::mat4(1.0f)}, kMaxTextureStackDepth}};
  /// The active texture unit's stack (what GL_TEXTURE mode and the queries address).
  MatrixStack& texture_matrix() { return texture_matrices[textures.active]; }
  const MatrixStack& texture_matrix() const { return texture_matrices[textures.active]; }

  Framebuffer fb;
  /// The fast pipeline's threads and buffers, made at the first draw and kept for the
  /// context's life; null with SHADELAB_REFERENCE set (the reference pipeline draws).
  std::unique_ptr<PipelineContext> pipeline;
  bool use_reference = false;
  /// The texture objects draws waiting in `pipeline` read, kept alive until they are drawn
  /// (texture_draw_state), each with the number of the last draw that read it
  /// (PipelineContext::draws_made).
  struct KeptTexture {
    std::shared_ptr<const TextureObject> object;
    std::uint64_t draw = 0;
  };
  std::vector<KeptTexture> textures_of_waiting_draws;
  /// SHADELAB_STATS: the file a line of the context's draw and fragment counts is appended to
  /// when it is destroyed (PipelineContext::set_counting); empty: no counting.
  std::string stats_path;
  /// SHADELAB_CAPTURE_SCENE: the frame kept as a scene file (capture.hpp); null without it.
  std::unique_ptr<FrameCapture, FrameCaptureDeleter> capture;
  UserBuffer user;
  TileMap tiles;
  bool ever_current = false;  // the first OSMesaMakeCurrent sets the viewport
  std::vector<std::uint8_t> depth_export;  // OSMesaGetDepthBuffer's copy
  bool depth_exported = false;
  SurfaceHooks* surface = nullptr;  // the drawable it draws into, when a platform bound one
  bool double_buffered = false;     // GL_DRAW_BUFFER / GL_READ_BUFFER are GL_BACK
  /// A double-buffered drawable's two colour buffers (buffers.cpp): `fb.color` holds the one
  /// the draw buffer names (the back one unless the program draws into the front only), and
  /// `other_color` the other while the program uses its front buffer (empty otherwise: the
  /// front buffer is then the surface's image, what was last shown).
  ColorBuffer other_color;
  bool front_in_fb = false;
  SampleBuffers ms;  ///< the multisample buffer, when the visual has samples

  /// A context with OpenGL's initial state; it shares texture objects and display lists
  /// with `share` when there is one (OSMesa's sharelist, GLX's share context).
  GlContext(GLenum format, int depth, int stencil, const GlContext* share);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  /// Records `code` unless an earlier error is still unread (GL 1.1 section 2.5).
  void set_error(GLenum code) {
    if (error == GL_NO_ERROR) error = code;
  }
  MatrixStack& current_stack();
};

/// The context current in this thread (nullptr when none). Initial-exec TLS, as Mesa's own
/// dispatch pointer: every GL call reads it with one load, where the default model for a
/// shared library calls __tls_get_addr (glBegin/glEnd programs make tens of thousands of calls
/// a frame).
inline thread_local GlContext* current_context_ __attribute__((tls_model("initial-exec"))) = nullptr;
inline GlContext*& current_context() { return current_context_; }

/// Runs `f(ctx)` on the current context, if any; exceptions (out of memory) become
/// GL_OUT_OF_MEMORY so that nothing unwinds into C callers. For the OSMesa calls that act on
/// the current context; GL commands get this from their generated entry points
/// (gl/generated/run.hpp).
template <class F>
void with_context(F&& f) noexcept {
  GlContext* c = current_context();
  if (!c) return;
  try {
    f(*c);
  } catch (...) {
    c->set_error(GL_OUT_OF_MEMORY);
  }
}

/// What the first binding of a context to a drawable of `width` x `height` pixels sets: the
/// viewport and the scissor box (GL 1.1 sections 2.10.1 and 4.1.2).
void set_initial_window_state(GlContext& c, int width, int height);

/// Makes the context's pipeline at first use, drawing deferred (PipelineContext::set_deferred:
/// a frame's draws are rasterized tile by tile when something reads the framebuffer); none
/// with use_reference.
void make_pipeline(GlContext& c);
/// Copies the tiles changed since the last copy into the caller's buffer (present.cpp).
void present(GlContext& c);
/// The caller's buffer (a surface's image) read into `into` in the framebuffer's layout, as
/// many pixels as the framebuffer has (formats without alpha read as opaque).
void read_user_buffer(const GlContext& c, ColorBuffer& into);
/// Rasterizes the deferred draws and applies the clears left to the draws
/// (PipelineContext::PendingClears) now: before anything but a draw through the pipeline reads
/// or writes the framebuffer.
void settle_clears(GlContext& c);
/// Sizes the tile map for the framebuffer: nothing changed, nothing known cleared, nothing
/// pending.
void reset_tiles(GlContext& c);
/// Refreshes `depth_export` from the framebuffer's depth (and stencil) in Mesa's layout.
void export_depth(GlContext& c);
/// Marks the tiles a window-space rectangle touches as changed, colour and depth alike.
void mark_dirty(GlContext& c, int x0, int y0, int x1, int y1);
/// After a draw_triangles through c.pipeline: marks the tiles it may have written (those
/// the pipeline names) as changed.
void mark_drawn(GlContext& c);
/// Every tile to be copied again at the next present (the caller's buffer layout changed).
void mark_all_changed(GlContext& c);
/// Runs fn(x0, y0, x1, y1) over pixel rectangles [x0, x1) x [y0, y1) that together cover
/// the tiles in c.tiles.list (in increasing order): a run of neighbours in a row of tiles is
/// one rectangle, so that a run across the whole buffer is filled or copied as contiguous
/// memory. On the pipeline's threads, a rectangle each, when there are many tiles.
template <class Fn>
void for_listed_tiles(GlContext& c, const Fn& fn) {
  constexpr int kSize = PipelineContext::kTileSize;
  TileMap& m = c.tiles;
  m.runs.clear();  // (first tile, tiles) pairs
  for (std::size_t i = 0; i < m.list.size();) {
    std::size_t j = i + 1;
    while (j < m.list.size() && m.list[j] == m.list[j - 1] + 1 && m.list[j] % m.columns != 0) ++j;
    m.runs.push_back(m.list[i]);
    m.runs.push_back(int(j - i));
    i = j;
  }
  auto rects = [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r) {
      const int first = m.runs[2 * r], tx = (first % m.columns) * kSize, ty = (first / m.columns) * kSize;
      fn(tx, ty, std::min(tx + m.runs[2 * r + 1] * kSize, c.fb.width), std::min(ty + kSize, c.fb.height));
    }
  };
  const std::size_t runs = m.runs.size() / 2;
  if (c.pipeline && m.list.size() >= 16) c.pipeline->parallel_for(runs, 1, rects);
  else rects(0, runs);
}

/// Sets what the context's visual gives it (buffers.cpp): a double-buffered colour buffer
/// (GL_DRAW_BUFFER and GL_READ_BUFFER start as GL_BACK), accumulation bits per channel and a
/// multisample buffer (of 4 samples, the one count there is) when `samples` is above 0.
void configure_buffers(GlContext& c, bool double_buffered, int accum_bits, int samples = 0);
/// Whether drawing writes colour (GL_DRAW_BUFFER is not GL_NONE).
bool draws_color(const GlContext& c);
/// Puts the colour buffer GL_DRAW_BUFFER names into fb.color (the back one when it names both)
/// and, when it names the front buffer, the other one into other_color: after glDrawBuffer,
/// glPopAttrib, a swap and a binding to a drawable (buffers.cpp).
void select_draw_buffer(GlContext& c);
/// The colour buffer GL_READ_BUFFER names, its pending draws and clears applied.
const ColorBuffer& read_color_buffer(GlContext& c);
/// Whether GL_DRAW_BUFFER names both the front and the back buffer of a double-buffered
/// drawable (GL_FRONT_AND_BACK, GL_LEFT).
bool draws_both_buffers(const GlContext& c);
/// Exchanges fb.color and other_color, the pending draws and clears applied first (a front
/// buffer exchanged out of fb.color is presented, so that the surface's image shows it).
void exchange_color_buffers(GlContext& c);
/// Binding to a drawable: the back buffer in fb.color, the old drawable's front let go.
void leave_drawable(GlContext& c);
/// A swap made the back buffer the front one (the surface's image): the copy of the old
/// front is dropped and the draw buffer selected again.
void swapped_color_buffers(GlContext& c);
/// The depth and stencil values before a drawing that goes into both colour buffers: the
/// second pass starts from them, so that both buffers get the fragments the first one got.
struct DepthStencilCopy {
  std::vector<float> depth;
  std::vector<std::uint8_t> stencil;
};
DepthStencilCopy save_depth_stencil(GlContext& c);
void restore_depth_stencil(GlContext& c, DepthStencilCopy& saved);
/// Multisampling (multisample.cpp). Exchanges sample k's buffers into fb, for a pass that
/// draws that sample (the waiting draws finished first); leave_sample puts them back.
void enter_sample(GlContext& c, int k);
void leave_sample(GlContext& c);
/// The samples a primitive may cover: all of them, less those glSampleCoverage's mask leaves
/// out when GL_SAMPLE_COVERAGE is on (a bit per sample).
unsigned sample_mask(const GlContext& c);
/// A sample pass's fragment state with GL_MULTISAMPLE on: smooth points and lines drawn as
/// multisampled ones, and GL_SAMPLE_ALPHA_TO_COVERAGE's test of the fragment's alpha.
void sample_fragment_state(const GlContext& c, FragmentState& f);
/// `projection` followed by the active sample pass's shift (unchanged outside a pass).
glm::mat4 sample_projection(const GlContext& c, const glm::mat4& projection);
/// Brings the resolved colours of the tiles drawn since the last resolve up to date (nothing
/// during a sample pass or without a multisample buffer). settle_clears and present call it.
void resolve_samples(GlContext& c);
/// After the samples were drawn into both colour buffers' multisample buffer: resolves into
/// the front one as well as into fb.color.
void resolve_into_both_buffers(GlContext& c);
/// The occlusion-query counts a pass of a drawing adds to: the first pass's, and every
/// sample's (GL 1.5 section 4.1.6: samples are counted where there is a multisample buffer).
inline RenderStats* pass_counts(GlContext& c, bool first) {
  return first || c.ms.active >= 0 ? query_counts(c) : nullptr;
}
/// Runs fn() once with each sample's buffers in fb (once, with fb's own, without a multisample
/// buffer): writes that bypass rasterization (stencil and depth images) reach every sample.
template <class Fn>
void for_each_sample_buffer(GlContext& c, const Fn& fn) {
  if (c.ms.count == 0) return fn();
  for (int k = 0; k < c.ms.count; ++k) {
    enter_sample(c, k);
    fn();
    leave_sample(c);
  }
}

/// Runs draw(first) once for each colour buffer GL_DRAW_BUFFER names: once (true) into
/// fb.color; with both buffers named, a second time (false: occlusion queries and the frame
/// capture have counted it already) into the front buffer, from the same depth and stencil.
/// With a multisample buffer, once per sample the coverage mask leaves in (first: the first
/// of them), then resolved into the colour buffers named.
template <class Draw>
void for_each_draw_buffer(GlContext& c, const Draw& draw) {
  if (c.ms.count > 0) {
    const unsigned mask = sample_mask(c);
    bool first = true;
    for (int k = 0; k < c.ms.count; ++k) {
      if (!(mask >> k & 1u)) continue;
      enter_sample(c, k);
      draw(first);
      leave_sample(c);
      first = false;
    }
    if (draws_both_buffers(c)) resolve_into_both_buffers(c);
    return;
  }
  if (!draws_both_buffers(c)) return draw(true);
  DepthStencilCopy saved = save_depth_stencil(c);
  draw(true);
  exchange_color_buffers(c);
  restore_depth_stencil(c, saved);
  draw(false);
  exchange_color_buffers(c);
}
/// glClear's GL_ACCUM_BUFFER_BIT: the accumulation buffer (if any) to glClearAccum's value,
/// inside the scissor box when the scissor test is on (accum.cpp).
void clear_accum(GlContext& c);
/// The scissor box cut to the framebuffer, [x0, x1) x [y0, y1), when the scissor test is on
/// and leaves some pixel of the framebuffer out; false (the box not set) when every pixel
/// passes (fragment.cpp, GL 1.1 section 4.1.2).
bool scissor_box(const GlContext& c, int& x0, int& y0, int& x1, int& y1);

/// The flag behind a glEnable capability (nullptr: not accepted) and behind a client array.
bool* capability_flag(GlContext& c, GLenum cap);
/// The flags of the evaluator capabilities (GL_MAPn_*, GL_AUTO_NORMAL), nullptr for others
/// (eval.cpp).
bool* eval_capability_flag(GlContext& c, GLenum cap);
/// The number of values of a control point of an evaluator target, 0 for another enum.
int eval_components(GLenum target);
bool* client_capability_flag(GlContext& c, GLenum cap);

/// Applies the current colour to the material parameters glColorMaterial selects, when
/// GL_COLOR_MATERIAL is on (GL 1.1 section 2.13.3).
void apply_color_material(GlContext& c);

/// Before the material changes inside glBegin/glEnd: lights the primitive's vertices so far
/// with the material still in force, so later vertices can take the new one (draw.cpp).
void settle_lighting(GlContext& c);

}  // namespace shadelab::gl
