#include "kinematics/report/report_content.h"

#include "kinematics/analysis/column_extrema.h"
#include "kinematics/dynamics/force_columns.h"
#include "kinematics/dynamics/force_extrema.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/report/report_sections.h"
#include "kinematics/solve/motion_law.h"
#include "kinematics/solve/sweep_columns.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics::report {
namespace {

using kinematics::ColumnQuantity;
using kinematics::formatFixed;
using kinematics::SweepColumn;

constexpr std::size_t kPlotSamples = 721;

// A rate is "toggle" where the linkage has none, as analyze's text table writes it.
std::string cellText(const SweepColumn& c, const SweepResult& r, std::size_t j, const ReportUnits& units,
                     std::optional<double>& value) {
  if (c.isRate() && !r.ok(j)) return "toggle";
  value = c.value(r, j) * unitScale(c, units);
  return formatFixed(*value, kTableDecimals);
}

ReportTable sweepTable(const Mechanism& m, const SweepResult& r, const std::vector<SweepColumn>& columns,
                       const ReportUnits& units) {
  ReportTable table;
  for (const SweepColumn& c : columns) table.columns.push_back(columnHeading(m, c, units));
  for (std::size_t j = 0; j < r.size(); ++j) {
    if (!r.assembled(j)) continue;
    std::vector<std::string>& cells = table.cells.emplace_back();
    std::vector<std::optional<double>>& values = table.values.emplace_back();
    for (const SweepColumn& c : columns) cells.push_back(cellText(c, r, j, units, values.emplace_back()));
  }
  return table;
}

ReportTable extremesTable(const Mechanism& m, const SweepSpec& spec, const SweepResult& r,
                          const std::vector<SweepColumn>& columns, const ReportUnits& units) {
  const bool timeBase = spec.time.has_value();
  const std::string where = timeBase ? "at time" : "at " + inputName(m);
  const std::string whereUnit = timeBase ? "s" : inputUnit(m) == "°" ? "deg" : inputUnit(m);
  ReportTable table;
  table.columns = {{"quantity", ""}, {"minimum", ""}, {where, whereUnit}, {"maximum", ""}, {where, whereUnit}};
  for (const SweepColumn& c : columns) {
    if (c.quantity == ColumnQuantity::InputAngle || c.quantity == ColumnQuantity::InputLength ||
        c.quantity == ColumnQuantity::Time)
      continue;
    const auto e = kinematics::columnExtrema(m, spec, r, c);
    if (!e) continue;
    const auto at = [&](const Extremum& x) { return timeBase ? x.time : inputDisplayValue(m, x.inputAngle); };
    const double minAt = at(e->minimum), maxAt = at(e->maximum);
    const double scale = unitScale(c, units);
    const double lo = e->minimum.value * scale, hi = e->maximum.value * scale;
    // As `extremes` prints them: nine significant digits, the input to four decimals, a time
    // to six.
    const int decimals = timeBase ? 6 : 4;
    table.cells.push_back({columnName(c, units), kinematics::formatShort(lo, 9), formatFixed(minAt, decimals),
                           kinematics::formatShort(hi, 9), formatFixed(maxAt, decimals)});
    table.values.push_back({std::nullopt, lo, minAt, hi, maxAt});
  }
  return table;
}

// The curve of `column` over the fine sweep, broken where it has no value.
PlotCurve curveOf(const Mechanism& m, const SweepResult& r, const SweepColumn& c, const ReportUnits& units) {
  PlotCurve curve{columnHeading(m, c, units).heading, {}};
  const double scale = unitScale(c, units);
  bool open = false;
  for (std::size_t j = 0; j < r.size(); ++j) {
    const bool valid = c.isRate() ? r.ok(j) : r.assembled(j);
    if (!valid || (j > 0 && r.lockedAfter(j - 1))) open = false;
    if (!valid) continue;
    if (!open) curve.segments.emplace_back();
    open = true;
    const double x = r.time.empty() ? inputDisplayValue(m, r.inputAngle[j]) : r.time[j];
    curve.segments.back().emplace_back(x, c.value(r, j) * scale);
  }
  return curve;
}

std::vector<ReportPlot> plotsOf(const Mechanism& m, const SweepResult& r, const std::vector<SweepColumn>& columns,
                                const ReportUnits& units) {
  const std::string unit = inputUnit(m) == "°" ? "deg" : inputUnit(m);
  const std::string xTitle = r.time.empty() ? inputName(m) + " (" + unit + ")" : "time (s)";
  std::vector<ReportPlot> plots;
  for (const PlotKind& kind : plotKinds(m, units)) {
    ReportPlot plot{kind.title, xTitle, kind.unit, {}};
    for (const SweepColumn& c : columns)
      if (std::find(kind.quantities.begin(), kind.quantities.end(), c.quantity) != kind.quantities.end())
        plot.curves.push_back(curveOf(m, r, c, units));
    if (!plot.curves.empty()) plots.push_back(std::move(plot));
  }
  return plots;
}

// "F_O2_N" → ("F_O2", "N"); "T_drive_Nm" → ("T_drive", "N·m").
TableColumn forceHeading(const std::string& name) {
  for (const auto& [suffix, unit] : {std::pair{"_Nm", "N·m"}, {"_N", "N"}})
    if (name.ends_with(suffix)) return {name.substr(0, name.size() - std::string(suffix).size()), unit};
  return {name, ""};
}

Result<ReportTable> forcesTable(const Mechanism& m, const LinkageDynamics& dynamics, const SweepResult& r,
                                const SweepColumn& input) {
  auto forces = sweepForces(m, dynamics, r);
  if (!forces) return Error{forces.error().code, "dynamics", "the forces: " + forces.error().message};
  std::vector<kinematics::ForceColumn> columns;
  for (kinematics::ForceColumn& c : kinematics::forceColumns(forces->bodies))
    if (c.isSummary()) columns.push_back(std::move(c));
  ReportTable table;
  table.columns.push_back(columnHeading(m, input));
  for (const kinematics::ForceColumn& c : columns) table.columns.push_back(forceHeading(c.name));
  for (std::size_t j = 0; j < r.size(); ++j) {
    if (!r.assembled(j)) continue;
    std::vector<std::string>& cells = table.cells.emplace_back();
    std::vector<std::optional<double>>& values = table.values.emplace_back();
    cells.push_back(cellText(input, r, j, ReportUnits{}, values.emplace_back()));
    for (const kinematics::ForceColumn& c : columns) {
      if (!forces->ok(j)) {
        cells.push_back(r.ok(j) ? "singular" : "toggle");
        values.emplace_back();
        continue;
      }
      values.emplace_back(c.value(*forces, j));
      cells.push_back(formatFixed(*values.back(), kTableDecimals));
    }
  }
  return table;
}

// Where the shaking force and moment peak over the fine sweep (of `grid`), refined between its
// samples on poses solved afresh (force_extrema.h), and for a crank how far the driving torque by
// virtual work is from Newton–Euler's, for the forces' caption.
Result<std::string> forcesOverCycle(const Mechanism& m, const LinkageDynamics& dynamics, const SweepSpec& grid,
                                    const SweepResult& fine) {
  auto forces = sweepForces(m, dynamics, fine);
  if (!forces) return Error{forces.error().code, "dynamics", "the forces: " + forces.error().message};
  double torquePeak = 0.0, torqueDifference = 0.0;
  for (std::size_t j = 0; j < forces->size(); ++j) {
    if (!forces->ok(j)) continue;
    torquePeak = std::max(torquePeak, std::abs(forces->driveTorque[j]));
    torqueDifference = std::max(torqueDifference, std::abs(forces->driveTorque[j] - forces->virtualWorkTorque[j]));
  }
  const auto peaks = shakingPeaks(m, dynamics, grid, *forces);
  if (!peaks) return std::string();
  const auto at = [&](const Extremum& e) {
    const std::string unit = inputUnit(m);
    return grid.time ? formatShort(e.time) + " s"
                     : formatShort(inputDisplayValue(m, e.inputAngle)) + (unit == "°" ? unit : " " + unit);
  };
  std::string text = " Refined between the cycle's " + std::to_string(fine.size()) +
                     " samples, the shaking force peaks at " + formatShort(peaks->force.value, 4) + " N (at " +
                     at(peaks->force) + ") and the shaking moment at " + formatShort(peaks->moment.value, 4) +
                     " N·m (at " + at(peaks->moment) + ").";
  if (forces->bodies.drive.kind == DriveKind::Crank && torquePeak > 0.0)
    text += " The driving torque by virtual work differs from Newton–Euler's by at most " +
            formatShort(torqueDifference, 2) + " N·m (" + formatShort(torqueDifference / torquePeak, 2) +
            " of its peak).";
  return text;
}

// The span the table runs over: the grid's inputs, or its time base's times.
double spanOf(const SweepSpec& grid) {
  return grid.time ? grid.time->toTime - grid.time->fromTime : grid.toAngle - grid.fromAngle;
}

// The table's grid: the plots' range every `step`, its last row where a whole step lands.
SweepSpec tableSpec(const SweepSpec& grid, double step) {
  SweepSpec spec = grid;
  const double intervals = std::floor(spanOf(grid) / step + 1e-9);
  spec.samples = static_cast<std::size_t>(intervals) + 1;
  if (spec.time) spec.time->toTime = grid.time->fromTime + intervals * step;
  else spec.toAngle = grid.fromAngle + intervals * step;
  return spec;
}

std::optional<Error> checkRequest(const Mechanism& m, const ReportRequest& request) {
  if (auto e = checkSweepSpec(request.grid, inputKind(m))) return e;
  const double span = spanOf(request.grid);
  if (request.tableStep > 0.0 && std::floor(span / request.tableStep + 1e-9) + 1.0 > kMaxTableRows) {
    const bool time = request.grid.time.has_value();
    const auto shown = [&](double v) {
      return time ? kinematics::formatShort(v) + " s"
                  : kinematics::formatShort(inputDisplayValue(m, v) - inputDisplayValue(m, 0.0));
    };
    return Error{ErrorCode::InvalidValue, "tableStep",
                 "the table step " + shown(request.tableStep) + " gives more than " +
                     kinematics::formatShort(kMaxTableRows) + " rows; a report's step must be at least " +
                     shown(span / (kMaxTableRows - 1.0))};
  }
  if (const auto& time = request.grid.time) {
    if (!(std::isfinite(request.tableStep) && request.tableStep > 0.0 && request.tableStep <= std::max(span, 1e-300)))
      return Error{ErrorCode::InvalidValue, "tableStep",
                   "the table step must be positive and at most the time span tabulated, " +
                       kinematics::formatShort(span) + " s (got " + kinematics::formatShort(request.tableStep) + " s)"};
    if (!(request.drawAt >= time->fromTime && request.drawAt <= time->toTime))
      return Error{ErrorCode::InvalidValue, "time",
                   "the drawn time (--at) must be within the time span, " + kinematics::formatShort(time->fromTime) +
                       " to " + kinematics::formatShort(time->toTime) + " s (got " +
                       kinematics::formatShort(request.drawAt) + " s)"};
    return std::nullopt;
  }
  if (!(std::isfinite(request.tableStep) && request.tableStep > 0.0 && request.tableStep <= std::max(span, 1e-300)))
    return Error{ErrorCode::InvalidValue, "tableStep",
                 "the table step must be positive and at most the range tabulated, " +
                     kinematics::formatShort(inputDisplayValue(m, request.grid.fromAngle + span) -
                                             inputDisplayValue(m, request.grid.fromAngle)) +
                     " (got " + kinematics::formatShort(inputDisplayValue(m, request.tableStep)) + ")"};
  return std::nullopt;
}

}  // namespace

