// The lighting lab's server: embedded page assets and the JSON API (docs/lab.md). Scenes come
// in as scene-file JSON and go through the same reader as the command line, so a bad value
// gets the same message, with its key path, as a 400 answer. Connections are served by a large
// pool of threads (an idle or slow connection holds only its own), request bodies are read
// within a time limit, and renders run on a few workers through a fair, bounded queue
// (render_queue.hpp), each with its own pipeline.
#include "lab_server.hpp"

#include <httplib.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <thread>

#include <nlohmann/json.hpp>

#include "lab_assets.hpp"
#include "render_queue.hpp"
#include "shadelab/explain.hpp"
#include "shadelab/image.hpp"
#include "shadelab/materials.hpp"
#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"
#include "text_file.hpp"

namespace shadelab::cli {

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

// JSON text; a string that is not valid UTF-8 (a request's bytes quoted in a message, a file
// name) has its bad bytes replaced rather than failing the answer.
std::string text_of(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

json diagnostics_json(const Diagnostics& d) {
  json errors = json::array();
  for (const Diagnostic& e : d.items()) {
    errors.push_back({{"path", e.key_path},
                      {"line", e.location.line},
                      {"column", e.location.column},
                      {"message", e.message},
                      {"text", e.to_string()}});
  }
  return errors;
}

void send_error(httplib::Response& res, int status, const std::string& message,
                json errors = json::array()) {
  if (errors.empty()) errors.push_back({{"path", ""}, {"message", message}, {"text", message}});
  res.status = status;
  res.set_content(text_of(json{{"error", message}, {"errors", errors}}), "application/json");
}

json color_json(const glm::vec3& c) { return {c.r, c.g, c.b}; }
json color_json(const glm::vec4& c) { return {c.r, c.g, c.b, c.a}; }

json material_json(const Material& m) {
  return {{"ambient", color_json(m.ambient)},
          {"diffuse", color_json(m.diffuse)},
          {"specular", color_json(m.specular)},
          {"emission", color_json(m.emission)},
          {"shininess", m.shininess}};
}

class Lab {
 public:
  explicit Lab(const LabOptions& o)
      : options_(o),
        queue_(std::make_unique<RenderQueue>(o.render_workers > 0 ? o.render_workers
                                                                  : std::max(2, int(std::thread::hardware_concurrency())),
                                             o.max_queued_renders, o.max_client_renders)) {
    base_dir_ = o.scene_path.empty() ? fs::path(".") : fs::path(o.scene_path).parent_path();
    if (base_dir_.empty()) base_dir_ = ".";
  }

  // A request that renders, with its body: read within the request's time limit, then run
  // through the render queue; a full queue is answered 503 at once, with Retry-After.
  void queued(const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader,
              void (Lab::*handler)(const httplib::Request&, const std::string&, httplib::Response&) const) const {
    std::string body;
    if (!read_body(reader, body)) {  // too large (httplib set 413 then), or too slow
      res.set_header("Connection", "close");
      if (res.status == 413 || body.size() > options_.max_body) return send_error(res, 413, "the request is too large");
      return send_error(res, 408, "the request's body took longer than the lab's limit of " +
                                      std::to_string(options_.max_request_seconds) + " s");
    }
    std::exception_ptr error;  // a render's exception goes to the server's handler (500), as before
    const bool ran = queue_->run(req.remote_addr, [&] {
      try {
        (this->*handler)(req, body, res);
      } catch (...) {
        error = std::current_exception();
      }
    });
    if (error) std::rethrow_exception(error);
    if (!ran) {
      res.set_header("Retry-After", "1");
      send_error(res, 503, "the lab is busy: " + std::to_string(options_.max_queued_renders) +
                               " renders are waiting (at most " + std::to_string(options_.max_client_renders) +
                               " from one client); try again");
    }
  }

  void explain_request(const httplib::Request&, const std::string& body, httplib::Response& res) const {
    explain(body, res);
  }

  // The request's body, read in pieces until it is complete; false when it takes longer than
  // the request time limit from the request's start (a client trickling its body) or is larger
  // than the body limit.
  bool read_body(const httplib::ContentReader& reader, std::string& body) const {
    const auto deadline = request_start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                              std::chrono::duration<double>(options_.max_request_seconds));
    return reader([&](const char* data, std::size_t n) {
      body.append(data, n);
      return body.size() <= options_.max_body && std::chrono::steady_clock::now() < deadline;
    });
  }

  // When the request this thread serves began (set before its body is read).
  static thread_local std::chrono::steady_clock::time_point request_start;

  // Parses a scene sent by the page; on failure answers 400 and returns nothing.
  std::optional<Scene> scene_from(const std::string& text, httplib::Response& res,
                                  const std::vector<std::string>& overrides = {}) const {
    LoadOptions load;
    load.overrides = overrides;
    load.max_pixels = options_.max_pixels;
    load.max_triangles = options_.max_triangles;
    load.max_lights = options_.max_lights;
    load.confine_files = true;  // OBJ and texture files only from the served scene's folder
    LoadResult r = parse_scene(text, "scene", base_dir_.string(), load);
    if (!r.scene) {
      send_error(res, 400, "the scene has errors", diagnostics_json(r.diagnostics));
      return std::nullopt;
    }
    return std::move(*r.scene);
  }

  void render(const httplib::Request& req, const std::string& body, httplib::Response& res) const {
    std::vector<std::string> overrides;
    RenderOptions ro;
    ro.threads = 1;  // one thread per request: the server's pool serves clients side by side
    ro.max_fragment_memory = options_.max_fragment_mib << 20;
    if (req.has_param("shading")) {
      std::string s = req.get_param_value("shading");
      if (s == "flat") ro.shading = ShadingMode::kFlat;
      else if (s == "gouraud") ro.shading = ShadingMode::kGouraud;
      else if (s == "phong") ro.shading = ShadingMode::kPhong;
      else return send_error(res, 400, "shading: expected flat, gouraud or phong, got \"" + s + "\"");
    }
    std::optional<Scene> scene = scene_from(body, res, overrides);
    if (!scene) return;
    auto start = std::chrono::steady_clock::now();
    ro.deadline = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(options_.max_render_seconds));
    RenderStats stats;
    Image img = render_scene(*scene, ro, &stats);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (stats.interrupted) {
      return send_error(res, 503, "the render took longer than the lab's limit of " +
                                      std::to_string(options_.max_render_seconds) + " s");
    }
    if (stats.fragments_dropped > 0) {
      return send_error(res, 503, "exact transparency needs more than the lab's limit of " +
                                      std::to_string(options_.max_fragment_mib) +
                                      " MiB for its fragment lists");
    }
    std::vector<std::uint8_t> png = encode_png(img);
    res.set_header("X-Render-Ms", std::to_string(ms));
    res.set_header("Cache-Control", "no-store");
    res.set_content(std::string(png.begin(), png.end()), "image/png");
  }

