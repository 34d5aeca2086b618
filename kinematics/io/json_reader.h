#pragma once
// Typed access to the members of a parsed JSON document (json.h) for the document readers.
// The first failure is kept, and names the member's full path ("mechanism.points[2].length"),
// so a reader can go on reading and report one clear error at the end.

#include "kinematics/io/json.h"
#include "kinematics/model/result.h"

#include <optional>
#include <string>

namespace linkwright::kinematics::io {

class JsonReader {
public:
  std::optional<Error> error;

  /// The object member `key` of `parent`; nullptr if missing (an error if `required`).
  const JsonValue* object(const JsonValue& parent, const std::string& key, const std::string& path,
                          bool required = true);
  /// The array member `key` of `parent`; nullptr if missing (an error if `required`).
  const JsonValue* array(const JsonValue& parent, const std::string& key, const std::string& path,
                         bool required = true);
  std::optional<double> number(const JsonValue& parent, const std::string& key, const std::string& path);
  /// A number that must be positive and finite.
  std::optional<double> positive(const JsonValue& parent, const std::string& key, const std::string& path);
  std::optional<std::string> string(const JsonValue& parent, const std::string& key, const std::string& path);
  /// Whether `parent` has a member `key` (any type).
  static bool has(const JsonValue& parent, const std::string& key) { return findMember(parent, key) != nullptr; }

  /// Records `path + " " + why` as the error unless one is recorded already.
  std::nullptr_t fail(const std::string& path, const std::string& why);

private:
  const JsonValue* member(const JsonValue& parent, const std::string& key, const std::string& path, bool required);
};

}  // namespace linkwright::kinematics::io
