#include "app/cli/classify_linkage.h"
#include "app/cli/commands.h"

#include "kinematics/design/derived_design.h"
#include "kinematics/design/examples.h"
#include "kinematics/io/json.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"

#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatFixed;
using k::formatJsonNumber;

// Everything classify reports on a four-bar, computed once (the core's analyseDesign, as the
// designer shows it) and printed as text or JSON.
struct Classification {
  k::FourBarStructure fourBar;
  std::string lengthUnit;
  k::GrashofReport grashof;
  k::MobilityReport mobility;
  k::InputRange range;
  std::optional<k::TransmissionRange> transmission;
  k::LimitReport limits;

  Classification(const k::FourBarStructure& f, std::string unit, const k::DesignAnalysis& a)
      : fourBar(f), lengthUnit(std::move(unit)), grashof(*a.grashof), mobility(a.mobility), range(a.inputRange),
        transmission(a.transmission), limits(a.limits) {}
};

std::string deg(double radians) { return formatFixed(k::radToDeg(radians), 2) + "°"; }
std::string jsonDeg(double radians) { return formatJsonNumber(k::radToDeg(radians)); }
std::string branchName(k::Branch b) { return b == k::Branch::Open ? "open" : "crossed"; }

template <typename T>
std::string jsonOptional(const std::optional<T>& value, std::string (*format)(double)) {
  return value ? format(*value) : "null";
}

void printText(const Classification& c, std::ostream& out) {
  const auto& l = c.fourBar.lengths;
  const std::string& u = c.lengthUnit;
  const auto len = [&](double v) { return k::formatShort(v) + " " + u; };
  out << "four-bar             frame " << len(l.frame) << ", crank " << len(l.crank) << ", coupler " << len(l.coupler)
      << ", rocker " << len(l.rocker) << ", branch " << branchName(c.fourBar.branch) << "\n";
  out << "Grashof class        " << k::toString(c.grashof.category)
      << " (shortest link: " << k::toString(c.grashof.shortest) << ", longest: " << k::toString(c.grashof.longest)
      << ")\n";
  out << "S + L, P + Q         " << len(c.grashof.sPlusL) << ", " << len(c.grashof.pPlusQ) << "\n";
  out << "mobility (Gruebler)  M = 3(" << c.mobility.links << " - 1) - 2*" << c.mobility.fullJoints << " - "
      << c.mobility.halfJoints << " = " << c.mobility.mobility << "\n";
  out << "crank turns fully    " << (c.range.fullRotation ? "yes" : "no") << "\n";
  out << "assemblable crank    ";
  if (c.range.fullRotation) out << "all angles\n";
  else if (c.range.ranges.empty()) out << "none: the loop never closes\n";
  else {
    for (std::size_t i = 0; i < c.range.ranges.size(); ++i)
      out << (i ? ", " : "") << deg(c.range.ranges[i].from) << " to " << deg(c.range.ranges[i].to);
    out << "\n";
  }
  if (c.transmission)
    out << "transmission angle   min " << deg(c.transmission->minimum) << " at crank "
        << deg(c.transmission->minimumAtCrank) << ", max " << deg(c.transmission->maximum) << " at crank "
        << deg(c.transmission->maximumAtCrank) << " (worst deviation from 90°: " << deg(c.transmission->worstDeviation)
        << ")\n";
  for (const auto& p : c.limits.positions)
    out << "rocker limit         " << (p.extended ? "extended" : "folded  ") << " crank " << deg(p.crankAngle)
        << ", rocker " << deg(p.rockerAngle) << "\n";
  if (c.limits.positions.empty()) out << "rocker limits        none on this branch\n";
  if (c.limits.rockerSwing) out << "rocker swing         " << deg(*c.limits.rockerSwing) << "\n";
  if (c.limits.timeRatio)
    out << "time ratio           " << formatFixed(*c.limits.timeRatio, 4) << " (slow stroke "
        << deg(*c.limits.slowStrokeCrankArc) << ", quick stroke " << deg(*c.limits.quickStrokeCrankArc)
        << " of crank rotation)\n";
}

