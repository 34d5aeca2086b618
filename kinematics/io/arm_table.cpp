#include "kinematics/io/arm_table.h"

#include "kinematics/io/csv_writer.h"
#include "kinematics/model/number_text.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace linkwright::kinematics::io {
namespace {

constexpr int kDecimals = 4;

std::string whole(const ArmRun& run, bool aligned) {
  std::ostringstream out;
  ArmTableWriter writer(out, run.lengthUnit, aligned);
  writer.write(run.rows);
  return out.str();
}

}  // namespace

ArmTableWriter::ArmTableWriter(std::ostream& out, const std::string& lengthUnit, bool aligned)
    : m_out(out), m_columns(armColumns(lengthUnit)) {
  for (std::size_t c = 0; c < m_columns.size(); ++c) {
    const std::string& name = m_columns[c].name;
    if (!aligned) {
      m_out << (c ? "," : "") << csvField(name);
      continue;
    }
    m_widths.push_back(std::max(static_cast<int>(name.size()), kDecimals + 8));
    m_out << (c ? "  " : "") << std::setw(m_widths.back()) << name;
  }
  m_out << (aligned ? "\n" : "\r\n");
}

void ArmTableWriter::write(const std::vector<ArmRow>& rows) {
  const bool aligned = !m_widths.empty();
  for (const ArmRow& row : rows) {
    for (std::size_t c = 0; c < m_columns.size(); ++c) {
      const ArmColumn& column = m_columns[c];
      const bool defined = armCellDefined(column, row);
      if (aligned) {
        const std::string text = defined                           ? formatFixed(column.value(row), kDecimals)
                                 : row.reach == ArmReach::Singular ? "singular"
                                                                   : "unreachable";
        m_out << (c ? "  " : "") << std::setw(m_widths[c]) << text;
        continue;
      }
      m_out << (c ? "," : "");
      if (defined)
        m_out << (column.kind == ArmColumn::Kind::Time ? formatShort(column.value(row), 12)
                                                       : formatDouble(column.value(row)));
    }
    m_out << (aligned ? "\n" : "\r\n");
  }
}

std::string armCsv(const ArmRun& run) { return whole(run, false); }
std::string armTable(const ArmRun& run) { return whole(run, true); }

}  // namespace linkwright::kinematics::io
