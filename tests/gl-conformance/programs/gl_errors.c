/* GL errors compared with Mesa's, call by call: a table of wrong calls (an enum no command
 * accepts, values out of range, stacks overflowed and underflowed, commands out of order) for
 * every GL 1.1 entry point libshadelab-gl implements, and every one of them called between
 * glBegin and glEnd (GL 1.1 section 2.6.3: GL_INVALID_OPERATION but for the commands the
 * section allows there). After each call the glGetError code is printed to NAME.txt (compared
 * line by line by tools/gl_values) and drawn as a cell. Commands still pending in
 * gl/api/pending.txt join the table when they land. */
#include <stdio.h>
#include <string.h>

#include "conf.h"

enum { kCols = 32, kRows = 24, kCells = kCols * kRows };
static unsigned cells[kCells];
static int n_cells = 0;
static FILE* out;

/* Prints the call's text and the error it left (and a second glGetError: always 0). */
static void report(const char* call) {
  GLenum e = glGetError();
  GLenum again = glGetError();
  fprintf(out, "%s: err %x %x\n", call, e, again);
  cells[n_cells % kCells] ^= e * 2654435761u + (unsigned)n_cells;
  ++n_cells;
}

/* A wrong call, then its error. */
#define E(call) ((void)(call), report(#call))
/* A call between glBegin and glEnd, then the error (glGetError itself is not allowed there). */
#define B(call) (glBegin(GL_TRIANGLES), (void)(call), glEnd(), report("in begin/end: " #call))

