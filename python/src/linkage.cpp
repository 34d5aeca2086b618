#include "python/src/linkage.h"

#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/design/sweep_grid.h"
#include "kinematics/dynamics/force_columns.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/io/bounded_read.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/io/document_json.h"
#include "kinematics/io/law_table_csv.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/sweep_columns.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <tuple>

namespace linkwright::python {

namespace k = kinematics;

namespace {

// A table held whole in Python must fit: the arrays take about 18 bytes a cell (the values, the
// mask, and NumPy's copy of both), the CSV about 50 (its text, and Python's copy of it).
constexpr double kMostTableBytes = 2e9;
constexpr double kArrayBytesPerCell = 18.0, kCsvBytesPerCell = 50.0;

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
  const k::Design design = k::designFromExample(*e);
  return Linkage{std::move(e->mechanism),  k::sweepGridOf(*e),
                 std::move(e->dynamics),   e->kind,
                 "the example " + e->name, {design.omega, design.alpha, design.fromDeg, design.toDeg, design.samples}};
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
  return designLinkage(*design, path);
}

Linkage designLinkage(const k::Design& design, std::string source) {
  return Linkage{design.mechanism,  k::sweepGridOf(design),
                 design.dynamics,   design.kind,
                 std::move(source), {design.omega, design.alpha, design.fromDeg, design.toDeg, design.samples}};
}

k::Design linkageDesign(const Linkage& linkage) {
  k::Design d;
  d.kind = linkage.kind;
  d.mechanism = linkage.mechanism;
  d.dynamics = linkage.dynamics;
  d.omega = linkage.designGrid.omega;
  d.alpha = linkage.designGrid.alpha;
  d.fromDeg = linkage.designGrid.fromDeg;
  d.toDeg = linkage.designGrid.toDeg;
  d.samples = linkage.designGrid.samples;
  d.time = linkage.grid.time;
  if (d.time) d.samples = static_cast<std::size_t>(linkage.grid.timeSamples);
  return d;
}

std::string linkageState(const Linkage& linkage) {
  const k::Design d = linkageDesign(linkage);
  // The grid's numbers as hexadecimal floats (exact), then the source's name, then the document.
  const k::SweepGrid& g = linkage.grid;
  std::ostringstream out;
  out << std::hexfloat << g.omega << ' ' << g.alpha << ' ' << g.fromDeg << ' ' << g.toDeg << ' ' << g.stepDeg << ' '
      << g.timeSamples << '\n'
      << linkage.source << '\n'
      << k::io::writeDocument(d);
  return std::move(out).str();
}

k::Result<Linkage> linkageFromState(const std::string& state) {
  std::istringstream in(state);
  std::string numbers, source;
  std::getline(in, numbers);
  std::getline(in, source);
  const auto documentAt = static_cast<std::size_t>(in.tellg());
  std::istringstream values(numbers);
  std::string omega, alpha, from, to, step;
  long long timeSamples = 0;
  values >> omega >> alpha >> from >> to >> step >> timeSamples;
  if (!values || documentAt > state.size())
    return k::Error{k::ErrorCode::InvalidValue, "state", "not a pickled linkwright.Linkage"};
  auto design = k::io::readDocument(std::string_view(state).substr(documentAt));
  if (!design) return k::Error{design.error().code, "state", "a pickled Linkage: " + design.error().message};
  Linkage l = designLinkage(*design, source);
  // std::strtod reads hexadecimal floats exactly (operator>> does not, in libstdc++).
  l.grid.omega = std::strtod(omega.c_str(), nullptr);
  l.grid.alpha = std::strtod(alpha.c_str(), nullptr);
  l.grid.fromDeg = std::strtod(from.c_str(), nullptr);
  l.grid.toDeg = std::strtod(to.c_str(), nullptr);
  l.grid.stepDeg = std::strtod(step.c_str(), nullptr);
  l.grid.timeSamples = timeSamples;
  return l;
}

k::Result<k::SweepSpec> sweepSpecFor(const Linkage& linkage, const SweepOptions& o) {
  // The keyword arguments; the module offers no rpm or step, so their names are empty.
  static const k::GridFieldNames names{"",           "omega",     "alpha",       "start_deg",   "stop_deg",
                                       "",           "samples",   "law",         "ramp_time_s", "rise_deg",
                                       "duration_s", "law_table", "from_time_s", "to_time_s",   "step_time_s"};
  k::SweepGrid grid = linkage.grid;
  grid.input = k::inputKind(linkage.mechanism);
  grid.lengthUnit = linkage.mechanism.lengthUnit;
  k::SweepGridRequest request{std::nullopt, o.omega, o.alpha, o.startDeg, o.stopDeg, std::nullopt, o.samples};
  request.law = o.law;
  request.rampTime = o.rampTimeS;
  request.rise = o.riseDeg;
  request.duration = o.durationS;
  request.fromTime = o.fromTimeS;
  request.toTime = o.toTimeS;
  request.stepTime = o.stepTimeS;
  if (o.lawTable) {
    const auto text = k::io::readFileBounded(*o.lawTable, k::io::kMaxLawTableBytes, "a table");
    if (!text) return badValue("law_table", text.error().message);
    auto table = k::io::readLawTableCsv(*text, grid.input, grid.lengthUnit);
    if (!table) return badValue("law_table", *o.lawTable + ": " + table.error().message);
    request.table = std::move(table).value();
  }
  auto spec = k::sweepGridSpec(request, grid, names);
  if (!spec) {
    // The core names a field by its neutral key; a refusal here names the keyword.
    k::Error e = spec.error();
    using F = k::GridField;
    for (const auto field : {F::Omega, F::Alpha, F::Start, F::Stop, F::Samples, F::Law, F::RampTime, F::Rise,
                             F::Duration, F::LawTable, F::FromTime, F::ToTime, F::StepTime})
      if (e.field == k::gridFieldKey(field)) {
        e.field = names[field];
        break;
      }
    return e;
  }
  if (auto e = k::checkSweepSpec(*spec, grid.input)) return *e;
  return spec;
}

k::Result<SweepTable> sweepTable(const Linkage& linkage, const k::SweepSpec& spec, const TableRequest& request) {
  const k::Mechanism& m = linkage.mechanism;
  if (request.forces && linkage.dynamics.empty())
    return badValue("forces", "needs masses and loads, and " + linkage.source +
                                  " has none: give them in a document's \"dynamics\" (see docs/document_format.md), "
                                  "or try linkwright.example(\"funsho-fourbar\")");
  SweepTable table;
  std::ostringstream csvText;
  k::io::SweepCsvWriter csv(csvText, m);
  std::vector<k::SweepColumn> columns;
  std::vector<k::ForceColumn> forceColumns;
  std::optional<k::Error> refused;
  bool sized = false;
  auto swept = k::sweepInWindows(m, spec, {}, k::kSweepWindow, [&](const k::SweepResult& part, std::size_t) {
    std::optional<k::ForceSweep> forces;
    if (request.forces) {
      auto solved = k::sweepForces(m, linkage.dynamics, part);
      if (!solved) {
        refused = k::Error{solved.error().code, "forces", solved.error().message};
        return false;
      }
      forces = std::move(solved).value();
    }
    if (!sized) {
      sized = true;
      const std::size_t count = k::sweepColumns(m, part.request, !part.time.empty()).size() +
                                (forces ? k::forceColumns(forces->bodies).size() : 0);
      const double bytesPerRow = static_cast<double>(count) * (request.csv ? kCsvBytesPerCell : kArrayBytesPerCell);
      const double rows = static_cast<double>(spec.samples);
      if (rows * bytesPerRow > kMostTableBytes) {
        const auto most = static_cast<long long>(kMostTableBytes / bytesPerRow);
        refused = k::Error{k::ErrorCode::InvalidValue, "samples",
                           "samples: a table held whole in Python may take at most 2 GB, about " +
                               std::to_string(most) + " samples of this linkage's " + std::to_string(count) +
                               " columns (got " + std::to_string(spec.samples) +
                               "); linkwright-cli analyze -o FILE writes any number of samples, streamed"};
        return false;
      }
    }
    if (request.csv) csv.write(part, forces ? &*forces : nullptr);
    if (!request.columns) return true;
    if (table.names.empty()) {
      columns = k::sweepColumns(m, part.request, !part.time.empty());
      if (forces) forceColumns = k::forceColumns(forces->bodies);
      for (const k::SweepColumn& c : columns) table.names.push_back(c.name);
      for (const k::ForceColumn& c : forceColumns) table.names.push_back(c.name);
      table.values.resize(table.names.size());
      table.defined.resize(table.names.size());
    }
    for (std::size_t j = 0; j < part.size(); ++j) {
      if (!part.assembled(j)) continue;  // as the CSV: the row is left out
      // The CSV's empty cells: rates at a toggle, forces where they are not determined, and (by
      // number_text's one rule) anything not finite.
      const auto add = [&](std::size_t c, double value, bool defined) {
        defined = defined && std::isfinite(value);
        table.values[c].push_back(defined ? value : 0.0);
        table.defined[c].push_back(defined);
      };
      for (std::size_t c = 0; c < columns.size(); ++c) {
        const k::SweepColumn& column = columns[c];
        const double value = column.value(part, j);
        add(c, isGridColumn(column) ? gridCellValue(value) : value, part.ok(j) || !column.isRate());
      }
      for (std::size_t c = 0; c < forceColumns.size(); ++c)
        add(columns.size() + c, forceColumns[c].value(*forces, j), forces->ok(j));
    }
    return true;
  });
  if (refused) return *refused;
  if (!swept) return swept.error();
  table.summary = std::move(swept).value();
  table.csv = std::move(csvText).str();
  return table;
}

}  // namespace linkwright::python
