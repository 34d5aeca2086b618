// The JSON reader behind documents (nlohmann-json): values, escapes, order, depth, and errors
// with line and column.

#include "kinematics/io/json.h"

#include "tests/support/catch.h"

#include <string>

using namespace linkwright::kinematics::io;

TEST_CASE("parses every JSON value kind and keeps member order", "[io][json]") {
  const auto v = parseJson(R"( {"b": [1, -2.5e3, true, false, null], "a": {"s": "x\"\\\/\n\u00e9\ud83d\ude00"}} )");
  REQUIRE(v.ok());
  REQUIRE(v->is_object());
  REQUIRE(v->size() == 2);
  CHECK(v->begin().key() == "b");  // file order, not sorted
  const JsonValue* b = findMember(*v, "b");
  REQUIRE(b != nullptr);
  REQUIRE(b->size() == 5);
  CHECK((*b)[0].get<double>() == 1.0);
  CHECK((*b)[1].get<double>() == -2500.0);
  CHECK((*b)[2].get<bool>());
  CHECK((*b)[3].is_boolean());
  CHECK_FALSE((*b)[3].get<bool>());
  CHECK((*b)[4].is_null());
  CHECK(findMember(*findMember(*v, "a"), "s")->get<std::string>() ==
        "x\"\\/\n\xc3\xa9\xf0\x9f\x98\x80");  // é and 😀 in UTF-8
  CHECK(findMember(*v, "missing") == nullptr);
  CHECK(findMember(*b, "b") == nullptr);  // an array has no members
}

TEST_CASE("numbers read back bit for bit", "[io][json]") {
  const auto v = parseJson("[0.1, 1.0471975511965976, 5e-324, 1.7976931348623157e308]");
  REQUIRE(v.ok());
  CHECK((*v)[0].get<double>() == 0.1);
  CHECK((*v)[1].get<double>() == 1.0471975511965976);
  CHECK((*v)[2].get<double>() == 5e-324);
  CHECK((*v)[3].get<double>() == 1.7976931348623157e308);
}

TEST_CASE("malformed JSON is refused with line, column and what was expected", "[io][json][errors]") {
  auto [text, expected] = GENERATE(table<std::string, std::string>({
      {"", "line 1, column 1: syntax error while parsing value - unexpected end of input"},
      {"{\"a\" 1}",
       "line 1, column 6: syntax error while parsing object separator - unexpected number literal; expected ':'"},
      {"{\"a\": 1,\n \"b\": }", "line 2, column 7: syntax error while parsing value - unexpected '}'"},
      {"[1, 2", "line 1, column 6: syntax error while parsing array - unexpected end of input; expected ']'"},
      {"[01]", "line 1, column 3: syntax error while parsing array - unexpected number literal"},
      {"[1.]", "expected digit after '.'"},
      {"[1e]", "expected '+', '-', or digit after exponent"},
      {"[1e999]", "number overflow parsing '1e999': beyond the range of a double"},
      {"\"abc", "missing closing quote"},
      {"\"a\tb\"", "control character U+0009 (HT) must be escaped"},
      {"\"\\q\"", "forbidden character after backslash"},
      {"\"\\u12G4\"", "'\\u' must be followed by 4 hex digits"},
      {"\"\\ud800x\"", "surrogate U+D800..U+DBFF must be followed by U+DC00..U+DFFF"},
      {"\"\xff\"", "ill-formed UTF-8 byte"},
      {"[NaN]", "line 1, column 2: syntax error while parsing value - invalid literal"},
      {"{a: 1}", "expected string literal"},
      {"{} {}", "line 1, column 4: syntax error while parsing value - unexpected '{'; expected end of input"},
      {std::string(65, '[') + std::string(65, ']'), "nesting deeper than 64"},
  }));
  CAPTURE(text);
  const auto v = parseJson(text);
  REQUIRE_FALSE(v.ok());
  CHECK_THAT(v.error().message, Catch::Contains(expected));
}

TEST_CASE("nesting up to the limit is accepted", "[io][json]") {
  CHECK(parseJson(std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']')).ok());
}

TEST_CASE("jsonQuote escapes what JSON requires", "[io][json]") {
  CHECK(jsonQuote("mm") == "\"mm\"");
  CHECK(jsonQuote("a\"b\\c\nd\x01") == "\"a\\\"b\\\\c\\nd\\u0001\"");
  const auto back = parseJson(jsonQuote("tab\there \"q\" \x1f"));
  REQUIRE(back.ok());
  CHECK(back->get<std::string>() == "tab\there \"q\" \x1f");
  CHECK(jsonQuote("bad\xff") == "\"bad\xef\xbf\xbd\"");  // invalid UTF-8 written as U+FFFD
}

TEST_CASE("a document that is not UTF-8 is refused with a message that is", "[io][json][errors]") {
  // nlohmann quotes the bytes it last read; raw, they made Python's load() raise
  // UnicodeDecodeError instead of the refusal.
  const auto parsed = parseJson("{\"format\": \"caf\xE9\"}");
  REQUIRE_FALSE(parsed.ok());
  const std::string& m = parsed.error().message;
  CHECK(m.find("ill-formed UTF-8") != std::string::npos);
  CHECK(m.find("caf\\xE9") != std::string::npos);
  CHECK(m.find('\xE9') == std::string::npos);
  // Valid UTF-8 in a message is kept as it is.
  const auto euro = parseJson("{\"a\": \"€\" x}");
  REQUIRE_FALSE(euro.ok());
  CHECK(euro.error().message.find("\\x") == std::string::npos);
}