static const GLfloat kFloats[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
static const GLdouble kDoubles[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
static const GLint kInts[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
static const GLshort kShorts[4] = {1, 2, 3, 4};
static const GLbyte kBytes[4] = {1, 2, 3, 4};
static const GLubyte kUbytes[64] = {1, 2, 3, 4};
static const GLushort kUshorts[4] = {1, 2, 3, 4};
static const GLuint kUints[4] = {1, 2, 3, 4};
static const GLboolean kTrue = GL_TRUE;
static GLfloat fbuf[16];
static GLint ibuf[16];
static GLdouble dbuf[16];
static GLboolean bbuf[16];
static GLubyte pixels[64 * 4];
static void* pointer;
static GLuint names[4];

#define BAD 0x1234 /* no GL 1.1 command accepts this enum */

/* Wrong arguments, command by command (alphabetical). */
static void wrong_arguments(void) {
  E(glAlphaFunc(BAD, 0.5f));
  E(glAlphaFunc(GL_LEQUAL, 2.0f));
  E(glArrayElement(-1));
  E(glBindTexture(BAD, 1));
  E(glBindTexture(GL_TEXTURE_2D, 1));
  E(glBlendFunc(BAD, GL_ONE));
  E(glBlendFunc(GL_ONE, BAD));
  E(glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_SRC_ALPHA_SATURATE));
  E(glBlendFunc(GL_SRC_COLOR, GL_DST_COLOR));
  E(glCallList(0));
  E(glCallLists(-1, GL_UNSIGNED_BYTE, kUbytes));
  E(glCallLists(1, BAD, kUbytes));
  E(glCallLists(1, GL_FLOAT, kFloats));
  E(glClear(0x1));
  E(glClear(GL_ACCUM_BUFFER_BIT));
  E(glColorMaterial(BAD, GL_AMBIENT));
  E(glColorMaterial(GL_FRONT, BAD));
  E(glColorMaterial(GL_FRONT, GL_SHININESS));
  E(glColorPointer(2, GL_FLOAT, 0, kFloats));
  E(glColorPointer(4, BAD, 0, kFloats));
  E(glColorPointer(4, GL_FLOAT, -1, kFloats));
  E(glCullFace(BAD));
  E(glDeleteLists(1, -1));
  E(glDeleteTextures(-1, names));
  E(glDepthFunc(BAD));
  E(glDisable(BAD));
  E(glDisableClientState(BAD));
  E(glDisableClientState(GL_LIGHTING));
  E(glDrawArrays(BAD, 0, 3));
  E(glDrawArrays(GL_TRIANGLES, 0, -1));
  E(glDrawElements(BAD, 3, GL_UNSIGNED_BYTE, kUbytes));
  E(glDrawElements(GL_TRIANGLES, -1, GL_UNSIGNED_BYTE, kUbytes));
  E(glDrawElements(GL_TRIANGLES, 3, GL_INT, kInts));
  E(glDrawElements(GL_TRIANGLES, 3, BAD, kUbytes));
  E(glEdgeFlagPointer(-1, kUbytes));
  E(glEnable(BAD));
  E(glEnable(GL_VERTEX_ARRAY));
  E(glEnableClientState(BAD));
  E(glEnableClientState(GL_LIGHTING));
  E(glEnd());
  E(glEndList());
  E(glFogf(BAD, 1.0f));
  E(glFogf(GL_FOG_DENSITY, -1.0f));
  E(glFogf(GL_FOG_MODE, (GLfloat)BAD));
  E(glFogi(GL_FOG_MODE, GL_LINEAR));
  E(glFogfv(BAD, kFloats));
  E(glFogiv(GL_FOG_MODE, kInts));
  E(glFogiv(GL_FOG_COLOR, kInts));
  E(glFrustum(-1, 1, -1, 1, 0, 10));
  E(glFrustum(-1, 1, -1, 1, 2, 1));
  E(glFrustum(1, 1, -1, 1, 1, 10));
  E(glFrustum(-1, 1, -1, 1, 1, 1));
  E(glGenLists(-1));
  E(glGenLists(0));
  E(glGenTextures(-1, names));
  E(glGetBooleanv(BAD, bbuf));
  E(glGetDoublev(BAD, dbuf));
  E(glGetFloatv(BAD, fbuf));
  E(glGetIntegerv(BAD, ibuf));
  E(glGetLightfv(BAD, GL_AMBIENT, fbuf));
  E(glGetLightfv(GL_LIGHT0, BAD, fbuf));
  E(glGetLightiv(GL_LIGHT0, GL_SHININESS, ibuf));
  E(glGetMaterialfv(BAD, GL_AMBIENT, fbuf));
  E(glGetMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, fbuf));
  E(glGetMaterialfv(GL_FRONT, BAD, fbuf));
  E(glGetMaterialiv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, ibuf));
  E(glGetPointerv(BAD, &pointer));
  E(glGetString(BAD));
  E(glGetTexEnvfv(BAD, GL_TEXTURE_ENV_MODE, fbuf));
  E(glGetTexEnviv(GL_TEXTURE_ENV, BAD, ibuf));
  E(glGetTexParameterfv(BAD, GL_TEXTURE_MIN_FILTER, fbuf));
  E(glGetTexParameteriv(GL_TEXTURE_2D, BAD, ibuf));
  E(glGetPolygonStipple(pixels));
  E(glHint(BAD, GL_NICEST));
  E(glHint(GL_FOG_HINT, BAD));
  E(glIndexPointer(BAD, 0, kFloats));
  E(glIndexPointer(GL_BYTE, 0, kBytes));
  E(glIndexPointer(GL_FLOAT, -1, kFloats));
  E(glInterleavedArrays(BAD, 0, kFloats));
  E(glInterleavedArrays(GL_V3F, -1, kFloats));
  E(glIsEnabled(BAD));
  E(glIsEnabled(GL_FRONT));
  E(glLogicOp(BAD));
  E(glLogicOp(GL_CLEAR - 1));
  E(glLogicOp(GL_SET + 1));
  E(glLightModelf(BAD, 1.0f));
  E(glLightModelf(GL_LIGHT_MODEL_AMBIENT, 1.0f));
  E(glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, BAD));
  E(glLightModelfv(BAD, kFloats));
  E(glLightModeliv(GL_LIGHT_MODEL_TWO_SIDE, kInts));
  E(glLightf(BAD, GL_SPOT_EXPONENT, 1.0f));
  E(glLightf(GL_LIGHT0, GL_AMBIENT, 1.0f));
  E(glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 200.0f));
  E(glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, -1.0f));
  E(glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 100.0f));
  E(glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0f));
  E(glLighti(GL_LIGHT0, GL_CONSTANT_ATTENUATION, -1));
  E(glLightfv(GL_LIGHT0, BAD, kFloats));
  E(glLightiv(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, kInts));
  E(glMaterialf(BAD, GL_SHININESS, 1.0f));
  E(glMaterialf(GL_FRONT, GL_SHININESS, 200.0f));
  E(glMaterialf(GL_FRONT, GL_AMBIENT, 1.0f));
  E(glMateriali(GL_FRONT_AND_BACK, GL_SHININESS, -1));
  E(glMaterialfv(GL_FRONT, BAD, kFloats));
  E(glMaterialiv(GL_BACK, GL_COLOR_INDEXES, kInts));
  E(glMatrixMode(BAD));
  E(glNewList(0, GL_COMPILE));
  E(glNewList(1, BAD));
  E(glNormalPointer(BAD, 0, kFloats));
  E(glNormalPointer(GL_UNSIGNED_BYTE, 0, kUbytes));
  E(glNormalPointer(GL_FLOAT, -1, kFloats));
  E(glOrtho(1, 1, 0, 1, 0, 1));
  E(glOrtho(0, 1, 0, 1, 1, 1));
  E(glPixelStoref(BAD, 1.0f));
  E(glPolygonStipple(kUbytes));
  E(glPixelStorei(GL_PACK_ALIGNMENT, 3));
  E(glPixelStorei(GL_UNPACK_ALIGNMENT, 0));
  E(glPixelStorei(GL_UNPACK_ROW_LENGTH, -1));
  E(glPixelStoref(GL_PACK_SKIP_ROWS, -1.0f));
  E(glPopAttrib());
  E(glPopClientAttrib());
  E(glPopMatrix());
  E(glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
  E(glReadPixels(0, 0, 1, 1, BAD, GL_UNSIGNED_BYTE, pixels));
  E(glReadPixels(0, 0, 1, 1, GL_RGBA, BAD, pixels));
  E(glReadPixels(0, 0, 1, 1, GL_RGBA, GL_BITMAP, pixels));
  E(glScissor(0, 0, -1, 4));
  E(glScissor(-5, -5, 4, -1));
  E(glScissor(-5, -5, 0, 0));
  E(glShadeModel(BAD));
  E(glStencilFunc(BAD, 0, 0));
  E(glStencilOp(BAD, GL_KEEP, GL_KEEP));
  E(glStencilOp(GL_KEEP, GL_KEEP, BAD));
  E(glTexCoordPointer(5, GL_FLOAT, 0, kFloats));
  E(glTexCoordPointer(2, GL_BYTE, 0, kBytes));
  E(glTexCoordPointer(2, GL_FLOAT, -1, kFloats));
  E(glTexEnvf(BAD, GL_TEXTURE_ENV_MODE, GL_MODULATE));
  E(glTexEnvf(GL_TEXTURE_ENV, BAD, GL_MODULATE));
  E(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, BAD));
  E(glTexEnvfv(GL_TEXTURE_ENV, BAD, kFloats));
  E(glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, kInts));
  E(glTexImage2D(BAD, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
  E(glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
  E(glTexImage2D(GL_TEXTURE_2D, 0, 7, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, BAD, GL_UNSIGNED_BYTE, pixels));
  E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, BAD, pixels));
  E(glTexParameteri(BAD, GL_TEXTURE_MIN_FILTER, GL_LINEAR));
  E(glTexParameteri(GL_TEXTURE_2D, BAD, GL_LINEAR));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, BAD));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR));
  E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, BAD));
  E(glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, 1.5f));
  E(glTexParameterfv(GL_TEXTURE_2D, BAD, kFloats));
  E(glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, kInts));
  E(glVertexPointer(1, GL_FLOAT, 0, kFloats));
  E(glVertexPointer(3, GL_BYTE, 0, kBytes));
  E(glVertexPointer(3, BAD, 0, kFloats));
  E(glVertexPointer(3, GL_FLOAT, -1, kFloats));
  E(glViewport(0, 0, -1, 1));
  E(glViewport(0, 0, 1, -1));
}

