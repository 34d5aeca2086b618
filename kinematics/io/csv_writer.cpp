#include "kinematics/io/csv_writer.h"

#include "kinematics/model/number_text.h"

namespace linkwright::kinematics::io {
namespace {

constexpr const char* kLineEnd = "\r\n";

// The input and time columns are the requested grid: 12 significant digits print 30 as "30",
// not as the radian round trip "29.999999999999996", and 3 × 0.01 s as "0.03".
std::string cellText(const SweepColumn& column, const SweepResult& r, std::size_t j) {
  const double value = column.value(r, j);
  const bool grid = column.quantity == ColumnQuantity::InputAngle || column.quantity == ColumnQuantity::InputLength ||
                    column.quantity == ColumnQuantity::Time;
  return grid ? formatShort(value, 12) : formatDouble(value);
}

}  // namespace

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::vector<std::string> sweepCsvHeader(const Mechanism& m, const SolveRequest& request) {
  std::vector<std::string> names;
  for (const SweepColumn& c : sweepColumns(m, request)) names.push_back(c.name);
  return names;
}

void SweepCsvWriter::write(const SweepResult& r, const ForceSweep* forces) {
  if (!m_headerWritten) {
    m_columns = sweepColumns(m_mechanism, r.request, !r.time.empty());
    m_forceColumns = forces ? forceColumns(forces->bodies) : std::vector<ForceColumn>{};
    for (std::size_t c = 0; c < m_columns.size(); ++c) m_out << (c ? "," : "") << csvField(m_columns[c].name);
    for (const ForceColumn& c : m_forceColumns) m_out << ',' << csvField(c.name);
    m_out << kLineEnd;
    m_headerWritten = true;
  }
  for (std::size_t j = 0; j < r.size(); ++j) {
    if (!r.assembled(j)) continue;
    m_row.clear();
    for (std::size_t c = 0; c < m_columns.size(); ++c) {
      if (c) m_row += ',';
      // At a toggle the rates do not exist: leave the cell empty.
      if (r.ok(j) || !m_columns[c].isRate()) m_row += cellText(m_columns[c], r, j);
    }
    for (const ForceColumn& c : m_forceColumns) {
      m_row += ',';
      if (forces->ok(j)) m_row += formatDouble(c.value(*forces, j));
    }
    m_out << m_row << kLineEnd;
  }
}

void writeSweepCsv(std::ostream& out, const Mechanism& m, const SweepResult& r) { SweepCsvWriter(out, m).write(r); }

void writeSweepCsv(std::ostream& out, const Mechanism& m, const SweepResult& r, const ForceSweep& forces) {
  SweepCsvWriter(out, m).write(r, &forces);
}

}  // namespace linkwright::kinematics::io
