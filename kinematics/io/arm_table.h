#pragma once
// The arm's rows (kinematics/design/arm_request.h) as linkwright-cli arm writes them: CSV with
// the unit in every column name and an empty cell where a value does not exist, or an aligned
// table with "singular" or "unreachable" in such a cell. Written once, for the CLI and Python.

#include "kinematics/design/arm_request.h"

#include <ostream>
#include <string>
#include <vector>

namespace linkwright::kinematics::io {

/// Writes the rows to a stream as a run hands them on (runArm's sink), so a table of 10⁷ rows
/// is never held whole: the header when made, each window's rows by write(). CSV (CRLF rows):
/// round-trip doubles, the time column to 12 significant digits (0.03, not
/// 0.029999999999999999); the table: 4 decimals, columns aligned.
class ArmTableWriter {
public:
  ArmTableWriter(std::ostream& out, const std::string& lengthUnit, bool aligned);
  void write(const std::vector<ArmRow>& rows);

private:
  std::ostream& m_out;
  std::vector<ArmColumn> m_columns;
  std::vector<int> m_widths;  ///< per column; empty for CSV
};

/// A run's kept rows as CSV, and as the aligned table.
std::string armCsv(const ArmRun& run);
std::string armTable(const ArmRun& run);

}  // namespace linkwright::kinematics::io