/* Stacks past their limits and commands out of order. */
static void stacks_and_order(void) {
  char what[64];
  for (int i = 0; i < 33; ++i) glPushMatrix();
  report("33 glPushMatrix (modelview)");
  for (int i = 0; i < 33; ++i) glPopMatrix();
  report("33 glPopMatrix (modelview)");
  glMatrixMode(GL_TEXTURE);
  for (int i = 0; i < 11; ++i) glPushMatrix();
  report("11 glPushMatrix (texture)");
  for (int i = 0; i < 11; ++i) glPopMatrix();
  report("11 glPopMatrix (texture)");
  glMatrixMode(GL_MODELVIEW);
  for (int i = 0; i < 17; ++i) glPushAttrib(GL_ALL_ATTRIB_BITS);
  report("17 glPushAttrib");
  for (int i = 0; i < 17; ++i) glPopAttrib();
  report("17 glPopAttrib");
  for (int i = 0; i < 17; ++i) glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  report("17 glPushClientAttrib");
  for (int i = 0; i < 17; ++i) glPopClientAttrib();
  report("17 glPopClientAttrib");
  glBegin(GL_TRIANGLES);
  glBegin(GL_TRIANGLES);
  glEnd();
  report("glBegin in glBegin");
  glGenTextures(1, names);
  E(glNewList(5, GL_COMPILE));
  E(glNewList(6, GL_COMPILE));
  E(glEndList());
  E(glEndList());
  for (int i = 0; i < 3; ++i) {
    snprintf(what, sizeof what, "glGetError %d", i);
    report(what);
  }
}

