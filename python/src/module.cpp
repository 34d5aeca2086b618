// The pybind11 binding: `import linkwright` (python/linkwright/__init__.py re-exports this
// extension, _linkwright). It converts and nothing more: every number comes from the core
// (python/src/linkage.h), every refusal is the core's Error raised as linkwright.Error (a
// ValueError) with the core's sentence, and no NaN or infinity reaches Python: a CSV cell the
// core leaves empty is a masked entry of a numpy.ma.MaskedArray (docs/python.md).

#include "python/src/bindings.h"
#include "python/src/convert.h"
#include "python/src/linkage.h"

#include "kinematics/design/design_analysis.h"
#include "kinematics/design/examples.h"
#include "kinematics/design/sweep_notes.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;
namespace k = linkwright::kinematics;
namespace lp = linkwright::python;
using lp::CoreError;
using lp::degrees;
using lp::number;
using lp::valueOrThrow;

namespace {

const char* codeName(k::ErrorCode code) {
  switch (code) {
  case k::ErrorCode::InvalidValue: return "invalid-value";
  case k::ErrorCode::InvalidStructure: return "invalid-structure";
  case k::ErrorCode::NotAssemblable: return "not-assemblable";
  case k::ErrorCode::Singular: return "singular";
  case k::ErrorCode::Cancelled: return "cancelled";
  }
  return "invalid-value";
}

// Linkage.sweep and Linkage.sweep_csv: one signature, the grid's or a law's keywords.
template <typename Sweep>
void defSweep(py::class_<lp::Linkage>& linkage, const char* name, Sweep sweep, const char* doc) {
  linkage.def(
      name,
      [sweep](const lp::Linkage& l, std::optional<double> startDeg, std::optional<double> stopDeg,
              std::optional<long long> samples, std::optional<double> omega, std::optional<double> alpha, bool forces,
              std::optional<std::string> law, std::optional<double> rampTime, std::optional<double> riseDeg,
              std::optional<double> duration, std::optional<std::string> lawTable, std::optional<double> fromTime,
              std::optional<double> toTime, std::optional<double> stepTime) {
        return sweep(l,
                     lp::SweepOptions{startDeg, stopDeg, samples, omega, alpha, std::move(law), rampTime, riseDeg,
                                      duration, std::move(lawTable), fromTime, toTime, stepTime},
                     forces);
      },
      py::arg("start_deg") = py::none(), py::arg("stop_deg") = py::none(), py::arg("samples") = py::none(),
      py::arg("omega") = py::none(), py::arg("alpha") = py::none(), py::arg("forces") = false, py::kw_only(),
      py::arg("law") = py::none(), py::arg("ramp_time_s") = py::none(), py::arg("rise_deg") = py::none(),
      py::arg("duration_s") = py::none(), py::arg("law_table") = py::none(), py::arg("from_time_s") = py::none(),
      py::arg("to_time_s") = py::none(), py::arg("step_time_s") = py::none(), doc);
}

// The CLI's notes on stderr, as Python warnings (linkwright.SweepWarning): a warning filter
// set to "error" makes them exceptions.
py::handle sweepWarning;

void warnAbout(const lp::Linkage& linkage, const k::SweepSummary& summary) {
  for (const std::string& note : k::sweepNoteSentences(linkage.mechanism, summary))
    if (PyErr_WarnEx(sweepWarning.ptr(), note.c_str(), 2) != 0) throw py::error_already_set();
}

py::dict sweepColumns(const lp::Linkage& linkage, const lp::SweepOptions& options, bool forces) {
  const k::SweepSpec spec = valueOrThrow(lp::sweepSpecFor(linkage, options));
  lp::SweepTable table;
  {
    py::gil_scoped_release unlocked;  // the sweep is the core's alone
    table = valueOrThrow(lp::sweepTable(linkage, spec, {false, true, forces}));
  }
  warnAbout(linkage, table.summary);
  py::dict columns;
  for (std::size_t c = 0; c < table.names.size(); ++c)
    columns[py::str(table.names[c])] = lp::maskedArray(table.values[c], table.defined[c]);
  return columns;
}

std::string sweepCsv(const lp::Linkage& linkage, const lp::SweepOptions& options, bool forces) {
  const k::SweepSpec spec = valueOrThrow(lp::sweepSpecFor(linkage, options));
  lp::SweepTable table;
  {
    py::gil_scoped_release unlocked;
    table = valueOrThrow(lp::sweepTable(linkage, spec, {true, false, forces}));
  }
  warnAbout(linkage, table.summary);
  return std::move(table.csv);
}

py::dict classify(const lp::Linkage& linkage) {
  const k::Mechanism& m = linkage.mechanism;
  const k::SweepSpec spec = valueOrThrow(lp::sweepSpecFor(linkage, {}));
  k::SolveRequest positions;
  positions.velocities = false;
  positions.accelerations = false;
  positions.transmissionAngles = false;
  const k::SweepResult grid = valueOrThrow(k::sweep(m, spec, positions));
  const k::DesignAnalysis a = k::analyseDesign(m, grid);
  const bool angle = k::inputKind(m) == k::InputKind::Angle;
  const auto input = [angle](double q) { return angle ? degrees(q) : number(q); };

  py::dict out;
  out["kind"] = linkage.kind;
  out["length_unit"] = m.lengthUnit;
  out["input"] = k::inputName(m);
  out["input_unit"] = k::inputUnit(m);
  out["mobility"] = a.mobility.mobility;
  out["links"] = a.mobility.links;
  out["full_joints"] = a.mobility.fullJoints;
  out["half_joints"] = a.mobility.halfJoints;
  out["input_fully_rotates"] = a.inputRange.fullRotation;
  py::list ranges;
  for (const k::AngleRange& r : a.inputRange.ranges) ranges.append(py::make_tuple(input(r.from), input(r.to)));
  out["input_ranges"] = ranges;
  if (a.grashof) {
    py::dict g;
    g["class"] = std::string(k::toString(a.grashof->category));
    g["shortest"] = std::string(k::toString(a.grashof->shortest));
    g["longest"] = std::string(k::toString(a.grashof->longest));
    g["s_plus_l"] = number(a.grashof->sPlusL);
    g["p_plus_q"] = number(a.grashof->pPlusQ);
    g["input_fully_rotates"] = a.grashof->inputFullyRotates;
    g["output_fully_rotates"] = a.grashof->outputFullyRotates;
    out["grashof"] = g;
  } else {
    out["grashof"] = py::none();
  }
  if (a.transmission) {
    py::dict t;
    t["minimum_deg"] = degrees(a.transmission->minimum);
    t["minimum_at_crank_deg"] = degrees(a.transmission->minimumAtCrank);
    t["maximum_deg"] = degrees(a.transmission->maximum);
    t["maximum_at_crank_deg"] = degrees(a.transmission->maximumAtCrank);
    t["worst_deviation_deg"] = degrees(a.transmission->worstDeviation);
    out["transmission"] = t;
  } else {
    out["transmission"] = py::none();
  }
  if (a.quickReturn) {
    py::dict q;
    q["time_ratio"] = number(a.quickReturn->timeRatio);
    q["slow_stroke_crank_arc_deg"] = degrees(a.quickReturn->slowStrokeCrankArc);
    q["quick_stroke_crank_arc_deg"] = degrees(a.quickReturn->quickStrokeCrankArc);
    q["rocker_swing_deg"] = degrees(a.quickReturn->rockerSwing);
    q["stroke"] = number(a.quickReturn->stroke);
    q["whitworth"] = a.quickReturn->whitworth;
    out["quick_return"] = q;
  } else {
    out["quick_return"] = py::none();
  }
  return out;
}

}  // namespace

