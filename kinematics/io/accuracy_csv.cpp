#include "kinematics/io/accuracy_csv.h"

#include "kinematics/io/csv_writer.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"

#include <sstream>

namespace linkwright::kinematics::io {

std::vector<std::string> accuracyColumns() {
  return {"example",         "method",          "samples_per_rev",        "time_us",         "omega_rel_error",
          "alpha_rel_error", "speed_rel_error", "acceleration_rel_error", "angle_error_deg", "reference"};
}

std::string accuracyCsv(const std::vector<AccuracyRow>& rows) {
  std::vector<std::vector<std::string>> table{accuracyColumns()};
  for (const AccuracyRow& r : rows)
    table.push_back({r.example, r.method, std::to_string(r.samples), formatShort(r.microseconds, 4),
                     formatShort(r.error.omega, 3), formatShort(r.error.alpha, 3), formatShort(r.error.speed, 3),
                     formatShort(r.error.acceleration, 3), formatShort(radToDeg(r.error.angle), 3), r.reference});
  std::ostringstream out;
  for (const auto& cells : table) {
    for (std::size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << csvField(cells[i]);
    out << "\r\n";  // RFC 4180, as every CSV Linkwright writes
  }
  return out.str();
}

}  // namespace linkwright::kinematics::io
