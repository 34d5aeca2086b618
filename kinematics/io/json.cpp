#include "kinematics/io/json.h"

#include <regex>

namespace linkwright::kinematics::io {
namespace {

// Thrown by the depth check inside nlohmann's parse callback, which has no other way out.
struct TooDeep {};

// nlohmann says "[json.exception.parse_error.101] parse error at line 2, column 7: syntax
// error while parsing value - unexpected '}'; expected '[', '{', or a literal"; the document
// readers say "line 2, column 7: syntax error while parsing value - …".
std::string withoutPrefix(const nlohmann::json::exception& e) {
  static const std::regex prefix(R"(^\[json\.exception\.[a-z_]+\.\d+\] (parse error at )?)");
  return std::regex_replace(e.what(), prefix, "");
}

}  // namespace

Result<JsonValue> parseJson(std::string_view text) {
  const auto limitDepth = [](int depth, JsonValue::parse_event_t, JsonValue&) {
    if (depth >= kMaxJsonDepth) throw TooDeep{};  // depth counts the enclosing levels
    return true;
  };
  // nlohmann-json words an empty input differently from one version to the next (3.11.3:
  // "attempting to parse an empty input…"); say it as for any other input that ends too soon.
  if (text.empty()) {
    return Error{ErrorCode::InvalidValue, "json",
                 "line 1, column 1: syntax error while parsing value - unexpected end of input; expected '[', "
                 "'{', or a literal"};
  }
  try {
    return JsonValue::parse(text.begin(), text.end(), limitDepth);
  } catch (const nlohmann::json::parse_error& e) {
    return Error{ErrorCode::InvalidValue, "json", withoutPrefix(e)};
  } catch (const nlohmann::json::out_of_range& e) {
    // A number beyond the double range: "number overflow parsing '1e999'" (no position).
    return Error{ErrorCode::InvalidValue, "json", withoutPrefix(e) + ": beyond the range of a double (±1.8e308)"};
  } catch (const TooDeep&) {
    return Error{ErrorCode::InvalidValue, "json",
                 "nesting deeper than " + std::to_string(kMaxJsonDepth) + " arrays and objects"};
  }
}

const JsonValue* findMember(const JsonValue& value, std::string_view key) {
  if (!value.is_object()) return nullptr;
  const auto it = value.find(std::string(key));
  return it == value.end() ? nullptr : &*it;
}

std::string jsonQuote(std::string_view text) {
  return JsonValue(std::string(text)).dump(-1, ' ', false, JsonValue::error_handler_t::replace);
}

}  // namespace linkwright::kinematics::io
