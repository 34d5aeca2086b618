#include "kinematics/io/json.h"

#include <regex>

namespace linkwright::kinematics::io {
namespace {

// Thrown by the depth check inside nlohmann's parse callback, which has no other way out.
struct TooDeep {};

// nlohmann says "[json.exception.parse_error.101] parse error at line 2, column 7: syntax
// error while parsing value - unexpected '}'; expected '[', '{', or a literal"; the document
// readers say "line 2, column 7: syntax error while parsing value - …".
// The length of the UTF-8 sequence at text[i] (RFC 3629: no overlong form, no surrogate, at most
// U+10FFFF), 0 if it is not one.
std::size_t utf8Length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u; };
  const unsigned c = byte(0);
  const auto tail = [&](std::size_t k) { return (byte(k) & 0xC0u) == 0x80u; };
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) return tail(1) ? 2 : 0;
  if (c >= 0xE0 && c <= 0xEF) {
    const unsigned lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
    return byte(1) >= lo && byte(1) <= hi && tail(2) ? 3 : 0;
  }
  if (c >= 0xF0 && c <= 0xF4) {
    const unsigned lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
    return byte(1) >= lo && byte(1) <= hi && tail(2) && tail(3) ? 4 : 0;
  }
  return 0;
}

// nlohmann's message quotes the bytes it last read, which in a file that is not UTF-8 are not
// text: each such byte is shown as \xNN, so the message is UTF-8 wherever it is shown.
std::string asText(std::string_view text) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (const std::size_t n = utf8Length(text, i); n > 0) {
      out.append(text.substr(i, n));
      i += n;
    } else {
      const auto c = static_cast<unsigned char>(text[i++]);
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 0xF];
    }
  }
  return out;
}

std::string withoutPrefix(const nlohmann::json::exception& e) {
  static const std::regex prefix(R"(^\[json\.exception\.[a-z_]+\.\d+\] (parse error at )?)");
  return asText(std::regex_replace(e.what(), prefix, ""));
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
