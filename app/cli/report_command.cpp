// `linkwright-cli report`: the lab-report PDF of a linkage (kinematics/report/): the drawing at
// one input, the Grashof / mobility analysis, a table every --step degrees (seconds on a time
// base), the refined
// extremes, the plots and, with masses, the forces. The content and the file come from the
// core calls the designer's Report ▸ PDF makes, so both write the same report.

#include "app/cli/commands.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/report/report_pdf.h"
#include "kinematics/report/report_sections.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;

// The thesis (seed 000) tabulates every 30°.
constexpr double kDefaultStepDeg = 30.0;

// Today in UTC, or SOURCE_DATE_EPOCH's day where it is set (reproducible files).
std::string today() {
  std::time_t now = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"))
    if (const auto value = std::strtoll(epoch, nullptr, 10); value > 0) now = static_cast<std::time_t>(value);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", &utc);
  return text;
}

// The grid the plots and extremes run on: the document's or example's own, or its time base.
k::SweepSpec gridOf(const GridDefaults& d) {
  if (d.time) {
    k::SweepSpec spec;
    spec.time = d.time;
    spec.samples = static_cast<std::size_t>(std::max(2LL, d.timeSamples));
    return spec;
  }
  const double intervals = std::max(1.0, std::round((d.toDeg - d.fromDeg) / d.stepDeg));
  k::SweepSpec spec;
  spec.fromAngle = d.toInput(d.fromDeg);
  spec.toAngle = d.toInput(d.toDeg);
  spec.samples = static_cast<std::size_t>(intervals) + 1;
  spec.omega = d.omega;
  spec.alpha = d.alpha;
  return spec;
}

// --step on a time base: seconds, more than 0 and at most the time span; a twelfth of it by
// default (13 rows, as 30° gives over a turn).
k::Result<double> timeStep(const Invocation& inv, const k::TimeBase& time) {
  const double span = time.toTime - time.fromTime;
  const double step = inv.stepDeg.value_or(span / 12.0);
  if (!(std::isfinite(step) && step > 0.0 && step <= span))
    return k::Error{k::ErrorCode::InvalidValue, "--step",
                    "--step must be more than 0 and at most " + k::formatShort(span) +
                        " s (the time span) on a time base (got " + k::formatNumber(step) + ")"};
  return step;
}

// --step: more than 0 and at most a turn for a crank, at most the range for a linear driver.
k::Result<double> tableStep(const Invocation& inv, const GridDefaults& d) {
  if (d.time) return timeStep(inv, *d.time);
  const bool crank = d.input == k::InputKind::Angle;
  const double span = crank ? 360.0 : d.toDeg - d.fromDeg;
  const double step = inv.stepDeg.value_or(crank ? kDefaultStepDeg : span / 12.0);
  if (!(std::isfinite(step) && step > 0.0 && step <= span))
    return k::Error{k::ErrorCode::InvalidValue, "--step",
                    "--step must be more than 0 and at most " + k::formatShort(span) +
                        (crank ? " degrees" : " " + d.lengthUnit + " (the input's range)") + " (got " +
                        k::formatNumber(step) + ")"};
  return d.toInput(step);
}

}  // namespace

ExitCode runReport(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto fail = [&](const k::Error& e, ExitCode code = ExitCode::BadInput) {
    err << "linkwright-cli: " << e.message << "\n";
    return code;
  };
  const auto paper = k::report::paperFromName(inv.paper.value_or("a4"));
  if (!paper)
    return fail({k::ErrorCode::InvalidValue, "--paper", "--paper must be a4 or letter (got '" + *inv.paper + "')"});
  const std::string rates = inv.rates.value_or("rad"), angles = inv.angles.value_or("deg");
  if (rates != "rad" && rates != "deg")
    return fail({k::ErrorCode::InvalidValue, "--rates",
                 "--rates must be rad (rad/s, rad/s²) or deg (deg/s, deg/s²) (got '" + rates + "')"});
  if (angles != "deg" && angles != "rad")
    return fail({k::ErrorCode::InvalidValue, "--angles", "--angles must be deg or rad (got '" + angles + "')"});
  const auto resolved = resolveMechanism(inv);
  if (!resolved) return fail(resolved.error());
  const GridDefaults& d = resolved->defaults;
  if (auto e = checkAtOption(inv, d)) return fail(*e);
  const auto step = tableStep(inv, d);
  if (!step) return fail(step.error());
  k::report::ReportRequest request;
  k::report::setReportHeading(request,
                              inv.documentPath ? std::filesystem::path(*inv.documentPath).filename().string()
                              : inv.example    ? *inv.example
                                               : "Four-bar " + k::formatShort(inv.fourBar->frame) + ", " +
                                                  k::formatShort(inv.fourBar->crank) + ", " +
                                                  k::formatShort(inv.fourBar->coupler) + ", " +
                                                  k::formatShort(inv.fourBar->rocker) + " " + inv.lengthUnit,
                              resolved->description, resolved->kind);
  request.date = today();
  request.grid = gridOf(d);
  request.tableStep = *step;
  // On a time base --at is a time (s), as --step is.
  request.drawAt = d.time ? (inv.atDeg.empty() ? d.time->fromTime : inv.atDeg.front())
                          : d.toInput(inv.atDeg.empty() ? d.fromDeg : inv.atDeg.front());
  request.units.rates = rates == "deg" ? k::report::RateUnit::Degrees : k::report::RateUnit::Radians;
  request.units.angles = angles == "rad" ? k::report::AngleUnit::Radians : k::report::AngleUnit::Degrees;
  const auto content = k::report::buildReport(resolved->mechanism, resolved->dynamics, request);
  if (!content)
    return fail(content.error(), content.error().field == "--at" ? ExitCode::NotAssemblable : ExitCode::BadInput);
  if (auto e = k::report::writeReportPdf(*content, *paper, *inv.outputFile)) return fail(*e, ExitCode::IoError);
  out << "wrote " << *inv.outputFile << ": the lab report of " << resolved->source << " ("
      << (*paper == k::report::Paper::A4 ? "A4" : "Letter") << "), a table row every "
      << (d.time ? k::formatShort(*step) + " s" : k::report::inputText(resolved->mechanism, *step, false)) << "\n";
  return ExitCode::Success;
}

}  // namespace linkwright::cli
