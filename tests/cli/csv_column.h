#pragma once
// Reads one named column of a CLI's CSV output as numbers, for tests that check a column
// against an independent computation.

#include "tests/support/catch.h"

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace linkwright::test {

inline std::vector<std::string> splitText(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream s(text);
  for (std::string part; std::getline(s, part, separator);) parts.push_back(part);
  return parts;
}

/// The values of the column headed `name` in `csv` (a header line, then one row a line).
inline std::vector<double> csvColumn(const std::string& csv, const std::string& name) {
  const std::vector<std::string> rows = splitText(csv, '\n');
  REQUIRE_FALSE(rows.empty());
  const std::vector<std::string> header = splitText(rows[0], ',');
  const auto found = std::find(header.begin(), header.end(), name);
  REQUIRE(found != header.end());
  const auto column = static_cast<std::size_t>(found - header.begin());
  std::vector<double> values;
  for (std::size_t i = 1; i < rows.size(); ++i) values.push_back(std::stod(splitText(rows[i], ',')[column]));
  return values;
}

}  // namespace linkwright::test
