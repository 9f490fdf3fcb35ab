// Checked readers for the located JSON tree (see reader.hpp).
#include "scene/reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace shadelab::detail {

std::string format_number(double x) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string join_path(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string index_path(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

bool Reader::is_type(const JsonValue& v, JsonValue::Type t, const std::string& path) {
  if (v.type == t) return true;
  JsonValue want;
  want.type = t;
  error(v, path, "expected " + want.type_name() + ", got " + v.type_name());
  return false;
}

bool Reader::object(const JsonValue& v, const std::string& path, const std::vector<std::string>& allowed) {
  if (!is_type(v, JsonValue::Type::kObject, path)) return false;
  for (std::size_t i = 0; i < v.members.size(); ++i) {
    const std::string& k = v.members[i].first;
    if (std::find(allowed.begin(), allowed.end(), k) != allowed.end()) continue;
    std::string near = nearest_match(k, allowed);
    diags_.error(v.key_locations[i], path,
                 "unknown key \"" + k + "\"" + (near.empty() ? "" : " (did you mean \"" + near + "\"?)"));
  }
  return true;
}

void Reader::number(const JsonValue& obj, const std::string& key, const std::string& path, float& out,
                    double lo, double hi, const std::string& range, std::optional<double> extra) {
  const JsonValue* v = obj.find(key);
  std::string p = join_path(path, key);
  if (!v || !is_type(*v, JsonValue::Type::kNumber, p)) return;
  bool in = (v->number >= lo && v->number <= hi) || (extra && v->number == *extra);
  if (!in) {
    error(*v, p, format_number(v->number) + " is out of range " + range);
    return;
  }
  out = static_cast<float>(v->number);
}

void Reader::positive(const JsonValue& obj, const std::string& key, const std::string& path, float& out,
                      double lo) {
  const JsonValue* v = obj.find(key);
  std::string p = join_path(path, key);
  if (!v || !is_type(*v, JsonValue::Type::kNumber, p)) return;
  if (!(v->number > lo) || v->number > 1e9) {
    error(*v, p, "expected a number greater than " + format_number(lo) + (v->number > 1e9 ? " and at most 1e+09" : "") +
                     ", got " + format_number(v->number));
    return;
  }
  out = static_cast<float>(v->number);
}

void Reader::integer(const JsonValue& obj, const std::string& key, const std::string& path, int& out,
                     int lo, int hi) {
  const JsonValue* v = obj.find(key);
  std::string p = join_path(path, key);
  if (!v || !is_type(*v, JsonValue::Type::kNumber, p)) return;
  if (v->number != std::floor(v->number)) {
    error(*v, p, "expected an integer, got " + format_number(v->number));
  } else if (v->number < lo || v->number > hi) {
    error(*v, p, format_number(v->number) + " is out of range (" + std::to_string(lo) + ".." +
                     std::to_string(hi) + ")");
  } else {
    out = static_cast<int>(v->number);
  }
}

void Reader::boolean(const JsonValue& obj, const std::string& key, const std::string& path, bool& out) {
  const JsonValue* v = obj.find(key);
  if (v && is_type(*v, JsonValue::Type::kBool, join_path(path, key))) out = v->boolean;
}

int Reader::choice(const JsonValue& obj, const std::string& key, const std::string& path,
                   const std::vector<std::string>& choices) {
  const JsonValue* v = obj.find(key);
  std::string p = join_path(path, key);
  if (!v || !is_type(*v, JsonValue::Type::kString, p)) return -1;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (choices[i] == v->text) return int(i);
  }
  std::string list;
  for (const std::string& c : choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
  std::string near = nearest_match(v->text, choices);
  error(*v, p, "expected one of " + list + ", got \"" + v->text + "\"" +
                   (near.empty() ? "" : " (did you mean \"" + near + "\"?)"));
  return -1;
}

bool Reader::numbers(const JsonValue& v, const std::string& path, std::vector<double>& out, int n,
                     int n_alt, double lo, double hi) {
  std::string want = n_alt > 0 ? std::to_string(n) + " or " + std::to_string(n_alt) : std::to_string(n);
  if (v.type != JsonValue::Type::kArray) {
    error(v, path, "expected an array of " + want + " numbers, got " + v.type_name());
    return false;
  }
  if (int(v.items.size()) != n && int(v.items.size()) != n_alt) {
    error(v, path, "expected an array of " + want + " numbers, got " + std::to_string(v.items.size()) +
                       (v.items.size() == 1 ? " number" : " numbers"));
    return false;
  }
  out.clear();
  bool good = true;
  for (std::size_t i = 0; i < v.items.size(); ++i) {
    const JsonValue& x = v.items[i];
    std::string p = index_path(path, i);
    if (!is_type(x, JsonValue::Type::kNumber, p)) {
      good = false;
    } else if (x.number < lo || x.number > hi) {
      error(x, p, format_number(x.number) + " is out of range (" + format_number(lo) + ".." +
                      format_number(hi) + ")");
      good = false;
    }
    out.push_back(x.number);
  }
  return good;
}

void Reader::color(const JsonValue& obj, const std::string& key, const std::string& path,
                   glm::vec4& out, double lo, double hi) {
  const JsonValue* v = obj.find(key);
  std::vector<double> n;
  if (!v || !numbers(*v, join_path(path, key), n, 3, 4, lo, hi)) return;
  out = glm::vec4(float(n[0]), float(n[1]), float(n[2]), n.size() == 4 ? float(n[3]) : 1.0f);
}

void Reader::vec3(const JsonValue& obj, const std::string& key, const std::string& path, glm::vec3& out) {
  const JsonValue* v = obj.find(key);
  std::vector<double> n;
  if (v && numbers(*v, join_path(path, key), n, 3)) out = glm::vec3(float(n[0]), float(n[1]), float(n[2]));
}

void Reader::vec4(const JsonValue& obj, const std::string& key, const std::string& path, glm::vec4& out) {
  const JsonValue* v = obj.find(key);
  std::vector<double> n;
  if (v && numbers(*v, join_path(path, key), n, 4)) {
    out = glm::vec4(float(n[0]), float(n[1]), float(n[2]), float(n[3]));
  }
}

}  // namespace shadelab::detail
