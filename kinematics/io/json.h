#pragma once
// JSON for Linkwright's documents, read with nlohmann-json (Debian's nlohmann-json3-dev, a
// well-kept and continuously fuzzed parser) instead of a reader of our own. Objects keep file
// order (ordered_json), numbers outside the double range are refused, and errors give line and
// column. Nesting is limited so a hostile file cannot make a deep tree.

#include "kinematics/model/result.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace linkwright::kinematics::io {

/// A parsed JSON value; objects iterate in file order.
using JsonValue = nlohmann::ordered_json;

/// Maximum nesting of arrays and objects.
inline constexpr int kMaxJsonDepth = 64;

/// Parses a whole document (strict RFC 8259: no comments, no trailing text); the error message
/// says "line L, column C: what went wrong".
Result<JsonValue> parseJson(std::string_view text);

/// The member named `key` of an object, or nullptr (also when `value` is not an object).
const JsonValue* findMember(const JsonValue& value, std::string_view key);

/// Escapes and quotes `text` as a JSON string (invalid UTF-8 becomes U+FFFD).
std::string jsonQuote(std::string_view text);

}  // namespace linkwright::kinematics::io
