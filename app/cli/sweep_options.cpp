#include "app/cli/commands.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <cmath>
#include <tuple>

namespace linkwright::cli {
namespace {

using kinematics::Error;
using kinematics::ErrorCode;
using kinematics::formatShort;

using kinematics::kMaxSamples;

Error badValue(const std::string& option, const std::string& why) {
  return Error{ErrorCode::InvalidValue, option, option + " " + why};
}

}  // namespace

// The input domain (kinematics/model/validate.h, driver.h), named by the option the user
// typed: --from, --to and --step in degrees for a crank, in the length unit for a linear driver.
std::optional<Error> checkDriveOptions(const Invocation& inv, kinematics::InputKind kind) {
  using namespace kinematics;
  // The bound in whole rev/min, rounded down so that every speed it states is accepted.
  if (inv.rpm && !(std::isfinite(*inv.rpm) && std::abs(rpmToRadPerSec(*inv.rpm)) <= kMaxOmega))
    return badValue("--rpm", "must be finite and within ±" + formatNumber(std::floor(kMaxOmega * 60.0 / (2.0 * kPi))) +
                                 " rev/min, which is 1e6 rad/s (got " + formatNumber(*inv.rpm) + ")");
  const InputDomain d = inputDomain(kind);
  const bool angle = kind == InputKind::Angle;
  const double grid = angle ? kMaxAngleDeg : d.position;
  const char* gridUnit = angle ? "degrees" : d.positionUnit;
  for (const auto& [value, option, max, unit] : {std::tuple{inv.omega, "--omega", d.rate, d.rateUnit},
                                                 {inv.alpha, "--alpha", d.acceleration, d.accelerationUnit},
                                                 {inv.fromDeg, "--from", grid, gridUnit},
                                                 {inv.toDeg, "--to", grid, gridUnit},
                                                 {inv.stepDeg, "--step", 2.0 * grid, gridUnit}})
    if (value)
      if (auto e = checkMagnitude(*value, option, max, unit)) return e;
  return std::nullopt;
}

std::optional<Error> checkAtOption(const Invocation& inv, const GridDefaults& d) {
  using namespace kinematics;
  const InputDomain domain = inputDomain(d.input);
  const bool angle = d.input == InputKind::Angle;
  // On a time base --at is an instant (s); else the input, in degrees or the length unit.
  const double max = d.time ? 1e6 : angle ? kMaxAngleDeg : domain.position;
  const char* unit = d.time ? "s" : angle ? "degrees" : domain.positionUnit;
  for (const double at : inv.atDeg)
    if (auto e = checkMagnitude(at, "--at", max, unit)) return e;
  return std::nullopt;
}

double GridDefaults::toInput(double value) const {
  return input == kinematics::InputKind::Angle ? kinematics::degToRad(value) : value;
}

kinematics::Result<kinematics::SweepSpec> sweepSpecFor(const Invocation& inv, const GridDefaults& d) {
  if (auto e = checkDriveOptions(inv, d.input)) return *e;
  if (inv.law) return timeSweepSpecFor(inv, d);
  if (d.time) {
    // A document or example whose driver follows a law: its time base, at --samples instants
    // if given.
    for (const auto& [given, option] : {std::pair{inv.rpm.has_value(), "--rpm"},
                                        {inv.omega.has_value(), "--omega"},
                                        {inv.alpha.has_value(), "--alpha"},
                                        {inv.fromDeg.has_value(), "--from"},
                                        {inv.toDeg.has_value(), "--to"},
                                        {inv.stepDeg.has_value(), "--step"}})
      if (given)
        return badValue(option,
                        "does not apply: this linkage's driver follows a motion law in time (give --law "
                        "to replace it)");
    // The count checked as typed, before it becomes unsigned (-5 read as 18446744073709551611).
    const long long samples = inv.samples.value_or(d.timeSamples);
    if (samples < 1 || samples > kMaxSamples)
      return badValue("--samples", "must be between 1 and " + std::to_string(kMaxSamples) + " (got " +
                                       std::to_string(samples) + ")");
    kinematics::SweepSpec spec;
    spec.time = d.time;
    spec.samples = static_cast<std::size_t>(samples);
    if (auto e = kinematics::checkSweepSpec(spec, d.input)) return badValue("--samples", e->message);
    return spec;
  }
  kinematics::SweepSpec spec;
  spec.omega = inv.rpm ? kinematics::rpmToRadPerSec(*inv.rpm) : inv.omega.value_or(d.omega);
  spec.alpha = inv.alpha.value_or(d.alpha);
  const double from = inv.fromDeg.value_or(d.fromDeg);
  const double to = inv.toDeg.value_or(d.toDeg);
  if (to < from)
    return badValue(
        "--to", "must not be less than --from (got --from " + formatShort(from) + ", --to " + formatShort(to) + ")");
  double last = to;
  long long samples = 0;
  if (inv.samples) {
    samples = *inv.samples;
    if (samples < 1 || samples > kMaxSamples)
      return badValue("--samples", "must be between 1 and " + std::to_string(kMaxSamples) + " (got " +
                                       std::to_string(samples) + ")");
    if (samples > 1 && to == from)
      return badValue("--samples", "needs --to greater than --from for more than one sample");
  } else {
    const double step = inv.stepDeg.value_or(d.stepDeg);
    if (!(step > 0.0)) return badValue("--step", "must be positive (got " + formatShort(step) + ")");
    // The grid includes --to when it lands on it, allowing for round-off in (to − from)/step.
    const double intervals = std::floor((to - from) / step + 1e-9);
    if (intervals + 1.0 > static_cast<double>(kMaxSamples))
      return badValue("--step", "is too small: it would give " + formatShort(intervals + 1.0) + " rows (at most " +
                                    std::to_string(kMaxSamples) + ")");
    samples = static_cast<long long>(intervals) + 1;
    last = from + intervals * step;
  }
  spec.fromAngle = d.toInput(from);
  spec.toAngle = d.toInput(last);
  spec.samples = static_cast<std::size_t>(samples);
  return spec;
}

}  // namespace linkwright::cli
