// Checked access to a located JSON tree: types, ranges, unknown keys with "did you mean",
// every problem recorded as file:line:col: key.path: message. Private to the scene reader.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/json_tree.hpp"

namespace shadelab::detail {

/// Shortest text that reads back as `x` (120, 2.5, 1e+30).
std::string format_number(double x);

class Reader {
 public:
  explicit Reader(Diagnostics& diags) : diags_(diags) {}

  void error(const JsonValue& at, const std::string& path, const std::string& message) {
    diags_.error(at.location, path, message);
  }
  bool ok() const { return diags_.empty(); }

  /// Is `v` an object whose keys are all in `allowed`? Unknown keys are reported at the key.
  bool object(const JsonValue& v, const std::string& path, const std::vector<std::string>& allowed);
  bool is_type(const JsonValue& v, JsonValue::Type t, const std::string& path);

  /// Sets `out` from member `key` of `obj` if present and valid ([lo, hi], or `extra`).
  void number(const JsonValue& obj, const std::string& key, const std::string& path, float& out,
              double lo, double hi, const std::string& range, std::optional<double> extra = {});
  /// A number strictly greater than `lo`.
  void positive(const JsonValue& obj, const std::string& key, const std::string& path, float& out,
                double lo = 0.0);
  void integer(const JsonValue& obj, const std::string& key, const std::string& path, int& out,
               int lo, int hi);
  void boolean(const JsonValue& obj, const std::string& key, const std::string& path, bool& out);
  /// One of `choices`; returns the index chosen, or -1 (absent or invalid).
  int choice(const JsonValue& obj, const std::string& key, const std::string& path,
             const std::vector<std::string>& choices);
  /// An array of exactly n (or n_alt) finite numbers, each in [lo, hi].
  bool numbers(const JsonValue& v, const std::string& path, std::vector<double>& out, int n,
               int n_alt = -1, double lo = -1e30, double hi = 1e30);
  void color(const JsonValue& obj, const std::string& key, const std::string& path, glm::vec4& out,
             double lo, double hi);
  void vec3(const JsonValue& obj, const std::string& key, const std::string& path, glm::vec3& out);
  void vec4(const JsonValue& obj, const std::string& key, const std::string& path, glm::vec4& out);

 private:
  Diagnostics& diags_;
};

std::string join_path(const std::string& path, const std::string& key);
std::string index_path(const std::string& path, std::size_t i);

}  // namespace shadelab::detail
