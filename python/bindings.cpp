// The Python module's native part (_shadelab): scenes read and changed through the scene
// reader (the same key paths, overrides and diagnostics as the command's --set), renders into
// numpy arrays that own the library's pixels (no copy), the pixel explanation, sweeps and the
// material table. The Python package (python/shadelab/__init__.py) wraps it; nothing here
// prints. Renders and sweeps run with the GIL released.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "shadelab/contact_sheet.hpp"
#include "shadelab/explain.hpp"
#include "shadelab/image.hpp"
#include "shadelab/materials.hpp"
#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"
#include "sweep.hpp"
#include "text_file.hpp"

namespace py = pybind11;

namespace shadelab::python {
namespace {

// Raised with the reader's diagnostics: a list of (file, line, column, key_path, message).
// A plain reference, kept for the interpreter's life (a py::object here would be released
// after the interpreter has finalized).
PyObject* scene_error_type = PyExc_Exception;

[[noreturn]] void raise_diagnostics(const Diagnostics& diags) {
  py::list items;
  for (const Diagnostic& d : diags.items()) {
    items.append(py::make_tuple(d.location.file, d.location.line, d.location.column, d.key_path, d.message));
  }
  std::string text = diags.to_string();
  if (!text.empty() && text.back() == '\n') text.pop_back();
  PyErr_SetObject(scene_error_type, py::make_tuple(text, items).ptr());
  throw py::error_already_set();
}

// A scene as the reader made it: its JSON text (a file's contents or a dict's dump), where
// relative paths in it start, the overrides set so far, and the validated Scene.
class PyScene {
 public:
  PyScene(std::string text, std::string filename, std::string base_dir)
      : text_(std::move(text)), filename_(std::move(filename)), base_dir_(std::move(base_dir)) {
    reload(overrides_);
  }

  // Applies "key=json" on top of the overrides so far; on an error the scene is unchanged.
  void set(const std::string& key, const std::string& json_value) {
    std::vector<std::string> next = overrides_;
    next.push_back(key + "=" + json_value);
    reload(next);
  }

  const Scene& scene() const { return *scene_; }
  const std::string& text() const { return text_; }
  const std::string& filename() const { return filename_; }
  const std::string& base_dir() const { return base_dir_; }
  const std::vector<std::string>& overrides() const { return overrides_; }

  // The scene with further overrides (a render's size or samples), or the error.
  Scene with(const std::vector<std::string>& more) const {
    if (more.empty()) return *scene_;
    LoadOptions options;
    options.overrides = overrides_;
    options.overrides.insert(options.overrides.end(), more.begin(), more.end());
    LoadResult r = parse_scene(text_, filename_, base_dir_, options);
    if (!r.scene) raise_diagnostics(r.diagnostics);
    return std::move(*r.scene);
  }

 private:
  void reload(const std::vector<std::string>& overrides) {
    LoadOptions options;
    options.overrides = overrides;
    LoadResult r = parse_scene(text_, filename_, base_dir_, options);
    if (!r.scene) raise_diagnostics(r.diagnostics);
    scene_ = std::make_shared<const Scene>(std::move(*r.scene));
    overrides_ = overrides;
  }

  std::string text_, filename_, base_dir_;
  std::vector<std::string> overrides_;
  std::shared_ptr<const Scene> scene_;
};

PyScene scene_from_file(const std::string& path) {
  std::optional<std::string> text = cli::read_text_file(path);
  if (!text) {
    Diagnostics d;
    d.error({path, 0, 0}, "", "cannot open the scene file");
    raise_diagnostics(d);
  }
  std::string dir = std::filesystem::path(path).parent_path().string();
  return PyScene(std::move(*text), path, dir.empty() ? "." : dir);
}

// An H x W x 4 uint8 array over the image's own pixels: the capsule owns them.
py::array_t<std::uint8_t> to_array(Image&& image) {
  auto* owned = new std::vector<std::uint8_t>(std::move(image.rgba));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<std::uint8_t>*>(p); });
  const auto h = py::ssize_t(image.height), w = py::ssize_t(image.width);
  return py::array_t<std::uint8_t>({h, w, py::ssize_t(4)}, {w * 4, py::ssize_t(4), py::ssize_t(1)}, owned->data(),
                                   owner);
}

