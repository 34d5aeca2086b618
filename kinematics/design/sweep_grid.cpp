#include "kinematics/design/sweep_grid.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <cmath>
#include <tuple>
#include <variant>

namespace linkwright::kinematics {
namespace {

Error badValue(GridField field, const GridFieldNames& names, const std::string& why) {
  return Error{ErrorCode::InvalidValue, gridFieldKey(field), names[field] + " " + why};
}

std::optional<Error> checkSampleCount(long long samples, const GridFieldNames& names) {
  if (samples >= 1 && samples <= kMaxSamples) return std::nullopt;
  return badValue(GridField::Samples, names,
                  "must be between 1 and " + std::to_string(kMaxSamples) + " (got " + std::to_string(samples) + ")");
}

// The rows (`intervals` + 1) a grid would have, as text for a refusal: a count, never
// "undefined". A span over a step of 1e-320 is more intervals than a double holds; its power of
// ten still says how many.
std::string rowsText(double intervals, double span, double step) {
  if (std::isfinite(intervals)) return formatShort(intervals + 1.0);
  const double exponent = std::log10(span) - std::log10(step);
  const double whole = std::floor(exponent);
  return "about " + formatShort(std::pow(10.0, exponent - whole), 2) + "e" +
         std::to_string(static_cast<long long>(whole));
}
}  // namespace

double SweepGrid::toInput(double value) const { return input == InputKind::Angle ? degToRad(value) : value; }

MachineDefaults machineDefaultsOf(const SweepGrid& grid) {
  return {grid.omega, degToRad(grid.fromDeg), grid.time.has_value()};
}

SweepGrid sweepGridOf(const Example& e) {
  SweepGrid grid;
  grid.omega = e.omega;
  grid.alpha = e.alpha;
  grid.fromDeg = e.fromDeg;
  grid.toDeg = e.toDeg;
  grid.stepDeg = e.stepDeg;
  grid.time = e.time;
  grid.timeSamples = static_cast<long long>(e.timeSamples);
  return grid;
}

SweepGrid sweepGridOf(const Design& d) {
  SweepGrid grid;
  grid.omega = d.omega;
  grid.alpha = d.alpha;
  grid.fromDeg = d.fromDeg;
  grid.toDeg = d.toDeg;
  grid.stepDeg = (d.toDeg - d.fromDeg) / static_cast<double>(d.samples - 1);
  grid.time = d.time;
  grid.timeSamples = static_cast<long long>(d.samples);
  return grid;
}

const char* gridFieldKey(GridField field) {
  switch (field) {
  case GridField::Rpm: return "rpm";
  case GridField::Omega: return "omega";
  case GridField::Alpha: return "alpha";
  case GridField::Start: return "start";
  case GridField::Stop: return "stop";
  case GridField::Step: return "step";
  case GridField::Samples: return "samples";
  case GridField::Law: return "law";
  case GridField::RampTime: return "rampTime";
  case GridField::Rise: return "rise";
  case GridField::Duration: return "duration";
  case GridField::LawTable: return "lawTable";
  case GridField::FromTime: return "fromTime";
  case GridField::ToTime: return "toTime";
  case GridField::StepTime: return "stepTime";
  }
  return "";
}

const std::string& GridFieldNames::operator[](GridField field) const {
  switch (field) {
  case GridField::Rpm: return rpm;
  case GridField::Omega: return omega;
  case GridField::Alpha: return alpha;
  case GridField::Start: return start;
  case GridField::Stop: return stop;
  case GridField::Step: return step;
  case GridField::Samples: return samples;
  case GridField::Law: return law;
  case GridField::RampTime: return rampTime;
  case GridField::Rise: return rise;
  case GridField::Duration: return duration;
  case GridField::LawTable: return lawTable;
  case GridField::FromTime: return fromTime;
  case GridField::ToTime: return toTime;
  case GridField::StepTime: return stepTime;
  }
  return samples;
}

std::optional<Error> checkGridRequest(const SweepGridRequest& r, InputKind kind, const GridFieldNames& names) {
  // The bound in whole rev/min, rounded down so that every speed it states is accepted.
  if (r.rpm && !(std::isfinite(*r.rpm) && std::abs(rpmToRadPerSec(*r.rpm)) <= kMaxOmega))
    return badValue(GridField::Rpm, names,
                    "must be finite and within ±" + formatNumber(std::floor(kMaxOmega * 60.0 / (2.0 * kPi))) +
                        " rev/min, which is 1e6 rad/s (got " + formatNumber(*r.rpm) + ")");
  const InputDomain d = inputDomain(kind);
  const bool angle = kind == InputKind::Angle;
  const double grid = angle ? kMaxAngleDeg : d.position;
  const char* gridUnit = angle ? "degrees" : d.positionUnit;
  for (const auto& [value, field, max, unit] : {std::tuple{r.omega, GridField::Omega, d.rate, d.rateUnit},
                                                {r.alpha, GridField::Alpha, d.acceleration, d.accelerationUnit},
                                                {r.start, GridField::Start, grid, gridUnit},
                                                {r.stop, GridField::Stop, grid, gridUnit},
                                                {r.step, GridField::Step, 2.0 * grid, gridUnit}})
    if (value)
      if (auto e = checkMagnitude(*value, names[field], max, unit)) {
        e->field = gridFieldKey(field);
        return e;
      }
  return std::nullopt;
}

Result<SweepSpec> sweepGridSpec(const SweepGridRequest& r, const SweepGrid& d, const GridFieldNames& names) {
  if (auto e = checkGridRequest(r, d.input, names)) return *e;
  if (r.law) return lawGridSpec(r, d, names);
  if (d.time) {
    // A document or example whose driver follows a law: its time base, at `samples` instants
    // if given.
    const std::string replace = names.law.empty() ? "" : " (give " + names.law + " to replace it)";
    for (const auto& [given, field] : {std::pair{r.rpm.has_value(), GridField::Rpm},
                                       {r.omega.has_value(), GridField::Omega},
                                       {r.alpha.has_value(), GridField::Alpha},
                                       {r.start.has_value(), GridField::Start},
                                       {r.stop.has_value(), GridField::Stop},
                                       {r.step.has_value(), GridField::Step}})
      if (given)
        return badValue(field, names, "does not apply: this linkage's driver follows a motion law in time" + replace);
    // The count checked as typed, before it becomes unsigned (-5 read as 18446744073709551611).
    const long long samples = r.samples.value_or(d.timeSamples);
    if (auto e = checkSampleCount(samples, names)) return *e;
    SweepSpec spec;
    spec.time = d.time;
    spec.samples = static_cast<std::size_t>(samples);
    if (auto e = checkSweepSpec(spec, d.input)) return badValue(GridField::Samples, names, e->message);
    return spec;
  }
  SweepSpec spec;
  spec.omega = r.rpm ? rpmToRadPerSec(*r.rpm) : r.omega.value_or(d.omega);
  spec.alpha = r.alpha.value_or(d.alpha);
  const double from = r.start.value_or(d.fromDeg);
  const double to = r.stop.value_or(d.toDeg);
  if (to < from)
    return badValue(GridField::Stop, names,
                    "must not be less than " + names.start + " (got " + names.start + " " + formatShort(from) + ", " +
                        names.stop + " " + formatShort(to) + ")");
  double last = to;
  long long samples = 0;
  if (r.samples) {
    samples = *r.samples;
    if (auto e = checkSampleCount(samples, names)) return *e;
    if (samples > 1 && to == from)
      return badValue(GridField::Samples, names,
                      "needs " + names.stop + " greater than " + names.start + " for more than one sample");
  } else {
    // The step given, else the source's. Where the front end offers no step, the way out of a
    // step that does not fit is a sample count, and the message says so.
    const double step = r.step.value_or(d.stepDeg);
    const bool ownStep = names.step.empty();
    if (!(step > 0.0)) {
      if (ownStep)
        return badValue(GridField::Samples, names,
                        "is needed: the linkage's step is not positive (" + formatShort(step) + ")");
      return badValue(GridField::Step, names, "must be positive (got " + formatShort(step) + ")");
    }
    // The grid includes the stop when it lands on it, allowing for round-off in (to − from)/step.
    const double intervals = std::floor((to - from) / step + 1e-9);
    if (intervals + 1.0 > static_cast<double>(kMaxSamples)) {
      if (ownStep)
        return badValue(GridField::Samples, names,
                        "is needed: the linkage's step would give " + rowsText(intervals, to - from, step) +
                            " rows (at most " + std::to_string(kMaxSamples) + ")");
      return badValue(GridField::Step, names,
                      "is too small: it would give " + rowsText(intervals, to - from, step) + " rows (at most " +
                          std::to_string(kMaxSamples) + ")");
    }
    samples = static_cast<long long>(intervals) + 1;
    last = from + intervals * step;
  }
  spec.fromAngle = d.toInput(from);
  spec.toAngle = d.toInput(last);
  spec.samples = static_cast<std::size_t>(samples);
  return spec;
}

namespace {

// The law the request names, starting at `start` (the driver's coordinate) at `omega`.
Result<MotionLaw> lawOf(const SweepGridRequest& r, const SweepGrid& d, const GridFieldNames& names, double start,
                        double omega) {
  const std::string& name = *r.law;
  const auto needs = [&](GridField field) {
    return badValue(field, names, "is needed: " + names.law + " " + name + " takes it");
  };
  if (name == "constant") return MotionLaw{ConstantVelocity{start, omega}};
  if (name == "ramp") {
    if (!r.rampTime) return needs(GridField::RampTime);
    return MotionLaw{RampToSpeed{start, omega, *r.rampTime}};
  }
  if (name == "cycloidal" || name == "345") {
    if (!r.rise) return needs(GridField::Rise);
    if (!r.duration) return needs(GridField::Duration);
    const double rise = d.toInput(*r.rise);
    if (name == "cycloidal") return MotionLaw{CycloidalRise{start, rise, *r.duration}};
    return MotionLaw{PolynomialRise{start, rise, *r.duration}};
  }
  if (name == "table") {
    if (!r.table) return needs(GridField::LawTable);
    return MotionLaw{*r.table};
  }
  std::string known;
  for (const char* law : kMotionLawNames) known += (known.empty() ? "" : ", ") + std::string(law);
  return badValue(GridField::Law, names, "must be one of " + known + " (got \"" + name + "\")");
}

// Where a law's time base ends by default: a rise's end, a ramp and one turn at speed, one turn.
std::optional<double> defaultEndTime(const MotionLaw& law, double omega) {
  if (const auto span = lawTimeSpan(law)) return span->second;
  if (const auto* rise = std::get_if<CycloidalRise>(&law)) return rise->duration;
  if (const auto* rise = std::get_if<PolynomialRise>(&law)) return rise->duration;
  if (omega == 0.0) return std::nullopt;
  const double turn = 2.0 * kPi / std::abs(omega);
  if (const auto* ramp = std::get_if<RampToSpeed>(&law)) return ramp->rampTime + turn;
  return turn;
}

// The figures of one law given with another, and the angle grid's fields beside a law.
std::optional<Error> checkLawFields(const SweepGridRequest& r, const GridFieldNames& names) {
  const std::string& law = *r.law;
  for (const auto& [given, field, owner] :
       {std::tuple{r.rampTime.has_value(), GridField::RampTime, law == "ramp"},
        {r.rise.has_value(), GridField::Rise, law == "cycloidal" || law == "345"},
        {r.duration.has_value(), GridField::Duration, law == "cycloidal" || law == "345"},
        {r.table.has_value(), GridField::LawTable, law == "table"}})
    if (given && !owner) return badValue(field, names, "does not apply to " + names.law + " " + law);
  for (const auto& [given, field] : {std::pair{r.stop.has_value(), GridField::Stop},
                                     {r.step.has_value(), GridField::Step},
                                     {r.alpha.has_value(), GridField::Alpha}})
    if (given)
      return badValue(field, names,
                      "sets the angle grid; with " + names.law + " the driver follows the law in time (give " +
                          names.fromTime + ", " + names.toTime + " and " + names.samples + " instead)");
  if (r.stepTime && r.samples)
    return badValue(GridField::Samples, names, "and " + names.stepTime + " cannot be given together");
  if (r.stepTime && !(std::isfinite(*r.stepTime) && *r.stepTime > 0.0))
    return badValue(GridField::StepTime, names, "must be positive and finite (got " + formatNumber(*r.stepTime) + ")");
  return std::nullopt;
}

}  // namespace

Result<SweepSpec> lawGridSpec(const SweepGridRequest& r, const SweepGrid& d, const GridFieldNames& names) {
  if (auto e = checkLawFields(r, names)) return *e;
  const double omega = r.rpm ? rpmToRadPerSec(*r.rpm) : r.omega.value_or(d.omega);
  auto law = lawOf(r, d, names, d.toInput(r.start.value_or(d.fromDeg)), omega);
  if (!law) return law.error();
  if (auto e = checkMotionLaw(*law, d.input)) return badValue(GridField::Law, names, "gives " + e->message);
  const auto span = lawTimeSpan(*law);
  const double from = r.fromTime.value_or(span ? span->first : 0.0);
  const auto end = r.toTime ? r.toTime : defaultEndTime(*law, omega);
  if (!end)
    return badValue(GridField::ToTime, names, "is needed: the crank does not turn, so no default end time follows");
  if (*end < from)
    return badValue(
        GridField::ToTime, names,
        "must not be before " + names.fromTime + " (got " + formatShort(from) + " to " + formatShort(*end) + " s)");
  long long samples = r.samples.value_or(kDefaultLawSamples);
  if (r.stepTime) {
    const double intervals = std::floor((*end - from) / *r.stepTime + 1e-9);
    if (!(intervals + 1.0 <= static_cast<double>(kMaxSamples)))
      return badValue(GridField::StepTime, names,
                      "is too small: it would give " + rowsText(intervals, *end - from, *r.stepTime) +
                          " rows (at most " + std::to_string(kMaxSamples) + ")");
    samples = static_cast<long long>(intervals) + 1;
  }
  if (auto e = checkSampleCount(samples, names)) return *e;
  SweepSpec spec;
  spec.samples = static_cast<std::size_t>(samples);
  const double last = r.stepTime ? from + static_cast<double>(samples - 1) * *r.stepTime : *end;
  spec.time = TimeBase{std::move(*law), from, last};
  if (auto e = checkSweepSpec(spec, d.input))
    return badValue(GridField::FromTime, names, "/ " + names.toTime + ": " + e->message);
  return spec;
}

}  // namespace linkwright::kinematics

