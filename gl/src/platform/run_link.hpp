// The link between a GL program's window-system layer and `shadelab run` (apps/shadelab/
// run_cmd.cpp), which started the program: every frame shown (a swap, or a flush of a
// single-buffered window) is reported over the socket the runner handed down, with its pixels
// when the runner captures, and the program waits for the runner's answer before it goes on,
// so that the runner can end it after exactly N frames. The library only reports and waits:
// it never writes files, prints or exits. Without the runner's variables nothing happens.
//
// Protocol (one stream socket, native byte order): the program sends a FrameHeader followed by
// `pixel_bytes` bytes of RGBA rows from the top, then reads one byte: kGoOn, or kLastFrame, after
// which it flushes its standard I/O streams (what a program ended after N frames printed is not
// lost in its buffers), sends one byte back and waits to be ended.
#pragma once

#include <cstdint>

namespace shadelab::gl::platform {

class Surface;

namespace run_link {

/// Environment variables set by `shadelab run`.
inline constexpr const char* kSocketVariable = "SHADELAB_RUN_FD";        ///< the socket's fd
inline constexpr const char* kCaptureVariable = "SHADELAB_RUN_CAPTURE";  ///< "1": send pixels
inline constexpr const char* kSizeVariable = "SHADELAB_RUN_SIZE";        ///< "WxH": window size

/// The runner's answers to a frame.
inline constexpr char kGoOn = 1, kLastFrame = 2;

struct FrameHeader {
  char magic[4];  ///< "SLF1"
  std::uint32_t width, height;
  std::uint32_t pixel_bytes;  ///< 0 when not capturing, else width * height * 4
};

/// Whether a runner listens (its socket variable names an open socket).
bool active();
/// Reports a frame of `surface` and waits for the runner's answer. A runner that went away
/// ends the link (the program goes on alone).
void frame(const Surface& surface);
/// The window size the runner asks for (`--size`), if any.
bool requested_size(int& width, int& height);

}  // namespace run_link
}  // namespace shadelab::gl::platform
