// glXCopyContext (GLX 1.4 section 3.3.7: the state groups of glPushAttrib's mask copied from
// one context to another) and glXUseXFont (section 3.3.12: display lists that draw an X
// font's glyphs with glBitmap). Both work on GL front-end state only; glXUseXFont reaches the
// display-list and bitmap calls through the GL's own table, so that it uses whatever the GL
// front end implements.
#include <vector>

#include "gl/glx/glx_protocol.hpp"
#include "gl/glx/glx_context.hpp"
#include "gl/src/proc_table.hpp"

namespace shadelab::gl::glx {
namespace {

// The groups the GL front end keeps (GL 1.1 table 6.x's attribute columns).
void copy_groups(const GlContext& s, GlContext& d, unsigned long mask) {
  const RasterState& a = s.raster;
  RasterState& b = d.raster;
  if (mask & GL_CURRENT_BIT) d.current = s.current;
  if (mask & GL_LIGHTING_BIT) d.lighting = s.lighting;
  if (mask & GL_VIEWPORT_BIT) b.viewport = a.viewport;
  if (mask & GL_TRANSFORM_BIT) {
    d.matrix_mode = s.matrix_mode;
    d.lighting.normalize = s.lighting.normalize, d.lighting.rescale_normal = s.lighting.rescale_normal;
    d.prims.clip_planes = s.prims.clip_planes, d.prims.clip_enabled = s.prims.clip_enabled;
  }
  if (mask & GL_ENABLE_BIT) {
    d.lighting.enabled = s.lighting.enabled, d.lighting.color_material = s.lighting.color_material;
    for (std::size_t i = 0; i < s.lighting.lights.size(); ++i) d.lighting.lights[i].enabled = s.lighting.lights[i].enabled;
    b.depth_test = a.depth_test, b.blend = a.blend, b.cull = a.cull, b.stencil_test = a.stencil_test;
    b.polygon_offset_fill = a.polygon_offset_fill, b.dither = a.dither;
    for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {  // every texture unit's (GL 1.3)
      TextureUnitState& to = d.textures.units[u];
      const TextureUnitState& from = s.textures.units[u];
      to.enabled_1d = from.enabled_1d, to.enabled_2d = from.enabled_2d, to.enabled_3d = from.enabled_3d;
      for (std::size_t i = 0; i < 4; ++i) to.gen[i].enabled = from.gen[i].enabled;
    }
    PrimState& e = d.prims;
    const PrimState& f = s.prims;
    e.point_smooth = f.point_smooth, e.line_smooth = f.line_smooth, e.line_stipple = f.line_stipple;
    e.offset_point = f.offset_point, e.offset_line = f.offset_line,
    e.polygon_smooth = f.polygon_smooth;
    e.clip_enabled = f.clip_enabled;
  }
  if (mask & GL_LINE_BIT) {
    d.prims.line_width = s.prims.line_width, d.prims.line_smooth = s.prims.line_smooth;
    d.prims.line_stipple = s.prims.line_stipple, d.prims.stipple_pattern = s.prims.stipple_pattern;
    d.prims.stipple_repeat = s.prims.stipple_repeat;
  }
  if (mask & GL_POINT_BIT)
    d.prims.point_size = s.prims.point_size, d.prims.point_smooth = s.prims.point_smooth;
  if (mask & GL_COLOR_BUFFER_BIT) {
    b.blend = a.blend, b.blend_src = a.blend_src, b.blend_dst = a.blend_dst;
    b.color_mask = a.color_mask, b.clear_color = a.clear_color, b.dither = a.dither;
  }
  if (mask & GL_DEPTH_BUFFER_BIT) {
    b.depth_test = a.depth_test, b.depth_func = a.depth_func, b.depth_mask = a.depth_mask;
    b.clear_depth = a.clear_depth;
  }
  if (mask & GL_STENCIL_BUFFER_BIT) {
    b.stencil_test = a.stencil_test, b.stencil_func = a.stencil_func, b.stencil_ref = a.stencil_ref;
    b.stencil_value_mask = a.stencil_value_mask, b.stencil_write_mask = a.stencil_write_mask;
    b.stencil_fail = a.stencil_fail, b.stencil_zfail = a.stencil_zfail, b.stencil_zpass = a.stencil_zpass;
    b.clear_stencil = a.clear_stencil;
  }
  if (mask & GL_POLYGON_BIT) {
    b.cull = a.cull, b.cull_mode = a.cull_mode, b.front_face = a.front_face;
    b.polygon_offset_fill = a.polygon_offset_fill, b.offset_factor = a.offset_factor, b.offset_units = a.offset_units;
    d.prims.front_mode = s.prims.front_mode, d.prims.back_mode = s.prims.back_mode;
    d.prims.offset_point = s.prims.offset_point, d.prims.offset_line = s.prims.offset_line;
    d.prims.polygon_smooth = s.prims.polygon_smooth;
  }
  if (mask & GL_HINT_BIT) d.hints = s.hints;
  if (mask & GL_TEXTURE_BIT) {
    d.textures.active = s.textures.active;
    for (std::size_t u = 0; u < kMaxTextureUnits; ++u) {  // every texture unit's (GL 1.3)
      TextureUnitState& to = d.textures.units[u];
      const TextureUnitState& from = s.textures.units[u];
      to.enabled_1d = from.enabled_1d, to.enabled_2d = from.enabled_2d, to.enabled_3d = from.enabled_3d;
      to.env_mode = from.env_mode, to.env_color = from.env_color, to.lod_bias = from.lod_bias;
      to.combine = from.combine;
      to.gen = from.gen;
      if (d.textures.names != s.textures.names) continue;  // a binding means something only within a share group
      for (GLenum target : {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D}) {
        const TextureBinding& b = from.binding(target);
        TextureBinding& t = to.binding(target);
        t.name = b.name;
        t.object = b.name ? b.object : t.default_object;
      }
    }
  }
}

template <class F>
F gl_function(const char* name) {
  return reinterpret_cast<F>(find_proc(name));
}

// One glyph of `font` as a glBitmap image: rows from the bottom, most significant bit first,
// drawn by the server into a depth-1 pixmap and read back (as Mesa's xfont.c does).
std::vector<GLubyte> glyph_bitmap(Display* dpy, Pixmap pixmap, GC gc, const XCharStruct& ch, unsigned c,
                                  int width, int height) {
  const int row_bytes = (width + 7) / 8;
  std::vector<GLubyte> bits(std::size_t(row_bytes) * std::size_t(height), 0);
  XSetForeground(dpy, gc, 0);
  XFillRectangle(dpy, pixmap, gc, 0, 0, unsigned(row_bytes * 8), unsigned(height));
  XSetForeground(dpy, gc, 1);
  XChar2b glyph{static_cast<unsigned char>(c >> 8), static_cast<unsigned char>(c & 0xff)};
  XDrawString16(dpy, pixmap, gc, -ch.lbearing, ch.ascent, &glyph, 1);
  XImage* image = XGetImage(dpy, pixmap, 0, 0, unsigned(row_bytes * 8), unsigned(height), 1, XYPixmap);
  if (!image) return bits;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (XGetPixel(image, x, y)) bits[std::size_t(height - 1 - y) * std::size_t(row_bytes) + std::size_t(x / 8)] |= GLubyte(0x80u >> (x % 8));
    }
  }
  XDestroyImage(image);
  return bits;
}