PYBIND11_MODULE(_linkwright, module) {
  module.doc() = "Linkwright's kinematics core: planar linkages swept to NumPy columns (docs/python.md).";

  static py::exception<CoreError> error(module, "Error", PyExc_ValueError);
  error.doc() =
      "A refusal of Linkwright's core: the message names the field, the value and the accepted range. "
      "Attributes: field (str), code (str).";
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const CoreError& e) {
      const auto type = py::reinterpret_borrow<py::object>(error);
      py::object instance = type(lp::text(e.error.message));
      instance.attr("field") = lp::text(e.error.field);
      instance.attr("code") = codeName(e.error.code);
      PyErr_SetObject(error.ptr(), instance.ptr());
    }
  });

  sweepWarning = PyErr_NewExceptionWithDoc("linkwright.SweepWarning",
                                           "What linkwright-cli analyze notes on stderr about a sweep: samples that "
                                           "cannot be assembled (rows left out), toggles (rates masked), locks.",
                                           PyExc_UserWarning, nullptr);
  if (!sweepWarning) throw py::error_already_set();
  module.add_object("SweepWarning", sweepWarning);

  py::class_<lp::Linkage> linkage(module, "Linkage",
                                  "A planar linkage with the input grid linkwright-cli analyze uses for it.");
  linkage
      .def_property_readonly(
          "kind", [](const lp::Linkage& l) { return l.kind; }, "Its label: 'four-bar', 'slider-crank', …")
      .def_property_readonly(
          "source", [](const lp::Linkage& l) { return lp::text(l.source); }, "Where it came from, as messages name it.")
      .def_property_readonly(
          "length_unit", [](const lp::Linkage& l) { return l.mechanism.lengthUnit; }, "The unit of every length.")
      .def_property_readonly(
          "points",
          [](const lp::Linkage& l) {
            std::vector<std::string> names;
            for (const k::Point& p : l.mechanism.points) names.push_back(p.name);
            return names;
          },
          "The points' names, in the model's order.")
      .def_property_readonly(
          "links",
          [](const lp::Linkage& l) {
            std::vector<std::string> names;
            for (const k::Link& link : l.mechanism.links) names.push_back(link.name);
            return names;
          },
          "The links' names, in the model's order.")
      .def("classify", &classify,
           "What the linkage is: mobility, the input ranges where it assembles, and for a four-bar its Grashof "
           "class and transmission-angle range, for a quick return its time ratio and stroke. Angles in degrees.")
      .def(py::pickle([](const lp::Linkage& l) { return py::bytes(lp::linkageState(l)); },
                      [](const py::bytes& state) { return valueOrThrow(lp::linkageFromState(state)); }))
      .def("__repr__", [](const lp::Linkage& l) {
        return lp::text("<linkwright.Linkage " + (l.kind.empty() ? std::string("linkage") : l.kind) + " from " +
                        l.source + ">");
      });
  defSweep(linkage, "sweep", &sweepColumns,
           "Sweeps the linkage over an input grid and returns its table as a dict of column name to "
           "numpy.ma.MaskedArray, with exactly linkwright-cli analyze's column names and rows. What is not given "
           "is the linkage's own grid (an example's step, a document's grid; 0° to 360° every 1° at 1 rad/s for "
           "four_bar()). start_deg and stop_deg are degrees for a crank (the length unit for a linear driver); "
           "samples replaces the step; omega in rad/s, alpha in rad/s². Rows where the linkage cannot be "
           "assembled are left out; at a toggle position the rate entries are masked (the CSV's empty cells). "
           "forces=True adds linkwright-cli analyze --forces's columns (joint forces in N, the driving torque in "
           "N·m, the shaking force and moment), for a linkage with masses; masked where they are not determined. "
           "law= makes the driver follow a motion law in time instead, as analyze --law: 'constant' (at omega), "
           "'ramp' (to omega in ramp_time_s), 'cycloidal' or '345' (a rise of rise_deg in duration_s) or 'table' "
           "(law_table: a CSV of time_s and the input), starting at start_deg, at `samples` instants (default "
           "361) or every step_time_s from from_time_s to to_time_s.");
  defSweep(linkage, "sweep_csv", &sweepCsv,
           "The same sweep as CSV text, written by the core's CSV writer: byte for byte linkwright-cli analyze's "
           "output (CRLF line ends); with forces=True, analyze --forces's; with law=, analyze --law's.");
  lp::bindCentres(linkage);
  lp::bindExtremes(linkage);
  lp::bindMachine(linkage);
  lp::bindClassroom(linkage);
  lp::bindCognates(linkage);
  lp::bindBalance(linkage);
  lp::bindDxf(linkage);
  lp::bindTolerance(linkage);
  lp::bindSynthesis(module);
  lp::bindProblems(module);
  lp::bindAtlas(module);
  lp::bindArm(module, sweepWarning);
  lp::bindAccuracy(module);

  module.def(
      "examples",
      [] {
        std::vector<std::string> names;
        for (const k::Example& e : k::examples()) names.push_back(e.name);
        return names;
      },
      "The names of the built-in examples, in display order (linkwright-cli examples).");
  module.def(
      "example", [](const std::string& name) { return valueOrThrow(lp::exampleLinkage(name)); }, py::arg("name"),
      "The built-in example `name`, with its own speed and grid.");
  module.def(
      "four_bar",
      [](double frame, double crank, double coupler, double rocker, const std::string& unit, const std::string& branch,
         std::optional<std::pair<double, double>> couplerPoint) {
        std::optional<k::CouplerPointSpec> point;
        if (couplerPoint) point = k::CouplerPointSpec{couplerPoint->first, couplerPoint->second};
        return valueOrThrow(lp::fourBarLinkage({frame, crank, coupler, rocker}, unit, branch, point));
      },
      py::arg("frame"), py::arg("crank"), py::arg("coupler"), py::arg("rocker"), py::arg("unit") = "mm",
      py::arg("branch") = "open", py::arg("coupler_point") = py::none(),
      "A four-bar from its lengths (one unit): ground pivots O2 at the origin and O4 at (frame, 0), crank "
      "O2→B, coupler B→C, rocker O4→C, on the 'open' or 'crossed' branch; coupler_point=(along, across) adds "
      "P on the coupler (along B→C, across 90° CCW from it).");
  module.def(
      "load", [](const std::string& path) { return valueOrThrow(lp::loadLinkage(path)); }, py::arg("path"),
      "A Linkwright document (.linkwright JSON), read as linkwright-cli reads it.");
}