std::optional<ShadingMode> shading_of(const std::optional<std::string>& s) {
  if (!s) return std::nullopt;
  if (*s == "flat") return ShadingMode::kFlat;
  if (*s == "gouraud") return ShadingMode::kGouraud;
  if (*s == "phong") return ShadingMode::kPhong;
  throw py::value_error("shading: expected \"flat\", \"gouraud\" or \"phong\", got \"" + *s + "\"");
}

py::array_t<std::uint8_t> render(const PyScene& s, std::optional<std::pair<int, int>> size,
                                 std::optional<std::string> shading, std::optional<int> samples, bool reference) {
  std::vector<std::string> more;
  if (size) {
    more.push_back("image.width=" + std::to_string(size->first));
    more.push_back("image.height=" + std::to_string(size->second));
  }
  if (samples) more.push_back("image.samples=" + std::to_string(*samples));
  const Scene scene = s.with(more);
  RenderOptions options;
  options.shading = shading_of(shading);
  options.reference = reference;
  Image image;
  {
    py::gil_scoped_release unlocked;
    image = render_scene(scene, options);
  }
  return to_array(std::move(image));
}

py::list vec3(const glm::vec3& v) { return py::cast(std::vector<float>{v.x, v.y, v.z}); }

py::object explain(const PyScene& s, int x, int y) {
  std::optional<PixelExplanation> e;
  {
    py::gil_scoped_release unlocked;
    e = explain_pixel(s.scene(), x, y);
  }
  if (!e) return py::none();
  const LightingBreakdown& b = e->breakdown;
  py::list lights;
  for (const LightTerm& t : b.lights) {
    py::dict term;
    term["light"] = t.light;
    term["attenuation"] = t.attenuation;
    term["spot"] = t.spot;
    term["n_dot_l"] = t.n_dot_l;
    term["ambient"] = vec3(t.ambient);
    term["diffuse"] = vec3(t.diffuse);
    term["specular"] = vec3(t.specular);
    lights.append(term);
  }
  py::dict out;
  out["object"] = e->object;
  out["shading"] = e->shading == ShadingMode::kFlat ? "flat" : e->shading == ShadingMode::kGouraud ? "gouraud" : "phong";
  out["lit"] = e->lit;
  out["back_face"] = e->back_face;
  out["position"] = vec3(e->position);
  out["normal"] = vec3(e->normal);
  out["depth"] = e->depth;
  out["emission"] = vec3(b.emission);
  out["global_ambient"] = vec3(b.global_ambient);
  out["lights"] = lights;
  out["unclamped"] = vec3(b.unclamped);
  out["result"] = py::cast(std::vector<float>{b.result.primary.r, b.result.primary.g, b.result.primary.b,
                                              b.result.primary.a});
  out["secondary"] = vec3(glm::vec3(b.result.secondary));
  return out;
}

// vary: [(key, [json values])], one or two keys.
py::array_t<std::uint8_t> sweep(const PyScene& s, const std::vector<std::pair<std::string, std::vector<std::string>>>& vary,
                                std::optional<std::string> shading, std::optional<int> samples, int columns,
                                const std::string& title, const std::vector<std::string>& labels) {
  cli::SweepRequest request;
  request.scene = s.filename();
  request.scene_text = s.text();
  request.base_dir = s.base_dir();
  request.overrides = s.overrides();
  for (const auto& [key, values] : vary) request.vary.push_back({key, values});
  request.shading = shading_of(shading);
  request.samples = samples;
  request.columns = columns;
  request.title = title;
  request.labels = labels;
  std::string error;
  std::unique_ptr<Font> font = Font::load(Font::kDefaultPath, &error);
  if (!font) throw std::runtime_error(error);
  Diagnostics diags;
  std::optional<Image> sheet;
  {
    py::gil_scoped_release unlocked;
    sheet = cli::run_sweep(request, *font, diags, [](int, int, const std::string&) {});
  }
  if (!sheet) raise_diagnostics(diags);
  return to_array(std::move(*sheet));
}

