/* The state and the errors of the pixel commands, value by value (GL 1.1 sections 2.12,
 * 3.6, 3.7, 4.2, 4.3, 6.1): every GL_CURRENT_RASTER_* query, glPixelZoom, glPixelTransfer,
 * glPixelStore (both directions), the pixel map sizes and contents (glPixelMap{fv,uiv,usv}
 * read back through glGetPixelMap{fv,uiv,usv}), GL_MAX_PIXEL_MAP_TABLE, the accumulation
 * buffer's bits and clear value, GL_DRAW_BUFFER / GL_READ_BUFFER, each through
 * glGetFloatv and glGetIntegerv, and the glGetError code of every call, in contexts with and
 * without an accumulation buffer; what glPopAttrib restores of them (the current, pixel,
 * colour-buffer and accumulation groups, section 6.1.14). The values are written as bytes and
 * compared with Mesa's exactly.
 *
 * Left out, where Mesa departs from the specification: glGetPixelMapuiv of GL_PIXEL_MAP_I_TO_I
 * (Mesa scales the indices like colours, overflowing) and of GL_PIXEL_MAP_S_TO_S (Mesa returns
 * the bits of its floats); glReadPixels of GL_COLOR_INDEX (Mesa 22.3 reports an implementation
 * error on stderr). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "conf.h"

enum { kOutMax = 1 << 16 };

static unsigned char out[kOutMax];
static long out_n;

static void emit(const void* p, long n) {
  if (out_n + n > kOutMax) {
    fprintf(stderr, "output full\n");
    exit(5);
  }
  memcpy(out + out_n, p, (size_t)n);
  out_n += n;
}

static void emit_error(void) {
  unsigned short e = (unsigned short)glGetError();
  emit(&e, 2);
}

/* `n` values of `pname` as floats and as integers, then the error code. */
static void query(GLenum pname, int n) {
  GLfloat f[16];
  GLint i[16];
  for (int k = 0; k < 16; ++k) f[k] = -99.0f, i[k] = -99;
  glGetFloatv(pname, f);
  glGetIntegerv(pname, i);
  emit(f, 4L * n);
  emit(i, 4L * n);
  emit_error();
}

#define E(stmt) \
  do {          \
    stmt;       \
    emit_error(); \
  } while (0)

static void all_state(void) {
  static const struct { GLenum pname; int n; } q[] = {
    {GL_CURRENT_RASTER_POSITION, 4}, {GL_CURRENT_RASTER_COLOR, 4}, {GL_CURRENT_RASTER_INDEX, 1},
    {GL_CURRENT_RASTER_TEXTURE_COORDS, 4}, {GL_CURRENT_RASTER_POSITION_VALID, 1},
    {GL_CURRENT_RASTER_DISTANCE, 1}, {GL_ZOOM_X, 1}, {GL_ZOOM_Y, 1}, {GL_MAP_COLOR, 1},
    {GL_MAP_STENCIL, 1}, {GL_INDEX_SHIFT, 1}, {GL_INDEX_OFFSET, 1}, {GL_RED_SCALE, 1},
    {GL_RED_BIAS, 1}, {GL_GREEN_SCALE, 1}, {GL_GREEN_BIAS, 1}, {GL_BLUE_SCALE, 1},
    {GL_BLUE_BIAS, 1}, {GL_ALPHA_SCALE, 1}, {GL_ALPHA_BIAS, 1}, {GL_DEPTH_SCALE, 1},
    {GL_DEPTH_BIAS, 1}, {GL_PIXEL_MAP_I_TO_I_SIZE, 1}, {GL_PIXEL_MAP_S_TO_S_SIZE, 1},
    {GL_PIXEL_MAP_I_TO_R_SIZE, 1}, {GL_PIXEL_MAP_I_TO_G_SIZE, 1}, {GL_PIXEL_MAP_I_TO_B_SIZE, 1},
    {GL_PIXEL_MAP_I_TO_A_SIZE, 1}, {GL_PIXEL_MAP_R_TO_R_SIZE, 1}, {GL_PIXEL_MAP_G_TO_G_SIZE, 1},
    {GL_PIXEL_MAP_B_TO_B_SIZE, 1}, {GL_PIXEL_MAP_A_TO_A_SIZE, 1}, {GL_MAX_PIXEL_MAP_TABLE, 1},
    {GL_ACCUM_RED_BITS, 1}, {GL_ACCUM_GREEN_BITS, 1}, {GL_ACCUM_BLUE_BITS, 1},
    {GL_ACCUM_ALPHA_BITS, 1}, {GL_ACCUM_CLEAR_VALUE, 4}, {GL_DRAW_BUFFER, 1}, {GL_READ_BUFFER, 1},
    {GL_DOUBLEBUFFER, 1}, {GL_AUX_BUFFERS, 1}, {GL_UNPACK_SWAP_BYTES, 1},
    {GL_UNPACK_LSB_FIRST, 1}, {GL_UNPACK_ROW_LENGTH, 1}, {GL_UNPACK_SKIP_ROWS, 1},
    {GL_UNPACK_SKIP_PIXELS, 1}, {GL_UNPACK_ALIGNMENT, 1}, {GL_PACK_SWAP_BYTES, 1},
    {GL_PACK_LSB_FIRST, 1}, {GL_PACK_ROW_LENGTH, 1}, {GL_PACK_SKIP_ROWS, 1},
    {GL_PACK_SKIP_PIXELS, 1}, {GL_PACK_ALIGNMENT, 1},
  };
  for (unsigned k = 0; k < sizeof q / sizeof q[0]; ++k) query(q[k].pname, q[k].n);
}

