#include "kinematics/io/csv_writer.h"

#include "kinematics/io/force_columns.h"
#include "kinematics/io/number_format.h"
#include "kinematics/io/sweep_columns.h"

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

namespace {

void writeCsv(std::ostream& out, const Mechanism& m, const SweepResult& r, const ForceSweep* forces) {
  const std::vector<SweepColumn> columns = sweepColumns(m, r.request, !r.time.empty());
  const std::vector<ForceColumn> forceCols = forces ? forceColumns(forces->bodies) : std::vector<ForceColumn>{};
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << csvField(columns[c].name);
  for (const ForceColumn& c : forceCols) out << ',' << csvField(c.name);
  out << kLineEnd;
  std::string row;
  for (std::size_t j = 0; j < r.size(); ++j) {
    if (!r.assembled(j)) continue;
    row.clear();
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c) row += ',';
      // At a toggle the rates do not exist: leave the cell empty.
      if (r.ok(j) || !columns[c].isRate()) row += cellText(columns[c], r, j);
    }
    for (const ForceColumn& c : forceCols) {
      row += ',';
      if (forces->ok(j)) row += formatDouble(c.value(*forces, j));
    }
    out << row << kLineEnd;
  }
}

}  // namespace

void writeSweepCsv(std::ostream& out, const Mechanism& m, const SweepResult& r) { writeCsv(out, m, r, nullptr); }

void writeSweepCsv(std::ostream& out, const Mechanism& m, const SweepResult& r, const ForceSweep& forces) {
  writeCsv(out, m, r, &forces);
}

}  // namespace linkwright::kinematics::io
