// Readable JSON syntax-error messages ("expected '}' or ',' after an object member, got 'x'")
// made from nlohmann-json's parse errors and the text around the offending token. Private to
// the scene reader. Text only: it neither parses nor reports.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace shadelab::detail {

/// The token starting at byte `at`, for "got ..." messages: 'x', '}', '"abc"', end of file.
std::string describe_token(std::string_view text, std::size_t at);

struct SyntaxError {
  std::size_t offset = 0;  ///< where the offending token starts (text.size() at the end)
  std::string message;     ///< "syntax error: ..."
};

/// Explains a parse error. `token_start` is the first byte after the last good token that is
/// not blank, ',' or ':'; `lexer_position` is how many characters nlohmann had read; `what` is
/// its exception text.
SyntaxError explain_syntax_error(std::string_view text, std::size_t token_start,
                                 std::size_t lexer_position, const std::string& what);

}  // namespace shadelab::detail
