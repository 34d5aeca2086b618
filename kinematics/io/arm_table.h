#pragma once
// The arm's rows (kinematics/design/arm_request.h) as linkwright-cli arm writes them: CSV with
// the unit in every column name and an empty cell where a value does not exist, or an aligned
// table with "singular" or "unreachable" in such a cell. Written once, for the CLI and Python.

#include "kinematics/design/arm_request.h"

#include <string>

namespace linkwright::kinematics::io {

/// CSV (CRLF rows): round-trip doubles, the time column to 12 significant digits (0.03, not
/// 0.029999999999999999).
std::string armCsv(const ArmRun& run);

/// The same rows as a table for people: 4 decimals, columns aligned.
std::string armTable(const ArmRun& run);

}  // namespace linkwright::kinematics::io
