// Shapes: each type's parameters are checked and its triangle count worked out before the mesh
// is built, so that a scene over the triangle limit never allocates its meshes. OBJ files are
// counted by a streaming pass over their face lines before they are loaded, and loaded once.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>

#include "scene/scene_reader.hpp"
#include "shadelab/shapes.hpp"

namespace shadelab::detail {

using Type = JsonValue::Type;

namespace {

/// A shape ready to build: how many triangles it will have, and how to build it.
struct ShapePlan {
  long long triangles = 0;
  std::function<Mesh()> build;
};

using PlanFn = ShapePlan (*)(Reader&, const JsonValue&, const std::string&);

struct ShapeKind {
  std::string type;
  std::vector<std::string> keys;  ///< parameters besides "type"
  PlanFn plan;                    ///< null for "mesh" (read by the SceneReader: files, cache)
};

constexpr int kMaxSegments = 4096;

ShapePlan teapot(Reader& r, const JsonValue& p, const std::string& path) {
  TeapotParams t;
  r.number(p, "size", path, t.size, above(0));
  r.integer(p, "tessellation", path, t.tessellation, 1, 64);
  long long n = t.tessellation;
  return {32 * 2 * n * n, [t] { return make_teapot(t); }};  // 32 patches of n x n quads
}

ShapePlan sphere(Reader& r, const JsonValue& p, const std::string& path) {
  SphereParams s;
  r.number(p, "radius", path, s.radius, above(0));
  r.integer(p, "slices", path, s.slices, 3, kMaxSegments);
  r.integer(p, "stacks", path, s.stacks, 2, kMaxSegments);
  return {2LL * s.slices * s.stacks, [s] { return make_sphere(s); }};
}

ShapePlan cylinder(Reader& r, const JsonValue& p, const std::string& path) {
  CylinderParams c;
  r.number(p, "radius", path, c.radius, above(0));
  r.number(p, "height", path, c.height, above(0));
  r.integer(p, "slices", path, c.slices, 3, kMaxSegments);
  r.integer(p, "stacks", path, c.stacks, 1, kMaxSegments);
  r.boolean(p, "caps", path, c.caps);
  r.boolean(p, "angle_colors", path, c.angle_colors);
  return {2LL * c.slices * (c.stacks + (c.caps ? 2 : 0)), [c] { return make_cylinder(c); }};
}

ShapePlan cone(Reader& r, const JsonValue& p, const std::string& path) {
  ConeParams c;
  r.number(p, "radius", path, c.radius, above(0));
  r.number(p, "height", path, c.height, above(0));
  r.integer(p, "slices", path, c.slices, 3, kMaxSegments);
  r.integer(p, "stacks", path, c.stacks, 1, kMaxSegments);
  r.boolean(p, "cap", path, c.cap);
  return {2LL * c.slices * (c.stacks + (c.cap ? 1 : 0)), [c] { return make_cone(c); }};
}

ShapePlan torus(Reader& r, const JsonValue& p, const std::string& path) {
  TorusParams t;
  r.number(p, "major_radius", path, t.major_radius, above(0));
  r.number(p, "minor_radius", path, t.minor_radius, above(0));
  r.integer(p, "sides", path, t.sides, 3, kMaxSegments);
  r.integer(p, "rings", path, t.rings, 3, kMaxSegments);
  return {2LL * t.sides * t.rings, [t] { return make_torus(t); }};
}

ShapePlan cube(Reader& r, const JsonValue& p, const std::string& path) {
  float size = 1.0f;
  r.number(p, "size", path, size, above(0));
  return {12, [size] { return make_cube(size); }};
}

ShapePlan tetrahedron(Reader&, const JsonValue&, const std::string&) {
  return {4, [] { return make_tetrahedron(); }};
}

ShapePlan wall(Reader& r, const JsonValue& p, const std::string& path) {
  WallParams w;
  r.number(p, "width", path, w.width, above(0));
  r.number(p, "height", path, w.height, above(0));
  r.integer(p, "nx", path, w.nx, 1, kMaxSegments);
  r.integer(p, "ny", path, w.ny, 1, kMaxSegments);
  return {2LL * w.nx * w.ny, [w] { return make_wall(w); }};
}

ShapePlan plane(Reader& r, const JsonValue& p, const std::string& path) {
  float size = 10.0f;
  int n = 1;
  r.number(p, "size", path, size, above(0));
  r.integer(p, "n", path, n, 1, kMaxSegments);
  return {2LL * n * n, [size, n] { return make_plane(size, n); }};
}

ShapePlan disk(Reader& r, const JsonValue& p, const std::string& path) {
  DiskParams d;
  std::size_t errors = r.error_count();
  bool inner = r.number(p, "inner_radius", path, d.inner_radius, closed(0, kMaxLength));
  bool outer = r.number(p, "outer_radius", path, d.outer_radius, above(0));
  if (r.error_count() == errors && (inner || outer) && d.outer_radius <= d.inner_radius) {
    std::string key = outer ? "outer_radius" : "inner_radius";
    r.error(*p.find(key), join_path(path, key), "outer_radius (" + format_number(d.outer_radius) +
                                                    ") must be greater than inner_radius (" +
                                                    format_number(d.inner_radius) + ")");
  }
  r.integer(p, "slices", path, d.slices, 3, kMaxSegments);
  r.integer(p, "loops", path, d.loops, 1, kMaxSegments);
  return {2LL * d.slices * d.loops, [d] { return make_disk(d); }};
}

const std::vector<ShapeKind>& shape_kinds() {
  static const std::vector<ShapeKind> kinds = {
      {"teapot", {"size", "tessellation"}, teapot},
      {"sphere", {"radius", "slices", "stacks"}, sphere},
      {"cylinder", {"radius", "height", "slices", "stacks", "caps", "angle_colors"}, cylinder},
      {"cone", {"radius", "height", "slices", "stacks", "cap"}, cone},
      {"torus", {"major_radius", "minor_radius", "sides", "rings"}, torus},
      {"cube", {"size"}, cube},
      {"tetrahedron", {}, tetrahedron},
      {"wall", {"width", "height", "nx", "ny"}, wall},
      {"plane", {"size", "n"}, plane},
      {"disk", {"inner_radius", "outer_radius", "slices", "loops"}, disk},
      {"mesh", {"file"}, nullptr},
  };
  return kinds;
}

struct ObjCounts {
  long long triangles = 0;  ///< after fan triangulation: n - 2 per face of n vertices
  long long vertices = 0;
};

// One streaming pass over an OBJ file, without reading whole lines into memory.
bool count_obj(const std::string& path, ObjCounts& out) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  enum { kStart, kF, kV, kFace, kSkip } state = kStart;
  long long corners = 0;
  bool in_token = false;
  auto end_line = [&] {
    if (state == kFace) out.triangles += std::max(0LL, corners - 2);
    state = kStart;
    corners = 0;
    in_token = false;
  };
  char buf[1 << 16];
  while (f.read(buf, sizeof buf) || f.gcount() > 0) {
    for (std::streamsize i = 0; i < f.gcount(); ++i) {
      char c = buf[i];
      bool blank = c == ' ' || c == '\t' || c == '\r';
      if (c == '\n') {
        end_line();
      } else if (state == kStart && !blank) {
        state = c == 'f' ? kF : c == 'v' ? kV : kSkip;
      } else if (state == kF || state == kV) {
        if (blank && state == kV) ++out.vertices;
        state = !blank ? kSkip : state == kF ? kFace : kSkip;
      } else if (state == kFace) {
        if (!blank && !in_token) ++corners;
        in_token = !blank;
      }
    }
  }
  end_line();
  return true;
}

}  // namespace

