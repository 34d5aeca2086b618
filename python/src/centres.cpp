// Linkage.instant_centres (kinematics/analysis/instant_centres.h): every pair of bodies'
// instant centre at one input, how it was found, and the velocity ratio and mechanical
// advantage they give, as linkwright-cli centres prints them.

#include "python/src/bindings.h"
#include "python/src/convert.h"

#include "kinematics/analysis/instant_centres.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/pose_solver.h"

#include <pybind11/stl.h>

#include <string>

namespace linkwright::python {
namespace {

namespace k = kinematics;

// "I13"; with ten bodies or more, "I1,10".
std::string centreName(std::size_t i, std::size_t j) {
  return "I" + std::to_string(i) + (i >= 10 || j >= 10 ? "," : "") + std::to_string(j);
}

py::object ratio(const k::Ratio& r) {
  switch (r.kind) {
  case k::RatioKind::Finite: return number(r.value);
  case k::RatioKind::Infinite: return py::str("infinite");
  case k::RatioKind::Undefined: break;
  }
  return py::none();
}

py::dict centre(const k::InstantCentre& c, const k::CentreOrigin& o, const std::vector<std::string>& bodies) {
  py::dict d;
  switch (c.kind) {
  case k::CentreKind::Finite:
    d["kind"] = "finite";
    d["x"] = number(c.position.x());
    d["y"] = number(c.position.y());
    break;
  case k::CentreKind::AtInfinity:
    d["kind"] = "at-infinity";
    d["direction_deg"] = degrees(std::atan2(c.direction.y(), c.direction.x()));
    break;
  case k::CentreKind::Indeterminate: d["kind"] = "indeterminate"; break;
  case k::CentreKind::Unresolved: d["kind"] = "unresolved"; break;
  }
  switch (o.rule) {
  case k::CentreRule::Pin: d["found_by"] = "pin " + o.joint; break;
  case k::CentreRule::Slide: d["found_by"] = "slide at " + o.joint; break;
  case k::CentreRule::Kennedy:
    d["found_by"] = "Kennedy via " + bodies[o.via[0] - 1] + " and " + bodies[o.via[1] - 1];
    break;
  case k::CentreRule::None: d["found_by"] = py::none(); break;
  }
  return d;
}

py::dict centresAt(const Linkage& linkage, double at) {
  const k::Mechanism& m = linkage.mechanism;
  const k::InputKind input = k::inputKind(m);
  const k::InputDomain domain = k::inputDomain(input);
  const bool angle = input == k::InputKind::Angle;
  if (auto e = k::checkMagnitude(at, "at", angle ? k::kMaxAngleDeg : domain.position,
                                 angle ? "degrees" : domain.positionUnit))
    throw CoreError(*e);
  k::SweepGrid grid = linkage.grid;
  grid.input = input;
  // Positions are all the centres need; without rates a toggle pose still solves.
  const k::Pose pose = valueOrThrow(k::solvePose(m, {grid.toInput(at), 0.0, 0.0}, k::SolveRequest{false, false}));
  const k::InstantCentres c = valueOrThrow(k::instantCentres(m, pose));
  py::dict out;
  out["bodies"] = c.bodies;
  py::dict centres;
  for (std::size_t i = 1; i <= c.bodyCount(); ++i)
    for (std::size_t j = i + 1; j <= c.bodyCount(); ++j)
      centres[py::str(centreName(i, j))] = centre(c.centre(i, j), c.origin(i, j), c.bodies);
  out["centres"] = centres;
  if (c.ratio.exists()) {
    const k::MechanicalAdvantage ma = k::mechanicalAdvantage(c);
    out["input_body"] = c.bodies[c.ratio.input - 1];
    out["output_body"] = c.bodies[c.ratio.output - 1];
    out["output_slides"] = c.ratio.outputSlides;
    out["velocity_ratio"] = ratio(ma.velocityRatio);
    out["mechanical_advantage"] = ratio(ma.advantage);
  }
  return out;
}

}  // namespace

void bindCentres(py::class_<Linkage>& linkage) {
  linkage.def("instant_centres", &centresAt, py::arg("at"),
              "The instant centres of every pair of bodies at input `at` (degrees for a crank, the length unit for a "
              "linear driver), as linkwright-cli centres: a dict of bodies (body 1 the frame), centres ('I13': kind "
              "'finite' with x, y in the length unit, 'at-infinity' with direction_deg, 'indeterminate' or "
              "'unresolved', and found_by), and where the linkage has a crank input and an output on the frame: "
              "input_body, output_body, output_slides, velocity_ratio (ω_out/ω_in, or v/ω_in in length unit per "
              "rad) and mechanical_advantage (its inverse), each None where undefined or 'infinite'.");
}

}  // namespace linkwright::python
