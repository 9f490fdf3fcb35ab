// Compares the values a conformance program printed under Mesa (the reference) with those it
// printed under libshadelab-gl, line by line: PASS when both files have the same lines, each
// with the same label (everything before the first ':') and the same tokens after it, where
// two numeric tokens may differ by --abs plus --rel times the larger magnitude (floats Mesa and
// shadelab compute in a different order) and any other token must be equal. Prints every
// differing line (up to 200) and a RESULT line as gl_compare does.
//
//   gl_values REFERENCE.txt ACTUAL.txt [--name NAME] [--rel R] [--abs A]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Options {
  std::string reference, actual, name;
  double rel = 0.0, abs = 0.0;
};

bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if ((a == "--name" || a == "--rel" || a == "--abs") && i + 1 < argc) {
      std::string v = argv[++i];
      if (a == "--name") o.name = v;
      else (a == "--rel" ? o.rel : o.abs) = std::atof(v.c_str());
    } else if (o.reference.empty()) {
      o.reference = a;
    } else if (o.actual.empty()) {
      o.actual = a;
    } else {
      return false;
    }
  }
  return !o.reference.empty() && !o.actual.empty();
}

bool read_lines(const std::string& path, std::vector<std::string>& lines) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "gl_values: cannot read %s\n", path.c_str());
    return false;
  }
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return true;
}

std::vector<std::string> tokens(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

bool number(const std::string& t, double& v) {
  char* end = nullptr;
  v = std::strtod(t.c_str(), &end);
  return end && *end == '\0' && end != t.c_str();
}

bool same_token(const std::string& a, const std::string& b, const Options& o) {
  if (a == b) return true;
  double x, y;
  if (!number(a, x) || !number(b, y)) return false;
  if (std::isnan(x) || std::isnan(y)) return std::isnan(x) && std::isnan(y);
  return std::fabs(x - y) <= o.abs + o.rel * std::max(std::fabs(x), std::fabs(y));
}

bool same_line(const std::string& a, const std::string& b, const Options& o) {
  const std::size_t ca = a.find(':'), cb = b.find(':');
  if (a.substr(0, ca) != b.substr(0, cb)) return false;
  if (ca == std::string::npos || cb == std::string::npos) return ca == cb;
  const auto ta = tokens(a.substr(ca + 1)), tb = tokens(b.substr(cb + 1));
  if (ta.size() != tb.size()) return false;
  for (std::size_t i = 0; i < ta.size(); ++i) {
    if (!same_token(ta[i], tb[i], o)) return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    std::fprintf(stderr, "usage: gl_values REFERENCE.txt ACTUAL.txt [--name NAME] [--rel R] [--abs A]\n");
    return 2;
  }
  std::vector<std::string> ref, act;
  if (!read_lines(o.reference, ref) || !read_lines(o.actual, act)) return 1;
  const std::string name = o.name.empty() ? o.actual : o.name;
  const std::size_t n = std::max(ref.size(), act.size());
  int differing = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string a = i < ref.size() ? ref[i] : "(none)", b = i < act.size() ? act[i] : "(none)";
    if (i < ref.size() && i < act.size() && same_line(a, b, o)) continue;
    if (++differing <= 200) std::printf("gl_values: line %zu\n  mesa:     %s\n  shadelab: %s\n", i + 1, a.c_str(), b.c_str());
  }
  std::printf("gl_values: %s: %zu lines, %d differ (reference %zu lines)\n", name.c_str(), act.size(), differing,
              ref.size());
  std::printf("RESULT %s.values equal=%zu of %zu %s\n", name.c_str(), n - std::size_t(differing), n,
              differing ? "FAIL" : "PASS");
  return differing ? 1 : 0;
}
