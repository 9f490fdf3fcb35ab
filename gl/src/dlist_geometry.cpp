// Geometry compiled once (GL 1.1 section 5.4): at glEndList, each glBegin ... glEnd of
// vertex and attribute commands (glVertex, glNormal, glColor, glTexCoord, glArrayElement),
// and each dereferenced glDrawArrays / glDrawElements, becomes a mesh of distinct vertices
// and indices, replacing those commands in the list. When the list runs, a mesh is drawn as
// glDrawElements draws client arrays (draw_array_mesh: each distinct vertex transformed and
// lit once, on the pipeline's threads); when the state of that moment rules that path out
// (colour material with per-vertex colours, flat quads, w != 1 under lighting, a primitive
// already begun, ...), it is specified vertex by vertex as the commands it replaced would
// specify it. Either way the same vertices, attributes and current values.
#include "gl/src/dlist_geometry.hpp"

#include <algorithm>
#include <cstring>
#include <unordered_map>

#include <glm/gtc/type_ptr.hpp>

#include "gl/generated/run.hpp"
#include "gl/src/dlist.hpp"
#include "gl/src/draw.hpp"

namespace shadelab::gl {
namespace {

// A vertex with the attributes a mesh keeps per vertex, compared bit by bit.
struct VertexKey {
  float v[15];
  bool operator==(const VertexKey& o) const { return std::memcmp(v, o.v, sizeof v) == 0; }
};

struct VertexKeyHash {
  std::size_t operator()(const VertexKey& k) const {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the bits
    const auto* b = reinterpret_cast<const unsigned char*>(k.v);
    for (std::size_t i = 0; i < sizeof k.v; ++i) h = (h ^ b[i]) * 1099511628211ull;
    return std::size_t(h);
  }
};

// Builds a mesh vertex by vertex: a vertex equal in every kept attribute to one before it is
// that one again.
class MeshBuilder {
 public:
  explicit MeshBuilder(ListMesh& m) : m_(m) {}

  // Which attributes the mesh keeps per vertex; fixed before the first vertex.
  void keep(bool normals, bool colors, bool texcoords) {
    normals_ = normals, colors_ = colors, texcoords_ = texcoords;
  }
  bool has_vertices() const { return !m_.indices.empty(); }

  void vertex(const glm::vec4& position, const glm::vec3& normal, const glm::vec4& color,
              const glm::vec4& texcoord) {
    VertexKey key{};
    std::memcpy(&key.v[0], &position[0], 16);
    if (normals_) std::memcpy(&key.v[4], &normal[0], 12);
    if (colors_) std::memcpy(&key.v[7], &color[0], 16);
    if (texcoords_) std::memcpy(&key.v[11], &texcoord[0], 16);
    auto [it, added] = index_.try_emplace(key, std::uint32_t(m_.positions.size()));
    if (added) {
      m_.positions.push_back(position);
      if (normals_) m_.normals.push_back(normal);
      if (colors_) m_.colors.push_back(color);
      if (texcoords_) m_.texcoords.push_back(texcoord);
    }
    m_.indices.push_back(it->second);
  }

 private:
  ListMesh& m_;
  bool normals_ = false, colors_ = false, texcoords_ = false;
  std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> index_;
};

// The attributes a glBegin ... glEnd sets as it goes. An attribute it sets only after its
// first vertex would give that vertex the current value of replay time in one vertex and not
// the other: such a primitive is not compiled.
struct RunState {
  glm::vec3 normal{0.0f};
  glm::vec4 color{0.0f}, texcoord{0.0f};
  bool normal_set = false, color_set = false, texcoord_set = false;
  bool vertex_seen = false;

