#include "app/cli/atomic_file.h"
#include "app/cli/commands.h"
#include "app/cli/text_table.h"

#include "kinematics/analysis/assembly_range.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/io/number_format.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <cmath>
#include <ostream>
#include <sstream>

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

// The crank speed in rad/s and the angle grid, from the options and the example's defaults.
kinematics::Result<kinematics::SweepSpec> sweepSpec(const Invocation& inv, const ResolvedFourBar& fb) {
  for (const auto& [value, option] : {std::pair{inv.rpm, "--rpm"}, {inv.omega, "--omega"}, {inv.alpha, "--alpha"},
                                      {inv.fromDeg, "--from"}, {inv.toDeg, "--to"}, {inv.stepDeg, "--step"}})
    if (auto e = checkOption(value, option)) return *e;
  kinematics::SweepSpec spec;
  spec.omega = inv.rpm ? kinematics::rpmToRadPerSec(*inv.rpm)
                       : inv.omega.value_or(fb.example ? fb.example->omega : 1.0);
  spec.alpha = inv.alpha.value_or(fb.example ? fb.example->alpha : 0.0);
  const double from = inv.fromDeg.value_or(fb.example ? fb.example->fromDeg : 0.0);
  const double to = inv.toDeg.value_or(fb.example ? fb.example->toDeg : 360.0);
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
    const double step = inv.stepDeg.value_or(fb.example ? fb.example->stepDeg : 1.0);
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

std::string degreesText(double radians) { return formatShort(kinematics::radToDeg(radians)) + "°"; }

std::string rangesText(const std::vector<kinematics::AngleRange>& ranges) {
  std::string text;
  for (const auto& r : ranges) {
    if (!text.empty()) text += ", ";
    text += r.from == r.to ? degreesText(r.from) : degreesText(r.from) + " to " + degreesText(r.to);
  }
  return text;
}

void reportUnassembled(const kinematics::SweepResult& result, const ResolvedFourBar& fb, std::ostream& err) {
  std::size_t failed = 0;
  for (std::size_t j = 0; j < result.size(); ++j) failed += result.assembled(j) ? 0 : 1;
  err << "linkwright-cli: the linkage cannot be assembled at " << failed << " of " << result.size()
      << " requested crank angles (" << rangesText(result.notAssembled) << "); those rows are left out.\n";
  if (result.firstFailure) err << "  " << *result.firstFailure << ".\n";
  const kinematics::InputRange range = kinematics::fourBarInputRange(fb.lengths);
  if (range.ranges.empty()) err << "  It cannot be assembled at any crank angle.\n";
  else err << "  It can be assembled for crank angles " << rangesText(range.ranges) << " (exact).\n";
}

} // namespace

ExitCode runAnalyze(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto fail = [&](const Error& e) {
    err << "linkwright-cli: " << e.message << "\n";
    return ExitCode::BadInput;
  };
  const auto fb = resolveFourBar(inv);
  if (!fb) return fail(fb.error());
  const auto spec = sweepSpec(inv, *fb);
  if (!spec) return fail(spec.error());
  const auto mechanism = kinematics::makeFourBar(fb->lengths, fb->branch, fb->lengthUnit, inv.couplerPoint);
  if (!mechanism) return fail(mechanism.error());
  const auto result = kinematics::sweep(*mechanism, *spec);
  if (!result) return fail(result.error());

  std::ostringstream csv;
  if (inv.tableFormat) writeSweepTable(csv, *mechanism, *result);
  else kinematics::io::writeSweepCsv(csv, *mechanism, *result);
  if (inv.outputFile) {
    if (auto problem = writeFileAtomically(*inv.outputFile, csv.str())) {
      err << "linkwright-cli: " << *problem << "\n";
      return ExitCode::IoError;
    }
  } else {
    out << csv.str() << std::flush;
  }
  for (const double angle : result->singularAngles)
    err << "linkwright-cli: note: toggle position at crank angle " << degreesText(angle)
        << ": coupler and rocker are collinear, ω and α are undefined (cells left empty)\n";
  if (!result->notAssembled.empty()) {
    reportUnassembled(*result, *fb, err);
    return ExitCode::NotAssemblable;
  }
  return ExitCode::Success;
}

} // namespace linkwright::cli
