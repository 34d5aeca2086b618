// Linkage.machine (kinematics/dynamics/machine_request.h): the core's machine request, its
// keywords the request's fields, its answer the core's JSON (linkwright-cli machine --json's, to
// the bit) as a dict, with the turn's curves as arrays.

#include "python/src/bindings.h"
#include "python/src/convert.h"

#include "kinematics/design/sweep_grid.h"
#include "kinematics/dynamics/machine_request.h"
#include "kinematics/io/machine_json.h"
#include "kinematics/model/units.h"

#include <pybind11/numpy.h>

#include <string>
#include <vector>

namespace linkwright::python {
namespace {

namespace k = kinematics;

std::vector<double> inDegrees(std::vector<double> radians) {
  for (double& v : radians) v = k::radToDeg(v);
  return radians;
}

// The keywords as the request's values: numbers only, None for "not given".
k::RequestValues requestValues(const py::kwargs& keywords) {
  k::RequestValues values;
  for (const auto& [name, value] : keywords) {
    const std::string key = py::str(name);
    if (k::findField(k::machineFields(), key) == nullptr)
      throw py::type_error("machine() got an unexpected keyword argument '" + key + "'");
    if (value.is_none()) continue;
    if (py::isinstance<py::bool_>(value) || !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)))
      throw py::type_error(key + " must be a number (got " +
                           std::string(py::str(py::type::of(value).attr("__name__"))) + ")");
    values[key] = value.cast<double>();
  }
  return values;
}

py::dict machine(const Linkage& linkage, const py::kwargs& keywords) {
  const k::MachineRequest request = valueOrThrow(k::machineRequest(requestValues(keywords), k::FrontEnd::Python));
  if (auto e = k::checkCrankDriven(linkage.mechanism)) throw CoreError(*e);
  if (linkage.dynamics.empty())
    throw CoreError(k::Error{k::ErrorCode::InvalidValue, "dynamics",
                             "machine needs masses and loads, and " + linkage.source + " has none"});
  k::MachineRun run = [&] {
    py::gil_scoped_release unlocked;
    return valueOrThrow(
        k::runMachine(linkage.mechanism, linkage.dynamics, k::machineDefaultsOf(linkage.grid), request));
  }();
  py::dict out = py::module_::import("json").attr("loads")(k::io::machineJson(run, request).dump());
  const k::MachineDuty& d = run.duty;
  out["angle_deg"] = array(inDegrees(d.angle));
  out["torque_Nm"] = array(d.torque);
  out["energy_J"] = array(d.energy);
  if (d.flywheelRun) {
    py::dict flywheel;
    flywheel["time_s"] = array(d.flywheelRun->time);
    flywheel["angle_deg"] = array(inDegrees(d.flywheelRun->angle));
    flywheel["speed_rad_s"] = array(d.flywheelRun->speed);
    out["flywheel_run"] = flywheel;
  }
  return out;
}

// The docstring, read off the request's fields.
std::string machineDoc() {
  std::string doc =
      "What one crank turn asks of the machine, as linkwright-cli machine --json: a dict of the figures in SI "
      "units (the motor's under 'motor'), each figure's relative error estimate under 'accuracy', the samples the "
      "turn was read at and whether every estimate is within the tolerance ('converged'); the turn's angle_deg, "
      "torque_Nm and energy_J as arrays, and with cs the flywheel's run in time ('flywheel_run').\n\nKeywords:\n";
  for (const k::RequestField& field : k::machineFields())
    doc += "    " + k::fieldName(field, k::FrontEnd::Python) + ": " + k::helpText(field) + "\n";
  return doc;
}

}  // namespace

void bindMachine(py::class_<Linkage>& linkage) {
  static const std::string doc = machineDoc();
  linkage.def("machine", &machine, doc.c_str());
}

}  // namespace linkwright::python
