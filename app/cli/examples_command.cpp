#include "app/cli/commands.h"

#include "kinematics/design/examples.h"
#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/number_text.h"

#include <ostream>

namespace linkwright::cli {

namespace {

namespace k = kinematics;
using k::formatShort;

// A value of the input in its own unit: "30°" for a crank, "0.3 m" for a linear driver.
std::string inputValue(const k::Mechanism& m, double value) {
  const std::string unit = k::inputUnit(m);
  return formatShort(value) + (unit == "°" ? unit : " " + unit);
}

// The input's speed option and unit: rad/s for a crank, the length unit per second otherwise.
std::string inputSpeed(const k::Mechanism& m, double value) {
  return formatShort(value) + (k::inputKind(m) == k::InputKind::Angle ? " rad/s" : " " + m.lengthUnit + "/s");
}

}  // namespace

// A four-bar is listed with the options that give the same linkage; any other by its kind,
// its driver in that driver's units (a crank in rad/s and degrees, a path or an actuator in
// the length unit), and, when its driver follows a motion law, the law's travel and time.
ExitCode runExamples(std::ostream& out) {
  for (const k::Example& e : k::examples()) {
    const k::Mechanism& m = e.mechanism;
    out << e.name << "\n  " << e.description << "\n  ";
    if (const auto fourBar = k::asFourBar(m)) {
      const auto& l = fourBar->lengths;
      out << "--fourbar " << formatShort(l.frame) << "," << formatShort(l.crank) << "," << formatShort(l.coupler) << ","
          << formatShort(l.rocker) << " (" << m.lengthUnit << ")";
      if (const auto p = k::couplerPointOf(m, *fourBar))
        out << ", --coupler-point " << formatShort(p->spec.along) << "," << formatShort(p->spec.across);
      out << ", --omega " << inputSpeed(m, e.omega) << ", every " << inputValue(m, e.stepDeg) << " from "
          << inputValue(m, e.fromDeg) << " to " << inputValue(m, e.toDeg) << "\n";
    } else if (e.time) {
      const double duration = e.time->toTime - e.time->fromTime;
      out << e.kind << " (" << m.lengthUnit << "), its " << k::inputName(m) << " from " << inputValue(m, e.fromDeg)
          << " to " << inputValue(m, e.toDeg) << " in " << formatShort(duration) << " s (mean "
          << inputSpeed(m, e.omega) << ") on its motion law, at " << e.timeSamples << " instants\n";
    } else {
      out << e.kind << " (" << m.lengthUnit << "), --omega " << inputSpeed(m, e.omega) << ", every "
          << inputValue(m, e.stepDeg) << "\n";
    }
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
