// Wavefront OBJ loading: tinyobjloader parses, this file checks every index and number, merges
// the shapes, splits polygons the way OpenGL would, and keys vertices by the OBJ's indices.
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <tiny_obj_loader.h>

#include "shadelab/shapes.hpp"

namespace shadelab {

namespace {

/// Larger files are refused rather than read (a guard against running out of memory).
constexpr std::size_t kMaxFileBytes = std::size_t(256) << 20;
/// At most this many problems are listed one by one; the rest are counted.
constexpr int kMaxListed = 10;

/// Appends diagnostics for one file, listing the first kMaxListed problems.
struct Reporter {
  Diagnostics& diags;
  const std::string& path;
  int count = 0;
  void operator()(int line, const std::string& message) {
    if (++count <= kMaxListed) diags.error({path, line, 0}, "", message);
  }
  bool finish() {
    if (count > kMaxListed) diags.error({path, 0, 0}, "", std::to_string(count - kMaxListed) + " more problems");
    return count == 0;
  }
};

bool read_file(const std::string& path, std::string& text, Reporter& report) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    report(0, std::string("cannot open mesh file: ") + std::strerror(errno));
    return false;
  }
  char buffer[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, f)) > 0 && text.size() <= kMaxFileBytes) {
    text.append(buffer, got);
  }
  int error = std::ferror(f) ? errno : 0;
  std::fclose(f);
  if (error != 0) report(0, std::string("cannot read mesh file: ") + std::strerror(error));
  if (text.size() > kMaxFileBytes) report(0, "mesh file is larger than 256 MiB");
  return report.count == 0;
}

/// 1-based line numbers of the `v`, `vn`, `vt` and face lines, in file order (tinyobjloader does
/// not say where each element came from). Faces with fewer than 3 vertices are skipped, as
/// tinyobjloader skips them.
struct ObjLines {
  std::vector<int> v, vn, vt, f;
};

ObjLines scan_lines(const std::string& text) {
  ObjLines lines;
  std::istringstream in(text);
  std::string line, keyword, token;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    if (!(words >> keyword)) continue;
    if (keyword == "v") lines.v.push_back(number);
    if (keyword == "vn") lines.vn.push_back(number);
    if (keyword == "vt") lines.vt.push_back(number);
    int corners = 0;
    while (keyword == "f" && words >> token) ++corners;
    if (corners >= 3) lines.f.push_back(number);
  }
  return lines;
}

int line_of(const std::vector<int>& lines, std::size_t i) { return i < lines.size() ? lines[i] : 0; }

void check_finite(const std::vector<tinyobj::real_t>& values, int per_item, const char* what,
                  const std::vector<int>& lines, Reporter& report) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (std::isfinite(values[i])) continue;
    std::size_t item = i / std::size_t(per_item);
    report(line_of(lines, item), std::string(what) + " " + std::to_string(item + 1) + " has a coordinate that is not a finite number");
    i = (item + 1) * std::size_t(per_item) - 1;  // one report per item
  }
}

/// Reports an index that is out of range (-1, "no index", is allowed where `optional`).
void check_index(int index, std::size_t count, bool optional, const char* what, int line, Reporter& report) {
  if ((optional && index == -1) || (index >= 0 && std::size_t(index) < count)) return;
  std::string which = index < 0 ? "a " + std::string(what) + " before the first" : std::string(what) + " " + std::to_string(index + 1);
  report(line, "face refers to " + which + " but the file has " + std::to_string(count));
}

void check_faces(const std::vector<tinyobj::shape_t>& shapes, const tinyobj::attrib_t& a, const ObjLines& lines,
                 Reporter& report) {
  std::size_t face = 0;
  for (const tinyobj::shape_t& s : shapes) {
    std::size_t corners = 0;
    for (unsigned char n : s.mesh.num_face_vertices) corners += n;
    if (corners != s.mesh.indices.size()) {  // tinyobjloader counts corners in an unsigned char
      report(0, "a face has more than 255 vertices");
      return;
    }
    std::size_t offset = 0;
    for (unsigned char n : s.mesh.num_face_vertices) {
      int line = line_of(lines.f, face++);
      for (std::size_t k = offset; k < offset + n; ++k) {
        const tinyobj::index_t& i = s.mesh.indices[k];
        check_index(i.vertex_index, a.vertices.size() / 3, false, "vertex", line, report);
        check_index(i.normal_index, a.normals.size() / 3, true, "normal", line, report);
        check_index(i.texcoord_index, a.texcoords.size() / 2, true, "texture coordinate", line, report);
      }
      offset += n;
    }
  }
}

/// The mesh under construction: one vertex per distinct (position, normal, texcoord) index
/// triple, with the OBJ position index of each vertex remembered for smooth normals.
struct Builder {
  Builder(const tinyobj::attrib_t& attrib, bool use_file_normals) : a(attrib), file_normals(use_file_normals) {}
  const tinyobj::attrib_t& a;
  bool file_normals;
  Mesh mesh;
  std::vector<int> position_of;  ///< OBJ position index of each mesh vertex
  std::vector<Triangle> by_position;  ///< the triangles in OBJ position indices
  struct Hash {
    std::size_t operator()(const std::array<int, 3>& k) const {
      return std::hash<long long>()((long long)k[0] * 1000003LL ^ (long long)k[1] * 7919LL ^ k[2]);
    }
  };
  std::unordered_map<std::array<int, 3>, std::uint32_t, Hash> index_of;