  void explain(const std::string& text, httplib::Response& res) const {
    json body = json::parse(text, nullptr, false);
    if (body.is_discarded() || !body.is_object()) return send_error(res, 400, "expected a JSON object {scene, x, y}");
    if (!body.contains("scene") || !body["scene"].is_object()) return send_error(res, 400, "scene: expected the scene object");
    if (!body.contains("x") || !body["x"].is_number_integer() || !body.contains("y") || !body["y"].is_number_integer()) {
      return send_error(res, 400, "x, y: expected the pixel's integer coordinates");
    }
    std::optional<Scene> scene = scene_from(text_of(body["scene"]), res);
    if (!scene) return;
    long long x = body["x"].get<long long>(), y = body["y"].get<long long>();
    if (x < 0 || y < 0 || x >= scene->width || y >= scene->height) {
      return send_error(res, 400, "x, y: the pixel lies outside the image");
    }
    std::optional<PixelExplanation> e = explain_pixel(*scene, int(x), int(y));
    if (!e) {
      res.set_content(text_of(json{{"hit", false}, {"background", color_json(scene->background)}}),
                      "application/json");
      return;
    }
    const LightingBreakdown& b = e->breakdown;
    json lights = json::array();
    for (const LightTerm& t : b.lights) {
      lights.push_back({{"light", t.light},
                        {"attenuation", t.attenuation},
                        {"spot", t.spot},
                        {"n_dot_l", t.n_dot_l},
                        {"ambient", color_json(t.ambient)},
                        {"diffuse", color_json(t.diffuse)},
                        {"specular", color_json(t.specular)}});
    }
    const char* shading = e->shading == ShadingMode::kFlat      ? "flat"
                          : e->shading == ShadingMode::kGouraud ? "gouraud"
                                                                : "phong";
    res.set_content(text_of(json{{"hit", true},
                         {"object", e->object},
                         {"shading", shading},
                         {"lit", e->lit},
                         {"back_face", e->back_face},
                         {"position", color_json(e->position)},
                         {"normal", color_json(e->normal)},
                         {"emission", color_json(b.emission)},
                         {"global_ambient", color_json(b.global_ambient)},
                         {"lights", lights},
                         {"unclamped", color_json(b.unclamped)},
                         {"result", color_json(b.result.primary)},
                         {"secondary", color_json(b.result.secondary)}}),
                    "application/json");
  }

