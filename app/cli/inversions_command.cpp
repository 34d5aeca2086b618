// `linkwright-cli inversions`: a four-bar's or slider-crank's four inversions
// (kinematics/analysis/inversions.h): which link is grounded, which is driven, the lengths as a
// four-bar, the textbook class and whether the driven link turns fully. Text or JSON.

#include "app/cli/commands.h"

#include "kinematics/analysis/inversions.h"
#include "kinematics/io/inversions_json.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/recognise.h"

#include <optional>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

void printFourBar(const k::FourBarLengths& lengths, const std::vector<k::FourBarInversion>& inversions,
                  const std::string& unit, std::ostream& out) {
  const k::GrashofReport g = k::classifyGrashof(lengths);
  out << "inversions of the four-bar frame " << formatShort(lengths.frame) << ", crank " << formatShort(lengths.crank)
      << ", coupler " << formatShort(lengths.coupler) << ", rocker " << formatShort(lengths.rocker) << " " << unit
      << ": S + L = " << formatShort(g.sPlusL) << ", P + Q = " << formatShort(g.pPlusQ) << " ("
      << (g.category == k::GrashofClass::TripleRocker  ? "non-Grashof"
          : g.category == k::GrashofClass::ChangePoint ? "change point"
                                                       : "Grashof")
      << ")\n";
  for (const k::FourBarInversion& inv : inversions)
    out << "  ground the " << k::toString(inv.grounded) << ": " << inv.name << "; drive the " << k::toString(inv.driven)
        << " (" << (inv.grashof.inputFullyRotates ? "turns fully" : "rocks") << "); as a four-bar "
        << formatShort(inv.lengths.frame) << "," << formatShort(inv.lengths.crank) << ","
        << formatShort(inv.lengths.coupler) << "," << formatShort(inv.lengths.rocker) << "\n";
}

void printSliderCrank(const k::SliderCrankGeometry& g, const std::vector<k::SliderCrankInversion>& inversions,
                      const std::string& unit, std::ostream& out) {
  out << "inversions of the slider-crank crank " << formatShort(g.crank) << ", rod " << formatShort(g.rod)
      << ", offset " << formatShort(g.offset) << " " << unit << "\n";
  for (const k::SliderCrankInversion& inv : inversions) {
    out << "  ground the " << k::toString(inv.grounded) << ": " << inv.name << "; drive the " << inv.driven << " ("
        << (inv.driverTurnsFully ? "turns fully" : "rocks") << ")";
    if (!inv.mechanism) out << "; not built: " << inv.note;
    out << "\n";
  }
}

}  // namespace

ExitCode runInversions(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto resolved = resolveMechanism(inv);
  if (!resolved) {
    err << "linkwright-cli: " << resolved.error().message << "\n";
    return ExitCode::BadInput;
  }
  const k::Mechanism& m = resolved->mechanism;
  const auto inversions = k::linkageInversions(m, resolved->source, resolved->kind);
  if (!inversions) {
    err << "linkwright-cli: " << inversions.error().message << "\n";
    return ExitCode::BadInput;
  }
  if (inv.json) out << k::io::inversionsJson(*inversions, m.lengthUnit).dump(2) << "\n";
  else if (inversions->fourBar) printFourBar(*inversions->fourBar, inversions->fourBars, m.lengthUnit, out);
  else printSliderCrank(*inversions->sliderCrank, inversions->sliderCranks, m.lengthUnit, out);
  return ExitCode::Success;
}

}  // namespace linkwright::cli