  std::uint32_t vertex(const tinyobj::index_t& i) {
    std::array<int, 3> key{i.vertex_index, file_normals ? i.normal_index : -1, i.texcoord_index};
    auto [it, added] = index_of.emplace(key, std::uint32_t(mesh.positions.size()));
    if (added) {
      const tinyobj::real_t* p = &a.vertices[3 * std::size_t(i.vertex_index)];
      mesh.positions.push_back({p[0], p[1], p[2]});
      const tinyobj::real_t* t = i.texcoord_index >= 0 ? &a.texcoords[2 * std::size_t(i.texcoord_index)] : nullptr;
      mesh.texcoords.push_back(t ? glm::vec2(t[0], t[1]) : glm::vec2(0.0f));
      if (!a.colors.empty()) {
        const tinyobj::real_t* k = &a.colors[3 * std::size_t(i.vertex_index)];
        mesh.colors.push_back(glm::clamp(glm::vec4(k[0], k[1], k[2], 1.0f), 0.0f, 1.0f));
      }
      position_of.push_back(i.vertex_index);
    }
    return it->second;
  }

  /// Triangles as OpenGL splits a triangle, a quad (add_quad's (a,b,d), (b,c,d)) and a convex
  /// polygon (a fan whose triangles all end in the first vertex, GL_POLYGON's provoking vertex).
  /// Vertices are numbered in the order the file lists them.
  void face(const tinyobj::index_t* c, std::size_t n) {
    std::uint32_t ids[256];
    for (std::size_t k = 0; k < n; ++k) ids[k] = vertex(c[k]);
    auto triangle = [&](std::size_t x, std::size_t y, std::size_t z) {
      mesh.triangles.push_back({ids[x], ids[y], ids[z]});
      by_position.push_back({std::uint32_t(c[x].vertex_index), std::uint32_t(c[y].vertex_index),
                             std::uint32_t(c[z].vertex_index)});
    };
    if (n == 3) {
      triangle(0, 1, 2);
    } else if (n == 4) {
      triangle(0, 1, 3);
      triangle(1, 2, 3);
    } else {
      for (std::size_t k = 1; k + 1 < n; ++k) triangle(k, k + 1, 0);
    }
  }

  void normals();
};

/// Smooth normals are computed over OBJ positions, so faces that share a position but not a
/// texture coordinate still join smoothly; the file's normals, when used, are normalized (a
/// zero one falls back to the smooth normal).
void Builder::normals() {
  Mesh shared;
  for (std::size_t i = 0; i + 2 < a.vertices.size(); i += 3) shared.positions.push_back({a.vertices[i], a.vertices[i + 1], a.vertices[i + 2]});
  shared.triangles = by_position;
  compute_smooth_normals(shared);
  for (const auto& [key, v] : index_of) {
    glm::vec3 smooth = shared.normals[std::size_t(position_of[v])], n = smooth;
    if (file_normals) {
      const tinyobj::real_t* q = &a.normals[3 * std::size_t(key[1])];
      float len = glm::length(glm::vec3(q[0], q[1], q[2]));
      if (len > 0.0f && std::isfinite(len)) n = glm::vec3(q[0], q[1], q[2]) / len;
    }
    mesh.normals[v] = n;
  }
}

bool parse(const std::string& text, tinyobj::attrib_t& attrib, std::vector<tinyobj::shape_t>& shapes, Reporter& report) {
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  std::istringstream in(text);
  // No material reader: an OBJ's .mtl is not part of the scene (materials are). No triangulation
  // here: indices are checked before anything uses them, then faces are split below.
  // Vertex colours (`v x y z r g b`, an extension many tools write) are kept only when every
  // vertex has one.
  if (tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, nullptr, false, false)) return true;
  while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
  report(0, "cannot parse mesh file: " + (err.empty() ? std::string("bad OBJ data") : err));
  return false;
}

}  // namespace

bool load_obj(const std::string& path, Mesh& out, Diagnostics& diags) {
  Reporter report{diags, path};
  std::string text;
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  if (!read_file(path, text, report) || !parse(text, attrib, shapes, report)) return report.finish();
  ObjLines lines = scan_lines(text);
  check_finite(attrib.vertices, 3, "vertex", lines.v, report);
  check_finite(attrib.normals, 3, "normal", lines.vn, report);
  check_finite(attrib.texcoords, 2, "texture coordinate", lines.vt, report);
  check_finite(attrib.colors, 3, "vertex colour", lines.v, report);
  check_faces(shapes, attrib, lines, report);
  if (report.count > 0) return report.finish();
  bool file_normals = true;
  for (const auto& s : shapes)
    for (const auto& i : s.mesh.indices) file_normals = file_normals && i.normal_index >= 0;
  Builder b(attrib, file_normals);
  for (const auto& s : shapes) {
    std::size_t offset = 0;
    for (unsigned char n : s.mesh.num_face_vertices) {
      b.face(&s.mesh.indices[offset], n);
      offset += n;
    }
  }
  if (b.mesh.triangles.empty()) {
    report(0, "mesh has no triangles");
    return report.finish();
  }
  b.mesh.normals.resize(b.mesh.positions.size());
  b.normals();
  out = std::move(b.mesh);
  return true;
}

}  // namespace shadelab