  void presets(httplib::Response& res) const {
    json list = json::array();
    for (const MaterialPreset& p : material_presets()) {
      list.push_back({{"name", p.name}, {"description", p.description}, {"material", material_json(p.material)}});
    }
    res.set_content(text_of(list), "application/json");
  }

  // The built-in shapes the page offers, and the OBJ files beside the served scene.
  void shapes(httplib::Response& res) const {
    json objs = json::array();
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(base_dir_, ec)) {
      if (entry.is_regular_file(ec) && entry.path().extension() == ".obj") {
        objs.push_back(entry.path().filename().string());
      }
    }
    std::sort(objs.begin(), objs.end());
    res.set_content(text_of(json{{"shapes", {"teapot", "sphere", "torus", "cylinder", "cone", "cube", "wall"}},
                                 {"obj_files", objs}}),
                    "application/json");
  }

  void scene(httplib::Response& res) const { res.set_content(options_.scene_text, "application/json"); }

  // The figures beside the served scene (its folder's *.json but rows.json: the lecture's
  // figures for the default scene), each with its caption, and the row experiments of that
  // folder's rows.json, for the page's "lecture" menu.
  void figures(httplib::Response& res) const {
    json list = json::array();
    const std::vector<std::string> files = figure_files();
    for (const std::string& name : files) {
      json scene = json::parse(read_file(base_dir_ / name), nullptr, false);
      const std::string caption = scene.is_object() ? scene.value("caption", "") : "";
      list.push_back({{"file", name}, {"caption", caption}});
    }
    json rows = json::parse(read_file(base_dir_ / "rows.json"), nullptr, false);
    json out_rows = json::array();
    if (rows.is_array()) {
      for (const json& row : rows) {
        // Rows of scenes the page can open: the figures above.
        if (!row.is_object() || !row.contains("scene") || !row["scene"].is_string() ||
            std::find(files.begin(), files.end(), row["scene"].get<std::string>()) == files.end()) {
          continue;
        }
        out_rows.push_back(row);
      }
    }
    res.set_content(text_of(json{{"figures", list}, {"rows", out_rows}}), "application/json");
  }

  // One of those figures' scene file, by its name (nothing else of the folder).
  void figure(const std::string& name, httplib::Response& res) const {
    const std::vector<std::string> files = figure_files();
    if (std::find(files.begin(), files.end(), name) == files.end()) {
      return send_error(res, 404, "no figure \"" + name + "\" beside the served scene");
    }
    res.set_content(read_file(base_dir_ / name), "application/json");
  }

 private:
  std::vector<std::string> figure_files() const {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(base_dir_, ec)) {
      const std::string name = entry.path().filename().string();
      if (entry.is_regular_file(ec) && entry.path().extension() == ".json" && name != "rows.json") names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  static std::string read_file(const fs::path& path) { return read_text_file(path.string()).value_or(""); }

  LabOptions options_;
  std::unique_ptr<RenderQueue> queue_;
  fs::path base_dir_;
};