const XCharStruct* char_info(const XFontStruct& fs, unsigned c) {
  const unsigned byte1 = c >> 8, byte2 = c & 0xff;  // the font's bounds are unsigned too
  if (byte1 < fs.min_byte1 || byte1 > fs.max_byte1 || byte2 < fs.min_char_or_byte2 || byte2 > fs.max_char_or_byte2) return nullptr;
  if (!fs.per_char) return &fs.min_bounds;
  const unsigned columns = fs.max_char_or_byte2 - fs.min_char_or_byte2 + 1;
  const XCharStruct* ch = &fs.per_char[(byte1 - fs.min_byte1) * columns + (byte2 - fs.min_char_or_byte2)];
  const bool empty = ch->width == 0 && ch->lbearing == 0 && ch->rbearing == 0 && ch->ascent == 0 && ch->descent == 0;
  return empty ? nullptr : ch;
}

}  // namespace

void copy_context(Display* dpy, GLXContext source, GLXContext dest, unsigned long mask) {
  std::lock_guard lock(vendor_mutex());
  GlxContext* s = find_context(source);
  GlxContext* d = find_context(dest);
  if (!s || !d) {
    send_glx_error(dpy, GLXBadContext, 0, X_GLXCopyContext);
    return;
  }
  if (s->dpy != d->dpy || s->config->screen != d->config->screen) {
    send_x_error(dpy, BadMatch, 0, X_GLXCopyContext);
    return;
  }
  if (d->current) {  // the destination may not be current to any thread
    send_x_error(dpy, BadAccess, 0, X_GLXCopyContext);
    return;
  }
  copy_groups(*s->gl, *d->gl, mask);
}

