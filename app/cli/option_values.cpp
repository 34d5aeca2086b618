#include "app/cli/option_values.h"

#include <charconv>

namespace linkwright::cli {

kinematics::Error usage(const std::string& option, const std::string& message) {
  return kinematics::Error{kinematics::ErrorCode::InvalidValue, option, message};
}

std::optional<double> parseNumber(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc{} || ptr != end || text.empty()) return std::nullopt;
  return value;
}

std::vector<std::string> splitCommas(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1)
    parts.push_back(text.substr(start, comma - start));
  parts.push_back(text.substr(start));
  return parts;
}

kinematics::Result<std::vector<double>> parseList(const std::string& option, const std::string& text, std::size_t count,
                                                  const std::string& shape) {
  const std::vector<std::string> parts = splitCommas(text);
  if (count != 0 && parts.size() != count) return usage(option, option + " expects " + shape + " (got '" + text + "')");
  std::vector<double> values;
  for (const std::string& part : parts) {
    const auto value = parseNumber(part);
    if (!value) return usage(option, option + ": '" + part + "' is not a number (expected " + shape + ")");
    values.push_back(*value);
  }
  return values;
}

}  // namespace linkwright::cli
