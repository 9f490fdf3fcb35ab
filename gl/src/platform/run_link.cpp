// The program's side of `shadelab run`'s frame socket (run_link.hpp): sends frames, waits for
// the answer. Blocking writes and reads on a socket inherited from the runner; a failed write
// or read closes the link for good.
#include "gl/src/platform/run_link.hpp"

#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <vector>

#include "gl/src/platform/surface.hpp"

namespace shadelab::gl::platform::run_link {
namespace {

struct Link {
  std::mutex mutex;  // frames of several threads are reported one at a time
  int fd = -1;
  bool capture = false;
  std::vector<std::uint8_t> pixels;
};

// Parsed once, at the first frame: the variables are the runner's, set before the program ran.
Link& link() {
  static Link* l = [] {
    auto* made = new Link;  // never freed: frames may be reported from exit handlers
    const char* fd = std::getenv(kSocketVariable);
    struct stat st {};
    if (fd && *fd && fstat(std::atoi(fd), &st) == 0 && S_ISSOCK(st.st_mode)) made->fd = std::atoi(fd);
    const char* capture = std::getenv(kCaptureVariable);
    made->capture = capture && std::strcmp(capture, "1") == 0;
    return made;
  }();
  return *l;
}

bool send_all(int fd, const void* data, std::size_t n) {
  const auto* p = static_cast<const char*>(data);
  while (n > 0) {
    ssize_t sent = send(fd, p, n, MSG_NOSIGNAL);
    if (sent < 0 && errno == EINTR) continue;
    if (sent <= 0) return false;
    p += sent, n -= std::size_t(sent);
  }
  return true;
}

// The runner's answer to a frame; 0 when the socket failed or closed.
char wait_answer(int fd) {
  char answer = 0;
  for (;;) {
    ssize_t got = recv(fd, &answer, 1, 0);
    if (got < 0 && errno == EINTR) continue;
    return got == 1 ? answer : 0;
  }
}

// The runner ends the program after this frame: its buffered output reaches its files and
// pipes first (the runner waits for the byte sent back), then the program waits to be ended.
void end_of_run(int fd) {
  std::fflush(nullptr);
  const char done = kGoOn;
  if (!send_all(fd, &done, 1)) return;
  while (wait_answer(fd) != 0) {
  }
}

}  // namespace

bool active() { return link().fd >= 0; }

void frame(const Surface& surface) {
  Link& l = link();
  std::lock_guard lock(l.mutex);
  if (l.fd < 0) return;
  FrameHeader h{{'S', 'L', 'F', '1'}, std::uint32_t(surface.width()), std::uint32_t(surface.height()), 0};
  if (l.capture) {
    surface.copy_rgba(l.pixels);
    h.pixel_bytes = std::uint32_t(l.pixels.size());
  }
  const bool sent = send_all(l.fd, &h, sizeof h) && (h.pixel_bytes == 0 || send_all(l.fd, l.pixels.data(), l.pixels.size()));
  const char answer = sent ? wait_answer(l.fd) : 0;
  if (answer == kLastFrame) end_of_run(l.fd);
  if (answer != kGoOn) l.fd = -1;
}

bool requested_size(int& width, int& height) {
  const char* size = std::getenv(kSizeVariable);
  return size && std::sscanf(size, "%dx%d", &width, &height) == 2 && width > 0 && height > 0;
}

}  // namespace shadelab::gl::platform::run_link