static void raster(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 64, 0, 64, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor4f(0.2f, 0.4f, 0.6f, 0.8f);
  glTexCoord2f(0.25f, 2.0f);
  glRasterPos3f(10.5f, 20.25f, 0.5f);
  all_state();
  glTranslatef(3.0f, 4.0f, 0.0f);
  glRasterPos4f(10.0f, 10.0f, -0.25f, 2.0f);
  query(GL_CURRENT_RASTER_POSITION, 4);
  query(GL_CURRENT_RASTER_DISTANCE, 1);
  glRasterPos2f(-5.0f, 3.0f); /* outside: invalid, the rest kept */
  query(GL_CURRENT_RASTER_POSITION_VALID, 1);
  query(GL_CURRENT_RASTER_POSITION, 4);
  /* Two rows of one bit, each row padded to GL_UNPACK_ALIGNMENT's 4 bytes. */
  static const GLubyte bits[8] = {0xff, 0, 0, 0, 0xff, 0, 0, 0};
  glBitmap(1, 2, 0.0f, 0.0f, 5.0f, 5.0f, bits); /* no move while invalid */
  query(GL_CURRENT_RASTER_POSITION, 4);
  glLoadIdentity();
  glRasterPos2i(60, 60);
  glBitmap(1, 2, 0.0f, 0.0f, 10.5f, -70.25f, bits); /* moves out of the window, stays valid */
  query(GL_CURRENT_RASTER_POSITION, 4);
  query(GL_CURRENT_RASTER_POSITION_VALID, 1);
}

