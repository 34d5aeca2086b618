#include "app/cli/text_table.h"

#include "kinematics/model/number_text.h"

#include <algorithm>
#include <iomanip>

namespace linkwright::cli {

void SweepTableWriter::writeHeader(const kinematics::SweepResult& r, const kinematics::ForceSweep* forces) {
  using kinematics::ColumnQuantity;
  const kinematics::Mechanism& m = m_mechanism;
  for (auto& c : kinematics::sweepColumns(m, r.request, !r.time.empty())) {
    // The crank's own ω and α are the constant input: the CSV has them, the table need not.
    const bool crankRate = (c.quantity == ColumnQuantity::LinkOmega || c.quantity == ColumnQuantity::LinkAlpha) &&
                           kinematics::isDrivenCrankLink(m, kinematics::LinkId{c.index});
    if (c.quantity <= ColumnQuantity::TransmissionAngle && !crankRate) m_columns.push_back(std::move(c));
  }
  if (forces)
    for (auto& c : kinematics::forceColumns(forces->bodies))
      if (c.isSummary()) m_forceColumns.push_back(std::move(c));
  auto header = [&](const std::string& name) {
    m_widths.push_back(std::max(static_cast<int>(name.size()), m_decimals + 8));
    m_out << (m_widths.size() > 1 ? "  " : "") << std::setw(m_widths.back()) << name;
  };
  for (const auto& c : m_columns) header(c.name);
  for (const auto& c : m_forceColumns) header(c.name);
  m_out << "\n";
}

void SweepTableWriter::write(const kinematics::SweepResult& r, const kinematics::ForceSweep* forces) {
  if (!m_headerWritten) writeHeader(r, forces);
  m_headerWritten = true;
  for (std::size_t j = 0; j < r.size(); ++j) {
    if (!r.assembled(j)) continue;
    for (std::size_t c = 0; c < m_columns.size(); ++c) {
      const bool defined = r.ok(j) || !m_columns[c].isRate();
      const std::string text =
          defined ? kinematics::formatFixed(m_columns[c].value(r, j), m_decimals) : std::string("toggle");
      m_out << (c ? "  " : "") << std::setw(m_widths[c]) << text;
    }
    for (std::size_t c = 0; c < m_forceColumns.size(); ++c) {
      const std::string text = forces->ok(j) ? kinematics::formatFixed(m_forceColumns[c].value(*forces, j), m_decimals)
                                             : std::string(r.ok(j) ? "singular" : "toggle");
      m_out << "  " << std::setw(m_widths[m_columns.size() + c]) << text;
    }
    m_out << "\n";
  }
}

void writeSweepTable(std::ostream& out, const kinematics::Mechanism& m, const kinematics::SweepResult& r,
                     const kinematics::ForceSweep* forces, int decimals) {
  SweepTableWriter(out, m, decimals).write(r, forces);
}

}  // namespace linkwright::cli
