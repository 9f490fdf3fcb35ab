/* shadelab's own <GL/osmesa.h>: off-screen contexts that render into a buffer owned by the
 * caller, with the signatures and constants of Mesa's OSMesa interface, so that an OSMesa
 * program links with -lshadelab-gl instead of -lOSMesa unchanged. Declarations only. */
#ifndef OSMESA_H
#define OSMESA_H

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

#define OSMESA_MAJOR_VERSION 11
#define OSMESA_MINOR_VERSION 2
#define OSMESA_PATCH_VERSION 0

/* Buffer formats (the `format` of OSMesaCreateContext) */
#define OSMESA_COLOR_INDEX GL_COLOR_INDEX
#define OSMESA_RGBA GL_RGBA
#define OSMESA_BGRA 0x1
#define OSMESA_ARGB 0x2
#define OSMESA_RGB GL_RGB
#define OSMESA_BGR 0x4
#define OSMESA_RGB_565 0x5

/* OSMesaPixelStore parameters */
#define OSMESA_ROW_LENGTH 0x10
#define OSMESA_Y_UP 0x11

/* OSMesaGetIntegerv parameters */
#define OSMESA_WIDTH 0x20
#define OSMESA_HEIGHT 0x21
#define OSMESA_FORMAT 0x22
#define OSMESA_TYPE 0x23
#define OSMESA_MAX_WIDTH 0x24
#define OSMESA_MAX_HEIGHT 0x25

/* OSMesaCreateContextAttribs attributes */
#define OSMESA_DEPTH_BITS 0x30
#define OSMESA_STENCIL_BITS 0x31
#define OSMESA_ACCUM_BITS 0x32
#define OSMESA_PROFILE 0x33
#define OSMESA_CORE_PROFILE 0x34
#define OSMESA_COMPAT_PROFILE 0x35
#define OSMESA_CONTEXT_MAJOR_VERSION 0x36
#define OSMESA_CONTEXT_MINOR_VERSION 0x37
/* shadelab's own (Mesa's OSMesa has none): samples per pixel of a multisample buffer; 0 (the
 * default) for none, 1 to 4 for 4 samples (the one count shadelab has), more: no context. */
#define OSMESA_SAMPLES_SHADELAB 0x5301

typedef struct osmesa_context* OSMesaContext;
typedef void (*OSMESAproc)();

/* A context for buffers of `format` with a 24-bit depth and an 8-bit stencil buffer. */
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContext(GLenum format, OSMesaContext sharelist);

/* A context with the given depth, stencil and accumulation buffer sizes (accumulation is not
 * supported and ignored). Textures are shared with `sharelist` when it is not NULL. */
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextExt(GLenum format, GLint depthBits,
                                                      GLint stencilBits, GLint accumBits,
                                                      OSMesaContext sharelist);

/* attribList: pairs (OSMESA_FORMAT, OSMESA_DEPTH_BITS, ...) ending with 0. */
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextAttribs(const int* attribList,
                                                          OSMesaContext sharelist);

GLAPI void GLAPIENTRY OSMesaDestroyContext(OSMesaContext ctx);

/* Binds `ctx` to the caller's buffer (type GL_UNSIGNED_BYTE) and makes it current in this
 * thread. OSMesaMakeCurrent(NULL, NULL, 0, 0, 0) releases the current context. */
GLAPI GLboolean GLAPIENTRY OSMesaMakeCurrent(OSMesaContext ctx, void* buffer, GLenum type,
                                             GLsizei width, GLsizei height);

GLAPI OSMesaContext GLAPIENTRY OSMesaGetCurrentContext(void);

GLAPI void GLAPIENTRY OSMesaPixelStore(GLint pname, GLint value);

GLAPI void GLAPIENTRY OSMesaGetIntegerv(GLint pname, GLint* value);

GLAPI GLboolean GLAPIENTRY OSMesaGetDepthBuffer(OSMesaContext c, GLint* width, GLint* height,
                                                GLint* bytesPerValue, void** buffer);

GLAPI GLboolean GLAPIENTRY OSMesaGetColorBuffer(OSMesaContext c, GLint* width, GLint* height,
                                                GLint* format, void** buffer);

GLAPI OSMESAproc GLAPIENTRY OSMesaGetProcAddress(const char* funcName);

GLAPI void GLAPIENTRY OSMesaColorClamp(GLboolean enable);

#ifdef __cplusplus
}
#endif

#endif /* OSMESA_H */
