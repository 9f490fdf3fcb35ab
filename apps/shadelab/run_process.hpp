// Process control for `shadelab run` (run_cmd.cpp): a private Xvfb on a free display, the GL
// program in its own process group with the frame socket of gl/src/platform/run_link.hpp,
// frames received (and written as PNG), a deadline, and an end that leaves no process behind.
// POSIX only; prints nothing itself: results and errors are returned to the command.
#pragma once

#include <sys/types.h>

#include <functional>
#include <string>
#include <vector>

namespace shadelab::cli::run {

/// A private X server (Xvfb -displayfd): started on the first free display, stopped by the
/// destructor.
class Xvfb {
 public:
  Xvfb() = default;
  ~Xvfb();
  Xvfb(const Xvfb&) = delete;
  Xvfb& operator=(const Xvfb&) = delete;
  /// Starts `Xvfb` (found on PATH) with a screen of width x height x 24; false with `error`.
  bool start(int width, int height, double timeout_seconds, std::string& error);
  /// ":N", for DISPLAY.
  const std::string& display() const { return display_; }
  void stop();

 private:
  pid_t pid_ = -1;
  std::string display_;
};

struct Frame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  ///< rows from the top; empty when not captured
};

struct ChildOptions {
  std::vector<std::string> command;            ///< program and its arguments
  std::vector<std::string> environment;        ///< NAME=VALUE entries added to ours
  bool frame_socket = false;                   ///< hand the program run_link's socket
  int stop_after_frames = 0;                   ///< 0: never
  double timeout_seconds = 0;                  ///< 0: none
  std::function<bool(int, const Frame&)> on_frame;  ///< frame number from 1; false stops it
};

struct ChildResult {
  enum class End { kExited, kSignaled, kFramesDone, kTimedOut, kNotStarted, kInterrupted, kFrameError };
  End end = End::kNotStarted;
  int status = 0;   ///< exit status (kExited), signal (kSignaled), errno (kNotStarted)
  int frames = 0;   ///< frames received
};

/// Runs the program to its end (or to the frame count, the deadline, an interrupt of this
/// process); its whole process group is killed before returning.
ChildResult run_child(const ChildOptions& options);

}  // namespace shadelab::cli::run
