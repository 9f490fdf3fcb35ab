// The lighting lab's HTTP server (shadelab serve): the page's embedded assets and the JSON API
// of docs/lab.md, rendering with the library. One server per process; requests are served by
// a pool of threads, each render on its own.
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
};

/// Sets up `server` as the lab: its routes, worker threads and request limits. The returned
/// handle holds the lab's state and must outlive the server's serving. For run_lab_server and
/// for tests and fuzzers that serve the lab in-process.
std::shared_ptr<const void> install_lab(httplib::Server& server, const LabOptions& options);

/// Serves until the process is stopped; prints the address once listening (to stdout, so
/// that scripts can read the port chosen for port 0). Returns the exit status.
int run_lab_server(const LabOptions& options);

}  // namespace shadelab::cli