void printJson(const Classification& c, std::ostream& out) {
  const auto& l = c.fourBar.lengths;
  const auto& g = c.grashof;
  out << "{\n  \"lengths\": {\"frame\": " << formatJsonNumber(l.frame) << ", \"crank\": " << formatJsonNumber(l.crank)
      << ", \"coupler\": " << formatJsonNumber(l.coupler) << ", \"rocker\": " << formatJsonNumber(l.rocker)
      << "},\n  \"length_unit\": " << k::io::jsonQuote(c.lengthUnit) << ",\n  \"branch\": \""
      << branchName(c.fourBar.branch) << "\",\n";
  out << "  \"grashof\": {\"class\": \"" << k::toString(g.category) << "\", \"shortest\": \"" << k::toString(g.shortest)
      << "\", \"longest\": \"" << k::toString(g.longest) << "\", \"s_plus_l\": " << formatJsonNumber(g.sPlusL)
      << ", \"p_plus_q\": " << formatJsonNumber(g.pPlusQ)
      << ", \"crank_fully_rotates\": " << (g.inputFullyRotates ? "true" : "false")
      << ", \"rocker_fully_rotates\": " << (g.outputFullyRotates ? "true" : "false") << "},\n";
  out << "  \"mobility\": {\"links\": " << c.mobility.links << ", \"full_joints\": " << c.mobility.fullJoints
      << ", \"half_joints\": " << c.mobility.halfJoints << ", \"mobility\": " << c.mobility.mobility << "},\n";
  out << "  \"assemblable_crank_range_deg\": {\"full_rotation\": " << (c.range.fullRotation ? "true" : "false")
      << ", \"ranges\": [";
  for (std::size_t i = 0; i < c.range.ranges.size(); ++i)
    out << (i ? ", " : "") << "[" << jsonDeg(c.range.ranges[i].from) << ", " << jsonDeg(c.range.ranges[i].to) << "]";
  out << "]},\n  \"transmission_angle_deg\": ";
  if (c.transmission)
    out << "{\"min\": " << jsonDeg(c.transmission->minimum)
        << ", \"min_at_crank\": " << jsonDeg(c.transmission->minimumAtCrank)
        << ", \"max\": " << jsonDeg(c.transmission->maximum)
        << ", \"max_at_crank\": " << jsonDeg(c.transmission->maximumAtCrank)
        << ", \"worst_deviation_from_90\": " << jsonDeg(c.transmission->worstDeviation) << "}";
  else out << "null";
  out << ",\n  \"rocker_limit_positions\": [";
  for (std::size_t i = 0; i < c.limits.positions.size(); ++i) {
    const auto& p = c.limits.positions[i];
    out << (i ? ", " : "") << "{\"kind\": \"" << (p.extended ? "extended" : "folded")
        << "\", \"crank_angle_deg\": " << jsonDeg(p.crankAngle) << ", \"rocker_angle_deg\": " << jsonDeg(p.rockerAngle)
        << "}";
  }
  out << "],\n  \"rocker_swing_deg\": " << jsonOptional(c.limits.rockerSwing, jsonDeg)
      << ",\n  \"time_ratio\": " << jsonOptional(c.limits.timeRatio, formatJsonNumber)
      << ",\n  \"slow_stroke_crank_arc_deg\": " << jsonOptional(c.limits.slowStrokeCrankArc, jsonDeg)
      << ",\n  \"quick_stroke_crank_arc_deg\": " << jsonOptional(c.limits.quickStrokeCrankArc, jsonDeg) << "\n}\n";
}

}  // namespace

