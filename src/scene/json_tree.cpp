// JSON with positions: nlohmann's SAX parser reads through an iterator that counts how far the
// input has been read; between two SAX events there are only blanks, ',' and ':', so each
// token starts at the first other character after the previous event.
#include "scene/json_tree.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <iterator>

#include <nlohmann/json.hpp>

namespace shadelab::detail {

const JsonValue* JsonValue::find(const std::string& key) const {
  for (const auto& [k, v] : members) {
    if (k == key) return &v;
  }
  return nullptr;
}

std::string JsonValue::type_name() const {
  switch (type) {
    case Type::kNull: return "null";
    case Type::kBool: return "a boolean";
    case Type::kNumber: return "a number";
    case Type::kString: return "a string";
    case Type::kArray: return "an array";
    case Type::kObject: return "an object";
  }
  return "?";
}

namespace {

constexpr int kMaxDepth = 64;

// A char iterator that records the furthest offset read.
struct CountingIterator {
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;
  const char* p;
  const char* begin;
  std::size_t* furthest;
  reference operator*() const { return *p; }
  CountingIterator& operator++() {
    ++p;
    *furthest = std::max(*furthest, std::size_t(p - begin));
    return *this;
  }
  bool operator==(const CountingIterator& o) const { return p == o.p; }
  bool operator!=(const CountingIterator& o) const { return p != o.p; }
};

class TreeBuilder : public nlohmann::json_sax<nlohmann::json> {
 public:
  TreeBuilder(std::string_view text, std::string file, std::size_t* furthest, Diagnostics& d)
      : text_(text), file_(std::move(file)), furthest_(furthest), diags_(d) {}
  JsonValue root;

  bool null() override { return scalar(JsonValue{}); }
  bool boolean(bool b) override {
    JsonValue v;
    v.type = JsonValue::Type::kBool;
    v.boolean = b;
    return scalar(std::move(v));
  }
  bool number_integer(number_integer_t n) override { return number(double(n), true); }
  bool number_unsigned(number_unsigned_t n) override { return number(double(n), true); }
  bool number_float(number_float_t x, const string_t& s) override {
    return number(x, s.find_first_of(".eE") == std::string::npos);
  }
  bool string(string_t& s) override {
    JsonValue v;
    v.type = JsonValue::Type::kString;
    v.text = s;
    return scalar(std::move(v));
  }
  bool binary(binary_t&) override { return false; }
  bool start_object(std::size_t) override { return open(JsonValue::Type::kObject); }
  bool start_array(std::size_t) override { return open(JsonValue::Type::kArray); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& k) override {
    SourceLocation loc = token_start();
    JsonValue& obj = *stack_.back();
    for (std::size_t i = 0; i < obj.members.size(); ++i) {
      if (obj.members[i].first == k) {
        diags_.error(loc, "", "duplicate key \"" + k + "\" (first at line " +
                                  std::to_string(obj.key_locations[i].line) + ")");
        return false;
      }
    }
    obj.members.emplace_back(k, JsonValue{});
    obj.key_locations.push_back(loc);
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    // nlohmann: "[json.exception.parse_error.101] parse error at line L, column C: MESSAGE";
    // a number too large for a double comes as out_of_range.406.
    std::string what = e.what();
    std::size_t colon = what.find(": ", what.find("column"));
    std::string message = e.id == 406 ? "expected a finite number"
                          : colon == std::string::npos ? what : what.substr(colon + 2);
    diags_.error(token_start(), "", message);
    return false;
  }

 private:
  std::string_view text_;
  std::string file_;
  std::size_t* furthest_;
  Diagnostics& diags_;
  std::vector<JsonValue*> stack_;
  std::size_t scan_ = 0;  // where the previous event ended

  SourceLocation location_of(std::size_t offset) const {
    SourceLocation loc{file_, 1, 1};
    for (std::size_t i = 0; i < offset && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++loc.line;
        loc.column = 1;
      } else if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) {
        ++loc.column;  // count characters, not UTF-8 continuation bytes
      }
    }
    return loc;
  }
  SourceLocation token_start() {
    std::size_t i = scan_;
    while (i < text_.size() && (std::isspace(static_cast<unsigned char>(text_[i])) || text_[i] == ',' || text_[i] == ':')) ++i;
    scan_ = *furthest_;
    return location_of(i);
  }
  JsonValue* slot() {
    if (stack_.empty()) return &root;
    JsonValue& top = *stack_.back();
    if (top.type == JsonValue::Type::kArray) {
      top.items.emplace_back();
      return &top.items.back();
    }
    return &top.members.back().second;
  }
  bool scalar(JsonValue v) {
    v.location = token_start();
    *slot() = std::move(v);
    return true;
  }
  bool number(double x, bool integral) {
    JsonValue v;
    v.type = JsonValue::Type::kNumber;
    v.number = x;
    v.integral = integral;
    v.location = token_start();
    if (!std::isfinite(x)) {
      diags_.error(v.location, "", "expected a finite number");
      return false;
    }
    *slot() = std::move(v);
    return true;
  }
  bool open(JsonValue::Type type) {
    SourceLocation loc = token_start();
    if (stack_.size() >= kMaxDepth) {
      diags_.error(loc, "", "nesting deeper than " + std::to_string(kMaxDepth) + " levels");
      return false;
    }
    JsonValue* v = slot();
    v->type = type;
    v->location = loc;
    stack_.push_back(v);
    return true;
  }
  bool close() {
    stack_.pop_back();
    scan_ = *furthest_;
    return true;
  }
};

