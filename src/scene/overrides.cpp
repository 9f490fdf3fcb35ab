// --set overrides: parse the key path (a.b[2].c), walk the tree creating what is missing, and
// put the value (JSON, or a bare word as a string) in place, marked as coming from "--set".
#include "scene/overrides.hpp"

#include <algorithm>
#include <string_view>
#include <vector>

namespace shadelab::detail {

namespace {

using Type = JsonValue::Type;

constexpr std::size_t kMaxIndexDigits = 6;  // larger indexes are past any end anyway

struct PathStep {
  std::string key;
  std::size_t index = 0;
  bool is_index = false;
};

// Reads "[3][4]..." at `i`; false if malformed.
bool parse_indexes(std::string_view s, std::size_t& i, std::vector<PathStep>& steps) {
  while (i < s.size() && s[i] == '[') {
    std::size_t close = s.find(']', i);
    if (close == std::string_view::npos || close == i + 1 || close - i - 1 > kMaxIndexDigits) return false;
    std::string_view digits = s.substr(i + 1, close - i - 1);
    if (digits.find_first_not_of("0123456789") != std::string_view::npos) return false;
    steps.push_back({"", std::stoul(std::string(digits)), true});
    i = close + 1;
  }
  return true;
}

// key ( "[" digits "]" )* ( "." key ( "[" digits "]" )* )*
bool parse_path(std::string_view s, std::vector<PathStep>& steps) {
  std::size_t i = 0;
  while (true) {
    std::size_t end = std::min(s.find_first_of(".[]", i), s.size());
    if (end == i) return false;  // empty key
    steps.push_back({std::string(s.substr(i, end - i))});
    i = end;
    if (!parse_indexes(s, i, steps)) return false;
    if (i >= s.size()) return true;
    if (s[i] != '.') return false;
    ++i;
  }
}

void mark_as_override(JsonValue& v) {
  v.line = v.column = 0;
  for (JsonValue& item : v.items) mark_as_override(item);
  for (JsonMember& m : v.members) {
    m.line = m.column = 0;
    mark_as_override(m.value);
  }
}

JsonValue* step_key(JsonValue& node, const std::string& key, const std::string& walked,
                    Diagnostics& diags) {
  if (node.type == Type::kNull) node.type = Type::kObject;
  if (node.type != Type::kObject) {
    diags.error({"--set", 0, 0}, walked,
                "expected an object to set \"" + key + "\" in, got " + node.type_name());
    return nullptr;
  }
  if (JsonValue* v = node.find(key)) return v;
  node.members.push_back({key, 0, 0, {}});
  return &node.members.back().value;
}

JsonValue* step_index(JsonValue& node, std::size_t index, const std::string& walked,
                      Diagnostics& diags) {
  if (node.type == Type::kNull) node.type = Type::kArray;
  if (node.type != Type::kArray) {
    diags.error({"--set", 0, 0}, walked, "expected an array to take element [" +
                                             std::to_string(index) + "] of, got " + node.type_name());
    return nullptr;
  }
  std::size_t n = node.items.size();
  if (index > n) {
    diags.error({"--set", 0, 0}, walked,
                "index " + std::to_string(index) + " is beyond the end (the array has " +
                    std::to_string(n) + (n == 1 ? " element" : " elements") + "; [" +
                    std::to_string(n) + "] appends)");
    return nullptr;
  }
  return index == n ? &node.items.emplace_back() : &node.items[index];
}

// The value text as JSON, else as a bare string. A number too large for a double is an error.
bool override_value(const std::string& text, const std::string& path, JsonValue& out,
                    Diagnostics& diags) {
  Diagnostics json_errors;
  if (parse_json(text, "--set", out, json_errors)) {
    mark_as_override(out);
    return true;
  }
  for (const Diagnostic& d : json_errors.items()) {
    if (d.message == "expected a finite number") {
      diags.error({"--set", 0, 0}, path, d.message);
      return false;
    }
  }
  out = JsonValue{};
  out.type = Type::kString;
  out.text = text;
  return true;
}

}  // namespace

bool apply_override(JsonValue& root, const std::string& assignment, Diagnostics& diags) {
  std::size_t eq = assignment.find('=');
  std::vector<PathStep> steps;
  if (eq == std::string::npos || !parse_path(std::string_view(assignment).substr(0, eq), steps)) {
    diags.error({"--set", 0, 0}, "",
                "expected KEY.PATH=VALUE (e.g. lights[0].spot.cutoff=30), got \"" + assignment + "\"");
    return false;
  }
  JsonValue* node = &root;
  std::string walked;
  for (const PathStep& s : steps) {
    node = s.is_index ? step_index(*node, s.index, walked, diags) : step_key(*node, s.key, walked, diags);
    if (!node) return false;
    walked = s.is_index ? index_path(walked, s.index) : join_path(walked, s.key);
  }
  JsonValue value;
  if (!override_value(assignment.substr(eq + 1), walked, value, diags)) return false;
  *node = std::move(value);
  return true;
}

}  // namespace shadelab::detail
