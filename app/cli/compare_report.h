#pragma once
// `linkwright-cli compare`'s output: what was compared (the table, its layout, the x column,
// the drive, the offset and the tolerance), a line per mapped column (worst and rms deviation,
// tolerance, how many rows are flagged), then the flagged rows of each column; or the same as
// JSON with every row.

#include "kinematics/compare/table_comparison.h"

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>

namespace linkwright::cli {

/// What the report says besides the comparison itself.
struct CompareContext {
  const std::string& tablePath;
  const std::string& source;  ///< "the example NAME", "FILE"
  const kinematics::io::NumericTable& table;
  const kinematics::compare::CompareDrive& drive;
  const kinematics::compare::CompareOptions& options;
  const kinematics::compare::ColumnMapping& mapping;
};

/// The comparison as aligned text for a terminal.
void writeComparisonText(std::ostream& out, const CompareContext& context,
                         const kinematics::compare::Comparison& comparison);

/// The comparison as JSON: the settings, each column's summary and all its rows; `progress`
/// hears how many rows are written as they are.
void writeComparisonJson(std::ostream& out, const CompareContext& context,
                         const kinematics::compare::Comparison& comparison,
                         const std::function<void(std::size_t done, std::size_t total)>& progress = {});

}  // namespace linkwright::cli
