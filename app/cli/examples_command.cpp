#include "app/cli/commands.h"

#include "kinematics/design/examples.h"
#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/io/number_format.h"

#include <ostream>

namespace linkwright::cli {

// A four-bar is listed with the options that give the same linkage; any other by its kind.
ExitCode runExamples(std::ostream& out) {
  using kinematics::io::formatShort;
  for (const kinematics::Example& e : kinematics::examples()) {
    out << e.name << "\n  " << e.description << "\n  ";
    if (const auto fourBar = kinematics::asFourBar(e.mechanism)) {
      const auto& l = fourBar->lengths;
      out << "--fourbar " << formatShort(l.frame) << "," << formatShort(l.crank) << "," << formatShort(l.coupler) << ","
          << formatShort(l.rocker) << " (" << e.mechanism.lengthUnit << ")";
      if (const auto p = kinematics::couplerPointOf(e.mechanism, *fourBar))
        out << ", --coupler-point " << formatShort(p->spec.along) << "," << formatShort(p->spec.across);
      out << ", --omega " << formatShort(e.omega) << " rad/s, every " << formatShort(e.stepDeg) << "° from "
          << formatShort(e.fromDeg) << "° to " << formatShort(e.toDeg) << "°\n";
    } else {
      out << e.kind << " (" << e.mechanism.lengthUnit << "), --omega " << formatShort(e.omega) << " rad/s, every "
          << formatShort(e.stepDeg) << "°\n";
    }
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
