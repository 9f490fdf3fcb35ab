// JSON read into a tree that remembers where each value and key came from (file, line,
// column), for error messages; nlohmann-json does the lexing through its SAX interface.
// Also applies --set overrides to such a tree. Never throws on bad input.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "shadelab/diagnostics.hpp"

namespace shadelab::detail {

struct JsonValue {
  enum class Type { kNull, kBool, kNumber, kString, kArray, kObject };
  Type type = Type::kNull;
  bool boolean = false;
  double number = 0.0;
  bool integral = false;  ///< written without fraction or exponent
  std::string text;       ///< string value, or the number as written
  std::vector<JsonValue> items;                     ///< array elements
  std::vector<std::pair<std::string, JsonValue>> members;  ///< object members, in order
  std::vector<SourceLocation> key_locations;        ///< one per member
  SourceLocation location;

  const JsonValue* find(const std::string& key) const;
  std::string type_name() const;  ///< "a number", "an array", ...
};

/// Parses `text`; on a syntax error (or nesting deeper than 64) adds a diagnostic and returns
/// false.
bool parse_json(std::string_view text, const std::string& filename, JsonValue& out,
                Diagnostics& diags);

/// Applies "key.path[2].x=value" to `root`: the value is JSON, or a bare word taken as a
/// string; missing objects are created, an index equal to an array's length appends.
/// Values set this way are located at file "--set".
bool apply_override(JsonValue& root, const std::string& assignment, Diagnostics& diags);

}  // namespace shadelab::detail
