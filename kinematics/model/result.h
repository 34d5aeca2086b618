#pragma once
// Error values and Result<T>: how the core reports user-reachable problems (bad lengths,
// a pose that cannot be assembled, a singular position) without exceptions and without NaN.

#include <string>
#include <utility>
#include <variant>

namespace linkwright::kinematics {

enum class ErrorCode {
  InvalidValue,      ///< a number is non-positive, NaN, infinite or out of its range
  InvalidStructure,  ///< the mechanism's topology is malformed (bad id, wrong order)
  NotAssemblable,    ///< the linkage cannot be assembled at the requested input
  Singular,          ///< the position exists but velocities/accelerations are undefined
  Cancelled,         ///< a long computation was stopped by its caller (a newer one replaced it)
};

/// A user-facing problem: which field is wrong and why, with the offending value.
struct Error {
  ErrorCode code = ErrorCode::InvalidValue;
  std::string field;    ///< e.g. "coupler", "--step", "points[3].length"
  std::string message;  ///< full sentence naming the field and the value
  bool operator==(const Error&) const = default;
};

/// Either a value or an Error. C++20 has no std::expected; this is the small subset we use.
template <typename T>
class [[nodiscard]] Result {
public:
  Result(T value) : m_state(std::move(value)) {}      // NOLINT(google-explicit-constructor)
  Result(Error error) : m_state(std::move(error)) {}  // NOLINT(google-explicit-constructor)

  bool ok() const { return std::holds_alternative<T>(m_state); }
  explicit operator bool() const { return ok(); }

  const T& value() const& { return std::get<T>(m_state); }
  T& value() & { return std::get<T>(m_state); }
  T&& value() && { return std::get<T>(std::move(m_state)); }
  const T& operator*() const& { return value(); }
  const T* operator->() const { return &value(); }

  const Error& error() const { return std::get<Error>(m_state); }

private:
  std::variant<T, Error> m_state;
};

}  // namespace linkwright::kinematics
