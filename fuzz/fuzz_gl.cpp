// Sequences of GL calls: the input bytes are decoded into libshadelab-gl calls on a 32x32
// OSMesa context (with a multisample buffer for a quarter of the seeds), with arbitrary enums (valid and not), values (NaN, infinities, huge,
// negative), calls between glBegin and glEnd or outside, in any order, compiled into display
// lists or not (lists calling lists, themselves, glCallLists over up to 65,536 names), evaluator
// maps of every order and the meshes they draw. Only what OpenGL cannot defend against is kept
// valid: every pointer handed to the library points into buffers of this program that are large
// enough for what the call may read or write.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

// EXT_blend_equation_separate's command, which <GL/gl.h> does not declare.
extern "C" void glBlendEquationSeparateEXT(GLenum mode_rgb, GLenum mode_alpha);

namespace {

class Input {
 public:
  Input(const std::uint8_t* d, std::size_t n) : d_(d), n_(n) {}
  bool done() const { return i_ >= n_; }
  std::uint8_t byte() { return i_ < n_ ? d_[i_++] : 0; }
  int small(int lo, int hi) { return lo + byte() % (hi - lo + 1); }
  // Interesting floats: small values, edges of ranges, and values no GL call should choke on.
  float number() {
    static const float kSpecial[] = {0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 90.0f, 128.0f, 180.0f, 1e-30f, 1e30f,
                                     -1e30f, std::numeric_limits<float>::infinity(),
                                     -std::numeric_limits<float>::infinity(),
                                     std::numeric_limits<float>::quiet_NaN(), 200.0f, -5.0f};
    std::uint8_t b = byte();
    if (b < 64) return kSpecial[b % 16];
    return (float(b) - 160.0f) / 16.0f;
  }
  GLenum any_enum() {
    static const GLenum kEnums[] = {
        GL_LIGHTING, GL_LIGHT0, GL_LIGHT1, GL_LIGHT7, GL_LIGHT0 + 31, GL_LIGHT0 + 40, GL_NORMALIZE,
        GL_RESCALE_NORMAL, GL_DEPTH_TEST, GL_BLEND, GL_CULL_FACE, GL_COLOR_MATERIAL, GL_STENCIL_TEST,
        GL_POLYGON_OFFSET_FILL, GL_TEXTURE_2D, GL_FRONT, GL_BACK, GL_FRONT_AND_BACK, GL_AMBIENT,
        GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS, GL_AMBIENT_AND_DIFFUSE, GL_POSITION,
        GL_SPOT_DIRECTION, GL_SPOT_CUTOFF, GL_SPOT_EXPONENT, GL_CONSTANT_ATTENUATION,
        GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION, GL_LIGHT_MODEL_AMBIENT,
        GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE, GL_LIGHT_MODEL_COLOR_CONTROL,
        GL_SEPARATE_SPECULAR_COLOR, GL_FLAT, GL_SMOOTH, GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE,
        GL_NEVER, GL_LESS, GL_LEQUAL, GL_ALWAYS, GL_ZERO, GL_ONE, GL_SRC_ALPHA,
        GL_ONE_MINUS_SRC_ALPHA, GL_DST_COLOR, GL_SRC_ALPHA_SATURATE, GL_KEEP, GL_REPLACE, GL_INCR,
        GL_DECR, GL_INVERT, GL_CW, GL_CCW, GL_RGBA, GL_RGB, GL_LUMINANCE, GL_ALPHA, GL_UNSIGNED_BYTE,
        GL_FLOAT, GL_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT, GL_INT, GL_DOUBLE,
        GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_NEAREST,
        GL_LINEAR, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_REPEAT, GL_CLAMP,
        GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE, GL_DECAL, GL_TEXTURE_ENV_COLOR,
        GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON,
        GL_POINTS, GL_LINES, GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_TEXTURE_COORD_ARRAY,
        GL_MAX_LIGHTS, GL_MODELVIEW_MATRIX, GL_VIEWPORT, GL_DEPTH_RANGE, GL_COLOR_CLEAR_VALUE,
        GL_CURRENT_COLOR, GL_MATRIX_MODE, GL_MAX_MODELVIEW_STACK_DEPTH, GL_UNPACK_ALIGNMENT,
        GL_PACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_PACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS,
        GL_PACK_SKIP_PIXELS, GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST, GL_VENDOR, GL_EXTENSIONS,
        GL_COMPILE, GL_COMPILE_AND_EXECUTE, GL_2_BYTES, GL_3_BYTES, GL_4_BYTES, GL_LIST_INDEX,
        GL_LIST_MODE, GL_LIST_BASE, GL_MAX_LIST_NESTING,
        GL_FOG, GL_SCISSOR_TEST, GL_ALPHA_TEST, GL_COLOR_LOGIC_OP, GL_LOGIC_OP, GL_POLYGON_STIPPLE,
        GL_DITHER, GL_FOG_MODE, GL_FOG_DENSITY, GL_FOG_START, GL_FOG_END, GL_FOG_COLOR, GL_FOG_INDEX,
        GL_FOG_HINT, GL_EXP, GL_EXP2, GL_XOR, GL_SET, GL_CLEAR, GL_SCISSOR_BOX, GL_ALPHA_TEST_REF,
        GL_LOGIC_OP_MODE, GL_UNPACK_LSB_FIRST, GL_PACK_LSB_FIRST, GL_UNPACK_SKIP_PIXELS,
        // Pixel operations: formats, types, copy types, pixel store, transfer and map names,
        // buffers, accumulation operations.
        GL_COLOR_INDEX, GL_STENCIL_INDEX, GL_DEPTH_COMPONENT, GL_RED, GL_GREEN, GL_BLUE,
        GL_LUMINANCE_ALPHA, GL_BGR, GL_BGRA, GL_BITMAP, GL_COLOR, GL_DEPTH, GL_STENCIL,
        GL_UNSIGNED_BYTE_3_3_2, GL_UNSIGNED_SHORT_5_6_5_REV, GL_UNSIGNED_SHORT_4_4_4_4,
        GL_UNSIGNED_SHORT_1_5_5_5_REV, GL_UNSIGNED_INT_8_8_8_8_REV, GL_UNSIGNED_INT_10_10_10_2,
        GL_UNPACK_SWAP_BYTES, GL_PACK_SWAP_BYTES, GL_PACK_SKIP_ROWS, GL_MAP_COLOR, GL_MAP_STENCIL,
        GL_INDEX_SHIFT, GL_INDEX_OFFSET, GL_RED_SCALE, GL_GREEN_BIAS, GL_ALPHA_SCALE, GL_DEPTH_SCALE, GL_DEPTH_BIAS,
        GL_ZOOM_X, GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R,
        GL_PIXEL_MAP_I_TO_A, GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_A_TO_A, GL_PIXEL_MAP_R_TO_R_SIZE,
        GL_CURRENT_RASTER_POSITION, GL_CURRENT_RASTER_COLOR, GL_CURRENT_RASTER_DISTANCE,
        GL_CURRENT_RASTER_POSITION_VALID, GL_ACCUM_RED_BITS, GL_ACCUM_CLEAR_VALUE, GL_DRAW_BUFFER,
        GL_NONE, GL_LEFT, GL_RIGHT, GL_AUX0, GL_FRONT_LEFT, GL_BACK_RIGHT, GL_ACCUM, GL_LOAD,
        GL_RETURN, GL_MULT, GL_ADD,
        // Textures: targets, texture generation, internal formats, level parameters.
        GL_TEXTURE_1D, GL_PROXY_TEXTURE_1D, GL_PROXY_TEXTURE_2D, GL_S, GL_T, GL_R, GL_Q,
        GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP, GL_OBJECT_PLANE,
        GL_EYE_PLANE, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_Q, GL_INTENSITY, GL_RGB5_A1, GL_RGBA16,
        GL_R3_G3_B2, GL_TEXTURE_BORDER_COLOR, GL_TEXTURE_WIDTH, GL_TEXTURE_BORDER,
        GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_PRIORITY, GL_TEXTURE_RESIDENT,
        // GL 1.4's per-vertex state: the colour sum, the secondary colour array.
        GL_COLOR_SUM, GL_SECONDARY_COLOR_ARRAY, GL_CURRENT_SECONDARY_COLOR,
        GL_FOG_COORD_ARRAY, GL_FOG_COORD_SRC, GL_FOG_COORD, GL_FRAGMENT_DEPTH, GL_CURRENT_FOG_COORD,
        GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX, GL_POINT_FADE_THRESHOLD_SIZE, GL_POINT_DISTANCE_ATTENUATION,
        // GL 1.4's blending and stencil, GL 1.5's occlusion queries.
        GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX, GL_CONSTANT_COLOR,
        GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_COLOR,
        GL_ONE_MINUS_DST_COLOR, GL_BLEND_COLOR, GL_BLEND_EQUATION, 0x883D /* GL_BLEND_EQUATION_ALPHA_EXT */, GL_BLEND_SRC_RGB, GL_BLEND_DST_ALPHA,
        GL_INCR_WRAP, GL_DECR_WRAP, GL_SAMPLES_PASSED, GL_QUERY_RESULT, GL_QUERY_RESULT_AVAILABLE,
        GL_QUERY_COUNTER_BITS, GL_CURRENT_QUERY,
        // GL 1.3's multisample enables.
        GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE,
        // GL 1.2-1.4 texture state: wrap modes, LOD clamps and bias, level range, generation.
        GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT, GL_TEXTURE_WRAP_R,
        GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD, GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL,
        GL_TEXTURE_LOD_BIAS, GL_TEXTURE_FILTER_CONTROL, GL_MAX_TEXTURE_LOD_BIAS, GL_GENERATE_MIPMAP,
        GL_GENERATE_MIPMAP_HINT, GL_TEXTURE_3D, GL_PROXY_TEXTURE_3D, GL_TEXTURE_BINDING_3D,
        GL_MAX_3D_TEXTURE_SIZE, GL_TEXTURE_DEPTH, GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES,
        GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES,
        // GL 1.3 cube maps and their texture generation modes.
        GL_TEXTURE_CUBE_MAP, GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_CUBE_MAP_NEGATIVE_X,
        GL_TEXTURE_CUBE_MAP_POSITIVE_Y, GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, GL_TEXTURE_CUBE_MAP_POSITIVE_Z,
        GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, GL_PROXY_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP,
        GL_MAX_CUBE_MAP_TEXTURE_SIZE, GL_NORMAL_MAP, GL_REFLECTION_MAP,
        // GL 1.4 depth textures and their comparison.
        GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32, GL_TEXTURE_DEPTH_SIZE,
        GL_DEPTH_TEXTURE_MODE, GL_TEXTURE_COMPARE_MODE, GL_TEXTURE_COMPARE_FUNC, GL_COMPARE_R_TO_TEXTURE,
        // EXT_packed_depth_stencil (GL 1.5's header does not name them): GL_DEPTH_STENCIL_EXT,
        // GL_UNSIGNED_INT_24_8_EXT, GL_DEPTH24_STENCIL8_EXT, GL_TEXTURE_STENCIL_SIZE_EXT.
        0x84F9u, 0x84FAu, 0x88F0u, 0x88F1u,
        // ARB_texture_rectangle: the target, its binding, its proxy, its maximum size.
        0x84F5u, 0x84F6u, 0x84F7u, 0x84F8u,
        // ARB_point_sprite: the enable (and glTexEnv target), GL_COORD_REPLACE_ARB.
        0x8861u, 0x8862u,
        0, 1, 0x1234, 0xFFFFFFFFu, GL_TEXTURE_2D + 1};
    return kEnums[byte() % (sizeof kEnums / sizeof kEnums[0])];
  }

