// Compares a reference image (Mesa's) with an actual one (shadelab-gl's) pixel by pixel and
// decides PASS / FAIL: PASS when at least --min-percent of the pixels are within --tolerance
// on every channel (R, G, B and A). Prints the share of pixels within 0, 1, 2 and 255, the worst
// difference and where it is; writes a difference image when asked (always on failure).
//
//   gl_compare REFERENCE.png ACTUAL.png [--diff DIFF.png] [--tolerance N] [--min-percent P]
//              [--name NAME] [--always-diff]
//   gl_compare --not-blank IMAGE.png      (exit 0 when the image has at least two colours)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "shadelab/image.hpp"

namespace {

struct Options {
  std::string reference, actual, diff, name;
  int tolerance = 2;
  double min_percent = 99.5;
  bool always_diff = false;
  std::string not_blank;
};

struct Stats {
  long within[4] = {0, 0, 0, 0};  // pixels whose largest channel difference is <= 0, 1, 2, tol
  int worst = -1, worst_x = 0, worst_y = 0, worst_channel = 0;
};

bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    std::string v;
    if (a == "--diff") {
      if (!value(o.diff)) return false;
    } else if (a == "--name") {
      if (!value(o.name)) return false;
    } else if (a == "--not-blank") {
      if (!value(o.not_blank)) return false;
    } else if (a == "--tolerance") {
      if (!value(v)) return false;
      o.tolerance = std::atoi(v.c_str());
    } else if (a == "--min-percent") {
      if (!value(v)) return false;
      o.min_percent = std::atof(v.c_str());
    } else if (a == "--always-diff") {
      o.always_diff = true;
    } else if (o.reference.empty()) {
      o.reference = a;
    } else if (o.actual.empty()) {
      o.actual = a;
    } else {
      return false;
    }
  }
  return !o.not_blank.empty() || (!o.reference.empty() && !o.actual.empty());
}

bool load(const std::string& path, shadelab::Image& img) {
  std::string error;
  if (shadelab::read_image(path, img, &error)) return true;
  std::fprintf(stderr, "gl_compare: cannot read %s: %s\n", path.c_str(), error.c_str());
  return false;
}

int not_blank(const std::string& path) {
  shadelab::Image img;
  if (!load(path, img)) return 1;
  const std::uint8_t* first = img.pixel(0, 0);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (!std::equal(first, first + 4, img.pixel(x, y))) {
        std::printf("gl_compare: %s is %dx%d and not blank\n", path.c_str(), img.width, img.height);
        return 0;
      }
  std::printf("gl_compare: %s is one colour (%d, %d, %d, %d): FAIL\n", path.c_str(), first[0],
              first[1], first[2], first[3]);
  return 1;
}

Stats measure(const shadelab::Image& ref, const shadelab::Image& act, int tolerance) {
  Stats s;
  for (int y = 0; y < ref.height; ++y) {
    for (int x = 0; x < ref.width; ++x) {
      const std::uint8_t* a = ref.pixel(x, y);
      const std::uint8_t* b = act.pixel(x, y);
      int d = 0, ch = 0;
      for (int c = 0; c < 4; ++c) {
        int dc = std::abs(int(a[c]) - int(b[c]));
        if (dc > d) d = dc, ch = c;
      }
      for (int k = 0; k < 3; ++k) s.within[k] += d <= k;
      s.within[3] += d <= tolerance;
      if (d > s.worst) s.worst = d, s.worst_x = x, s.worst_y = y, s.worst_channel = ch;
    }
  }
  return s;
}

// Dim grey copy of the reference; pixels over the tolerance in red (brighter = larger), pixels
// that differ within the tolerance in dark blue.
bool write_diff(const shadelab::Image& ref, const shadelab::Image& act, int tolerance,
                const std::string& path) {
  shadelab::Image out;
  out.width = ref.width;
  out.height = ref.height;
  out.rgba.resize(ref.rgba.size());
  for (int y = 0; y < ref.height; ++y) {
    for (int x = 0; x < ref.width; ++x) {
      const std::uint8_t* a = ref.pixel(x, y);
      const std::uint8_t* b = act.pixel(x, y);
      int d = 0;
      for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
      int grey = (a[0] * 77 + a[1] * 150 + a[2] * 29) >> 10;  // a quarter of the luminance
      std::uint8_t* o = out.pixel(x, y);
      o[0] = o[1] = o[2] = std::uint8_t(grey);
      o[3] = 255;
      if (d > tolerance) {
        o[0] = std::uint8_t(std::min(255, 128 + d)), o[1] = o[2] = 0;
      } else if (d > 0) {
        o[2] = std::uint8_t(std::min(255, grey + 96));
      }
    }
  }
  std::string error;
  if (shadelab::write_png(out, path, &error)) return true;
  std::fprintf(stderr, "gl_compare: cannot write %s: %s\n", path.c_str(), error.c_str());
  return false;
}

double percent(long n, long total) { return total ? 100.0 * double(n) / double(total) : 100.0; }

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    std::fprintf(stderr,
                 "usage: gl_compare REFERENCE.png ACTUAL.png [--diff DIFF.png] [--tolerance N] "
                 "[--min-percent P] [--name NAME] [--always-diff]\n"
                 "       gl_compare --not-blank IMAGE.png\n");
    return 2;
  }
  if (!o.not_blank.empty()) return not_blank(o.not_blank);
  shadelab::Image ref, act;
  if (!load(o.reference, ref) || !load(o.actual, act)) return 1;
  std::string name = o.name.empty() ? o.actual : o.name;
  if (ref.width != act.width || ref.height != act.height) {
    std::printf("gl_compare: %s: size %dx%d, reference %dx%d: FAIL\n", name.c_str(), act.width,
                act.height, ref.width, ref.height);
    return 1;
  }
  Stats s = measure(ref, act, o.tolerance);
  long total = long(ref.width) * ref.height;
  double pass_share = percent(s.within[3], total);
  bool pass = pass_share >= o.min_percent;
  const char* channels = "RGBA";
  const std::uint8_t* a = ref.pixel(s.worst_x, s.worst_y);
  const std::uint8_t* b = act.pixel(s.worst_x, s.worst_y);
  std::printf(
      "gl_compare: %s: %dx%d pixels within 0/255: %.3f%%, 1/255: %.3f%%, 2/255: %.3f%%, "
      "255/255: 100%%; within %d/255: %.3f%% (needs %.2f%%)\n"
      "gl_compare: worst difference %d/255 in %c at (%d, %d) from the top left: reference "
      "(%d, %d, %d, %d), actual (%d, %d, %d, %d)\n",
      name.c_str(), ref.width, ref.height, percent(s.within[0], total),
      percent(s.within[1], total), percent(s.within[2], total), o.tolerance, pass_share,
      o.min_percent, s.worst, channels[s.worst_channel], s.worst_x, s.worst_y, a[0], a[1], a[2],
      a[3], b[0], b[1], b[2], b[3]);
  // The machine-readable line the documentation's table is made from.
  std::printf("RESULT %s within2=%.3f worst=%d at=%d,%d %s\n", name.c_str(),
              percent(s.within[2], total), s.worst, s.worst_x, s.worst_y, pass ? "PASS" : "FAIL");
  if (!o.diff.empty() && (!pass || o.always_diff)) {
    if (write_diff(ref, act, o.tolerance, o.diff))
      std::printf("gl_compare: difference image %s\n", o.diff.c_str());
  }
  return pass ? 0 : 1;
}
