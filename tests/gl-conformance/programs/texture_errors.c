/* Wrong calls to every texture command of OpenGL 1.1, each followed by glGetError, whose
 * codes are compared with Mesa's (conf_error records them): bad targets, levels, sizes,
 * borders, internal formats, formats and types, sub-images out of range or of undefined
 * levels, copies, queries, texture objects bound to the other target, texture generation,
 * parameters and environment values, glPrioritizeTextures and glAreTexturesResident. The
 * state after the wrong calls is recorded too (it must be unchanged), and a textured quad
 * drawn with what is left checks that nothing was stored by a refused call. */
#include <string.h>

#include "conf.h"

static unsigned char g_pixels[64 * 64 * 4];

static void teximage_errors(ConfContext* c) {
  glTexImage2D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D target 1D");
  glTexImage2D(GL_TEXTURE_ENV, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D target ENV");
  glTexImage1D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage1D target 2D");
  glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D level -1");
  glTexImage2D(GL_TEXTURE_2D, 15, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D level 15");
  glTexImage2D(GL_TEXTURE_2D, 14, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D level 14 1x1");
  glTexImage2D(GL_TEXTURE_2D, 14, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D level 14 2x1");
  glTexImage2D(GL_TEXTURE_2D, 3, GL_RGBA, 2049, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_error(c, "TexImage2D level 3 2049 wide");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D border 2");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, -1, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D border -1");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D width 1 border 1");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D width -4");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, -4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D height -4");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16385, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_error(c, "TexImage2D width 16385");
  glTexImage2D(GL_TEXTURE_2D, 0, 0, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D internal 0");
  glTexImage2D(GL_TEXTURE_2D, 0, 5, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D internal 5");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COLOR_INDEX, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D internal COLOR_INDEX");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_BITMAP, g_pixels);
  conf_error(c, "TexImage2D RGBA BITMAP");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT, g_pixels);
  conf_error(c, "TexImage2D DEPTH_COMPONENT");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D STENCIL_INDEX");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_DOUBLE, g_pixels);
  conf_error(c, "TexImage2D type DOUBLE");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA8, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D format RGBA8");
  glTexImage2D(GL_TEXTURE_2D, 0, 7, 4, 4, 0, 0x1234, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D bad internal and format");
  glTexImage2D(GL_TEXTURE_2D, -1, 7, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D bad level and internal");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexImage2D COLOR_INDEX ubyte");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 4, 0, GL_COLOR_INDEX, GL_BITMAP, g_pixels);
  conf_error(c, "TexImage2D COLOR_INDEX BITMAP");
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 16385, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_error(c, "TexImage1D width 16385");
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_error(c, "TexImage1D width 0");
}

static void subimage_errors(ConfContext* c) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage2D before an image");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 6, 6, 3, 3, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage2D past the edge");
  glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage2D x -1");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage2D width -1");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 20, 0, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage2D empty past the edge");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 8, 8, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage2D empty at the corner");
  glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage2D undefined level 1");
  glTexSubImage2D(GL_TEXTURE_2D, 15, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage2D level 15");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage2D bad format");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, 0x1234, g_pixels);
  conf_error(c, "TexSubImage2D bad type");
  glTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage2D proxy");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, g_pixels);
  conf_error(c, "TexSubImage2D DEPTH_COMPONENT");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 1, GL_COLOR_INDEX, GL_BITMAP, g_pixels);
  conf_error(c, "TexSubImage2D COLOR_INDEX BITMAP");
  glTexSubImage1D(GL_TEXTURE_1D, 0, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage1D default 1D undefined");
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  glTexSubImage1D(GL_TEXTURE_1D, 0, 10, 7, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage1D past the edge");
  glTexSubImage1D(GL_TEXTURE_2D, 0, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  conf_error(c, "TexSubImage1D target 2D");
  glDeleteTextures(1, &t);
}

static void copy_errors(ConfContext* c) {
  glCopyTexImage2D(GL_TEXTURE_2D, 0, 1, 0, 0, 4, 4, 0);
  conf_error(c, "CopyTexImage2D internal 1");
  glCopyTexImage2D(GL_TEXTURE_2D, 0, 4, 0, 0, 4, 4, 0);
  conf_error(c, "CopyTexImage2D internal 4");
  glCopyTexImage2D(GL_TEXTURE_2D, 0, 5, 0, 0, 4, 4, 0);
  conf_error(c, "CopyTexImage2D internal 5");
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, -4, 4, 0);
  conf_error(c, "CopyTexImage2D width -4");
  glCopyTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
  conf_error(c, "CopyTexImage2D proxy");
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 2);
  conf_error(c, "CopyTexImage2D border 2");
  glCopyTexImage2D(GL_TEXTURE_2D, 15, GL_RGBA, 0, 0, 4, 4, 0);
  conf_error(c, "CopyTexImage2D level 15");
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 1, 1, 1);
  conf_error(c, "CopyTexImage2D 1x1 border 1");
  glCopyTexImage1D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 4, 0);
  conf_error(c, "CopyTexImage1D target 2D");
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 0, 0, 4, 0);
  conf_error(c, "CopyTexImage1D fine");
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 8, 8, 0);
  conf_error(c, "CopyTexImage2D fine");
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 7, 7, 0, 0, 2, 2);
  conf_error(c, "CopyTexSubImage2D past the edge");
  glCopyTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 0, 0, 1, 1);
  conf_error(c, "CopyTexSubImage2D undefined level 1");
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, -1, 1);
  conf_error(c, "CopyTexSubImage2D width -1");
  glCopyTexSubImage2D(GL_TEXTURE_1D, 0, 0, 0, 0, 0, 1, 1);
  conf_error(c, "CopyTexSubImage2D target 1D");
  glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 3, 0, 0, 4);
  conf_error(c, "CopyTexSubImage1D past the edge");
  glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 0, 0, 0, 4);
  conf_error(c, "CopyTexSubImage1D fine");
}

