// JSON read into a small tree that remembers where each value and each key was written (line
// and column), for error messages. nlohmann-json does the lexing through its SAX interface.
// Private to the scene reader. Never throws on bad input; bounded in depth, size and count.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "shadelab/diagnostics.hpp"

namespace shadelab::detail {

/// Limits against hostile input (documented in docs/scene-format.md).
inline constexpr int kMaxJsonDepth = 64;
inline constexpr std::size_t kMaxJsonBytes = 16u << 20;  // 16 MiB
inline constexpr std::size_t kMaxJsonValues = 1u << 18;  // 262,144 values and keys

struct JsonMember;

/// One JSON value. `line` and `column` are 1-based (column in characters); line 0 means the
/// value came from a --set override rather than from the file.
struct JsonValue {
  enum class Type { kNull, kBool, kNumber, kString, kArray, kObject };
  Type type = Type::kNull;
  bool boolean = false;
  double number = 0.0;  ///< always finite
  int line = 0;
  int column = 0;
  std::string text;                 ///< string value
  std::vector<JsonValue> items;     ///< array elements
  std::vector<JsonMember> members;  ///< object members, in file order

  const JsonValue* find(std::string_view key) const;
  JsonValue* find(std::string_view key);
  std::string type_name() const;  ///< "a number", "an array", "null", ...
};

/// An object member; the position is the key's (where "unknown key" errors point).
struct JsonMember {
  std::string key;
  int line = 0;
  int column = 0;
  JsonValue value;
};

/// "a.b" and "a[2]": key paths as they appear in messages.
std::string join_path(const std::string& path, std::string_view key);
std::string index_path(const std::string& path, std::size_t index);

/// Parses `text`. On a syntax error (or a duplicate key, nesting deeper than kMaxJsonDepth, a
/// number too large for a double, too many values) adds diagnostics located in `filename` and
/// returns false.
bool parse_json(std::string_view text, const std::string& filename, JsonValue& out,
                Diagnostics& diags);

}  // namespace shadelab::detail