std::shared_ptr<const Mesh> SceneReader::shape(const JsonValue& v, const std::string& path) {
  if (v.type != Type::kString && v.type != Type::kObject) {
    r_.error(v, path, "expected a shape name or an object with \"type\", got " + v.type_name());
    return nullptr;
  }
  const JsonValue* type = v.type == Type::kString ? &v : v.find("type");
  std::string type_path = v.type == Type::kString ? path : join_path(path, "type");
  if (!type) {
    r_.error(v, path, "missing required key \"type\"");
    return nullptr;
  }
  if (!r_.is_type(*type, Type::kString, type_path)) return nullptr;
  const auto& kinds = shape_kinds();
  auto kind = std::find_if(kinds.begin(), kinds.end(), [&](const ShapeKind& k) { return k.type == type->text; });
  if (kind == kinds.end()) {
    std::vector<std::string> names;
    for (const ShapeKind& k : kinds) names.push_back(k.type);
    r_.error(*type, type_path, "unknown shape \"" + type->text + "\"" + suggestion(type->text, names));
    return nullptr;
  }
  JsonValue no_params;  // a bare name: every parameter takes its default
  no_params.type = Type::kObject;
  no_params.line = v.line;
  no_params.column = v.column;
  const JsonValue& params = v.type == Type::kObject ? v : no_params;
  std::vector<std::string> keys = kind->keys;
  keys.push_back("type");
  std::size_t errors = r_.error_count();
  if (!r_.object(params, path, keys)) return nullptr;
  if (!kind->plan) return mesh_file(params, path);
  ShapePlan plan = kind->plan(r_, params, path);
  if (r_.error_count() != errors || !count(v, path, plan.triangles)) return nullptr;
  return std::make_shared<const Mesh>(plan.build());
}

