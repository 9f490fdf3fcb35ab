// `shadelab run`'s processes (run_process.hpp): Xvfb started with -displayfd and stopped with
// SIGTERM; the program forked into its own process group, exec failures reported through a
// close-on-exec pipe, frames read from a socket pair, the group killed at the end (SIGTERM,
// then SIGKILL after a grace period), interrupts of shadelab itself forwarded as an end.
#include "run_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

#include "gl/src/platform/run_link.hpp"

namespace shadelab::cli::run {
namespace {

using Clock = std::chrono::steady_clock;

volatile sig_atomic_t g_interrupted = 0;
void on_interrupt(int) { g_interrupted = 1; }

// SIGINT and SIGTERM end the program and Xvfb cleanly instead of killing shadelab alone.
void catch_interrupts() {
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  signal(SIGPIPE, SIG_IGN);
}

// Waits up to `seconds` for `pid` to end; true (and its status) if it did.
bool wait_for(pid_t pid, double seconds, int& status) {
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  for (;;) {
    pid_t r = waitpid(pid, &status, WNOHANG);
    if (r == pid || (r < 0 && errno != EINTR)) return true;
    if (Clock::now() >= end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

// The program's last frame: it flushes its buffered output (what it printed before the frame
// reaches its files and pipes), then says so; waited for a second at most.
void let_output_out(int socket_fd) {
  const char last = gl::platform::run_link::kLastFrame;
  if (write(socket_fd, &last, 1) != 1) return;
  pollfd p{socket_fd, POLLIN, 0};
  char done = 0;
  if (poll(&p, 1, 1000) > 0) [[maybe_unused]] const ssize_t got = read(socket_fd, &done, 1);
}

// Ends a process group: SIGTERM, then SIGKILL if it lingers; reaps `leader` if still there.
void end_group(pid_t leader, bool leader_reaped) {
  kill(-leader, SIGTERM);
  int status = 0;
  if (!leader_reaped && !wait_for(leader, 2.0, status)) {
    kill(-leader, SIGKILL);
    waitpid(leader, &status, 0);
  }
  kill(-leader, SIGKILL);  // anything the program left running in its group
}

bool read_all(int fd, void* data, std::size_t n) {
  auto* p = static_cast<char*>(data);
  while (n > 0) {
    ssize_t got = read(fd, p, n);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    p += got, n -= std::size_t(got);
  }
  return true;
}

bool read_frame(int fd, Frame& frame) {
  gl::platform::run_link::FrameHeader h{};
  if (!read_all(fd, &h, sizeof h) || std::memcmp(h.magic, "SLF1", 4) != 0) return false;
  if (h.width > 65536 || h.height > 65536) return false;
  frame.width = int(h.width), frame.height = int(h.height);
  if (h.pixel_bytes != 0 && std::uint64_t(h.pixel_bytes) != std::uint64_t(h.width) * h.height * 4) return false;
  frame.rgba.resize(h.pixel_bytes);
  return h.pixel_bytes == 0 || read_all(fd, frame.rgba.data(), frame.rgba.size());
}

std::vector<char*> c_strings(const std::vector<std::string>& v) {
  std::vector<char*> out;
  for (const std::string& s : v) out.push_back(const_cast<char*>(s.c_str()));
  out.push_back(nullptr);
  return out;
}

// The child's side of the fork: its own process group, the environment, exec. An exec failure
// is written to `status_fd` (close-on-exec: a successful exec closes it silently).
[[noreturn]] void exec_child(const ChildOptions& o, int socket_fd, int status_fd) {
  setpgid(0, 0);
  for (const std::string& e : o.environment) putenv(const_cast<char*>(e.c_str()));
  std::string fd_variable;
  if (socket_fd >= 0) {
    fd_variable = std::string(gl::platform::run_link::kSocketVariable) + "=" + std::to_string(socket_fd);
    putenv(fd_variable.data());
  }
  struct sigaction sa {};
  sa.sa_handler = SIG_DFL;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGPIPE, &sa, nullptr);
  std::vector<char*> argv = c_strings(o.command);
  execvp(argv[0], argv.data());
  int error = errno;
  (void)!write(status_fd, &error, sizeof error);
  _exit(127);
}

}  // namespace

Xvfb::~Xvfb() { stop(); }

bool Xvfb::start(int width, int height, double timeout_seconds, std::string& error) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    error = std::string("pipe: ") + std::strerror(errno);
    return false;
  }
  const std::string screen = std::to_string(width) + "x" + std::to_string(height) + "x24";
  pid_ = fork();
  if (pid_ == 0) {
    setpgid(0, 0);  // a terminal's Ctrl-C reaches shadelab, which stops the server itself
    int null = open("/dev/null", O_RDWR);
    dup2(null, 0), dup2(null, 1), dup2(null, 2);
    int fd = dup(fds[1]);  // without close-on-exec: Xvfb writes its display number to it
    std::string fd_text = std::to_string(fd);
    execlp("Xvfb", "Xvfb", "-displayfd", fd_text.c_str(), "-screen", "0", screen.c_str(), "-nolisten", "tcp",
           "-noreset", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  if (pid_ < 0) {
    close(fds[0]);
    error = std::string("fork: ") + std::strerror(errno);
    return false;
  }
  std::string number;
  const auto end = Clock::now() + std::chrono::duration<double>(timeout_seconds);
  for (char c = 0; number.empty() || c != '\n';) {
    pollfd p{fds[0], POLLIN, 0};
    const int left = int(std::chrono::duration_cast<std::chrono::milliseconds>(end - Clock::now()).count());
    if (left <= 0 || poll(&p, 1, left) <= 0 || read(fds[0], &c, 1) != 1) break;
    if (c >= '0' && c <= '9') number += c;
    else if (c == '\n' && !number.empty()) display_ = ":" + number;
  }
  close(fds[0]);
  if (display_.empty()) {
    int status = 0;
    bool ended = wait_for(pid_, 0.2, status);
    error = ended && WIFEXITED(status) && WEXITSTATUS(status) == 127
                ? "Xvfb not found (Debian package xvfb)"
                : "Xvfb did not start (no display number within the time allowed)";
    if (!ended) stop();
    pid_ = -1;
    return false;
  }
  return true;
}

void Xvfb::stop() {
  if (pid_ <= 0) return;
  kill(pid_, SIGTERM);
  int status = 0;
  if (!wait_for(pid_, 5.0, status)) {
    kill(pid_, SIGKILL);
    waitpid(pid_, &status, 0);
  }
  pid_ = -1;
}

ChildResult run_child(const ChildOptions& o) {
  ChildResult result;
  catch_interrupts();
  int sockets[2] = {-1, -1};
  if (o.frame_socket && socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0) {
    result.status = errno;
    return result;
  }
  int status_pipe[2];
  if (pipe2(status_pipe, O_CLOEXEC) != 0) {
    result.status = errno;
    return result;
  }
  pid_t pid = fork();
  if (pid == 0) {
    int child_socket = -1;
    if (o.frame_socket) child_socket = dup(sockets[1]);  // without close-on-exec: it passes exec
    exec_child(o, child_socket, status_pipe[1]);
  }
  close(status_pipe[1]);
  if (o.frame_socket) close(sockets[1]);
  if (pid < 0) {
    result.status = errno;
    close(status_pipe[0]);
    return result;
  }
  setpgid(pid, pid);  // as the child does: whichever runs first
  int exec_error = 0;
  const bool exec_failed = read_all(status_pipe[0], &exec_error, sizeof exec_error);
  close(status_pipe[0]);
  if (exec_failed) {
    int status = 0;
    waitpid(pid, &status, 0);
    if (o.frame_socket) close(sockets[0]);
    result.status = exec_error;
    return result;
  }
  const bool has_deadline = o.timeout_seconds > 0;
  const auto deadline = Clock::now() + std::chrono::duration<double>(has_deadline ? o.timeout_seconds : 0);
  int socket_fd = o.frame_socket ? sockets[0] : -1;
  Frame frame;
  for (;;) {
    int status = 0;
    pid_t r = waitpid(pid, &status, WNOHANG);
    if (r == pid) {
      result.end = WIFSIGNALED(status) ? ChildResult::End::kSignaled : ChildResult::End::kExited;
      result.status = WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status);
      end_group(pid, true);
      break;
    }
    if (g_interrupted || (has_deadline && Clock::now() >= deadline)) {
      result.end = g_interrupted ? ChildResult::End::kInterrupted : ChildResult::End::kTimedOut;
      end_group(pid, false);
      break;
    }
    pollfd p{socket_fd, POLLIN, 0};
    if (socket_fd < 0 || poll(&p, 1, 20) <= 0) {
      if (socket_fd < 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    if (!read_frame(socket_fd, frame)) {  // the program closed its side (or sent garbage)
      close(socket_fd);
      socket_fd = -1;
      continue;
    }
    ++result.frames;
    const bool go_on = !o.on_frame || o.on_frame(result.frames, frame);
    if (!go_on || (o.stop_after_frames > 0 && result.frames >= o.stop_after_frames)) {
      result.end = go_on ? ChildResult::End::kFramesDone : ChildResult::End::kFrameError;
      if (go_on) let_output_out(socket_fd);
      end_group(pid, false);
      break;
    }
    const char answer = gl::platform::run_link::kGoOn;
    if (write(socket_fd, &answer, 1) != 1) close(socket_fd), socket_fd = -1;
  }
  if (socket_fd >= 0) close(socket_fd);
  return result;
}

}  // namespace shadelab::cli::run
