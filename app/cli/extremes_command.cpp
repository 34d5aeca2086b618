#include "app/cli/commands.h"
#include "app/cli/progress.h"

#include "kinematics/analysis/column_extrema.h"
#include "kinematics/analysis/extrema.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/sweep_columns.h"

#include <iomanip>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;

// Where an extremum is: the input (a crank's angle in degrees) on an input grid, the instant
// on a time base.
std::string whereText(const k::Mechanism& m, const k::Extremum& e, bool timeBase) {
  return timeBase ? k::formatFixed(e.time, 6) : k::formatFixed(k::inputDisplayValue(m, e.inputAngle), 4);
}

void printRow(std::ostream& out, const k::Mechanism& m, const std::string& name, const k::Extrema& e, bool timeBase) {
  out << std::left << std::setw(26) << name << std::right << std::setw(18) << k::formatShort(e.minimum.value, 9)
      << std::setw(14) << whereText(m, e.minimum, timeBase) << std::setw(18) << k::formatShort(e.maximum.value, 9)
      << std::setw(14) << whereText(m, e.maximum, timeBase) << "\n";
}

}  // namespace

ExitCode runExtremes(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto fail = [&](const k::Error& e) {
    err << "linkwright-cli: " << e.message << "\n";
    return ExitCode::BadInput;
  };
  const auto resolved = resolveMechanism(inv);
  if (!resolved) return fail(resolved.error());
  const auto spec = sweepSpecFor(inv, resolved->defaults);
  if (!spec) return fail(spec.error());
  const k::Mechanism& m = resolved->mechanism;

  // The sweep is scanned a window at a time: each column's and each point's best samples are
  // kept, never the columns, and refined between their neighbours afterwards.
  std::vector<k::ColumnExtremaScan> columns;
  std::vector<std::size_t> moving;  // the moving points: their speeds and accelerations
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (!std::holds_alternative<k::GroundPoint>(m.points[i].definition)) moving.push_back(i);
  std::vector<k::SampledExtrema> speeds(moving.size()), accels(moving.size());
  Progress progress(err, "extremes", "samples");
  const auto summary =
      k::sweepInWindows(m, *spec, {}, k::kSweepWindow, [&](const k::SweepResult& part, std::size_t first) {
        if (first == 0)
          for (const k::SweepColumn& column : k::sweepColumns(m, part.request))
            if (column.quantity != k::ColumnQuantity::InputAngle && column.quantity != k::ColumnQuantity::InputLength)
              columns.emplace_back(column);
        for (k::ColumnExtremaScan& scan : columns) scan.add(part, first);
        for (std::size_t p = 0; p < moving.size(); ++p) {
          const std::size_t i = moving[p];
          for (std::size_t j = 0; j < part.size(); ++j) {
            const bool ok = part.ok(j);
            speeds[p].add(first + j, ok, ok ? part.velocity[i][j].norm() : 0.0);
            accels[p].add(first + j, ok, ok ? part.acceleration[i][j].norm() : 0.0);
          }
        }
        progress.update(first + part.size(), spec->samples);
        return true;
      });
  if (!summary) return fail(summary.error());

  const bool timeBase = spec->time.has_value();
  const bool crank = k::inputKind(m) == k::InputKind::Angle;
  const std::string rateUnit = crank ? "rad/s" : m.lengthUnit + "/s";
  if (timeBase)
    out << "extremes over times " << k::formatShort(spec->time->fromTime) << " s to "
        << k::formatShort(spec->time->toTime) << " s, refined between " << spec->samples << " samples; the "
        << (crank ? "crank" : "driver") << " follows its motion law\n";
  else if (crank)
    out << "extremes over crank angles " << k::formatShort(k::radToDeg(spec->fromAngle)) << "° to "
        << k::formatShort(k::radToDeg(spec->toAngle)) << "°, refined between " << spec->samples << " samples; crank "
        << k::formatShort(spec->omega) << " rad/s, " << k::formatShort(spec->alpha) << " rad/s²\n";
  else
    out << "extremes over " << k::inputName(m) << " " << k::formatShort(spec->fromAngle) << " to "
        << k::formatShort(spec->toAngle) << " " << m.lengthUnit << ", refined between " << spec->samples
        << " samples; driver " << k::formatShort(spec->omega) << " " << rateUnit << ", " << k::formatShort(spec->alpha)
        << " " << rateUnit << "²\n";
  const char* where = timeBase ? "at time_s" : crank ? "at crank_deg" : "at input";
  out << std::left << std::setw(26) << "quantity" << std::right << std::setw(18) << "minimum" << std::setw(14) << where
      << std::setw(18) << "maximum" << std::setw(14) << where << "\n";
  for (const k::ColumnExtremaScan& scan : columns)
    if (const auto e = scan.refine(m, *spec)) printRow(out, m, scan.column().name, *e, timeBase);
  // Speed and acceleration magnitudes of each moving point: what seed 003 reports.
  const std::string& u = m.lengthUnit;
  for (std::size_t p = 0; p < moving.size(); ++p) {
    const std::size_t i = moving[p];
    const auto speed =
        k::refineExtrema(m, *spec, speeds[p], [i](const k::Pose& pose, double) { return pose.velocity[i].norm(); });
    if (speed) printRow(out, m, m.points[i].name + "_speed_" + u + "_s", *speed, timeBase);
    const auto accel =
        k::refineExtrema(m, *spec, accels[p], [i](const k::Pose& pose, double) { return pose.acceleration[i].norm(); });
    if (accel) printRow(out, m, m.points[i].name + "_accel_" + u + "_s2", *accel, timeBase);
  }
  noteLocks(m, summary->lockedBetween, err);
  if (!summary->notAssembled.empty()) {
    err << "linkwright-cli: the linkage cannot be assembled over the whole range; extremes are over the part that "
           "can\n";
    return ExitCode::NotAssemblable;
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
