// classify for any linkage that is not a plain four-bar (a six-bar, a slider-crank, a
// document's linkage): mobility, where a full crank turn assembles, toggle positions, and
// the refined extremes of every dyad's transmission angle.

#include "app/cli/classify_linkage.h"

#include "kinematics/analysis/extrema.h"
#include "kinematics/analysis/mobility.h"
#include "kinematics/design/derived_design.h"
#include "kinematics/io/json.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <cmath>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatFixed;
using k::formatJsonNumber;

// A full turn every 0.25°: fine enough that a refined extremum's bracket is one step.
constexpr std::size_t kSamples = 1441;

// Crank angles are shown within [0°, 360°): the sweep's last sample is its first.
double turn(double radians) { return radians - 2.0 * k::kPi * std::floor(radians / (2.0 * k::kPi)); }
std::string deg(double radians) { return formatFixed(k::radToDeg(radians), 2) + "°"; }
std::string jsonDeg(double radians) { return formatJsonNumber(k::radToDeg(radians)); }

struct TransmissionExtremes {
  std::string point;
  k::Extrema extrema;
};

std::vector<TransmissionExtremes> transmissionExtremes(const k::Mechanism& m, const k::SweepSpec& spec,
                                                       const k::SweepResult& sweep) {
  std::vector<TransmissionExtremes> out;
  for (const std::size_t i : k::transmissionJoints(m)) {
    std::vector<bool> valid(sweep.size());
    for (std::size_t j = 0; j < sweep.size(); ++j) valid[j] = sweep.assembled(j);
    const auto e = k::refineExtrema(m, spec, sweep.transmissionAngle[i], valid,
                                    [i](const k::Pose& p, double) { return p.transmissionAngle[i]; });
    if (e) out.push_back({m.points[i].name, *e});
  }
  return out;
}

}  // namespace

ExitCode classifyLinkage(const std::string& kind, const k::Mechanism& m, bool json, std::ostream& out,
                         std::ostream& err) {
  const k::SweepSpec spec{0.0, 2.0 * k::kPi, kSamples, 1.0, 0.0};
  const auto sweep = k::sweep(m, spec, {false, false});
  if (!sweep) {
    err << "linkwright-cli: " << sweep.error().message << "\n";
    return ExitCode::BadInput;
  }
  const k::MobilityReport mob = k::mobility(m);
  const auto transmission = transmissionExtremes(m, spec, *sweep);
  const bool none = sweep->notAssembled.size() == 1 && sweep->notAssembled.front().from == 0.0 &&
                    sweep->notAssembled.front().to == spec.toAngle;
  if (json) {
    out << "{\n  \"mechanism\": " << k::io::jsonQuote(kind) << ",\n  \"mobility\": {\"links\": " << mob.links
        << ", \"full_joints\": " << mob.fullJoints << ", \"half_joints\": " << mob.halfJoints
        << ", \"mobility\": " << mob.mobility << "},\n  \"not_assembled_crank_ranges_deg\": [";
    for (std::size_t i = 0; i < sweep->notAssembled.size(); ++i)
      out << (i ? ", " : "") << "[" << jsonDeg(sweep->notAssembled[i].from) << ", "
          << jsonDeg(sweep->notAssembled[i].to) << "]";
    out << "],\n  \"transmission_angles_deg\": [";
    for (std::size_t i = 0; i < transmission.size(); ++i) {
      const auto& t = transmission[i];
      out << (i ? ", " : "") << "{\"point\": " << k::io::jsonQuote(t.point)
          << ", \"min\": " << jsonDeg(t.extrema.minimum.value)
          << ", \"min_at_crank\": " << jsonDeg(turn(t.extrema.minimum.inputAngle))
          << ", \"max\": " << jsonDeg(t.extrema.maximum.value)
          << ", \"max_at_crank\": " << jsonDeg(turn(t.extrema.maximum.inputAngle)) << "}";
    }
    out << "],\n  \"length_unit\": " << k::io::jsonQuote(m.lengthUnit) << "\n}\n";
  } else {
    out << "linkage              " << kind << ": " << m.points.size() << " points, " << m.links.size()
        << " moving links\n";
    out << "mobility (Gruebler)  M = 3(" << mob.links << " - 1) - 2*" << mob.fullJoints << " - " << mob.halfJoints
        << " = " << mob.mobility << "\n";
    out << "assembles            ";
    if (sweep->notAssembled.empty()) out << "over the whole crank turn\n";
    else if (none) out << "nowhere: the loops never close\n";
    else {
      out << "except crank ";
      for (std::size_t i = 0; i < sweep->notAssembled.size(); ++i)
        out << (i ? ", " : "") << deg(sweep->notAssembled[i].from) << " to " << deg(sweep->notAssembled[i].to);
      out << " (to 0.25°)\n";
    }
    for (const auto& t : transmission)
      out << "transmission at " << t.point << std::string(t.point.size() < 5 ? 5 - t.point.size() : 1, ' ') << "min "
          << deg(t.extrema.minimum.value) << " at crank " << deg(turn(t.extrema.minimum.inputAngle)) << ", max "
          << deg(t.extrema.maximum.value) << " at crank " << deg(turn(t.extrema.maximum.inputAngle)) << "\n";
  }
  // The designer's verdict on the same linkage (kinematics/design/derived_design.h).
  if (const auto verdict = k::deriveDesign(m, *sweep); !verdict) {
    err << "linkwright-cli: " << verdict.error().message << "\n";
    return ExitCode::NotAssemblable;
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
