#include "kinematics/io/json_reader.h"

#include "kinematics/model/number_text.h"

#include <cmath>

namespace linkwright::kinematics::io {

const JsonValue* JsonReader::object(const JsonValue& parent, const std::string& key, const std::string& path,
                                    bool required) {
  const JsonValue* v = member(parent, key, path, required);
  if (v != nullptr && !v->is_object()) return fail(path, "must be an object");
  return v;
}

const JsonValue* JsonReader::array(const JsonValue& parent, const std::string& key, const std::string& path,
                                   bool required) {
  const JsonValue* v = member(parent, key, path, required);
  if (v != nullptr && !v->is_array()) return fail(path, "must be an array");
  return v;
}

std::optional<double> JsonReader::number(const JsonValue& parent, const std::string& key, const std::string& path) {
  const JsonValue* v = member(parent, key, path, true);
  if (v == nullptr) return std::nullopt;
  if (!v->is_number()) {
    fail(path, "must be a number");
    return std::nullopt;
  }
  return v->get<double>();
}

std::optional<double> JsonReader::positive(const JsonValue& parent, const std::string& key, const std::string& path) {
  const auto v = number(parent, key, path);
  if (v && !(*v > 0.0)) {
    fail(path, "must be positive and finite (got " + formatShort(*v) + ")");
    return std::nullopt;
  }
  return v;
}

std::optional<std::string> JsonReader::string(const JsonValue& parent, const std::string& key,
                                              const std::string& path) {
  const JsonValue* v = member(parent, key, path, true);
  if (v == nullptr) return std::nullopt;
  if (!v->is_string()) {
    fail(path, "must be a string");
    return std::nullopt;
  }
  return v->get<std::string>();
}

std::nullptr_t JsonReader::fail(const std::string& path, const std::string& why) {
  if (!error) error = Error{ErrorCode::InvalidValue, path, path + " " + why};
  return nullptr;
}

const JsonValue* JsonReader::member(const JsonValue& parent, const std::string& key, const std::string& path,
                                    bool required) {
  if (error) return nullptr;
  const JsonValue* v = findMember(parent, key);
  if (v == nullptr && required) return fail(path, "is missing");
  return v;
}

}  // namespace linkwright::kinematics::io
