#include "kinematics/compare/column_mapping.h"

#include "kinematics/model/number_text.h"

#include <charconv>
#include <cmath>

namespace linkwright::kinematics::compare {
namespace {

Error mapError(const std::string& field, const std::string& why) { return Error{ErrorCode::InvalidValue, field, why}; }

std::string columnName(std::size_t column) { return "column " + std::to_string(column + 1); }

std::vector<std::string> split(const std::string& text, const std::string& separators) {
  std::vector<std::string> parts(1);
  for (const char c : text) {
    if (separators.find(c) != std::string::npos) parts.emplace_back();
    else if (c != ' ') parts.back() += c;
  }
  return parts;
}

// A value no linkage reaches (1e308 degrees) means a wrong mapping or unit: it would compare
// to nothing meaningful, and an angle would even "agree" modulo a turn.
std::optional<Error> checkMagnitudes(const io::NumericTable& table, std::size_t column, Dimension dimension,
                                     const UnitChoice& unit) {
  const double largest = largestMagnitude(dimension) / std::abs(unit.factor);
  for (const io::NumericRow& row : table.rows) {
    const std::optional<double>& value = row.cells[column];
    if (value && !(std::abs(*value) <= largest))
      return mapError("map", columnName(column) + " holds " + kinematics::formatShort(*value) + " " + unit.name +
                                 " on line " + std::to_string(row.line) + ", beyond the ±" +
                                 kinematics::formatShort(largest, 3) + " " + unit.name + " any " +
                                 dimensionName(dimension) +
                                 " of a linkage stays within: is it mapped to the right quantity and unit?");
  }
  return std::nullopt;
}

std::string quantityList(const Mechanism& m) {
  std::string list;
  for (const CompareQuantity& q : compareQuantities(m)) list += (list.empty() ? "" : ", ") + q.key;
  return list;
}

std::optional<Error> applyFlag(MappedColumn& mapped, const std::string& flag, const std::string& entry) {
  if (flag == "abs" || flag == "magnitude") mapped.magnitude = true;
  else if (flag == "neg" || flag == "negated") mapped.negated = true;
  else if (flag == "rev" || flag == "reversed") mapped.reversed = true;
  else
    return mapError("--map", "--map entry '" + entry + "': unknown flag '" + flag +
                                 "' (flags: abs for a magnitude, neg for the opposite sign, rev for an angle "
                                 "measured from the link's other end)");
  return std::nullopt;
}

// "crank-angle[:UNIT]" or "time[:UNIT]".
Result<AxisColumn> parseAxis(std::size_t column, const std::vector<std::string>& parts, const std::string& entry) {
  const bool angle = parts[1] == "crank-angle";
  AxisColumn axis{column, angle ? AxisKind::CrankAngle : AxisKind::Time,
                  angle ? UnitChoice{"deg", 1.0} : UnitChoice{"s", 1.0}};
  if (parts.size() > 3) return mapError("--map", "--map entry '" + entry + "': the x column takes a unit, no flags");
  if (parts.size() == 3) {
    const Dimension d = angle ? Dimension::Angle : Dimension::Time;
    const auto unit = findUnit(d, "", parts[2]);
    if (!unit)
      return mapError("--map", "--map entry '" + entry + "': unit '" + parts[2] + "' does not fit the " +
                                   (angle ? "crank angle" : "time") + " (accepted: " + unitList(d, "") + ")");
    axis.unit = *unit;
  }
  return axis;
}

Result<MappedColumn> parseQuantity(std::size_t column, const std::vector<std::string>& parts, const std::string& entry,
                                   const Mechanism& m) {
  std::string implied;
  const auto quantity = findQuantity(m, parts[1], &implied);
  if (!quantity)
    return mapError(
        "--map", "--map entry '" + entry + "': '" + parts[1] +
                     "' is not a quantity of this linkage (x: crank-angle, time; quantities: " + quantityList(m) + ")");
  MappedColumn mapped{column, *quantity, unitsFor(quantity->dimension, m.lengthUnit).front()};
  std::size_t next = 2;
  if (implied.empty() && parts.size() > 2) {
    const auto unit = findUnit(quantity->dimension, m.lengthUnit, parts[2]);
    if (!unit)
      return mapError("--map", "--map entry '" + entry + "': unit '" + parts[2] + "' does not fit " + quantity->key +
                                   " (" + dimensionName(quantity->dimension) +
                                   "; accepted: " + unitList(quantity->dimension, m.lengthUnit) + ")");
    mapped.unit = *unit;
    next = 3;
  }
  for (std::size_t i = next; i < parts.size(); ++i)
    if (auto e = applyFlag(mapped, parts[i], entry)) return *e;
  return mapped;
}

}  // namespace

std::string MappedColumn::describe() const {
  std::string text = quantity.key + " " + unit.name;
  if (reversed) text += " rev";
  if (negated) text += " neg";
  if (magnitude) text += " abs";
  return text;
}

std::optional<Error> checkColumnMapping(const ColumnMapping& mapping, const io::NumericTable& table) {
  if (!mapping.axis)
    return mapError("map",
                    "no x column: map one column as the crank angle (crank-angle:deg or :rad) or the time "
                    "(time:s)");
  const std::size_t columns = table.columns();
  std::vector<int> seen(columns, 0);
  const auto claim = [&](std::size_t column) -> std::optional<Error> {
    if (column >= columns)
      return mapError("map", columnName(column) + " is beyond the table, which has " + std::to_string(columns) +
                                 " columns (1 to " + std::to_string(columns) + ")");
    if (seen[column]++) return mapError("map", columnName(column) + " is mapped twice; map each column once");
    return std::nullopt;
  };
  if (auto e = claim(mapping.axis->column)) return e;
  for (const MappedColumn& mapped : mapping.columns) {
    if (auto e = claim(mapped.column)) return e;
    if (mapped.reversed && mapped.quantity.dimension != Dimension::Angle)
      return mapError("map", columnName(mapped.column) +
                                 ": rev (measured from the other end) applies to angles, not to " +
                                 mapped.quantity.key);
    if (mapped.magnitude && mapped.negated)
      return mapError("map", columnName(mapped.column) + ": abs and neg cannot both apply (a magnitude has no sign)");
    bool any = false;
    for (const io::NumericRow& row : table.rows) any = any || row.cells[mapped.column].has_value();
    if (!any) return mapError("map", columnName(mapped.column) + " has no number in any row");
  }
  if (mapping.columns.empty())
    return mapError("map", "no quantity mapped: map at least one column besides the x column");
  for (const io::NumericRow& row : table.rows)
    if (!row.cells[mapping.axis->column])
      return mapError("map", "the x column (" + columnName(mapping.axis->column) + ") is empty on line " +
                                 std::to_string(row.line) + "; every row needs its crank angle or time");
  const Dimension axisDimension = mapping.axis->kind == AxisKind::CrankAngle ? Dimension::Angle : Dimension::Time;
  if (auto e = checkMagnitudes(table, mapping.axis->column, axisDimension, mapping.axis->unit)) return e;
  for (const MappedColumn& mapped : mapping.columns)
    if (auto e = checkMagnitudes(table, mapped.column, mapped.quantity.dimension, mapped.unit)) return e;
  return std::nullopt;
}

Result<ColumnMapping> parseColumnMap(const std::string& text, const Mechanism& m) {
  ColumnMapping mapping;
  for (const std::string& entry : split(text, ",;")) {
    if (entry.empty()) continue;
    const std::size_t eq = entry.find('=');
    std::size_t column = 0;
    const char* end = entry.data() + (eq == std::string::npos ? 0 : eq);
    const auto [ptr, ec] = std::from_chars(entry.data(), end, column);
    if (eq == std::string::npos || ec != std::errc{} || ptr != end || column < 1)
      return mapError("--map", "--map entry '" + entry +
                                   "' must be COLUMN=WHAT[:UNIT][:FLAG...], COLUMN a number from 1 (e.g. "
                                   "3=rocker_omega:deg/s:abs)");
    std::vector<std::string> parts{entry.substr(0, eq)};
    for (const std::string& part : split(entry.substr(eq + 1), ":")) parts.push_back(part);
    if (parts[1] == "crank-angle" || parts[1] == "time") {
      if (mapping.axis)
        return mapError("--map", "--map entry '" + entry + "': the x column is already column " +
                                     std::to_string(mapping.axis->column + 1) + "; a table has one x column");
      auto axis = parseAxis(column - 1, parts, entry);
      if (!axis) return axis.error();
      mapping.axis = *axis;
      continue;
    }
    auto mapped = parseQuantity(column - 1, parts, entry, m);
    if (!mapped) return mapped.error();
    mapping.columns.push_back(*mapped);
  }
  return mapping;
}

std::string formatColumnMap(const ColumnMapping& mapping) {
  std::string text;
  const auto add = [&text](const std::string& entry) { text += (text.empty() ? "" : ",") + entry; };
  if (mapping.axis)
    add(std::to_string(mapping.axis->column + 1) + "=" +
        (mapping.axis->kind == AxisKind::CrankAngle ? "crank-angle:" : "time:") + mapping.axis->unit.name);
  for (const MappedColumn& c : mapping.columns) {
    std::string entry = std::to_string(c.column + 1) + "=" + c.quantity.key + ":" + c.unit.name;
    if (c.reversed) entry += ":rev";
    if (c.negated) entry += ":neg";
    if (c.magnitude) entry += ":abs";
    add(entry);
  }
  return text;
}

}  // namespace linkwright::kinematics::compare
