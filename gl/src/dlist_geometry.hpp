// Geometry compiled once (GL 1.1 section 5.4 leaves how a list is stored to the
// implementation): at glEndList, each glBegin ... glEnd made only of vertices and their
// attributes, and each dereferenced vertex-array draw, becomes one ListMesh, drawn when the
// list runs as glDrawElements draws (draw_array_mesh), or vertex by vertex when the state of
// that moment rules the fast path out. Decides nothing about what is drawn: the same vertices
// and current values as the recorded commands.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <initializer_list>

#include <glm/vec4.hpp>

#include "gl/src/convert.hpp"

namespace shadelab::gl {

struct DisplayList;
struct GlContext;
class ListReader;
enum class Opcode : std::uint16_t;

/// The attribute a glVertex / glNormal / glColor / glTexCoord command sets.
enum class AttributeKind { kVertex, kNormal, kColor, kTexCoord };

/// One such command's value, with the components it did not give filled as GL fills them
/// (z 0 and w 1 for vertices, alpha 1 for colours, t 0, r 0, q 1 for texture coordinates).
struct VertexAttribute {
  AttributeKind kind = AttributeKind::kVertex;
  glm::vec4 value{0.0f, 0.0f, 0.0f, 1.0f};

  static VertexAttribute make(AttributeKind kind, std::initializer_list<float> given) {
    VertexAttribute a;
    a.kind = kind;
    int i = 0;
    for (float v : given) a.value[i++] = v;
    return a;
  }
};

/// A component of such a command as the command itself converts it (GL 1.1 table 2.6: the
/// integer forms of glColor and glNormal through color_component, as gl/src/current.cpp
/// does; the others convert directly), so that a mesh and the immediate call agree.
template <class T>
float attribute_value(T v, AttributeKind kind) {
  if (kind == AttributeKind::kColor || kind == AttributeKind::kNormal) return color_component(v);
  return float(v);
}

/// The attribute command at `reader` (generated for every implemented glVertex, glNormal,
/// glColor and glTexCoord form): true and its value, or false (another command, or a null
/// pointer, which the command itself rejects) with the reader anywhere in the command.
bool decode_attribute(Opcode op, ListReader& reader, VertexAttribute& out);

/// At glEndList: the list's geometry as meshes (the commands they replace leave the code).
void compile_geometry(DisplayList& list);

}  // namespace shadelab::gl
