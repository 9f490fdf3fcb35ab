// `shadelab animate SCENE --vary KEY=FROM:TO --frames N --fps F -o OUT`: one scene rendered
// once per frame with keys moving linearly (numbers, or arrays of numbers component by
// component) and/or the camera orbiting its target, written as an animated PNG or, through
// Debian's ffmpeg command, as MP4 or WebM. With --shard I/N it renders its share of the frames
// into OUT.parts/ for `shadelab merge OUT` (shard.hpp).
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "shadelab/render.hpp"
#include "shadelab/scene_io.hpp"
#include "shard.hpp"

namespace shadelab::cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct AnimateArgs {
  std::string scene, output, shading, size, shard;
  std::vector<std::string> vary, overrides;
  bool orbit = false;
  int frames = 48, fps = 24, samples = 0;
};

// One --vary KEY=FROM:TO: numbers, or arrays of numbers of one length.
struct Motion {
  std::string key;
  json from, to;
};

bool parse_motion(const std::string& text, Motion& m, std::string* error) {
  const std::size_t eq = text.find('=');
  const std::size_t colon = eq == std::string::npos ? eq : text.find(':', eq + 1);
  if (eq == std::string::npos || eq == 0 || colon == std::string::npos) {
    *error = "--vary: expected KEY=FROM:TO, got \"" + text + "\"";
    return false;
  }
  m.key = text.substr(0, eq);
  m.from = json::parse(text.substr(eq + 1, colon - eq - 1), nullptr, false);
  m.to = json::parse(text.substr(colon + 1), nullptr, false);
  auto numbers = [](const json& j) {
    if (j.is_number()) return true;
    if (!j.is_array() || j.empty()) return false;
    for (const json& e : j) {
      if (!e.is_number()) return false;
    }
    return true;
  };
  if (!numbers(m.from) || !numbers(m.to) || m.from.is_array() != m.to.is_array() ||
      (m.from.is_array() && m.from.size() != m.to.size())) {
    *error = "--vary: " + m.key + ": expected FROM:TO as two numbers or two arrays of numbers of one length, got \"" +
             text.substr(eq + 1) + "\"";
    return false;
  }
  return true;
}

// The value of `m` at t in [0, 1], as JSON text.
std::string value_at(const Motion& m, double t) {
  auto lerp = [t](const json& a, const json& b) {
    const double x = a.get<double>(), y = b.get<double>();
    return t >= 1.0 ? y : x + (y - x) * t;
  };
  if (!m.from.is_array()) return json(lerp(m.from, m.to)).dump();
  json out = json::array();
  for (std::size_t i = 0; i < m.from.size(); ++i) out.push_back(lerp(m.from[i], m.to[i]));
  return out.dump();
}

struct Job {
  AnimateArgs args;
  std::vector<Motion> motions;
  std::vector<std::string> overrides;  // --set, --size and --samples
  std::optional<ShadingMode> shading;
  Camera camera;                       // the scene's, for --orbit
};

// Frame k's overrides: every motion at k / (frames - 1), the orbit at k / frames of a turn
// (the last frame leads back to the first).
std::vector<std::string> frame_overrides(const Job& job, int k) {
  std::vector<std::string> o = job.overrides;
  const int n = job.args.frames;
  const double t = n > 1 ? double(k) / double(n - 1) : 0.0;
  for (const Motion& m : job.motions) o.push_back(m.key + "=" + value_at(m, t));
  if (job.args.orbit) {
    const Camera& c = job.camera;
    const float angle = float(2.0 * M_PI * double(k) / double(n));
    const glm::vec3 axis = glm::length(c.up) > 0.0f ? glm::normalize(c.up) : glm::vec3(0, 1, 0);
    const glm::vec3 eye = c.target + glm::vec3(glm::rotate(glm::mat4(1.0f), angle, axis) * glm::vec4(c.eye - c.target, 0.0f));
    o.push_back("camera.eye=" + json::array({eye.x, eye.y, eye.z}).dump());
  }
  return o;
}

// Diagnostics from overrides report file "--set"; those of a frame's values say "--vary".
void print_frame_errors(const Diagnostics& diags) {
  for (Diagnostic d : diags.items()) {
    if (d.location.file == "--set") d.location.file = "--vary";
    std::cerr << d.to_string() << "\n";
  }
}

std::optional<Image> render_frame(const Job& job, int k) {
  LoadOptions options;
  options.overrides = frame_overrides(job, k);
  LoadResult r = load_scene_file(job.args.scene, options);
  if (!r.scene) {
    print_frame_errors(r.diagnostics);
    return std::nullopt;
  }
  RenderOptions ro;
  ro.shading = job.shading;
  return render_scene(*r.scene, ro);
}

