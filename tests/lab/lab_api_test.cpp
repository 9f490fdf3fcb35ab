// The lab's JSON API over real HTTP on loopback: `shadelab serve --port 0` runs as a child
// process, and these tests talk to it as the page does (docs/lab.md).
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "shadelab/image.hpp"
#include "support/sanitizers.hpp"
#include "support/test_support.hpp"

namespace shadelab {
namespace {

using json = nlohmann::json;

std::string read_text(const std::string& path) {
  std::ifstream in(std::string(SHADELAB_SOURCE_DIR) + "/" + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The server as a child process; its first line of output names the port.
class LabServer {
 public:
  explicit LabServer(std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {SHADELAB_CLI, "serve", "--port", "0"};
    args.insert(args.end(), extra.begin(), extra.end());
    int fds[2];
    if (pipe(fds) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      dup2(fds[1], STDOUT_FILENO);
      close(fds[0]);
      close(fds[1]);
      if (chdir(SHADELAB_SOURCE_DIR) != 0) _exit(127);
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(SHADELAB_CLI, argv.data());
      _exit(127);
    }
    close(fds[1]);
    FILE* out = fdopen(fds[0], "r");
    char line[256] = {0};
    if (out && std::fgets(line, sizeof line, out)) {
      std::string s(line);
      std::size_t colon = s.rfind(':');
      if (colon != std::string::npos) port_ = std::atoi(s.c_str() + colon + 1);
    }
    out_ = out;
  }
  ~LabServer() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
    if (out_) std::fclose(out_);
  }
  int port() const { return port_; }
  httplib::Client client() const {
    httplib::Client c("127.0.0.1", port_);
    c.set_read_timeout(60, 0);
    return c;
  }

 private:
  pid_t pid_ = -1;
  int port_ = 0;
  FILE* out_ = nullptr;
};

LabServer& server() {
  static LabServer s;
  return s;
}

Image decode(const std::string& png) {
  std::string path = test::output_dir() + "/lab_api_render.png";
  std::ofstream(path, std::ios::binary) << png;
  Image img;
  std::string error;
  EXPECT_TRUE(read_image(path, img, &error)) << error;
  return img;
}

const char* kPhongScene = R"({
  "image": {"width": 120, "height": 90, "background": [0, 0, 0]},
  "camera": {"eye": [0, 0, 6], "target": [0, 0, 0], "fovy": 30},
  "lights": [{"position": [2, 2, 3, 1], "diffuse": [1, 0.9, 0.7], "specular": [1, 1, 1]},
             {"position": [-1, 0, 1, 0], "diffuse": [0.2, 0.3, 0.8], "specular": [0, 0, 0]}],
  "objects": [{"name": "ball", "shape": {"type": "sphere", "radius": 1.3, "slices": 64, "stacks": 32},
               "material": {"diffuse": [0.7, 0.6, 0.5], "specular": [0.8, 0.8, 0.8], "shininess": 20},
               "shading": "phong"}]
})";

TEST(LabApi, ServesThePageAndTheLecturesPanel) {
  ASSERT_GT(server().port(), 0);
  auto c = server().client();
  auto page = c.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("Lighting Controls"), std::string::npos);
  auto js = c.Get("/lab.js");
  ASSERT_TRUE(js);
  EXPECT_EQ(js->status, 200);
  EXPECT_EQ(js->get_header_value("Content-Type"), "text/javascript; charset=utf-8");
  auto scene = c.Get("/api/scene");
  ASSERT_TRUE(scene);
  json s = json::parse(scene->body);
  EXPECT_EQ(s["lights"].size(), 9u);  // the lecture's nine lights
  auto presets = c.Get("/api/presets");
  ASSERT_TRUE(presets);
  json p = json::parse(presets->body);
  ASSERT_GT(p.size(), 20u);
  EXPECT_TRUE(p[0].contains("material"));
  auto shapes = c.Get("/api/shapes");
  ASSERT_TRUE(shapes);
  EXPECT_NE(shapes->body.find("teapot"), std::string::npos);
  // Only the embedded files are served: nothing from the disk.
  auto outside = c.Get("/../../CMakeLists.txt");
  ASSERT_TRUE(outside);
  EXPECT_EQ(outside->status, 404);
}

