// The lab's HTTP API: the lab serves in-process on a loopback port, and each input becomes one
// request. The first byte picks the route (or, for a few values, sends the rest of the input
// verbatim as a raw HTTP request); the rest is the body. Every answer must be a well-formed
// HTTP response with a status the API documents: the server never crashes, hangs or stops
// answering.
#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <thread>

#include "lab_server.hpp"

namespace {

struct InProcessLab {
  httplib::Server server;
  std::shared_ptr<const void> lab;
  std::thread thread;
  int port = -1;

  InProcessLab() {
    shadelab::cli::LabOptions options;
    options.max_pixels = 64 * 64;  // small renders: many requests a second
    options.max_triangles = 20000;
    options.max_lights = 16;
    options.max_render_seconds = 2;
    options.max_body = 64 * 1024;
    options.scene_text = R"({"image": {"width": 16, "height": 12}})";
    options.connection_threads = 16;  // the fuzzer's requests come one at a time
    options.render_workers = 2;
    lab = shadelab::cli::install_lab(server, options);
    port = server.bind_to_any_port("127.0.0.1");
    thread = std::thread([this] { server.listen_after_bind(); });
    while (!server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ~InProcessLab() {
    server.stop();
    thread.join();
  }
};

// Sends `bytes` on a fresh connection, closes the sending side, and reads until the server
// closes (or a second passes).
void send_raw(int port, const std::string& bytes) {
  int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return;
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(std::uint16_t(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0) {
    std::size_t sent = 0;
    while (sent < bytes.size()) {
      ssize_t n = send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) break;
      sent += std::size_t(n);
    }
    shutdown(fd, SHUT_WR);
    timeval tv{1, 0};
    setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    char buf[4096];
    while (recv(fd, buf, sizeof buf, 0) > 0) {
    }
  }
  close(fd);
}

std::string percent_encoded(const std::string& s) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : s) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.') {
      out += char(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

bool documented(int status) {
  switch (status) {
    case 200: case 400: case 404: case 405: case 413: case 414: case 431: case 503: return true;
    default: return false;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static InProcessLab lab;
  if (lab.port <= 0) __builtin_trap();
  if (size == 0) return 0;
  std::string body(reinterpret_cast<const char*>(data) + 1, size - 1);
  httplib::Client client("127.0.0.1", lab.port);
  client.set_read_timeout(20, 0);
  if (data[0] % 8 >= 6) {
    // Raw bytes as a request: httplib's parser and the handlers behind it see anything.
    // Whatever it answers (or not), the server must still answer the next request.
    send_raw(lab.port, body);
    httplib::Result r = client.Get("/api/presets");
    if (!r || r->status != 200) __builtin_trap();
    return 0;
  }
  httplib::Result r = [&] {
    switch (data[0] % 8) {
      case 0: return client.Post("/api/render", body, "application/json");
      case 1: return client.Post("/api/render?shading=" + percent_encoded(body.substr(0, 16)), body,
                                 "application/json");
      case 2: return client.Post("/api/explain", body, "application/json");
      case 3: return client.Get("/api/presets");
      case 4: return client.Get("/api/shapes");
      default: return client.Get("/" + percent_encoded(body.substr(0, 64)));
    }
  }();
  if (!r) __builtin_trap();  // the server stopped answering
  if (!documented(r->status)) {
    std::fprintf(stderr, "fuzz_lab: status %d, body %s\n", r->status, r->body.c_str());
    __builtin_trap();
  }
  return 0;
}
