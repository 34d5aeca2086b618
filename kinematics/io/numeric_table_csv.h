#pragma once
// A table of numbers exported by another tool (SolidWorks Motion, MATLAB, Excel, NX), read
// from CSV text for a comparison (kinematics/compare/). The delimiter is found from the
// first lines: a tab, else ';', else ','. With ';' or a tab, a decimal comma is read as a
// decimal point (European Excel writes "33,28;-121,51"; a ',' delimiter keeps '.' only).
// Header rows are the lines before the first numeric row, however many there are; each
// column's label joins their cells. A numeric row is one whose cells are all numbers or empty,
// at least one a number. After the first numeric row, blank lines and lines starting with
// '#' are skipped; any other line that is not numeric is an error naming it. Each column also
// keeps the precision it is printed to (two decimals: 0.005), the table's own rounding.

#include "kinematics/model/result.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace linkwright::kinematics::io {

/// A bound that keeps a wrong file (an image, a device) out; exports are far smaller.
inline constexpr std::size_t kMaxNumericTableBytes = 64u << 20;

/// One numeric row as read: a cell per column, empty where the file's cell is empty.
struct NumericRow {
  int line = 0;  ///< the 1-based line of the file it came from, for messages
  std::vector<std::optional<double>> cells;
  bool operator==(const NumericRow&) const = default;
};

/// The numbers of a table, with what was detected about its layout.
struct NumericTable {
  char delimiter = ',';             ///< ',', ';' or '\t'
  bool decimalComma = false;        ///< true when a ',' inside a cell was read as the decimal point
  std::vector<std::string> labels;  ///< per column: its header cells joined by spaces ("" without a header)
  std::vector<double> rounding;     ///< per column: half a unit in the last printed digit (0.005 for "33,28")
  std::vector<NumericRow> rows;     ///< at least one
  bool operator==(const NumericTable&) const = default;

  /// The number of columns: the widest row's or header's.
  std::size_t columns() const { return labels.size(); }
};

/// The table in `text`, or an Error (field "csv") naming the line and what is wrong: no
/// numeric row at all, a non-numeric line after the numbers began, a file over the bound.
Result<NumericTable> readNumericTable(std::string_view text);

}  // namespace linkwright::kinematics::io
