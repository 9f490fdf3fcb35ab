// EXT_vertex_array (1995; GL 1.1 made it core): its pointer commands carry a count of the
// elements that are "static", which only allowed an implementation to copy them once; like
// Mesa's, they set the GL 1.1 arrays and leave the count out. Its glArrayElementEXT,
// glDrawArraysEXT and glGetPointervEXT are the core commands under other names (config.toml).
#include "gl/generated/exec.hpp"
#include "gl/src/context.hpp"

namespace shadelab::gl {

void exec::VertexPointerEXT(GlContext& c, GLint size, GLenum type, GLsizei stride, GLsizei /*count*/,
                            const void* pointer) {
  VertexPointer(c, size, type, stride, pointer);
}

void exec::NormalPointerEXT(GlContext& c, GLenum type, GLsizei stride, GLsizei /*count*/, const void* pointer) {
  NormalPointer(c, type, stride, pointer);
}

void exec::ColorPointerEXT(GlContext& c, GLint size, GLenum type, GLsizei stride, GLsizei /*count*/,
                           const void* pointer) {
  ColorPointer(c, size, type, stride, pointer);
}

void exec::IndexPointerEXT(GlContext& c, GLenum type, GLsizei stride, GLsizei /*count*/, const void* pointer) {
  IndexPointer(c, type, stride, pointer);
}

void exec::TexCoordPointerEXT(GlContext& c, GLint size, GLenum type, GLsizei stride, GLsizei /*count*/,
                              const void* pointer) {
  TexCoordPointer(c, size, type, stride, pointer);
}

void exec::EdgeFlagPointerEXT(GlContext& c, GLsizei stride, GLsizei /*count*/, const GLboolean* pointer) {
  EdgeFlagPointer(c, stride, pointer);
}

}  // namespace shadelab::gl
