#include "kinematics/design/sweep_notes.h"

#include "kinematics/design/design_analysis.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/recognise.h"

namespace linkwright::kinematics {
namespace {

std::string rangesText(const Mechanism& m, const std::vector<AngleRange>& ranges) {
  std::string text;
  for (const auto& r : ranges) {
    if (!text.empty()) text += ", ";
    text += r.from == r.to ? inputValueText(m, r.from) : inputValueText(m, r.from) + " to " + inputValueText(m, r.to);
  }
  return text;
}

// Why a toggle has no rates: a four-bar's coupler and output link (its rocker, or its crank
// when driven from the rocker) are collinear; any other linkage has a dyad stretched or folded.
std::string toggleText(const Mechanism& m) {
  const auto linkName = [&m](PointId a, PointId b) -> std::string {
    for (const Link& link : m.links)
      if ((link.first == a && link.second == b) || (link.first == b && link.second == a)) return link.name;
    return m.points[a.index].name + "–" + m.points[b.index].name;
  };
  if (const auto f = asFourBar(m))
    return linkName(f->b, f->c) + " and " + linkName(f->o4, f->c) + " are collinear, ω and α are undefined";
  return "a dyad is stretched straight or folded, its rates are undefined";
}

}  // namespace

std::string inputValueText(const Mechanism& m, double q) {
  const std::string unit = inputUnit(m);
  return formatShort(inputDisplayValue(m, q)) + (unit == "°" ? unit : " " + unit);
}

std::string inputsName(const Mechanism& m) {
  std::string name = inputName(m);
  return name.ends_with("position") || name.ends_with("length") || name.ends_with("angle") ? name + "s" : name;
}

std::string toggleNote(const Mechanism& m, double q) {
  return "toggle position at " + inputName(m) + " " + inputValueText(m, q) + ": " + toggleText(m) +
         " (cells left empty)";
}

std::string lockNote(const Mechanism& m, const AngleRange& step) {
  return "the linkage locks between " + inputsName(m) + " " + inputValueText(m, step.from) + " and " +
         inputValueText(m, step.to) + " (a dyad passes its assembly limit between these samples); from " +
         inputValueText(m, step.to) + " on it is assembled afresh on the chosen branches, so points jump there";
}

std::vector<std::string> notAssembledNote(const Mechanism& m, const SweepSummary& summary) {
  if (summary.notAssembled.empty()) return {};
  std::vector<std::string> note;
  note.push_back("the linkage cannot be assembled at " + std::to_string(summary.samples - summary.assembledSamples) +
                 " of " + std::to_string(summary.samples) + " requested " + inputsName(m) + " (" +
                 rangesText(m, summary.notAssembled) + "); those rows are left out.");
  if (summary.firstFailure) note.push_back(*summary.firstFailure + ".");
  if (!asFourBar(m)) return note;
  const InputRange range = analyseDesign(m, {}).inputRange;
  if (range.ranges.empty()) note.push_back("It cannot be assembled at any " + inputName(m) + ".");
  else note.push_back("It can be assembled for " + inputsName(m) + " " + rangesText(m, range.ranges) + " (exact).");
  return note;
}

std::vector<std::string> sweepNoteSentences(const Mechanism& m, const SweepSummary& summary) {
  std::vector<std::string> notes;
  for (const double q : summary.singularAngles) notes.push_back(toggleNote(m, q));
  for (const AngleRange& step : summary.lockedBetween) notes.push_back(lockNote(m, step));
  std::string left;
  for (const std::string& sentence : notAssembledNote(m, summary)) left += (left.empty() ? "" : " ") + sentence;
  if (!left.empty()) notes.push_back(left);
  return notes;
}

}  // namespace linkwright::kinematics
