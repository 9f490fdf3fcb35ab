// `shadelab run [OPTIONS] -- PROGRAM ARGS...`: runs an unchanged, already-built GL program on
// shadelab (docs/platform.md). It selects shadelab's GLVND vendors and its libOSMesa.so.8 for the
// program (found next to this executable: the build tree's gl/platform, or the installed
// library folder), starts a private Xvfb when asked and no display is set, writes the frames the
// program shows as PNG, ends it after N frames or at a deadline, and stops Xvfb afterwards.
// With --capture-scene or --explain, the chosen frame is also kept as a scene file (gl/src/
// capture.hpp) and the pixels asked for are explained from it.
// Exit status: the program's own; 0 when it was ended after --frames N; 2 for bad arguments;
// 1 when shadelab could not run it (no vendor library, Xvfb failed); 124 at the deadline;
// 126/127 when the program cannot be executed or found; 128+N when signal N killed it.
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "explain_text.hpp"
#include "gl/src/capture.hpp"
#include "gl/src/platform/run_link.hpp"
#include "run_process.hpp"
#include "shadelab/image.hpp"
#include "shadelab/scene_io.hpp"

#ifndef SHADELAB_INSTALL_LIBDIR
#define SHADELAB_INSTALL_LIBDIR "lib"
#endif
#ifndef SHADELAB_INSTALL_DATADIR
#define SHADELAB_INSTALL_DATADIR "share"
#endif

namespace shadelab::cli {
namespace {

namespace fs = std::filesystem;

struct RunOptions {
  bool xvfb = false;
  std::string capture;  // printf pattern with one integer conversion
  int frames = 0;
  std::string size;
  double timeout = 0;
  std::string capture_scene;         // the scene file of a frame
  int scene_frame = 0;               // which frame (0: --frames N, else 1)
  std::vector<std::string> explain;  // pixels "X,Y"
  std::vector<std::string> command;

  int chosen_frame() const { return scene_frame > 0 ? scene_frame : frames > 0 ? frames : 1; }
  bool wants_scene() const { return !capture_scene.empty() || !explain.empty(); }
};

constexpr int kExitTimeout = 124;

// shadelab's vendor libraries for this executable: the folders holding libGLX_shadelab.so.0
// and libOSMesa.so.8, and the EGL vendor's JSON file. The build tree keeps all of them in
// gl/platform beside the executable; an installation keeps the vendors in the library folder,
// libOSMesa.so.8 in its shadelab/ subfolder and the JSON file in GLVND's egl_vendor.d.
struct VendorFiles {
  std::vector<fs::path> folders;  // empty: none found
  fs::path egl_json;              // used when it exists
};

VendorFiles vendor_files() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const fs::path dir = exe.parent_path();
  const fs::path build = dir / "gl" / "platform";
  if (fs::exists(build / "libGLX_shadelab.so.0")) return {{build}, build / "shadelab.json"};
  const fs::path installed = dir.parent_path() / SHADELAB_INSTALL_LIBDIR;
  if (!fs::exists(installed / "libGLX_shadelab.so.0")) return {};
  const fs::path egl_vendors =
      dir.parent_path() / SHADELAB_INSTALL_DATADIR / "glvnd" / "egl_vendor.d";
  return {{installed, installed / "shadelab"}, egl_vendors / "50_shadelab.json"};
}

// One %d (with flags and width: %04d) and no other conversion, %% aside.
bool valid_pattern(const std::string& p) {
  int conversions = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i] != '%') continue;
    if (i + 1 < p.size() && p[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < p.size() && std::strchr("0-+ ", p[j])) ++j;
    while (j < p.size() && std::isdigit(static_cast<unsigned char>(p[j]))) ++j;
    if (j >= p.size() || (p[j] != 'd' && p[j] != 'i' && p[j] != 'u')) return false;
    ++conversions;
    i = j;
  }
  return conversions == 1;
}

