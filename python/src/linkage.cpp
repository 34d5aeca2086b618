#include "python/src/linkage.h"

#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/io/bounded_read.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/io/document_json.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/sweep_columns.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <tuple>

namespace linkwright::python {

namespace k = kinematics;

namespace {

// As the CLI's kSweepWindowSamples: memory does not grow with the sample count.
constexpr std::size_t kWindowSamples = 4096;

k::Error badValue(const std::string& field, const std::string& why) {
  return k::Error{k::ErrorCode::InvalidValue, field, field + " " + why};
}

// The value a CSV cell's text holds: the grid columns are written to 12 significant digits
// (csv_writer.cpp), so 30° reads back as 30, not as its radian round trip.
double gridCellValue(double value) {
  const std::string text = k::formatShort(value, 12);
  double parsed = value;
  std::from_chars(text.data(), text.data() + text.size(), parsed);
  return parsed;
}

bool isGridColumn(const k::SweepColumn& column) {
  return column.quantity == k::ColumnQuantity::InputAngle || column.quantity == k::ColumnQuantity::InputLength ||
         column.quantity == k::ColumnQuantity::Time;
}

}  // namespace

k::Result<Linkage> exampleLinkage(const std::string& name) {
  auto e = k::findExample(name);
  if (!e) {
    std::string names;
    for (const k::Example& x : k::examples()) names += (names.empty() ? "" : ", ") + x.name;
    return k::Error{k::ErrorCode::InvalidValue, "name", "no example named '" + name + "' (available: " + names + ")"};
  }
  return Linkage{
      std::move(e->mechanism),
      {e->omega, e->alpha, e->fromDeg, e->toDeg, e->stepDeg, e->time, static_cast<long long>(e->timeSamples)},
      std::move(e->dynamics),
      e->kind,
      "the example " + e->name};
}

k::Result<Linkage> fourBarLinkage(const k::FourBarLengths& lengths, const std::string& unit, const std::string& branch,
                                  std::optional<k::CouplerPointSpec> couplerPoint) {
  // As the CLI's --unit: the unit is part of every column name.
  if (unit.empty() ||
      unit.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ") != std::string::npos)
    return badValue("unit", "must be a unit name made of letters, e.g. mm, m, in (got '" + unit + "')");
  if (branch != "open" && branch != "crossed")
    return badValue("branch", "must be \"open\" or \"crossed\" (got \"" + branch + "\")");
  if (couplerPoint) {
    if (auto e = k::checkCoordinate(couplerPoint->along, "coupler point along")) return *e;
    if (auto e = k::checkCoordinate(couplerPoint->across, "coupler point across")) return *e;
  }
  auto m = k::makeFourBar(lengths, branch == "open" ? k::Branch::Open : k::Branch::Crossed, unit, couplerPoint);
  if (!m) return m.error();
  if (auto e = k::checkMechanism(*m)) return *e;
  return Linkage{std::move(*m), {}, {}, "four-bar", "four_bar()"};
}

k::Result<Linkage> loadLinkage(const std::string& path) {
  const auto text = k::io::readFileBounded(path, k::io::kMaxDocumentBytes, "a Linkwright document");
  if (!text) return k::Error{text.error().code, path, text.error().message};
  auto design = k::io::readDocument(*text);
  if (!design) return k::Error{design.error().code, path, path + ": " + design.error().message};
  // A design's samples become the step that reproduces them, as the CLI reads a document.
  Grid grid{design->omega,
            design->alpha,
            design->fromDeg,
            design->toDeg,
            (design->toDeg - design->fromDeg) / static_cast<double>(design->samples - 1),
            design->time,
            static_cast<long long>(design->samples)};
  return Linkage{std::move(design->mechanism), grid, std::move(design->dynamics), design->kind, path};
}

// The CLI's sweepSpecFor and checkDriveOptions (app/cli/sweep_options.cpp), the refusals naming
// the keyword arguments.
k::Result<k::SweepSpec> sweepSpecFor(const Linkage& linkage, const SweepOptions& o) {
  const k::InputKind kind = k::inputKind(linkage.mechanism);
  const k::InputDomain d = k::inputDomain(kind);
  const bool angle = kind == k::InputKind::Angle;
  const double gridMax = angle ? k::kMaxAngleDeg : d.position;
  const char* gridUnit = angle ? "degrees" : d.positionUnit;
  for (const auto& [value, field, max, unit] : {std::tuple{o.omega, "omega", d.rate, d.rateUnit},
                                                {o.alpha, "alpha", d.acceleration, d.accelerationUnit},
                                                {o.startDeg, "start_deg", gridMax, gridUnit},
                                                {o.stopDeg, "stop_deg", gridMax, gridUnit}})
    if (value)
      if (auto e = k::checkMagnitude(*value, field, max, unit)) return *e;

  const Grid& g = linkage.grid;
  if (g.time) {
    for (const auto& [given, field] : {std::pair{o.omega.has_value(), "omega"},
                                       {o.alpha.has_value(), "alpha"},
                                       {o.startDeg.has_value(), "start_deg"},
                                       {o.stopDeg.has_value(), "stop_deg"}})
      if (given) return badValue(field, "does not apply: this linkage's driver follows a motion law in time");
    k::SweepSpec spec;
    spec.time = g.time;
    const long long samples = o.samples.value_or(g.timeSamples);
    if (samples < 1 || samples > k::kMaxSamples)
      return badValue("samples", "must be between 1 and " + std::to_string(k::kMaxSamples) + " (got " +
                                     std::to_string(samples) + ")");
    spec.samples = static_cast<std::size_t>(samples);
    if (auto e = k::checkSweepSpec(spec, kind)) return badValue("samples", e->message);
    return spec;
  }

  const auto toInput = [angle](double value) { return angle ? k::degToRad(value) : value; };
  k::SweepSpec spec;
  spec.omega = o.omega.value_or(g.omega);
  spec.alpha = o.alpha.value_or(g.alpha);
  const double from = o.startDeg.value_or(g.fromDeg);
  const double to = o.stopDeg.value_or(g.toDeg);
  if (to < from)
    return badValue("stop_deg", "must not be less than start_deg (got start_deg " + k::formatShort(from) +
                                    ", stop_deg " + k::formatShort(to) + ")");
  double last = to;
  long long samples = 0;
  if (o.samples) {
    samples = *o.samples;
    if (samples < 1 || samples > k::kMaxSamples)
      return badValue("samples", "must be between 1 and " + std::to_string(k::kMaxSamples) + " (got " +
                                     std::to_string(samples) + ")");
    if (samples > 1 && to == from)
      return badValue("samples", "needs stop_deg greater than start_deg for more than one sample");
  } else {
    // The linkage's step; the grid includes the stop when it lands on it, allowing for
    // round-off in (to − from)/step.
    const double intervals = std::floor((to - from) / g.stepDeg + 1e-9);
    if (intervals + 1.0 > static_cast<double>(k::kMaxSamples))
      return badValue("samples", "is needed: the linkage's step would give " + k::formatShort(intervals + 1.0) +
                                     " rows (at most " + std::to_string(k::kMaxSamples) + ")");
    samples = static_cast<long long>(intervals) + 1;
    last = from + intervals * g.stepDeg;
  }
  spec.fromAngle = toInput(from);
  spec.toAngle = toInput(last);
  spec.samples = static_cast<std::size_t>(samples);
  if (auto e = k::checkSweepSpec(spec, kind)) return *e;
  return spec;
}

namespace {

// "30°" for a crank, "12 mm" for a linear driver, as the CLI writes an input.
std::string inputText(const k::Mechanism& m, double q) {
  const std::string unit = k::inputUnit(m);
  return k::formatShort(k::inputDisplayValue(m, q)) + (unit == "°" ? unit : " " + unit);
}

// "crank angles", "tip path positions", "actuator A–C lengths".
std::string inputsName(const k::Mechanism& m) {
  std::string name = k::inputName(m);
  return name.ends_with("position") || name.ends_with("length") || name.ends_with("angle") ? name + "s" : name;
}

}  // namespace

std::vector<std::string> sweepNotes(const k::Mechanism& m, const k::SweepSummary& summary) {
  std::vector<std::string> notes;
  if (!summary.notAssembled.empty()) {
    std::string ranges;
    for (const k::AngleRange& r : summary.notAssembled) {
      if (!ranges.empty()) ranges += ", ";
      ranges += r.from == r.to ? inputText(m, r.from) : inputText(m, r.from) + " to " + inputText(m, r.to);
    }
    std::string note =
        "the linkage cannot be assembled at " + std::to_string(summary.samples - summary.assembledSamples) + " of " +
        std::to_string(summary.samples) + " requested " + inputsName(m) + " (" + ranges + "); those rows are left out";
    if (summary.firstFailure) note += ". " + *summary.firstFailure;
    notes.push_back(note);
  }
  for (const double q : summary.singularAngles)
    notes.push_back("toggle position at " + k::inputName(m) + " " + inputText(m, q) +
                    ": the rates are undefined there (masked)");
  for (const k::AngleRange& step : summary.lockedBetween)
    notes.push_back("the linkage locks between " + inputsName(m) + " " + inputText(m, step.from) + " and " +
                    inputText(m, step.to) + "; from " + inputText(m, step.to) +
                    " on it is assembled afresh on the chosen branches, so points jump there");
  return notes;
}

k::Result<SweepTable> sweepTable(const Linkage& linkage, const k::SweepSpec& spec, bool withCsv, bool withColumns) {
  const k::Mechanism& m = linkage.mechanism;
  SweepTable table;
  std::ostringstream csvText;
  k::io::SweepCsvWriter csv(csvText, m);
  std::vector<k::SweepColumn> columns;
  auto swept = k::sweepInWindows(m, spec, {}, kWindowSamples, [&](const k::SweepResult& part, std::size_t) {
    if (withCsv) csv.write(part);
    if (!withColumns) return true;
    if (columns.empty()) {
      columns = k::sweepColumns(m, part.request, !part.time.empty());
      for (const k::SweepColumn& c : columns) table.names.push_back(c.name);
      table.values.resize(columns.size());
      table.defined.resize(columns.size());
    }
    for (std::size_t j = 0; j < part.size(); ++j) {
      if (!part.assembled(j)) continue;  // as the CSV: the row is left out
      for (std::size_t c = 0; c < columns.size(); ++c) {
        const k::SweepColumn& column = columns[c];
        // The CSV's empty cells: rates at a toggle, and (by number_text's one rule) anything
        // not finite.
        const double value = column.value(part, j);
        const bool defined = (part.ok(j) || !column.isRate()) && std::isfinite(value);
        table.values[c].push_back(!defined ? 0.0 : isGridColumn(column) ? gridCellValue(value) : value);
        table.defined[c].push_back(defined);
      }
    }
    return true;
  });
  if (!swept) return swept.error();
  table.summary = std::move(swept).value();
  table.csv = std::move(csvText).str();
  return table;
}

}  // namespace linkwright::python