static void maps(void) {
  GLfloat m[300];
  GLuint um[300];
  GLushort sm[300];
  for (int i = 0; i < 300; ++i) m[i] = (float)i / 300.0f, um[i] = (GLuint)i * 1000000u, sm[i] = (GLushort)(i * 200);
  E(glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, m)); /* not a power of two */
  E(glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, m));
  E(glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 3, m)); /* any size */
  E(glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 3, m));
  E(glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 5, m));
  E(glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 0, m));
  E(glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 65536, m));
  E(glPixelMapfv(GL_PIXEL_MAP_I_TO_B, -1, m));
  E(glPixelMapfv(0x1234, 2, m));
  E(glPixelMapuiv(GL_PIXEL_MAP_I_TO_A, 8, um));
  E(glPixelMapusv(GL_PIXEL_MAP_G_TO_G, 16, sm));
  E(glPixelMapusv(GL_PIXEL_MAP_I_TO_I, 16, sm));
  E(glPixelMapuiv(GL_PIXEL_MAP_S_TO_S, 4, um));
  E(glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 7, m + 100));
  E(glPixelMapuiv(GL_PIXEL_MAP_A_TO_A, 2, um + 4));
  static const GLenum names[] = {
    GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R, GL_PIXEL_MAP_I_TO_G, GL_PIXEL_MAP_I_TO_B,
    GL_PIXEL_MAP_I_TO_A, GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_G_TO_G, GL_PIXEL_MAP_B_TO_B, GL_PIXEL_MAP_A_TO_A,
  };
  for (int k = 0; k < 10; ++k) {
    GLfloat f[300];
    GLuint u[300];
    GLushort s[300];
    for (int i = 0; i < 300; ++i) f[i] = -1.0f, u[i] = 7, s[i] = 7;
    glGetPixelMapfv(names[k], f);
    emit_error();
    if (names[k] != GL_PIXEL_MAP_I_TO_I && names[k] != GL_PIXEL_MAP_S_TO_S) glGetPixelMapuiv(names[k], u);
    emit_error();
    glGetPixelMapusv(names[k], s);
    emit_error();
    emit(f, 4 * 20);
    emit(u, 4 * 20);
    emit(s, 2 * 20);
  }
  E(glGetPixelMapfv(0x1234, m));
  E(glGetPixelMapuiv(0x1234, um));
  E(glGetPixelMapusv(0x1234, sm));
}

static void transfer_zoom_store(void) {
  E(glPixelTransferf(GL_RED_SCALE, 2.0f));
  E(glPixelTransferi(GL_MAP_COLOR, 5));
  E(glPixelTransferf(GL_INDEX_SHIFT, 2.7f));
  E(glPixelTransferf(GL_INDEX_OFFSET, -3.6f));
  E(glPixelTransferf(0x1234, 1.0f));
  E(glPixelTransferf(GL_DEPTH_BIAS, 0.25f));
  E(glPixelTransferi(GL_ALPHA_BIAS, -1));
  E(glPixelTransferi(GL_MAP_STENCIL, 1));
  E(glPixelZoom(-2.5f, 0.5f));
  E(glPixelStorei(GL_UNPACK_ALIGNMENT, 3));
  E(glPixelStorei(GL_UNPACK_ALIGNMENT, 8));
  E(glPixelStorei(GL_PACK_ROW_LENGTH, -1));
  E(glPixelStoref(GL_PACK_SKIP_ROWS, 2.6f));
  E(glPixelStorei(0x1234, 1));
  E(glPixelStorei(GL_UNPACK_SWAP_BYTES, 7));
  E(glPixelStoref(GL_PACK_LSB_FIRST, 0.2f));
  E(glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3));
  E(glPixelStorei(GL_PACK_ALIGNMENT, 2));
}