namespace {

// A quick return's figures: limits, time ratio, stroke, mobility. `kind` and `description`
// head the text.
ExitCode classifyQuickReturn(const std::string& kind, const std::string& description, const k::Mechanism& mechanism,
                             bool json, std::ostream& out) {
  const k::DesignAnalysis a = k::analyseDesign(mechanism, k::SweepResult{});
  const auto& q = a.quickReturn;
  const k::MobilityReport& m = a.mobility;
  if (json) {
    out << "{\n  \"mechanism\": " << k::io::jsonQuote(kind) << ",\n  \"mobility\": " << m.mobility;
    if (q)
      out << ",\n  \"limit_crank_angles_deg\": [" << jsonDeg(q->firstLimitCrankAngle) << ", "
          << jsonDeg(q->secondLimitCrankAngle) << "],\n  \"time_ratio\": " << formatJsonNumber(q->timeRatio)
          << ",\n  \"slow_stroke_crank_arc_deg\": " << jsonDeg(q->slowStrokeCrankArc)
          << ",\n  \"quick_stroke_crank_arc_deg\": " << jsonDeg(q->quickStrokeCrankArc)
          << ",\n  \"rocker_swing_deg\": " << jsonDeg(q->rockerSwing)
          << ",\n  \"whitworth\": " << (q->whitworth ? "true" : "false")
          << ",\n  \"stroke\": " << formatJsonNumber(q->stroke);
    out << ",\n  \"length_unit\": " << k::io::jsonQuote(mechanism.lengthUnit) << "\n}\n";
    return ExitCode::Success;
  }
  out << kind << std::string(kind.size() < 21 ? 21 - kind.size() : 1, ' ') << description << "\n";
  out << "mobility (Gruebler)  M = 3(" << m.links << " - 1) - 2*" << m.fullJoints << " - " << m.halfJoints << " = "
      << m.mobility << "\n";
  if (!q) {
    out << "quick return         none: the ram has no two limit positions\n";
    return ExitCode::Success;
  }
  if (q->whitworth) {
    out << "ram limits           crank " << deg(q->firstLimitCrankAngle) << " and " << deg(q->secondLimitCrankAngle)
        << " (link to the ram along the slotted link; Whitworth form, the slotted link turns fully)\n";
  } else {
    out << "rocker limits        crank " << deg(q->firstLimitCrankAngle) << " and " << deg(q->secondLimitCrankAngle)
        << " (crank at right angles to the slot)\n";
    out << "rocker swing         " << deg(q->rockerSwing) << "\n";
  }
  out << "time ratio           " << formatFixed(q->timeRatio, 4) << " (slow stroke " << deg(q->slowStrokeCrankArc)
      << ", quick stroke " << deg(q->quickStrokeCrankArc) << " of crank rotation)\n";
  out << "ram stroke           " << k::formatShort(q->stroke, 8) << " " << mechanism.lengthUnit << "\n";
  return ExitCode::Success;
}

}  // namespace

// What a linkage is decides what classify reports, not how it was given: a four-bar saved as a
// general linkage is still a four-bar, a quick return still one.
ExitCode runClassify(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto resolved = resolveMechanism(inv);
  if (!resolved) {
    err << "linkwright-cli: " << resolved.error().message << "\n";
    return ExitCode::BadInput;
  }
  const k::Mechanism& m = resolved->mechanism;
  const auto fourBar = k::asFourBar(m);
  if (!fourBar) {
    // An example is named by its kind and description; a document by what it is and its file.
    const bool example = !inv.documentPath;
    if (k::asQuickReturn(m))
      return classifyQuickReturn(example ? resolved->kind : "quick return",
                                 example ? resolved->description : "from " + *inv.documentPath, m, inv.json, out);
    return classifyLinkage(example ? resolved->kind : "linkage", m, inv.json, out, err);
  }
  const Classification c{*fourBar, m.lengthUnit, k::analyseDesign(m, k::SweepResult{})};
  if (inv.json) printJson(c, out);
  else printText(c, out);
  // The designer's verdict on the same linkage (kinematics/design/derived_design.h).
  if (const auto verdict = k::deriveDesign(m, k::SweepResult{}); !verdict) {
    err << "linkwright-cli: " << verdict.error().message << "\n";
    return ExitCode::NotAssemblable;
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
