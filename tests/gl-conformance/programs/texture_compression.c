/* GL 1.3's compressed-texture commands where no specific compressed format is used: the
 * glGetError code of glCompressedTexImage1D/2D/3D, glCompressedTexSubImage1D/2D/3D and
 * glGetCompressedTexImage with uncompressed and unknown formats, wrong targets, levels and
 * sizes (the codes Mesa gives a format or target it cannot compress), and glTexImage2D with
 * the generic compressed internal formats (GL_COMPRESSED_RGB ...), stored uncompressed: the
 * level's parameters compared with Mesa's, and the textures drawn. */
#define GL_GLEXT_PROTOTYPES
#include "conf.h"

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 192, 128)) return 1;
  static GLubyte data[8 * 8 * 4];
  for (int k = 0; k < 8 * 8 * 4; ++k) data[k] = (GLubyte)(k * 37 + (k / 32) * 11);
  const GLenum formats[] = {GL_RGBA, GL_RGB, GL_COMPRESSED_RGB, GL_COMPRESSED_INTENSITY, 0x1234};
  const char* names[] = {"RGBA", "RGB", "generic RGB", "generic intensity", "junk"};
  char label[128];
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
  glBindTexture(GL_TEXTURE_1D, 2);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
  for (int f = 0; f < 5; ++f) {
    const GLenum fmt = formats[f];
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmt, 4, 4, 0, 16, data);
    snprintf(label, sizeof label, "CompressedTexImage2D %s", names[f]), conf_error(&c, label);
    glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, fmt, 4, 4, 0, 16, data);
    snprintf(label, sizeof label, "CompressedTexImage2D proxy %s", names[f]), conf_error(&c, label);
    glCompressedTexImage2D(GL_TEXTURE_1D, 0, fmt, 4, 4, 0, 16, data);
    snprintf(label, sizeof label, "CompressedTexImage2D target 1D %s", names[f]), conf_error(&c, label);
    glCompressedTexImage2D(GL_TEXTURE_2D, -1, fmt, 4, 4, 0, 16, data);
    snprintf(label, sizeof label, "CompressedTexImage2D level -1 %s", names[f]), conf_error(&c, label);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmt, -4, 4, 0, 16, data);
    snprintf(label, sizeof label, "CompressedTexImage2D width -4 %s", names[f]), conf_error(&c, label);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmt, 4, 4, 1, 16, data);
    snprintf(label, sizeof label, "CompressedTexImage2D border 1 %s", names[f]), conf_error(&c, label);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmt, 4, 4, 0, -1, data);
    snprintf(label, sizeof label, "CompressedTexImage2D size -1 %s", names[f]), conf_error(&c, label);
    glCompressedTexImage1D(GL_TEXTURE_1D, 0, fmt, 4, 0, 16, data);
    snprintf(label, sizeof label, "CompressedTexImage1D %s", names[f]), conf_error(&c, label);
    glCompressedTexImage1D(GL_TEXTURE_2D, 0, fmt, 4, 0, 16, data);
    snprintf(label, sizeof label, "CompressedTexImage1D target 2D %s", names[f]), conf_error(&c, label);
    glCompressedTexImage3D(GL_TEXTURE_3D, 0, fmt, 4, 4, 4, 0, 16, data);
    snprintf(label, sizeof label, "CompressedTexImage3D %s", names[f]), conf_error(&c, label);
    glCompressedTexImage3D(GL_TEXTURE_2D, 0, fmt, 4, 4, 4, 0, 16, data);
    snprintf(label, sizeof label, "CompressedTexImage3D target 2D %s", names[f]), conf_error(&c, label);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, fmt, 16, data);
    snprintf(label, sizeof label, "CompressedTexSubImage2D %s", names[f]), conf_error(&c, label);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 5, 0, 0, 4, 4, fmt, 16, data);
    snprintf(label, sizeof label, "CompressedTexSubImage2D level 5 %s", names[f]), conf_error(&c, label);
    glCompressedTexSubImage2D(GL_TEXTURE_1D, 0, 0, 0, 4, 4, fmt, 16, data);
    snprintf(label, sizeof label, "CompressedTexSubImage2D target 1D %s", names[f]), conf_error(&c, label);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, fmt, -1, data);
    snprintf(label, sizeof label, "CompressedTexSubImage2D size -1 %s", names[f]), conf_error(&c, label);
    glCompressedTexSubImage1D(GL_TEXTURE_1D, 0, 0, 4, fmt, 16, data);
    snprintf(label, sizeof label, "CompressedTexSubImage1D %s", names[f]), conf_error(&c, label);
    glCompressedTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 4, 4, 4, fmt, 16, data);
    snprintf(label, sizeof label, "CompressedTexSubImage3D %s", names[f]), conf_error(&c, label);
  }
  glGetCompressedTexImage(GL_TEXTURE_2D, 0, data), conf_error(&c, "GetCompressedTexImage uncompressed");
  glGetCompressedTexImage(GL_TEXTURE_1D, 0, data), conf_error(&c, "GetCompressedTexImage 1D uncompressed");
  glGetCompressedTexImage(GL_TEXTURE_2D, 3, data), conf_error(&c, "GetCompressedTexImage no level");
  glGetCompressedTexImage(GL_TEXTURE_2D, -1, data), conf_error(&c, "GetCompressedTexImage level -1");
  glGetCompressedTexImage(GL_TEXTURE_2D, 20, data), conf_error(&c, "GetCompressedTexImage level 20");
  glGetCompressedTexImage(GL_TEXTURE_ENV, 0, data), conf_error(&c, "GetCompressedTexImage target");
  glGetCompressedTexImage(GL_PROXY_TEXTURE_2D, 0, data), conf_error(&c, "GetCompressedTexImage proxy");
  glBegin(GL_POINTS);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, 16, data);
  glEnd();
  conf_error(&c, "CompressedTexImage2D in glBegin");
  GLint n = -1;
  glGetIntegerv(GL_TEXTURE_COMPRESSION_HINT, &n), conf_value(&c, "GL_TEXTURE_COMPRESSION_HINT", n);
  conf_error(&c, "hint query");

  /* The generic compressed formats through glTexImage2D, stored uncompressed: those llvmpipe
   * does not compress either (it stores GL_COMPRESSED_LUMINANCE, _LUMINANCE_ALPHA, _RGB and
   * _RGBA as LATC1, LATC2, DXT1 and DXT3), each twice. */
  const GLenum generic[] = {GL_COMPRESSED_ALPHA, GL_COMPRESSED_INTENSITY, GL_COMPRESSED_ALPHA,
                            GL_COMPRESSED_INTENSITY, GL_COMPRESSED_ALPHA, GL_COMPRESSED_INTENSITY};
  static const GLenum params[] = {GL_TEXTURE_WIDTH, GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE,
                                  GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE,
                                  GL_TEXTURE_INTENSITY_SIZE};
  glClearColor(0.3f, 0.1f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int g = 0; g < 6; ++g) {
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)generic[g], 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
    snprintf(label, sizeof label, "TexImage2D generic 0x%x", generic[g]), conf_error(&c, label);
    for (unsigned p = 0; p < sizeof params / sizeof params[0]; ++p) {
      GLint v = -1;
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, params[p], &v);
      snprintf(label, sizeof label, "generic 0x%x parameter 0x%x", generic[g], params[p]);
      conf_value(&c, label, v);
    }
    GLint internal = -1, compressed = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
    snprintf(label, sizeof label, "generic 0x%x GL_TEXTURE_INTERNAL_FORMAT", generic[g]);
    conf_value(&c, label, internal);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &compressed);
    snprintf(label, sizeof label, "generic 0x%x GL_TEXTURE_COMPRESSED", generic[g]);
    conf_value(&c, label, compressed);
    conf_error(&c, label);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &compressed);
    snprintf(label, sizeof label, "generic 0x%x GL_TEXTURE_COMPRESSED_IMAGE_SIZE", generic[g]);
    conf_error(&c, label);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, g < 2 ? GL_MODULATE : g < 4 ? GL_REPLACE : GL_DECAL);
    conf_panel(&c, g % 3, g / 3, 3, 2);
    glBegin(GL_TRIANGLES);
    glTexCoord2f(0, 0), glVertex2f(-0.9f, -0.9f);
    glTexCoord2f(1, 0), glVertex2f(0.9f, -0.9f);
    glTexCoord2f(1, 1), glVertex2f(0.9f, 0.9f);
    glTexCoord2f(0, 0), glVertex2f(-0.9f, -0.9f);
    glTexCoord2f(1, 1), glVertex2f(0.9f, 0.9f);
    glTexCoord2f(0, 1), glVertex2f(-0.9f, 0.9f);
    glEnd();
  }
  glDisable(GL_BLEND);
  glDisable(GL_TEXTURE_2D);
  return conf_finish(&c);
}
