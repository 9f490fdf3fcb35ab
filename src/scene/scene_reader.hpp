// The scene reader: a located JSON tree (after --set overrides) checked key by key and turned
// into a Scene. Its parts live in scene_reader.cpp (image, camera, lights), object_reader.cpp
// (materials, objects, transforms), shape_reader.cpp (shapes and meshes, sized before they are
// built) and extras_reader.cpp (textures, planar shadows). Private to the scene module.
// Every problem becomes a diagnostic and reading goes on; it never prints or throws on bad
// input.
#pragma once

#include <map>
#include <memory>
#include <string>

#include <glm/mat4x4.hpp>

#include "scene/reader.hpp"
#include "shadelab/scene.hpp"
#include "shadelab/scene_io.hpp"

namespace shadelab::detail {

class SceneReader {
 public:
  SceneReader(const std::string& file, std::string base_dir, const LoadOptions& options,
              Diagnostics& diags)
      : r_(file, diags), base_dir_(std::move(base_dir)), options_(options) {}

  /// Reads the whole tree, reporting every problem; `scene` is complete only if none was found.
  void read(const JsonValue& root, Scene& scene);

 private:
  Reader r_;
  std::string base_dir_;
  const LoadOptions& options_;
  std::map<std::string, Material> materials_;
  std::map<std::string, std::shared_ptr<const Mesh>> meshes_;
  std::map<std::string, std::shared_ptr<const Texture>> textures_;
  long long triangles_ = 0;

  // scene_reader.cpp
  void image(const JsonValue& v, Scene& s);
  void samples(const JsonValue& v, Scene& s);
  void camera(const JsonValue& v, Camera& c);
  void check_view(const JsonValue& v, const Camera& c);
  void projection_matrix(const JsonValue& v, Camera& c);
  void light_model(const JsonValue& v, LightModel& m);
  void lights(const JsonValue& v, Scene& s);
  SceneLight light(const JsonValue& v, const std::string& path, int index);
  void attenuation(const JsonValue& v, const std::string& path, Light& l);
  void spot(const JsonValue& v, const std::string& path, Light& l);
  void light_shadow(const JsonValue& v, const std::string& path, SceneLight& l);

  // object_reader.cpp
  void materials(const JsonValue& v);
  Material material_object(const JsonValue& v, const std::string& path);
  Material material(const JsonValue& v, const std::string& path);
  void objects(const JsonValue& v, Scene& s);
  void object(const JsonValue& v, const std::string& path, Scene& s);
  void appearance(const JsonValue& v, const std::string& path, SceneObject& o);
  glm::mat4 transform(const JsonValue& v, const std::string& path);
  glm::mat4 rotations(const JsonValue& v, const std::string& path);
  glm::mat4 scaling(const JsonValue& v, const std::string& path);

  // shape_reader.cpp
  std::shared_ptr<const Mesh> shape(const JsonValue& v, const std::string& path);
  std::shared_ptr<const Mesh> mesh_file(const JsonValue& params, const std::string& path);
  bool obj_fits(const std::string& full, const JsonValue& file, const std::string& path);
  bool within_limit(const JsonValue& at, const std::string& path, long long triangles);
  bool count(const JsonValue& at, const std::string& path, long long triangles);
  std::string resolve(const std::string& relative) const;
  /// With LoadOptions::confine_files, false (and an error at `at`) when `full` lies outside
  /// the scene's folder.
  bool confined(const JsonValue& at, const std::string& path, const std::string& full);

  // extras_reader.cpp
  void texture(const JsonValue& v, const std::string& path, SceneObject& o);
  std::shared_ptr<const Texture> load_texture(const JsonValue& file, const std::string& path,
                                              const Texture& settings);
  void shadows(const JsonValue& v, Scene& s);
  void shadow(const JsonValue& v, const std::string& path, Scene& s);
};

}  // namespace shadelab::detail
