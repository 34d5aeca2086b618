// linkwright.accuracy (kinematics/design/accuracy_study.h): the speed-accuracy trade of reading
// peaks off a sampled cycle, as the core's one study; its rows the columns linkwright-cli
// accuracy writes, the errors at full precision (the CLI prints 3 digits), and with `output`
// the CLI's CSV written where -o writes it.

#include "python/src/bindings.h"
#include "python/src/convert.h"

#include "kinematics/design/accuracy_study.h"
#include "kinematics/io/accuracy_csv.h"
#include "kinematics/model/units.h"

#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

namespace linkwright::python {
namespace {

namespace k = kinematics;

py::dict accuracy(std::optional<std::string> example, std::optional<std::string> output) {
  const std::vector<k::AccuracyRow> rows = [&] {
    py::gil_scoped_release unlocked;
    return valueOrThrow(k::measureAccuracy({std::move(example), k::FrontEnd::Python}));
  }();
  if (output) writeOrThrow(*output, k::io::accuracyCsv(rows));
  std::vector<std::string> examples, methods, references;
  std::vector<double> samples, time, omega, alpha, speed, acceleration, angle;
  for (const k::AccuracyRow& r : rows) {
    examples.push_back(r.example);
    methods.push_back(r.method);
    references.push_back(r.reference);
    samples.push_back(static_cast<double>(r.samples));
    time.push_back(r.microseconds);
    omega.push_back(r.error.omega);
    alpha.push_back(r.error.alpha);
    speed.push_back(r.error.speed);
    acceleration.push_back(r.error.acceleration);
    angle.push_back(k::radToDeg(r.error.angle));
  }
  py::dict columns;
  columns["example"] = examples;
  columns["method"] = methods;
  columns["samples_per_rev"] = array(samples).attr("astype")("int64");
  columns["time_us"] = array(time);
  columns["omega_rel_error"] = array(omega);
  columns["alpha_rel_error"] = array(alpha);
  columns["speed_rel_error"] = array(speed);
  columns["acceleration_rel_error"] = array(acceleration);
  columns["angle_error_deg"] = array(angle);
  columns["reference"] = references;
  return columns;
}

}  // namespace

void bindAccuracy(py::module_& module) {
  module.def("accuracy", &accuracy, py::kw_only(), py::arg("example") = py::none(), py::arg("output") = py::none(),
             "The speed-accuracy trade, measured, as linkwright-cli accuracy: for one example (or the seeds' "
             "miranda-fourbar, ls3-engine, shaper and watt-ii) the relative errors of the peaks of |ω|, |α|, a "
             "point's speed and acceleration and the angle error in degrees, read off 12 to 3600 samples per turn "
             "(method 'samples'), off frame differences ('frames') and refined between samples ('refined'), "
             "against a refined 7200-sample reference; and every RRR joint solved by Newton at tolerances 1e-4 "
             "to 1e-14 against the closed form. Returns a dict of the CLI's columns (example, method, reference "
             "as lists; the numbers as arrays, the errors at full precision); time_us is each choice's median "
             "wall time of five runs, which varies run to run. With output=PATH the CLI's CSV is written there, "
             "atomically.");
}

}  // namespace linkwright::python
