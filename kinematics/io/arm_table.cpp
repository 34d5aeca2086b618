#include "kinematics/io/arm_table.h"

#include "kinematics/io/csv_writer.h"
#include "kinematics/model/number_text.h"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <vector>

namespace linkwright::kinematics::io {

std::string armCsv(const ArmRun& run) {
  const std::vector<ArmColumn> columns = armColumns(run.lengthUnit);
  std::ostringstream out;
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << csvField(columns[c].name);
  out << "\r\n";
  for (const ArmRow& row : run.rows) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      out << (c ? "," : "");
      if (!armCellDefined(columns[c], row)) continue;
      const double value = columns[c].value(row);
      out << (columns[c].kind == ArmColumn::Kind::Time ? formatShort(value, 12) : formatDouble(value));
    }
    out << "\r\n";
  }
  return out.str();
}

std::string armTable(const ArmRun& run) {
  constexpr int kDecimals = 4;
  const std::vector<ArmColumn> columns = armColumns(run.lengthUnit);
  std::ostringstream out;
  std::vector<int> widths;
  for (const ArmColumn& c : columns) {
    widths.push_back(std::max(static_cast<int>(c.name.size()), kDecimals + 8));
    out << (widths.size() > 1 ? "  " : "") << std::setw(widths.back()) << c.name;
  }
  out << "\n";
  for (const ArmRow& row : run.rows) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::string text = armCellDefined(columns[c], row)   ? formatFixed(columns[c].value(row), kDecimals)
                               : row.reach == ArmReach::Singular ? "singular"
                                                                 : "unreachable";
      out << (c ? "  " : "") << std::setw(widths[c]) << text;
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace linkwright::kinematics::io
