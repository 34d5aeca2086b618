#include "app/cli/text_table.h"

#include "kinematics/io/force_columns.h"
#include "kinematics/io/number_format.h"
#include "kinematics/io/sweep_columns.h"

#include <algorithm>
#include <iomanip>

namespace linkwright::cli {

void writeSweepTable(std::ostream& out, const kinematics::Mechanism& m, const kinematics::SweepResult& r,
                     const kinematics::ForceSweep* forces, int decimals) {
  using kinematics::io::ColumnQuantity;
  std::vector<kinematics::io::SweepColumn> columns;
  for (auto& c : kinematics::io::sweepColumns(m, r.request, !r.time.empty())) {
    // The crank's own ω and α are the constant input: the CSV has them, the table need not.
    const bool crankRate = (c.quantity == ColumnQuantity::LinkOmega || c.quantity == ColumnQuantity::LinkAlpha) &&
                           kinematics::io::isDrivenCrankLink(m, kinematics::LinkId{c.index});
    if (c.quantity <= ColumnQuantity::TransmissionAngle && !crankRate) columns.push_back(std::move(c));
  }
  std::vector<kinematics::io::ForceColumn> forceColumns;
  if (forces)
    for (auto& c : kinematics::io::forceColumns(forces->bodies))
      if (c.isSummary()) forceColumns.push_back(std::move(c));
  std::vector<int> widths;
  auto header = [&](const std::string& name) {
    widths.push_back(std::max(static_cast<int>(name.size()), decimals + 8));
    out << (widths.size() > 1 ? "  " : "") << std::setw(widths.back()) << name;
  };
  for (const auto& c : columns) header(c.name);
  for (const auto& c : forceColumns) header(c.name);
  out << "\n";
  for (std::size_t j = 0; j < r.size(); ++j) {
    if (!r.assembled(j)) continue;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const bool defined = r.ok(j) || !columns[c].isRate();
      const std::string text =
          defined ? kinematics::io::formatFixed(columns[c].value(r, j), decimals) : std::string("toggle");
      out << (c ? "  " : "") << std::setw(widths[c]) << text;
    }
    for (std::size_t c = 0; c < forceColumns.size(); ++c) {
      const std::string text = forces->ok(j) ? kinematics::io::formatFixed(forceColumns[c].value(*forces, j), decimals)
                                             : std::string(r.ok(j) ? "singular" : "toggle");
      out << "  " << std::setw(widths[columns.size() + c]) << text;
    }
    out << "\n";
  }
}

}  // namespace linkwright::cli
