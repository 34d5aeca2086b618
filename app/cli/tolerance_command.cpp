// `linkwright-cli tolerance`: a tolerance study of a linkage (kinematics/design/
// tolerance_monte_carlo.h, tolerance_sensitivity.h): ± --tolerance on every length and pivot,
// a Monte-Carlo run over the grid with its worst deviation per output column, the first-order
// worst case from the exact sensitivities beside it, and the largest sensitivity of each column
// to each dimension (or all of them at --at). Text for reading, JSON in the linkage's length
// unit and the columns' units, and with -o the band as CSV through the one writer.

#include "app/cli/commands.h"
#include "app/cli/progress.h"

#include "kinematics/io/csv_writer.h"
#include "kinematics/io/json.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/number_text.h"
#include "kinematics/tune/tolerance_monte_carlo.h"
#include "kinematics/tune/tolerance_sensitivity.h"

#include <algorithm>
#include <limits>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

// The unit after a column's name: "coupler_angle_deg" → "deg", "P_x_mm" → "mm".
std::string unitOf(const k::SweepColumn& c, const std::string& lengthUnit) {
  return k::columnUnit(c.quantity, lengthUnit);
}

// The study's grid input at a sample, as its column shows it (degrees, length or seconds).
struct InputAxis {
  k::SweepColumn column;
  k::SweepSpec spec;
  double at(std::size_t j) const { return k::toleranceInputAt(column, spec, j); }
  double at(const k::SweepResult& s, std::size_t j) const { return column.value(s, j); }
};

struct Study {
  k::MonteCarloResult monteCarlo;
  k::SensitivitySummary sensitivities;      // over the grid, folded window by window
  std::optional<k::SweepSensitivities> at;  // --at: one input
  InputAxis input;
  std::string unit;
};

std::string optionFor(const std::string& field) {
  if (field == "tolerance") return "--tolerance";
  if (field == "samples") return "--mc-samples";
  if (field.rfind("perDimension", 0) == 0) return "--tolerance-of";
  if (field == "band") return "-o";
  return "";
}

// The dimension with the largest sensitivity of column c, and that sensitivity.
std::pair<std::size_t, double> mostSensitive(const k::SensitivitySummary& s, std::size_t c) {
  std::size_t best = 0;
  double value = -1.0;
  for (std::size_t d = 0; d < s.dimensions.size(); ++d)
    if (const double v = s.largest[c][d]; v > value) {
      value = v;
      best = d;
    }
  return {best, value};
}

void printText(std::ostream& out, const Study& st, const std::string& source) {
  const auto& mc = st.monteCarlo;
  const auto& s = st.sensitivities;
  const std::string& u = st.unit;
  const auto n = [](double v) { return formatShort(v, 4); };
  const std::size_t last = mc.inputs - 1;
  out << "tolerance study of " << source << ": ±" << n(mc.spec.tolerance) << " " << u << " on " << mc.dimensions.size()
      << " dimensions";
  for (const k::DimensionTolerance& own : mc.spec.perDimension)
    out << (&own == &mc.spec.perDimension.front() ? " (" : ", ") << own.dimension << " ±" << n(own.tolerance);
  out << (mc.spec.perDimension.empty() ? "" : ")") << ", each uniform and independent; " << mc.spec.samples
      << " samples (seed " << mc.spec.seed << "), each swept over " << mc.inputs << " inputs (" << st.input.column.name
      << " " << n(st.input.at(0)) << " to " << n(st.input.at(last)) << ")\n";
  out << "samples: " << mc.used << " in the band, " << mc.notAssembled << " did not assemble at every input, "
      << mc.singular << " met a toggle\n";
  const k::MonteCarloError& e = mc.error;
  const auto percent = [&](double f) { return n(100.0 * f) + " %"; };
  out << "Monte-Carlo error, for the " << e.samples << " samples in the band: one more linkage falls outside the band "
      << "at an input with chance 2/(n+1) = " << n(e.outsideBand) << " (with " << percent(k::kToleranceConfidence)
      << " confidence at most " << percent(e.outsideBandBound) << " of all linkages lie outside it), and deviates "
      << "more than a column's worst with chance 1/(n+1) = " << n(e.beyondWorst) << " (at most "
      << percent(e.beyondWorstBound) << "); at most 1 % outside with " << percent(k::kToleranceConfidence)
      << " confidence takes " << k::toleranceSamplesFor(0.01) << " samples in the band, 0.1 % takes "
      << k::toleranceSamplesFor(0.001) << "\n";
  out << "dimensions (" << u << "):";
  for (const auto& d : mc.dimensions) out << " " << d.name << " " << n(d.value) << ";";
  out << "\n\n";
  std::size_t width = 6;
  for (const auto& b : mc.bands) width = std::max(width, b.column.name.size());
  const auto pad = [](std::string text, std::size_t w) {
    text.resize(std::max(w, text.size() + 1), ' ');
    return text;
  };
  out << "MC worst: the deviation of the sample that deviates most at the grid's inputs; first order: "
         "sum of |dy/dp|·t over the dimensions; each refined between the grid's inputs\n";
  out << pad("column", width + 2) << pad("MC worst", 12) << pad("at " + st.input.column.name, 22)
      << pad("first order", 13) << pad("at " + st.input.column.name, 22) << "most sensitive to\n";
  for (std::size_t c = 0; c < mc.bands.size(); ++c) {
    const auto& b = mc.bands[c];
    const auto [d, value] = mostSensitive(s, c);
    out << pad(b.column.name, width + 2) << pad(n(b.worstDeviation), 12)
        << pad(mc.used > 0 ? n(b.worstInput) : std::string(k::kUndefinedText), 22) << pad(n(s.firstOrderWorst[c]), 13)
        << pad(n(s.firstOrderWorstInput[c]), 22);
    // The driven crank's ω and α are the driver's: sensitive to nothing.
    if (value > 0.0) out << s.dimensions[d].name << " (" << n(value) << " " << unitOf(b.column, u) << "/" << u << ")\n";
    else out << "none\n";
  }
  out << "\nsensitivities, "
      << (st.at ? "at " + st.input.column.name + " " + n(st.input.at(st.at->sweep, 0))
                : std::string("largest |∂y/∂p| over the grid's range, refined between its inputs"))
      << " (each column's unit per " << u << "):\n";
  for (std::size_t c = 0; c < s.columns.size(); ++c) {
    out << "  " << s.columns[c].name << ":";
    for (std::size_t d = 0; d < s.dimensions.size(); ++d)
      out << " " << s.dimensions[d].name << " " << n(st.at ? st.at->derivative[c][d][0] : s.largest[c][d])
          << (d + 1 < s.dimensions.size() ? "," : "");
    out << "\n";
  }
}

