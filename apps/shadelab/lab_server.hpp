// The lighting lab's HTTP server (shadelab serve): the page's embedded assets and the JSON API
// of docs/lab.md, rendering with the library. One server per process; connections are served
// by a large pool of threads, renders by a few workers through a fair, bounded queue.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

namespace httplib {
class Server;
}

namespace shadelab::cli {

struct LabOptions {
  std::string host = "127.0.0.1";
  int port = 8080;           ///< 0: any free port
  std::string scene_path;    ///< the served scene (its folder's OBJ files are offered)
  std::string scene_text;    ///< its JSON
  // Limits against hostile requests.
  std::size_t max_body = 1u << 20;         ///< bytes of a request body
  long long max_pixels = 1024LL * 1024LL;  ///< width x height x samples of one render
  long long max_triangles = 2'000'000;
  int max_lights = 64;
  double max_render_seconds = 10.0;  ///< objects not started by then are left out: answered 503
  std::size_t max_fragment_mib = 256;  ///< exact transparency's fragment lists; over it: 503
  // Serving a class: connections, request time and the render queue (render_queue.hpp).
  int connection_threads = 256;  ///< connections served at once (more wait to be accepted)
  double max_request_seconds = 10.0;  ///< to receive a request's body, from its start
  int render_workers = 0;             ///< renders run at once; 0: the cores (at least 2)
  std::size_t max_queued_renders = 64;  ///< waiting or running; more: 503 with Retry-After
  std::size_t max_client_renders = 16;  ///< of those, from one client address
};

/// Sets up `server` as the lab: its routes, worker threads and request limits. The returned
/// handle holds the lab's state and must outlive the server's serving. For run_lab_server and
/// for tests and fuzzers that serve the lab in-process.
std::shared_ptr<const void> install_lab(httplib::Server& server, const LabOptions& options);

/// Serves until the process is stopped; prints the address once listening (to stdout, so
/// that scripts can read the port chosen for port 0). Returns the exit status.
int run_lab_server(const LabOptions& options);

}  // namespace shadelab::cli
