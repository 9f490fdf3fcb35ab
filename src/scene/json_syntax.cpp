// Turns nlohmann-json's parse errors ("syntax error while parsing object - invalid literal;
// last read: '1 x'; expected '}'") into short messages that name what was expected and show
// the token found, located at that token's first character.
#include "scene/json_syntax.hpp"

#include <algorithm>
#include <cstdio>

namespace shadelab::detail {

namespace {

constexpr std::size_t kMaxShown = 24;  // bytes of a token quoted in a message
constexpr std::string_view kPunctuation = "{}[],:";

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool is_control(unsigned char c) { return c < 0x20 || c == 0x7f; }

// Cuts `token` at kMaxShown bytes without splitting a UTF-8 sequence.
std::string shorten(std::string_view token) {
  if (token.size() <= kMaxShown) return std::string(token);
  std::size_t n = kMaxShown;
  while (n > 0 && (static_cast<unsigned char>(token[n]) & 0xC0) == 0x80) --n;
  return std::string(token.substr(0, n)) + "...";
}

// The string literal starting at `at` (up to its closing quote, or the end of the line).
std::string_view string_token(std::string_view text, std::size_t at) {
  std::size_t i = at + 1;
  while (i < text.size() && text[i] != '"' && text[i] != '\n') i += text[i] == '\\' ? 2 : 1;
  return text.substr(at, std::min(i + 1, text.size()) - at);
}

// A bare word starting at `at`: up to a blank, punctuation, a quote or a control character.
std::string_view word_token(std::string_view text, std::size_t at) {
  std::size_t i = at;
  while (i < text.size() && !is_blank(text[i]) && text[i] != '"' &&
         kPunctuation.find(text[i]) == std::string_view::npos &&
         !is_control(static_cast<unsigned char>(text[i]))) {
    ++i;
  }
  return text.substr(at, std::max<std::size_t>(i - at, 1));
}

// The part of `what` between `begin` and `end` (both excluded); "" if `begin` is absent.
std::string between(const std::string& what, std::string_view begin, std::string_view end) {
  std::size_t b = what.find(begin);
  if (b == std::string::npos) return "";
  b += begin.size();
  std::size_t e = end.empty() ? std::string::npos : what.find(end, b);
  return what.substr(b, e == std::string::npos ? std::string::npos : e - b);
}

// The last character before `at` that is not blank, or '\0'.
char previous_char(std::string_view text, std::size_t at) {
  while (at > 0 && is_blank(text[at - 1])) --at;
  return at > 0 ? text[at - 1] : '\0';
}

// What the parser expected, from nlohmann's context ("object key", "array", ...).
std::string expectation(const std::string& context, const std::string& what) {
  if (context == "object key") return "expected a key in double quotes";
  if (context == "object separator") return "expected ':' after an object key";
  if (context == "object") return "expected '}' or ',' after an object member";
  if (context == "array") return "expected ']' or ',' after an array element";
  if (what.find("; expected end of input") != std::string::npos) {
    return "expected end of file after the JSON value";
  }
  return "expected a value";
}

// A hint for the usual mistakes: trailing commas, comments, single quotes.
std::string hint(std::string_view text, std::size_t at) {
  if (at >= text.size()) return "";
  char c = text[at];
  if ((c == '}' || c == ']') && previous_char(text, at) == ',') {
    return std::string(" (JSON allows no ',' before '") + c + "')";
  }
  if (c == '/') return " (JSON has no comments)";
  if (c == '\'') return " (JSON strings take double quotes)";
  return "";
}

// A message of the lexer's own ("invalid string: ...", "invalid number; ...") or "".
std::string lexer_message(const std::string& body) {
  std::size_t last_read = body.find("; last read: ");
  if (last_read == std::string::npos) return "";
  std::string m = body.substr(0, last_read);
  if (m == "invalid literal") return "";  // better told by what was expected
  if (m == "invalid string: missing closing quote") return "the string has no closing quote";
  if (std::size_t semi = m.find("; "); semi != std::string::npos) m.replace(semi, 2, ": ");
  return m;
}

bool only_blanks(std::string_view text) {
  return std::all_of(text.begin(), text.end(), is_blank);
}

}  // namespace

std::string describe_token(std::string_view text, std::size_t at) {
  if (at >= text.size()) return "end of file";
  auto c = static_cast<unsigned char>(text[at]);
  if (is_control(c)) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "control character U+%04X", unsigned(c));
    return buf;
  }
  if (kPunctuation.find(char(c)) != std::string_view::npos) return std::string("'") + char(c) + "'";
  std::string token = shorten(c == '"' ? string_token(text, at) : word_token(text, at));
  char quote = token.find('\'') == std::string::npos ? '\'' : '"';
  return quote + token + quote;
}

SyntaxError explain_syntax_error(std::string_view text, std::size_t token_start,
                                 std::size_t lexer_position, const std::string& what) {
  SyntaxError e;
  std::size_t last_read = lexer_position > 0 ? lexer_position - 1 : 0;
  e.offset = std::min({token_start, last_read, text.size()});
  if (only_blanks(text)) {
    e.offset = 0;
    e.message = "syntax error: the file is empty (expected a JSON object)";
    return e;
  }
  std::string body = between(what, " - ", "");
  if (std::string lexer = lexer_message(body); !lexer.empty()) {
    // Inside a string, point at the offending character; else at the token.
    bool inside = lexer.rfind("invalid string", 0) == 0;
    if (inside) e.offset = std::min(last_read, text.size());
    e.message = "syntax error: " + lexer;
    return e;
  }
  std::string context = between(what, "while parsing ", " - ");
  e.message = "syntax error: " + expectation(context, body) + ", got " +
              describe_token(text, e.offset) + hint(text, e.offset);
  return e;
}

}  // namespace shadelab::detail