 private:
  const std::uint8_t* d_;
  std::size_t n_, i_ = 0;
};

constexpr int kSize = 32;           // the context's buffer
constexpr int kElements = 64;       // vertex array elements the arrays hold
constexpr int kMaxStride = 64;      // bytes
constexpr std::size_t kArrayBytes = kElements * kMaxStride + 64;
constexpr int kMaxImage = 16;       // texture and glReadPixels extents and pixel-store values

struct Buffers {
  std::vector<unsigned char> color = std::vector<unsigned char>(kSize * kSize * 4);
  alignas(16) unsigned char arrays[4][kArrayBytes];
  std::uint32_t indices[256];
  // Pixel data: (skip + extent) rows of up to max(row length, extent) pixels of up to 16 bytes
  // (4 float components), with alignment padding; far more than any allowed call can touch.
  // Room for 3D images too: up to kMaxImage skipped images of kMaxImage rows of kMaxImage
  // 16-byte pixels, and the images themselves.
  alignas(16) unsigned char pixels[(2 * kMaxImage + kSize) * (2 * kMaxImage + kSize) * 16 + 96 * 1024];
  double out[32];
  // glCallLists' names: bytes (up to 16 names of up to 4 bytes), and 65,536 GL_UNSIGNED_INT
  // names of which only the first few name lists the calls can define.
  unsigned char list_names[64];
  GLuint many_names[65536];
};

// Lists the calls may define are 1..9. So that executing one stays cheap (a list may call
// lists that call lists, up to 64 deep, and GL lets a list call itself), a list being compiled
// calls only lists of larger names, at most twice: a list's execution runs at most 2^9 others.
struct ListCalls {
  GLint compiling = 0;  // GL_LIST_INDEX when last asked
  int calls = 0;        // glCallList calls compiled into it so far
  // The name the next glCallList may use (0: none), given the fuzzer's choice.
  GLuint allowed(GLuint wanted) {
    GLint index = -1;
    glGetIntegerv(GL_LIST_INDEX, &index);  // unchanged between glBegin and glEnd: no call then
    if (index < 0) return 0;
    if (index != compiling) compiling = index, calls = 0;
    if (index == 0) return wanted;
    if (calls == 2 || wanted <= GLuint(index)) return 0;
    ++calls;
    return wanted;
  }
  bool outside_lists() {
    GLint index = -1;
    glGetIntegerv(GL_LIST_INDEX, &index);
    return index == 0;
  }
};

// Whether a buffer object is bound (GL_ARRAY_BUFFER_BINDING or GL_ELEMENT_ARRAY_BUFFER_BINDING):
// array pointers or indices are offsets then, else they must point into our memory.
bool buffer_bound(GLenum binding) {
  GLint name = 0;
  glGetIntegerv(binding, &name);  // unchanged between glBegin and glEnd
  return name != 0;
}
bool array_buffer_bound() { return buffer_bound(GL_ARRAY_BUFFER_BINDING); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;
  static Buffers* b = new Buffers;
  Input in(data, size);
  // Array contents and indices from one seed byte: the rest of the input is calls.
  std::uint8_t seed = in.byte();
  for (std::size_t i = 0; i < sizeof b->arrays; ++i) (&b->arrays[0][0])[i] = std::uint8_t(i * 37 + seed);
  for (std::size_t i = 0; i < 256; ++i) b->indices[i] = std::uint32_t(i * 7 + seed) % kElements;
  for (std::size_t i = 0; i < sizeof b->list_names; ++i) b->list_names[i] = std::uint8_t(i % 11 == 0 ? seed : i % 7);
  for (std::size_t i = 0; i < 65536; ++i) b->many_names[i] = GLuint(i < 4 ? 1 + (seed + i) % 9 : 1000 + i);
  ListCalls list_calls;
  // An accumulation buffer with odd seeds, a multisample buffer (4 samples) with one seed in 4.
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_ACCUM_BITS, seed % 2 ? 16 : 0,
                            OSMESA_SAMPLES_SHADELAB, seed % 4 == 3 ? 4 : 0, 0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!ctx) return 0;
  if (!OSMesaMakeCurrent(ctx, b->color.data(), GL_UNSIGNED_BYTE, kSize, kSize)) {
    OSMesaDestroyContext(ctx);
    return 0;
  }
  GLfloat f[4];
  int calls = 0;
  while (!in.done() && ++calls < 400) {
    const std::uint8_t op = in.byte();
    // Evaluators take the three highest bytes (which chose cases 61 to 63 before them), the
    // selection and feedback modes the byte below them (case 60 before).
    switch (op >= 253 ? 64 + (op - 253) : op == 252 ? 67 : op % 64) {
      case 0: glEnable(in.any_enum()); break;
      case 1: glDisable(in.any_enum()); break;
      case 2: glBegin(in.any_enum()); break;
      case 3: glEnd(); break;
      case 4: glVertex3f(in.number(), in.number(), in.number()); break;
      case 5: glVertex4f(in.number(), in.number(), in.number(), in.number()); break;
      case 6: glNormal3f(in.number(), in.number(), in.number()); break;
      case 7:  // the primary colour, or GL 1.4's secondary colour
        if (in.byte() % 4) glColor4f(in.number(), in.number(), in.number(), in.number());
        else if (in.byte() % 2) glSecondaryColor3f(in.number(), in.number(), in.number());
        else glFogCoordf(in.number());
        break;
      case 8: glTexCoord2f(in.number(), in.number()); break;
      case 9:
        for (float& v : f) v = in.number();
        glLightfv(in.any_enum(), in.any_enum(), f);
        break;
      case 10: glLightf(in.any_enum(), in.any_enum(), in.number()); break;
      case 11:
        for (float& v : f) v = in.number();
        glMaterialfv(in.any_enum(), in.any_enum(), f);
        break;
      case 12:
        for (float& v : f) v = in.number();
        glLightModelfv(in.any_enum(), f);
        break;
      case 13: glMatrixMode(in.any_enum()); break;
      case 14: glPushMatrix(); break;
      case 15: glPopMatrix(); break;
      case 16:  // the identity, or a matrix row by row (GL 1.3)
        for (float& v : f) v = in.number();
        switch (in.byte() % 4) {
          case 0: glLoadIdentity(); break;
          case 1: {
            const GLfloat m[16] = {f[0], f[1], 0, f[2], f[3], 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
            glLoadTransposeMatrixf(m);
            break;
          }
          case 2: {
            const GLdouble m[16] = {f[0], 0, 0, 0, f[1], f[2], 0, 0, 0, 0, f[3], 0, 0, 0, 0, 1};
            glMultTransposeMatrixd(m);
            break;
          }
          default: glMultTransposeMatrixf(reinterpret_cast<const GLfloat*>(b->out)); break;
        }
        break;
      case 17: glRotatef(in.number(), in.number(), in.number(), in.number()); break;
      case 18: glTranslatef(in.number(), in.number(), in.number()); break;
      case 19: glScalef(in.number(), in.number(), in.number()); break;
      case 20: glFrustum(in.number(), in.number(), in.number(), in.number(), in.number(), in.number()); break;
      case 21: glOrtho(in.number(), in.number(), in.number(), in.number(), in.number(), in.number()); break;
      case 22: glViewport(in.small(-40, 40), in.small(-40, 40), in.small(-2, 80), in.small(-2, 80)); break;
      case 23: glClear(GLbitfield(in.byte()) << 8 | in.byte()); break;
      case 24:  // blending (GL 1.4) and occlusion queries (GL 1.5), names 0 to 4
        switch (in.byte() % 8) {
          case 0: glBlendFunc(in.any_enum(), in.any_enum()); break;
          case 1: glBlendFuncSeparate(in.any_enum(), in.any_enum(), in.any_enum(), in.any_enum()); break;
          case 2:  // and EXT_blend_equation_separate's
            if (in.byte() % 2) glBlendEquation(in.any_enum());
            else glBlendEquationSeparateEXT(in.any_enum(), in.any_enum());
            break;
          case 3: glBlendColor(in.number(), in.number(), in.number(), in.number()); break;
          case 4: {
            GLuint names[4] = {GLuint(in.small(0, 4)), GLuint(in.small(0, 4)), 0, 1};
            if (in.byte() % 2) glGenQueries(in.small(-1, 4), names);
            else glDeleteQueries(in.small(-1, 4), names);
            break;
          }
          case 5: glBeginQuery(in.any_enum(), GLuint(in.small(0, 4))); break;
          case 6: glEndQuery(in.any_enum()); break;
          default:
            (void)glIsQuery(GLuint(in.small(0, 4)));
            glGetQueryiv(in.any_enum(), in.any_enum(), reinterpret_cast<GLint*>(b->out));
            glGetQueryObjectiv(GLuint(in.small(0, 4)), in.any_enum(), reinterpret_cast<GLint*>(b->out));
            glGetQueryObjectuiv(GLuint(in.small(0, 4)), in.any_enum(), reinterpret_cast<GLuint*>(b->out));
            break;
        }
        break;
      case 25: glDepthFunc(in.any_enum()); break;
      case 26: glStencilFunc(in.any_enum(), in.small(-2, 300), GLuint(in.byte())); break;
      case 27: glStencilOp(in.any_enum(), in.any_enum(), in.any_enum()); break;
      case 28: glShadeModel(in.any_enum()); break;
      case 29:  // polygon offset, sample coverage (GL 1.3), compressed images
        switch (in.byte() % 4) {
          case 0: glSampleCoverage(in.number(), GLboolean(in.byte() % 3)); break;
          case 1:
            glCompressedTexImage2D(in.any_enum(), in.small(-1, 4), in.any_enum(), in.small(-1, kMaxImage),
                                   in.small(-1, kMaxImage), in.small(0, 1), in.small(-1, 64), b->pixels);
            glCompressedTexSubImage1D(in.any_enum(), in.small(-1, 4), 0, in.small(-1, kMaxImage), in.any_enum(),
                                      in.small(-1, 64), b->pixels);
            break;
          case 2: glGetCompressedTexImage(in.any_enum(), in.small(-1, 4), b->pixels); break;
          default: glPolygonOffset(in.number(), in.number()); break;
        }
        break;
      case 30: {  // arrays: pointers into our buffers, strides that stay inside them
        int which = in.byte() % 6, sz = in.small(1, 4), stride = in.small(0, kMaxStride / 4) * 4;
        GLenum type = in.any_enum();
        void* p = b->arrays[which % 4];
        // Or an offset into a buffer object (GL 1.5), of any size, bound or not.
        if (in.byte() % 4 == 0) glBindBuffer(GL_ARRAY_BUFFER, GLuint(in.small(0, 3)));
        if (array_buffer_bound()) p = reinterpret_cast<void*>(std::uintptr_t(in.small(0, 64) * 4));
        if (which == 0) glVertexPointer(sz, type, stride, p);
        else if (which == 1) glNormalPointer(type, stride, p);
        else if (which == 2) glColorPointer(sz, type, stride, p);
        else if (which == 3) glTexCoordPointer(sz, type, stride, p);
        else if (which == 4) glSecondaryColorPointer(sz, type, stride, p);
        else glFogCoordPointer(type, stride, p);
        break;
      }
      case 31:
        if (in.byte() % 2) {
          glEnableClientState(in.any_enum());
          break;
        }
        switch (in.byte() % 8) {  // buffer objects (GL 1.5): names 0 to 3, either target
          case 0: {
            GLuint names[2];
            glGenBuffers(in.small(-1, 2), names);
            break;
          }
          case 1: {
            const GLuint names[2] = {GLuint(in.small(0, 3)), GLuint(in.small(0, 3))};
            glDeleteBuffers(in.small(-1, 2), names);
            (void)glIsBuffer(names[0]);
            break;
          }
          case 2: glBindBuffer(in.byte() % 2 ? GL_ARRAY_BUFFER : GL_ELEMENT_ARRAY_BUFFER + in.small(0, 1), GLuint(in.small(0, 3))); break;
          case 3:
            glBufferData(in.byte() % 2 ? GL_ARRAY_BUFFER : GL_ELEMENT_ARRAY_BUFFER, in.small(-1, 64) * 64,
                         in.byte() % 4 ? b->arrays[0] : nullptr, GL_STATIC_DRAW + in.small(-1, 10));
            break;
          case 4:
            glBufferSubData(in.byte() % 2 ? GL_ARRAY_BUFFER : GL_ELEMENT_ARRAY_BUFFER, in.small(-1, 64) * 16,
                            in.small(-1, 64) * 16, b->arrays[1]);
            glGetBufferSubData(in.byte() % 2 ? GL_ARRAY_BUFFER : GL_ELEMENT_ARRAY_BUFFER, in.small(-1, 64) * 16,
                               in.small(-1, 64) * 16, b->arrays[2]);
            break;
          case 5: {
            const GLenum target = in.byte() % 2 ? GL_ARRAY_BUFFER : GL_ELEMENT_ARRAY_BUFFER;
            GLint size = 0;
            glGetBufferParameteriv(target, GL_BUFFER_SIZE, &size);
            auto* mapped = static_cast<unsigned char*>(glMapBuffer(target, GL_READ_ONLY + in.small(-1, 3)));
            if (mapped && size > 0) mapped[in.byte() % size] = in.byte();
            break;
          }
          case 6: (void)glUnmapBuffer(in.byte() % 2 ? GL_ARRAY_BUFFER : GL_ELEMENT_ARRAY_BUFFER); break;
          default: {
            GLint v;
            void* pointer;
            glGetBufferParameteriv(in.byte() % 2 ? GL_ARRAY_BUFFER : in.any_enum(), GL_BUFFER_SIZE + in.small(-1, 3), &v);
            glGetBufferPointerv(GL_ARRAY_BUFFER, in.byte() % 2 ? GL_BUFFER_MAP_POINTER : in.any_enum(), &pointer);
            const std::uintptr_t offset = std::uintptr_t(in.small(0, 16) * 4);
            glInterleavedArrays(GL_V2F + in.small(-1, 14), in.small(0, 4) * 4,
                                array_buffer_bound() ? reinterpret_cast<void*>(offset) : b->arrays[0] + offset);
            break;
          }
        }
        break;
      case 32: glDrawArrays(in.any_enum(), in.small(0, kElements / 2), in.small(-1, kElements / 2)); break;
      case 33: {  // indexed and multiple draws (GL 1.2, 1.4), indices in client memory or a buffer
        const GLenum mode = in.any_enum();
        const GLenum type = in.byte() % 4 ? GL_UNSIGNED_INT : GL_UNSIGNED_BYTE + in.small(-1, 6);
        const bool buffer = in.byte() % 4 == 0;
        if (buffer) glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, GLuint(in.small(0, 3)));
        else glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
        const std::uintptr_t offset = std::uintptr_t(in.small(0, 16) * 4);
        const void* indices = buffer_bound(GL_ELEMENT_ARRAY_BUFFER_BINDING) ? reinterpret_cast<void*>(offset) : b->indices;
        const GLint first[3] = {in.small(-1, kElements / 2), in.small(0, kElements / 2), 0};
        // (glMultiDrawArrays reads up to element first + count: at most kElements.)
        const GLsizei count[3] = {in.small(-1, kElements / 2), in.small(0, kElements / 2), in.small(0, 3)};
        const void* lists[3] = {indices, in.byte() % 4 ? b->indices : nullptr, b->indices + 64};
        switch (in.byte() % 4) {
          case 0: glDrawElements(mode, in.small(-1, 256), type, indices); break;
          case 1:
            glDrawRangeElements(mode, GLuint(in.small(0, 70)), GLuint(in.small(0, 70)), in.small(-1, 128), type, indices);
            break;
          case 2: glMultiDrawArrays(mode, first, count, in.small(-1, 3)); break;
          default: glMultiDrawElements(mode, count, type, lists, in.small(-1, 3)); break;
        }
        break;
      }
      case 34: {  // textures with small images from our pixel buffer
        GLuint name = 0;
        glGenTextures(1, &name);
        glBindTexture(GL_TEXTURE_2D, in.byte() % 2 ? name : in.byte());
        glPixelStorei(in.any_enum(), in.small(0, kMaxImage));
        glTexImage2D(in.any_enum(), in.small(-1, 4), GLint(in.any_enum()), in.small(-1, kMaxImage),
                     in.small(-1, kMaxImage), in.small(0, 1), in.any_enum(), in.any_enum(), b->pixels);
        glTexParameteri(GL_TEXTURE_2D, in.any_enum(), GLint(in.any_enum()));
        glTexEnvi(in.any_enum(), in.any_enum(), GLint(in.any_enum()));
        // Numeric parameters (LOD clamps and biases, levels), a mipmap generation hint.
        glTexParameterf(GL_TEXTURE_2D, in.any_enum(), in.byte() % 2 ? in.number() : float(in.small(-2, 20)));
        glTexEnvf(in.any_enum(), in.any_enum(), in.number());
        glHint(in.any_enum(), in.any_enum());
        if (in.byte() % 4 == 0) glDeleteTextures(1, &name);
        break;
      }
      case 35:
        glPixelStorei(in.any_enum(), in.small(0, kMaxImage));
        glReadPixels(in.small(-4, kSize), in.small(-4, kSize), in.small(-1, kMaxImage), in.small(-1, kMaxImage),
                     in.any_enum(), in.any_enum(), b->pixels);
        break;
      case 36: {
        GLenum what = in.any_enum();
        glGetFloatv(what, reinterpret_cast<GLfloat*>(b->out));
        glGetIntegerv(what, reinterpret_cast<GLint*>(b->out));
        glGetDoublev(what, b->out);
        GLboolean flags[32];
        glGetBooleanv(what, flags);
        (void)glIsEnabled(what);
        (void)glGetString(what);
        glGetLightfv(in.any_enum(), in.any_enum(), reinterpret_cast<GLfloat*>(b->out));
        glGetMaterialfv(in.any_enum(), in.any_enum(), reinterpret_cast<GLfloat*>(b->out));
        break;
      }
      case 37: (void)glGetError(); break;
      case 38: glColorMaterial(in.any_enum(), in.any_enum()); break;
      case 40: glNewList(GLuint(in.small(-1, 9)), in.byte() % 4 ? GL_COMPILE + in.byte() % 2 : in.any_enum()); break;
      case 41: glEndList(); break;
      case 42: {
        const GLuint name = list_calls.allowed(GLuint(in.small(0, 10)));
        if (name) glCallList(name);
        break;
      }
      case 43:  // outside lists being compiled only (so that nothing recurses unboundedly)
        if (list_calls.outside_lists()) {
          if (in.byte() % 4 == 0) glCallLists(in.small(0, 255) * 256 + in.byte(), GL_UNSIGNED_INT, b->many_names);
          else glCallLists(in.small(-1, 16), in.any_enum(), b->list_names);
        }
        break;
      case 44:
        switch (in.byte() % 4) {
          case 0: (void)glGenLists(in.byte() % 8 ? in.small(-1, 8) : 0x7fffffff - in.small(0, 3)); break;
          case 1: glDeleteLists(GLuint(in.small(-1, 10)), in.byte() % 8 ? in.small(-1, 4) : 0x7fffffff); break;
          case 2: (void)glIsList(GLuint(in.small(-1, 10))); break;
          default: glListBase(GLuint(in.small(-2, 4))); break;
        }
        break;
      case 45: {  // the attribute stacks: any mask, pushed past their depth
        const GLbitfield mask = in.byte() % 4 ? GLbitfield(1) << (in.byte() % 32) : GL_ALL_ATTRIB_BITS;
        switch (in.byte() % 4) {
          case 0: glPushAttrib(mask); break;
          case 1: glPopAttrib(); break;
          case 2: glPushClientAttrib(mask); break;
          default: glPopClientAttrib(); break;
        }
        break;
      }
      case 46: {  // fog and point parameters through every form
        for (float& v : f) v = in.number();
        const GLint iv[4] = {GLint(in.any_enum()), in.small(-3, 3) << 29, in.small(-100, 100), 0x7fffffff};
        const GLenum pname = in.any_enum();
        const int form = in.byte() % 6;
        if (form < 2) glFogfv(pname, f), glFogf(pname, f[0]);
        else if (form < 4) glFogiv(pname, iv), glFogi(pname, iv[0]);
        else if (form == 4) glPointParameterfv(pname, f), glPointParameterf(pname, f[0]), glPointSize(f[1]);
        else glPointParameteriv(pname, iv), glPointParameteri(pname, iv[0]);
        break;
      }
      case 47: glScissor(in.small(-40, 40), in.small(-40, 40), in.small(-2, 80), in.small(-2, 80)); break;
      case 48: glAlphaFunc(in.any_enum(), in.number()); break;
      case 49: glLogicOp(in.byte() % 2 ? in.any_enum() : GLenum(GL_CLEAR + in.small(-1, 16))); break;
      case 50:  // the stipple through random pixel-store state (the pixel buffer holds any)
        glPixelStorei(in.any_enum(), in.small(0, kMaxImage));
        if (in.byte() % 2) glPolygonStipple(b->pixels);
        else glGetPolygonStipple(b->pixels);
        break;
      case 59:  // 1D images and sub-images, any target
        glBindTexture(in.any_enum(), in.byte() % 4);
        glTexImage1D(in.any_enum(), in.small(-1, 4), GLint(in.any_enum()), in.small(-1, kMaxImage + 2),
                     in.small(-1, 1), in.any_enum(), in.any_enum(), in.byte() % 8 ? b->pixels : nullptr);
        glTexSubImage1D(in.any_enum(), in.small(-1, 4), in.small(-2, kMaxImage), in.small(-1, kMaxImage),
                        in.any_enum(), in.any_enum(), b->pixels);
        break;
      case 60:
        glTexSubImage2D(in.any_enum(), in.small(-1, 4), in.small(-2, kMaxImage), in.small(-2, kMaxImage),
                        in.small(-1, kMaxImage), in.small(-1, kMaxImage), in.any_enum(), in.any_enum(), b->pixels);
        // 3D images (at most 6 x 6 x 5 with a border) and sub-images.
        glBindTexture(GL_TEXTURE_3D, in.byte() % 4);
        glTexImage3D(in.byte() % 2 ? GLenum(GL_TEXTURE_3D) : in.any_enum(), in.small(-1, 3), GLint(in.any_enum()),
                     in.small(-1, 4), in.small(-1, 4), in.small(-1, 3), in.small(0, 1), in.any_enum(), in.any_enum(),
                     in.byte() % 8 ? b->pixels : nullptr);
        glTexSubImage3D(in.byte() % 2 ? GLenum(GL_TEXTURE_3D) : in.any_enum(), in.small(-1, 3), in.small(-2, 4),
                        in.small(-2, 4), in.small(-2, 3), in.small(-1, 4), in.small(-1, 4), in.small(-1, 3),
                        in.any_enum(), in.any_enum(), b->pixels);
        glCopyTexSubImage3D(GL_TEXTURE_3D, in.small(-1, 3), in.small(-2, 4), in.small(-2, 4), in.small(-2, 3),
                            in.small(-20, kSize), in.small(-20, kSize), in.small(-1, 4), in.small(-1, 4));
        {  // a cube map's faces (GL 1.3), square or not, and the cube map enabled
          glBindTexture(GL_TEXTURE_CUBE_MAP, in.byte() % 4);
          const int side = in.small(-1, 4);
          glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + in.byte() % 7), in.small(-1, 3), GLint(in.any_enum()),
                       side, in.byte() % 4 ? side : in.small(-1, 4), in.small(0, 1), in.any_enum(), in.any_enum(),
                       in.byte() % 8 ? b->pixels : nullptr);
          if (in.byte() % 2) glEnable(GL_TEXTURE_CUBE_MAP);
        }
        break;
      case 61:  // copies from the framebuffer, inside it or not
        glCopyTexImage2D(in.any_enum(), in.small(-1, 4), in.any_enum(), in.small(-20, kSize), in.small(-20, kSize),
                         in.small(-1, kMaxImage + 2), in.small(-1, kMaxImage + 2), in.small(-1, 1));
        glCopyTexSubImage2D(in.any_enum(), in.small(-1, 4), in.small(-2, kMaxImage), in.small(-2, kMaxImage),
                            in.small(-20, kSize), in.small(-20, kSize), in.small(-1, kMaxImage), in.small(-1, kMaxImage));
        glCopyTexImage1D(in.any_enum(), in.small(-1, 4), in.any_enum(), in.small(-20, kSize), in.small(-20, kSize),
                         in.small(-1, kMaxImage + 2), in.small(-1, 1));
        glCopyTexSubImage1D(in.any_enum(), in.small(-1, 4), in.small(-2, kMaxImage), in.small(-20, kSize),
                            in.small(-20, kSize), in.small(-1, kMaxImage));
        break;
      case 62: {  // queries into our buffers (levels are at most kMaxImage on a side)
        glPixelStorei(in.any_enum(), in.small(0, kMaxImage));
        glGetTexImage(in.any_enum(), in.small(-1, 4), in.any_enum(), in.any_enum(), b->pixels);
        glGetTexLevelParameteriv(in.any_enum(), in.small(-1, 15), in.any_enum(), reinterpret_cast<GLint*>(b->out));
        glGetTexLevelParameterfv(in.any_enum(), in.small(-1, 15), in.any_enum(), reinterpret_cast<GLfloat*>(b->out));
        GLuint names[4] = {in.byte(), in.byte(), 0, 1};
        const GLclampf priorities[4] = {in.number(), in.number(), in.number(), in.number()};
        GLboolean resident[4];
        glPrioritizeTextures(in.small(-1, 4), names, priorities);
        (void)glAreTexturesResident(in.small(-1, 4), names, resident);
        break;
      }
      case 63: {  // texture coordinate generation, on a texture unit of any number (GL 1.3)
        if (in.byte() % 2) {
          glActiveTexture(GL_TEXTURE0 + GLenum(in.small(-1, 4)));
          glClientActiveTexture(GL_TEXTURE0 + GLenum(in.small(-1, 4)));
          glMultiTexCoord4f(GL_TEXTURE0 + GLenum(in.small(-1, 4)), in.number(), in.number(), in.number(), in.number());
          if (in.byte() % 2) glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        }
        for (int i = 0; i < 4; ++i) f[i] = in.number();
        glTexGenfv(in.any_enum(), in.any_enum(), f);
        glTexGeni(in.any_enum(), in.any_enum(), GLint(in.any_enum()));
        glGetTexGenfv(in.any_enum(), in.any_enum(), reinterpret_cast<GLfloat*>(b->out));
        glTexCoordPointer(4, GL_FLOAT, 0, b->arrays[3]);
        break;
      }
      case 39: {
        glFinish();
        GLint w, h, bytes;
        void* depth = nullptr;
        (void)OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &depth);
        break;
      }
      case 51:  // the raster position, through the transforms or in window coordinates (GL 1.4)
        if (in.byte() % 2) glRasterPos4f(in.number(), in.number(), in.number(), in.number());
        else if (in.byte() % 2) glWindowPos3f(in.number(), in.number(), in.number());
        else glWindowPos2i(in.small(-40, 40), in.small(-40, 40));
        break;
      case 52:  // bitmaps of every size and unpack state, read from our pixel buffer
        glPixelStorei(in.any_enum(), in.small(0, kMaxImage));
        glBitmap(in.small(-1, kMaxImage), in.small(-1, kMaxImage), in.number(), in.number(), in.number(),
                 in.number(), in.byte() % 8 ? b->pixels : nullptr);
        break;
      case 53:
        glPixelStorei(in.any_enum(), in.small(0, kMaxImage));
        glDrawPixels(in.small(-1, kMaxImage), in.small(-1, kMaxImage), in.any_enum(), in.any_enum(), b->pixels);
        break;
      case 54:
        glCopyPixels(in.small(-kSize, kSize), in.small(-kSize, kSize), in.small(-1, 2 * kSize), in.small(-1, 2 * kSize),
                     in.any_enum());
        break;
      case 55: glPixelZoom(in.number(), in.number()); break;
      case 56: {  // transfer modes and maps (values from our buffer, as floats or integers)
        glPixelTransferf(in.any_enum(), in.number());
        const int n = in.small(-1, 260);
        const GLenum map = in.any_enum();
        const int kind = in.byte() % 3;
        if (kind == 0) glPixelMapfv(map, n, reinterpret_cast<const GLfloat*>(b->pixels));
        else if (kind == 1) glPixelMapuiv(map, n, reinterpret_cast<const GLuint*>(b->pixels));
        else glPixelMapusv(map, n, reinterpret_cast<const GLushort*>(b->pixels));
        break;
      }
      case 57:
        glClearAccum(in.number(), in.number(), in.number(), in.number());
        glAccum(in.any_enum(), in.number());
        break;
      case 58: {
        glDrawBuffer(in.any_enum());
        glReadBuffer(in.any_enum());
        const GLenum map = in.any_enum();
        glGetPixelMapfv(map, reinterpret_cast<GLfloat*>(b->pixels));
        glGetPixelMapuiv(map, reinterpret_cast<GLuint*>(b->pixels));
        glGetPixelMapusv(map, reinterpret_cast<GLushort*>(b->pixels));
        break;
      }
      case 67: {  // selection and feedback: modes, our buffers of any size, the name stack
        GLuint* const select = reinterpret_cast<GLuint*>(b->out);  // 64 values, never null:
        GLfloat* const feedback = reinterpret_cast<GLfloat*>(b->out);  // GL checks no select buffer
        switch (in.byte() % 6) {
          case 0: (void)glRenderMode(in.byte() % 4 ? GL_RENDER + GLenum(in.byte() % 3) : in.any_enum()); break;
          case 1: glSelectBuffer(in.small(-1, 64), select); break;
          case 2:
            glFeedbackBuffer(in.small(-1, 64), in.byte() % 8 ? GL_2D + GLenum(in.byte() % 5) : in.any_enum(),
                             in.byte() % 8 ? feedback : nullptr);
            break;
          case 3: glPushName(in.byte()); break;
          case 4: glPopName(); glLoadName(in.byte()); break;
          default: glInitNames(); glPassThrough(in.number()); break;
        }
        break;
      }
      case 64: {  // glMap1/glMap2 of any target, orders up to 31, strides up to 128 values
        // (the largest read, 30 * 128 * 2 + 4 doubles, stays inside b->pixels)
        const GLenum target = GLenum((in.byte() % 2 ? GL_MAP1_COLOR_4 : GL_MAP2_COLOR_4) + in.small(-1, 9));
        const int uorder = in.small(0, 31), vorder = in.small(0, 31);
        const int ustride = in.small(-1, 128), vstride = in.small(-1, 128);
        const float u1 = in.number(), u2 = in.number(), v1 = in.number(), v2 = in.number();
        const auto* fp = reinterpret_cast<const GLfloat*>(b->pixels);
        const auto* dp = reinterpret_cast<const GLdouble*>(b->pixels);
        switch (in.byte() % 4) {
          case 0: glMap1f(target, u1, u2, ustride, uorder, in.byte() % 8 ? fp : nullptr); break;
          case 1: glMap1d(target, u1, u2, ustride, uorder, dp); break;
          case 2: glMap2f(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, fp); break;
          default: glMap2d(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, in.byte() % 8 ? dp : nullptr);
        }
        break;
      }
      case 65: {  // grids and meshes (at most 9 x 9 grid points a mesh)
        const int un = in.small(-1, 8), vn = in.small(-1, 8);
        if (in.byte() % 2) glMapGrid1f(un, in.number(), in.number());
        else glMapGrid2d(un, in.number(), in.number(), vn, in.number(), in.number());
        const int i1 = in.small(-4, 8), j1 = in.small(-4, 8);
        if (in.byte() % 2) glEvalMesh1(in.any_enum(), i1, i1 + in.small(-1, 8));
        else glEvalMesh2(in.byte() % 2 ? GL_FILL : in.any_enum(), i1, i1 + in.small(-1, 8), j1, j1 + in.small(-1, 8));
        break;
      }
      case 66: {  // evaluation (in or out of glBegin) and glGetMap into b->pixels
        const GLenum target = GLenum((in.byte() % 2 ? GL_MAP1_COLOR_4 : GL_MAP2_COLOR_4) + in.small(-1, 9));
        glEnable(target);
        if (in.byte() % 2) glEnable(GL_AUTO_NORMAL);
        glEvalCoord1f(in.number()), glEvalCoord2f(in.number(), in.number());
        glEvalPoint1(in.small(-2, 10)), glEvalPoint2(in.small(-2, 10), in.small(-2, 10));
        const GLenum query = in.byte() % 2 ? in.any_enum() : GLenum(GL_COEFF + in.small(0, 2));
        glGetMapfv(target, query, reinterpret_cast<GLfloat*>(b->pixels));
        glGetMapdv(target, query, reinterpret_cast<GLdouble*>(b->pixels));
        glGetMapiv(target, query, reinterpret_cast<GLint*>(b->pixels));
        break;
      }
    }
  }
  glEnd();
  glFinish();
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
  return 0;
}