// GLX 1.4 section 3.3.12: list list_base + i draws glyph first + i with glBitmap and advances
// the raster position by its width; a missing glyph makes an empty list.
void use_x_font(Font font, int first, int count, int list_base) {
  GlxContext* c = current_glx_context();
  using NewList = void (*)(GLuint, GLenum);
  using EndList = void (*)();
  using Bitmap = void (*)(GLsizei, GLsizei, GLfloat, GLfloat, GLfloat, GLfloat, const GLubyte*);
  auto new_list = gl_function<NewList>("glNewList");
  auto end_list = gl_function<EndList>("glEndList");
  auto bitmap = gl_function<Bitmap>("glBitmap");
  if (!c) return;
  if (!new_list || !end_list || !bitmap) {
    c->gl->set_error(GL_INVALID_OPERATION);  // the GL front end has no display lists or bitmaps yet
    return;
  }
  Display* dpy = c->dpy;
  XFontStruct* fs = XQueryFont(dpy, font);
  if (!fs) {
    send_x_error(dpy, BadFont, font, X_GLXUseXFont);
    return;
  }
  const int max_width = fs->max_bounds.rbearing - fs->min_bounds.lbearing;
  const int max_height = fs->max_bounds.ascent + fs->max_bounds.descent;
  Pixmap pixmap = XCreatePixmap(dpy, RootWindow(dpy, DefaultScreen(dpy)), unsigned(std::max(max_width, 1) + 8),
                                unsigned(std::max(max_height, 1)), 1);
  XGCValues values{};
  values.font = font;
  GC gc = XCreateGC(dpy, pixmap, GCFont, &values);
  // The glyphs are packed tightly: unpack state as glBitmap expects it, restored afterwards.
  GlContext& gl = *c->gl;
  const PixelStore saved = gl.unpack;
  gl.unpack = PixelStore{};
  gl.unpack.alignment = 1;
  for (int i = 0; i < count; ++i) {
    const unsigned ch = unsigned(first + i);
    new_list(GLuint(list_base + i), GL_COMPILE);
    if (const XCharStruct* info = char_info(*fs, ch)) {
      const int width = info->rbearing - info->lbearing, height = info->ascent + info->descent;
      std::vector<GLubyte> bits;
      if (width > 0 && height > 0) bits = glyph_bitmap(dpy, pixmap, gc, *info, ch, width, height);
      bitmap(std::max(width, 0), std::max(height, 0), GLfloat(-info->lbearing), GLfloat(info->descent - 1),
             GLfloat(info->width), 0.0f, bits.empty() ? nullptr : bits.data());
    }
    end_list();
  }
  gl.unpack = saved;
  XFreeGC(dpy, gc);
  XFreePixmap(dpy, pixmap);
  XFreeFontInfo(nullptr, fs, 1);
}

}  // namespace shadelab::gl::glx