std::vector<std::string> split_path(const std::string& path, bool& ok) {
  std::vector<std::string> parts;  // "[3]" kept with brackets to mark an index
  std::string cur;
  ok = !path.empty();
  for (std::size_t i = 0; i < path.size() && ok; ++i) {
    char c = path[i];
    if (c == '.') {
      ok = !cur.empty() || (!parts.empty() && parts.back()[0] == '[');
      if (!cur.empty()) parts.push_back(cur);
      cur.clear();
    } else if (c == '[') {
      if (!cur.empty()) parts.push_back(cur);
      cur.clear();
      std::size_t close = path.find(']', i);
      // At most 6 digits: indexes beyond that are errors anyway, and stoul must not overflow.
      ok = close != std::string::npos && close > i + 1 && close - i - 1 <= 6 &&
           path.find_first_not_of("0123456789", i + 1) == close;
      if (ok) parts.push_back(path.substr(i, close - i + 1));
      i = close;
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) parts.push_back(cur);
  return parts;
}

void relocate(JsonValue& v, const SourceLocation& loc) {
  v.location = loc;
  for (JsonValue& i : v.items) relocate(i, loc);
  for (auto& [k, m] : v.members) relocate(m, loc);
  for (SourceLocation& k : v.key_locations) k = loc;
}

}  // namespace

bool parse_json(std::string_view text, const std::string& filename, JsonValue& out,
                Diagnostics& diags) {
  std::size_t furthest = 0;
  TreeBuilder builder(text, filename, &furthest, diags);
  CountingIterator first{text.data(), text.data(), &furthest};
  CountingIterator last{text.data() + text.size(), text.data(), &furthest};
  std::size_t before = diags.size();
  bool ok = nlohmann::json::sax_parse(first, last, &builder);
  if (!ok || diags.size() != before) {
    if (diags.size() == before) diags.error({filename, 0, 0}, "", "invalid JSON");
    return false;
  }
  out = std::move(builder.root);
  return true;
}

bool apply_override(JsonValue& root, const std::string& assignment, Diagnostics& diags) {
  SourceLocation here{"--set", 0, 0};
  std::size_t eq = assignment.find('=');
  bool ok = eq != std::string::npos && eq > 0;
  std::vector<std::string> parts = ok ? split_path(assignment.substr(0, eq), ok) : std::vector<std::string>{};
  if (!ok || parts.empty()) {
    diags.error(here, "", "expected KEY.PATH=VALUE (e.g. lights[0].spot.cutoff=30), got \"" + assignment + "\"");
    return false;
  }
  std::string value_text = assignment.substr(eq + 1);
  JsonValue value;
  Diagnostics ignored;
  if (!parse_json(value_text, "--set", value, ignored)) {
    value = JsonValue{};
    value.type = JsonValue::Type::kString;
    value.text = value_text;
  }
  relocate(value, here);
  JsonValue* node = &root;
  std::string walked;
  for (const std::string& part : parts) {
    bool index = part[0] == '[';
    if (index) {
      if (node->type == JsonValue::Type::kNull) node->type = JsonValue::Type::kArray;
      std::size_t i = std::stoul(part.substr(1, part.size() - 2));
      if (node->type != JsonValue::Type::kArray || i > node->items.size() || i > 100000) {
        diags.error(here, walked, node->type != JsonValue::Type::kArray
                                      ? "is " + node->type_name() + ", not an array"
                                      : "index " + std::to_string(i) + " is beyond the end (" +
                                            std::to_string(node->items.size()) + " elements)");
        return false;
      }
      if (i == node->items.size()) node->items.emplace_back().location = here;
      node = &node->items[i];
    } else {
      if (node->type == JsonValue::Type::kNull) node->type = JsonValue::Type::kObject;
      if (node->type != JsonValue::Type::kObject) {
        diags.error(here, walked, "is " + node->type_name() + ", not an object");
        return false;
      }
      JsonValue* next = nullptr;
      for (auto& [k, v] : node->members) {
        if (k == part) next = &v;
      }
      if (!next) {
        node->members.emplace_back(part, JsonValue{});
        node->key_locations.push_back(here);
        next = &node->members.back().second;
        next->location = here;
      }
      node = next;
    }
    walked += index ? part : (walked.empty() ? "" : ".") + part;
  }
  *node = std::move(value);
  return true;
}

}  // namespace shadelab::detail
