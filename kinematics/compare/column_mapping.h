#pragma once
// Which column of another tool's table holds what: one column is the x of the table, the crank
// angle (deg or rad) or the time (s, ms, min); each other mapped column is a quantity of
// compare_quantity.h in a unit, as the other tool writes it: as is or negated, signed or a
// magnitude (SolidWorks Motion writes |ω|), and for an angle, measured from the link's other
// end (θ + 180°: SolidWorks' "inner" rocker angle). Columns are numbered from 1 in text and
// messages, from 0 in the structs. The text form is the CLI's --map:
//   1=crank-angle:deg,3=coupler_angle:deg,4=rocker_angle:deg:rev,5=rocker_omega:deg/s:abs
// entries COLUMN=WHAT[:UNIT][:FLAG...] separated by ',' (or ';'), WHAT "crank-angle", "time"
// or a quantity key (or a full analyze column name, which brings its unit); flags abs
// (magnitude), neg (negated), rev (reversed angle).

#include "kinematics/compare/compare_quantity.h"
#include "kinematics/io/numeric_table_csv.h"
#include "kinematics/model/result.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics::compare {

/// What the table's x column is.
enum class AxisKind { CrankAngle, Time };

/// The table's x: the crank angle or the time, in `unit` (its factor gives degrees or seconds).
struct AxisColumn {
  std::size_t column = 0;  ///< 0-based
  AxisKind kind = AxisKind::CrankAngle;
  UnitChoice unit{"deg", 1.0};
};

/// A column compared with a quantity of the exact solution.
struct MappedColumn {
  std::size_t column = 0;  ///< 0-based
  CompareQuantity quantity;
  UnitChoice unit;
  bool negated = false;    ///< the tool's sign convention is the opposite of ours (CW positive)
  bool magnitude = false;  ///< the tool writes |value|
  bool reversed = false;   ///< an angle measured from the link's other end: ours + 180°

  /// "rocker_omega deg/s abs": the quantity, its unit and flags, as a table heading.
  std::string describe() const;
};

/// The whole mapping of a table.
struct ColumnMapping {
  std::optional<AxisColumn> axis;
  std::vector<MappedColumn> columns;
};

/// Error (field "map") naming the column and what is wrong, or nullopt: no x column, a column
/// beyond the table's, a column mapped twice, an x column with an empty cell, a mapped column
/// without a number, a flag that does not fit the quantity (rev on a non-angle; abs with neg).
std::optional<Error> checkColumnMapping(const ColumnMapping& mapping, const io::NumericTable& table);

/// The mapping the --map text gives for `mechanism`, or an Error (field "--map") naming the
/// entry, the value and what is accepted (quantities, units). Not checked against a table.
Result<ColumnMapping> parseColumnMap(const std::string& text, const Mechanism& mechanism);

/// The --map text of `mapping` (parseColumnMap reads it back).
std::string formatColumnMap(const ColumnMapping& mapping);

}  // namespace linkwright::kinematics::compare