std::string frame_path(const std::string& pattern, int frame) {
  std::vector<char> buffer(pattern.size() + 64);
  std::snprintf(buffer.data(), buffer.size(), pattern.c_str(), frame);
  return buffer.data();
}

bool parse_pixel(const std::string& text, int& x, int& y) {
  char comma = 0, extra = 0;
  return std::sscanf(text.c_str(), "%d%c%d%c", &x, &comma, &y, &extra) == 3 && comma == ',' && x >= 0 && y >= 0;
}

bool parse_size(const std::string& text, int& width, int& height) {
  char x = 0, extra = 0;
  return std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) == 3 && x == 'x' && width > 0 &&
         height > 0 && width <= 16384 && height <= 16384;
}

// Checks what CLI11 cannot; prints the error and returns false.
bool validate(const RunOptions& o) {
  int w = 0, h = 0;
  const char* error = nullptr;
  if (o.command.empty()) error = "no program given (shadelab run [OPTIONS] -- PROGRAM ARGS...)";
  else if (!o.capture.empty() && !valid_pattern(o.capture))
    error = "--capture: the file pattern needs exactly one frame-number conversion, e.g. 'out/frame%04d.png'";
  else if (!o.size.empty() && !parse_size(o.size, w, h)) error = "--size: expected WIDTHxHEIGHT (e.g. 640x480)";
  for (const std::string& p : o.explain) {
    if (!error && !parse_pixel(p, w, h)) error = "--explain: expected a pixel X,Y from the frame's top left (e.g. 160,120)";
  }
  if (!error) return true;
  std::cerr << "shadelab run: " << error << "\n";
  return false;
}

std::string signal_name(int sig) {
  const char* name = strsignal(sig);
  return std::to_string(sig) + (name ? std::string(" (") + name + ")" : "");
}

// The program's environment: shadelab's vendor libraries first on the library path.
std::vector<std::string> program_environment(const RunOptions& o, const VendorFiles& vendor,
                                             const std::string& display, const std::string& scene) {
  std::string path;
  for (const fs::path& f : vendor.folders) path += f.string() + ":";
  const char* old = std::getenv("LD_LIBRARY_PATH");
  std::vector<std::string> env = {"LD_LIBRARY_PATH=" + path + (old ? old : ""),
                                  "__GLX_VENDOR_LIBRARY_NAME=shadelab"};
  if (!vendor.egl_json.empty() && fs::exists(vendor.egl_json))
    env.push_back("__EGL_VENDOR_LIBRARY_FILENAMES=" + vendor.egl_json.string());
  if (!display.empty()) env.push_back("DISPLAY=" + display);
  if (!o.capture.empty()) env.push_back(std::string(gl::platform::run_link::kCaptureVariable) + "=1");
  if (!o.size.empty()) env.push_back(std::string(gl::platform::run_link::kSizeVariable) + "=" + o.size);
  if (!scene.empty()) {
    env.push_back(std::string(gl::kCaptureSceneVariable) + "=" + scene);
    env.push_back(std::string(gl::kCaptureFrameVariable) + "=" + std::to_string(o.chosen_frame()));
  }
  if (!o.explain.empty()) env.push_back(std::string(gl::platform::run_link::kCaptureVariable) + "=1");
  return env;
}

// Writes a captured frame; false (after saying why) stops the program.
bool write_frame(const std::string& pattern, int number, const run::Frame& frame) {
  if (pattern.empty() || frame.rgba.empty()) return true;
  const std::string path = frame_path(pattern, number);
  std::error_code ec;
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) fs::create_directories(parent, ec);
  Image image{frame.width, frame.height, frame.rgba};
  std::string error;
  if (write_png(image, path, &error)) return true;
  std::cerr << "shadelab run: --capture: " << error << "\n";
  return false;
}

