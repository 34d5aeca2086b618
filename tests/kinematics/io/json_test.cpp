// The strict JSON reader behind documents: values, escapes, and errors with line and column.

#include "kinematics/io/json.h"

#include <catch2/catch.hpp>

#include <string>

using namespace linkwright::kinematics::io;

TEST_CASE("parses every JSON value kind and keeps member order", "[io][json]") {
  const auto v = parseJson(R"( {"b": [1, -2.5e3, true, false, null], "a": {"s": "x\"\\\/\n\u00e9\ud83d\ude00"}} )");
  REQUIRE(v.ok());
  REQUIRE(v->type == JsonValue::Type::Object);
  REQUIRE(v->object.size() == 2);
  CHECK(v->object[0].first == "b");  // file order, not sorted
  const JsonValue* b = v->find("b");
  REQUIRE(b != nullptr);
  REQUIRE(b->array.size() == 5);
  CHECK(b->array[0].number == 1.0);
  CHECK(b->array[1].number == -2500.0);
  CHECK(b->array[2].boolean);
  CHECK(b->array[3].type == JsonValue::Type::Bool);
  CHECK_FALSE(b->array[3].boolean);
  CHECK(b->array[4].type == JsonValue::Type::Null);
  CHECK(v->find("a")->find("s")->string == "x\"\\/\n\xc3\xa9\xf0\x9f\x98\x80");  // é and 😀 in UTF-8
  CHECK(v->find("missing") == nullptr);
}

TEST_CASE("numbers read back bit for bit", "[io][json]") {
  const auto v = parseJson("[0.1, 1.0471975511965976, 5e-324, 1.7976931348623157e308]");
  REQUIRE(v.ok());
  CHECK(v->array[0].number == 0.1);
  CHECK(v->array[1].number == 1.0471975511965976);
  CHECK(v->array[2].number == 5e-324);
  CHECK(v->array[3].number == 1.7976931348623157e308);
}

TEST_CASE("malformed JSON is refused with line, column and what was expected", "[io][json][errors]") {
  auto [text, expected] = GENERATE(table<std::string, std::string>({
      {"", "line 1, column 1: unexpected end of the document"},
      {"{\"a\" 1}", "line 1, column 6: expected ':'"},
      {"{\"a\": 1,\n \"b\": }", "line 2, column 7: expected a value"},
      {"[1, 2", "line 1, column 6: expected ',' or ']'"},
      {"[01]", "line 1, column 3: expected ',' or ']'"},
      {"[1.]", "expected a digit after '.'"},
      {"[1e]", "expected an exponent"},
      {"[1e999]", "number out of range"},
      {"\"abc", "unterminated string"},
      {"\"a\tb\"", "control character in string"},
      {"\"\\q\"", "invalid escape in string"},
      {"\"\\u12G4\"", "expected four hex digits"},
      {"\"\\ud800x\"", "invalid surrogate pair"},
      {"[NaN]", "expected a value"},
      {"{a: 1}", "expected a member name in quotes"},
      {"{} {}", "unexpected text after the document"},
      {std::string(100, '[') + std::string(100, ']'), "nesting deeper than 64"},
  }));
  CAPTURE(text);
  const auto v = parseJson(text);
  REQUIRE_FALSE(v.ok());
  CHECK_THAT(v.error().message, Catch::Contains(expected));
}

TEST_CASE("jsonQuote escapes what JSON requires", "[io][json]") {
  CHECK(jsonQuote("mm") == "\"mm\"");
  CHECK(jsonQuote("a\"b\\c\nd\x01") == "\"a\\\"b\\\\c\\nd\\u0001\"");
  const auto back = parseJson(jsonQuote("tab\there \"q\" \x1f"));
  REQUIRE(back.ok());
  CHECK(back->string == "tab\there \"q\" \x1f");
}
