// Linkage.tolerance_study (kinematics/tune/tolerance_monte_carlo.h): the seeded Monte-Carlo
// study linkwright-cli tolerance runs, over samples [first_sample, first_sample + mc_samples),
// so linkwright.batch can run a study of any size as shards whose bands it combines by their
// lowest and highest values (exactly the one run's).

#include "python/src/bindings.h"
#include "python/src/convert.h"

#include "kinematics/tune/tolerance_monte_carlo.h"

#include <pybind11/stl.h>

#include <optional>
#include <string>

namespace linkwright::python {
namespace {

namespace k = kinematics;

// The Python keywords for the fields the core names.
k::Error spelled(k::Error e) {
  for (const auto& [core, keyword] :
       {std::pair<std::string, std::string>{"samples", "mc_samples"}, {"firstSample", "first_sample"}})
    if (e.field == core) {
      e.field = keyword;
      e.message.replace(0, core.size(), keyword);
    }
  // "perDimension[1]": the dict's entries in the order Python gives them.
  if (e.field.rfind("perDimension", 0) == 0) e.field = "per_dimension" + e.field.substr(12);
  return e;
}

// Entry `index` of per_dimension as a name and a ±: a str and a number, else refused naming
// the entry (pybind11's own refusal is a RuntimeError "Unable to cast").
std::pair<std::string, double> perDimensionEntry(std::size_t index, py::handle name, py::handle t) {
  const auto refuse = [&] {
    throw CoreError(k::Error{k::ErrorCode::InvalidValue, "per_dimension[" + std::to_string(index) + "]",
                             "per_dimension maps a dimension's name (a str) to its ± (a number, in the length unit); "
                             "entry " +
                                 std::to_string(index) + " is " + std::string(py::repr(name)) + ": " +
                                 std::string(py::repr(t))});
  };
  if (!py::isinstance<py::str>(name) || py::isinstance<py::str>(t) || py::isinstance<py::bytes>(t) ||
      py::isinstance<py::bool_>(t))
    refuse();
  try {
    return {name.cast<std::string>(), t.cast<double>()};
  } catch (const py::cast_error&) {
    refuse();
  }
  return {};
}

py::dict study(const Linkage& linkage, const SweepOptions& grid, double tolerance, long long samples,
               std::uint64_t seed, long long firstSample, const std::vector<std::pair<std::string, double>>& own) {
  // Checked as typed, before they become unsigned.
  if (samples < 1 || samples > static_cast<long long>(k::kMaxToleranceSamples))
    throw CoreError(k::Error{k::ErrorCode::InvalidValue, "mc_samples",
                             "mc_samples must be between 1 and " + std::to_string(k::kMaxToleranceSamples) + " (got " +
                                 std::to_string(samples) + ")"});
  if (firstSample < 0)
    throw CoreError(k::Error{k::ErrorCode::InvalidValue, "first_sample",
                             "first_sample must be between 0 and " + std::to_string(k::kMaxToleranceFirstSample) +
                                 " (got " + std::to_string(firstSample) + ")"});
  const k::SweepSpec spec = valueOrThrow(sweepSpecFor(linkage, grid));
  k::MonteCarloSpec mc{tolerance, static_cast<std::size_t>(samples), seed, static_cast<std::uint64_t>(firstSample)};
  for (const auto& [name, t] : own) mc.perDimension.push_back({name, t});
  auto ran = [&] {
    py::gil_scoped_release unlocked;
    return k::toleranceMonteCarlo(linkage.mechanism, spec, mc);
  }();
  if (!ran) throw CoreError(spelled(ran.error()));
  const k::MonteCarloResult r = std::move(ran).value();

  py::dict out;
  const k::SweepColumn input = k::sweepColumns(linkage.mechanism, r.nominal.request, !r.nominal.time.empty()).front();
  std::vector<double> inputs;
  for (std::size_t j = 0; j < r.nominal.size(); ++j) inputs.push_back(input.value(r.nominal, j));
  out["input_name"] = input.name;
  out["input"] = maskedArray(inputs, {});
  py::dict columns;
  for (const k::ToleranceBand& band : r.bands) {
    py::dict b;
    b["nominal"] = maskedArray(band.nominal, {});
    b["low"] = maskedArray(band.low, {});
    b["high"] = maskedArray(band.high, {});
    b["worst_deviation"] = number(band.worstDeviation);
    b["worst_at"] = std::isfinite(band.worstDeviation) ? py::object(py::int_(band.worstGridSample)) : py::none();
    b["worst_input"] = std::isfinite(band.worstDeviation) ? number(band.worstInput) : py::none();
    b["worst_on_grid"] = number(band.sampledWorstDeviation);
    columns[py::str(band.column.name)] = b;
  }
  out["columns"] = columns;
  py::list dimensions;
  for (const k::ToleranceDimension& d : r.dimensions) dimensions.append(d.name);
  out["dimensions"] = dimensions;
  out["tolerance"] = number(tolerance);
  py::dict perDimension;
  for (const k::DimensionTolerance& t : mc.perDimension) perDimension[py::str(t.dimension)] = number(t.tolerance);
  out["per_dimension"] = perDimension;
  out["seed"] = seed;
  out["first_sample"] = firstSample;
  out["mc_samples"] = samples;
  out["used"] = r.used;
  out["not_assembled"] = r.notAssembled;
  out["singular"] = r.singular;
  return out;
}

}  // namespace

void bindTolerance(py::class_<Linkage>& linkage) {
  linkage.def(
      "tolerance_study",
      [](const Linkage& l, double tolerance, long long mcSamples, std::uint64_t seed, long long firstSample,
         std::optional<double> startDeg, std::optional<double> stopDeg, std::optional<long long> samples,
         std::optional<double> omega, std::optional<double> alpha, const py::dict& perDimension) {
        // The dict in its own order, so that a refusal's index is the entry's.
        std::vector<std::pair<std::string, double>> own;
        for (const auto& [name, t] : perDimension) own.push_back(perDimensionEntry(own.size(), name, t));
        return study(l, {startDeg, stopDeg, samples, omega, alpha}, tolerance, mcSamples, seed, firstSample, own);
      },
      py::arg("tolerance"), py::kw_only(), py::arg("mc_samples") = 1000, py::arg("seed") = k::kDefaultToleranceSeed,
      py::arg("first_sample") = 0, py::arg("start_deg") = py::none(), py::arg("stop_deg") = py::none(),
      py::arg("samples") = py::none(), py::arg("omega") = py::none(), py::arg("alpha") = py::none(),
      py::arg("per_dimension") = py::dict(),
      "linkwright-cli tolerance's Monte-Carlo study: every length and pivot coordinate moved by a uniform offset "
      "in ±tolerance (the length unit; per_dimension={'coupler length': 0.02} gives a dimension a ± of its own, as "
      "--tolerance-of), mc_samples linkages (samples first_sample onwards: sample k's offsets "
      "depend on the seed and k alone) swept over the grid (keywords as sweep's). Returns a dict: input_name, "
      "input (the grid), columns (per output column: nominal, low, high as masked arrays over the grid, "
      "worst_deviation, refined between the grid's inputs; worst_input, where, in the input's unit; worst_at, "
      "the grid index nearest it; worst_on_grid, the same linkage's worst at the inputs alone), dimensions, used, "
      "not_assembled, singular and the study's "
      "tolerance, seed, first_sample, mc_samples.");
}

}  // namespace linkwright::python
