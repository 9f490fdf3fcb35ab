// Wavefront OBJ loading through tinyobjloader: shapes merged, polygons triangulated, indices
// checked, normals from the file when every face has them, else computed smooth.
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <tuple>

#include <tiny_obj_loader.h>

#include "shadelab/shapes.hpp"

namespace shadelab {

namespace {

bool fail(Diagnostics& diags, const std::string& path, const std::string& message) {
  diags.error({path, 0, 0}, "", message);
  return false;
}

}  // namespace

bool load_obj(const std::string& path, Mesh& out, Diagnostics& diags) {
  {
    std::ifstream probe(path);
    if (!probe) return fail(diags, path, std::string("cannot open mesh file: ") + std::strerror(errno));
  }
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  // No material library reading: an OBJ's .mtl is not part of the scene (materials are).
  std::string no_mtl_dir = "/nonexistent/";
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, path.c_str(), no_mtl_dir.c_str(), true)) {
    return fail(diags, path, "cannot read mesh file: " + (err.empty() ? std::string("bad OBJ data") : err));
  }
  std::size_t nv = attrib.vertices.size() / 3, nn = attrib.normals.size() / 3, nt = attrib.texcoords.size() / 2;
  for (float f : attrib.vertices) {
    if (!std::isfinite(f)) return fail(diags, path, "mesh file has a non-finite coordinate");
  }
  bool all_normals = true;
  for (const auto& s : shapes)
    for (const auto& i : s.mesh.indices) all_normals &= i.normal_index >= 0;
  Mesh m;
  std::map<std::tuple<int, int, int>, std::uint32_t> index_of;
  for (const auto& s : shapes) {
    std::size_t offset = 0;
    for (unsigned char fv : s.mesh.num_face_vertices) {
      if (fv != 3) return fail(diags, path, "face with " + std::to_string(fv) + " vertices after triangulation");
      Triangle t;
      for (int k = 0; k < 3; ++k) {
        const tinyobj::index_t& i = s.mesh.indices[offset + k];
        if (i.vertex_index < 0 || std::size_t(i.vertex_index) >= nv) {
          return fail(diags, path, "face refers to vertex " + std::to_string(i.vertex_index + 1) +
                                       " but the file has " + std::to_string(nv));
        }
        if ((all_normals && std::size_t(i.normal_index) >= nn) ||
            (i.texcoord_index >= 0 && std::size_t(i.texcoord_index) >= nt)) {
          return fail(diags, path, "face refers to a normal or texture coordinate the file lacks");
        }
        auto key = std::make_tuple(i.vertex_index, all_normals ? i.normal_index : -1, i.texcoord_index);
        auto [it, added] = index_of.emplace(key, std::uint32_t(m.positions.size()));
        if (added) {
          const float* p = &attrib.vertices[3 * i.vertex_index];
          m.positions.push_back({p[0], p[1], p[2]});
          if (all_normals) {
            const float* q = &attrib.normals[3 * i.normal_index];
            glm::vec3 n(q[0], q[1], q[2]);
            float len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
            m.normals.push_back(len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0, 0, 1));
          }
          const float* tc = i.texcoord_index >= 0 ? &attrib.texcoords[2 * i.texcoord_index] : nullptr;
          m.texcoords.push_back(tc ? glm::vec2(tc[0], tc[1]) : glm::vec2(0.0f));
        }
        t[k] = it->second;
      }
      m.triangles.push_back(t);
      offset += 3;
    }
  }
  if (m.triangles.empty()) return fail(diags, path, "mesh has no triangles");
  if (!all_normals) compute_smooth_normals(m);
  out = std::move(m);
  return true;
}

}  // namespace shadelab