  bool set(AttributeKind kind, const glm::vec4& v) {
    bool& flag = kind == AttributeKind::kNormal ? normal_set : kind == AttributeKind::kColor ? color_set : texcoord_set;
    if (!flag && vertex_seen) return false;
    flag = true;
    if (kind == AttributeKind::kNormal) normal = glm::vec3(v);
    else if (kind == AttributeKind::kColor) color = v;
    else texcoord = v;
    return true;
  }
};

// The mesh of the glBegin ... glEnd at `start`, and the offset after its glEnd; 0 when it is
// not made of vertices and attributes only (or has no glEnd in this list).
std::size_t begin_end_mesh(const DisplayList& list, std::size_t start, ListMesh& mesh) {
  ListReader r(list);
  r.seek(start);
  r.next();
  mesh.mode = r.scalar<GLenum>();
  if (mesh.mode > GL_POLYGON) return 0;  // glBegin's error, recorded as it is
  // Which attributes change per vertex is known only at the end: the vertices are gathered
  // first, then deduplicated.
  struct Vertex {
    glm::vec4 position;
    glm::vec3 normal;
    glm::vec4 color, texcoord;
  };
  std::vector<Vertex> vertices;
  RunState s;
  auto vertex = [&](const glm::vec4& p) {
    s.vertex_seen = true;
    vertices.push_back({p, s.normal, s.color, s.texcoord});
  };
  r.skip_command();  // past glBegin
  while (!r.done()) {
    const Opcode op = r.next();
    if (op == Opcode::kEnd) {
      MeshBuilder b(mesh);
      b.keep(s.normal_set, s.color_set, s.texcoord_set);
      for (const Vertex& v : vertices) b.vertex(v.position, v.normal, v.color, v.texcoord);
      mesh.sets_normal = s.normal_set, mesh.sets_color = s.color_set, mesh.sets_texcoord = s.texcoord_set;
      mesh.last_normal = s.normal, mesh.last_color = s.color, mesh.last_texcoord = s.texcoord;
      r.skip_command();
      return r.offset();
    }
    if (op == Opcode::kArrayElements) {
      const RecordedElements e(r);
      // Edge flags, secondary colours, fog coordinates per vertex: a mesh keeps none (replayed
      // as recorded).
      if (e.edges || e.secondary || e.fog || e.other_units()) return 0;
      for (std::uint64_t k = 0; k < e.count; ++k) {
        if (e.normals && !s.set(AttributeKind::kNormal, glm::vec4(glm::make_vec3(&e.normals[3 * k]), 0.0f))) return 0;
        if (e.colors && !s.set(AttributeKind::kColor, glm::make_vec4(&e.colors[4 * k]))) return 0;
        if (e.texcoords && !s.set(AttributeKind::kTexCoord, glm::make_vec4(&e.texcoords[4 * k]))) return 0;
        if (e.positions) vertex(glm::make_vec4(&e.positions[4 * k]));
      }
    } else {
      VertexAttribute a;
      if (!decode_attribute(op, r, a)) return 0;
      if (a.kind == AttributeKind::kVertex) vertex(a.value);
      else if (!s.set(a.kind, a.value)) return 0;
    }
    r.skip_command();
  }
  return 0;
}

// The mesh of an ArrayDraw command (the reader after its opcode); false when its elements
// carry edge flags, secondary colours, fog coordinates or texture coordinates of units past 0,
// which a mesh does not keep (the command is then replayed as recorded).
bool array_draw_mesh(ListReader& r, ListMesh& mesh) {
  mesh.mode = r.scalar<GLenum>();
  mesh.array_draw = true;
  const RecordedElements e(r);
  if (e.edges || e.secondary || e.fog || e.other_units()) return false;
  MeshBuilder b(mesh);
  b.keep(e.normals != nullptr, e.colors != nullptr, e.texcoords != nullptr);
  for (std::uint64_t k = 0; k < e.count; ++k) {
    b.vertex(glm::make_vec4(&e.positions[4 * k]), e.normals ? glm::make_vec3(&e.normals[3 * k]) : glm::vec3(0.0f),
             e.colors ? glm::make_vec4(&e.colors[4 * k]) : glm::vec4(0.0f),
             e.texcoords ? glm::make_vec4(&e.texcoords[4 * k]) : glm::vec4(0.0f));
  }
  return true;
}

// Vertex v's attributes become current, then it is specified.
void specify(GlContext& c, const ListMesh& m, std::uint32_t v) {
  if (!m.normals.empty()) c.current.normal = m.normals[v];
  if (!m.colors.empty()) {
    c.current.color = m.colors[v];
    apply_color_material(c);
  }
  if (!m.texcoords.empty()) c.current.texcoords[0] = m.texcoords[v];
  if (c.prim.active) emit_vertex(c, m.positions[v]);
}

// What a glBegin ... glEnd leaves current (GL 1.1 section 2.7): the attributes it set last.
void leave_current(GlContext& c, const ListMesh& m) {
  if (m.sets_normal) c.current.normal = m.last_normal;
  if (m.sets_color) {
    c.current.color = m.last_color;
    apply_color_material(c);
  }
  if (m.sets_texcoord) c.current.texcoords[0] = m.last_texcoord;
}

// The commands the mesh replaced, vertex by vertex.
void specify_each(GlContext& c, const ListMesh& m) {
  if (m.array_draw) {  // as replay_internal::ArrayDraw
    const CurrentAttribs saved = c.current;
    const Material front = c.lighting.front, back = c.lighting.back;
    begin_primitive(c, m.mode);
    for (std::uint32_t v : m.indices) specify(c, m, v);
    end_primitive(c);
    c.current = saved;
    c.lighting.front = front, c.lighting.back = back;
    return;
  }
  run::Begin(c, m.mode);  // within a primitive already begun: its error, then its vertices
  for (std::uint32_t v : m.indices) specify(c, m, v);
  leave_current(c, m);
  run::End(c);
}

// The mesh through the vertex-array path, if it applies now; false with nothing drawn.
bool draw_fast(GlContext& c, const ListMesh& m) {
  if (c.prim.active || m.indices.empty()) return false;
  const CurrentAttribs now = c.current;
  auto load = [&](std::size_t first, std::size_t n, glm::vec4* positions, glm::vec3* normals,
                  glm::vec4* colors, glm::vec4* texcoords) {
    std::copy_n(&m.positions[first], n, positions);
    if (m.normals.empty()) std::fill_n(normals, n, now.normal);
    else std::copy_n(&m.normals[first], n, normals);
    if (colors && m.colors.empty()) std::fill_n(colors, n, now.color);
    else if (colors) std::copy_n(&m.colors[first], n, colors);
    if (texcoords && m.texcoords.empty()) std::fill_n(texcoords, n, now.texcoords[0]);
    else if (texcoords) std::copy_n(&m.texcoords[first], n, texcoords);
  };
  const bool triangles = m.mode == GL_TRIANGLES;
  if (!triangles) c.array_scratch.sequence.assign(m.indices.begin(), m.indices.end());
  const std::uint32_t hi = std::uint32_t(m.positions.size() - 1);
  if (!draw_array_mesh(c, m.mode, !m.colors.empty(), false, m.indices.size(), triangles ? m.indices.data() : nullptr,
                       0, hi, load)) {
    return false;
  }
  if (!m.array_draw) leave_current(c, m);
  return true;
}

}  // namespace

void compile_geometry(DisplayList& list) {
  std::vector<std::uint64_t> code;
  code.reserve(list.code.size());
  ListReader r(list);
  while (!r.done()) {
    const std::size_t start = r.offset();
    const Opcode op = r.next();
    r.skip_command();
    const std::size_t end = r.offset();
    ListMesh mesh;
    std::size_t after = 0;
    if (op == Opcode::kBegin) {
      after = begin_end_mesh(list, start, mesh);
    } else if (op == Opcode::kArrayDraw) {
      r.seek(start);
      r.next();
      if (array_draw_mesh(r, mesh)) after = end;
    }
    if (after == 0) {
      code.insert(code.end(), list.code.begin() + std::ptrdiff_t(start), list.code.begin() + std::ptrdiff_t(end));
      r.seek(end);
      continue;
    }
    ListWriter w(code, Opcode::kMesh);
    w.scalar(std::uint64_t(list.meshes.size()));
    list.meshes.push_back(std::move(mesh));
    r.seek(after);
  }
  list.code = std::move(code);
}

void replay_internal::Mesh(GlContext& c, ListReader& r) {
  const ListMesh& m = r.list().meshes[r.scalar<std::uint64_t>()];
  if (m.array_draw && c.prim.active) return c.set_error(GL_INVALID_OPERATION);  // glDrawArrays' rule
  if (draw_fast(c, m)) {
    ++c.lists.meshes_fast;
    return;
  }
  ++c.lists.meshes_by_vertex;
  specify_each(c, m);
}

}  // namespace shadelab::gl