std::string SceneReader::resolve(const std::string& relative) const {
  return (std::filesystem::path(base_dir_) / relative).lexically_normal().string();
}

bool SceneReader::confined(const JsonValue& at, const std::string& path, const std::string& full) {
  if (!options_.confine_files) return true;
  std::error_code ec;
  std::filesystem::path folder = std::filesystem::weakly_canonical(base_dir_.empty() ? "." : base_dir_, ec);
  std::filesystem::path file = std::filesystem::weakly_canonical(full, ec);
  auto [end, _] = std::mismatch(folder.begin(), folder.end(), file.begin(), file.end());
  if (!ec && end == folder.end()) return true;
  r_.error(at, path, "\"" + at.text + "\" is outside the scene's folder");
  return false;
}

// A Wavefront OBJ file, relative to the scene's folder; each file is loaded once and shared.
std::shared_ptr<const Mesh> SceneReader::mesh_file(const JsonValue& params, const std::string& path) {
  const JsonValue* file = params.find("file");
  std::string file_path = join_path(path, "file");
  if (!file) {
    r_.error(params, path, "missing required key \"file\"");
    return nullptr;
  }
  if (!r_.is_type(*file, Type::kString, file_path)) return nullptr;
  std::string full = resolve(file->text);
  if (!confined(*file, file_path, full)) return nullptr;
  if (auto it = meshes_.find(full); it != meshes_.end()) {
    return count(*file, file_path, (long long)it->second->triangles.size()) ? it->second : nullptr;
  }
  if (!obj_fits(full, *file, file_path)) return nullptr;
  Mesh mesh;
  Diagnostics mesh_errors;
  if (!load_obj(full, mesh, mesh_errors)) {
    for (const Diagnostic& d : mesh_errors.items()) {
      std::string message = d.location.file;
      if (d.location.line > 0) message += ':' + std::to_string(d.location.line);
      message += ": ";
      message += d.message;
      r_.error(*file, file_path, message);
    }
    return nullptr;
  }
  if (!count(*file, file_path, (long long)mesh.triangles.size())) return nullptr;
  return meshes_[full] = std::make_shared<const Mesh>(std::move(mesh));
}

// Counts an OBJ file's faces and vertices before it is loaded. An unreadable file passes: loading
// it explains the problem.
bool SceneReader::obj_fits(const std::string& full, const JsonValue& file, const std::string& path) {
  ObjCounts counts;
  if (!count_obj(full, counts)) return true;
  if (!within_limit(file, path, counts.triangles)) return false;
  long long max_vertices = 3 * options_.max_triangles;
  if (counts.vertices <= max_vertices) return true;
  r_.error(file, path, "the mesh has " + std::to_string(counts.vertices) + " vertices, more than the limit of " +
                           std::to_string(max_vertices) + " (3 per triangle of the triangle limit)");
  return false;
}

// Would `triangles` more stay within the scene's limit? Reports if not.
bool SceneReader::within_limit(const JsonValue& at, const std::string& path, long long triangles) {
  if (triangles_ + triangles <= options_.max_triangles) return true;
  r_.error(at, path, "the scene would have " + std::to_string(triangles_ + triangles) +
                         " triangles, more than the limit of " + std::to_string(options_.max_triangles));
  return false;
}

bool SceneReader::count(const JsonValue& at, const std::string& path, long long triangles) {
  if (!within_limit(at, path, triangles)) return false;
  triangles_ += triangles;
  return true;
}

}  // namespace shadelab::detail
