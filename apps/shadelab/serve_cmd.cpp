// shadelab serve: the lighting lab in the browser (docs/lab.md).
#include <filesystem>
#include <iostream>
#include <optional>
#include <utility>

#include "commands.hpp"
#include "lab_server.hpp"
#include "text_file.hpp"

namespace shadelab::cli {

namespace {

struct ServeArgs {
  std::string scene;
  std::string host = "127.0.0.1";
  int port = 8080;
  LabOptions limits;  // only the limits (max_*, connections, render workers)
};

// The default scene: the lecture's Lighting Controls panel (9 lights on a sphere).
std::string default_scene_path() {
  for (const char* p : {"scenes/lecture/18-lighting-controls.json"}) {
    if (std::filesystem::exists(p)) return p;
  }
  return "";
}

int run_serve(const ServeArgs& args) {
  LabOptions o = args.limits;
  o.host = args.host;
  o.port = args.port;
  o.scene_path = args.scene.empty() ? default_scene_path() : args.scene;
  if (o.scene_path.empty()) {
    std::cerr << "shadelab serve: no scene given and scenes/lecture/18-lighting-controls.json "
                 "is not here; name a scene file\n";
    return kExitBadInput;
  }
  std::optional<std::string> text = read_text_file(o.scene_path);
  if (!text) {
    std::cerr << o.scene_path << ": cannot open scene file\n";
    return kExitBadInput;
  }
  o.scene_text = std::move(*text);
  return run_lab_server(o);
}

}  // namespace

Action add_serve_command(CLI::App& app) {
  auto args = std::make_shared<ServeArgs>();
  CLI::App* cmd = app.add_subcommand("serve", "The lighting lab: the lecture's Lighting Controls panel in the browser");
  cmd->add_option("scene", args->scene,
                  "Scene to start from (default: the lecture's panel, scenes/lecture/18-lighting-controls.json)");
  cmd->add_option("--host", args->host,
                  "Address to listen on (default 127.0.0.1: this machine only; 0.0.0.0 serves every network)");
  cmd->add_option("--port", args->port, "Port (default 8080; 0 picks a free one)")->check(CLI::Range(0, 65535));
  cmd->add_option("--max-pixels", args->limits.max_pixels, "Limit per render: width x height x samples (default 1048576)")
      ->check(CLI::Range(1LL, 1LL << 28));
  cmd->add_option("--max-triangles", args->limits.max_triangles, "Limit per render: triangles (default 2000000)")
      ->check(CLI::Range(1LL, 20'000'000LL));
  cmd->add_option("--max-lights", args->limits.max_lights, "Limit per render: lights (default 64)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--max-render-seconds", args->limits.max_render_seconds,
                  "Limit per render: objects not started by then are left out and the request fails (default 10)")
      ->check(CLI::Range(0.001, 3600.0));
  cmd->add_option("--max-fragment-memory", args->limits.max_fragment_mib,
                  "Limit per render: exact transparency's fragment lists, MiB (default 256)")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 16));
  cmd->add_option("--max-body", args->limits.max_body, "Limit on a request's size in bytes (default 1048576)")
      ->check(CLI::Range(std::size_t(1024), std::size_t(1) << 30));
  cmd->add_option("--connections", args->limits.connection_threads,
                  "Connections served at once; more wait to be accepted (default 256)")
      ->check(CLI::Range(4, 4096));
  cmd->add_option("--max-request-seconds", args->limits.max_request_seconds,
                  "Limit on receiving a request's body, from its start (default 10)")
      ->check(CLI::Range(0.1, 3600.0));
  cmd->add_option("--render-workers", args->limits.render_workers,
                  "Renders run at once (default: the cores, at least 2)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--max-queued-renders", args->limits.max_queued_renders,
                  "Renders waiting or running; more are answered 503 with Retry-After (default 64)")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 16));
  cmd->add_option("--max-client-renders", args->limits.max_client_renders,
                  "Of those, from one client address (default 16)")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 16));
  cmd->footer("Example:\n  shadelab serve            then open http://127.0.0.1:8080/");
  return [args] { return run_serve(*args); };
}

}  // namespace shadelab::cli