static void query_errors(ConfContext* c) {
  GLint v = -7;
  GLfloat f = -7.0f;
  glGetTexLevelParameteriv(GL_TEXTURE_ENV, 0, GL_TEXTURE_WIDTH, &v);
  conf_error(c, "GetTexLevelParameteriv target ENV");
  glGetTexLevelParameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, &v);
  conf_error(c, "GetTexLevelParameteriv level -1");
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 15, GL_TEXTURE_WIDTH, &v);
  conf_error(c, "GetTexLevelParameteriv level 15");
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_MIN_FILTER, &v);
  conf_error(c, "GetTexLevelParameteriv pname MIN_FILTER");
  glGetTexLevelParameterfv(GL_PROXY_TEXTURE_1D, 0, GL_TEXTURE_BORDER_COLOR, &f);
  conf_error(c, "GetTexLevelParameterfv pname BORDER_COLOR");
  conf_value(c, "unchanged int", v); /* (Mesa's fv form writes an undefined value then) */
  unsigned char out[16];
  glGetTexImage(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  conf_error(c, "GetTexImage proxy");
  glGetTexImage(GL_TEXTURE_2D, 15, GL_RGBA, GL_UNSIGNED_BYTE, out);
  conf_error(c, "GetTexImage level 15");
  glGetTexImage(GL_TEXTURE_2D, 9, GL_RGBA, GL_UNSIGNED_BYTE, out);
  conf_error(c, "GetTexImage undefined level 9");
  glGetTexImage(GL_TEXTURE_2D, 0, 0x1234, GL_UNSIGNED_BYTE, out);
  conf_error(c, "GetTexImage bad format");
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, out);
  conf_error(c, "GetTexImage DEPTH_COMPONENT");
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_BITMAP, out);
  conf_error(c, "GetTexImage BITMAP");
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, 0x1234, out);
  conf_error(c, "GetTexImage bad type");
  glGetTexParameteriv(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
  conf_error(c, "GetTexParameteriv proxy");
  glGetTexParameteriv(GL_TEXTURE_1D, GL_TEXTURE_WIDTH, &v);
  conf_error(c, "GetTexParameteriv pname WIDTH");
}

