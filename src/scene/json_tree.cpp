// JSON with positions: nlohmann's SAX parser reads through an iterator that records how far the
// input has been read; between two SAX events there are only blanks, ',' and ':', so each value
// or key starts at the first other character after the previous event's end.
#include "scene/json_tree.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "scene/json_syntax.hpp"

namespace shadelab::detail {

const JsonValue* JsonValue::find(std::string_view key) const {
  for (const JsonMember& m : members) {
    if (m.key == key) return &m.value;
  }
  return nullptr;
}

JsonValue* JsonValue::find(std::string_view key) {
  return const_cast<JsonValue*>(std::as_const(*this).find(key));
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

std::string join_path(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string index_path(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

namespace {

// A char iterator for nlohmann's input adapter that records the furthest offset read.
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
};

// Byte offsets to 1-based line and column (columns count UTF-8 characters, not bytes). Offsets
// asked for in increasing order cost O(distance).
class LineCounter {
 public:
  explicit LineCounter(std::string_view text) : text_(text) {}
  void locate(std::size_t offset, int& line, int& column) {
    offset = std::min(offset, text_.size());
    if (offset < offset_) offset_ = 0, line_ = 1, column_ = 1;
    for (; offset_ < offset; ++offset_) {
      char c = text_[offset_];
      if (c == '\n') {
        ++line_;
        column_ = 1;
      } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
        ++column_;
      }
    }
    line = line_;
    column = column_;
  }

 private:
  std::string_view text_;
  std::size_t offset_ = 0;
  int line_ = 1;
  int column_ = 1;
};

bool is_separator(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',' || c == ':';
}

class TreeBuilder : public nlohmann::json_sax<nlohmann::json> {
 public:
  TreeBuilder(std::string_view text, const std::string& file, const std::size_t& furthest,
              Diagnostics& diags)
      : text_(text), file_(file), furthest_(furthest), diags_(diags), lines_(text) {}

  JsonValue root;

  bool null() override { return scalar(JsonValue{}); }
  bool boolean(bool b) override {
    JsonValue v;
    v.type = JsonValue::Type::kBool;
    v.boolean = b;
    return scalar(std::move(v));
  }
  bool number_integer(number_integer_t n) override { return number(double(n)); }
  bool number_unsigned(number_unsigned_t n) override { return number(double(n)); }
  bool number_float(number_float_t x, const string_t&) override { return number(x); }
  bool string(string_t& s) override {
    JsonValue v;
    v.type = JsonValue::Type::kString;
    v.text = std::move(s);
    return scalar(std::move(v));
  }
  bool binary(binary_t&) override { return false; }  // not produced by the JSON parser
  bool start_object(std::size_t) override { return open(JsonValue::Type::kObject); }
  bool start_array(std::size_t) override { return open(JsonValue::Type::kArray); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& k) override;
  bool parse_error(std::size_t position, const std::string&,
                   const nlohmann::detail::exception& e) override;

 private:
  struct Open {
    JsonValue* value;
    std::unordered_map<std::string, int> key_lines;  // objects: key -> line of first use
  };
  std::string_view text_;
  const std::string& file_;
  const std::size_t& furthest_;
  Diagnostics& diags_;
  LineCounter lines_;
  std::vector<Open> stack_;
  std::size_t scan_ = 0;  // where the previous event ended
  std::size_t count_ = 0;

  std::size_t next_token() const;
  void locate(std::size_t offset, int& line, int& column) { lines_.locate(offset, line, column); }
  SourceLocation location(std::size_t offset);
  std::string container_path(std::size_t depth) const;
  std::string value_path() const;
  JsonValue* slot();
  bool counted(std::size_t at);
  bool scalar(JsonValue v);
  bool number(double x);
  bool open(JsonValue::Type type);
  bool close();
};

// Where the next token starts: the first character after the previous event that is not a
// blank or a separator.
std::size_t TreeBuilder::next_token() const {
  std::size_t i = scan_;
  while (i < text_.size() && is_separator(text_[i])) ++i;
  return i;
}

SourceLocation TreeBuilder::location(std::size_t offset) {
  SourceLocation loc{file_, 0, 0};
  locate(offset, loc.line, loc.column);
  return loc;
}

// The key path of the container open at `depth` (0 = the root).
std::string TreeBuilder::container_path(std::size_t depth) const {
  std::string path;
  for (std::size_t i = 0; i < depth; ++i) {
    const JsonValue& c = *stack_[i].value;
    path = c.type == JsonValue::Type::kObject ? join_path(path, c.members.back().key)
                                              : index_path(path, c.items.size() - 1);
  }
  return path;
}

// The key path of the value about to be read.
std::string TreeBuilder::value_path() const {
  if (stack_.empty()) return "";
  std::string path = container_path(stack_.size() - 1);
  const JsonValue& top = *stack_.back().value;
  return top.type == JsonValue::Type::kObject ? join_path(path, top.members.back().key)
                                              : index_path(path, top.items.size());
}

JsonValue* TreeBuilder::slot() {
  if (stack_.empty()) return &root;
  JsonValue& top = *stack_.back().value;
  if (top.type == JsonValue::Type::kArray) return &top.items.emplace_back();
  return &top.members.back().value;
}

bool TreeBuilder::counted(std::size_t at) {
  if (++count_ <= kMaxJsonValues) return true;
  diags_.error(location(at), "",
               "more than " + std::to_string(kMaxJsonValues) + " values (a scene needs far fewer)");
  return false;
}

bool TreeBuilder::scalar(JsonValue v) {
  std::size_t at = next_token();
  if (!counted(at)) return false;
  locate(at, v.line, v.column);
  *slot() = std::move(v);
  scan_ = furthest_;
  return true;
}

bool TreeBuilder::number(double x) {
  JsonValue v;
  v.type = JsonValue::Type::kNumber;
  v.number = x;
  return scalar(std::move(v));  // nlohmann reports non-finite numbers through parse_error
}

bool TreeBuilder::open(JsonValue::Type type) {
  std::size_t at = next_token();
  if (!counted(at)) return false;
  if (stack_.size() >= std::size_t(kMaxJsonDepth)) {
    diags_.error(location(at), "", "nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return false;
  }
  JsonValue* v = slot();
  v->type = type;
  locate(at, v->line, v->column);
  stack_.push_back({v, {}});
  scan_ = furthest_;
  return true;
}

bool TreeBuilder::close() {
  stack_.pop_back();
  scan_ = furthest_;
  return true;
}

bool TreeBuilder::key(string_t& k) {
  std::size_t at = next_token();
  if (!counted(at)) return false;
  JsonMember m;
  locate(at, m.line, m.column);
  auto [first, added] = stack_.back().key_lines.emplace(k, m.line);
  if (!added) {
    // Reported, and parsing goes on to find more errors; the tree is not used.
    diags_.error(location(at), container_path(stack_.size() - 1),
                 "duplicate key \"" + k + "\" (first at line " + std::to_string(first->second) + ")");
  }
  m.key = std::move(k);
  stack_.back().value->members.push_back(std::move(m));
  scan_ = furthest_;
  return true;
}

bool TreeBuilder::parse_error(std::size_t position, const std::string&,
                              const nlohmann::detail::exception& e) {
  if (e.id == 406) {  // out_of_range.406: a number too large for a double (1e999)
    diags_.error(location(next_token()), value_path(), "expected a finite number");
    return false;
  }
  SyntaxError s = explain_syntax_error(text_, next_token(), position, e.what());
  if (s.offset >= text_.size() && !stack_.empty()) {
    const JsonValue& open = *stack_.back().value;
    s.message += std::string(" (the '") + (open.type == JsonValue::Type::kObject ? '{' : '[') +
                 "' at line " + std::to_string(open.line) + ", column " +
                 std::to_string(open.column) + " is not closed)";
  }
  diags_.error(location(s.offset), "", s.message);
  return false;
}

// Text files never hold NUL bytes, and nlohmann would take one for the end of the input.
bool reject_nul(std::string_view text, const std::string& filename, Diagnostics& diags) {
  std::size_t nul = text.find('\0');
  if (nul == std::string_view::npos) return false;
  SourceLocation loc{filename, 0, 0};
  LineCounter(text).locate(nul, loc.line, loc.column);
  diags.error(loc, "", "syntax error: a NUL byte (is this a text file?)");
  return true;
}

}  // namespace

bool parse_json(std::string_view text, const std::string& filename, JsonValue& out,
                Diagnostics& diags) {
  if (text.size() > kMaxJsonBytes) {
    diags.error({filename, 0, 0}, "", "the file is " + std::to_string(text.size()) +
                                          " bytes, more than the limit of " +
                                          std::to_string(kMaxJsonBytes));
    return false;
  }
  if (reject_nul(text, filename, diags)) return false;
  std::size_t furthest = 0;
  TreeBuilder builder(text, filename, furthest, diags);
  CountingIterator first{text.data(), text.data(), &furthest};
  CountingIterator last{text.data() + text.size(), text.data(), &furthest};
  std::size_t before = diags.size();
  bool ok = nlohmann::json::sax_parse(first, last, &builder);
  if (ok && diags.size() == before) {
    out = std::move(builder.root);
    return true;
  }
  if (diags.size() == before) diags.error({filename, 0, 0}, "", "syntax error");
  return false;
}

}  // namespace shadelab::detail