// Checks the arguments and the scene (the first and last frames, which hold every key's
// extremes); prints what is wrong.
std::optional<Job> prepare(const AnimateArgs& a) {
  Job job;
  job.args = a;
  std::string error;
  for (const std::string& text : a.vary) {
    Motion m;
    if (!parse_motion(text, m, &error)) {
      std::cerr << error << "\n";
      return std::nullopt;
    }
    job.motions.push_back(m);
  }
  if (job.motions.empty() && !a.orbit) {
    std::cerr << "shadelab animate: give --vary KEY=FROM:TO (repeatable) or --orbit\n";
    return std::nullopt;
  }
  job.overrides = a.overrides;
  if (!a.size.empty() && !add_size_overrides(a.size, "animate", job.overrides)) return std::nullopt;
  if (a.samples > 0) job.overrides.push_back("image.samples=" + std::to_string(a.samples));
  if (a.shading == "flat") job.shading = ShadingMode::kFlat;
  if (a.shading == "gouraud") job.shading = ShadingMode::kGouraud;
  if (a.shading == "phong") job.shading = ShadingMode::kPhong;
  LoadOptions base;
  base.overrides = job.overrides;
  LoadResult r = load_scene_file(a.scene, base);
  if (!r.scene) {
    std::cerr << r.diagnostics.to_string();
    return std::nullopt;
  }
  job.camera = r.scene->camera;
  for (int k : {0, a.frames - 1}) {
    LoadOptions options;
    options.overrides = frame_overrides(job, k);
    LoadResult f = load_scene_file(a.scene, options);
    if (!f.scene) {
      print_frame_errors(f.diagnostics);
      return std::nullopt;
    }
  }
  return job;
}

enum class Format { kApng, kVideo };

std::optional<Format> format_of(const std::string& output) {
  const std::string ext = fs::path(output).extension().string();
  if (ext == ".png" || ext == ".apng") return Format::kApng;
  if (ext == ".mp4" || ext == ".webm") return Format::kVideo;
  return std::nullopt;
}

// Runs `argv` and waits; true when it exits with status 0.
bool run_program(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    execvp(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  pid_t waited;
  do {
    waited = waitpid(pid, &status, 0);
  } while (waited < 0 && errno == EINTR);
  return waited == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

bool ffmpeg_available() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = dirs.find(':', start);
    const std::string dir = dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!dir.empty() && access((fs::path(dir) / "ffmpeg").c_str(), X_OK) == 0) return true;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return false;
}

// The frames (PNG files frame-00000.png ... in `dir`) as a video through ffmpeg: H.264 in MP4,
// VP9 in WebM, yuv420p (sizes padded to even numbers) so that browsers play them.
bool encode_video(const std::string& dir, const std::string& output, int fps, std::string* error) {
  const bool webm = fs::path(output).extension() == ".webm";
  std::vector<std::string> argv = {"ffmpeg", "-nostdin", "-y", "-loglevel", "error", "-framerate", std::to_string(fps),
                                   "-i", (fs::path(dir) / "frame-%05d.png").string(),
                                   "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p"};
  if (webm) {
    for (const char* a : {"-c:v", "libvpx-vp9", "-b:v", "0", "-crf", "32"}) argv.push_back(a);
  } else {
    for (const char* a : {"-c:v", "libx264", "-crf", "20", "-movflags", "+faststart"}) argv.push_back(a);
  }
  argv.push_back(output);
  if (!run_program(argv)) {
    *error = "ffmpeg could not write " + output;
    return false;
  }
  return true;
}

// Writes the finished frames as the output's format.
int write_output(const std::vector<Image>& frames, const std::string& output, int fps) {
  std::string error;
  if (format_of(output) == Format::kApng) {
    if (!write_apng(frames, output, 1, fps, &error)) {
      std::cerr << "shadelab animate: " << error << "\n";
      return kExitFailure;
    }
    return kExitOk;
  }
  const fs::path dir = fs::path(output).parent_path() / (fs::path(output).filename().string() + ".frames");
  std::error_code ec;
  fs::create_directories(dir, ec);
  for (std::size_t k = 0; k < frames.size() && !ec; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%05zu.png", k);
    if (!write_png(frames[k], (dir / name).string(), &error)) break;
  }
  const bool ok = error.empty() && !ec && encode_video(dir.string(), output, fps, &error);
  fs::remove_all(dir, ec);
  if (!ok) {
    std::cerr << "shadelab animate: " << (error.empty() ? "cannot write the frames" : error) << "\n";
    return kExitFailure;
  }
  return kExitOk;
}

json manifest_of(const AnimateArgs& a) {
  return {{"command", "animate"}, {"parts", a.frames}, {"scene", a.scene}, {"vary", a.vary},
          {"orbit", a.orbit}, {"frames", a.frames}, {"fps", a.fps}, {"size", a.size},
          {"set", a.overrides}, {"shading", a.shading}, {"samples", a.samples}};
}