static void object_errors(ConfContext* c) {
  GLuint t[3];
  glGenTextures(-1, t);
  conf_error(c, "GenTextures -1");
  glGenTextures(3, t);
  conf_value(c, "IsTexture generated", glIsTexture(t[0]));
  glBindTexture(GL_TEXTURE_1D, t[0]);
  conf_error(c, "BindTexture 1D");
  conf_value(c, "IsTexture bound", glIsTexture(t[0]));
  glBindTexture(GL_TEXTURE_2D, t[0]);
  conf_error(c, "BindTexture the 1D texture to 2D");
  glBindTexture(GL_PROXY_TEXTURE_2D, t[1]);
  conf_error(c, "BindTexture proxy");
  glBindTexture(GL_TEXTURE_ENV, t[1]);
  conf_error(c, "BindTexture ENV");
  GLint binding = -1;
  glGetIntegerv(GL_TEXTURE_BINDING_1D, &binding);
  conf_value(c, "binding 1D", binding);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &binding);
  conf_value(c, "binding 2D", binding);
  glDeleteTextures(-2, t);
  conf_error(c, "DeleteTextures -2");
  glDeleteTextures(1, t);
  glGetIntegerv(GL_TEXTURE_BINDING_1D, &binding);
  conf_value(c, "binding 1D after delete", binding);
  GLboolean residences[3] = {7, 7, 7};
  GLuint names[3] = {t[1], t[2], 0};
  conf_value(c, "resident", glAreTexturesResident(2, names, residences));
  conf_error(c, "AreTexturesResident");
  conf_value(c, "residences untouched", residences[0] + residences[1]);
  conf_value(c, "resident with 0", glAreTexturesResident(3, names, residences));
  conf_error(c, "AreTexturesResident with 0");
  names[2] = 4000;
  conf_value(c, "resident with unknown", glAreTexturesResident(3, names, residences));
  conf_error(c, "AreTexturesResident with an unknown name");
  conf_value(c, "resident n -1", glAreTexturesResident(-1, names, residences));
  conf_error(c, "AreTexturesResident n -1");
  const GLclampf priorities[3] = {0.25f, 2.0f, -1.0f};
  glPrioritizeTextures(-1, names, priorities);
  conf_error(c, "PrioritizeTextures n -1");
  glPrioritizeTextures(3, names, priorities);
  conf_error(c, "PrioritizeTextures unknown name");
  GLfloat p = 0.0f;
  glBindTexture(GL_TEXTURE_2D, t[1]);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &p);
  conf_value(c, "priority t1", p);
  glBindTexture(GL_TEXTURE_2D, t[2]);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &p);
  conf_value(c, "priority t2 (clamped)", p);
  glBindTexture(GL_TEXTURE_2D, 0);
  glDeleteTextures(3, t);
}

static void parameter_errors(ConfContext* c) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_LINEAR);
  conf_error(c, "TexParameteri WRAP_S LINEAR");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  conf_error(c, "TexParameteri MAG_FILTER mipmap");
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, 9729.6f);
  conf_error(c, "TexParameterf MIN_FILTER 9729.6");
  GLfloat filter = 9728.6f;
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &filter);
  conf_error(c, "TexParameterfv MIN_FILTER 9728.6");
  GLint value = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &value);
  conf_value(c, "min filter", value);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1.0f);
  conf_error(c, "TexParameterf BORDER_COLOR");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_RESIDENT, 1);
  conf_error(c, "TexParameteri RESIDENT");
  glTexParameteri(GL_PROXY_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
  conf_error(c, "TexParameteri proxy");
  glTexParameteri(GL_TEXTURE_2D, 0x1234, 0);
  conf_error(c, "TexParameteri bad pname");
  const GLfloat border[4] = {2.0f, -1.0f, 0.5f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  GLfloat got[4];
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, got);
  conf_values(c, "border colour clamped", (double[]){got[0], got[1], got[2], got[3]}, 4);
  const GLint iborder[4] = {0x7fffffff, -0x7fffffff, 0, 0x3fffffff};
  glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, iborder);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, got);
  conf_values(c, "border colour from integers", (double[]){got[0], got[1], got[2], got[3]}, 4);
  GLint igot[4];
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, igot);
  conf_values(c, "border colour as integers", (double[]){igot[0], igot[1], igot[2], igot[3]}, 4);
  /* In a display list the scalar forms are recorded as the vector ones: the border colour
   * becomes (v, 0, 0, 0) without an error, compiling and executing or replayed, and
   * glTexParameteri's value goes in as a float. */
  const GLuint border_list = glGenLists(1);
  glNewList(border_list, GL_COMPILE_AND_EXECUTE);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.25f);
  glEndList();
  conf_error(c, "list TexParameterf BORDER_COLOR, compiled and executed");
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, got);
  conf_values(c, "border colour from a listed scalar", (double[]){got[0], got[1], got[2], got[3]}, 4);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glCallList(border_list);
  conf_error(c, "list TexParameterf BORDER_COLOR, replayed");
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, got);
  conf_values(c, "border colour from a replayed scalar", (double[]){got[0], got[1], got[2], got[3]}, 4);
  glNewList(border_list, GL_COMPILE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, 9729.6f);
  glEndList();
  glCallList(border_list);
  conf_error(c, "list TexParameteri BORDER_COLOR 1, TexParameterf MIN_FILTER 9729.6");
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, got);
  conf_values(c, "border colour from a listed integer", (double[]){got[0], got[1], got[2], got[3]}, 4);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, igot);
  conf_value(c, "min filter from a listed 9729.6", igot[0]);
  glDeleteLists(border_list, 1);
  glTexParameterf(GL_TEXTURE_1D, GL_TEXTURE_PRIORITY, 3.0f);
  glGetTexParameterfv(GL_TEXTURE_1D, GL_TEXTURE_PRIORITY, got);
  conf_value(c, "priority 3 clamped", got[0]);
  glGetTexParameteriv(GL_TEXTURE_1D, GL_TEXTURE_RESIDENT, igot);
  conf_value(c, "resident parameter", igot[0]);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_LINEAR);
  conf_error(c, "TexEnvi MODE LINEAR");
  glTexEnvi(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, GL_DECAL);
  conf_error(c, "TexEnvi target 2D");
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 0.75f);
  conf_error(c, "TexEnvf COLOR scalar");
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, got);
  conf_values(c, "env colour after scalar", (double[]){got[0], got[1], got[2], got[3]}, 4);
  const GLfloat env[4] = {2.0f, -1.0f, 0.5f, 1.0f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, got);
  conf_values(c, "env colour clamped", (double[]){got[0], got[1], got[2], got[3]}, 4);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, igot);
  conf_value(c, "env mode", igot[0]);
}

