// Linkage.extremes (kinematics/analysis/column_extrema.h): each column's refined minimum and
// maximum over a sweep and where they fall, as linkwright-cli extremes prints them.

#include "python/src/bindings.h"
#include "python/src/convert.h"

#include "kinematics/analysis/column_extrema.h"
#include "kinematics/model/driver.h"

#include <pybind11/stl.h>

#include <optional>

namespace linkwright::python {
namespace {

namespace k = kinematics;

py::dict extremes(const Linkage& linkage, const SweepOptions& grid) {
  const k::Mechanism& m = linkage.mechanism;
  const k::SweepSpec spec = valueOrThrow(sweepSpecFor(linkage, grid));
  std::vector<k::ColumnExtremaScan> scans;
  std::vector<std::optional<k::Extrema>> found;
  {
    py::gil_scoped_release unlocked;
    valueOrThrow(k::sweepInWindows(m, spec, {}, k::kSweepWindow, [&](const k::SweepResult& part, std::size_t first) {
      if (scans.empty())
        for (const k::SweepColumn& column : k::sweepColumns(m, part.request, !part.time.empty()))
          if (column.quantity != k::ColumnQuantity::InputAngle && column.quantity != k::ColumnQuantity::InputLength &&
              column.quantity != k::ColumnQuantity::Time)
            scans.emplace_back(column);
      for (k::ColumnExtremaScan& scan : scans) scan.add(part, first);
      return true;
    }));
    for (const k::ColumnExtremaScan& scan : scans) found.push_back(scan.refine(m, spec));
  }
  const bool timeBase = spec.time.has_value();
  const bool angle = k::inputKind(m) == k::InputKind::Angle;
  const char* where = timeBase ? "at_s" : angle ? "at_deg" : "at";
  const auto at = [&](const k::Extremum& e) {
    return timeBase ? number(e.time) : angle ? degrees(e.inputAngle) : number(e.inputAngle);
  };
  py::dict out;
  for (std::size_t c = 0; c < scans.size(); ++c) {
    if (!found[c]) continue;  // no value at all
    py::dict e;
    e["min"] = number(found[c]->minimum.value);
    e[py::str(std::string("min_") + where)] = at(found[c]->minimum);
    e["max"] = number(found[c]->maximum.value);
    e[py::str(std::string("max_") + where)] = at(found[c]->maximum);
    out[py::str(scans[c].column().name)] = e;
  }
  return out;
}

}  // namespace

void bindExtremes(py::class_<Linkage>& linkage) {
  linkage.def(
      "extremes",
      [](const Linkage& l, std::optional<double> startDeg, std::optional<double> stopDeg,
         std::optional<long long> samples, std::optional<double> omega, std::optional<double> alpha) {
        return extremes(l, {startDeg, stopDeg, samples, omega, alpha});
      },
      py::arg("start_deg") = py::none(), py::arg("stop_deg") = py::none(), py::arg("samples") = py::none(),
      py::arg("omega") = py::none(), py::arg("alpha") = py::none(),
      "Each column's minimum and maximum over the sweep (keywords as sweep's), refined between samples with the "
      "pose solver, as linkwright-cli extremes: a dict of column name to {min, min_at_deg, max, max_at_deg} "
      "(at_s on a time base, at in the length unit for a linear driver).");
}

}  // namespace linkwright::python