thread_local std::chrono::steady_clock::time_point Lab::request_start;

}  // namespace

std::shared_ptr<const void> install_lab(httplib::Server& server, const LabOptions& options) {
  auto lab = std::make_shared<const Lab>(options);
  const Lab* l = lab.get();
  // A thread per connection, from a pool large enough for a class: an idle keep-alive
  // connection or a slow client holds only its own thread (until the timeouts below close it);
  // renders are limited apart, by the queue.
  const int threads = std::max(options.connection_threads, 4);
  server.new_task_queue = [threads] { return new httplib::ThreadPool(std::size_t(threads)); };
  server.set_payload_max_length(options.max_body);
  server.set_read_timeout(5, 0);  // a client that sends nothing for 5 s is dropped
  server.set_write_timeout(10, 0);
  server.set_keep_alive_timeout(5);
  server.set_keep_alive_max_count(100);
  server.set_pre_routing_handler([](const httplib::Request&, httplib::Response&) {
    Lab::request_start = std::chrono::steady_clock::now();
    return httplib::Server::HandlerResponse::Unhandled;
  });
  for (const LabAsset& a : lab_assets()) {
    std::string path = a.name == "index.html" ? "/" : "/" + a.name;
    server.Get(path, [&a](const httplib::Request&, httplib::Response& res) {
      res.set_content(std::string(a.data), a.mime);
    });
  }
  server.Post("/api/render", [l](const httplib::Request& q, httplib::Response& r, const httplib::ContentReader& c) {
    l->queued(q, r, c, &Lab::render);
  });
  server.Post("/api/explain", [l](const httplib::Request& q, httplib::Response& r, const httplib::ContentReader& c) {
    l->queued(q, r, c, &Lab::explain_request);
  });
  server.Get("/api/presets", [l](const httplib::Request&, httplib::Response& r) { l->presets(r); });
  server.Get("/api/shapes", [l](const httplib::Request&, httplib::Response& r) { l->shapes(r); });
  server.Get("/api/scene", [l](const httplib::Request&, httplib::Response& r) { l->scene(r); });
  server.Get("/api/figures", [l](const httplib::Request&, httplib::Response& r) { l->figures(r); });
  server.Get(R"(/api/figure/([^/]+))", [l](const httplib::Request& q, httplib::Response& r) { l->figure(q.matches[1], r); });
  server.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
    send_error(res, 500, "internal error");
  });
  server.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if (res.body.empty()) {
      send_error(res, res.status, res.status == 413 ? "the request is too large" : "not found");
    }
  });
  return lab;
}

int run_lab_server(const LabOptions& options) {
  httplib::Server server;
  std::shared_ptr<const void> lab = install_lab(server, options);
  int port = options.port;
  if (port == 0) {
    port = server.bind_to_any_port(options.host);
  } else if (!server.bind_to_port(options.host, port)) {
    port = -1;
  }
  if (port < 0) {
    std::fprintf(stderr, "shadelab serve: cannot listen on %s:%d\n", options.host.c_str(), options.port);
    return 1;
  }
  std::printf("shadelab lab: open http://%s:%d/\n", options.host.c_str(), port);
  std::fflush(stdout);
  return server.listen_after_bind() ? 0 : 1;
}

}  // namespace shadelab::cli