int report(const RunOptions& o, const run::ChildResult& r) {
  using End = run::ChildResult::End;
  const std::string& program = o.command.front();
  // Frames are counted only when the program was handed the frame socket.
  const bool counted = o.frames > 0 || !o.capture.empty();
  const std::string shown = counted ? " after " + std::to_string(r.frames) + " frames" : "";
  switch (r.end) {
    case End::kExited:
      if (o.frames > 0 && r.frames < o.frames)
        std::cerr << "shadelab run: " << program << " ended after " << r.frames << " of " << o.frames << " frames\n";
      return r.status;
    case End::kSignaled:
      std::cerr << "shadelab run: " << program << " was killed by signal " << signal_name(r.status) << shown << "\n";
      return 128 + r.status;
    case End::kFramesDone: return kExitOk;
    case End::kFrameError: return kExitFailure;
    case End::kTimedOut:
      std::cerr << "shadelab run: " << program << " did not end within " << o.timeout << " s" << shown
                << "; stopped\n";
      return kExitTimeout;
    case End::kInterrupted: return 128 + SIGINT;
    case End::kNotStarted:
      std::cerr << "shadelab run: cannot run " << program << ": " << std::strerror(r.status) << "\n";
      return r.status == ENOENT ? 127 : 126;
  }
  return kExitFailure;
}

// Where the frame's scene goes: --capture-scene's file (made absolute: the program may change
// its folder), or for --explain alone a temporary folder removed afterwards.
struct ScenePlace {
  std::string file;
  fs::path temporary;
  ~ScenePlace() {
    std::error_code ec;
    if (!temporary.empty()) fs::remove_all(temporary, ec);
  }
};

bool place_scene(const RunOptions& o, ScenePlace& place) {
  std::error_code ec;
  if (!o.capture_scene.empty()) {
    const fs::path file = fs::absolute(o.capture_scene, ec);
    if (!file.parent_path().empty()) fs::create_directories(file.parent_path(), ec);
    fs::remove(file, ec);  // a file left from an earlier run must not pass for this frame
    place.file = file.string();
    return true;
  }
  std::string pattern = (fs::temp_directory_path(ec) / "shadelab-explain-XXXXXX").string();
  if (!mkdtemp(pattern.data())) {
    std::cerr << "shadelab run: --explain: cannot make a temporary folder: " << std::strerror(errno) << "\n";
    return false;
  }
  place.temporary = pattern;
  place.file = (place.temporary / "frame.json").string();
  return true;
}

// After the program: the scene written, its pixels explained. False when the frame was not
// captured or the scene cannot be read (said why).
bool report_scene(const RunOptions& o, const std::string& file, int frames_shown, const run::Frame& frame) {
  if (!fs::exists(file)) {
    std::cerr << "shadelab run: --" << (o.capture_scene.empty() ? "explain" : "capture-scene") << ": the program drew nothing in frame "
              << o.chosen_frame() << " (it showed " << frames_shown << (frames_shown == 1 ? " frame)" : " frames)")
              << "; choose another with --scene-frame\n";
    return false;
  }
  if (!o.capture_scene.empty()) {
    std::cerr << "shadelab run: frame " << o.chosen_frame() << " written as " << o.capture_scene
              << " (open it in the lab: shadelab serve " << o.capture_scene << ")\n";
  }
  if (o.explain.empty()) return true;
  LoadResult loaded = load_scene_file(file);
  if (!loaded.scene) {
    std::cerr << "shadelab run: --explain: the captured scene cannot be read:\n" << loaded.diagnostics.to_string();
    return false;
  }
  for (const std::string& p : o.explain) {
    int x = 0, y = 0;
    parse_pixel(p, x, y);
    std::optional<std::array<std::uint8_t, 3>> shown;
    if (!frame.rgba.empty() && x < frame.width && y < frame.height) {
      const std::uint8_t* px = &frame.rgba[(std::size_t(y) * std::size_t(frame.width) + std::size_t(x)) * 4];
      shown = std::array<std::uint8_t, 3>{px[0], px[1], px[2]};
    }
    std::cout << "frame " << o.chosen_frame() << ", " << explain_text(*loaded.scene, x, y, shown);
  }
  return true;
}