void setReportHeading(ReportRequest& request, const std::string& name, const std::string& description,
                      const std::string& kind) {
  request.title = name;
  request.subtitle = description.empty() ? kind : description;
  if (request.subtitle == request.title) request.subtitle.clear();
}

Result<ReportContent> buildReport(const Mechanism& m, const LinkageDynamics& dynamics, const ReportRequest& request) {
  if (auto e = checkRequest(m, request)) return *e;
  ReportContent report;
  report.title = request.title;
  report.subtitle = request.subtitle;
  report.date = request.date;
  // On a time base the drawn pose is the law's at the time asked for.
  const double drawnInput =
      request.grid.time ? motionAt(request.grid.time->law, request.drawAt).position : request.drawAt;
  auto drawing = reportDrawing(m, drawnInput);
  if (!drawing) return drawing.error();
  report.drawing = std::move(*drawing);
  const SweepSpec tSpec = tableSpec(request.grid, request.tableStep);
  const auto table = sweep(m, tSpec);
  const auto fine = sweep(m, request.grid);
  // The plots need more than a coarse grid (the thesis example's is every 30°): at least 720
  // steps, every half degree of a crank's turn.
  SweepSpec plotSpec = request.grid;
  plotSpec.samples = std::max<std::size_t>(plotSpec.samples, kPlotSamples);
  const auto plotted = sweep(m, plotSpec);
  if (!table) return table.error();
  if (!fine) return fine.error();
  if (!plotted) return plotted.error();
  report.analysis = analysisLines(m, *plotted);
  const std::vector<SweepColumn> columns = reportColumns(m, *table);
  report.table = sweepTable(m, *table, columns, request.units);
  report.tableCaption =
      tSpec.time ? timeCaption(m, tSpec, "every " + kinematics::formatShort(request.tableStep) + " s")
                 : gridCaption(m, tSpec, "every " + inputText(m, request.tableStep, false), request.units.rates);
  report.extremes = extremesTable(m, request.grid, *fine, columns, request.units);
  const std::string refined = "refined between " + std::to_string(request.grid.samples) + " samples";
  report.extremesCaption = request.grid.time ? timeCaption(m, request.grid, refined)
                                             : gridCaption(m, request.grid, refined, request.units.rates);
  report.plots = plotsOf(m, *plotted, columns, request.units);
  if (!dynamics.empty()) {
    auto forces = forcesTable(m, dynamics, *table, columns.front());
    if (!forces) return forces.error();
    report.forces = std::move(*forces);
    const auto peaks = forcesOverCycle(m, dynamics, request.grid, *fine);
    if (!peaks) return peaks.error();
    report.forcesCaption =
        "Joint force sizes, driving torque or force, shaking force (N, N·m), at the table's inputs." + *peaks;
  }
  report.notes = sweepNotes(m, *fine);
  return report;
}

}  // namespace linkwright::kinematics::report
