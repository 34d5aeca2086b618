#pragma once
// A small strict JSON (RFC 8259) reader for Linkwright's documents. The core depends on Eigen
// and the standard library only, and documents need just this: values, objects in file
// order, numbers read with std::from_chars (locale-independent), and errors with line and
// column. Nesting is limited so a hostile file cannot exhaust the stack.

#include "kinematics/model/result.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace linkwright::kinematics::io {

struct JsonValue {
  enum class Type { Null, Bool, Number, String, Array, Object };
  Type type = Type::Null;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<JsonValue> array;
  std::vector<std::pair<std::string, JsonValue>> object;  ///< members in file order

  /// The member named `key` of an object, or nullptr.
  const JsonValue* find(std::string_view key) const;
};

/// Maximum nesting of arrays and objects.
inline constexpr int kMaxJsonDepth = 64;

/// Parses a whole document; the error message says "line L, column C: what was expected".
Result<JsonValue> parseJson(std::string_view text);

/// Escapes and quotes `text` as a JSON string.
std::string jsonQuote(std::string_view text);

} // namespace linkwright::kinematics::io