// The dimensions with a ± of their own, by name.
k::io::JsonValue ownTolerances(const k::MonteCarloSpec& spec) {
  k::io::JsonValue own = k::io::JsonValue::object();
  for (const k::DimensionTolerance& t : spec.perDimension) own[t.dimension] = t.tolerance;
  return own;
}

void printJson(std::ostream& out, const Study& st, const std::string& source) {
  const auto& mc = st.monteCarlo;
  const auto& s = st.sensitivities;
  const std::string& u = st.unit;
  k::io::JsonValue json{{"source", source},
                        {"length_unit", u},
                        {"tolerance_" + u, mc.spec.tolerance},
                        {"own_tolerances_" + u, ownTolerances(mc.spec)},
                        {"distribution", "uniform"},
                        {"samples", mc.spec.samples},
                        {"seed", mc.spec.seed},
                        {"samples_in_band", mc.used},
                        {"samples_not_assembled", mc.notAssembled},
                        {"samples_singular", mc.singular},
                        {"input_column", st.input.column.name},
                        {"inputs", mc.inputs}};
  k::io::JsonValue dims = k::io::JsonValue::array();
  for (const auto& d : mc.dimensions) dims.push_back({{"name", d.name}, {"nominal_" + u, d.value}});
  json["dimensions"] = dims;
  const k::MonteCarloError& e = mc.error;
  json["monte_carlo_error"] = k::io::JsonValue{
      {"samples", e.samples},
      {"confidence", k::kToleranceConfidence},
      {"outside_band_chance", e.outsideBand},
      {"outside_band_at_confidence", e.outsideBandBound},
      {"beyond_worst_chance", e.beyondWorst},
      {"beyond_worst_at_confidence", e.beyondWorstBound},
      {"samples_for_outside_band",
       k::io::JsonValue{{"0.01", k::toleranceSamplesFor(0.01)}, {"0.001", k::toleranceSamplesFor(0.001)}}}};
  k::io::JsonValue columns = k::io::JsonValue::array();
  for (std::size_t c = 0; c < mc.bands.size(); ++c) {
    const auto& b = mc.bands[c];
    k::io::JsonValue column{{"name", b.column.name},
                            {"worst_deviation", b.worstDeviation},
                            {"worst_at", mc.used > 0 ? b.worstInput : kNoValue},
                            {"worst_on_grid", b.sampledWorstDeviation},
                            {"first_order_worst", s.firstOrderWorst[c]},
                            {"first_order_worst_at", s.firstOrderWorstInput[c]},
                            {"first_order_worst_on_grid", s.sampledFirstOrderWorst[c]}};
    k::io::JsonValue largest = k::io::JsonValue::object();
    for (std::size_t d = 0; d < s.dimensions.size(); ++d) largest[s.dimensions[d].name] = s.largest[c][d];
    column["largest_sensitivity_per_" + u] = largest;
    if (st.at) {
      k::io::JsonValue at = k::io::JsonValue::object();
      for (std::size_t d = 0; d < st.at->dimensions.size(); ++d)
        at[st.at->dimensions[d].name] = st.at->derivative[c][d][0];
      column["sensitivity_at_per_" + u] = at;
    }
    columns.push_back(column);
  }
  if (st.at) json["at"] = st.input.at(st.at->sweep, 0);
  json["columns"] = columns;
  // A value that is not finite (a band nobody reached) is a JSON null, never nan.
  out << json.dump(2) << "\n";
}

