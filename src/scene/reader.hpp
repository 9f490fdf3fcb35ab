// Checked access to a located JSON tree: types, ranges, enums and unknown keys with "did you
// mean", every problem recorded as `file:line:col: key.path: message` and reading going on, so
// that all problems are found in one pass. Private to the scene reader.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/json_tree.hpp"

namespace shadelab::detail {

/// Magnitudes above this are refused everywhere (they overflow floats in the renderer).
inline constexpr double kHuge = 1e30;
/// The largest length (radius, size, distance) a shape or camera accepts.
inline constexpr double kMaxLength = 1e6;

/// Shortest text that reads back as `x`: 120, 2.5, -0.25, 1e+30, 1e-05.
std::string format_number(double x);
/// The same for a float (0.1f prints as 0.1, not as the double nearest to it).
std::string format_number(float x);

/// An allowed interval, written in messages as "(0..128)", "(0 or more)", "(greater than 0)",
/// "(greater than 0, at most 1e+06)", "(greater than 0 and less than 180)", "(0..90, or 180)".
struct Range {
  double lo = -kHuge;
  double hi = kHuge;
  bool lo_open = false;
  bool hi_open = false;
  std::optional<double> also;  ///< one more allowed value outside [lo, hi]

  bool contains(double x) const;
  std::string text() const;
};
Range closed(double lo, double hi);              ///< [lo, hi]
Range at_least(double lo);                       ///< [lo, kHuge]
Range above(double lo, double hi = kMaxLength);  ///< (lo, hi]
Range exclusive(double lo, double hi);            ///< (lo, hi)

/// " (did you mean \"x\"?)" when a candidate is close to `word`, else "".
std::string suggestion(const std::string& word, const std::vector<std::string>& candidates);

class Reader {
 public:
  Reader(std::string file, Diagnostics& diags) : file_(std::move(file)), diags_(diags) {}

  /// The value's location: in the file, or "--set" for overridden values (line 0).
  SourceLocation where(const JsonValue& v) const { return where(v.line, v.column); }
  SourceLocation where(int line, int column) const;
  void error(const JsonValue& at, const std::string& path, std::string message);
  std::size_t error_count() const { return diags_.size(); }

  /// Is `v` an object whose keys are all in `allowed`? Unknown keys are reported at the key
  /// (and are not fatal: the known ones are still read).
  bool object(const JsonValue& v, const std::string& path, const std::vector<std::string>& allowed);
  bool is_type(const JsonValue& v, JsonValue::Type type, const std::string& path);

  // Each reader below looks up member `key` of `obj` (whose key path is `path`). When it is
  // present and valid it sets `out` and returns true; when invalid it reports and returns false;
  // when absent it leaves `out` (the default) and returns false.
  bool number(const JsonValue& obj, std::string_view key, const std::string& path, float& out,
              const Range& range);
  bool integer(const JsonValue& obj, std::string_view key, const std::string& path, int& out,
               int lo, int hi);
  bool boolean(const JsonValue& obj, std::string_view key, const std::string& path, bool& out);
  bool string(const JsonValue& obj, std::string_view key, const std::string& path, std::string& out);
  /// One of `choices`; returns its index, or -1 when absent or invalid.
  int choice(const JsonValue& obj, std::string_view key, const std::string& path,
             const std::vector<std::string>& choices);
  /// 3 or 4 numbers in `each` (alpha defaults to 1).
  bool color(const JsonValue& obj, std::string_view key, const std::string& path, glm::vec4& out,
             const Range& each);
  bool vec3(const JsonValue& obj, std::string_view key, const std::string& path, glm::vec3& out);
  bool vec4(const JsonValue& obj, std::string_view key, const std::string& path, glm::vec4& out);

  /// `v` itself: an array of exactly `n` (or `n_alt`) numbers, each in `each`.
  bool numbers(const JsonValue& v, const std::string& path, std::vector<double>& out, int n,
               int n_alt = -1, const Range& each = {});
  /// `v` itself: a number in `range`.
  bool number_value(const JsonValue& v, const std::string& path, double& out, const Range& range);

 private:
  std::string file_;
  Diagnostics& diags_;
};

}  // namespace shadelab::detail