/* Every implemented command between glBegin and glEnd (section 2.6.3). */
static void inside_begin_end(void) {
  B(glAlphaFunc(GL_LESS, 0.5f));
  B(glArrayElement(0));
  B(glFogf(GL_FOG_START, 1.0f));
  B(glFogi(GL_FOG_MODE, GL_EXP));
  B(glFogfv(GL_FOG_COLOR, kFloats));
  B(glFogiv(GL_FOG_COLOR, kInts));
  B(glGetPolygonStipple(pixels));
  B(glLogicOp(GL_XOR));
  B(glPolygonStipple(kUbytes));
  B(glScissor(0, 0, 4, 4));
  B(glBindTexture(GL_TEXTURE_2D, 0));
  B(glBlendFunc(GL_ONE, GL_ZERO));
  B(glCallList(5));
  B(glCallLists(1, GL_UNSIGNED_BYTE, kUbytes));
  B(glClear(GL_COLOR_BUFFER_BIT));
  B(glClearColor(0, 0, 0, 0));
  B(glClearDepth(1));
  B(glClearIndex(0));
  B(glClearStencil(0));
  B(glColor3b(1, 2, 3)), B(glColor3bv(kBytes)), B(glColor3d(1, 0, 0)), B(glColor3dv(kDoubles));
  B(glColor3f(1, 0, 0)), B(glColor3fv(kFloats)), B(glColor3i(1, 0, 0)), B(glColor3iv(kInts));
  B(glColor3s(1, 0, 0)), B(glColor3sv(kShorts)), B(glColor3ub(1, 0, 0)), B(glColor3ubv(kUbytes));
  B(glColor3ui(1, 0, 0)), B(glColor3uiv(kUints)), B(glColor3us(1, 0, 0)), B(glColor3usv(kUshorts));
  B(glColor4b(1, 2, 3, 4)), B(glColor4bv(kBytes)), B(glColor4d(1, 0, 0, 1)), B(glColor4dv(kDoubles));
  B(glColor4f(1, 0, 0, 1)), B(glColor4fv(kFloats)), B(glColor4i(1, 0, 0, 1)), B(glColor4iv(kInts));
  B(glColor4s(1, 0, 0, 1)), B(glColor4sv(kShorts)), B(glColor4ub(1, 0, 0, 1)), B(glColor4ubv(kUbytes));
  B(glColor4ui(1, 0, 0, 1)), B(glColor4uiv(kUints)), B(glColor4us(1, 0, 0, 1)), B(glColor4usv(kUshorts));
  B(glColorMask(1, 1, 1, 1));
  B(glColorMaterial(GL_FRONT, GL_DIFFUSE));
  B(glColorPointer(4, GL_FLOAT, 0, kFloats));
  B(glCullFace(GL_BACK));
  B(glDeleteLists(100, 1));
  B(glDeleteTextures(1, &names[3]));
  B(glDepthFunc(GL_LESS));
  B(glDepthMask(1));
  B(glDepthRange(0, 1));
  B(glDisable(GL_DITHER));
  B(glDrawArrays(GL_TRIANGLES, 0, 0));
  B(glDrawElements(GL_TRIANGLES, 0, GL_UNSIGNED_BYTE, kUbytes));
  B(glEdgeFlag(1)), B(glEdgeFlagv(&kTrue));
  B(glEdgeFlagPointer(0, kUbytes));
  B(glEnable(GL_DITHER));
  B(glEndList());
  B(glFinish());
  B(glFlush());
  B(glFrontFace(GL_CCW));
  B(glFrustum(-1, 1, -1, 1, 1, 10));
  B(glGenLists(1));
  B(glGenTextures(1, &names[2]));
  B(glGetBooleanv(GL_DEPTH_TEST, bbuf));
  B(glGetDoublev(GL_DEPTH_TEST, dbuf));
  B(glGetFloatv(GL_DEPTH_TEST, fbuf));
  B(glGetIntegerv(GL_DEPTH_TEST, ibuf));
  B(glGetLightfv(GL_LIGHT0, GL_AMBIENT, fbuf));
  B(glGetLightiv(GL_LIGHT0, GL_AMBIENT, ibuf));
  B(glGetMaterialfv(GL_FRONT, GL_AMBIENT, fbuf));
  B(glGetMaterialiv(GL_FRONT, GL_AMBIENT, ibuf));
  B(glGetPointerv(GL_VERTEX_ARRAY_POINTER, &pointer));
  B(glGetString(GL_VENDOR));
  B(glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, fbuf));
  B(glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, ibuf));
  B(glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, fbuf));
  B(glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, ibuf));
  B(glHint(GL_FOG_HINT, GL_NICEST));
  B(glIndexMask(1));
  B(glIndexPointer(GL_FLOAT, 0, kFloats));
  B(glIndexd(1)), B(glIndexdv(kDoubles)), B(glIndexf(1)), B(glIndexfv(kFloats));
  B(glIndexi(1)), B(glIndexiv(kInts)), B(glIndexs(1)), B(glIndexsv(kShorts));
  B(glIndexub(1)), B(glIndexubv(kUbytes));
  B(glInterleavedArrays(GL_V3F, 0, kFloats));
  B(glIsEnabled(GL_DEPTH_TEST));
  B(glIsList(5));
  B(glIsTexture(names[0]));
  B(glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 0)), B(glLightModelfv(GL_LIGHT_MODEL_AMBIENT, kFloats));
  B(glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0)), B(glLightModeliv(GL_LIGHT_MODEL_AMBIENT, kInts));
  B(glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 1)), B(glLightfv(GL_LIGHT0, GL_AMBIENT, kFloats));
  B(glLighti(GL_LIGHT0, GL_SPOT_EXPONENT, 1)), B(glLightiv(GL_LIGHT0, GL_AMBIENT, kInts));
  B(glListBase(0));
  B(glLoadIdentity());
  B(glLoadMatrixd(kDoubles)), B(glLoadMatrixf(kFloats));
  B(glMaterialf(GL_FRONT, GL_SHININESS, 1)), B(glMaterialfv(GL_FRONT, GL_AMBIENT, kFloats));
  B(glMateriali(GL_FRONT, GL_SHININESS, 1)), B(glMaterialiv(GL_FRONT, GL_AMBIENT, kInts));
  B(glMatrixMode(GL_MODELVIEW));
  B(glMultMatrixd(kDoubles)), B(glMultMatrixf(kFloats));
  B(glNewList(7, GL_COMPILE));
  B(glNormal3b(1, 2, 3)), B(glNormal3bv(kBytes)), B(glNormal3d(0, 0, 1)), B(glNormal3dv(kDoubles));
  B(glNormal3f(0, 0, 1)), B(glNormal3fv(kFloats)), B(glNormal3i(0, 0, 1)), B(glNormal3iv(kInts));
  B(glNormal3s(0, 0, 1)), B(glNormal3sv(kShorts));
  B(glNormalPointer(GL_FLOAT, 0, kFloats));
  B(glOrtho(0, 1, 0, 1, 0, 1));
  B(glPixelStoref(GL_PACK_ALIGNMENT, 4)), B(glPixelStorei(GL_PACK_ALIGNMENT, 4));
  B(glPolygonOffset(0, 0));
  B(glPopAttrib());
  B(glPushAttrib(GL_ALL_ATTRIB_BITS));
  B(glPopMatrix());
  B(glPushMatrix());
  B(glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
  B(glRectd(0, 0, 1, 1)), B(glRectdv(kDoubles, kDoubles + 2)), B(glRectf(0, 0, 1, 1));
  B(glRectfv(kFloats, kFloats + 2)), B(glRecti(0, 0, 1, 1)), B(glRectiv(kInts, kInts + 2));
  B(glRects(0, 0, 1, 1)), B(glRectsv(kShorts, kShorts + 2));
  B(glRotated(1, 0, 0, 1)), B(glRotatef(1, 0, 0, 1));
  B(glScaled(1, 1, 1)), B(glScalef(1, 1, 1));
  B(glShadeModel(GL_SMOOTH));
  B(glStencilFunc(GL_ALWAYS, 0, 0xff));
  B(glStencilMask(0xff));
  B(glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP));
  B(glTexCoord1d(0)), B(glTexCoord1dv(kDoubles)), B(glTexCoord1f(0)), B(glTexCoord1fv(kFloats));
  B(glTexCoord1i(0)), B(glTexCoord1iv(kInts)), B(glTexCoord1s(0)), B(glTexCoord1sv(kShorts));
  B(glTexCoord2d(0, 0)), B(glTexCoord2dv(kDoubles)), B(glTexCoord2f(0, 0)), B(glTexCoord2fv(kFloats));
  B(glTexCoord2i(0, 0)), B(glTexCoord2iv(kInts)), B(glTexCoord2s(0, 0)), B(glTexCoord2sv(kShorts));
  B(glTexCoord3d(0, 0, 0)), B(glTexCoord3dv(kDoubles)), B(glTexCoord3f(0, 0, 0));
  B(glTexCoord3fv(kFloats)), B(glTexCoord3i(0, 0, 0)), B(glTexCoord3iv(kInts));
  B(glTexCoord3s(0, 0, 0)), B(glTexCoord3sv(kShorts));
  B(glTexCoord4d(0, 0, 0, 1)), B(glTexCoord4dv(kDoubles)), B(glTexCoord4f(0, 0, 0, 1));
  B(glTexCoord4fv(kFloats)), B(glTexCoord4i(0, 0, 0, 1)), B(glTexCoord4iv(kInts));
  B(glTexCoord4s(0, 0, 0, 1)), B(glTexCoord4sv(kShorts));
  B(glTexCoordPointer(2, GL_FLOAT, 0, kFloats));
  B(glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE));
  B(glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, kFloats));
  B(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE));
  B(glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, kInts));
  B(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
  B(glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR));
  B(glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, kFloats));
  B(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR));
  B(glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, kInts));
  B(glTranslated(0, 0, 0)), B(glTranslatef(0, 0, 0));
  B(glVertex2d(0, 0)), B(glVertex2dv(kDoubles)), B(glVertex2f(0, 0)), B(glVertex2fv(kFloats));
  B(glVertex2i(0, 0)), B(glVertex2iv(kInts)), B(glVertex2s(0, 0)), B(glVertex2sv(kShorts));
  B(glVertex3d(0, 0, 0)), B(glVertex3dv(kDoubles)), B(glVertex3f(0, 0, 0)), B(glVertex3fv(kFloats));
  B(glVertex3i(0, 0, 0)), B(glVertex3iv(kInts)), B(glVertex3s(0, 0, 0)), B(glVertex3sv(kShorts));
  B(glVertex4d(0, 0, 0, 1)), B(glVertex4dv(kDoubles)), B(glVertex4f(0, 0, 0, 1));
  B(glVertex4fv(kFloats)), B(glVertex4i(0, 0, 0, 1)), B(glVertex4iv(kInts));
  B(glVertex4s(0, 0, 0, 1)), B(glVertex4sv(kShorts));
  B(glVertexPointer(3, GL_FLOAT, 0, kFloats));
  B(glViewport(0, 0, 64, 64));
  B(glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS));
  B(glPopClientAttrib());
  B(glEnableClientState(GL_VERTEX_ARRAY));
  B(glDisableClientState(GL_VERTEX_ARRAY));
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 128, 96)) return 1;
  out = conf_open_values(&c);
  if (!out) return 1;
  glGetError();
  wrong_arguments();
  stacks_and_order();
  inside_begin_end();
  fclose(out);
  glGetError();
  conf_value_cells(&c, cells, kCells, kCols, kRows);
  return conf_finish(&c);
}