static void buffers(void) {
  E(glAccum(GL_ACCUM, 1.0f));
  E(glAccum(0x1234, 1.0f));
  E(glClearAccum(2.0f, -3.0f, 0.5f, 0.25f));
  E(glClear(GL_ACCUM_BUFFER_BIT));
  E(glAccum(GL_RETURN, 1.0f));
  E(glAccum(GL_MULT, -1.0f));
  E(glAccum(GL_LOAD, 0.5f));
  E(glAccum(GL_ADD, 0.5f));
  E(glDrawBuffer(GL_BACK));
  E(glDrawBuffer(GL_FRONT));
  E(glDrawBuffer(GL_FRONT_LEFT));
  E(glDrawBuffer(GL_FRONT_AND_BACK));
  E(glDrawBuffer(GL_LEFT));
  E(glDrawBuffer(GL_RIGHT));
  E(glDrawBuffer(GL_AUX0));
  E(glDrawBuffer(GL_NONE));
  query(GL_DRAW_BUFFER, 1);
  E(glDrawBuffer(0x1234));
  E(glDrawBuffer(GL_FRONT));
  E(glReadBuffer(GL_BACK));
  E(glReadBuffer(GL_NONE));
  E(glReadBuffer(GL_FRONT_AND_BACK));
  E(glReadBuffer(GL_LEFT));
  E(glReadBuffer(GL_AUX1));
  query(GL_READ_BUFFER, 1);
  E(glReadBuffer(GL_FRONT_LEFT));
  GLfloat px[16];
  E(glCopyPixels(0, 0, 2, 2, GL_ACCUM));
  E(glReadPixels(0, 0, 1, 1, GL_RGBA, GL_BITMAP, px));
  E(glReadPixels(0, 0, -1, 1, GL_RGBA, GL_FLOAT, px));
  E(glReadPixels(0, 0, 1, 1, 0x1234, GL_FLOAT, px));
  E(glBitmap(-1, 1, 0.0f, 0.0f, 0.0f, 0.0f, (const GLubyte*)px));
  E(glBegin(GL_POINTS); glBitmap(1, 1, 0.0f, 0.0f, 0.0f, 0.0f, (const GLubyte*)px); glEnd());
  E(glBegin(GL_POINTS); glRasterPos2i(1, 1); glEnd());
  E(glBegin(GL_POINTS); glAccum(GL_LOAD, 1.0f); glEnd());
  E(glBegin(GL_POINTS); glPixelZoom(1.0f, 1.0f); glEnd());
}

/* Sets every pixel-related attribute to a value of its own (`k` picks the set). */
static void change_all(int k) {
  const float f = (float)k;
  glPixelTransferf(GL_RED_SCALE, 0.5f + f);
  glPixelTransferf(GL_GREEN_BIAS, 0.25f * f);
  glPixelTransferf(GL_DEPTH_SCALE, 2.0f - f);
  glPixelTransferi(GL_INDEX_SHIFT, 1 + k);
  glPixelTransferi(GL_INDEX_OFFSET, -2 * k);
  glPixelTransferi(GL_MAP_COLOR, k % 2);
  glPixelTransferi(GL_MAP_STENCIL, (k + 1) % 2);
  glPixelZoom(1.5f + f, -0.5f * f);
  const GLfloat map[2] = {0.25f * f, 0.75f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, k + 1, map);
  glDrawBuffer(k % 2 ? GL_NONE : GL_BACK);
  glReadBuffer(k % 2 ? GL_BACK : GL_FRONT);
  glClearAccum(0.1f * f, -0.2f, 0.3f, f);
  glColor4f(0.1f * f, 0.2f, 0.3f, 0.4f);
  glRasterPos3f(5.0f + f, 7.0f, 0.25f * f);
}

/* glPushAttrib of each group that holds pixel state, and of all, then glPopAttrib: what comes
 * back and what stays (the pixel maps belong to no group). */
static void attrib_groups(void) {
  static const GLbitfield masks[] = {GL_ALL_ATTRIB_BITS, GL_PIXEL_MODE_BIT, GL_CURRENT_BIT, GL_COLOR_BUFFER_BIT,
                                     GL_ACCUM_BUFFER_BIT, GL_ENABLE_BIT};
  for (unsigned i = 0; i < sizeof masks / sizeof masks[0]; ++i) {
    change_all(0);
    E(glPushAttrib(masks[i]));
    change_all(1);
    E(glPopAttrib());
    all_state();
  }
}

/* One context's worth: a 64 x 64 RGBA buffer with `accum_bits` accumulation bits. */
static int run(int accum_bits) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, accum_bits, NULL);
  void* buffer = calloc(64 * 64, 4);
  if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 64, 64)) return 0;
  all_state();
  raster();
  maps();
  transfer_zoom_store();
  buffers();
  all_state();
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 64, 0, 64, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  attrib_groups();
  OSMesaDestroyContext(ctx);
  free(buffer);
  return 1;
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s OUTPUT.png\n", argv[0]);
    return 1;
  }
  if (!run(0) || !run(16)) {
    fprintf(stderr, "context creation failed\n");
    return 1;
  }
  if (!conf_write_bytes_png(argv[1], out, out_n, 256)) return 2;
  fprintf(stderr, "%ld bytes of state\n", out_n);
  return 0;
}
