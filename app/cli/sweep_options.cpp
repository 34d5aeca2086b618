#include "app/cli/commands.h"

#include "kinematics/io/number_format.h"
#include "kinematics/model/units.h"

#include <cmath>

namespace linkwright::cli {
namespace {

using kinematics::Error;
using kinematics::ErrorCode;
using kinematics::io::formatShort;

// Enough for a millidegree grid over many turns; more is a typo, not a request.
constexpr long long kMaxSamples = 10'000'000;

Error badValue(const std::string& option, const std::string& why) {
  return Error{ErrorCode::InvalidValue, option, option + " " + why};
}

std::optional<Error> checkOption(const std::optional<double>& value, const std::string& option) {
  if (value && !std::isfinite(*value)) return badValue(option, "must be finite (got " + formatShort(*value) + ")");
  return std::nullopt;
}

} // namespace

kinematics::Result<kinematics::SweepSpec> sweepSpecFor(const Invocation& inv, const GridDefaults& d) {
  for (const auto& [value, option] : {std::pair{inv.rpm, "--rpm"}, {inv.omega, "--omega"}, {inv.alpha, "--alpha"},
                                      {inv.fromDeg, "--from"}, {inv.toDeg, "--to"}, {inv.stepDeg, "--step"}})
    if (auto e = checkOption(value, option)) return *e;
  kinematics::SweepSpec spec;
  spec.omega = inv.rpm ? kinematics::rpmToRadPerSec(*inv.rpm)
                       : inv.omega.value_or(d.omega);
  spec.alpha = inv.alpha.value_or(d.alpha);
  const double from = inv.fromDeg.value_or(d.fromDeg);
  const double to = inv.toDeg.value_or(d.toDeg);
  if (to < from)
    return badValue("--to", "must not be less than --from (got --from " + formatShort(from) + ", --to " + formatShort(to) + ")");
  double last = to;
  long long samples = 0;
  if (inv.samples) {
    samples = *inv.samples;
    if (samples < 1 || samples > kMaxSamples)
      return badValue("--samples", "must be between 1 and " + std::to_string(kMaxSamples) + " (got " + std::to_string(samples) + ")");
    if (samples > 1 && to == from) return badValue("--samples", "needs --to greater than --from for more than one sample");
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
  spec.fromAngle = kinematics::degToRad(from);
  spec.toAngle = kinematics::degToRad(last);
  spec.samples = static_cast<std::size_t>(samples);
  return spec;
}

kinematics::Result<SweptMechanism> sweepInvocation(const Invocation& inv) {
  auto resolved = resolveMechanism(inv);
  if (!resolved) return resolved.error();
  const auto spec = sweepSpecFor(inv, resolved->defaults);
  if (!spec) return spec.error();
  auto result = kinematics::sweep(resolved->mechanism, *spec);
  if (!result) return result.error();
  return SweptMechanism{std::move(*resolved), *spec, std::move(*result)};
}

} // namespace linkwright::cli
