#pragma once
// Reading option values, shared by every command's parser: numbers read with std::from_chars
// (so '.' is the decimal point whatever the locale) and comma-separated lists; every error
// names the option and quotes what was wrong.

#include "kinematics/model/result.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::cli {

/// An error for a bad option: the option as its field, `message` as its sentence.
kinematics::Error usage(const std::string& option, const std::string& message);

/// `text` as a number if all of it is one.
std::optional<double> parseNumber(const std::string& text);

/// `text` split at its commas (one part without a comma).
std::vector<std::string> splitCommas(const std::string& text);

/// `count` comma-separated numbers (0: any number of them); `shape` says what was expected
/// ("two numbers X,Y") in the error.
kinematics::Result<std::vector<double>> parseList(const std::string& option, const std::string& text, std::size_t count,
                                                  const std::string& shape);

}  // namespace linkwright::cli
