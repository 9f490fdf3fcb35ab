// Error reporting for everything that reads user input: a source location, a key path and a
// message, collected in a list. The library never prints; callers format these.
#pragma once

#include <string>
#include <vector>

namespace shadelab {

/// Where a value came from. line/column are 1-based; 0 means unknown (e.g. a --set override
/// reports file "--set" and no line).
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

/// One problem: `file:line:col: key.path: message`.
struct Diagnostic {
  SourceLocation location;
  std::string key_path;  ///< e.g. "lights[2].spot.cutoff"; empty for file-level problems
  std::string message;
  std::string to_string() const;
};

/// An ordered list of problems. Readers collect all they find before giving up.
class Diagnostics {
 public:
  void error(SourceLocation loc, std::string key_path, std::string message);
  bool empty() const { return items_.empty(); }
  std::size_t size() const { return items_.size(); }
  const std::vector<Diagnostic>& items() const { return items_; }
  void append(const Diagnostics& other);
  /// All diagnostics, one per line, each ending in '\n'.
  std::string to_string() const;

 private:
  std::vector<Diagnostic> items_;
};

/// The closest candidate to `word` by edit distance, or "" if none is close enough
/// (for "did you mean" hints on unknown keys and names).
std::string nearest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace shadelab