int run(const AnimateArgs& a) {
  if (!format_of(a.output)) {
    std::cerr << "shadelab animate: -o: expected a .png (animated PNG), .mp4 or .webm file, got \"" << a.output
              << "\"\n";
    return kExitBadInput;
  }
  if (format_of(a.output) == Format::kVideo && !ffmpeg_available()) {
    std::cerr << "shadelab animate: " << a.output << " needs the ffmpeg command (Debian's ffmpeg package); "
              << "a .png output is an animated PNG without it\n";
    return kExitFailure;
  }
  Shard shard;
  std::string error;
  if (!a.shard.empty() && !parse_shard(a.shard, shard, &error)) {
    std::cerr << error << "\n";
    return kExitBadInput;
  }
  std::optional<Job> job = prepare(a);
  if (!job) return kExitBadInput;
  if (shard.active()) {
    if (!write_manifest(a.output, manifest_of(a), &error)) {
      std::cerr << "shadelab animate: " << error << "\n";
      return kExitFailure;
    }
    const std::vector<std::size_t> missing = missing_parts(a.output, std::size_t(a.frames));
    int done = 0, mine = 0;
    for (std::size_t k : missing) mine += shard.owns(k);
    for (std::size_t k : missing) {
      if (!shard.owns(k)) continue;
      std::optional<Image> frame = render_frame(*job, int(k));
      if (!frame) return kExitBadInput;
      if (!write_part(a.output, k, *frame, &error)) {
        std::cerr << "shadelab animate: " << error << "\n";
        return kExitFailure;
      }
      progress_bar(++done, mine, "frame " + std::to_string(k + 1));
    }
    return kExitOk;
  }
  std::vector<Image> frames;
  for (int k = 0; k < a.frames; ++k) {
    std::optional<Image> frame = render_frame(*job, k);
    if (!frame) return kExitBadInput;
    frames.push_back(std::move(*frame));
    progress_bar(k + 1, a.frames, "frame " + std::to_string(k + 1));
  }
  return write_output(frames, a.output, a.fps);
}

}  // namespace

int merge_animate(const json& m, const std::string& output) {
  const int fps = m.value("fps", 24), frames = m.value("frames", 0);
  if (fps < 1 || frames < 1) {
    std::cerr << "shadelab merge: " << parts_dir(output) << "/manifest.json: bad fps or frames\n";
    return kExitBadInput;
  }
  if (format_of(output) == Format::kVideo && !ffmpeg_available()) {
    std::cerr << "shadelab merge: " << output << " needs the ffmpeg command (Debian's ffmpeg package)\n";
    return kExitFailure;
  }
  std::vector<Image> images(static_cast<std::size_t>(frames));
  std::string error;
  for (std::size_t k = 0; k < images.size(); ++k) {
    if (!read_part(output, k, images[k], &error)) {
      std::cerr << "shadelab merge: " << error << "\n";
      return kExitFailure;
    }
  }
  return write_output(images, output, fps);
}

Action add_animate_command(CLI::App& app) {
  auto a = std::make_shared<AnimateArgs>();
  CLI::App* cmd = app.add_subcommand("animate", "Render a scene with keys moving (or the camera orbiting) into an animation");
  cmd->add_option("scene", a->scene, "Scene file")->required();
  cmd->add_option("--vary", a->vary,
                  "KEY=FROM:TO : a key path moving linearly from FROM to TO over the frames; numbers or "
                  "arrays of numbers (repeatable)");
  cmd->add_flag("--orbit", a->orbit, "Turn the camera once around its target, about its up axis (a turntable)");
  cmd->add_option("--frames", a->frames, "Number of frames")->check(CLI::Range(1, 100000))->capture_default_str();
  cmd->add_option("--fps", a->fps, "Frames per second")->check(CLI::Range(1, 240))->capture_default_str();
  cmd->add_option("-o,--output", a->output, "Output: .png (animated PNG), .mp4 or .webm (through ffmpeg)")->required();
  cmd->add_option("--set", a->overrides, "Override a scene value for every frame (repeatable)");
  cmd->add_option("--size", a->size, "Size of each frame, WIDTHxHEIGHT");
  cmd->add_option("--shading", a->shading, "Shading mode for every object")
      ->check(CLI::IsMember({"flat", "gouraud", "phong"}));
  cmd->add_option("--samples", a->samples, "Anti-aliasing samples per pixel (1, 4, 9 ... 64)")->check(CLI::Range(1, 64));
  cmd->add_option("--shard", a->shard,
                  "I/N: render only the I-th of N shares of the frames into OUTPUT.parts/ (then shadelab merge OUTPUT)");
  cmd->footer(
      "Examples:\n"
      "  shadelab animate scenes/lecture/10-spot-cutoff.json --vary 'lights[0].spot.cutoff=5:60' -o cutoff.png\n"
      "  shadelab animate scenes/teapot.json --orbit --frames 72 --fps 30 -o turntable.mp4\n"
      "  shadelab animate scenes/teapot.json --vary 'lights[0].position=[-4,3,4,1]:[4,3,4,1]' --shard 2/4 -o move.png\n"
      "Exit status: 0 success, 1 output could not be written, 2 bad scene, key or value.");
  return [a] { return run(*a); };
}

}  // namespace shadelab::cli