int run_program(const RunOptions& o) {
  if (!validate(o)) return kExitBadInput;
  ScenePlace scene;
  if (o.wants_scene() && !place_scene(o, scene)) return kExitFailure;
  const VendorFiles vendor = vendor_files();
  if (vendor.folders.empty()) {
    std::cerr << "shadelab run: libGLX_shadelab.so.0 not found beside this executable (build the "
                 "shadelab-glx target, or install shadelab)\n";
    return kExitFailure;
  }
  run::Xvfb xvfb;
  const char* display = std::getenv("DISPLAY");
  if (o.xvfb && (!display || !*display)) {
    int w = 1280, h = 1024;
    if (!o.size.empty()) parse_size(o.size, w, h);
    std::string error;
    if (!xvfb.start(std::max(w, 1280), std::max(h, 1024), 15.0, error)) {
      std::cerr << "shadelab run: --xvfb: " << error << "\n";
      return kExitFailure;
    }
  }
  run::ChildOptions child;
  child.command = o.command;
  child.environment = program_environment(o, vendor, xvfb.display(), scene.file);
  child.frame_socket = o.frames > 0 || !o.capture.empty() || !o.explain.empty();
  // --explain without --frames: the program has shown what is explained once its frame ends.
  child.stop_after_frames = o.frames > 0 ? o.frames : !o.explain.empty() ? o.chosen_frame() : 0;
  child.timeout_seconds = o.timeout;
  run::Frame chosen;  // the explained frame's pixels
  child.on_frame = [&](int n, const run::Frame& f) {
    if (!o.explain.empty() && n == o.chosen_frame()) chosen = f;
    return write_frame(o.capture, n, f);
  };
  const run::ChildResult result = run::run_child(child);
  int status = report(o, result);
  xvfb.stop();
  if (o.wants_scene() && result.end != run::ChildResult::End::kNotStarted &&
      !report_scene(o, scene.file, result.frames, chosen) && status == kExitOk)
    status = kExitFailure;
  return status;
}

}  // namespace

Action add_run_command(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* sub = app.add_subcommand(
      "run", "Run an unchanged, already-built GL program (GLX, GLUT, OSMesa) on shadelab");
  sub->add_flag("--xvfb", o->xvfb, "Start a private Xvfb for the program when DISPLAY is not set");
  sub->add_option("--capture", o->capture,
                  "Write every frame the program shows as PNG: a file pattern with one frame number, "
                  "e.g. 'out/frame%04d.png' (frames count from 1)");
  sub->add_option("--frames", o->frames, "End the program after N frames, with exit status 0")
      ->check(CLI::Range(1, 1 << 30));
  sub->add_option("--size", o->size, "Resize the program's top-level windows to WIDTHxHEIGHT");
  sub->add_option("--timeout", o->timeout, "Stop the program after S seconds (exit status 124)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--capture-scene", o->capture_scene,
                  "Keep a frame as a scene file (its lights, materials and triangles; OBJ files beside "
                  "it) that `shadelab serve FILE` opens in the lab");
  sub->add_option("--scene-frame", o->scene_frame,
                  "The frame --capture-scene and --explain take (default: --frames N, else 1)")
      ->check(CLI::Range(1, 1 << 30));
  sub->add_option("--explain", o->explain,
                  "Print how the lighting equation makes pixel X,Y (from the top left) of that frame "
                  "(the program is ended after it unless --frames says otherwise); may be given several times");
  sub->add_option("command", o->command, "-- PROGRAM ARGS...")->required();
  sub->footer(
      "A frame is a glXSwapBuffers, or a glFlush/glFinish of a single-buffered window.\n"
      "Example:\n"
      "  cc prog.c -lGL -lGLU -lglut -lm -o prog\n"
      "  shadelab run --xvfb --frames 1 --capture 'out/frame%04d.png' -- ./prog\n"
      "  shadelab run --xvfb --frames 1 --capture-scene out/frame.json --explain 160,120 -- ./prog");
  return [o] { return run_program(*o); };
}

}  // namespace shadelab::cli