namespace linkwright::kinematics {

Result<DriverState> crankStateAt(double deg, const SweepGridRequest& request, const SweepGrid& defaults,
                                 const GridFieldNames& names, const std::string& atName) {
  const InputDomain domain = inputDomain(InputKind::Angle);
  if (auto e = checkMagnitude(deg, atName, kMaxAngleDeg, "degrees")) return *e;
  if (request.rpm && request.omega)
    return Error{ErrorCode::InvalidValue, gridFieldKey(GridField::Rpm),
                 names.rpm + " and " + names.omega + " cannot be used together"};
  // rpm and omega checked in their own units (the grid rule), before rpm becomes rad/s.
  if (auto e = checkGridRequest(request, InputKind::Angle, names)) return *e;
  const double omega = request.rpm ? rpmToRadPerSec(*request.rpm) : request.omega.value_or(defaults.omega);
  if (auto e = checkMagnitude(omega, request.rpm ? names.rpm : names.omega, domain.rate, domain.rateUnit)) return *e;
  const double alpha = request.alpha.value_or(defaults.alpha);
  if (auto e = checkMagnitude(alpha, names.alpha, domain.acceleration, domain.accelerationUnit)) return *e;
  return DriverState{degToRad(deg), omega, alpha};
}

}  // namespace linkwright::kinematics