py::list materials() {
  py::list out;
  for (const MaterialPreset& p : material_presets()) {
    py::dict m;
    m["name"] = p.name;
    m["description"] = p.description;
    const Material& mat = p.material;
    m["ambient"] = py::cast(std::vector<float>{mat.ambient.r, mat.ambient.g, mat.ambient.b, mat.ambient.a});
    m["diffuse"] = py::cast(std::vector<float>{mat.diffuse.r, mat.diffuse.g, mat.diffuse.b, mat.diffuse.a});
    m["specular"] = py::cast(std::vector<float>{mat.specular.r, mat.specular.g, mat.specular.b, mat.specular.a});
    m["emission"] = py::cast(std::vector<float>{mat.emission.r, mat.emission.g, mat.emission.b, mat.emission.a});
    m["shininess"] = mat.shininess;
    out.append(m);
  }
  return out;
}

// PNG bytes of an H x W x 4 uint8 array (an image's _repr_png_ and save()).
py::bytes png(py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast> a) {
  if (a.ndim() != 3 || a.shape(2) != 4) throw py::value_error("expected an H x W x 4 array of uint8");
  Image image;
  image.height = int(a.shape(0));
  image.width = int(a.shape(1));
  image.rgba.assign(a.data(), a.data() + a.size());
  std::vector<std::uint8_t> bytes = encode_png(image);
  return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

}  // namespace
}  // namespace shadelab::python

PYBIND11_MODULE(_shadelab, m) {
  using namespace shadelab::python;
  m.doc() = "shadelab's native module; use the shadelab package";
  m.def("_set_error_type", [](py::object type) {  // the package's SceneError
    Py_INCREF(type.ptr());
    scene_error_type = type.ptr();
  });
  py::class_<PyScene>(m, "Scene")
      .def(py::init<std::string, std::string, std::string>(), py::arg("text"), py::arg("filename"),
           py::arg("base_dir"))
      .def("set", &PyScene::set, py::arg("key"), py::arg("json_value"))
      .def_property_readonly("width", [](const PyScene& s) { return s.scene().width; })
      .def_property_readonly("height", [](const PyScene& s) { return s.scene().height; })
      .def_property_readonly("samples", [](const PyScene& s) { return s.scene().samples; })
      .def_property_readonly("filename", &PyScene::filename)
      .def_property_readonly("overrides", &PyScene::overrides)
      .def_property_readonly("object_names",
                             [](const PyScene& s) {
                               std::vector<std::string> names;
                               for (const auto& o : s.scene().objects) names.push_back(o.name);
                               return names;
                             })
      .def_property_readonly("light_count", [](const PyScene& s) { return s.scene().lights.size(); });
  m.def("scene_from_file", &scene_from_file, py::arg("path"));
  m.def("render", &render, py::arg("scene"), py::arg("size") = py::none(), py::arg("shading") = py::none(),
        py::arg("samples") = py::none(), py::arg("reference") = false);
  m.def("explain", &explain, py::arg("scene"), py::arg("x"), py::arg("y"));
  m.def("sweep", &sweep, py::arg("scene"), py::arg("vary"), py::arg("shading") = py::none(),
        py::arg("samples") = py::none(), py::arg("columns") = 0, py::arg("title") = "",
        py::arg("labels") = std::vector<std::string>{});
  m.def("materials", &materials);
  m.def("png", &png, py::arg("image"));
}
