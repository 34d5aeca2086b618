// `linkwright-cli inversions`: a four-bar's or slider-crank's four inversions
// (kinematics/analysis/inversions.h): which link is grounded, which is driven, the lengths as a
// four-bar, the textbook class and whether the driven link turns fully. Text or JSON.

#include "app/cli/commands.h"

#include "kinematics/analysis/inversions.h"
#include "kinematics/io/json.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/recognise.h"

#include <optional>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

ExitCode fourBar(const k::FourBarStructure& f, const std::string& unit, bool json, std::ostream& out,
                 std::ostream& err) {
  const auto inversions = k::fourBarInversions(f.lengths, f.branch, unit);
  if (!inversions) {
    err << "linkwright-cli: " << inversions.error().message << "\n";
    return ExitCode::BadInput;
  }
  if (json) {
    k::io::JsonValue all = k::io::JsonValue::array();
    for (const k::FourBarInversion& inv : *inversions)
      all.push_back({{"grounded", k::toString(inv.grounded)},
                     {"driven", k::toString(inv.driven)},
                     {"lengths", {inv.lengths.frame, inv.lengths.crank, inv.lengths.coupler, inv.lengths.rocker}},
                     {"class", k::toString(inv.grashof.category)},
                     {"name", inv.name},
                     {"driven_turns_fully", inv.grashof.inputFullyRotates},
                     {"output_turns_fully", inv.grashof.outputFullyRotates}});
    out << k::io::JsonValue{{"linkage", "four-bar"}, {"length_unit", unit}, {"inversions", all}}.dump(2) << "\n";
    return ExitCode::Success;
  }
  const k::GrashofReport g = k::classifyGrashof(f.lengths);
  out << "inversions of the four-bar frame " << formatShort(f.lengths.frame) << ", crank "
      << formatShort(f.lengths.crank) << ", coupler " << formatShort(f.lengths.coupler) << ", rocker "
      << formatShort(f.lengths.rocker) << " " << unit << ": S + L = " << formatShort(g.sPlusL)
      << ", P + Q = " << formatShort(g.pPlusQ) << " ("
      << (g.category == k::GrashofClass::TripleRocker  ? "non-Grashof"
          : g.category == k::GrashofClass::ChangePoint ? "change point"
                                                       : "Grashof")
      << ")\n";
  for (const k::FourBarInversion& inv : *inversions)
    out << "  ground the " << k::toString(inv.grounded) << ": " << inv.name << "; drive the " << k::toString(inv.driven)
        << " (" << (inv.grashof.inputFullyRotates ? "turns fully" : "rocks") << "); as a four-bar "
        << formatShort(inv.lengths.frame) << "," << formatShort(inv.lengths.crank) << ","
        << formatShort(inv.lengths.coupler) << "," << formatShort(inv.lengths.rocker) << "\n";
  return ExitCode::Success;
}

ExitCode sliderCrank(const k::SliderCrankGeometry& g, const std::string& unit, bool json, std::ostream& out,
                     std::ostream& err) {
  const auto inversions = k::sliderCrankInversions(g, unit);
  if (!inversions) {
    err << "linkwright-cli: " << inversions.error().message << "\n";
    return ExitCode::BadInput;
  }
  if (json) {
    k::io::JsonValue all = k::io::JsonValue::array();
    for (const k::SliderCrankInversion& inv : *inversions)
      all.push_back({{"grounded", k::toString(inv.grounded)},
                     {"name", inv.name},
                     {"driven", inv.driven},
                     {"driven_turns_fully", inv.driverTurnsFully},
                     {"output_turns_fully", inv.outputTurnsFully},
                     {"built", inv.mechanism.has_value()},
                     {"note", inv.note}});
    out << k::io::JsonValue{{"linkage", "slider-crank"}, {"length_unit", unit}, {"inversions", all}}.dump(2) << "\n";
    return ExitCode::Success;
  }
  out << "inversions of the slider-crank crank " << formatShort(g.crank) << ", rod " << formatShort(g.rod)
      << ", offset " << formatShort(g.offset) << " " << unit << "\n";
  for (const k::SliderCrankInversion& inv : *inversions) {
    out << "  ground the " << k::toString(inv.grounded) << ": " << inv.name << "; drive the " << inv.driven << " ("
        << (inv.driverTurnsFully ? "turns fully" : "rocks") << ")";
    if (!inv.mechanism) out << "; not built: " << inv.note;
    out << "\n";
  }
  return ExitCode::Success;
}

}  // namespace

ExitCode runInversions(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto resolved = resolveMechanism(inv);
  if (!resolved) {
    err << "linkwright-cli: " << resolved.error().message << "\n";
    return ExitCode::BadInput;
  }
  const k::Mechanism& m = resolved->mechanism;
  if (const auto f = k::asFourBar(m, k::PointsOnLinks::AnyLink)) return fourBar(*f, m.lengthUnit, inv.json, out, err);
  if (const auto s = k::asSliderCrank(m, k::PointsOnLinks::AnyLink))
    if (const auto g = k::sliderCrankGeometry(m, *s)) return sliderCrank(*g, m.lengthUnit, inv.json, out, err);
  const std::string what = resolved->kind.empty() ? "neither" : "a " + resolved->kind;
  // A linkage driven along a path or by an actuator may be a slider-crank (piston-driven is),
  // but the inversions are built from its crank, which it does not have as its input.
  if (k::inputKind(m) != k::InputKind::Angle)
    err << "linkwright-cli: inversions needs a four-bar or a slider-crank driven by its crank; " << resolved->source
        << " is " << what << " driven by its " << k::inputName(m)
        << ", a length, so it has no crank to build the inversions from\n";
  else
    err << "linkwright-cli: inversions needs a four-bar or a slider-crank (" << resolved->source << " is " << what
        << ")\n";
  return ExitCode::BadInput;
}

}  // namespace linkwright::cli