// The band as CSV: the input, then per column its nominal, lowest and highest value.
std::optional<std::string> writeBand(std::ostream& out, const Study& st) {
  const auto& mc = st.monteCarlo;
  out << k::io::csvField(st.input.column.name);
  for (const auto& b : mc.bands)
    out << "," << k::io::csvField(b.column.name) << "," << k::io::csvField("low_" + b.column.name) << ","
        << k::io::csvField("high_" + b.column.name);
  out << "\r\n";
  for (std::size_t j = 0; j < mc.inputs; ++j) {
    out << k::formatDouble(st.input.at(j));
    for (const auto& b : mc.bands)
      out << "," << k::formatDouble(b.nominal[j]) << "," << k::formatDouble(b.low[j]) << ","
          << k::formatDouble(b.high[j]);
    out << "\r\n";
  }
  return std::nullopt;
}

// The spec of one input, --at, with the grid's rates.
k::SweepSpec atSpec(k::SweepSpec spec, double input) {
  if (spec.time) spec.time->fromTime = spec.time->toTime = input;
  else spec.fromAngle = spec.toAngle = input;
  spec.samples = 1;
  return spec;
}

}  // namespace

ExitCode runTolerance(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto resolved = resolveMechanism(inv);
  if (!resolved) {
    err << "linkwright-cli: " << resolved.error().message << "\n";
    return ExitCode::BadInput;
  }
  const k::Mechanism& m = resolved->mechanism;
  const auto spec = sweepSpecFor(inv, resolved->defaults);
  if (!spec) {
    err << "linkwright-cli: " << spec.error().message << "\n";
    return ExitCode::BadInput;
  }
  if (auto e = checkAtOption(inv, resolved->defaults)) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::BadInput;
  }
  const long long samples = inv.monteCarloSamples.value_or(1000);
  if (samples < 1 || samples > static_cast<long long>(k::kMaxToleranceSamples)) {
    err << "linkwright-cli: --mc-samples must be between 1 and " << k::kMaxToleranceSamples << " (got " << samples
        << ")\n";
    return ExitCode::BadInput;
  }
  k::MonteCarloSpec mcSpec{*inv.tolerance, static_cast<std::size_t>(samples),
                           inv.seed.value_or(k::kDefaultToleranceSeed)};
  for (const auto& [name, t] : inv.toleranceOf) mcSpec.perDimension.push_back({name, t});
  // The band at every input is held only to be written; without -o the grid streams.
  mcSpec.band = inv.outputFile.has_value();
  auto mc = [&] {
    Progress progress(err, "tolerance", "samples");
    k::RunControl control;
    control.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
    return k::toleranceMonteCarlo(m, *spec, mcSpec, control);
  }();
  if (!mc) {
    const k::Error& e = mc.error();
    const std::string option = optionFor(e.field);
    err << "linkwright-cli: " << (option.empty() ? "" : option + ": ") << e.message
        << (e.field == "band" ? "; give a coarser grid (--samples, --step) or leave out -o, without which the study "
                                "streams the grid"
                              : "")
        << "\n";
    return e.code == k::ErrorCode::NotAssemblable || e.code == k::ErrorCode::Singular ? ExitCode::NotAssemblable
                                                                                      : ExitCode::BadInput;
  }
  auto sensitivities = [&] {
    Progress progress(err, "tolerance: sensitivities", "inputs");
    k::RunControl control;
    control.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
    return k::sensitivitySummary(m, *spec, k::dimensionTolerances(mcSpec, mc->dimensions), control);
  }();
  if (!sensitivities) {
    err << "linkwright-cli: " << sensitivities.error().message << "\n";
    return ExitCode::BadInput;
  }
  Study st{std::move(*mc), std::move(*sensitivities), std::nullopt,
           InputAxis{k::sweepColumns(m, k::SolveRequest{}, spec->time.has_value()).front(), *spec}, m.lengthUnit};
  if (!inv.atDeg.empty()) {
    const double input = spec->time ? inv.atDeg.front() : resolved->defaults.toInput(inv.atDeg.front());
    auto at = k::sweepSensitivities(m, atSpec(*spec, input));
    if (!at || !at->sweep.ok(0)) {
      err << "linkwright-cli: --at: "
          << (at ? at->sweep.firstFailure.value_or("the linkage is at a toggle there") : at.error().message) << "\n";
      return ExitCode::NotAssemblable;
    }
    st.at = std::move(*at);
  }
  if (inv.outputFile) {
    if (auto e = k::io::writeStreamSafely(*inv.outputFile, [&](std::ostream& o) { return writeBand(o, st); })) {
      err << "linkwright-cli: " << e->message << "\n";
      return ExitCode::IoError;
    }
  }
  if (inv.json) printJson(out, st, resolved->source);
  else printText(out, st, resolved->source);
  return ExitCode::Success;
}

}  // namespace linkwright::cli
