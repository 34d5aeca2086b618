#include "app/cli/commands.h"

#include "kinematics/analysis/extrema.h"
#include "kinematics/io/column_extrema.h"
#include "kinematics/io/number_format.h"
#include "kinematics/io/sweep_columns.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"

#include <functional>
#include <iomanip>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;

// Refines the extremes of a quantity known at each sample (where `valid`) and on a pose.
std::optional<k::Extrema> refineOver(const k::Mechanism& m, const k::SweepSpec& spec, const k::SweepResult& r,
                                     const std::function<bool(std::size_t)>& valid,
                                     const std::function<double(std::size_t)>& sampled,
                                     const k::PoseQuantity& quantity) {
  std::vector<double> values(r.size(), 0.0);
  std::vector<bool> mask(r.size(), false);
  for (std::size_t j = 0; j < r.size(); ++j) {
    mask[j] = valid(j);
    if (mask[j]) values[j] = sampled(j);
  }
  return k::refineExtrema(m, spec, values, mask, quantity);
}

// Where an extremum is: the input (a crank's angle in degrees) on an input grid, the instant
// on a time base.
std::string whereText(const k::Mechanism& m, const k::Extremum& e, bool timeBase) {
  return timeBase ? k::io::formatFixed(e.time, 6) : k::io::formatFixed(k::inputDisplayValue(m, e.inputAngle), 4);
}

void printRow(std::ostream& out, const k::Mechanism& m, const std::string& name, const k::Extrema& e, bool timeBase) {
  out << std::left << std::setw(26) << name << std::right << std::setw(18) << k::io::formatShort(e.minimum.value, 9)
      << std::setw(14) << whereText(m, e.minimum, timeBase) << std::setw(18) << k::io::formatShort(e.maximum.value, 9)
      << std::setw(14) << whereText(m, e.maximum, timeBase) << "\n";
}

}  // namespace

ExitCode runExtremes(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto fail = [&](const k::Error& e) {
    err << "linkwright-cli: " << e.message << "\n";
    return ExitCode::BadInput;
  };
  const auto swept = sweepInvocation(inv);
  if (!swept) return fail(swept.error());
  const auto* resolved = &swept->resolved;
  const auto* spec = &swept->spec;
  const auto* result = &swept->result;

  const bool timeBase = spec->time.has_value();
  const k::Mechanism& linkage = resolved->mechanism;
  const bool crank = k::inputKind(linkage) == k::InputKind::Angle;
  const std::string rateUnit = crank ? "rad/s" : linkage.lengthUnit + "/s";
  if (timeBase)
    out << "extremes over times " << k::io::formatShort(spec->time->fromTime) << " s to "
        << k::io::formatShort(spec->time->toTime) << " s, refined between " << spec->samples << " samples; the "
        << (crank ? "crank" : "driver") << " follows its motion law\n";
  else if (crank)
    out << "extremes over crank angles " << k::io::formatShort(k::radToDeg(spec->fromAngle)) << "° to "
        << k::io::formatShort(k::radToDeg(spec->toAngle)) << "°, refined between " << spec->samples
        << " samples; crank " << k::io::formatShort(spec->omega) << " rad/s, " << k::io::formatShort(spec->alpha)
        << " rad/s²\n";
  else
    out << "extremes over " << k::inputName(linkage) << " " << k::io::formatShort(spec->fromAngle) << " to "
        << k::io::formatShort(spec->toAngle) << " " << linkage.lengthUnit << ", refined between " << spec->samples
        << " samples; driver " << k::io::formatShort(spec->omega) << " " << rateUnit << ", "
        << k::io::formatShort(spec->alpha) << " " << rateUnit << "²\n";
  const char* where = timeBase ? "at time_s" : crank ? "at crank_deg" : "at input";
  out << std::left << std::setw(26) << "quantity" << std::right << std::setw(18) << "minimum" << std::setw(14) << where
      << std::setw(18) << "maximum" << std::setw(14) << where << "\n";
  for (const k::io::SweepColumn& column : k::io::sweepColumns(resolved->mechanism, result->request)) {
    if (column.quantity == k::io::ColumnQuantity::InputAngle || column.quantity == k::io::ColumnQuantity::InputLength)
      continue;
    if (const auto e = k::io::columnExtrema(resolved->mechanism, *spec, *result, column))
      printRow(out, resolved->mechanism, column.name, *e, timeBase);
  }
  // Speed and acceleration magnitudes of each moving point: what seed 003 reports.
  const k::Mechanism& m = resolved->mechanism;
  const std::string& u = m.lengthUnit;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    if (std::holds_alternative<k::GroundPoint>(m.points[i].definition)) continue;
    const auto ok = [&](std::size_t j) { return result->ok(j); };
    const auto speed = refineOver(
        m, *spec, *result, ok, [&](std::size_t j) { return result->velocity[i][j].norm(); },
        [i](const k::Pose& p, double) { return p.velocity[i].norm(); });
    if (speed) printRow(out, resolved->mechanism, m.points[i].name + "_speed_" + u + "_s", *speed, timeBase);
    const auto accel = refineOver(
        m, *spec, *result, ok, [&](std::size_t j) { return result->acceleration[i][j].norm(); },
        [i](const k::Pose& p, double) { return p.acceleration[i].norm(); });
    if (accel) printRow(out, resolved->mechanism, m.points[i].name + "_accel_" + u + "_s2", *accel, timeBase);
  }
  noteLocks(resolved->mechanism, result->lockedBetween, err);
  if (!result->notAssembled.empty()) {
    err << "linkwright-cli: the linkage cannot be assembled over the whole range; extremes are over the part that "
           "can\n";
    return ExitCode::NotAssemblable;
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