static void texgen_errors(ConfContext* c) {
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  conf_error(c, "TexGeni R SPHERE_MAP");
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  conf_error(c, "TexGeni Q SPHERE_MAP");
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, 0x1234);
  conf_error(c, "TexGeni S bad mode");
  glTexGeni(0x1234, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  conf_error(c, "TexGeni bad coord");
  glTexGeni(GL_S, 0x1234, GL_EYE_LINEAR);
  conf_error(c, "TexGeni bad pname");
  glTexGenf(GL_T, GL_TEXTURE_GEN_MODE, 9217.7f);
  conf_error(c, "TexGenf T mode 9217.7");
  glTexGenf(GL_S, GL_OBJECT_PLANE, 3.0f);
  conf_error(c, "TexGenf S OBJECT_PLANE scalar");
  GLint mode = 0;
  glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, &mode);
  conf_value(c, "T mode", mode);
  GLfloat plane[4];
  glGetTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  conf_values(c, "S object plane", (double[]){plane[0], plane[1], plane[2], plane[3]}, 4);
  glGetTexGenfv(GL_Q, GL_OBJECT_PLANE, plane);
  conf_error(c, "GetTexGenfv Q");
  glGetTexGenfv(0x1234, GL_OBJECT_PLANE, plane);
  conf_error(c, "GetTexGenfv bad coord");
  glGetTexGenfv(GL_S, GL_TEXTURE_ENV_MODE, plane);
  conf_error(c, "GetTexGenfv bad pname");
  glBegin(GL_TRIANGLES);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glEnd();
  conf_error(c, "TexGeni between Begin and End");
  glBegin(GL_TRIANGLES);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  glEnd();
  conf_error(c, "TexImage2D between Begin and End");
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 64, 64)) return 1;
  for (int i = 0; i < 64 * 64 * 4; ++i) g_pixels[i] = (unsigned char)(i * 37 + (i >> 6) * 11);
  glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  teximage_errors(&c);
  subimage_errors(&c);
  copy_errors(&c);
  query_errors(&c);
  object_errors(&c);
  parameter_errors(&c);
  texgen_errors(&c);
  /* The default 2D texture: whatever the wrong calls left, drawn (nearest, no mipmaps). */
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_pixels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(-0.8f, -0.8f);
  glTexCoord2f(1, 0);
  glVertex2f(0.8f, -0.8f);
  glTexCoord2f(1, 1);
  glVertex2f(0.8f, 0.8f);
  glTexCoord2f(0, 1);
  glVertex2f(-0.8f, 0.8f);
  glEnd();
  return conf_finish(&c);
}
