#include "app/cli/commands.h"

#include "kinematics/io/number_format.h"

#include <ostream>

namespace linkwright::cli {

ExitCode runExamples(std::ostream& out) {
  for (const kinematics::FourBarExample& e : kinematics::fourBarExamples()) {
    using kinematics::io::formatShort;
    const auto& l = e.lengths;
    out << e.name << "\n  " << e.description << "\n  --fourbar " << formatShort(l.frame) << "," << formatShort(l.crank)
        << "," << formatShort(l.coupler) << "," << formatShort(l.rocker) << " (" << e.lengthUnit << ")";
    if (e.couplerPoint)
      out << ", --coupler-point " << formatShort(e.couplerPoint->along) << "," << formatShort(e.couplerPoint->across);
    out << ", --omega " << formatShort(e.omega) << " rad/s, every " << formatShort(e.stepDeg) << "° from "
        << formatShort(e.fromDeg) << "° to " << formatShort(e.toDeg) << "°\n";
  }
  for (const kinematics::MechanismExample& e : kinematics::mechanismExamples()) {
    using kinematics::io::formatShort;
    out << e.name << "\n  " << e.description << "\n  " << e.kind << " (" << e.mechanism.lengthUnit << "), --omega "
        << formatShort(e.omega) << " rad/s, every " << formatShort(e.stepDeg) << "°\n";
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
