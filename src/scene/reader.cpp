// Checked readers for the located JSON tree (see reader.hpp): one message style everywhere,
// "120 is out of range (0..90, or 180)", "expected a number, got a string".
#include "scene/reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace shadelab::detail {

using Type = JsonValue::Type;

std::string format_number(double x) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string format_number(float x) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

bool Range::contains(double x) const {
  if (also && x == *also) return true;
  bool above_lo = lo_open ? x > lo : x >= lo;
  bool below_hi = hi_open ? x < hi : x <= hi;
  return above_lo && below_hi;
}

std::string Range::text() const {
  std::string l = format_number(lo), h = format_number(hi), t;
  if (lo <= -kHuge && hi >= kHuge) t = l + ".." + h;
  else if (lo_open && hi_open) t = "greater than " + l + " and less than " + h;
  else if (lo_open) t = "greater than " + l + (hi >= kHuge ? "" : ", at most " + h);
  else t = hi >= kHuge ? l + " or more" : l + ".." + h;
  return "(" + t + (also ? ", or " + format_number(*also) : "") + ")";
}

Range closed(double lo, double hi) {
  Range r;
  r.lo = lo;
  r.hi = hi;
  return r;
}

Range at_least(double lo) { return closed(lo, kHuge); }

Range above(double lo, double hi) {
  Range r = closed(lo, hi);
  r.lo_open = true;
  return r;
}

Range exclusive(double lo, double hi) {
  Range r = above(lo, hi);
  r.hi_open = true;
  return r;
}

std::string suggestion(const std::string& word, const std::vector<std::string>& candidates) {
  // Edit distances cost |word| x |candidate|: keep hostile inputs cheap.
  constexpr std::size_t kMaxWord = 64, kMaxCandidates = 1000;
  if (word.size() > kMaxWord || candidates.size() > kMaxCandidates) return "";
  std::string near = nearest_match(word, candidates);
  return near.empty() ? "" : " (did you mean \"" + near + "\"?)";
}

SourceLocation Reader::where(int line, int column) const {
  if (line == 0) return {"--set", 0, 0};
  return {file_, line, column};
}

void Reader::error(const JsonValue& at, const std::string& path, std::string message) {
  diags_.error(where(at), path, std::move(message));
}

bool Reader::is_type(const JsonValue& v, Type type, const std::string& path) {
  if (v.type == type) return true;
  JsonValue want;
  want.type = type;
  error(v, path, "expected " + want.type_name() + ", got " + v.type_name());
  return false;
}

bool Reader::object(const JsonValue& v, const std::string& path,
                    const std::vector<std::string>& allowed) {
  if (!is_type(v, Type::kObject, path)) return false;
  for (const JsonMember& m : v.members) {
    if (std::find(allowed.begin(), allowed.end(), m.key) != allowed.end()) continue;
    diags_.error(where(m.line, m.column), path,
                 "unknown key \"" + m.key + "\"" + suggestion(m.key, allowed));
  }
  return true;
}

bool Reader::number_value(const JsonValue& v, const std::string& path, double& out,
                          const Range& range) {
  if (!is_type(v, Type::kNumber, path)) return false;
  if (!range.contains(v.number)) {
    bool too_large = range.lo > -kHuge && range.hi >= kHuge && v.number > range.hi;
    error(v, path, format_number(v.number) +
                       (too_large ? " is too large (at most " + format_number(kHuge) + ")"
                                  : " is out of range " + range.text()));
    return false;
  }
  out = v.number;
  return true;
}

bool Reader::number(const JsonValue& obj, std::string_view key, const std::string& path,
                    float& out, const Range& range) {
  const JsonValue* v = obj.find(key);
  double x = 0.0;
  if (!v || !number_value(*v, join_path(path, key), x, range)) return false;
  out = static_cast<float>(x);
  return true;
}

bool Reader::integer(const JsonValue& obj, std::string_view key, const std::string& path,
                     int& out, int lo, int hi) {
  const JsonValue* v = obj.find(key);
  std::string p = join_path(path, key);
  if (!v || !is_type(*v, Type::kNumber, p)) return false;
  if (v->number != std::floor(v->number)) {
    error(*v, p, "expected an integer, got " + format_number(v->number));
    return false;
  }
  double x = 0.0;
  if (!number_value(*v, p, x, closed(lo, hi))) return false;
  out = static_cast<int>(x);
  return true;
}

bool Reader::boolean(const JsonValue& obj, std::string_view key, const std::string& path,
                     bool& out) {
  const JsonValue* v = obj.find(key);
  if (!v || !is_type(*v, Type::kBool, join_path(path, key))) return false;
  out = v->boolean;
  return true;
}

bool Reader::string(const JsonValue& obj, std::string_view key, const std::string& path,
                    std::string& out) {
  const JsonValue* v = obj.find(key);
  if (!v || !is_type(*v, Type::kString, join_path(path, key))) return false;
  out = v->text;
  return true;
}

int Reader::choice(const JsonValue& obj, std::string_view key, const std::string& path,
                   const std::vector<std::string>& choices) {
  const JsonValue* v = obj.find(key);
  std::string p = join_path(path, key);
  if (!v || !is_type(*v, Type::kString, p)) return -1;
  auto it = std::find(choices.begin(), choices.end(), v->text);
  if (it != choices.end()) return int(it - choices.begin());
  std::string list;
  for (const std::string& c : choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
  error(*v, p, "expected one of " + list + ", got \"" + v->text + "\"" + suggestion(v->text, choices));
  return -1;
}

bool Reader::numbers(const JsonValue& v, const std::string& path, std::vector<double>& out, int n,
                     int n_alt, const Range& each) {
  std::string want = std::to_string(n) + (n_alt > 0 ? " or " + std::to_string(n_alt) : "");
  std::size_t count = v.items.size();
  if (v.type != Type::kArray || (int(count) != n && int(count) != n_alt)) {
    std::string got = v.type != Type::kArray ? v.type_name()
                      : std::to_string(count) + (count == 1 ? " number" : " numbers");
    error(v, path, "expected an array of " + want + " numbers, got " + got);
    return false;
  }
  out.assign(count, 0.0);
  bool good = true;
  for (std::size_t i = 0; i < count; ++i) {
    good &= number_value(v.items[i], index_path(path, i), out[i], each);
  }
  return good;
}

bool Reader::color(const JsonValue& obj, std::string_view key, const std::string& path,
                   glm::vec4& out, const Range& each) {
  const JsonValue* v = obj.find(key);
  std::vector<double> n;
  if (!v || !numbers(*v, join_path(path, key), n, 3, 4, each)) return false;
  out = glm::vec4(float(n[0]), float(n[1]), float(n[2]), n.size() == 4 ? float(n[3]) : 1.0f);
  return true;
}

bool Reader::vec3(const JsonValue& obj, std::string_view key, const std::string& path,
                  glm::vec3& out) {
  const JsonValue* v = obj.find(key);
  std::vector<double> n;
  if (!v || !numbers(*v, join_path(path, key), n, 3)) return false;
  out = glm::vec3(float(n[0]), float(n[1]), float(n[2]));
  return true;
}

bool Reader::vec4(const JsonValue& obj, std::string_view key, const std::string& path,
                  glm::vec4& out) {
  const JsonValue* v = obj.find(key);
  std::vector<double> n;
  if (!v || !numbers(*v, join_path(path, key), n, 4)) return false;
  out = glm::vec4(float(n[0]), float(n[1]), float(n[2]), float(n[3]));
  return true;
}

}  // namespace shadelab::detail