TEST(LabApi, RendersAScene) {
  auto c = server().client();
  auto r = c.Post("/api/render", read_text("scenes/lecture/18-lighting-controls.json"), "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
  EXPECT_FALSE(r->get_header_value("X-Render-Ms").empty());
  Image img = decode(r->body);
  EXPECT_EQ(img.width, 480);
  EXPECT_EQ(img.height, 480);
  const std::uint8_t* centre = img.pixel(240, 240);
  EXPECT_GT(centre[0] + centre[1] + centre[2], 30);  // the lit sphere, not the background
  auto flat = c.Post("/api/render?shading=flat", kPhongScene, "application/json");
  auto phong = c.Post("/api/render", kPhongScene, "application/json");
  ASSERT_TRUE(flat && phong);
  EXPECT_EQ(flat->status, 200);
  EXPECT_NE(flat->body, phong->body);  // the shading override changes the picture
}

// The figures beside the served scene (the lecture's, for the default scene) with their
// captions, the rows that open them, and each figure's scene; nothing else of the folder.
TEST(LabApi, ListsAndServesTheLecturesFigures) {
  auto c = server().client();
  auto r = c.Get("/api/figures");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  json list = json::parse(r->body);
  ASSERT_GE(list["figures"].size(), 18u);
  bool spot = false;
  for (const json& f : list["figures"]) {
    EXPECT_NE(f["file"], "rows.json");
    if (f["file"] == "10-spot-cutoff.json") spot = f["caption"].get<std::string>().rfind("Figure 10", 0) == 0;
  }
  EXPECT_TRUE(spot);
  ASSERT_GE(list["rows"].size(), 8u);
  for (const json& row : list["rows"]) EXPECT_NE(row["scene"].get<std::string>().find(".json"), std::string::npos);
  auto figure = c.Get("/api/figure/10-spot-cutoff.json");
  ASSERT_TRUE(figure);
  EXPECT_EQ(figure->status, 200);
  EXPECT_EQ(json::parse(figure->body)["lights"].size(), 1u);
  for (const char* bad : {"/api/figure/rows.json", "/api/figure/..%2Fteapot.json", "/api/figure/nothing.json"}) {
    auto no = c.Get(bad);
    ASSERT_TRUE(no);
    EXPECT_EQ(no->status, 404) << bad;
  }
}

// The explained parts add up, and on a Phong object they are the rendered pixel.
TEST(LabApi, ExplainedPixelsSumToTheRenderedColour) {
  auto c = server().client();
  auto r = c.Post("/api/render", kPhongScene, "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  Image img = decode(r->body);
  int hits = 0;
  for (int y = 5; y < 90; y += 12) {
    for (int x = 5; x < 120; x += 12) {
      json q = {{"scene", json::parse(kPhongScene)}, {"x", x}, {"y", y}};
      auto e = c.Post("/api/explain", q.dump(), "application/json");
      ASSERT_TRUE(e);
      ASSERT_EQ(e->status, 200) << e->body;
      json b = json::parse(e->body);
      if (!b["hit"].get<bool>()) continue;
      ++hits;
      for (int k = 0; k < 3; ++k) {
        double sum = b["emission"][k].get<double>() + b["global_ambient"][k].get<double>();
        for (const json& t : b["lights"]) {
          sum += t["ambient"][k].get<double>() + t["diffuse"][k].get<double>() + t["specular"][k].get<double>();
        }
        EXPECT_NEAR(sum, b["unclamped"][k].get<double>(), 1e-4);
        double clamped = std::min(std::max(sum, 0.0), 1.0);
        EXPECT_NEAR(std::lround(clamped * 255.0), img.pixel(x, y)[k], 2) << x << "," << y << " channel " << k;
      }
    }
  }
  EXPECT_GT(hits, 15);
}

TEST(LabApi, BadInputGets400WithTheCommandLinesDiagnostics) {
  auto c = server().client();
  auto error_of = [&](const std::string& path, const std::string& body) {
    auto r = c.Post(path, body, "application/json");
    EXPECT_TRUE(r);
    if (!r) return json();
    EXPECT_EQ(r->status, 400) << body;
    return json::parse(r->body, nullptr, false);
  };
  json e = error_of("/api/render", R"({"lights": [{"spot": {"cutoff": 120}}]})");
  EXPECT_EQ(e["errors"][0]["path"], "lights[0].spot.cutoff");
  EXPECT_EQ(e["errors"][0]["message"], "120 is out of range (0..90, or 180)");
  EXPECT_EQ(e["errors"][0]["line"], 1);
  e = error_of("/api/render", "{\"lights\": [\n  {\"positon\": [1, 1, 1, 0]}]}");
  EXPECT_EQ(e["errors"][0]["path"], "lights[0]");
  EXPECT_NE(e["errors"][0]["message"].get<std::string>().find("did you mean \"position\""), std::string::npos);
  e = error_of("/api/render", "{\"image\": {\"width\": 4000, \"height\": 4000}}");  // over the lab's pixel limit
  EXPECT_NE(e["errors"][0]["message"].get<std::string>().find("limit"), std::string::npos);
  e = error_of("/api/render", "{\"image\": ");  // truncated JSON
  EXPECT_EQ(e["errors"][0]["line"], 1);
  // Files only from the served scene's folder.
  e = error_of("/api/render", R"({"objects": [{"shape": {"type": "mesh", "file": "../../../../etc/passwd"}}]})");
  EXPECT_EQ(e["errors"][0]["path"], "objects[0].shape.file");
  EXPECT_NE(e["errors"][0]["message"].get<std::string>().find("outside the scene's folder"), std::string::npos);
  e = error_of("/api/render?shading=cel", kPhongScene);
  EXPECT_NE(e["error"].get<std::string>().find("shading"), std::string::npos);
  // Bytes that are not UTF-8, quoted back in the message (found by fuzz_lab: it was a 500).
  e = error_of("/api/render?shading=%A0lieht", kPhongScene);
  EXPECT_NE(e["error"].get<std::string>().find("lieht"), std::string::npos);
  error_of("/api/explain", "[1, 2]");
  error_of("/api/explain", json{{"scene", json::parse(kPhongScene)}, {"x", 1}}.dump());
  error_of("/api/explain", json{{"scene", json::parse(kPhongScene)}, {"x", 500}, {"y", 1}}.dump());
  error_of("/api/explain", json{{"scene", "teapot"}, {"x", 1}, {"y", 1}}.dump());
  // A body over the limit is refused before it is read whole.
  auto big = c.Post("/api/render", std::string(2u << 20, ' '), "application/json");
  ASSERT_TRUE(big);
  EXPECT_EQ(big->status, 413);
  auto missing = c.Get("/api/nothing");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
}

// A render over the time limit is refused as a whole (objects not started are not drawn).
TEST(LabApi, ARenderOverTheTimeLimitIsAnswered503) {
  LabServer strict({"--max-render-seconds", "0.001"});
  ASSERT_GT(strict.port(), 0);
  json scene = json::parse(kPhongScene);
  scene["objects"][0]["shape"]["slices"] = 512;  // half a million triangles each
  scene["objects"][0]["shape"]["stacks"] = 512;
  scene["objects"].push_back(scene["objects"][0]);
  scene["objects"][1]["name"] = "second";
  auto c = strict.client();
  auto r = c.Post("/api/render", scene.dump(), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 503);
  EXPECT_NE(r->body.find("limit"), std::string::npos) << r->body;
}

// Exact transparency's fragment lists have a memory limit per render: over it, 503.
TEST(LabApi, ExactTransparencyOverTheFragmentMemoryLimitIsAnswered503) {
  LabServer strict({"--max-fragment-memory", "1"});
  ASSERT_GT(strict.port(), 0);
  json scene = json::parse(kPhongScene);
  scene["transparency"] = "exact";
  scene["objects"][0]["blend"] = "alpha";
  scene["objects"][0]["material"]["diffuse"] = {0.7, 0.6, 0.5, 0.5};
  auto c = strict.client();
  auto r = c.Post("/api/render", scene.dump(), "application/json");  // 120 x 90: fits in 1 MiB
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  scene["image"] = {{"width", 1000}, {"height", 1000}};  // the lists alone need 24 MB
  r = c.Post("/api/render", scene.dump(), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 503);
  EXPECT_NE(r->body.find("exact transparency needs more than the lab's limit of 1 MiB"), std::string::npos)
      << r->body;
}

// Many clients at once all get their pictures, and a small render is not stuck behind a big
// one: it is answered while the big one is still being drawn.
TEST(LabApi, ConcurrentRequestsAreServedSideBySide) {
  std::string big = json::parse(kPhongScene).dump();
  json heavy = json::parse(kPhongScene);
  heavy["image"] = {{"width", 1000}, {"height", 1000}};
  heavy["objects"][0]["shape"]["slices"] = 1024;
  heavy["objects"][0]["shape"]["stacks"] = 512;
  std::atomic<int> ok{0}, failed{0};
  std::vector<std::thread> clients;
  for (int t = 0; t < 6; ++t) {
    clients.emplace_back([&, t] {
      auto c = server().client();
      for (int i = 0; i < 4; ++i) {
        auto r = c.Post("/api/render", t == 0 ? heavy.dump() : big, "application/json");
        (r && r->status == 200 ? ok : failed)++;
      }
    });
  }
  for (auto& t : clients) t.join();
  EXPECT_EQ(ok.load(), 24);
  EXPECT_EQ(failed.load(), 0);

  heavy["image"] = {{"width", 1024}, {"height", 1024}, {"samples", 1}};
  heavy["objects"][0]["shape"]["slices"] = 1600;  // 1.6 million triangles, under the limit
  heavy["objects"][0]["shape"]["stacks"] = 500;
  std::atomic<bool> heavy_done{false};
  std::thread slow([&] {
    auto c = server().client();
    auto r = c.Post("/api/render", heavy.dump(), "application/json");
    EXPECT_TRUE(r && r->status == 200) << (r ? r->body : "no answer");
    heavy_done = true;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // let the big one start first
  auto c = server().client();
  auto small = c.Post("/api/render", big, "application/json");
  bool answered_first = !heavy_done.load();
  slow.join();
  ASSERT_TRUE(small);
  EXPECT_EQ(small->status, 200);
  EXPECT_TRUE(answered_first);
}

// A raw connection to the lab on loopback (-1 on failure).
int connect_lab(int port) {
  int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return -1;
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(std::uint16_t(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

bool send_text(int fd, const std::string& s) {
  return send(fd, s.data(), s.size(), MSG_NOSIGNAL) == ssize_t(s.size());
}

// Latency bounds of the load test: generous, and ten times more in a sanitized build.
double latency_scale() {
  return test::kAddressSanitizer || test::kThreadSanitizer ? 10.0 : 1.0;
}

// A class on one lab: 200 connections at once, of which 32 idle (connected, nothing sent),
// 32 trickling a render request's body a byte at a time, and 136 keep-alive connections that
// made a request and wait; meanwhile the page is answered within 1 s and a small render within
// 2 s. (A pool of 8 threads, each held by a connection that does nothing, took 5-60 s.)
TEST(LabApi, AClassOfConnectionsDoesNotHoldUpThePageOrASmallRender) {
  const int port = server().port();
  ASSERT_GT(port, 0);
  // The connections arrive over about half a second, as a class's browsers do (a burst of
  // hundreds within microseconds would overflow the listening socket's accept queue).
  auto pace = [] { std::this_thread::sleep_for(std::chrono::milliseconds(2)); };
  std::vector<int> fds;
  for (int i = 0; i < 32; ++i) fds.push_back(connect_lab(port)), pace();
  std::vector<int> tricklers;
  for (int i = 0; i < 32; ++i) {
    pace();
    int fd = connect_lab(port);
    send_text(fd, "POST /api/render HTTP/1.1\r\nHost: lab\r\nContent-Type: application/json\r\n"
                  "Content-Length: 100000\r\n\r\n{");
    tricklers.push_back(fd);
  }
  std::atomic<bool> stop{false};
  std::thread trickle([&] {
    while (!stop) {
      for (int fd : tricklers) send_text(fd, " ");
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  for (int i = 0; i < 136; ++i) {
    pace();
    int fd = connect_lab(port);
    send_text(fd, "GET /api/presets HTTP/1.1\r\nHost: lab\r\n\r\n");
    fds.push_back(fd);
  }
  for (int fd : fds) EXPECT_GE(fd, 0);
  for (int fd : tricklers) EXPECT_GE(fd, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));

  auto c = server().client();
  auto t0 = std::chrono::steady_clock::now();
  auto page = c.Get("/");
  const double page_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_LT(page_s, 1.0 * latency_scale()) << "the page took " << page_s << " s";

  json small = json::parse(kPhongScene);
  small["image"] = {{"width", 32}, {"height", 24}};
  t0 = std::chrono::steady_clock::now();
  auto render = c.Post("/api/render", small.dump(), "application/json");
  const double render_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(render);
  EXPECT_EQ(render->status, 200);
  EXPECT_LT(render_s, 2.0 * latency_scale()) << "a small render took " << render_s << " s";
  std::printf("lab load: 200 connections open; the page in %.4f s, a small render in %.4f s\n", page_s, render_s);

  stop = true;
  trickle.join();
  for (int fd : fds) close(fd);
  for (int fd : tricklers) close(fd);
}

// A body trickled for longer than the request time limit is answered 408 at the limit, so
// that the client's thread is not held for as long as the client likes.
TEST(LabApi, ABodyTrickledPastTheRequestTimeLimitIsAnswered408) {
  LabServer lab({"--max-request-seconds", "1"});
  ASSERT_GT(lab.port(), 0);
  int fd = connect_lab(lab.port());
  ASSERT_GE(fd, 0);
  send_text(fd, "POST /api/render HTTP/1.1\r\nHost: lab\r\nContent-Length: 1000\r\n\r\n{");
  const auto t0 = std::chrono::steady_clock::now();
  std::string answer;
  while (answer.find("\r\n") == std::string::npos && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(20)) {
    send_text(fd, " ");
    char b[512];
    ssize_t n = recv(fd, b, sizeof b, MSG_DONTWAIT);
    if (n > 0) answer.append(b, std::size_t(n));
    if (n == 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  close(fd);
  EXPECT_EQ(answer.rfind("HTTP/1.1 408", 0), 0u) << answer;
  EXPECT_LT(s, 1.0 + 5.0 * latency_scale()) << "the trickled request was kept " << s << " s";
}

// More renders than the queue holds: the ones over it are answered 503 with Retry-After at
// once, before the renders that were queued are done; the others render. (Timed against the
// queued renders, not a clock: sanitized builds on a loaded machine are slow at both.)
TEST(LabApi, RendersOverTheQueuesBoundAre503WithRetryAfter) {
  LabServer lab({"--render-workers", "1", "--max-queued-renders", "2", "--max-client-renders", "2"});
  ASSERT_GT(lab.port(), 0);
  json medium = json::parse(kPhongScene);
  medium["image"] = {{"width", 400}, {"height", 300}};
  medium["objects"][0]["shape"]["slices"] = 512;
  medium["objects"][0]["shape"]["stacks"] = 256;
  const std::string body = medium.dump();
  struct Answer {
    int status = 0;  // 0: no answer
    std::string retry_after, error;
    double seconds = 0;
  };
  std::vector<Answer> answers(6);
  std::vector<std::thread> clients;
  for (Answer& a : answers) {
    clients.emplace_back([&lab, &body, &a] {
      auto c = lab.client();
      auto t0 = std::chrono::steady_clock::now();
      auto r = c.Post("/api/render", body, "application/json");
      a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (!r) {
        a.error = httplib::to_string(r.error());
        return;
      }
      a.status = r->status;
      a.retry_after = r->get_header_value("Retry-After");
      if (r->status != 200) a.error = r->body;
    });
  }
  for (std::thread& t : clients) t.join();
  int ok = 0, busy = 0, other = 0;
  double last_ok = 0, last_busy = 0;
  std::string all;
  for (const Answer& a : answers) {
    all += std::to_string(a.status) + " in " + std::to_string(a.seconds) + " s" +
           (a.retry_after.empty() ? "" : ", Retry-After " + a.retry_after) + (a.error.empty() ? "" : ": " + a.error) + "\n";
    if (a.status == 200) {
      ++ok;
      last_ok = std::max(last_ok, a.seconds);
    } else if (a.status == 503 && a.retry_after == "1") {
      ++busy;
      last_busy = std::max(last_busy, a.seconds);
    } else {
      ++other;
    }
  }
  EXPECT_GE(ok, 2) << all;
  EXPECT_GE(busy, 1) << all;
  EXPECT_EQ(other, 0) << all;
  EXPECT_LT(last_busy, last_ok) << "a refusal waited for the queued renders:\n" << all;
}

}  // namespace
}  // namespace shadelab
