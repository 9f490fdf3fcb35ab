// The located JSON tree: positions of values and keys (columns in characters), syntax errors
// in their short form at the offending token, and the limits against hostile input. Every
// line:column below was counted by hand in the literal text.
#include <gtest/gtest.h>

#include <string>

#include "scene/json_tree.hpp"
#include "shadelab/scene_io.hpp"

namespace shadelab {
namespace {

using detail::JsonValue;

std::string errors(const std::string& text) {
  return parse_scene(text, "s.json", ".").diagnostics.to_string();
}

TEST(JsonTree, ValuesAndKeysKnowTheirLineAndColumn) {
  // Line 3 has a two-byte character before `true`: columns count characters, not bytes.
  std::string text =
      "{\n"
      "  \"caption\": \"h\xC3\xA9llo\",\n"
      "  \"\xC3\xA9\": [1, true, null]\n"
      "}\n";
  JsonValue root;
  Diagnostics d;
  ASSERT_TRUE(detail::parse_json(text, "s.json", root, d)) << d.to_string();
  EXPECT_EQ(root.line, 1);
  EXPECT_EQ(root.column, 1);
  ASSERT_EQ(root.members.size(), 2u);
  EXPECT_EQ(root.members[0].key, "caption");
  EXPECT_EQ(root.members[0].line, 2);
  EXPECT_EQ(root.members[0].column, 3);
  EXPECT_EQ(root.members[0].value.text, "h\xC3\xA9llo");
  EXPECT_EQ(root.members[0].value.column, 14);
  const JsonValue& array = root.members[1].value;
  EXPECT_EQ(root.members[1].line, 3);
  EXPECT_EQ(root.members[1].column, 3);
  EXPECT_EQ(array.column, 8);
  ASSERT_EQ(array.items.size(), 3u);
  EXPECT_EQ(array.items[0].column, 9);
  EXPECT_EQ(array.items[1].type, JsonValue::Type::kBool);
  EXPECT_EQ(array.items[1].column, 12);
  EXPECT_EQ(array.items[2].column, 18);
  EXPECT_EQ(array.items[2].line, 3);
}

TEST(JsonTree, SyntaxErrorsSayWhatWasExpectedAndWhatWasFound) {
  EXPECT_EQ(errors("{\n  \"image\": {\"width\": 1\n    x}\n}"),
            "s.json:3:5: syntax error: expected '}' or ',' after an object member, got 'x'\n");
  EXPECT_EQ(errors("{\"lights\": [1 2]}"),
            "s.json:1:15: syntax error: expected ']' or ',' after an array element, got '2'\n");
  EXPECT_EQ(errors("{\"image\" {}}"),
            "s.json:1:10: syntax error: expected ':' after an object key, got '{'\n");
  EXPECT_EQ(errors("{image: {}}"),
            "s.json:1:2: syntax error: expected a key in double quotes, got 'image'\n");
  EXPECT_EQ(errors("{\"lights\": [1,,2]}"),
            "s.json:1:15: syntax error: expected a value, got ','\n");
  EXPECT_EQ(errors("{\"lights\": [tru]}"), "s.json:1:13: syntax error: expected a value, got 'tru'\n");
  EXPECT_EQ(errors("{} x"),
            "s.json:1:4: syntax error: expected end of file after the JSON value, got 'x'\n");
}

TEST(JsonTree, SyntaxErrorsHintAtTheUsualMistakes) {
  EXPECT_EQ(errors("{\n  \"image\": {\"width\": 10,}\n}"),
            "s.json:2:25: syntax error: expected a key in double quotes, got '}' (JSON allows no ',' "
            "before '}')\n");
  EXPECT_EQ(errors("{\"lights\": [{},]}"),
            "s.json:1:16: syntax error: expected a value, got ']' (JSON allows no ',' before ']')\n");
  EXPECT_EQ(errors("// scene\n{}"), "s.json:1:1: syntax error: expected a value, got '//' (JSON has no comments)\n");
  EXPECT_EQ(errors("{'image': {}}"),
            "s.json:1:2: syntax error: expected a key in double quotes, got \"'image'\" (JSON strings take "
            "double quotes)\n");
}

TEST(JsonTree, UnfinishedInputPointsAtTheEndAndTheOpenBracket) {
  EXPECT_EQ(errors(""), "s.json:1:1: syntax error: the file is empty (expected a JSON object)\n");
  EXPECT_EQ(errors("  \n "), "s.json:1:1: syntax error: the file is empty (expected a JSON object)\n");
  EXPECT_EQ(errors("["), "s.json:1:2: syntax error: expected a value, got end of file (the '[' at line 1, "
                         "column 1 is not closed)\n");
  EXPECT_EQ(errors("{\"a\": [1, 2"),
            "s.json:1:12: syntax error: expected ']' or ',' after an array element, got end of file (the "
            "'[' at line 1, column 7 is not closed)\n");
  EXPECT_EQ(errors("{\"caption\": \"abc"), "s.json:1:13: syntax error: the string has no closing quote\n");
}

TEST(JsonTree, LexicalErrorsPointAtTheBadCharacter) {
  EXPECT_EQ(errors("{\"caption\": \"a\\qb\"}"),
            "s.json:1:16: syntax error: invalid string: forbidden character after backslash\n");
  EXPECT_EQ(errors("{\"caption\": \"a\tb\"}"),
            "s.json:1:15: syntax error: invalid string: control character U+0009 (HT) must be escaped to "
            "\\u0009 or \\t\n");
  EXPECT_EQ(errors("{\"image\": {\"width\": 1.}}"),
            "s.json:1:21: syntax error: invalid number: expected digit after '.'\n");
  EXPECT_EQ(errors(std::string("{\"caption\": \"x\"}\0", 17)),
            "s.json:1:17: syntax error: a NUL byte (is this a text file?)\n");
}

TEST(JsonTree, DeepNestingIsAnErrorNotARecursion) {
  JsonValue v;
  Diagnostics d;
  EXPECT_TRUE(detail::parse_json(std::string(64, '[') + std::string(64, ']'), "s.json", v, d));
  EXPECT_EQ(errors(std::string(65, '[') + std::string(65, ']')),
            "s.json:1:65: nesting deeper than 64 levels\n");
  EXPECT_EQ(errors(std::string(1000000, '[')), "s.json:1:65: nesting deeper than 64 levels\n");
  EXPECT_EQ(errors("{\"a\":" + std::string(100, '[')), "s.json:1:69: nesting deeper than 64 levels\n");
}

TEST(JsonTree, NumbersMustBeFinite) {
  EXPECT_EQ(errors("{\"image\": {\"width\": 1e999}}"), "s.json:1:21: image.width: expected a finite number\n");
  EXPECT_EQ(errors("{\"lights\": [{}, {\"position\": [0, 0, -1e400, 0]}]}"),
            "s.json:1:37: lights[1].position[2]: expected a finite number\n");
  // Finite but huge numbers and integers beyond 64 bits are values like any other.
  EXPECT_EQ(errors("{\"image\": {\"width\": 123456789012345678901234567890}}"),
            "s.json:1:21: image.width: 1.2345678901234568e+29 is out of range (1..16384)\n");
  EXPECT_EQ(errors("{\"image\": {\"width\": -0.0}}"), "s.json:1:21: image.width: -0 is out of range (1..16384)\n");
}

TEST(JsonTree, DuplicateKeysAreAllReported) {
  EXPECT_EQ(errors("{\"image\": {}, \"image\": {}}"),
            "s.json:1:15: duplicate key \"image\" (first at line 1)\n");
  EXPECT_EQ(errors("{\n"
                   "  \"materials\": {\"red\": {\"ambient\": [1, 0, 0],\n"
                   "                         \"ambient\": [0, 1, 0]}},\n"
                   "  \"caption\": \"a\", \"caption\": \"b\"\n"
                   "}"),
            "s.json:3:26: materials.red: duplicate key \"ambient\" (first at line 2)\n"
            "s.json:4:19: duplicate key \"caption\" (first at line 4)\n");
}

TEST(JsonTree, SizeAndCountLimits) {
  std::string many = "[";
  for (int i = 0; i < 300000; ++i) many += "0,";
  many += "0]";
  // Value 262,145 is the 262,144th zero (the array is the first), at column 2 + 2 * 262,143.
  EXPECT_EQ(errors(many), "s.json:1:524288: more than 262144 values (a scene needs far fewer)\n");
  EXPECT_EQ(errors(std::string(17u << 20, ' ')),
            "s.json: the file is 17825792 bytes, more than the limit of 16777216\n");
}

}  // namespace
}  // namespace shadelab
